// The general model of the closed loop: the fractional law or the exact integrals, extended by
// the catalogue of effects, each a parameter with a null value at which the effect vanishes.
//
//   y_c = yhat_c + offset_c + sum_{d != c} g_{c<-d} yhat_d                     (rig effects)
//   yhat = (1 - lambda) law(F0, a, M0, m, kx, ky, kappa, beta, w_s)
//          + lambda exact(F0, kx, ky, kappa, beta, w_s; profile)               (shape blend)
// Friction falling with slip speed: f(w) = f (1 - beta (1 - exp(-w / w_s))) (beta = 0: none);
// at the effective speed w_eff = (v^2 + (2u/3)^2)^(1/2) (the mean local slip speed of a
// spinning uniform patch), or, with speed_in_exact, at the local slip speed w inside the
// exact integrals.
// exact(.) has the force scale F0 = f p* 2 pi R^2 A^1; with no profile given, its profile is
// p = 1 + b1 T1(2 rho^2 - 1) + b2 T2(2 rho^2 - 1) with b1, b2 identified.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/identification/exact_law_cache.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

enum ModelParameter : int {
  kF0,
  kA,
  kM0,
  kMShape,
  kKx,  // the fractional law
  kKy,
  kKappa,
  kSpeedDrop,
  kSpeedRef,  // physical effects
  kOffsetFx,
  kOffsetFy,
  kOffsetMz,  // channel offsets
  kXFxFy,
  kXFxMz,
  kXFyFx,
  kXFyMz,
  kXMzFx,
  kXMzFy,  // crosstalk g_{c<-d}
  kShapeBlend,
  kProfileB1,
  kProfileB2,  // shape
  kModelParameters
};

// Name, unit and null value of each parameter.
struct ParameterInfo {
  const char* name;
  const char* unit;
  double null_value;
};
const ParameterInfo& parameter_info(int index);
int parameter_index_by_name(const std::string& name);  // -1 if unknown
int offset_parameter(int channel);                     // kOffsetFx + channel
// The range that keeps a parameter physical (+-inf where it is open): what the fit enforces.
struct ParameterBounds {
  double lower, upper;
  bool closed() const { return std::isfinite(lower) && std::isfinite(upper); }
};
ParameterBounds parameter_bounds(int index);
int crosstalk_parameter(int channel, int source);  // g_{channel <- source}

struct ModelSpec {
  double radius_m = 0.0;
  std::optional<double> normal_load_n;
  // Constants of the law the diagrams do not identify (cross-shift shapes).
  double c = 4.0, a_k = 1.0, mk_ratio = 0.375;
  // The exact integrals over the given profile (unset: the parametric profile).
  std::optional<ExactModel<double>> profile_model;
  // The exact law of the profile (set with the profile by base_spec_for, or on first use).
  std::shared_ptr<ExactLawCache> exact_laws;
  // The profile's asymptote-matched law constants (reported with the exact model): a, m, M0/(F0 R).
  double profile_a = 1.0, profile_m = 64.0 / 9.0, profile_m0_ratio = 2.0 / 3.0;
  bool exact_only = false;      // the law is replaced by the exact integrals (lambda = 1)
  bool speed_in_exact = false;  // f(w) at the local slip speed inside the exact integrals
  std::array<bool, kModelParameters> free{};     // parameters being estimated
  std::array<double, kModelParameters> value{};  // their values (start or fixed)
  double exact_tolerance = 1e-6;                 // relative to f N: far below any measurement noise
  double regularization_speed = 1e-6;

  bool uses_exact() const { return exact_only || free[kShapeBlend] || value[kShapeBlend] != 0.0; }
};

// A spec with every parameter at its null value and the law's parameters free.
ModelSpec base_model_spec(double radius_m, std::optional<double> normal_load_n);

// The fractional law part of the model at parameters theta (without the speed factor).
template <class T>
FractionalLaw<T> fractional_law_of(const ModelSpec& spec, const T* theta);

// Evaluates the model at kinematics k with parameters theta (all kModelParameters of them).
template <class T>
Resultants<T> evaluate_model(const ModelSpec& spec, const T* theta, const Kinematics<double>& k);

}  // namespace contensou

#include "contensou/identification/effect_model_impl.hpp"
