#include "contensou/friction/limit_surface.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "contensou/friction/error.hpp"

namespace contensou {
namespace {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// The exact surface in scaled variables t = (vx, vy, omega R), W = (Fx, Fy, Mz/R)/(f N)
// (header comment): Dhat(t) = D(s)/(f N), grad Dhat(t) = -W(s) (Goyal et al. 1991).
struct ScaledExact {
  const LimitSurface& s;
  double radius() const { return s.radius; }
  double scale() const { return s.force_scale; }
  // Dhat and its gradient at t; degree 1: evaluated at t/|t| (the integrals are degree 0).
  void eval(const Vec3& t, double& d, Vec3& g) const {
    const double n = t.stableNorm();
    if (n == 0.0) {
      d = 0.0;
      g.setZero();
      return;
    }
    const Vec3 u = t / n;
    const Kinematics<double> k{u[0], u[1], u[2] / s.radius};
    const Resultants<double> r = exact_resultants(s.model, k, {s.tolerance}).resultants;
    g = -Vec3(r.Fx, r.Fy, r.Mz / s.radius) / s.force_scale;
    d = n * g.dot(u);  // Euler: Dhat = t . grad Dhat
  }
  // The Hessian from differences of the exact gradient. A degree-1 function has H u = 0
  // (u = t/|t|) and H(t) = H(u)/|t|, so H = P B P^T / |t| with P an orthonormal basis of the
  // plane orthogonal to u and B = P^T H P from differences along P's two columns: central
  // (step hessian_step, error O(h^2) + O(tolerance/h), about 1e-8 relative) for the reported
  // Hessian, forward (step 1e-6, about 1e-6 relative; g = grad Dhat(t) is known) for the Newton
  // iterations. Keeping H u = 0 exact matters: an error along u would be amplified by the
  // inverse of the metric's smallest eigenvalue in the projection.
  Mat3 hess_impl(const Vec3& t, const Vec3* g) const {
    const double n = t.stableNorm();
    if (n == 0.0) return Mat3::Zero();
    const Vec3 u = t / n;
    const Vec3 a = std::abs(u[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    Eigen::Matrix<double, 3, 2> P;
    P.col(0) = (a - a.dot(u) * u).normalized();
    P.col(1) = u.cross(P.col(0)).normalized();
    Eigen::Matrix<double, 3, 2> HP;
    for (int k = 0; k < 2; ++k) {
      Vec3 gp, gm;
      double d;
      if (g != nullptr) {
        constexpr double h = 1e-6;
        eval(u + h * P.col(k), d, gp);
        HP.col(k) = (gp - *g) / h;
      } else {
        const double h = s.hessian_step;
        eval(u + h * P.col(k), d, gp);
        eval(u - h * P.col(k), d, gm);
        HP.col(k) = (gp - gm) / (2.0 * h);
      }
    }
    Eigen::Matrix2d B = P.transpose() * HP;
    B = 0.5 * (B + B.transpose());
    return P * B * P.transpose() / n;
  }
  Mat3 hess(const Vec3& t) const { return hess_impl(t, nullptr); }
  Mat3 hess_newton(const Vec3& t, const Vec3& g) const { return hess_impl(t, &g); }
};

// The ellipsoid: Dhat_E(t) = sqrt(t1^2 + kappa^2 t2^2 + l^2 t3^2), l = L / R, scaled by its
// own F.
struct ScaledEllipsoid {
  const EllipsoidalLimitSurface& e;
  double radius() const { return e.radius; }
  double scale() const { return e.force_limit; }
  Vec3 lambda() const {
    const double l = e.torsional_length / e.radius;
    return {1.0, e.kappa * e.kappa, l * l};
  }
  void eval(const Vec3& t, double& d, Vec3& g) const {
    const Vec3 L = lambda();
    const double n = t.stableNorm();  // degree 1: on the unit sphere, no overflow
    if (n == 0.0) {
      d = 0.0;
      g.setZero();
      return;
    }
    const Vec3 u = t / n;
    const double du = std::sqrt(u.dot(L.cwiseProduct(u)));
    d = n * du;
    g = L.cwiseProduct(u) / du;
  }
  Mat3 hess(const Vec3& t) const {
    double d;
    Vec3 g;
    eval(t, d, g);
    if (d == 0.0) return Mat3::Zero();
    // H = (Lambda - g g^T) / D.
    return (Mat3(lambda().asDiagonal()) - g * g.transpose()) / d;
  }
  Mat3 hess_newton(const Vec3& t, const Vec3&) const { return hess(t); }
};

// The scaled view of either surface.
template <class Surface>
using ScaledOf =
    std::conditional_t<std::is_same_v<Surface, LimitSurface>, ScaledExact, ScaledEllipsoid>;

Mat3 scaling(double scale, double radius) {
  return Vec3(scale, scale, scale * radius).asDiagonal();
}

// Newton direction for a (nearly) positive definite H: Cholesky, shifted if it fails.
template <int N>
Eigen::Matrix<double, N, 1> newton_direction(const Eigen::Matrix<double, N, N>& H,
                                             const Eigen::Matrix<double, N, 1>& grad) {
  double mu = 0.0;
  const double scale = std::max(H.diagonal().cwiseAbs().maxCoeff(), 1e-300);
  for (int k = 0; k < 40; ++k) {
    const Eigen::Matrix<double, N, N> Hs = H + mu * Eigen::Matrix<double, N, N>::Identity();
    Eigen::LLT<Eigen::Matrix<double, N, N>> llt(Hs);
    if (llt.info() == Eigen::Success) return -llt.solve(grad);
    mu = mu == 0.0 ? 1e-10 * scale : 10.0 * mu;
  }
  return -grad;
}

// The gauge of a scaled wrench W: 1 / min{ Dhat(t) : e.t = 1 }, e = W / |W| (convex
// objective, affine constraint; the plane misses 0 where Dhat has its kink). Newton in the
// plane's coordinates z, t = e + P z, with a line search that accepts a step which decreases
// Dhat or halves the reduced gradient (the latter lets it converge below the integrals'
// round-off in Dhat).
template <class S>
Gauge scaled_gauge(const S& surf, const Vec3& W) {
  Gauge out;
  const double nW = W.stableNorm();
  if (nW == 0.0) return out;
  const Vec3 e = W / nW;
  // Orthonormal basis of the plane e.t = 0.
  const Vec3 a = std::abs(e[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  Eigen::Matrix<double, 3, 2> P;
  P.col(0) = (a - a.dot(e) * e).normalized();
  P.col(1) = e.cross(P.col(0));
  Eigen::Vector2d z = Eigen::Vector2d::Zero();
  Vec3 t = e, g;
  double d;
  surf.eval(t, d, g);
  for (int it = 0; it < 60; ++it) {
    out.iterations = it + 1;
    const Eigen::Vector2d rg = P.transpose() * g;
    if (rg.norm() <= 1e-11 * std::max(1.0, g.norm())) break;
    const Eigen::Matrix2d H = P.transpose() * surf.hess_newton(t, g) * P;
    const Eigen::Vector2d dz = newton_direction<2>(H, rg);
    double alpha = 1.0;
    bool moved = false;
    for (int ls = 0; ls < 50; ++ls) {
      const Eigen::Vector2d zn = z + alpha * dz;
      const Vec3 tn = e + P * zn;
      Vec3 gn;
      double dn;
      surf.eval(tn, dn, gn);
      if (dn <= d + 1e-4 * alpha * rg.dot(dz) || (P.transpose() * gn).norm() <= 0.5 * rg.norm()) {
        z = zn;
        t = tn;
        d = dn;
        g = gn;
        moved = true;
        break;
      }
      alpha *= 0.5;
    }
    if (!moved) break;
  }
  out.value = nW / d;
  out.normal = t.normalized();
  return out;
}

// A point of the scaled projection's Newton iteration: t, Dhat(t), grad Dhat(t), phi(t) and
// grad phi(t) (scaled_project).
struct ScaledPoint {
  Vec3 t;
  double d;
  Vec3 g;
  double phi;
  Vec3 grad;
};

// The scaled projection's objective (header comment): phi(t) = 1/2 t^T Q t - W_t.t + Dhat(t),
// grad phi(t) = Q t - W_t + grad Dhat(t), Q = Ghat^-1.
template <class S>
struct ScaledObjective {
  const S& surf;
  const Mat3& Q;
  const Vec3& Wt;

  ScaledPoint at(const Vec3& t) const {
    ScaledPoint p;
    p.t = t;
    surf.eval(t, p.d, p.g);
    p.phi = 0.5 * t.dot(Q * t) - Wt.dot(t) + p.d;
    p.grad = Q * t - Wt + p.g;
    return p;
  }

  // Backtracking along dt: the first alpha = 2^-i (i < 50) with phi < 0 and Armijo's decrease
  // or the gradient halved moves x there; false if none does. phi < 0 along the accepted
  // iterates keeps t away from 0 (phi(0) = 0).
  bool line_search(ScaledPoint& x, const Vec3& dt) const {
    double alpha = 1.0;
    for (int ls = 0; ls < 50; ++ls) {
      const ScaledPoint n = at(x.t + alpha * dt);
      if (n.phi < 0.0 && (n.phi <= x.phi + 1e-4 * alpha * x.grad.dot(dt) ||
                          n.grad.norm() <= 0.5 * x.grad.norm())) {
        x = n;
        return true;
      }
      alpha *= 0.5;
    }
    return false;
  }
};

// Newton on phi from x until |grad phi| <= tol plus the round-off floor of Q t: for a large
// metric t is large (|t| ~ |Ghat| |W_t - W*|), and its last bit times |Q| bounds how small grad
// phi can be computed (W* = grad Dhat(t) depends only on t's direction and is then accurate to
// that relative round-off). The cheap Hessian first, the central-difference one once it
// stalls or converges slowly (linearly: its error dominates for an ill-conditioned metric).
template <class S>
void scaled_newton(const ScaledObjective<S>& obj, double Qnorm, double tol, int max_iterations,
                   ScaledPoint& x, Projection& out) {
  auto round_off = [&] {
    return 2.0 * std::numeric_limits<double>::epsilon() * Qnorm * x.t.norm();
  };
  out.converged = false;
  bool accurate = false;
  for (int it = 0; it < max_iterations; ++it) {
    ++out.iterations;
    if (x.grad.norm() <= tol + round_off()) {
      out.converged = true;
      break;
    }
    const double before = x.grad.norm();
    const Mat3 H = obj.Q + (accurate ? obj.surf.hess(x.t) : obj.surf.hess_newton(x.t, x.g));
    const Vec3 dt = newton_direction<3>(H, x.grad);
    if (!obj.line_search(x, dt)) {
      if (accurate) break;
      accurate = true;
      continue;
    }
    if (x.grad.norm() > 0.25 * before) accurate = true;
  }
  if (!out.converged && x.grad.norm() <= tol + round_off()) out.converged = true;
}

// The scaled projection (header comment): Newton on phi(t) = 1/2 t^T Q t - W_t.t + Dhat(t),
// Q = Ghat^-1, from the gauge's normal ray where phi < 0.
template <class S>
Projection scaled_project(const S& surf, const Vec3& Wt, const Mat3& Ghat,
                          const ProjectionOptions& opt) {
  Projection out;
  const Gauge gg = scaled_gauge(surf, Wt);
  out.gauge = gg.value;
  out.iterations = gg.iterations;
  if (gg.value <= 1.0 + opt.inside_tolerance) {
    out.inside = true;
    out.wrench = Wt;
    return out;
  }
  // Beyond |W_t| = 1e100 phi could overflow; there the projection is the support point of
  // the direction Ghat W_t (the limit of the projection of lambda W_t as lambda -> infinity),
  // to a relative error O(cond(Ghat) / |W_t|).
  const double nWt = Wt.stableNorm();
  if (nWt > 1e100) {
    Vec3 g;
    double d;
    surf.eval(Ghat * (Wt / nWt), d, g);
    out.wrench = g;
    return out;
  }
  const Mat3 Q = Ghat.llt().solve(Mat3::Identity());
  const double Qnorm = Q.cwiseAbs().rowwise().sum().maxCoeff();  // infinity norm
  const Vec3 u = gg.normal;
  Vec3 g;
  double d;
  surf.eval(u, d, g);
  // Best point on the ray t = r u: r = (W_t.u - Dhat(u)) / u^T Q u > 0 (the gauge > 1).
  const double c = Wt.dot(u) - d, q = u.dot(Q * u);
  const ScaledObjective<S> obj{surf, Q, Wt};
  ScaledPoint x = obj.at(std::max(c, 0.0) / q * u);
  // Tolerance relative to f N + |W_t| (round-off of Q t - W_t for a large trial).
  scaled_newton(obj, Qnorm, opt.tolerance * (1.0 + nWt), opt.max_iterations, x, out);
  out.residual = x.grad.norm() / (1.0 + nWt);
  out.wrench = x.g;  // grad Dhat(t*): on the surface, with normal t*
  return out;
}

void check_surface(const LimitSurface& s) {
  require_positive("radius", s.radius);
  require_positive("force_scale", s.force_scale);
}
void check_surface(const EllipsoidalLimitSurface& e) {
  require_positive("force_limit", e.force_limit);
  require_positive("torsional_length", e.torsional_length);
  require_positive("kappa", e.kappa);
  require_positive("radius", e.radius);
}

void check_vector(const char* name, const Vec3& v) {
  static const char* const comp[3] = {"[0]", "[1]", "[2]"};
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(v[i]))
      throw InvalidArgument(std::string(name) + comp[i], format_value(v[i]), "must be finite");
}

void check_metric(const Mat3& G) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(G(i, j)))
        throw InvalidArgument("metric(" + std::to_string(i) + "," + std::to_string(j) + ")",
                              format_value(G(i, j)), "must be finite");
  const double asym = (G - G.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-12 * G.cwiseAbs().maxCoeff())
    throw InvalidArgument("metric", "asymmetry " + format_value(asym), "must be symmetric");
  Eigen::LLT<Mat3> llt(G);
  const double dmin = G.diagonal().minCoeff();
  if (llt.info() != Eigen::Success || !(dmin > 0.0))
    throw InvalidArgument("metric", "min diagonal " + format_value(dmin),
                          "must be positive definite");
}

template <class Surface>
Projection project_any(const Surface& surface, const Vec3& trial, const Mat3& metric,
                       const ProjectionOptions& opt) {
  check_surface(surface);
  check_vector("trial", trial);
  check_metric(metric);
  require_positive("tolerance", opt.tolerance);
  require_non_negative("inside_tolerance", opt.inside_tolerance);
  if (opt.max_iterations < 1)
    throw InvalidArgument("max_iterations", std::to_string(opt.max_iterations),
                          "must be at least 1");
  const ScaledOf<Surface> sc{surface};
  const Mat3 S = scaling(sc.scale(), sc.radius());
  const Vec3 Wt = S.inverse() * trial;
  Mat3 Ghat = S * metric * S;
  Ghat = 0.5 * (Ghat + Ghat.transpose());
  Projection p = scaled_project(sc, Wt, Ghat, opt);
  p.wrench = S * p.wrench;
  if (p.inside) {
    p.wrench = trial;
    p.twist.setZero();
  } else {
    p.twist = metric * (p.wrench - trial);
  }
  return p;
}

template <class Surface>
Gauge gauge_any(const Surface& surface, const Vec3& wrench) {
  check_surface(surface);
  check_vector("wrench", wrench);
  const ScaledOf<Surface> sc{surface};
  const Mat3 S = scaling(sc.scale(), sc.radius());
  Gauge g = scaled_gauge(sc, S.inverse() * wrench);
  // Scaled normal t = (vx, vy, omega R) -> twist direction (vx, vy, omega).
  g.normal[2] /= sc.radius();
  return g;
}

template <class Surface>
ContactStep step_any(const Surface& surface, const PlanarBody& body, const Vec3& twist,
                     const Vec3& applied, double h, const ProjectionOptions& opt) {
  require_positive("mass", body.mass);
  require_positive("inertia", body.inertia);
  require_positive("step", h);
  check_vector("twist", twist);
  check_vector("applied", applied);
  // A = h M^-1 (Delassus of one contact at the patch centre); s_free = s + A applied;
  // w_t = -A^-1 s_free; w = proj_C^A(w_t); s+ = s_free + A w (Moreau 1988, Leine & Glocker).
  const Vec3 a(h / body.mass, h / body.mass, h / body.inertia);
  const Vec3 s_free = twist + a.cwiseProduct(applied);
  const Vec3 wt = -s_free.cwiseQuotient(a);
  const Projection p = project_any(surface, wt, Mat3(a.asDiagonal()), opt);
  ContactStep out;
  out.wrench = p.wrench;
  out.stick = p.inside;
  out.iterations = p.iterations;
  out.twist = p.inside ? Vec3::Zero() : Vec3(s_free + a.cwiseProduct(p.wrench));
  return out;
}

// D, gradient and Hessian in the twist s from the scaled surface: t = S s (t3 = R omega),
// D = F Dhat(t), dD/ds = F S grad Dhat, d2D/ds2 = F S H S (F = f N, or the ellipsoid's F).
template <class Surface>
Dissipation derivatives_any(const Surface& surface, const Vec3& twist) {
  check_surface(surface);
  check_vector("twist", twist);
  const ScaledOf<Surface> sc{surface};
  const Mat3 S = scaling(1.0, sc.radius());
  const Vec3 t = S * twist;
  Dissipation out;
  Vec3 g;
  sc.eval(t, out.value, g);
  out.value *= sc.scale();
  out.gradient = sc.scale() * (S * g);
  out.hessian = sc.scale() * (S * sc.hess(t) * S);
  return out;
}

}  // namespace

LimitSurface make_limit_surface(const ContactPatch& patch, double tolerance) {
  validate(patch);
  if (patch.slip_speed_friction)
    throw InvalidArgument("slip_speed_friction", "set",
                          "the limit surface needs a constant friction coefficient");
  if (!(tolerance >= 1e-14 && tolerance <= 1e-6))
    throw InvalidArgument("tolerance", format_value(tolerance), "must be in [1e-14, 1e-6]");
  LimitSurface s;
  s.model = make_exact_model(patch);
  s.model.associated_orthotropy = true;  // the normality law of the set (header comment)
  s.radius = s.model.radius;
  s.force_scale = patch.friction * normal_load(patch);
  s.tolerance = tolerance;
  return s;
}

Dissipation dissipation_with_derivatives(const LimitSurface& surface, const Vec3& twist) {
  return derivatives_any(surface, twist);
}

double dissipation(const LimitSurface& surface, const Vec3& twist) {
  check_surface(surface);
  check_vector("twist", twist);
  const ScaledExact sc{surface};
  double d;
  Vec3 g;
  sc.eval(Vec3(twist[0], twist[1], twist[2] * surface.radius), d, g);
  return surface.force_scale * d;
}

double support(const LimitSurface& surface, const Vec3& direction) {
  return dissipation(surface, direction);
}

Vec3 surface_point(const LimitSurface& surface, const Vec3& normal) {
  check_surface(surface);
  check_vector("normal", normal);
  if (normal.norm() == 0.0) throw InvalidArgument("normal", "0", "must be non-zero");
  const ScaledExact sc{surface};
  double d;
  Vec3 g;
  sc.eval(Vec3(normal[0], normal[1], normal[2] * surface.radius), d, g);
  return scaling(surface.force_scale, surface.radius) * g;
}

Gauge gauge(const LimitSurface& surface, const Vec3& wrench) {
  return gauge_any(surface, wrench);
}

Projection project(const LimitSurface& surface, const Vec3& trial, const Mat3& metric,
                   const ProjectionOptions& options) {
  return project_any(surface, trial, metric, options);
}

EllipsoidalLimitSurface fit_ellipsoid(const LimitSurface& surface) {
  check_surface(surface);
  // Pure sliding along x and y (|F| = f N and kappa f N) and pure spin |Mz| (= M0 for kappa
  // = 1) from the exact integrals.
  auto at = [&](double vx, double vy, double omega) {
    return exact_resultants(surface.model, Kinematics<double>{vx, vy, omega}, {surface.tolerance})
        .resultants;
  };
  const Resultants<double> slide_x = at(1.0, 0.0, 0.0), slide_y = at(0.0, 1.0, 0.0);
  const Resultants<double> spin = at(0.0, 0.0, 1.0);
  EllipsoidalLimitSurface e;
  e.force_limit = std::hypot(slide_x.Fx, slide_x.Fy);
  e.kappa = std::hypot(slide_y.Fx, slide_y.Fy) / e.force_limit;
  e.torsional_length = std::abs(spin.Mz) / e.force_limit;
  e.radius = surface.radius;
  return e;
}

double support(const EllipsoidalLimitSurface& e, const Vec3& d) {
  check_surface(e);
  check_vector("direction", d);
  // D_E(s) = F sqrt(vx^2 + kappa^2 vy^2 + L^2 omega^2).
  return e.force_limit * std::sqrt(d[0] * d[0] + e.kappa * e.kappa * d[1] * d[1] +
                                   e.torsional_length * e.torsional_length * d[2] * d[2]);
}

Dissipation dissipation_with_derivatives(const EllipsoidalLimitSurface& e, const Vec3& twist) {
  return derivatives_any(e, twist);
}

Vec3 surface_point(const EllipsoidalLimitSurface& e, const Vec3& normal) {
  check_surface(e);
  check_vector("normal", normal);
  if (normal.norm() == 0.0) throw InvalidArgument("normal", "0", "must be non-zero");
  return dissipation_with_derivatives(e, normal).gradient;
}

Gauge gauge(const EllipsoidalLimitSurface& e, const Vec3& w) {
  check_surface(e);
  check_vector("wrench", w);
  // Closed form: g = sqrt((Fx/F)^2 + (Fy/(kappa F))^2 + (Mz/(F L))^2); normal Lambda^-1 W
  // (scaled).
  Gauge g;
  const double F = e.force_limit, L = e.torsional_length, Fy = e.kappa * F;
  g.value = std::sqrt((w[0] / F) * (w[0] / F) + (w[1] / Fy) * (w[1] / Fy) +
                      (w[2] / (F * L)) * (w[2] / (F * L)));
  if (g.value > 0.0) {
    const double l = L / e.radius;
    Vec3 t(w[0] / F, w[1] / F / (e.kappa * e.kappa), w[2] / (F * e.radius) / (l * l));
    t.normalize();
    t[2] /= e.radius;
    g.normal = t;
  }
  return g;
}

Projection project(const EllipsoidalLimitSurface& surface, const Vec3& trial, const Mat3& metric,
                   const ProjectionOptions& options) {
  return project_any(surface, trial, metric, options);
}

EllipsoidError ellipsoid_error(const LimitSurface& exact, const EllipsoidalLimitSurface& fit,
                               int n_theta, int n_phi) {
  check_surface(exact);
  check_surface(fit);
  if (n_theta < 2 || n_phi < 1)
    throw InvalidArgument("n_theta", std::to_string(n_theta), "must be >= 2 (n_phi >= 1)");
  EllipsoidError out;
  double sum = 0.0;
  int count = 0;
  // Polar angle from the spin axis of scaled twists; cos-spaced (denser near the poles, where
  // the centre of sliding is inside the patch), poles included.
  for (int i = 0; i <= n_theta; ++i) {
    const double th = std::numbers::pi * 0.5 * (1.0 - std::cos(std::numbers::pi * i / n_theta));
    const int nphi = (i == 0 || i == n_theta) ? 1 : n_phi;
    for (int j = 0; j < nphi; ++j) {
      const double ph = 2.0 * std::numbers::pi * j / n_phi;
      const Vec3 t(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
      const Vec3 n(t[0], t[1], t[2] / exact.radius);
      const Vec3 w = surface_point(exact, n);
      const double err = 1.0 / gauge(fit, w).value - 1.0;
      sum += err * err;
      ++count;
      if (std::abs(err) > std::abs(out.max_radial_error)) {
        out.max_radial_error = err;
        out.worst_normal = n;
      }
    }
  }
  out.max_radial_error = std::abs(out.max_radial_error);
  out.rms_radial_error = std::sqrt(sum / count);
  return out;
}

FractionalDissipation fractional_dissipation(const FractionalLaw<double>& law, const Vec3& twist) {
  check_vector("twist", twist);
  const Kinematics<double> k{twist[0], twist[1], twist[2]};
  const FractionalWithJacobian fj = fractional_resultants_with_jacobian(law, k);
  FractionalDissipation out;
  out.wrench = fj.resultants.vector();
  // D_f = -w(s).s, grad D_f = -(w + J^T s) (theory.md section 4 law; J analytic).
  out.value = -out.wrench.dot(twist);
  out.gradient = -(out.wrench + fj.jacobian.transpose() * twist);
  return out;
}

ContactStep moreau_jean_step(const LimitSurface& surface, const PlanarBody& body, const Vec3& twist,
                             const Vec3& applied, double step, const ProjectionOptions& options) {
  return step_any(surface, body, twist, applied, step, options);
}

ContactStep moreau_jean_step(const EllipsoidalLimitSurface& surface, const PlanarBody& body,
                             const Vec3& twist, const Vec3& applied, double step,
                             const ProjectionOptions& options) {
  return step_any(surface, body, twist, applied, step, options);
}

}  // namespace contensou
