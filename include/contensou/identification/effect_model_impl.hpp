// Implementation of evaluate_model (templated for ceres::Jet).
#pragma once

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace contensou {

namespace detail {

// Chebyshev series integral: A^1 = (1/2) integral_0^1 P(t) dt, integral of T_k(2t - 1) over
// [0, 1] = 1 / (1 - k^2) for even k, 0 for odd k.
template <class T>
T first_moment(const std::vector<T>& c) {
  T s(0.0);
  for (std::size_t k = 0; k < c.size(); k += 2) s += c[k] / (1.0 - static_cast<double>(k * k));
  return 0.5 * s;
}

// Friction falling with slip speed, relative to its value at rest: 1 - beta (1 - e^(-w/w_s)).
template <class T>
T speed_factor(const T& beta, const T& w_ref, const T& w) {
  using std::exp;
  return 1.0 - beta * (1.0 - exp(-w / w_ref));
}

// The parametric profile (no --profile) as a Bernstein polynomial in s = rho^2 (x = 2 s - 1):
// p = sum_k w_k B_{k,n}(s), w_0 = 1, B_{k,n} = C(n,k) s^k (1 - s)^(n-k), never negative for
// w_k >= 0 (centre w_0, rim w_n). In Chebyshev terms p = sum_j c_j T_j(x), c = M_n w with
// (rows j, columns k; B_{k,n} expanded in T_j(2 s - 1))
//   n = 2: [3/8 1/4 3/8; -1/2 0 1/2; 1/8 -1/4 1/8]
//   n = 4: [35/128 5/32 9/64 5/32 35/128; -7/16 -1/8 0 1/8 7/16; 7/32 -1/8 -3/16 -1/8 7/32;
//           -1/16 1/8 0 -1/8 1/16; 1/128 -1/32 3/64 -1/32 1/128].
// Returned as the coefficients of the basis laws 1, 1 + T1, ..., 1 + Tn (exact_law_cache.hpp):
// (c0 - c1 - ... - cn, c1, ..., cn); entries past n are zero.
template <class T>
std::array<T, 5> parametric_profile_coefficients(const T* th, int degree) {
  static constexpr double kM2[3][3] = {
      {3.0 / 8, 1.0 / 4, 3.0 / 8}, {-1.0 / 2, 0.0, 1.0 / 2}, {1.0 / 8, -1.0 / 4, 1.0 / 8}};
  static constexpr double kM4[5][5] = {{35.0 / 128, 5.0 / 32, 9.0 / 64, 5.0 / 32, 35.0 / 128},
                                       {-7.0 / 16, -1.0 / 8, 0.0, 1.0 / 8, 7.0 / 16},
                                       {7.0 / 32, -1.0 / 8, -3.0 / 16, -1.0 / 8, 7.0 / 32},
                                       {-1.0 / 16, 1.0 / 8, 0.0, -1.0 / 8, 1.0 / 16},
                                       {1.0 / 128, -1.0 / 32, 3.0 / 64, -1.0 / 32, 1.0 / 128}};
  const int n = degree == 4 ? 4 : 2;
  const T w[5] = {T(1.0), th[kProfileW1], th[kProfileW2], th[kProfileW3], th[kProfileW4]};
  std::array<T, 5> c{T(0.0), T(0.0), T(0.0), T(0.0), T(0.0)};
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= n; ++k) c[j] += (n == 4 ? kM4[j][k] : kM2[j][k]) * w[k];
  T first = c[0];
  for (int j = 1; j <= n; ++j) first -= c[j];
  c[0] = first;
  return c;
}

}  // namespace detail

template <class T>
FractionalLaw<T> fractional_law_of(const ModelSpec& s, const T* th) {
  FractionalLaw<T> law;
  law.F0 = th[kF0];
  law.a = th[kA];
  law.M0 = th[kM0];
  law.m = th[kMShape];
  law.kx = th[kKx];
  law.ky = th[kKy];
  law.kappa = th[kKappa];
  law.c = T(s.c);
  law.a_k = T(s.a_k);
  law.Mk = th[kM0] * s.mk_ratio;
  law.radius = s.radius_m;
  law.regularization_speed = s.regularization_speed;
  return law;
}

namespace detail {

// The friction factor of a row, s rho prod_j (1 + b_j1 T1(z_j) + b_j2 T2(z_j)) (effect_model.hpp).
template <class T>
T friction_factor(const ModelSpec& s, const T* th, const PointConditions& c) {
  T phi = th[kFrictionScale] * c.load_ratio;
  for (int j = 0; j < kDependenceSlots; ++j) {
    if (!s.dependence[j]) continue;
    const double z = c.z[j];
    phi *= 1.0 + th[dependence_parameter(j, false)] * z +
           th[dependence_parameter(j, true)] * (2.0 * z * z - 1.0);
  }
  return phi;
}

// The effective slip speed (v^2 + (2u/3)^2)^(1/2), u = |omega| R: the mean local slip speed of
// a spinning uniform patch.
template <class K>
K effective_speed(const Kinematics<K>& k, double R) {
  using std::abs;
  using std::sqrt;
  const K u = abs(k.omega) * R;
  return sqrt(k.vx * k.vx + k.vy * k.vy + (2.0 * u / 3.0) * (2.0 * u / 3.0));
}

// The friction part of the model (before the rig's offsets and crosstalk) at kinematics k of
// scalar K (double, or T when the rig's kinematics or the patch's growth are differentiated),
// with friction factor phi; the patch's radius is R g (the torque scales with g, u = omega R g
// is in k already).
template <class T, class K>
Resultants<T> friction_part(const ModelSpec& s, const T* th, const Kinematics<K>& k, const T& phi,
                            const T& g) {
  const double R = s.radius_m;
  const T lambda = s.exact_only ? T(1.0) : th[kShapeBlend];
  Resultants<T> y{T(0.0), T(0.0), T(0.0)};
  if (!s.exact_only) {
    FractionalLaw<T> law = fractional_law_of(s, th);
    const T speed = phi * speed_factor(th[kSpeedDrop], th[kSpeedRef], T(effective_speed(k, R)));
    law.F0 *= speed;
    law.M0 *= speed;
    law.Mk *= speed;
    const Resultants<T> r = fractional_resultants(law, Kinematics<T>{T(k.vx), T(k.vy), T(k.omega)});
    const T wl = 1.0 - lambda;
    y = {wl * r.Fx, wl * r.Fy, wl * r.Mz * g};
  }
  if (s.uses_exact()) {
    // The exact law of the profile (exact_law_cache.hpp): one law, or three or five basis laws
    // (the parametric profile's, or a corrected given profile's: parametric_profile_coefficients).
    // F0 = f p* R^2 L with f folded in.
    if (!s.exact_laws) throw std::logic_error("ModelSpec without exact laws (use base_model_spec)");
    const std::vector<ExactLaw>& laws = s.exact_laws->laws(s.speed_in_exact, {}, s.law_degree());
    std::array<T, 5> coef{T(1.0), T(0.0), T(0.0), T(0.0), T(0.0)};
    if (laws.size() > 1)
      coef = detail::parametric_profile_coefficients(th, laws.size() == 5 ? 4 : 2);
    T load(0.0);
    for (std::size_t i = 0; i < laws.size(); ++i) load += coef[i] * laws[i].load_area;
    const double Rl = laws.front().radius;
    ExactLawParameters<T> p;
    p.pressure = th[kF0] / (Rl * Rl * load);
    p.friction = T(1.0);
    p.kappa = th[kKappa];
    p.kx = th[kKx] * (Rl / R);
    p.ky = th[kKy] * (Rl / R);
    if (s.speed_in_exact) {
      // f(w) = 1 - beta (1 - exp(-w / w_s)): the law's Stribeck form with exponent 1.
      p.slip_speed = SlipSpeedFriction<T>{T(1.0), 1.0 - th[kSpeedDrop], th[kSpeedRef], T(1.0)};
    }
    Resultants<T> r{T(0.0), T(0.0), T(0.0)};
    for (std::size_t i = 0; i < laws.size(); ++i) {
      const auto ri = exact_law_resultants(laws[i], p, k);
      r.Fx += coef[i] * ri.Fx;
      r.Fy += coef[i] * ri.Fy;
      r.Mz += coef[i] * ri.Mz;
    }
    // Without f(w) inside the integrals, the friction falls at the effective slip speed.
    T speed = phi;
    if (!s.speed_in_exact)
      speed *= speed_factor(th[kSpeedDrop], th[kSpeedRef], T(effective_speed(k, R)));
    y.Fx += lambda * speed * r.Fx;
    y.Fy += lambda * speed * r.Fy;
    y.Mz += lambda * speed * r.Mz * g;
  }
  return y;
}

// Whether the rig's kinematics or the patch's growth take part (else the measured kinematics
// are used as doubles: the model's cost without them).
inline bool kinematics_vary(const ModelSpec& s, const PointConditions& c) {
  const auto used = [&](int i) { return s.free[i] || s.value[i] != parameter_info(i).null_value; };
  return s.differentiate_kinematics || used(kSlipAngleOffset) || used(kSpinOffset) ||
         used(kCentreX) || used(kCentreY) || used(kContactRatio) ||
         (c.load_ratio != 1.0 && used(kPatchGrowth));
}

}  // namespace detail

template <class T>
Resultants<T> evaluate_model(const ModelSpec& s, const T* th, const Kinematics<double>& k,
                             const PointConditions& c) {
  using std::pow;
  using std::tan;
  const T phi = detail::friction_factor(s, th, c);
  Resultants<T> y;
  if (!detail::kinematics_vary(s, c)) {
    y = detail::friction_part(s, th, k, phi, T(1.0));
  } else {
    // The rig's kinematics: vy + vx tan(delta), omega + omega_0; the patch R g with
    // g = c_R rho^q, so u = omega R g and the torque arm scales with g; its centre at
    // (x_c, y_c): sliding v + omega z x c there, torque Mz + x_c Fy - y_c Fx about the body's.
    const T g =
        (c.load_ratio == 1.0 ? T(1.0) : pow(T(c.load_ratio), th[kPatchGrowth])) * th[kContactRatio];
    const T omega = T(k.omega) + th[kSpinOffset];
    const T xc = th[kCentreX] * s.radius_m, yc = th[kCentreY] * s.radius_m;
    const Kinematics<T> kt{T(k.vx) - omega * yc,
                           T(k.vy) + T(k.vx) * tan(th[kSlipAngleOffset]) + omega * xc, omega * g};
    y = detail::friction_part(s, th, kt, phi, g);
    y.Mz += xc * y.Fy - yc * y.Fx;
  }
  // Rig: offsets and crosstalk.
  const T base[3] = {y.Fx, y.Fy, y.Mz};
  T out[3];
  for (int ch = 0; ch < 3; ++ch) {
    out[ch] = base[ch] + th[offset_parameter(ch)];
    for (int d = 0; d < 3; ++d)
      if (d != ch) out[ch] += th[crosstalk_parameter(ch, d)] * base[d];
  }
  return {out[0], out[1], out[2]};
}

}  // namespace contensou
