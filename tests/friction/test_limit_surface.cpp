// The limit surface (limit_surface.hpp) against independent oracles: the closed forms of
// theory.md section 3 (pure spin (2/3) f N R, pure slide f N), finite differences of D,
// ceres::Jet derivatives of the exact resultants, convexity, normality, and a brute-force
// projection by dense sampling of the boundary.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>

#include "contensou/friction/limit_surface.hpp"
#include "patches.hpp"

using namespace contensou;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
constexpr double kPi = std::numbers::pi;

namespace {

using test_support::uniform_patch;

ContactPatch shifted_seed() {
  ContactPatch p = seed_tire_patch();
  p.profile.keep_negative = true;
  p.profile.kx = 0.14;
  p.profile.ky = -0.05;
  return p;
}

// Boundary points grad D(n) for n on a (theta, phi) grid of scaled twists (vx, vy, omega R).
std::vector<Vec3> boundary_samples(const LimitSurface& s, int nt, int np) {
  std::vector<Vec3> w;
  for (int i = 0; i <= nt; ++i) {
    const double th = kPi * i / nt;
    for (int j = 0; j < ((i == 0 || i == nt) ? 1 : np); ++j) {
      const double ph = 2 * kPi * j / np;
      w.push_back(surface_point(s, Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph),
                                        std::cos(th) / s.radius)));
    }
  }
  return w;
}

}  // namespace

TEST(LimitSurface, SupportMatchesClosedFormsOfTheUniformDisk) {
  const ContactPatch p = uniform_patch();
  const LimitSurface s = make_limit_surface(p);
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  EXPECT_NEAR(support(s, Vec3(1, 0, 0)), fN, 1e-10 * fN);                       // pure slide
  EXPECT_NEAR(support(s, Vec3(0, -3, 0)), 3 * fN, 1e-10 * fN);                  // degree 1
  EXPECT_NEAR(support(s, Vec3(0, 0, 1)), 2.0 / 3.0 * fN * R, 1e-10 * fN * R);   // pure spin
  EXPECT_NEAR(support(s, Vec3(0, 0, -2)), 4.0 / 3.0 * fN * R, 1e-10 * fN * R);  // even
  // Tips of the surface: the wrench of pure spin is (0, 0, -(2/3) f N R) for omega > 0.
  // The point with normal n is the friction of kinematics -n: omega = +1 gives Mz < 0.
  const Vec3 tip = surface_point(s, Vec3(0, 0, -1));
  EXPECT_NEAR(tip[2], -2.0 / 3.0 * fN * R, 1e-10 * fN * R);
  EXPECT_NEAR(tip.head<2>().norm(), 0.0, 1e-10 * fN);
}

TEST(LimitSurface, GradientIsMinusTheResultantAndMatchesFiniteDifferences) {
  const ContactPatch p = shifted_seed();
  const LimitSurface s = make_limit_surface(p);
  const ExactModel<double> m = make_exact_model(p);
  const double fN = s.force_scale, R = s.radius;
  std::mt19937 rng(7);
  std::normal_distribution<double> n01;
  for (int trial = 0; trial < 12; ++trial) {
    const Vec3 tw(n01(rng), n01(rng), n01(rng) / R);
    const Dissipation d = dissipation_with_derivatives(s, tw);
    // Sign convention of theory.md section 1: the resultant on the tire is -grad D.
    const Resultants<double> r =
        exact_resultants(m, Kinematics<double>{tw[0], tw[1], tw[2]}, {1e-12}).resultants;
    EXPECT_NEAR(d.gradient[0], -r.Fx, 1e-9 * fN);
    EXPECT_NEAR(d.gradient[2], -r.Mz, 1e-9 * fN * R);
    EXPECT_GT(d.value, 0.0);
    // Central differences of D itself (value only, computed from the definition's Euler form).
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-5 * (j == 2 ? 1.0 / R : 1.0);
      const double fd =
          (dissipation(s, tw + h * Vec3::Unit(j)) - dissipation(s, tw - h * Vec3::Unit(j))) /
          (2 * h);
      EXPECT_NEAR(fd, d.gradient[j], 1e-6 * fN * (j == 2 ? R : 1.0)) << trial << " " << j;
    }
    // Degree 1: H s = 0; symmetric positive semi-definite (convex).
    const Vec3 sc(1, 1, R);
    const Mat3 Hs = sc.asDiagonal() * d.hessian * sc.asDiagonal();  // per scaled twist
    EXPECT_LT((d.hessian * tw).norm(), 1e-6 * fN * Vec3(1, 1, 1 / R).norm());
    Eigen::SelfAdjointEigenSolver<Mat3> es(Hs);
    EXPECT_GT(es.eigenvalues()[0], -1e-6 * fN / Vec3(tw[0], tw[1], tw[2] * R).norm());
  }
}

TEST(LimitSurface, HessianMatchesJetDerivativesOfTheExactResultants) {
  using J = ceres::Jet<double, 3>;
  const ContactPatch p = shifted_seed();
  const LimitSurface s = make_limit_surface(p);
  const ExactModel<J> mj = promote<J>(make_exact_model(p));
  const double fN = s.force_scale, R = s.radius;
  for (const Vec3& tw : {Vec3(0.3, -0.2, 5.0), Vec3(1.0, 0.4, 2.0), Vec3(0.0, 0.0, 3.0),
                         Vec3(0.8, 0.0, 0.0), Vec3(0.087 * 4.0, 0.0, 4.0)}) {
    const Dissipation d = dissipation_with_derivatives(s, tw);
    const Kinematics<J> k{J(tw[0], 0), J(tw[1], 1), J(tw[2], 2)};
    const Eigen::Matrix<J, 3, 1> gj = dissipation_gradient(mj, k, {1e-12});
    const J comp[3] = {-gj[0], -gj[1], -gj[2]};
    const double scale[3] = {1.0, 1.0, R};
    const double tn = Vec3(tw[0], tw[1], tw[2] * R).norm();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(d.hessian(i, j), -comp[i].v[j], 1e-6 * fN * scale[i] * scale[j] / tn)
            << tw.transpose() << " " << i << j;
  }
}

TEST(LimitSurface, DissipationIsConvexAndBoundsEveryBoundaryPoint) {
  const LimitSurface s = make_limit_surface(shifted_seed());
  const double R = s.radius;
  std::mt19937 rng(3);
  std::normal_distribution<double> n01;
  std::uniform_real_distribution<double> u01;
  for (int i = 0; i < 40; ++i) {
    const Vec3 a(n01(rng), n01(rng), n01(rng) / R), b(n01(rng), n01(rng), n01(rng) / R);
    const double l = u01(rng);
    EXPECT_LE(dissipation(s, l * a + (1 - l) * b),
              l * dissipation(s, a) + (1 - l) * dissipation(s, b) + 1e-10 * s.force_scale);
  }
  // Support function: D(d) >= w.d for every sampled boundary point w, with equality at the
  // point whose normal is d.
  const std::vector<Vec3> w = boundary_samples(s, 10, 12);
  for (int i = 0; i < 10; ++i) {
    const Vec3 d(n01(rng), n01(rng), n01(rng) / R);
    double best = -1e300;
    for (const Vec3& x : w) best = std::max(best, x.dot(d));
    EXPECT_LE(best, support(s, d) + 1e-10 * s.force_scale * d.norm());
    EXPECT_NEAR(surface_point(s, d).dot(d), support(s, d), 1e-10 * s.force_scale * d.norm());
  }
}

TEST(LimitSurface, GaugeIsOneOnTheBoundaryAndHomogeneous) {
  const LimitSurface s = make_limit_surface(shifted_seed());
  for (const Vec3& n : {Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0.3, -0.5, 4.0), Vec3(-1, 2, -30)}) {
    const Vec3 w = surface_point(s, n);
    const Gauge g = gauge(s, w);
    EXPECT_NEAR(g.value, 1.0, 1e-10) << n.transpose();
    EXPECT_NEAR(gauge(s, 2.5 * w).value, 2.5, 1e-9);
    // The normal found is n's direction (in scaled twists).
    const Vec3 a(n[0], n[1], n[2] * s.radius), b(g.normal[0], g.normal[1], g.normal[2] * s.radius);
    EXPECT_GT(a.normalized().dot(b.normalized()), 1 - 1e-8) << n.transpose();
  }
  EXPECT_EQ(gauge(s, Vec3::Zero()).value, 0.0);
}

// Projection: every regime (inside, on the boundary, just outside, far outside, beyond the
// spin tips) in an anisotropic metric, checked by the variational inequality
// (w - w*)^T G (w_t - w*) <= 0 for every sampled boundary point w, by brute force (no sampled
// point is nearer than w*), and by normality (the resultant of the returned twist is w*).
TEST(LimitSurface, ProjectionIsTheNearestPointInTheMetricAndObeysNormality) {
  const ContactPatch p = shifted_seed();
  const LimitSurface s = make_limit_surface(p);
  const ExactModel<double> m = make_exact_model(p);
  const double fN = s.force_scale, R = s.radius;
  const std::vector<Vec3> samples = boundary_samples(s, 40, 40);
  Mat3 B;
  B << 1.0, 0.3, 0.1, 0.2, 0.8, -0.3, 0.0, 0.1, 0.5;
  const Vec3 sc(1.0, 1.0, 1.0 / R);
  const Mat3 G = sc.asDiagonal() * (B * B.transpose() + 0.2 * Mat3::Identity()) * sc.asDiagonal() /
                 (fN * fN);  // dimensionless distance
  std::vector<Vec3> trials;
  const Vec3 tip = surface_point(s, Vec3(0, 0, 1));
  trials.push_back(0.5 * surface_point(s, Vec3(0.2, 0.4, 3)));   // inside
  trials.push_back(surface_point(s, Vec3(0.2, 0.4, 3)));         // on the boundary
  trials.push_back(1.001 * surface_point(s, Vec3(-1, 0.3, 7)));  // just outside
  trials.push_back(Vec3(3.0 * fN, -2.0 * fN, 0.5 * fN * R));     // outside
  trials.push_back(Vec3(1e4 * fN, 2e4 * fN, -3e3 * fN * R));     // far outside
  trials.push_back(3.0 * tip);                                   // beyond the spin tip
  trials.push_back(Vec3(0.0, 0.0, -5.0 * fN * R));               // beyond the other tip
  trials.push_back(Vec3(2.0 * fN, 0.0, 0.0));                    // beyond pure slide
  for (const Vec3& wt : trials) {
    const Projection pr = project(s, wt, G);
    ASSERT_TRUE(pr.converged) << wt.transpose();
    const Vec3 ws = pr.wrench;
    if (pr.inside) {
      EXPECT_LE(pr.gauge, 1.0 + 1e-10);
      EXPECT_EQ(ws, wt);
      EXPECT_EQ(pr.twist, Vec3::Zero());
      continue;
    }
    EXPECT_NEAR(gauge(s, ws).value, 1.0, 1e-9) << wt.transpose();
    const double dist = (ws - wt).dot(G * (ws - wt));
    double brute = 1e300;
    for (const Vec3& w : samples) {
      EXPECT_LE((w - ws).dot(G * (wt - ws)), 1e-8 * std::sqrt(dist) + 1e-12) << wt.transpose();
      brute = std::min(brute, (w - wt).dot(G * (w - wt)));
    }
    EXPECT_LE(dist, brute * (1 + 1e-9) + 1e-14) << wt.transpose();
    // Far from the set the sampling is fine enough to bound the distance from below too.
    if (dist > 1.0) {
      EXPECT_GT(dist, 0.97 * brute) << wt.transpose();
    }
    // Normality / maximum dissipation: the resultant of the kinematics `twist` is w*.
    const Resultants<double> r =
        exact_resultants(m, Kinematics<double>{pr.twist[0], pr.twist[1], pr.twist[2]}, {1e-12})
            .resultants;
    EXPECT_NEAR(r.Fx, ws[0], 1e-8 * fN) << wt.transpose();
    EXPECT_NEAR(r.Fy, ws[1], 1e-8 * fN) << wt.transpose();
    EXPECT_NEAR(r.Mz, ws[2], 1e-8 * fN * R) << wt.transpose();
  }
  RecordProperty("samples", static_cast<int>(samples.size()));
}

TEST(LimitSurface, ProjectionOfTheUniformDiskBeyondItsTipIsTheTip) {
  // By symmetry the Euclidean (scaled) projection of (0, 0, M) with |M| > (2/3) f N R is the tip.
  const ContactPatch p = uniform_patch();
  const LimitSurface s = make_limit_surface(p);
  const double fN = s.force_scale, R = s.radius;
  const Mat3 G = Vec3(1.0, 1.0, 1.0 / (R * R)).asDiagonal();
  for (double M : {0.7, 1.0, 100.0}) {
    const Projection pr = project(s, Vec3(0, 0, M * fN * R), G);
    EXPECT_TRUE(pr.converged);
    EXPECT_NEAR(pr.wrench[2], 2.0 / 3.0 * fN * R, 1e-9 * fN * R) << M;
    EXPECT_NEAR(pr.wrench.head<2>().norm(), 0.0, 1e-9 * fN) << M;
    EXPECT_LT(pr.twist[2], 0.0);  // spinning with omega < 0 gives Mz > 0
  }
  const Projection pr = project(s, Vec3(0, 0, 0.6 * fN * R), G);
  EXPECT_TRUE(pr.inside);
}

TEST(LimitSurface, EllipsoidMatchesTheExtremesAndItsProjectionIsExact) {
  const ContactPatch u = uniform_patch();
  const EllipsoidalLimitSurface e = fit_ellipsoid(make_limit_surface(u));
  const double fN = u.friction * normal_load(u), R = u.radius_m;
  EXPECT_NEAR(e.force_limit, fN, 1e-10 * fN);
  EXPECT_NEAR(e.torsional_length, 2.0 / 3.0 * R, 1e-10 * R);
  ContactPatch h = u;
  h.profile = hertz_profile();
  EXPECT_NEAR(fit_ellipsoid(make_limit_surface(h)).torsional_length, 3 * kPi / 16 * R, 1e-10 * R);
  // Ellipsoid projection in the Euclidean scaled metric: brute force over a dense grid of the
  // ellipsoid's surface.
  const Mat3 G = Vec3(1.0, 1.0, 1.0 / (R * R)).asDiagonal();
  for (const Vec3& wt : {Vec3(2 * fN, 0.5 * fN, 0.9 * fN * R), Vec3(0.1 * fN, 0, -4 * fN * R)}) {
    const Projection pr = project(e, wt, G);
    ASSERT_TRUE(pr.converged);
    EXPECT_NEAR(gauge(e, pr.wrench).value, 1.0, 1e-10);
    double brute = 1e300;
    for (int i = 0; i <= 400; ++i)
      for (int j = 0; j < 400; ++j) {
        const double th = kPi * i / 400, ph = 2 * kPi * j / 400;
        const Vec3 w(fN * std::sin(th) * std::cos(ph), fN * std::sin(th) * std::sin(ph),
                     fN * e.torsional_length * std::cos(th));
        brute = std::min(brute, (w - wt).dot(G * (w - wt)));
      }
    const double dist = (pr.wrench - wt).dot(G * (pr.wrench - wt));
    EXPECT_LE(dist, brute * (1 + 1e-12));
    EXPECT_GT(dist, brute * (1 - 1e-3));
  }
  // The ellipsoid error is zero at the two extremes it is fitted to, positive elsewhere.
  const LimitSurface s = make_limit_surface(u);
  EXPECT_NEAR(gauge(e, surface_point(s, Vec3(1, 0, 0))).value, 1.0, 1e-10);
  EXPECT_NEAR(gauge(e, surface_point(s, Vec3(0, 0, 1))).value, 1.0, 1e-10);
  const EllipsoidError err = ellipsoid_error(s, e, 8, 8);
  EXPECT_GT(err.max_radial_error, 1e-3);
  EXPECT_LT(err.max_radial_error, 0.5);
}

TEST(LimitSurface, FractionalDissipationGradientMatchesFiniteDifferences) {
  const FractionalLaw<double> law = fractional_law_from_patch(shifted_seed());
  const double R = law.radius;
  for (const Vec3& tw : {Vec3(0.4, -0.1, 3.0), Vec3(1.0, 0.2, 0.0), Vec3(0.0, 0.0, 2.0)}) {
    const FractionalDissipation d = fractional_dissipation(law, tw);
    EXPECT_GT(d.value, 0.0);
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-6 * (j == 2 ? 1.0 / R : 1.0);
      const double fd = (fractional_dissipation(law, tw + h * Vec3::Unit(j)).value -
                         fractional_dissipation(law, tw - h * Vec3::Unit(j)).value) /
                        (2 * h);
      EXPECT_NEAR(fd, d.gradient[j], 1e-5 * law.F0 * (j == 2 ? R : 1.0)) << j;
    }
  }
}

TEST(LimitSurface, BadInputIsRejectedWithTheParameterNamed) {
  ContactPatch p = uniform_patch();
  p.slip_speed_friction = SlipSpeedFriction<double>{0.6, 0.4, 1.0, 1.0};
  try {
    make_limit_surface(p);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "slip_speed_friction");
  }
  EllipsoidalLimitSurface bad_e = fit_ellipsoid(make_limit_surface(uniform_patch()));
  bad_e.kappa = 0.0;
  try {
    gauge(bad_e, Vec3(1, 0, 0));
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "kappa");
  }
  const LimitSurface s = make_limit_surface(uniform_patch());
  const Mat3 I = Mat3::Identity();
  EXPECT_THROW(project(s, Vec3(std::nan(""), 0, 0), I), InvalidArgument);
  EXPECT_THROW(project(s, Vec3(1, 0, 0), Vec3(1, -1, 1).asDiagonal()), InvalidArgument);
  Mat3 asym = I;
  asym(0, 1) = 0.5;
  EXPECT_THROW(project(s, Vec3(1, 0, 0), asym), InvalidArgument);
  Mat3 inf = I;
  inf(2, 2) = INFINITY;
  try {
    project(s, Vec3(1, 0, 0), inf);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "metric(2,2)");
  }
  EXPECT_THROW(make_limit_surface(uniform_patch(), 0.1), InvalidArgument);
}

// Every trial converges, from 1e-8 to 1e200 times f N, in metrics with condition numbers 1 and
// 1e8: the result is on the surface, and normality holds (the resultant of the returned twist
// is the returned wrench, an independent exact integral) to the dual's round-off floor, about
// cond x 1e-16 relative (1e-5 of f N allowed at cond 1e8, 1e-8 at cond 1).
TEST(LimitSurface, ProjectionConvergesForExtremeTrialsAndIllConditionedMetrics) {
  ContactPatch p = shifted_seed();
  const LimitSurface s = make_limit_surface(p);
  const ExactModel<double> m = make_exact_model(p);
  const double fN = s.force_scale, R = s.radius;
  Mat3 U;  // a fixed rotation
  U << 0.36, 0.48, -0.8, -0.8, 0.6, 0.0, 0.48, 0.64, 0.6;
  const Vec3 sc(1.0, 1.0, 1.0 / R);
  for (double cond : {1.0, 1e8}) {
    const Mat3 G0 = sc.asDiagonal() * U * Vec3(1.0, std::sqrt(cond), cond).asDiagonal() *
                    U.transpose() * sc.asDiagonal();
    const Mat3 G = 0.5 * (G0 + G0.transpose());
    for (double mag : {1e-8, 1.5, 1e3, 1e20, 1e200}) {
      const Vec3 wt = mag * Vec3(0.6 * fN, -0.7 * fN, 0.4 * fN * R);
      const Projection pr = project(s, wt, G);
      EXPECT_TRUE(pr.converged) << mag << " " << cond;
      if (pr.inside) {
        EXPECT_LT(mag, 1.0);
        continue;
      }
      ASSERT_TRUE(pr.wrench.allFinite() && pr.twist.allFinite()) << mag << " " << cond;
      EXPECT_NEAR(gauge(s, pr.wrench).value, 1.0, 1e-9) << mag << " " << cond;
      const Vec3 n = pr.twist / pr.twist.stableNorm();
      const Resultants<double> r =
          exact_resultants(m, Kinematics<double>{n[0], n[1], n[2]}, {1e-12}).resultants;
      const double tol = cond > 1.0 ? 1e-5 : 1e-8;
      EXPECT_NEAR(r.Fx, pr.wrench[0], tol * fN) << mag << " " << cond;
      EXPECT_NEAR(r.Fy, pr.wrench[1], tol * fN) << mag << " " << cond;
      EXPECT_NEAR(r.Mz, pr.wrench[2], tol * fN * R) << mag << " " << cond;
    }
  }
}

// --- Orthotropic friction (kappa != 1) -------------------------------------------------------

namespace {

struct BruteSurface {
  double D = 0.0;  // integral f sigma |K vc| dS, K = diag(1, kappa)
  Vec3 gradient;   // integral f sigma (K^2 vc/|K vc|) {1, r x} dS (dD/d(vx, vy, omega))
};

// Midpoint rule on an (r, theta) grid about O, straight from the definitions (header of
// limit_surface.hpp): the support function and its gradient, the associated traction.
BruteSurface brute_surface(const ContactPatch& p, const Vec3& s, int nr = 500, int nt = 1000) {
  BruteSurface out;
  out.gradient.setZero();
  const double R = p.radius_m, k2 = p.kappa * p.kappa;
  for (int i = 0; i < nr; ++i) {
    const double r = R * (i + 0.5) / nr;
    for (int j = 0; j < nt; ++j) {
      const double th = 2 * kPi * (j + 0.5) / nt;
      const double x = r * std::cos(th), y = r * std::sin(th);
      const double fs = p.friction * p.reference_pressure_pa * shape_value(p.profile, r / R) *
                        (1 + p.profile.kx * x / R + p.profile.ky * y / R) * r * (R / nr) *
                        (2 * kPi / nt);
      const double cx = s[0] - s[2] * y, cy = s[1] + s[2] * x;
      const double w = std::hypot(cx, p.kappa * cy);
      if (w == 0.0) continue;
      out.D += fs * w;
      const double tx = fs * cx / w, ty = fs * k2 * cy / w;
      out.gradient += Vec3(tx, ty, x * ty - y * tx);
    }
  }
  return out;
}

ContactPatch orthotropic(ContactPatch p, double kappa) {
  p.kappa = kappa;
  return p;
}

}  // namespace

// For kappa != 1 the surface is that of the local ellipses of tractions: its support function
// is integral f sigma |diag(1, kappa) vc| dS and its points the associated law's resultants,
// both checked against the brute-force grid (an oracle that does not use the chord integrals
// or Euler's relation) in every regime: centre inside, near the rim, outside, pure sliding
// (diagonal), pure spin; two kappas on both sides of 1, uniform and the shifted seed tire.
TEST(LimitSurface, OrthotropicSupportAndPointsMatchTheBruteForceIntegralOfTheEllipses) {
  for (const ContactPatch& base : {uniform_patch(), shifted_seed()}) {
    for (double kappa : {0.6, 1.5}) {
      const ContactPatch p = orthotropic(base, kappa);
      const LimitSurface s = make_limit_surface(p);
      const double fN = s.force_scale, R = s.radius;
      for (const Vec3& n :
           {Vec3(0.1, -0.05, 3.0), Vec3(0.3, 0.2, 1.0 / R * 0.4), Vec3(0.5, 0.5, 1.0 / R * 0.3),
            Vec3(0.6, -0.8, 0.0), Vec3(0, 0, 1.0 / R), Vec3(-0.9, 0.1, -2.0 / R)}) {
        const BruteSurface b = brute_surface(p, n);
        const double scale = fN * std::hypot(n.head<2>().norm(), n[2] * R);
        EXPECT_NEAR(support(s, n), b.D, 2e-4 * scale) << kappa << " " << n.transpose();
        const Vec3 w = surface_point(s, n);
        for (int j = 0; j < 3; ++j)
          EXPECT_NEAR(w[j], b.gradient[j], 2e-4 * fN * (j == 2 ? R : 1.0))
              << kappa << " " << n.transpose() << " component " << j;
      }
    }
  }
}

// The associated law is a gradient field: the Jacobian of its wrench (ceres::Jet through the
// exact integrals) is symmetric, and it annihilates the twist (degree 0); the library's default
// orthotropic law is not (asymmetry of order (1 - kappa) f N R, so the check can fail). At
// pure sliding the closed-form first order in omega (exact_resultants.hpp) gives the same
// symmetric Jacobian, and its dMz/domega matches a difference quotient of the integrals.
TEST(LimitSurface, OrthotropicLawIsAGradientWithASymmetricJacobianInEveryBranch) {
  using J = ceres::Jet<double, 3>;
  for (const ContactPatch& base : {uniform_patch(), shifted_seed()}) {
    const ContactPatch p = orthotropic(base, 0.7);
    const LimitSurface s = make_limit_surface(p);
    const double fN = s.force_scale, R = s.radius;
    ExactModel<double> plain = make_exact_model(p);
    const ExactModel<J> mj = promote<J>(s.model), mj_plain = promote<J>(plain);
    auto jacobian = [&](const ExactModel<J>& m, const Vec3& t) {
      const Kinematics<J> k{J(t[0], 0), J(t[1], 1), J(t[2], 2)};
      const Eigen::Matrix<J, 3, 1> g = dissipation_gradient(m, k, {1e-13});
      Mat3 H;
      for (int i = 0; i < 3; ++i) H.row(i) = g[i].v.transpose();
      return H;
    };
    // Scaled so that entries are comparable: S H S with S = diag(1, 1, 1/R).
    const Mat3 S = Vec3(1, 1, 1 / R).asDiagonal();
    for (const Vec3& t : {Vec3(0.1, -0.05, 3.0 / R), Vec3(0.3, 0.2, 0.4 / R),
                          Vec3(0.5, 0.5, 0.3 / R), Vec3(0.6, -0.8, 1e-18 / R)}) {
      const Mat3 H = S * jacobian(mj, t) * S;
      const double scale = fN / std::hypot(t.head<2>().norm(), t[2] * R);  // |H| ~ f N / |t|
      EXPECT_LT((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-8 * scale) << t.transpose();
      EXPECT_LT((jacobian(mj, t) * t).norm(), 1e-8 * fN) << t.transpose();
      if (t[2] * R > 1e-3) {
        const Mat3 Hp = S * jacobian(mj_plain, t) * S;
        EXPECT_GT((Hp - Hp.transpose()).cwiseAbs().maxCoeff(), 1e-4 * scale) << t.transpose();
      }
    }
    // Pure sliding: d(grad D)/domega from the first-order term against central differences.
    const Vec3 v(0.6, -0.8, 0.0);
    const double dw = 1e-4 / R;
    const Mat3 H0 = jacobian(mj, v);
    const Vec3 gp =
        -exact_resultants(s.model, Kinematics<double>{v[0], v[1], dw}, {1e-14}).resultants.vector();
    const Vec3 gm = -exact_resultants(s.model, Kinematics<double>{v[0], v[1], -dw}, {1e-14})
                         .resultants.vector();
    const Vec3 fd = (gp - gm) / (2 * dw);
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(H0(i, 2), fd[i], 1e-6 * fN * R * (i == 2 ? R : 1.0)) << i;
  }
}

// Pure spin of a uniform orthotropic disk (no shift): |Mz| = (2/3) f N R times the mean of
// |diag(1, kappa) e| over directions e (the associated traction at r is f sigma |D e_theta|
// along the moment arm); the fitted ellipsoid reproduces the three extremes.
TEST(LimitSurface, OrthotropicPureSpinAndEllipsoidExtremes) {
  for (double kappa : {0.5, 0.8, 1.3}) {
    const ContactPatch p = orthotropic(uniform_patch(), kappa);
    const LimitSurface s = make_limit_surface(p);
    const double fN = s.force_scale, R = s.radius;
    double mean = 0.0;
    constexpr int n = 4096;  // trapezoid on a periodic analytic integrand: spectral
    for (int j = 0; j < n; ++j) {
      const double th = 2 * kPi * j / n;
      mean += std::hypot(std::sin(th), kappa * std::cos(th)) / n;
    }
    EXPECT_NEAR(support(s, Vec3(0, 0, 1)), 2.0 / 3.0 * fN * R * mean, 1e-10 * fN * R) << kappa;
    EXPECT_NEAR(support(s, Vec3(0, 1, 0)), kappa * fN, 1e-10 * fN) << kappa;
    const EllipsoidalLimitSurface e = fit_ellipsoid(s);
    EXPECT_NEAR(e.force_limit, fN, 1e-10 * fN);
    EXPECT_NEAR(e.kappa, kappa, 1e-10);
    EXPECT_NEAR(e.force_limit * e.torsional_length, 2.0 / 3.0 * fN * R * mean, 1e-10 * fN * R);
    for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)})
      EXPECT_NEAR(support(e, d), support(s, d), 1e-9 * fN * (d[2] != 0 ? R : 1.0));
    const EllipsoidError err = ellipsoid_error(s, e, 12, 12);
    EXPECT_LT(err.max_radial_error, 0.15) << kappa;
    EXPECT_GT(err.max_radial_error, 0.0) << kappa;
  }
}

// Projection onto an orthotropic surface: the result is on the boundary (gauge 1) and obeys
// normality (the associated resultant of the returned twist is the returned wrench).
TEST(LimitSurface, OrthotropicProjectionLandsOnTheBoundaryWithNormality) {
  const ContactPatch p = orthotropic(shifted_seed(), 0.75);
  const LimitSurface s = make_limit_surface(p);
  const double fN = s.force_scale, R = s.radius;
  std::mt19937 rng(15);
  std::normal_distribution<double> N01;
  for (int trial = 0; trial < 40; ++trial) {
    const Vec3 w_t(2 * fN * N01(rng), 2 * fN * N01(rng), 2 * fN * R * N01(rng));
    Mat3 A = Mat3::Random();
    const Mat3 Sc = Vec3(1, 1, 1 / R).asDiagonal();
    const Mat3 G = Sc * (A * A.transpose() + Mat3::Identity()) * Sc;
    const Projection pr = project(s, w_t, 0.5 * (G + G.transpose()));
    ASSERT_TRUE(pr.converged) << trial;
    if (pr.inside) {
      EXPECT_LE(gauge(s, w_t).value, 1.0 + 1e-9);
      continue;
    }
    EXPECT_NEAR(gauge(s, pr.wrench).value, 1.0, 1e-8) << trial;
    const Vec3 w_n = surface_point(s, -pr.twist);
    EXPECT_LT(
        (Vec3(w_n[0], w_n[1], w_n[2] / R) - Vec3(pr.wrench[0], pr.wrench[1], pr.wrench[2] / R))
            .norm(),
        1e-7 * fN)
        << trial;
  }
}
