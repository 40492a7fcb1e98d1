/// \file
/// The general model of the closed loop: the fractional law or the exact integrals, extended by
/// the catalogue of effects, each a parameter with a null value at which the effect vanishes.
///
/// ~~~
///   y_c = yhat_c + offset_c + sum_{d != c} g_{c<-d} yhat_d                     (rig effects)
///   yhat = (1 - lambda) law(F0, a, M0, m, kx, ky, kappa, beta, w_s)
///          + lambda exact(F0, kx, ky, kappa, beta, w_s; profile)               (shape blend)
/// ~~~
/// at each row's own load and conditions:
/// ~~~
///   F0_i = F0 rho_i phi_i, M0_i = M0 rho_i^(1 + q) phi_i, R_i = R rho_i^q,  rho_i = N_i / N_ref
/// ~~~
/// (pressure in proportion to the load at fixed radius for q = 0; a patch that grows with the
/// load, R = R0 (N/N0)^q, for q != 0), and friction that follows recorded variables X_j,
/// phi_i = s prod_j (1 + b_j1 T1(z_ij) + b_j2 T2(z_ij)), z_ij = X_j of the row scaled to [-1, 1]
/// over the data (T1(z) = z, T2(z) = 2 z^2 - 1; s = 1, a fixed scale whose derivative gives
/// the score of any X);
/// at the rig's kinematics: vy + vx tan(delta) (a slip-angle offset delta of the rig) and
/// omega + omega_0 (a spin offset); on a patch whose centre sits at c = (x_c, y_c) = R (centre_x,
/// centre_y) off the body's (its sliding velocity v + omega z x c, its torque about the body's
/// centre Mz + x_c Fy - y_c Fx) and whose radius is c_R R (contact_ratio c_R <= 1: the given
/// radius an upper bound; spin enters as omega c_R R and the torque scales with c_R, as the
/// patch's growth's R_i).
/// Friction falling with slip speed: f(w) = f (1 - beta (1 - exp(-w / w_s))) (beta = 0: none);
/// at the effective speed w_eff = (v^2 + (2u/3)^2)^(1/2) (the mean local slip speed of a
/// spinning uniform patch), or, with speed_in_exact, at the local slip speed w inside the
/// exact integrals (the law's part stays at w_eff).
/// exact(.) has the force scale F0 = f p* 2 pi R^2 A^1; with no profile given, its profile is
/// a Bernstein polynomial in s = rho^2 of degree n = 2 (or 4),
/// p = sum_k w_k C(n,k) s^k (1-s)^(n-k) with w_0 = 1 and the weights w_1..w_n >= 0 identified:
/// never negative, centre 1, rim w_n, uniform at w = 1.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "contensou/identification/exact_law_cache.hpp"
#include "contensou/identification/measured_data.hpp"
#include "contensou/identification/rigid_patch.hpp"

namespace contensou {

/// The index of each parameter of the general model in its parameter vector theta (all
/// kModelParameters of them). Names and units: parameter_info.
enum ModelParameter : int {
  kF0,                ///< F0_N: the sliding force scale f N [N] (at the reference load)
  kA,                 ///< a: the law's sliding shape
  kM0,                ///< M0_Nm: the spin torque scale [N m] (at the reference load)
  kMShape,            ///< m: the law's spin shape
  kKx,                ///< kx: pressure shift along x (the last of the fractional law's five)
  kKy,                ///< ky: pressure shift along y (null 0)
  kKappa,             ///< kappa: lateral / longitudinal friction ratio (null 1)
  kSpeedDrop,         ///< speed_drop: beta of f(w) (null 0)
  kSpeedRef,          ///< speed_ref_mps: w_s of f(w) [m/s]
  kOffsetFx,          ///< offset_Fx_N: constant added to Fx [N]
  kOffsetFy,          ///< offset_Fy_N: constant added to Fy [N]
  kOffsetMz,          ///< offset_Mz_Nm: constant added to Mz [N m]
  kXFxFy,             ///< crosstalk_Fx_from_Fy: g of Fx picking up Fy
  kXFxMz,             ///< crosstalk_Fx_from_Mz: g of Fx picking up Mz [1/m]
  kXFyFx,             ///< crosstalk_Fy_from_Fx: g of Fy picking up Fx
  kXFyMz,             ///< crosstalk_Fy_from_Mz: g of Fy picking up Mz [1/m]
  kXMzFx,             ///< crosstalk_Mz_from_Fx: g of Mz picking up Fx [m]
  kXMzFy,             ///< crosstalk_Mz_from_Fy: g of Mz picking up Fy [m]
  kShapeBlend,        ///< shape_blend: lambda, the exact integrals' share (null 0)
  kProfileW1,         ///< profile_w1: Bernstein weight w1 of the parametric profile (null 1)
  kProfileW2,         ///< profile_w2: Bernstein weight w2 (null 1)
  kProfileW3,         ///< profile_w3: Bernstein weight w3 (degree 4 only; null 1)
  kProfileW4,         ///< profile_w4: Bernstein weight w4 (degree 4 only; null 1)
  kSlipAngleOffset,   ///< slip_angle_offset_rad: the rig's slip-angle offset delta [rad]
  kSpinOffset,        ///< spin_offset_radps: the rig's spin offset omega_0 [rad/s]
  kPatchGrowth,       ///< patch_growth_q: q of R = R0 (N / N0)^q (null 0)
  kFrictionScale,     ///< friction_scale: s, fixed at 1 (its column scores friction_dependence)
  kDependence1,       ///< friction_b1_1: b1 of the first friction_dependence slot (null 0)
  kDependence1Curve,  ///< friction_b2_1: b2 of the first slot (null 0)
  kDependence2,       ///< friction_b1_2: b1 of the second slot (null 0)
  kDependence2Curve,  ///< friction_b2_2: b2 of the second slot (null 0)
  kDependence3,       ///< friction_b1_3: b1 of the third slot (null 0)
  kDependence3Curve,  ///< friction_b2_3: b2 of the third slot (null 0)
  kCentreX,           ///< centre_x: the patch's centre off the body's, x_c / R (null 0)
  kCentreY,           ///< centre_y: the same along y, y_c / R (null 0)
  kContactRatio,      ///< contact_ratio: the contact's radius over the body's, c (null 1)
  kModelParameters    ///< the number of parameters
};

/// How many recorded variables friction may follow at once (friction_dependence slots).
inline constexpr int kDependenceSlots = 3;
/// The parameter b1 (or, with `curve`, b2) of friction_dependence slot `slot` (0-based):
/// kDependence1 + 2 slot (+ 1).
int dependence_parameter(int slot, bool curve);

/// A variable friction may follow: the normal load, the time (or the row order when the data
/// have no time), or a recorded column of the data (measured_data.hpp), scaled to [-1, 1] over
/// the data: z = (x - mid) / half_range.
struct Covariate {
  /// Where the variable's values come from.
  enum class Kind {
    load,     ///< the row's normal load Fz [N]
    time,     ///< the row's time [s]
    order,    ///< the row's place in the data: its file's index, then its line
    recorded  ///< a recorded column (MeasuredData::recorded)
  };
  Kind kind = Kind::recorded;  ///< where the values come from
  int recorded = -1;           ///< index into MeasuredData::recorded (Kind::recorded)
  std::string name;            ///< for reports: "Fz_N", "t_s", "row order", "T [degC]"
  std::string unit;            ///< SI unit of the values ("N", "s", "K"; "" for the order)
  double mid = 0.0,            ///< the middle of the data's range, in `unit`
      half_range = 1.0;        ///< half the data's range, in `unit`
  /// The variable at a row (NaN where the row has none).
  double value(const MeasuredPoint& p) const;
  /// z at a row, clamped to [-1, 1]: 0 (the middle) where the row has no value.
  double scaled(const MeasuredPoint& p) const;
};

/// What the model needs of a row besides its kinematics.
struct PointConditions {
  double load_ratio = 1.0;                   ///< rho = N_i / N_ref (1 where the row has no load)
  std::array<double, kDependenceSlots> z{};  ///< z of each friction_dependence slot (0: unused)
};

/// Name, unit and null value of each parameter.
struct ParameterInfo {
  const char* name;   ///< as in `--fix` and the JSON report ("F0_N", "kappa")
  const char* unit;   ///< "N", "N m", "m/s", "rad", "1", ...
  double null_value;  ///< the value at which its effect vanishes (base_model_spec starts there)
};
/// The info of parameter `index` (a ModelParameter). Throws InvalidArgument outside
/// [0, kModelParameters).
const ParameterInfo& parameter_info(int index);
/// The index of a parameter by its name (ParameterInfo::name); -1 if unknown.
int parameter_index_by_name(const std::string& name);
/// The offset parameter of a channel (0 Fx, 1 Fy, 2 Mz): kOffsetFx + channel.
int offset_parameter(int channel);
/// The range that keeps a parameter physical (+-inf where it is open): what the fit enforces.
struct ParameterBounds {
  double lower,  ///< lower bound (-inf: none)
      upper;     ///< upper bound (+inf: none)
  /// Whether both bounds are finite.
  bool closed() const { return std::isfinite(lower) && std::isfinite(upper); }
};
/// The bounds of parameter `index` (a ModelParameter). The law's shapes are those a
/// non-negative pressure on the patch can produce (theory.md section 4): a in (0, 4], m >= 4.
ParameterBounds parameter_bounds(int index);
/// What a parameter that ends on its lower (or `upper`) bound means, in words.
const char* bound_meaning(int index, bool upper);
/// The crosstalk parameter g_{channel <- source} (channels 0 Fx, 1 Fy, 2 Mz; source != channel).
int crosstalk_parameter(int channel, int source);

/// A model of the closed loop: its form (law, exact integrals, profile, effects' variables),
/// which parameters are free and the values of all of them.
struct ModelSpec {
  double radius_m = 0.0;                ///< patch radius R [m]
  std::optional<double> normal_load_n;  ///< N [N]: f = F0 / N is reported when set
  // Constants of the law the diagrams do not identify (cross-shift shapes).
  double c = 4.0,        ///< shape of the cross-shift force (FractionalLaw::c)
      a_k = 1.0,         ///< shape of the cross-shift torque (FractionalLaw::a_k)
      mk_ratio = 0.375;  ///< Mk / M0 (FractionalLaw::Mk)
  /// The exact integrals over the given profile (unset: the parametric profile).
  std::optional<ExactModel<double>> profile_model;
  /// The given profile's shape (no shift), from which profile_model was made: what the model's
  /// file records (model_file.hpp).
  std::optional<PressureProfile> profile;
  /// The parametric profile's Bernstein degree: 2 (weights w1, w2) or 4 (w1 to w4, the loop's
  /// profile_detail step).
  int profile_degree = 2;
  /// The given profile times a quadratic in rho^2, p_g sum_k w_k B_k2 with the weights w1, w2 of
  /// the parametric profile (the loop's profile_correction step; null w1 = w2 = 1: p_g).
  bool profile_corrected = false;
  /// The exact laws of the profile, built on first use and shared by the spec's copies
  /// (base_model_spec sets the parametric profile's, base_spec_for a given profile's); a spec
  /// that uses the exact integrals without them cannot be evaluated (std::logic_error).
  std::shared_ptr<ExactLawCache> exact_laws;
  // The profile's asymptote-matched law constants (reported with the exact model).
  double profile_a = 1.0,            ///< the profile's asymptote-matched a
      profile_m = 64.0 / 9.0,        ///< the profile's asymptote-matched m
      profile_m0_ratio = 2.0 / 3.0;  ///< the profile's asymptote-matched M0 / (F0 R)
  bool exact_only = false;           ///< the law is replaced by the exact integrals (lambda = 1)
  /// The law's a and m within what a non-negative pressure gives (a <= 4, m >= 4: theory.md
  /// section 4); false opens them to (0, inf).
  bool admissible_shape = true;
  /// Also a, m and M0 / (F0 R) together (a m <= 16, the torque ratio's range), by a stiff
  /// penalty in the fit (fit_problem.cpp). Off by default: where a channel leaves M0 or m
  /// undetermined, the penalty can move the determined parameters instead.
  bool joint_admissibility = false;
  bool speed_in_exact = false;  ///< f(w) at the local slip speed inside the exact integrals
  std::array<bool, kModelParameters> free{};     ///< parameters being estimated
  std::array<double, kModelParameters> value{};  ///< their values (start or fixed)
  double exact_tolerance = 1e-6;       ///< of the exact laws, relative to f N: far below any noise
  double regularization_speed = 1e-6;  ///< eps of the law [m/s]
  /// The reference load N_ref of rho_i = N_i / N_ref (the rows' Fz) [N]: F0 and M0 are at it.
  /// Unset: every row at the one load normal_load_n (rho = 1).
  std::optional<double> reference_load_n;
  /// The variable of each friction_dependence slot (unset: the slot is not used).
  std::array<std::optional<Covariate>, kDependenceSlots> dependence;
  /// Derivatives with respect to the rig's kinematics and the patch's growth are wanted at their
  /// null values too (the score test's Jacobian): the kinematics are differentiated always.
  bool differentiate_kinematics = false;
  /// The rigid patch that gives the motion from the force (rigid_patch.hpp: a limit surface
  /// that exists by construction, which the fitted law need not have); unset: the law's own
  /// inversion (prediction.hpp). The force from the motion is the law's either way.
  std::optional<RigidPatch> motion_patch;

  /// Whether the exact integrals take part: exact_only, or the shape blend free or non-zero.
  bool uses_exact() const { return exact_only || free[kShapeBlend] || value[kShapeBlend] != 0.0; }
  /// The degree ExactLawCache::laws takes: the parametric profile's, or for a given profile 0
  /// (as given) or 2 (corrected).
  int law_degree() const { return profile_model ? (profile_corrected ? 2 : 0) : profile_degree; }
};

/// The bounds under a spec: parameter_bounds(index), with a and m open to (0, inf) when
/// spec.admissible_shape is false (the seed's own fits, whose m = 1.72 no patch gives).
ParameterBounds parameter_bounds(const ModelSpec& spec, int index);

/// A spec of radius `radius_m` [m] and load `normal_load_n` [N] with every parameter at its null
/// value, the law's five (F0, a, M0, m, kx) free and the parametric profile's exact laws.
ModelSpec base_model_spec(double radius_m, std::optional<double> normal_load_n);

/// The fractional law part of the model at parameters theta: F0, a, M0, m, kx, ky, kappa from
/// theta, the constants and Mk = mk_ratio M0 from the spec (without the speed and friction
/// factors, the rig's effects or the patch's growth).
template <class T>
FractionalLaw<T> fractional_law_of(const ModelSpec& spec, const T* theta);

/// A row's conditions under a spec (its load ratio and scaled variables).
PointConditions conditions_of(const ModelSpec& spec, const MeasuredPoint& p);

/// Evaluates the model at kinematics k with parameters theta (all kModelParameters of them), at
/// a row's conditions (default: the reference load, every variable in the middle). T is double
/// or ceres::Jet. Throws InvalidArgument for parameters outside the model's domain and
/// std::logic_error for a spec that uses the exact integrals without exact_laws.
template <class T>
Resultants<T> evaluate_model(const ModelSpec& spec, const T* theta, const Kinematics<double>& k,
                             const PointConditions& conditions = {});

}  // namespace contensou

#include "contensou/identification/effect_model_impl.hpp"
