// Exact resultants of coupled sliding-spinning dry friction over a circular patch
// (theory.md section 2; seed eqs. 1-4), by adaptive cubature with an error estimate.
//
//   F  = integral_S tau dS,   Mz = integral_S (x tau_y - y tau_x) dS,
//   tau = -sigma(r) f(|vc|) diag(1, kappa) vc / |vc|,   vc = v + omega z x r.
//
// The integral is taken in polar coordinates (s, beta) about the instantaneous centre of
// sliding r_c = (-vy, vx)/omega, where vc/|vc| = sign(omega) z x e(beta) depends on beta alone:
//   F = -p* sign(omega) integral dbeta D (z x e) Q0(beta),   Q0 = integral f sigma/p* s ds,
// and the same with x, y weights for Mz. Inner integrals along a ray are Gauss-Legendre rules
// exact for the polynomial representation of p (or adaptive, for a Hertz edge or f(w)).
// Outer integrals: centre inside (|v| < |omega| R): four quarters of beta, each mapped by
// psi = b sinh(t), b = (R^2 - d^2)^(1/2)/d, which resolves the near-kink of the ray length at
// beta - gamma = +-pi/2 when the centre approaches the rim; centre outside: the wedge of rays
// that meet the disk, parametrised by the chord angle phi (sin theta = (R/d) sin phi, which
// removes the square root at the tangent rays) and mapped the same way near the tangents.
// omega = 0 (pure sliding) is in closed form.
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "contensou/adaptive_integration.hpp"
#include "contensou/contact_patch.hpp"
#include "contensou/error.hpp"
#include "contensou/kinematics.hpp"
#include "contensou/quadrature.hpp"
#include "contensou/scalar.hpp"

namespace contensou {

// The integration-ready form of a ContactPatch. Build it once (make_exact_model), evaluate
// many times: exact_resultants does no heap allocation.
template <class T = double>
struct ExactModel {
  double radius = 0.0;  // integration radius [m] (the positive part of a clipped profile)
  T pressure{};         // p* [Pa]
  T friction{};         // f (unused if slip_speed is set)
  T kappa{1.0};
  T kx{0.0}, ky{0.0};  // shift relative to `radius`
  // p = [sqrt(1 - t) if sqrt_edge] * sum_k chebyshev[k] T_k(2 t - 1), t = (r / radius)^2.
  std::vector<T> chebyshev;
  bool sqrt_edge = false;
  std::optional<SlipSpeedFriction<T>> slip_speed;
  GaussLegendreRule inner_rule;       // exact for the polynomial part along a ray
  double representation_error = 0.0;  // bound on |p - representation| (dimensionless)
  double load_area = 0.0;             // N / p* = 2 pi R^2 A^1 [m^2]
  double friction_scale = 0.0;        // f, or max(f_s, f_k)
};

// Builds the model: Chebyshev fit of p in t = rho^2 to 1e-15 (closed-form for uniform and
// Hertz), shrinking the disk to the positive part if a clipped profile is negative only
// near the rim. Validates the patch (throws InvalidArgument).
ExactModel<double> make_exact_model(const ContactPatch& patch);

// Casts a model to another scalar (e.g. ceres::Jet) with zero derivatives.
template <class T>
ExactModel<T> promote(const ExactModel<double>& m) {
  ExactModel<T> out;
  out.radius = m.radius;
  out.pressure = T(m.pressure);
  out.friction = T(m.friction);
  out.kappa = T(m.kappa);
  out.kx = T(m.kx);
  out.ky = T(m.ky);
  out.chebyshev.reserve(m.chebyshev.size());
  for (double c : m.chebyshev) out.chebyshev.push_back(T(c));
  out.sqrt_edge = m.sqrt_edge;
  if (m.slip_speed) {
    const auto& s = *m.slip_speed;
    out.slip_speed = SlipSpeedFriction<T>{T(s.static_coefficient), T(s.kinetic_coefficient),
                                          T(s.reference_speed), T(s.exponent)};
  }
  out.inner_rule = m.inner_rule;
  out.representation_error = m.representation_error;
  out.load_area = m.load_area;
  out.friction_scale = m.friction_scale;
  return out;
}

struct ExactOptions {
  // Requested accuracy, relative to f N for the forces and f N R for the torque.
  double tolerance = 1e-10;
};

template <class T = double>
struct ExactResult {
  Resultants<T> resultants;
  Resultants<double> error;  // estimated absolute error [N, N, N m]
  int evaluations = 0;       // rays evaluated (outer integrand evaluations)
  bool converged = true;     // false if the interval budget ran out before the tolerance
};

namespace detail {

// Clenshaw sum of a Chebyshev series in z = 2 t - 1.
template <class T>
T chebyshev_sum(const std::vector<T>& c, const T& t) {
  const T z = 2.0 * t - 1.0;
  T b1(0.0), b2(0.0);
  for (std::size_t k = c.size() - 1; k >= 1; --k) {
    const T b0 = c[k] + 2.0 * z * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + z * b1 - b2;
}

// A ray or chord: points r = origin + tau e, tau in [tau_a, tau_b]; distance from the centre
// of sliding s_c = s_offset + tau; the full chord through the disk is tau_mid +- half_chord.
template <class T>
struct Chord {
  T ox, oy, ex, ey;
  T tau_a, tau_b, s_offset, tau_mid, half_chord;
  double theta_a, theta_b;  // chord-angle range (values) for the adaptive inner rule
  T theta_a_t;              // theta_a with derivatives (interior rays)
};

template <class T>
using Moments3 = std::array<T, 3>;  // integral sigma s_c ds, with weights 1, x, y

template <class T>
Moments3<T> chord_moments(const ExactModel<T>& m, const Chord<T>& c, const T& abs_omega,
                          std::array<double, 3>& inner_error, const std::array<double, 3>& tol) {
  using std::cos;
  using std::sin;
  const double R = m.radius;
  Moments3<T> I{T(0.0), T(0.0), T(0.0)};
  inner_error = {0.0, 0.0, 0.0};
  if (!m.sqrt_edge && !m.slip_speed) {
    // Exact: sigma s_c x is a polynomial in tau of degree <= 2 deg(P) + 3. The Clenshaw
    // recurrence runs across a block of nodes at once: independent chains that vectorise.
    constexpr std::size_t kBlock = 32;
    const T mid = 0.5 * (c.tau_a + c.tau_b), half = 0.5 * (c.tau_b - c.tau_a);
    const std::size_t n = m.inner_rule.nodes.size(), deg = m.chebyshev.size() - 1;
    const T* cheb = m.chebyshev.data();
    for (std::size_t start = 0; start < n; start += kBlock) {
      const std::size_t len = std::min(kBlock, n - start);
      std::array<T, kBlock> x, y, z, b1, b2;
      for (std::size_t i = 0; i < len; ++i) {
        const T tau = mid + half * m.inner_rule.nodes[start + i];
        x[i] = c.ox + tau * c.ex;
        y[i] = c.oy + tau * c.ey;
        z[i] = 2.0 * (x[i] * x[i] + y[i] * y[i]) / (R * R) - 1.0;
        b1[i] = T(0.0);
        b2[i] = T(0.0);
      }
      for (std::size_t kk = deg; kk >= 1; --kk) {
        for (std::size_t i = 0; i < len; ++i) {
          const T b0 = cheb[kk] + 2.0 * z[i] * b1[i] - b2[i];
          b2[i] = b1[i];
          b1[i] = b0;
        }
      }
      for (std::size_t i = 0; i < len; ++i) {
        const double xi = m.inner_rule.nodes[start + i];
        const T sigma = (cheb[0] + z[i] * b1[i] - b2[i]) * (1.0 + (m.kx * x[i] + m.ky * y[i]) / R);
        const T v = (half * m.inner_rule.weights[start + i]) * sigma * (c.s_offset + mid + half * xi);
        I[0] += v;
        I[1] += v * x[i];
        I[2] += v * y[i];
      }
    }
    return I;
  }
  // Chord angle: tau = tau_mid + h sin(vartheta), so R^2 - |r|^2 = h^2 cos^2(vartheta).
  // vartheta = theta_a + (pi/2 ... ) mapped from xi in [0, 1] so that limits carry derivatives.
  const T th_a = c.theta_a_t;
  const T th_span = T(c.theta_b) - th_a;
  const T h = c.half_chord;
  auto f = [&](double xi, int) {
    Sample<T, 3> out;
    const T th = th_a + th_span * xi;
    const T cs = cos(th);
    const T tau = c.tau_mid + h * sin(th);
    const T x = c.ox + tau * c.ex, y = c.oy + tau * c.ey;
    const T edge = h * cs / R;  // sqrt(1 - t)
    const T t = 1.0 - edge * edge;
    T p = chebyshev_sum(m.chebyshev, t);
    if (m.sqrt_edge) p *= edge;
    const T sc = c.s_offset + tau;
    T v = p * (1.0 + (m.kx * x + m.ky * y) / R) * sc * (h * cs) * th_span;
    if (m.slip_speed) v *= friction_at(*m.slip_speed, abs_omega * sc);
    out.value = {v, v * x, v * y};
    return out;
  };
  const TaggedInterval whole{0.0, 1.0, 0};
  const auto r = integrate_adaptive<T, 3, 48>(f, &whole, 1, tol);
  inner_error = r.error;
  return r.value;
}

// Moments of the representation: {integral_0^1 p rho d rho, integral_0^1 p rho^3 d rho}.
template <class T>
std::array<T, 2> representation_moments(const ExactModel<T>& m) {
  // t = rho^2; with a sqrt edge substitute t = 1 - u^2 (dt = 2u du) to keep it polynomial.
  std::array<T, 2> a{T(0.0), T(0.0)};
  const auto& g = m.inner_rule;
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const double x = 0.5 * (1.0 + g.nodes[i]), w = 0.5 * g.weights[i];
    double t = x, jac = 1.0;
    if (m.sqrt_edge) {
      t = 1.0 - x * x;
      jac = 2.0 * x * x;  // sqrt(1 - t) = u, dt = 2 u du
    }
    const T p = chebyshev_sum(m.chebyshev, T(t)) * (w * jac);
    a[0] += 0.5 * p;
    a[1] += 0.5 * p * t;
  }
  return a;
}

}  // namespace detail

// Exact Fx, Fy, Mz for a model and kinematics, to the requested tolerance, with an error
// estimate. Throws InvalidArgument for non-finite velocities.
template <class T>
ExactResult<T> exact_resultants(const ExactModel<T>& m, const Kinematics<T>& k,
                                const ExactOptions& options = {}) {
  using std::abs;
  using std::asinh;
  using std::atan2;
  using std::cos;
  using std::cosh;
  using std::sin;
  using std::sinh;
  using std::sqrt;
  detail::require_finite("vx", value_of(k.vx));
  detail::require_finite("vy", value_of(k.vy));
  detail::require_finite("omega", value_of(k.omega));
  if (!(options.tolerance > 0.0) || !(options.tolerance < 1.0))
    throw InvalidArgument("tolerance", detail::format_value(options.tolerance),
                          "must lie in (0, 1)");
  const double R = m.radius;
  const double tol = std::max(options.tolerance, 1e-15);
  ExactResult<T> out;
  const double speed = std::hypot(value_of(k.vx), value_of(k.vy));
  const double w_abs = std::abs(value_of(k.omega));
  const double fscale = m.friction_scale;
  const double scale_F = fscale * value_of(m.pressure) * m.load_area;
  const double repr = m.representation_error * value_of(m.pressure) * fscale * std::numbers::pi *
                      R * R;  // bound on the load error of the representation
  out.error = {repr, repr, repr * R};

  if (speed == 0.0 && w_abs == 0.0) return out;

  // Pure sliding, or a centre so far that the spin is below the resolution of the result.
  if (w_abs == 0.0 || w_abs * R < 1e-3 * tol * speed) {
    const auto A = detail::representation_moments(m);
    const T v = sqrt(k.vx * k.vx + k.vy * k.vy);
    const T mu = m.slip_speed ? friction_at(*m.slip_speed, v) : m.friction;
    const T N = m.pressure * (2.0 * std::numbers::pi * R * R) * A[0];
    const T ux = k.vx / v, uy = k.vy / v;
    out.resultants.Fx = -mu * N * ux;
    out.resultants.Fy = -mu * N * m.kappa * uy;
    out.resultants.Mz = -mu * m.pressure * (std::numbers::pi * R * R * R) * A[1] *
                        (m.kappa * uy * m.kx - ux * m.ky);
    out.error.Fx += 2.0 * scale_F * w_abs * R / std::max(speed, 1e-300);
    out.error.Fy = out.error.Fx;
    out.error.Mz += out.error.Fx * R;
    return out;
  }

  const double sgn = value_of(k.omega) > 0.0 ? 1.0 : -1.0;
  const T abs_omega = sgn * k.omega;
  // Centre of sliding r_c = (-vy, vx) / omega, at distance d from O in direction g.
  const T rcx = -k.vy / k.omega, rcy = k.vx / k.omega;
  const T d = sqrt(rcx * rcx + rcy * rcy);
  const double dv = value_of(d);
  T gx(1.0), gy(0.0);
  if (dv > 0.0) {
    gx = rcx / d;
    gy = rcy / d;
  }
  // Tolerances in integrand units (the factor -f p* is applied at the end).
  const double unit = tol * m.load_area * (m.slip_speed ? fscale : 1.0);
  const std::array<double, 3> tol_out{unit, unit, unit * R};
  // Inner integrals are summed over at most 2 pi of beta: keep their share small.
  const double share = 1.0 / (40.0 * std::numbers::pi);
  const std::array<double, 3> tol_inner{unit * share, unit * share * R, unit * share * R};

  auto ray_contribution = [&](const detail::Chord<T>& ch, const T& jac) {
    detail::Sample<T, 3> s;
    std::array<double, 3> ie{};
    const auto I = detail::chord_moments(m, ch, abs_omega, ie, tol_inner);
    // u = sign(omega) z x e;  D u = (u_x, kappa u_y).
    const T ux = -sgn * ch.ey, uy = sgn * ch.ex * m.kappa;
    s.value = {ux * I[0] * jac, uy * I[0] * jac, (uy * I[1] - ux * I[2]) * jac};
    const double j = std::abs(value_of(jac));
    s.inner_error = {ie[0] * j, ie[1] * j, ie[2] * j};
    return s;
  };

  detail::AdaptiveResult<T, 3> res;
  if (dv < R) {
    // Interior centre: rays from r_c, theta = beta - gamma in four quarters about +-pi/2.
    const T delta2 = (R - d) * (R + d);
    const T delta = sqrt(delta2);
    const double b = dv > 0.0 ? value_of(delta) / dv : 2.0;
    const bool mapped = b < 1.0;
    const double t_end = mapped ? std::asinh(0.5 * std::numbers::pi / b) : 0.5 * std::numbers::pi;
    auto f = [&](double t, int quarter) {
      double ct, st, jpsi = 1.0;
      if (quarter >= 4) {  // plain theta = pi/2 + t
        ct = -std::sin(t);
        st = std::cos(t);
      } else {
        const double psi = mapped ? b * std::sinh(t) : t;
        jpsi = mapped ? b * std::cosh(t) : 1.0;
        const double sp = std::sin(psi), cp = std::cos(psi);
        // (cos theta, sin theta) for theta = pi/2 -+ psi, 3pi/2 -+ psi.
        ct = (quarter == 0 || quarter == 3) ? sp : -sp;
        st = (quarter <= 1) ? cp : -cp;
      }
      detail::Chord<T> ch;
      ch.ox = rcx;
      ch.oy = rcy;
      ch.ex = ct * gx - st * gy;
      ch.ey = ct * gy + st * gx;
      const T dc = d * ct;
      const T h = sqrt(delta2 + dc * dc);
      ch.tau_a = T(0.0);
      ch.tau_b = ct > 0.0 ? delta2 / (h + dc) : h - dc;
      ch.s_offset = T(0.0);
      ch.tau_mid = -dc;
      ch.half_chord = h;
      if (m.sqrt_edge || m.slip_speed) {
        ch.theta_a_t = atan2(dc, delta);
        ch.theta_a = value_of(ch.theta_a_t);
      }
      ch.theta_b = 0.5 * std::numbers::pi;
      return ray_contribution(ch, T(jpsi));
    };
    if (mapped) {
      const detail::TaggedInterval q[4] = {
          {0.0, t_end, 0}, {0.0, t_end, 1}, {0.0, t_end, 2}, {0.0, t_end, 3}};
      res = detail::integrate_adaptive<T, 3>(f, q, 4, tol_out);
    } else {
      // No near-kink: two halves theta in [0, pi], [pi, 2 pi] (tags 4, 5 -> theta = pi/2 + x).
      const detail::TaggedInterval q[2] = {{-0.5 * std::numbers::pi, 0.5 * std::numbers::pi, 4},
                                           {0.5 * std::numbers::pi, 1.5 * std::numbers::pi, 5}};
      res = detail::integrate_adaptive<T, 3>(f, q, 2, tol_out);
    }
  } else {
    // Exterior centre: chords of the wedge, phi = +-(pi/2 - psi), sin theta = (R/d) sin phi.
    const T eps2 = (d - R) * (d + R);
    const double b = std::max(std::sqrt(std::max(value_of(eps2), 0.0)) / R, 1e-7);
    const bool mapped = b < 1.0;
    const double t_end = mapped ? std::asinh(0.5 * std::numbers::pi / b) : 0.5 * std::numbers::pi;
    auto f = [&](double t, int half) {
      const double psi = mapped ? b * std::sinh(t) : t;
      const double jpsi = mapped ? b * std::cosh(t) : 1.0;
      const double cphi = std::sin(psi), sphi = half == 0 ? std::cos(psi) : -std::cos(psi);
      const T s_off = sqrt(eps2 + (R * cphi) * (R * cphi));  // d cos theta
      const T ct = s_off / d, st = (R / d) * sphi;
      // e = cos theta u0 + sin theta (z x u0), u0 = -g.
      detail::Chord<T> ch;
      ch.ex = -ct * gx + st * gy;
      ch.ey = -ct * gy - st * gx;
      ch.ox = -(R * sphi) * ch.ey;  // foot of the perpendicular: (R sin phi) z x e
      ch.oy = (R * sphi) * ch.ex;
      const double hc = R * cphi;
      ch.tau_a = T(-hc);
      ch.tau_b = T(hc);
      ch.s_offset = s_off;
      ch.tau_mid = T(0.0);
      ch.half_chord = T(hc);
      ch.theta_a = -0.5 * std::numbers::pi;
      ch.theta_a_t = T(ch.theta_a);
      ch.theta_b = 0.5 * std::numbers::pi;
      const T jac = (R * cphi) / s_off * jpsi;  // dtheta/dphi * dpsi/dt
      return ray_contribution(ch, jac);
    };
    const detail::TaggedInterval q[2] = {{0.0, t_end, 0}, {0.0, t_end, 1}};
    res = detail::integrate_adaptive<T, 3>(f, q, 2, tol_out);
  }
  const T factor = -(m.slip_speed ? T(1.0) : m.friction) * m.pressure;
  out.resultants.Fx = factor * res.value[0];
  out.resultants.Fy = factor * res.value[1];
  out.resultants.Mz = factor * res.value[2];
  const double fabs_ = std::abs(value_of(factor));
  out.error.Fx += fabs_ * res.error[0];
  out.error.Fy += fabs_ * res.error[1];
  out.error.Mz += fabs_ * res.error[2];
  out.evaluations = res.evaluations;
  out.converged = res.converged;
  return out;
}

// Convenience overload: builds the model (allocates) and evaluates it.
ExactResult<double> exact_resultants(const ContactPatch& patch, const Kinematics<double>& k,
                                     const ExactOptions& options = {});

}  // namespace contensou
