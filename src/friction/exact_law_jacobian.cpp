// The exact law's Jacobian d(Fx, Fy, Mz)/d(vx, vy, omega) (exact_law.hpp): the template's
// formula differentiated by hand, each intermediate carried with its gradient in the scaled
// velocities (vx, vy, omega R) / s. The same numbers as the template evaluated with
// ForwardDerivative<3> (a test compares them), at a fraction of its cost.
#include <array>
#include <cmath>

#include "contensou/friction/exact_law.hpp"

namespace contensou {

namespace {

// A value with its gradient in the three scaled velocities. No default values: the six
// functions' array is written whole by friction_functions, and zeroing it first cost a
// rep stos per call.
struct Scalar {
  double a;
  std::array<double, 3> d;
};

Scalar operator*(const Scalar& x, const Scalar& y) {
  return {x.a * y.a,
          {x.d[0] * y.a + x.a * y.d[0], x.d[1] * y.a + x.a * y.d[1], x.d[2] * y.a + x.a * y.d[2]}};
}
Scalar operator*(double c, const Scalar& x) {
  return {c * x.a, {c * x.d[0], c * x.d[1], c * x.d[2]}};
}
Scalar operator+(const Scalar& x, const Scalar& y) {
  return {x.a + y.a, {x.d[0] + y.d[0], x.d[1] + y.d[1], x.d[2] + y.d[2]}};
}
Scalar operator-(const Scalar& x, const Scalar& y) {
  return {x.a - y.a, {x.d[0] - y.d[0], x.d[1] - y.d[1], x.d[2] - y.d[2]}};
}

// The kinematic intermediates of exact_law_resultants with their gradients.
struct Kinematic {
  Scalar ex, ey, xi_x, xi_y, t, speed;  // speed: S = |v| + |omega| R (scaled)
  double sgn = 1.0;
};

Kinematic kinematic(double vx, double vy, double w) {
  Kinematic k;
  const double v2 = vx * vx + vy * vy;
  double v, ex = 1.0, ey = 0.0;
  std::array<double, 3> dex{}, dey{}, dv{};
  if (v2 > 1e-300) {
    v = std::sqrt(v2);
    ex = vx / v;
    ey = vy / v;
    dex = {(1.0 - ex * ex) / v, -ex * ey / v, 0.0};  // d e / d v = (I - e e') / |v|
    dey = {-ex * ey / v, (1.0 - ey * ey) / v, 0.0};
    dv = {ex, ey, 0.0};
  } else {  // |v| to first order along e = x (exact_law_resultants)
    v = std::abs(vx);
    dv = {vx < 0.0 ? -1.0 : 1.0, 0.0, 0.0};
  }
  k.sgn = w < 0.0 ? -1.0 : 1.0;
  const double S = v + k.sgn * w, iS = 1.0 / S;
  const std::array<double, 3> dS{dv[0], dv[1], k.sgn};
  k.ex = {ex, dex};
  k.ey = {ey, dey};
  k.speed = {S, dS};
  const double sigma = v * iS;
  k.t = {2.0 * sigma - 1.0, {}};
  for (int i = 0; i < 3; ++i) k.t.d[i] = 2.0 * (dv[i] - sigma * dS[i]) * iS;
  k.xi_x = {vx * iS, {}};
  k.xi_y = {vy * iS, {}};
  for (int i = 0; i < 3; ++i) {
    k.xi_x.d[i] = ((i == 0 ? 1.0 : 0.0) - k.xi_x.a * dS[i]) * iS;
    k.xi_y.d[i] = ((i == 1 ? 1.0 : 0.0) - k.xi_y.a * dS[i]) * iS;
  }
  return k;
}

// G_i = f g_i(t), or f_k g_i(t) + (f_s - f_k) h_i(t, z), z = (S s / w_s)^delta (s the scale),
// with gradients through t and S.
void friction_functions(const ExactLaw& law, const ExactLawParameters<double>& p,
                        const Kinematic& k, double scale, Scalar* G) {
  double g[kLawFunctions], gt[kLawFunctions];
  evaluate_chebyshev_fast(law.table, k.t.a, g, gt);
  double cg = p.friction, ch = 0.0, z = 0.0;
  double h[kLawFunctions] = {}, ht[kLawFunctions] = {}, hz[kLawFunctions] = {};
  if (p.slip_speed) {
    const SlipSpeedFriction<double>& f = *p.slip_speed;
    if (!law.falling || f.exponent != law.falling->exponent) {  // the template's errors
      double unused[kLawFunctions];
      detail::friction_functions(law, p, k.t.a, k.speed.a * scale, unused);
    }
    cg = f.kinetic_coefficient;
    ch = f.static_coefficient - f.kinetic_coefficient;
    const double q = k.speed.a * scale / f.reference_speed;
    z = f.exponent == 1.0 ? q : std::pow(q, f.exponent);
    detail::falling_values<true>(*law.falling, k.t.a, z, h, ht, hz);
  }
  // dz = delta z dS / S
  const double dz_dS = p.slip_speed ? p.slip_speed->exponent * z / k.speed.a : 0.0;
  for (int i = 0; i < kLawFunctions; ++i) {
    const double dt = cg * gt[i] + ch * ht[i], dS = ch * hz[i] * dz_dS;
    G[i].a = cg * g[i] + ch * h[i];
    for (int j = 0; j < 3; ++j) G[i].d[j] = dt * k.t.d[j] + dS * k.speed.d[j];
  }
}

}  // namespace

ExactLawWithJacobian exact_law_resultants_with_jacobian(const ExactLaw& law,
                                                        const ExactLawParameters<double>& p,
                                                        const Kinematics<double>& k0) {
  require_finite("vx", k0.vx);
  require_finite("vy", k0.vy);
  require_finite("omega", k0.omega);
  ExactLawWithJacobian out;
  out.jacobian.setZero();
  const double radius = law.radius;
  const double scale = std::max({std::abs(k0.vx), std::abs(k0.vy), std::abs(k0.omega) * radius});
  if (!(scale > 1e-290)) return out;  // rest (exact_law_resultants)
  const double inv = 1.0 / scale;
  const Kinematic k = kinematic(k0.vx * inv, k0.vy * inv, k0.omega * radius * inv);
  Scalar G[kLawFunctions];
  friction_functions(law, p, k, scale, G);
  const double s = k.sgn, kx = p.kx, ky = p.ky, kappa = p.kappa;
  // The formulas of exact_law_resultants.
  const Scalar kperp = ky * k.ex - kx * k.ey;
  const Scalar along = G[kLawSlide] + s * (G[kLawSpinSum] * kperp);
  const Scalar spin = s * G[kLawSpin];
  const double pN = p.pressure * (radius * radius * law.load_area);
  const Scalar Fx = -pN * (along * k.xi_x - ky * spin);
  const Scalar Fy = (-pN * kappa) * (along * k.xi_y + kx * spin);
  const Scalar spin_torque =
      (1.0 + kappa) * spin - s * (G[kLawSpinSum] * (k.xi_x * k.ex + kappa * (k.xi_y * k.ey)));
  const Scalar shift_torque =
      (0.5 * (1.0 + kappa)) * (G[kLawShiftDiff] * (ky * k.xi_x - kx * k.xi_y)) +
      (0.5 * (kappa - 1.0)) *
          (G[kLawShiftCross] * (kx * k.xi_y + ky * k.xi_x) +
           (G[kLawShiftSum] - G[kLawShiftCross]) * ((k.xi_x * k.ex - k.xi_y * k.ey) * kperp));
  const Scalar Mz = (-pN * radius) * (spin_torque + shift_torque);
  out.resultants = {Fx.a, Fy.a, Mz.a};
  // From the scaled velocities (vx, vy, omega R) / s to (vx, vy, omega).
  const double col[3] = {inv, inv, radius * inv};
  for (int j = 0; j < 3; ++j) {
    out.jacobian(0, j) = Fx.d[j] * col[j];
    out.jacobian(1, j) = Fy.d[j] * col[j];
    out.jacobian(2, j) = Mz.d[j] * col[j];
  }
  return out;
}

ExactLawWithJacobian exact_law_resultants_with_jacobian(const ExactLaw& law,
                                                        const Kinematics<double>& k) {
  return exact_law_resultants_with_jacobian(law, law.parameters, k);
}

}  // namespace contensou
