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

template <class T>
Resultants<T> evaluate_model(const ModelSpec& s, const T* th, const Kinematics<double>& k) {
  using std::sqrt;
  const double R = s.radius_m;
  const T lambda = s.exact_only ? T(1.0) : th[kShapeBlend];
  Resultants<T> y{T(0.0), T(0.0), T(0.0)};
  if (!s.exact_only) {
    FractionalLaw<T> law = fractional_law_of(s, th);
    const double u = std::abs(k.omega) * R;
    const double w_eff = std::sqrt(k.vx * k.vx + k.vy * k.vy + (2.0 * u / 3.0) * (2.0 * u / 3.0));
    const T phi = detail::speed_factor(th[kSpeedDrop], th[kSpeedRef], T(w_eff));
    law.F0 *= phi;
    law.M0 *= phi;
    law.Mk *= phi;
    const Resultants<T> r = fractional_resultants(law, Kinematics<T>{T(k.vx), T(k.vy), T(k.omega)});
    const T wl = 1.0 - lambda;
    y = {wl * r.Fx, wl * r.Fy, wl * r.Mz};
  }
  if (s.uses_exact()) {
    // The exact law of the profile (exact_law_cache.hpp): one law, or the parametric profile's
    // three basis laws with coefficients (1 - b1 - b2, b1, b2). F0 = f p* R^2 L with f folded in.
    if (!s.exact_laws) throw std::logic_error("ModelSpec without exact laws (use base_model_spec)");
    const std::vector<ExactLaw>& laws = s.exact_laws->laws(s.speed_in_exact);
    std::array<T, 3> coef{T(1.0), T(0.0), T(0.0)};
    if (laws.size() == 3)
      coef = {1.0 - th[kProfileB1] - th[kProfileB2], th[kProfileB1], th[kProfileB2]};
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
      const Resultants<T> ri = exact_law_resultants(laws[i], p, k);
      r.Fx += coef[i] * ri.Fx;
      r.Fy += coef[i] * ri.Fy;
      r.Mz += coef[i] * ri.Mz;
    }
    // Without f(w) inside the integrals, the friction falls at the effective slip speed.
    T phi(1.0);
    if (!s.speed_in_exact) {
      const double u = std::abs(k.omega) * R;
      const double w_eff = std::sqrt(k.vx * k.vx + k.vy * k.vy + 4.0 * u * u / 9.0);
      phi = detail::speed_factor(th[kSpeedDrop], th[kSpeedRef], T(w_eff));
    }
    y.Fx += lambda * phi * r.Fx;
    y.Fy += lambda * phi * r.Fy;
    y.Mz += lambda * phi * r.Mz;
  }
  // Rig: offsets and crosstalk.
  const T base[3] = {y.Fx, y.Fy, y.Mz};
  T out[3];
  for (int c = 0; c < 3; ++c) {
    out[c] = base[c] + th[offset_parameter(c)];
    for (int d = 0; d < 3; ++d)
      if (d != c) out[c] += th[crosstalk_parameter(c, d)] * base[d];
  }
  return {out[0], out[1], out[2]};
}

}  // namespace contensou
