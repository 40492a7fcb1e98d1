// Pure sliding in closed form, with its first order in omega (theory.md sections 2 and 3): at
// omega = 0 every point slides with v, so F = -f(|v|) N D e_v and Mz = -f C3 (t_y kx - t_x ky);
// the first order in eps = |omega| R / |v| makes d/domega right there, and serves whenever its
// remainder c eps^2 f N is within a tenth of the tolerance (a far centre of sliding).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/error_budget.hpp"
#include "contensou/friction/impl/profile_representation.hpp"
#include "contensou/friction/impl/slip_speed_integrals.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// c of the first order's remainder, at most c eps^2 f N with c = kappa_max^2 (1 + |k|) (1 +
// delta^2 for a slip-speed law of exponent delta); 10^3 random kinematics per profile kind,
// kappa in [1/3, 3], gave at most 0.3 of that.
template <class T>
double first_order_remainder(const ExactModel<T>& m) {
  const double kappa_max = std::max(value_of(m.kappa), 1.0 / value_of(m.kappa));
  const double delta = m.slip_speed ? value_of(m.slip_speed->exponent) : 0.0;
  return kappa_max * kappa_max * (1.0 + std::hypot(value_of(m.kx), value_of(m.ky))) *
         (1.0 + delta * delta);
}

// Whether the first order in omega is within a tenth of the tolerance: c eps^2 < tol / 10,
// eps = |omega| R / |v| (or pure sliding, omega = 0). Switching there rather than at eps ~ tol
// keeps the derivatives smooth: the integrals about a centre 1/eps radii away lose their
// derivatives in omega to cancellation (5 % at eps = 2e-13, tolerance 1e-10).
inline bool first_order_suffices(double w_abs, double R, double speed, double tol,
                                 double remainder) {
  return w_abs == 0.0 || w_abs * R < std::sqrt(0.1 * tol / remainder) * speed;
}

// The sliding state at omega = 0: |v| and e_v = (ux, uy) from velocities scaled by their largest
// component, so that no square under- or overflows (|v| = 1e-200 or 1e200 is still pure
// sliding); f(|v|); the load N = p* 2 pi R^2 A^1 and C3 = p* pi R^3 A^3 of the representation.
template <class T>
struct PureSlide {
  T v, ux, uy;
  T mu;
  T N, C3;
};

template <class T>
PureSlide<T> pure_slide(const ExactModel<T>& m, const Kinematics<T>& k) {
  using std::sqrt;
  const double R = m.radius;
  const auto A = representation_moments(m);
  const double sv = std::max(std::abs(value_of(k.vx)), std::abs(value_of(k.vy)));
  const T sx = k.vx / sv, sy = k.vy / sv;
  const T n = sqrt(sx * sx + sy * sy);  // in [1, sqrt 2]: never 0
  PureSlide<T> s;
  s.v = sv * n;
  s.ux = sx / n;
  s.uy = sy / n;
  s.mu = m.slip_speed ? friction_at(*m.slip_speed, s.v) : m.friction;
  s.N = m.pressure * (2.0 * std::numbers::pi * R * R) * A[0];
  s.C3 = m.pressure * (std::numbers::pi * R * R * R) * A[1];  // p* pi R^3 A^3
  return s;
}

// The resultants at omega = 0 (theory.md section 2): traction direction t0 (per unit f sigma)
// D u, or D^2 u / |D u| for the associated law; F = -f N t0, Mz = -f C3 (t0_y kx - t0_x ky).
template <class T>
Resultants<T> pure_sliding_resultants(const ExactModel<T>& m, const PureSlide<T>& s) {
  using std::sqrt;
  const bool assoc = m.associated_orthotropy;
  const T hu = assoc ? T(sqrt(s.ux * s.ux + m.kappa * m.kappa * s.uy * s.uy)) : T(1.0);
  const T tx = s.ux / hu, ty = (assoc ? m.kappa * m.kappa : m.kappa) * s.uy / hu;
  Resultants<T> r;
  r.Fx = -s.mu * s.N * tx;
  r.Fy = -s.mu * s.N * ty;
  r.Mz = -s.mu * s.C3 * (ty * m.kx - tx * m.ky);
  return r;
}

// The plain numbers of the first order in omega: e_v, the shift k and its components along e_v
// (kv) and e_p = z x e_v (kp), C3, f / |v| (1/|v| capped at 1e300: below |v| = 1e-300 no
// derivative in omega is representable) and f'(|v|). Taken as plain numbers: their own
// derivatives (~ 1/|v|^2, which overflow for |v| ~ 1e-200) only enter multiplied by omega R
// << tol |v|.
struct FirstOrderTerms {
  double ux, uy, kappa, kx, ky, kv, kp, c3, fv, fp, R;
};

template <class T>
FirstOrderTerms first_order_terms(const ExactModel<T>& m, const PureSlide<T>& s) {
  FirstOrderTerms q;
  q.ux = value_of(s.ux);
  q.uy = value_of(s.uy);
  q.kappa = value_of(m.kappa);
  q.kx = value_of(m.kx);
  q.ky = value_of(m.ky);
  q.kv = q.kx * q.ux + q.ky * q.uy;
  q.kp = q.ky * q.ux - q.kx * q.uy;
  q.c3 = value_of(s.C3);
  q.fv = value_of(s.mu) * std::min(1.0 / value_of(s.v), 1e300);
  q.fp = m.slip_speed ? value_of(friction_slope_at(*m.slip_speed, s.v)) : 0.0;
  q.R = m.radius;
  return q;
}

// d{Fx, Fy, Mz}/domega at omega = 0 (theory.md section 2, vc/|vc| linearised about e_v):
//   vc/|vc| = e_v + (omega/|v|) (r.e_v) e_p,  |vc| = |v| - omega (r.e_p),
//   integral sigma r dS = C3 k,  integral sigma r r^T dS = C3 R I,
//   dF/domega  = -(f C3/|v|) (k.e_v) D e_p + f'(|v|) C3 (k.e_p) D e_v,
//   dMz/domega = -C3 R [(f/|v|) (kappa ux^2 + uy^2) + f'(|v|) (kappa uy^2 + ux^2)],
// D = diag(1, kappa).
inline std::array<double, 3> orthotropic_omega_slopes(const FirstOrderTerms& q) {
  const double ux = q.ux, uy = q.uy, kap = q.kappa, c3 = q.c3, fv = q.fv, fp = q.fp;
  return {c3 * (fv * q.kv * uy + fp * q.kp * ux), c3 * kap * (-fv * q.kv * ux + fp * q.kp * uy),
          -c3 * q.R * (fv * (kap * ux * ux + uy * uy) + fp * (kap * uy * uy + ux * ux))};
}

// The same for the associated law (tau = -f sigma D n, n = D vc/|D vc|): with h = |D u|,
// n = D u / h, P = I - n n^T, J = z x, d tau/d omega = -sigma [f/(|v| h) D P D J r + f' (J r.u)
// D n]:
//   dF/domega  = -(f C3/(|v| h)) D P D J k + f' C3 kp D n,
//   dMz/domega = -C3 R [(f/(|v| h)) tr(D P D) + f' h],  tr(D P D) = 1 + kappa^2 - |D n|^2.
inline std::array<double, 3> associated_omega_slopes(const FirstOrderTerms& q) {
  const double ux = q.ux, uy = q.uy, c3 = q.c3, fv = q.fv, fp = q.fp;
  const double k2 = q.kappa * q.kappa, kxv = q.kx, kyv = q.ky;
  const double h = std::sqrt(ux * ux + k2 * uy * uy);
  const double txv = ux / h, tyv = k2 * uy / h;
  const double cr = (k2 * uy * kxv - ux * kyv) / h;  // n . D J k
  return {-c3 * (fv / h) * (-kyv - txv * cr) + c3 * fp * q.kp * txv,
          -c3 * (fv / h) * (k2 * kxv - tyv * cr) + c3 * fp * q.kp * tyv,
          -c3 * q.R * ((fv / h) * (1.0 + k2 - txv * txv - tyv * tyv) + fp * h)};
}

// The resultants to first order in omega: R(omega = 0) + omega dR/domega. Its value is below
// the tolerance here, but it makes d/domega right (also at omega = 0).
template <class T>
Resultants<T> sliding_to_first_order(const ExactModel<T>& m, const Kinematics<T>& k) {
  const PureSlide<T> s = pure_slide(m, k);
  Resultants<T> r = pure_sliding_resultants(m, s);
  const FirstOrderTerms q = first_order_terms(m, s);
  const std::array<double, 3> d =
      m.associated_orthotropy ? associated_omega_slopes(q) : orthotropic_omega_slopes(q);
  r.Fx += k.omega * d[0];
  r.Fy += k.omega * d[1];
  r.Mz += k.omega * d[2];
  return r;
}

// The first order's remainder in the estimate: twice its bound, 2 c eps^2 f N on the forces
// (on top of the representation's), and that times R on the torque.
inline void add_first_order_remainder(ResultantErrors& e, double remainder, double eps,
                                      const ToleranceScale& s) {
  e.Fx += 2.0 * remainder * eps * eps * s.scale_F;
  e.Fy = e.Fx;
  e.Mz += e.Fx * s.R;
}

}  // namespace contensou::detail
