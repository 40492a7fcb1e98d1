// The general model of the closed loop: the fractional law or the exact integrals, extended by
// the catalogue of effects, each a parameter with a null value at which the effect vanishes.
//
//   y_c = yhat_c + offset_c + sum_{d != c} g_{c<-d} yhat_d                     (rig effects)
//   yhat = (1 - lambda) law(F0, a, M0, m, kx, ky, kappa, beta, w_s)
//          + lambda exact(F0, kx, ky, kappa, beta, w_s; profile)               (shape blend)
// at each row's own load and conditions:
//   F0_i = F0 rho_i phi_i, M0_i = M0 rho_i^(1 + q) phi_i, R_i = R rho_i^q,  rho_i = N_i / N_ref
//   (pressure in proportion to the load at fixed radius for q = 0; a patch that grows with the
//   load, R = R0 (N/N0)^q, for q != 0), and friction that follows recorded variables X_j,
//   phi_i = s prod_j (1 + b_j1 T1(z_ij) + b_j2 T2(z_ij)), z_ij = X_j of the row scaled to [-1, 1]
//   over the data (T1(z) = z, T2(z) = 2 z^2 - 1; s = 1, a fixed scale whose derivative gives
//   the score of any X);
// at the rig's kinematics: vy + vx tan(delta) (a slip-angle offset delta of the rig) and
// omega + omega_0 (a spin offset).
// Friction falling with slip speed: f(w) = f (1 - beta (1 - exp(-w / w_s))) (beta = 0: none);
// at the effective speed w_eff = (v^2 + (2u/3)^2)^(1/2) (the mean local slip speed of a
// spinning uniform patch), or, with speed_in_exact, at the local slip speed w inside the
// exact integrals.
// exact(.) has the force scale F0 = f p* 2 pi R^2 A^1; with no profile given, its profile is
// a Bernstein polynomial in s = rho^2 of degree n = 2 (or 4), p = sum_k w_k C(n,k) s^k (1-s)^(n-k)
// with w_0 = 1 and the weights w_1..w_n >= 0 identified: never negative, centre 1, rim w_n,
// uniform at w = 1.
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
  kProfileW1,
  kProfileW2,
  kProfileW3,
  kProfileW4,  // shape: the parametric profile's Bernstein weights (w3, w4: degree 4)
  kSlipAngleOffset,
  kSpinOffset,     // the rig's kinematics
  kPatchGrowth,    // q of R = R0 (N / N0)^q
  kFrictionScale,  // s: fixed at 1 (its Jacobian column scores friction_dependence)
  kDependence1,
  kDependence1Curve,
  kDependence2,
  kDependence2Curve,
  kDependence3,
  kDependence3Curve,  // b_j1, b_j2 of the friction_dependence slots
  kModelParameters
};

// How many recorded variables friction may follow at once (friction_dependence slots).
inline constexpr int kDependenceSlots = 3;
int dependence_parameter(int slot, bool curve);  // kDependence1 + 2 slot (+ 1)

// A variable friction may follow: the normal load, the time (or the row order when the data
// have no time), or a recorded column of the data (measured_data.hpp), scaled to [-1, 1] over
// the data: z = (x - mid) / half_range.
struct Covariate {
  enum class Kind { load, time, order, recorded };
  Kind kind = Kind::recorded;
  int recorded = -1;  // index into MeasuredData::recorded (Kind::recorded)
  std::string name;   // for reports: "Fz_N", "t_s", "row order", "T [degC]"
  std::string unit;   // SI unit of the values ("N", "s", "K"; "" for the order)
  double mid = 0.0, half_range = 1.0;
  // The variable at a row (NaN where the row has none).
  double value(const MeasuredPoint& p) const;
  // z at a row: 0 (the middle) where the row has no value.
  double scaled(const MeasuredPoint& p) const;
};

// What the model needs of a row besides its kinematics.
struct PointConditions {
  double load_ratio = 1.0;  // rho = N_i / N_ref (1 where the row has no load)
  std::array<double, kDependenceSlots> z{};
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
  // The parametric profile's Bernstein degree: 2 (weights w1, w2) or 4 (w1 to w4, the loop's
  // profile_detail step).
  int profile_degree = 2;
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
  // The reference load N_ref of rho_i = N_i / N_ref (the rows' Fz): F0 and M0 are at it. Unset:
  // every row at the one load normal_load_n (rho = 1).
  std::optional<double> reference_load_n;
  // The variable of each friction_dependence slot (unset: the slot is not used).
  std::array<std::optional<Covariate>, kDependenceSlots> dependence;
  // Derivatives with respect to the rig's kinematics and the patch's growth are wanted at their
  // null values too (the score test's Jacobian): the kinematics are differentiated always.
  bool differentiate_kinematics = false;

  bool uses_exact() const { return exact_only || free[kShapeBlend] || value[kShapeBlend] != 0.0; }
};

// A spec with every parameter at its null value and the law's parameters free.
ModelSpec base_model_spec(double radius_m, std::optional<double> normal_load_n);

// The fractional law part of the model at parameters theta (without the speed factor).
template <class T>
FractionalLaw<T> fractional_law_of(const ModelSpec& spec, const T* theta);

// A row's conditions under a spec (its load ratio and scaled variables).
PointConditions conditions_of(const ModelSpec& spec, const MeasuredPoint& p);

// Evaluates the model at kinematics k with parameters theta (all kModelParameters of them), at
// a row's conditions (default: the reference load, every variable in the middle).
template <class T>
Resultants<T> evaluate_model(const ModelSpec& spec, const T* theta, const Kinematics<double>& k,
                             const PointConditions& conditions = {});

}  // namespace contensou

#include "contensou/identification/effect_model_impl.hpp"
