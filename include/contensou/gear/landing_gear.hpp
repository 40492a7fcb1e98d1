// A one-wheel main landing gear through touchdown, sliding and spin-up (docs/shimmy.md).
//
// Degrees of freedom (state x, SI units):
//   y, y'     lateral bending of the strut at the wheel [m, m/s]
//   psi, psi' torsion of the strut about its vertical axis [rad, rad/s]
//   Omega     wheel spin about the axle, positive when rolling forward [rad/s]
//   lambda    lateral deflection of the stretched-string tire's leading point [m]
//   x, x'     fore-aft bending of the strut at the wheel [m, m/s] (optional)
//   Omega2    the second wheel's spin of a twin gear [rad/s] (optional)
//   e_y, e_psi lateral offset and yaw of the sliding patch relative to the rim [m, rad]
//             (tire carcass compliance, optional; docs/shimmy.md, "Carcass compliance")
//   u, u2     longitudinal deflection of each wheel's tire, whose first-order relaxation gives the
//             longitudinal slip every contact law sees [m] (tire.longitudinal_relaxation_length_m)
// Ground frame X forward, Y left, Z up; the wheel frame is turned by psi. The patch centre lies
// a trail e behind the strut axis and an offset l to its left. Patch kinematics (theory.md
// section 1, with spin omega = psi'):
//   vx = (V + x') cos psi + (y' + Vd) sin psi - l psi' - Omega r
//   vy = -(V + x') sin psi + (y' + Vd) cos psi - e psi'
// Equations of motion (friction F = (Fx, Fy), Mz acting on the tire, wheel frame; g = I_w Omega / L
// the gyroscopic coupling, zero unless structure.gyroscopic_length_m is set):
//   m_y y''   = -k_y y - c_y y' + Fx sin psi + Fy cos psi + g psi'
//   I_psi psi'' = -k_psi d(psi) - c_psi psi' + Mz - e Fy - l Fx - g y'
// (d(psi) = psi without torque-link freeplay; GearStructure::freeplay_rad)
//   I_w Omega'  = -r Fx - T_brake   (per wheel for a twin gear)
//   m_x x''     = -k_x x - c_x x' + Fx cos psi - Fy sin psi   (fore-aft, optional)
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

// Which tire-ground law acts while the tire slides (docs/shimmy.md, "Contact models").
enum class ContactModel {
  coupled,       // the fractional law of theory.md section 4 (or the exact law)
  decoupled,     // Coulomb sliding force and an independent Coulomb spin torque, regularised
  von_schlippe,  // the classical tire: von Schlippe stretched string, combined slip on a
                 // friction circle, no spin friction (RollingTire)
  nonholonomic = von_schlippe  // the former name, kept as an alias
};
const char* to_string(ContactModel model);
ContactModel contact_model_from_string(const std::string& name);  // throws InvalidArgument

struct GearStructure {
  double lateral_mass_kg = 300.0;                 // m_y
  double lateral_stiffness_n_per_m = 3.0e6;       // k_y
  double lateral_damping_ns_per_m = 1000.0;       // c_y
  double torsional_inertia_kgm2 = 25.0;           // I_psi
  double torsional_stiffness_nm_per_rad = 1.0e6;  // k_psi
  // c_psi, strut damping and shimmy damper together: 1.4 times the largest damping the
  // classical (rolling, unbraked) model needs over 30-90 m/s (docs/shimmy.md, "Default gear");
  // the legacy gear (legacy_gear_config) has 100 (1 % of critical).
  double torsional_damping_nms_per_rad = 216.0;
  double trail_m = 0.05;             // e, patch centre behind the strut axis
  double offset_m = 0.25;            // l, patch centre left of the strut axis
  double wheel_radius_m = 0.57;      // r, rolling radius
  double wheel_inertia_kgm2 = 10.0;  // I_w
  // Gyroscopic coupling of the wheel spin with lateral bending and torsion:
  // the strut bends as a pendulum of length L about the aircraft's X axis, so the wheel rolls by
  // phi = y / L; its angular momentum I_w Omega along the axle then gives the strut the torque
  // -I_w Omega y' / L about its axis and the lateral force I_w Omega psi' / L at the wheel
  // (d/dt of the tilting momentum; they do no work together). 0 switches it off (the default).
  double gyroscopic_length_m = 0.0;  // L
  // Torque-link freeplay: the torsional spring acts on psi beyond a dead band
  // of half-width delta, k_psi d(psi) with the smooth dead zone
  //   d(psi) = ((psi - delta) + sqrt((psi - delta)^2 + s^2)) / 2
  //          + ((psi + delta) - sqrt((psi + delta)^2 + s^2)) / 2,   s = delta / 20
  // (d = psi - delta beyond, 0 inside, to O(s); slope 1 - delta / sqrt(delta^2 + s^2) = 1/800
  // at psi = 0); the damping acts throughout. 0: no freeplay.
  double freeplay_rad = 0.0;  // delta
  // Twin-wheel gear: two wheels on the axle at l + b/2 and l - b/2, each with
  // half the load, its own spin, anti-skid and patch, and the string's lateral deflection shared
  // (their lateral kinematics are the same). The drag difference of the two wheels acts on the
  // torsion through the lever b/2. 0: one wheel at the offset l.
  double wheel_spacing_m = 0.0;  // b
  // Fore-aft bending of the strut: the wheel moves along X by x against
  // k_x, c_x with modal mass m_x, loaded by the drag (the spin-up drag bends it back, its release
  // at the end of spin-up springs it forward). 0 stiffness: rigid fore-aft (the default).
  double fore_aft_mass_kg = 300.0;            // m_x
  double fore_aft_stiffness_n_per_m = 0.0;    // k_x (0: off)
  double fore_aft_damping_ns_per_m = 1000.0;  // c_x
  // Lateral and torsional carcass compliance of the sliding tire
  // (docs/shimmy.md, "Carcass compliance"): the patch, massless, moves relative to the rim by
  // e_y (lateral, wheel frame) and e_psi (yaw); the carcass carries
  //   k_cy e_y + c_cy e_y' = Fy(patch),   k_cpsi e_psi + c_cpsi e_psi' = Mz(patch),
  // with the friction law evaluated at the patch's own motion (Pacejka 2012, ch. 5 and 7;
  // Besselink 2000, ch. 3). Both stiffnesses 0: rigid carcass, the patch moves with the rim
  // (the default); both > 0: on (one wheel only). carcass_from_string_tire() gives the values
  // estimated from the stretched string.
  double carcass_lateral_stiffness_n_per_m = 0.0;        // k_cy (0: off)
  double carcass_lateral_damping_ns_per_m = 1000.0;      // c_cy (> 0 when on)
  double carcass_torsional_stiffness_nm_per_rad = 0.0;   // k_cpsi (0: off)
  double carcass_torsional_damping_nms_per_rad = 100.0;  // c_cpsi (> 0 when on)
  bool carcass_compliance() const {
    return carcass_lateral_stiffness_n_per_m > 0.0 || carcass_torsional_stiffness_nm_per_rad > 0.0;
  }
};

// The sliding tire: the seed tire's pressure profile (theory.md section 5) at the inflation
// pressure p*; the patch radius follows from the load, R = sqrt(N / (2 pi p* A^1)).
struct SlidingTire {
  double inflation_pressure_pa = 1.25e6;                     // p*
  double rolling_shift = 0.14;                               // kx (seed eq. 10, Table 3)
  SlipSpeedFriction<double> friction{0.8, 0.45, 10.0, 2.0};  // f(w), w the slip speed
  double regularization_speed = 0.05;                        // eps [m/s]
  // Coefficients a, m (and c, a_k) of the coupled law: "fitted" by least squares to the exact
  // integrals of the profile (fractional_law_fitted), "asymptotic" (fractional_law_from_patch)
  // or "seed" (a = 1.03, m = 1.72 of seed Table 3).
  std::string law_coefficients = "fitted";
  bool exact_integrals = false;  // coupled model: exact integrals instead of the law
  // Longitudinal relaxation of every contact model (docs/shimmy.md, "Longitudinal relaxation"):
  // each wheel's tire deflects longitudinally by u, and the laws see the relaxed slip velocity
  // V u / sigma_x instead of the kinematic vx (Pacejka 2012, ch. 7, the first-order transient
  // slip sigma_k dk'/dt + V k' = -V_sx, here with u = -sigma_x k'):
  //   u' = vx - (V / sigma_x) u,
  // so that a step in vx reaches 63 % after sigma_x of rolling. The default is the half contact
  // length (the patch radius R at the static load, 0.15 m), the order of the longitudinal
  // relaxation length at the nominal load (Pacejka 2012, ch. 7); an assumed number, varied in
  // the classical verdict's sensitivity table.
  // 0: no relaxation (the laws see vx itself).
  double longitudinal_relaxation_length_m = 0.15;  // sigma_x
};

// The rolling tire (von Schlippe / Somieski stretched string; Pacejka 2012, ch. 5) with combined
// slip on a friction circle (docs/shimmy.md, "von_schlippe"):
//   lambda' = -(vy + a psi') - (V / sigma) lambda,   alpha = lambda / sigma,  s = vx / V,
//   demanded forces D = (-C_x s N, C_Fa alpha N), z = |D| / cap, cap = mu N,
//   |F| = cap tanh(z)    (|F| <= mu N: braking and cornering share it),
//   F / |F| = normalise((1 - beta) D / |D| - beta e_s),  beta = tanh(z)^2,
//   Mz = -(C_Ma / C_Fa) (1 - beta) Fy - kappa_t (N / N_s) psi' / V,
// with a = R the half contact length, e_s = (vx, -V alpha) / w the tread's sliding direction and
// mu = f(w) the sliding tire's friction law at the slip speed w = (vx^2 + (V alpha)^2)^(1/2): at
// full slide (beta -> 1) the force is the sliding tires' -f(w) N e_s and the pneumatic trail is
// gone, so that all tires slide, and brake, with the same friction.
struct RollingTire {
  double relaxation_length_m = 0.6;             // sigma
  double cornering_coefficient = 8.0;           // C_Fa [1/rad], cornering stiffness / N
  double aligning_coefficient_m = 0.8;          // C_Ma [m/rad], aligning stiffness / N
  double tread_moment_nm2_per_rad = 500.0;      // kappa_t at full load, scaled with N
  double longitudinal_slip_coefficient = 20.0;  // C_x, longitudinal slip stiffness / N
};

// The landing: prescribed load ramp, constant forward speed, optional braking.
struct LandingScenario {
  double forward_speed_mps = 70.0;   // V
  double drift_speed_mps = 0.3;      // Vd, lateral ground speed at touchdown (residual crab)
  double static_load_n = 80.0e3;     // N after the ramp
  double touchdown_time_s = 0.02;    // load onset
  double load_ramp_s = 0.1;          // N = N_s S((t - t_td) / T), S(x) = x^2 (3 - 2 x)
  double end_time_s = 1.0;           // touchdown at or after it: the gear never lands
  double initial_torsion_rad = 0.0;  // psi(0)
  double initial_lateral_m = 0.0;    // y(0)
  double rolling_slip = 0.05;        // sliding -> rolling when s falls below (end of spin-up)
  double sliding_slip = 0.10;        // rolling -> sliding when s rises above
  bool braking = true;
  double brake_on_s = 0.25;  // brake command on / off (events)
  double brake_off_s = 0.95;
  double brake_max_torque_nm = 40.0e3;
  double brake_target_slip = 0.15;  // anti-skid: T = T_max / (1 + exp((s_w - s*) / ds)),
                                    // s_w = 1 - Omega r / V the wheel-speed slip
  double brake_slip_band = 0.01;    // ds
  // Shimmy is judged on [window_start, window_end]; negative means automatic (docs).
  double window_start_s = -1.0;
  double window_end_s = -1.0;
};

struct GearConfig {
  GearStructure structure;
  SlidingTire tire;
  RollingTire rolling;
  LandingScenario scenario;
};

// Throws InvalidArgument naming the first bad field (the ranges and relations of
// gear_parameters.hpp, row by row).
void validate(const GearConfig& config);

// Named gears (docs/shimmy.md, "Parameters"): "default" (GearConfig{}: classically stable with a
// margin of 1.4 over 30-90 m/s) and "legacy" (the first demo gear, torsional damping
// 100 N m s/rad, classically unstable). Throws InvalidArgument for another name.
GearConfig gear_config_by_name(const std::string& name);
GearConfig legacy_gear_config();

// The configuration with the carcass compliance switched on at the values the stretched string of
// config.rolling implies at the static load (docs/shimmy.md, "Carcass compliance"): string
// stiffness per length c_c = C_Fa N_s / (2 (sigma + a)^2), a the patch radius at N_s, then
//   k_cy = 2 c_c (sigma + a),   k_cpsi = c_c (2 a^3 / 3 + 2 a sigma (sigma + a));
// the dampings keep their (estimated) values.
GearConfig carcass_from_string_tire(GearConfig config);

// The numeric parameters of a GearConfig by dotted name ("structure.offset_m",
// "scenario.forward_speed_mps", "tire.friction.static_coefficient", ...); nullptr if unknown
// (gear_parameters.hpp has every key with its unit and range).
double* gear_parameter(GearConfig& config, std::string_view name);
std::vector<std::string> gear_parameter_names();

// x, x': fore-aft bending of the strut at the wheel (structure.fore_aft_stiffness_n_per_m > 0;
// inert otherwise).
// Omega2: the second wheel's spin of a twin gear (structure.wheel_spacing_m > 0; inert otherwise).
// e_y, e_psi: the patch's offset and yaw relative to the rim (structure.carcass_*; inert
// otherwise).
// u, u2: each wheel's longitudinal deflection (tire.longitudinal_relaxation_length_m > 0; u2 for
// a twin gear; inert otherwise).
enum StateIndex : int {
  kY = 0,
  kYDot,
  kPsi,
  kPsiDot,
  kSpin,
  kLambda,
  kX,
  kXDot,
  kSpin2,
  kCarcassY,
  kCarcassPsi,
  kSlipX,
  kSlipX2,
  kStateSize
};
using GearState = Eigen::Matrix<double, kStateSize, 1>;

// The states' scales (the solver's absolute tolerances are relative_tolerance times these): 1 mm,
// 0.1 m/s, 1 mrad, 0.1 rad/s, 100 rad/s, 1 mm, 1 mm, 0.1 m/s, 100 rad/s, 1 mm, 1 mrad, 1 mm,
// 1 mm (in StateIndex order).
inline constexpr std::array<double, kStateSize> kStateScale{
    1e-3, 1e-1, 1e-3, 1e-1, 1e2, 1e-3, 1e-3, 1e-1, 1e2, 1e-3, 1e-3, 1e-3, 1e-3};

// The discrete part of the state, changed only at events.
struct GearMode {
  bool loaded = false;         // after load onset
  bool rolling = false;        // rolling tire (after spin-up); always true for von_schlippe
  bool brake_command = false;  // between brake on and brake off
};

// What the contact sees and gives at one instant. For a twin gear: the mean kinematics, slip
// ratio and friction, the summed load, forces and brake torque, the moment about the midpoint
// between the patches, and one wheel's patch radius.
struct ContactState {
  double load_n = 0.0;           // N
  double patch_radius_m = 0.0;   // R
  Kinematics<double> slip;       // vx, vy, omega = psi'
  double slip_ratio = 0.0;       // s = vx / V
  double friction = 0.0;         // f at the effective slip speed (sliding) or mu (rolling)
  Resultants<double> force;      // on the tire, wheel frame
  double brake_torque_nm = 0.0;  // all wheels
  // Per wheel (a twin gear's second wheel in [1]; zero for one wheel): drag and brake torque.
  std::array<double, 2> wheel_fx_n{};
  std::array<double, 2> wheel_brake_nm{};
  // Carcass compliance: (e_y', e_psi'), the patch's motion relative to the rim; slip is then the
  // patch's own motion (the rim's plus these), on which the law acts.
  std::array<double, 2> carcass_rate{};
  // Longitudinal relaxation: each wheel's u' = vx_kinematic - (V / sigma_x) u (zero without it);
  // slip.vx (and slip_ratio) is then the relaxed V u / sigma_x the law acts on.
  std::array<double, 2> longitudinal_rate{};
};

// Everything fixed for one run: the configuration, the contact model and the friction law's
// coefficients; cheap to copy. Building it with exact_integrals fits the exact model once.
struct GearModel {
  GearConfig config;
  ContactModel contact = ContactModel::coupled;
  double moment_ratio_2 = 0.0;  // A^2 / A^1 (M0 = f N R A^2 / A^1)
  double moment_ratio_3 = 0.0;  // A^3 / A^1
  double moment_1 = 0.0;        // A^1
  double law_a = 1.0, law_m = 1.0, law_c = 4.0, law_a_k = 1.0;
  // The exact law of the unit patch (R = 1 m, p* = 1 Pa, f = 1) when tire.exact_integrals
  // (exact_law.hpp, certified to 1e-8 of f N): with L = N_1 / p*, F = (f N / L) F_1(vx, vy,
  // omega R), Mz = (f N R / L) Mz_1(vx, vy, omega R).
  std::shared_ptr<const ExactLaw> exact;
};
GearModel make_gear_model(const GearConfig& config, ContactModel contact);

// N(t): zero before touchdown, the smooth ramp, then the static load.
double vertical_load(const LandingScenario& s, double t);

// The initial state at t = 0 (wheel at rest, every model).
GearState initial_state(const GearModel& model);
GearMode initial_mode(const GearModel& model);

// Contact kinematics and forces for a state.
ContactState contact_state(const GearModel& model, const GearMode& mode, double t,
                           const GearState& x);

// dx/dt.
GearState gear_rhs(const GearModel& model, const GearMode& mode, double t, const GearState& x);

// d(dx/dt)/dx, structured (with carcass compliance on: forward differences of gear_rhs, one
// evaluation per state, since e_y', e_psi' come from an implicit solve): the gear's equations and
// kinematics differentiated by hand, the contact law's partials d(Fx, Fy, Mz)/d(vx, vy, omega,
// lambda) analytic for the coupled fractional law (fractional_resultants_with_jacobian and f'(w)),
// by forward differences of the law alone (one evaluation per input) for the others
// (docs/shimmy.md, "Numerics").
using GearJacobian = Eigen::Matrix<double, kStateSize, kStateSize>;
GearJacobian gear_jacobian(const GearModel& model, const GearMode& mode, double t,
                           const GearState& x);

// Stretched-string deflection that carries the sliding lateral force over unchanged when the
// tire starts to roll in state x (inverse of the rolling Fy law at the state's longitudinal slip,
// by bisection; the largest reachable force if |Fy| exceeds it).
double string_deflection_for_force(const GearModel& model, double t, const GearState& x,
                                   double lateral_force_n);

}  // namespace contensou
