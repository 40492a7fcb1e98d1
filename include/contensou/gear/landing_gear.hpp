/// \file
/// A one-wheel main landing gear through touchdown, sliding and spin-up (docs/shimmy.md).
///
/// Degrees of freedom (state x, SI units; StateIndex):
///   y, y'     lateral bending of the strut at the wheel [m, m/s]
///   psi, psi' torsion of the strut about its vertical axis [rad, rad/s]
///   Omega     wheel spin about the axle, positive when rolling forward [rad/s]
///   lambda    lateral deflection of the stretched-string tire's leading point [m]
///   x, x'     fore-aft bending of the strut at the wheel [m, m/s] (optional)
///   Omega2    the second wheel's spin of a twin gear [rad/s] (optional)
///   e_y, e_psi lateral offset and yaw of the sliding patch relative to the rim [m, rad]
///             (tire carcass compliance, optional; docs/shimmy.md, "Carcass compliance")
///   u, u2     longitudinal deflection of each wheel's tire, whose first-order relaxation gives the
///             longitudinal slip every contact law sees [m] (tire.longitudinal_relaxation_length_m)
/// Ground frame X forward, Y left, Z up; the wheel frame is turned by psi. The patch centre lies
/// a trail e behind the strut axis and an offset l to its left. Patch kinematics (theory.md
/// section 1, with spin omega = psi'; with longitudinal relaxation the laws see V u / sigma_x
/// instead of this vx):
///   vx = (V + x') cos psi + (y' + Vd) sin psi - l psi' - Omega r
///   vy = -(V + x') sin psi + (y' + Vd) cos psi - e psi'
/// Equations of motion (friction F = (Fx, Fy), Mz acting on the tire, wheel frame;
/// g = I_w Omega / L the gyroscopic coupling, Omega the sum of the wheels' spins, zero unless
/// structure.gyroscopic_length_m is set):
///   m_y y''   = -k_y y - c_y y' + Fx sin psi + Fy cos psi + g psi'
///   I_psi psi'' = -k_psi d(psi) - c_psi psi' + Mz - e Fy - l Fx - g y'
/// (d(psi) = psi without torque-link freeplay, GearStructure::freeplay_rad; with carcass
/// compliance the drag's lever is l + e_y)
///   I_w Omega'  = -r Fx - T_brake tanh(Omega / 1 rad/s)   (per wheel for a twin gear)
///   m_x x''     = -k_x x - c_x x' + Fx cos psi - Fy sin psi   (fore-aft, optional)
#pragma once

#include <Eigen/Core>
#include <array>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/kinematics.hpp"

namespace contensou {

struct ExactLaw;

/// Which tire-ground law acts while the tire slides (docs/shimmy.md, "Contact models").
enum class ContactModel {
  coupled,    ///< the fractional law of theory.md section 4 (or the exact law)
  decoupled,  ///< Coulomb sliding force and an independent Coulomb spin torque, regularised
  /// The classical tire: von Schlippe stretched string, combined slip on a friction circle, no
  /// spin friction (RollingTire).
  von_schlippe,
  nonholonomic = von_schlippe  ///< the former name, kept as an alias
};
/// "coupled", "decoupled" or "von_schlippe".
const char* to_string(ContactModel model);
/// The model of a to_string() name, or of "nonholonomic" (von_schlippe); throws InvalidArgument
/// for another name.
ContactModel contact_model_from_string(const std::string& name);

/// The strut, the wheel and their switchable parts; SI units, the symbols of the file's equations.
struct GearStructure {
  double lateral_mass_kg = 300.0;                 ///< m_y [kg]
  double lateral_stiffness_n_per_m = 3.0e6;       ///< k_y [N/m]
  double lateral_damping_ns_per_m = 1000.0;       ///< c_y [N s/m]
  double torsional_inertia_kgm2 = 25.0;           ///< I_psi [kg m^2]
  double torsional_stiffness_nm_per_rad = 1.0e6;  ///< k_psi [N m/rad]
  /// c_psi [N m s/rad], strut damping and shimmy damper together: 1.4 times the largest damping
  /// the classical (rolling, unbraked) model needs over 30-90 m/s (docs/shimmy.md, section 3,
  /// "Parameters"); the legacy gear (legacy_gear_config) has 100 (1 % of critical).
  double torsional_damping_nms_per_rad = 216.0;
  double trail_m = 0.05;             ///< e, patch centre behind the strut axis [m]
  double offset_m = 0.25;            ///< l, patch centre left of the strut axis [m]
  double wheel_radius_m = 0.57;      ///< r, rolling radius [m]
  double wheel_inertia_kgm2 = 10.0;  ///< I_w, each wheel's spin inertia [kg m^2]
  /// L [m], gyroscopic coupling of the wheel spin with lateral bending and torsion:
  /// the strut bends as a pendulum of length L about the aircraft's X axis, so the wheel rolls by
  /// phi = y / L; its angular momentum I_w Omega along the axle then gives the strut the torque
  /// -I_w Omega y' / L about its axis and the lateral force I_w Omega psi' / L at the wheel
  /// (d/dt of the tilting momentum; they do no work together). 0 switches it off (the default).
  double gyroscopic_length_m = 0.0;
  /// delta [rad], torque-link freeplay: the torsional spring acts on psi beyond a dead band
  /// of half-width delta, k_psi d(psi) with the smooth dead zone
  ///   d(psi) = ((psi - delta) + sqrt((psi - delta)^2 + s^2)) / 2 +
  ///            ((psi + delta) - sqrt((psi + delta)^2 + s^2)) / 2,   s = delta / 20
  /// (d = psi - delta beyond, 0 inside, to O(s); slope 1 - delta / sqrt(delta^2 + s^2) = 1/800
  /// at psi = 0); the damping acts throughout. 0: no freeplay.
  double freeplay_rad = 0.0;
  /// b [m], twin-wheel gear: two wheels on the axle at l + b/2 and l - b/2, each with
  /// half the load, its own spin, anti-skid and patch, and the string's lateral deflection shared
  /// (their lateral kinematics are the same). The drag difference of the two wheels acts on the
  /// torsion through the lever b/2. 0: one wheel at the offset l.
  double wheel_spacing_m = 0.0;
  /// m_x [kg], fore-aft bending of the strut: the wheel moves along X by x against
  /// k_x, c_x with modal mass m_x, loaded by the drag (the spin-up drag bends it back, its release
  /// at the end of spin-up springs it forward). 0 stiffness: rigid fore-aft (the default).
  double fore_aft_mass_kg = 300.0;
  double fore_aft_stiffness_n_per_m = 0.0;    ///< k_x [N/m] (0: off)
  double fore_aft_damping_ns_per_m = 1000.0;  ///< c_x [N s/m]
  /// k_cy [N/m] (0: off), lateral and torsional carcass compliance of the sliding tire
  /// (docs/shimmy.md, "Carcass compliance"): the patch, massless, moves relative to the rim by
  /// e_y (lateral, wheel frame) and e_psi (yaw); the carcass carries
  ///   k_cy e_y + c_cy e_y' = Fy(patch),   k_cpsi e_psi + c_cpsi e_psi' = Mz(patch),
  /// with the friction law evaluated at the patch's own motion (Pacejka 2012, ch. 5 and 7;
  /// Besselink 2000, ch. 3). Both stiffnesses 0: rigid carcass, the patch moves with the rim
  /// (the default); both > 0: on (one wheel only). carcass_from_string_tire() gives the values
  /// estimated from the stretched string.
  double carcass_lateral_stiffness_n_per_m = 0.0;
  double carcass_lateral_damping_ns_per_m = 1000.0;      ///< c_cy [N s/m] (> 0 when on)
  double carcass_torsional_stiffness_nm_per_rad = 0.0;   ///< k_cpsi [N m/rad] (0: off)
  double carcass_torsional_damping_nms_per_rad = 100.0;  ///< c_cpsi [N m s/rad] (> 0 when on)
  /// True when either carcass stiffness is > 0 (validate() requires both then).
  bool carcass_compliance() const {
    return carcass_lateral_stiffness_n_per_m > 0.0 || carcass_torsional_stiffness_nm_per_rad > 0.0;
  }
};

/// The sliding tire: the seed tire's pressure profile (theory.md section 5) at the inflation
/// pressure p*; the patch radius follows from the load, R = sqrt(N / (2 pi p* A^1)).
struct SlidingTire {
  double inflation_pressure_pa = 1.25e6;  ///< p* [Pa]
  double rolling_shift = 0.14;            ///< kx (seed eq. 10, Table 3)
  /// f(w), w the slip speed [m/s]: f_s 0.8, f_k 0.45, w_s 10 m/s, exponent 2.
  SlipSpeedFriction<double> friction{0.8, 0.45, 10.0, 2.0};
  double regularization_speed = 0.05;  ///< eps [m/s]
  /// Coefficients a, m (and c, a_k) of the coupled law: "fitted" by least squares to the exact
  /// integrals of the profile (fractional_law_fitted), "asymptotic" (fractional_law_from_patch)
  /// or "seed" (a = 1.03, m = 1.72 of seed Table 3).
  std::string law_coefficients = "fitted";
  bool exact_integrals = false;  ///< coupled model: exact integrals instead of the law
  /// sigma_x [m], longitudinal relaxation of every contact model (docs/shimmy.md, "Longitudinal
  /// relaxation"): each wheel's tire deflects longitudinally by u, and the laws see the relaxed
  /// slip velocity V u / sigma_x instead of the kinematic vx (Pacejka 2012, ch. 7, the
  /// first-order transient slip sigma_k dk'/dt + V k' = -V_sx, here with u = -sigma_x k'):
  ///   u' = vx - (V / sigma_x) u,
  /// so that a step in vx reaches 63 % after sigma_x of rolling. The default is the half contact
  /// length (the patch radius R at the static load, 0.15 m), the order of the longitudinal
  /// relaxation length at the nominal load (Pacejka 2012, ch. 7); an assumed number, varied in
  /// the classical verdict's sensitivity table.
  /// 0: no relaxation (the laws see vx itself).
  double longitudinal_relaxation_length_m = 0.15;
};

/// The rolling tire (von Schlippe / Somieski stretched string; Pacejka 2012, ch. 5) with combined
/// slip on a friction circle (docs/shimmy.md, "von_schlippe"):
///   lambda' = -(vy + a psi') - (V / sigma) lambda,   alpha = lambda / sigma,  s = vx / V,
///   demanded forces D = (-C_x s N, C_Fa alpha N), z = |D| / cap, cap = mu N,
///   |F| = cap tanh(z)    (|F| at most mu N: braking and cornering share it),
///   F / |F| = normalise((1 - beta) D / |D| - beta e_s),  beta = tanh(z)^2,
///   Mz = -(C_Ma / C_Fa) (1 - beta) Fy - kappa_t (N / N_s) psi' / V,
/// with a = R the half contact length, e_s = (vx, -V alpha) / w the tread's sliding direction and
/// mu = f(w) the sliding tire's friction law at the slip speed w = (vx^2 + (V alpha)^2)^(1/2): at
/// full slide (beta -> 1) the force is the sliding tires' -f(w) N e_s and the pneumatic trail is
/// gone, so that all tires slide, and brake, with the same friction.
struct RollingTire {
  double relaxation_length_m = 0.6;             ///< sigma [m]
  double cornering_coefficient = 8.0;           ///< C_Fa [1/rad], cornering stiffness / N
  double aligning_coefficient_m = 0.8;          ///< C_Ma [m/rad], aligning stiffness / N
  double tread_moment_nm2_per_rad = 500.0;      ///< kappa_t [N m^2/rad] at full load, scaled with N
  double longitudinal_slip_coefficient = 20.0;  ///< C_x, longitudinal slip stiffness / N
};

/// The landing: prescribed load ramp, constant forward speed, optional braking.
struct LandingScenario {
  double forward_speed_mps = 70.0;      ///< V [m/s]
  double drift_speed_mps = 0.3;         ///< Vd [m/s], lateral ground speed (residual crab)
  double static_load_n = 80.0e3;        ///< N_s [N], the load after the ramp
  double touchdown_time_s = 0.02;       ///< t_td [s], load onset
  double load_ramp_s = 0.1;             ///< T [s]: N = N_s S((t - t_td) / T), S(x) = x^2 (3 - 2 x)
  double end_time_s = 1.0;              ///< [s]; touchdown at or after it: the gear never lands
  double initial_torsion_rad = 0.0;     ///< psi(0) [rad]
  double initial_lateral_m = 0.0;       ///< y(0) [m]
  double rolling_slip = 0.05;           ///< sliding to rolling when s falls below (end of spin-up)
  double sliding_slip = 0.10;           ///< rolling to sliding when s rises above
  bool braking = true;                  ///< brake between brake_on_s and brake_off_s
  double brake_on_s = 0.25;             ///< brake command on [s] (an event)
  double brake_off_s = 0.95;            ///< brake command off [s] (an event)
  double brake_max_torque_nm = 40.0e3;  ///< T_max [N m], the anti-skid's largest torque per wheel
  /// s*, anti-skid: T = T_max / (1 + exp((s_w - s*) / ds)), s_w = 1 - Omega r / V the
  /// wheel-speed slip.
  double brake_target_slip = 0.15;
  double brake_slip_band = 0.01;  ///< ds
  /// Shimmy is judged on [window_start, window_end] [s]; negative means automatic
  /// (analysis_window()).
  double window_start_s = -1.0;
  double window_end_s = -1.0;  ///< the window's end [s]; negative: automatic
};

/// Everything configurable of a gear: the keys of gear_parameters.hpp, section by section.
struct GearConfig {
  GearStructure structure;   ///< the strut and the wheels
  SlidingTire tire;          ///< the sliding tire and what every contact model shares
  RollingTire rolling;       ///< the rolling (stretched-string) tire
  LandingScenario scenario;  ///< the landing
};

/// Throws InvalidArgument naming the first bad field (the ranges and relations of
/// gear_parameters.hpp, row by row).
void validate(const GearConfig& config);

/// Named gears (docs/shimmy.md, "Parameters"): "default" (GearConfig{}: classically stable with a
/// margin of 1.4 over 30-90 m/s) and "legacy" (legacy_gear_config()). Throws InvalidArgument for
/// another name.
GearConfig gear_config_by_name(const std::string& name);
/// The first demo gear: the default with torsional damping 100 N m s/rad, classically unstable.
GearConfig legacy_gear_config();

/// The configuration with the carcass compliance switched on at the values the stretched string of
/// config.rolling implies at the static load (docs/shimmy.md, "Carcass compliance"): string
/// stiffness per length c_c = C_Fa N_s / (2 (sigma + a)^2), a the patch radius at N_s, then
///   k_cy = 2 c_c (sigma + a),   k_cpsi = c_c (2 a^3 / 3 + 2 a sigma (sigma + a));
/// the dampings keep their (assumed) values.
GearConfig carcass_from_string_tire(GearConfig config);

/// The numeric parameters of a GearConfig by dotted name ("structure.offset_m",
/// "scenario.forward_speed_mps", "tire.friction.static_coefficient", ...); nullptr if unknown
/// or not a number (gear_parameters.hpp has every key with its unit and range).
double* gear_parameter(GearConfig& config, std::string_view name);
/// The dotted names of every number key, in the table's order.
std::vector<std::string> gear_parameter_names();

/// The state's components, the order of GearState. The optional ones are inert (zero rate)
/// while their part is off:
/// x, x': fore-aft bending of the strut at the wheel (structure.fore_aft_stiffness_n_per_m > 0).
/// Omega2: the second wheel's spin of a twin gear (structure.wheel_spacing_m > 0).
/// e_y, e_psi: the patch's offset and yaw relative to the rim (structure.carcass_*).
/// u, u2: each wheel's longitudinal deflection (tire.longitudinal_relaxation_length_m > 0; u2 for
/// a twin gear).
enum StateIndex : int {
  kY = 0,       ///< y, lateral bending [m]
  kYDot,        ///< y' [m/s]
  kPsi,         ///< psi, torsion [rad]
  kPsiDot,      ///< psi' [rad/s]
  kSpin,        ///< Omega, the (first) wheel's spin [rad/s]
  kLambda,      ///< lambda, the string's lateral deflection [m]
  kX,           ///< x, fore-aft bending [m]
  kXDot,        ///< x' [m/s]
  kSpin2,       ///< Omega2, a twin gear's second wheel's spin [rad/s]
  kCarcassY,    ///< e_y, the patch's lateral offset from the rim [m]
  kCarcassPsi,  ///< e_psi, the patch's yaw relative to the rim [rad]
  kSlipX,       ///< u, the (first) wheel's longitudinal tire deflection [m]
  kSlipX2,      ///< u2, the second wheel's [m]
  kStateSize    ///< the number of states
};
/// The gear's state x, indexed by StateIndex (SI units).
using GearState = Eigen::Matrix<double, kStateSize, 1>;

/// The states' scales (the solver's absolute tolerances are relative_tolerance times these): 1 mm,
/// 0.1 m/s, 1 mrad, 0.1 rad/s, 100 rad/s, 1 mm, 1 mm, 0.1 m/s, 100 rad/s, 1 mm, 1 mrad, 1 mm,
/// 1 mm (in StateIndex order).
inline constexpr std::array<double, kStateSize> kStateScale{
    1e-3, 1e-1, 1e-3, 1e-1, 1e2, 1e-3, 1e-3, 1e-1, 1e2, 1e-3, 1e-3, 1e-3, 1e-3};

/// The discrete part of the state, changed only at events.
struct GearMode {
  bool loaded = false;         ///< after load onset
  bool rolling = false;        ///< rolling tire (after spin-up); always true for von_schlippe
  bool brake_command = false;  ///< between brake on and brake off
};

/// What the contact sees and gives at one instant. For a twin gear: the mean kinematics, slip
/// ratio and friction, the summed load, forces and brake torque, the moment about the midpoint
/// between the patches, and one wheel's patch radius.
struct ContactState {
  double load_n = 0.0;          ///< N [N]
  double patch_radius_m = 0.0;  ///< R [m]
  Kinematics<double> slip;      ///< vx, vy [m/s], omega = psi' [rad/s]
  double slip_ratio = 0.0;      ///< s = vx / V
  double friction = 0.0;  ///< f at the effective slip speed (sliding) or mu (rolling); 0 unloaded
  Resultants<double> force;      ///< on the tire, wheel frame [N, N m]
  double brake_torque_nm = 0.0;  ///< the anti-skid's torque, all wheels [N m]
  /// Per wheel (a twin gear's second wheel in [1]; zero for one wheel): drag [N].
  std::array<double, 2> wheel_fx_n{};
  std::array<double, 2> wheel_brake_nm{};  ///< per wheel, likewise: brake torque [N m]
  /// Carcass compliance: (e_y', e_psi') [m/s, rad/s], the patch's motion relative to the rim; slip
  /// is then the patch's own motion (the rim's plus these), on which the law acts.
  std::array<double, 2> carcass_rate{};
  /// Longitudinal relaxation: each wheel's u' = vx_kinematic - (V / sigma_x) u [m/s] (zero
  /// without it or unloaded); slip.vx (and slip_ratio) is then the relaxed V u / sigma_x the law
  /// acts on.
  std::array<double, 2> longitudinal_rate{};
};

/// Everything fixed for one run: the configuration, the contact model and the friction law's
/// coefficients; cheap to copy. Building it with exact_integrals fits the exact model once.
struct GearModel {
  GearConfig config;                             ///< the gear, validated by make_gear_model()
  ContactModel contact = ContactModel::coupled;  ///< the law while the tire slides
  double moment_ratio_2 = 0.0;                   ///< A^2 / A^1 (M0 = f N R A^2 / A^1)
  double moment_ratio_3 = 0.0;                   ///< A^3 / A^1
  double moment_1 = 0.0;                         ///< A^1 (the patch radius from the load)
  /// The coupled fractional law's coefficient a (tire.law_coefficients).
  double law_a = 1.0, law_m = 1.0, law_c = 4.0, law_a_k = 1.0;  ///< the coupled law's a_k
  /// \var contensou::GearModel::law_m
  /// The coupled fractional law's coefficient m (tire.law_coefficients).
  /// \var contensou::GearModel::law_c
  /// The coupled fractional law's coefficient c (tire.law_coefficients).

  /// The exact law of the unit patch (R = 1 m, p* = 1 Pa, f = 1) when tire.exact_integrals
  /// and the coupled model, else null (exact_law.hpp, certified to 1e-8 of f N): with
  /// L = N_1 / p*, F = (f N / L) F_1(vx, vy, omega R), Mz = (f N R / L) Mz_1(vx, vy, omega R).
  std::shared_ptr<const ExactLaw> exact;
};
/// Validates config (throws InvalidArgument), then takes the profile's moments and the law's
/// coefficients (tire.law_coefficients) and, for the coupled model with tire.exact_integrals,
/// builds the exact law.
GearModel make_gear_model(const GearConfig& config, ContactModel contact);

/// N(t) [N]: zero before touchdown, the smooth ramp, then the static load.
double vertical_load(const LandingScenario& s, double t);

/// The initial state at t = 0: psi(0) and y(0) of the scenario, every other state zero (wheel at
/// rest, every model).
GearState initial_state(const GearModel& model);
/// The mode at t = 0: loaded if touchdown_time_s is 0, rolling for von_schlippe, the brake on
/// if braking with brake_on_s at 0.
GearMode initial_mode(const GearModel& model);

/// Contact kinematics and forces for a state x at time t [s] in `mode`.
ContactState contact_state(const GearModel& model, const GearMode& mode, double t,
                           const GearState& x);

/// dx/dt at time t [s] in `mode`.
GearState gear_rhs(const GearModel& model, const GearMode& mode, double t, const GearState& x);

/// d(dx/dt)/dx, a full kStateSize by kStateSize matrix (inert states included).
using GearJacobian = Eigen::Matrix<double, kStateSize, kStateSize>;
/// d(dx/dt)/dx, structured (with carcass compliance on: forward differences of gear_rhs, one
/// evaluation per state, since e_y', e_psi' come from an implicit solve): the gear's equations and
/// kinematics differentiated by hand, the contact law's partials d(Fx, Fy, Mz)/d(vx, vy, omega,
/// lambda) analytic for the coupled fractional law (fractional_resultants_with_jacobian and f'(w)),
/// by forward differences of the law alone (one evaluation per input) for the others
/// (docs/shimmy.md, "Numerics").
GearJacobian gear_jacobian(const GearModel& model, const GearMode& mode, double t,
                           const GearState& x);

/// Stretched-string deflection lambda [m] that carries the sliding lateral force [N] over
/// unchanged when the tire starts to roll in state x (inverse of the rolling Fy law at the state's
/// longitudinal slip, by bisection on lambda up to sigma, a slip angle of 1 rad; sigma with the
/// force's sign if the force is not reached there, 0 without load).
double string_deflection_for_force(const GearModel& model, double t, const GearState& x,
                                   double lateral_force_n);

}  // namespace contensou
