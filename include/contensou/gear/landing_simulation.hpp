/// \file
/// Integration of the landing-gear model with SUNDIALS CVODE (Adams-Moulton or BDF with Newton
/// iterations on a dense direct solver) and
/// root-finding for the events: load onset, full load, end of spin-up (sliding to rolling),
/// renewed sliding (rolling to sliding), brake on, brake off (docs/shimmy.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/oscillation.hpp"

namespace contensou {

/// CVODE's linear multistep family. Adams-Moulton (orders 1-12) takes fewer steps than BDF
/// (orders 1-5) on the landing's lightly damped 16-32 Hz modes at a given tolerance and is more
/// accurate there (docs/shimmy.md, "Numerics"); its Newton iterations use the same Jacobian. BDF
/// is for configurations much stiffer than the default gear (stiff struts, dampers of
/// 1e4 1/s and more), where Adams' bounded stability region would force tiny steps.
enum class Integrator {
  adams,  ///< Adams-Moulton, orders 1-12 (the default)
  bdf     ///< backward differentiation formulas, orders 1-5
};
/// How a landing is integrated and sampled. The absolute tolerance of each state is
/// relative_tolerance times its scale in kStateScale; only the states the configuration switches
/// on are integrated.
struct SolverOptions {
  double relative_tolerance = 1e-7;  ///< CVODE's relative tolerance (require_relative_tolerance)
  double output_interval_s = 5e-4;   ///< [s] samples for the time history and the shimmy analysis
  bool record = true;                ///< keep the samples (the analysis runs either way)
  long max_steps = 1000000;          ///< steps between two outputs (at least 1)
  /// Steps of one landing in all (at least 1; 0: no bound, as for a stepped run): a landing takes
  /// a few thousand, and a gear driven unstable (a negative torsional damping, say) can need
  /// millions of ever smaller steps; past this the landing fails with a message naming it.
  long max_total_steps = 500000;
  /// CVODE's Newton matrix from gear_jacobian (structured, analytic where the law allows), or
  /// from CVODE's own difference quotients (one right-hand side per state) when false.
  bool analytic_jacobian = true;
  Integrator method = Integrator::adams;  ///< Adams-Moulton or BDF
  /// Polled before every integrator step: the landing (and a map of them) throws Interrupted
  /// once it returns true (error.hpp).
  StopRequest stop{};
};

/// One output sample of a landing.
struct LandingSample {
  double t = 0.0;                   ///< time [s]
  GearState x = GearState::Zero();  ///< the state (StateIndex; inactive states zero)
  ContactState contact;             ///< the contact at (t, x) in the sample's mode
  bool rolling = false;             ///< the mode's rolling tire (GearMode::rolling)
};

/// An event of a landing, at the instant it happened.
struct LandingEvent {
  double t = 0.0;  ///< [s]
  /// "load onset", "full load", "spin-up", "sliding", "brake on", "brake off".
  std::string what;
};

/// The descriptive shimmy flag of a simulated landing (docs/shimmy.md, section 4, "Simulated
/// landings"): on the analysis window, the torsional oscillation grows or holds (fitted growth
/// rate above sustained_growth_rate_per_s, which admits a saturated limit cycle) and ends above
/// amplitude_threshold_rad.
struct ShimmyCriterion {
  double amplitude_threshold_rad = 1e-3;      ///< the torsion's last amplitude above it [rad]
  double sustained_growth_rate_per_s = -0.1;  ///< the torsion's growth rate above it [1/s]
};

/// The torsion of a landing judged on its analysis window.
struct ShimmyMetrics {
  /// The criterion met: a valid torsion estimate above both of ShimmyCriterion's limits.
  bool shimmy = false;
  OscillationEstimate torsion;    ///< psi (position) and psi' (rate) on the window
  double peak_torsion_rad = 0.0;  ///< max abs(psi) after touchdown [rad]
  double peak_lateral_m = 0.0;    ///< max abs(y) after touchdown [m]
};

/// A simulated landing: its samples, events, shimmy metrics and the integrator's counters.
struct LandingRun {
  ContactModel contact = ContactModel::coupled;  ///< the model that ran
  std::vector<LandingSample> samples;  ///< every output_interval_s; empty unless options.record
  std::vector<LandingEvent> events;    ///< in the order they happened
  /// Touchdown to the end of spin-up (slip ratio below rolling_slip) [s]; empty if it never
  /// ended.
  std::optional<double> spin_up_s;
  /// The analysis window's start [s] (analysis_window()).
  double window_start_s = 0.0, window_end_s = 0.0;  ///< the analysis window's end [s]
  ShimmyMetrics metrics;                            ///< the torsion on the analysis window
  long steps = 0;                                   ///< integrator steps
  long rhs_evaluations = 0;       ///< by the integrator, including those of difference quotients
  long jacobian_evaluations = 0;  ///< Jacobians formed (analytic or by difference quotients)
  long linear_setups = 0;         ///< LU factorisations of the Newton matrix I - gamma J
  long newton_iterations = 0;     ///< Newton iterations of the integrator
  long error_test_failures = 0;   ///< steps rejected by the local error test
  long convergence_failures = 0;  ///< of the Newton iteration
  double wall_s = 0.0;            ///< wall-clock time of simulate_landing [s]
};

/// The tightest relative tolerance CVODE can meet on the gear in double precision: tighter, the
/// weighted norm of the state times the unit roundoff passes 1 (CVODE's CV_TOO_MUCH_ACC).
inline constexpr double kTightestRelativeTolerance = 1e-14;
/// The loosest relative tolerance taken (excluded): looser is no integration.
inline constexpr double kLoosestRelativeTolerance = 0.1;

/// Throws InvalidArgument naming `name` unless `rtol` lies in [kTightestRelativeTolerance,
/// kLoosestRelativeTolerance).
void require_relative_tolerance(const std::string& name, double rtol);

/// The analysis window [s] of a scenario: from full load to the end, when braking from the later
/// of full load and brake on + 0.1 s to the earlier of brake off and the end; explicit
/// window_start_s / window_end_s override; the whole run if the window would be empty.
std::pair<double, double> analysis_window(const LandingScenario& scenario);

/// The gear's inputs furthest from the default gear's (GearConfig{}): a negative value where the
/// default is positive first ("structure.torsional_damping_nms_per_rad = -100 (negative; the
/// default is 216)"), then those 100 times or more off, by orders of magnitude, at most three in
/// all; "" when none is. A failed landing names them; an app can say them before it runs.
std::string unusual_gear_inputs(const GearConfig& config);

/// Integrates from t = 0 to scenario.end_time_s. Throws InvalidArgument for a bad
/// configuration or solver option (more than 1e6 samples included), std::runtime_error naming
/// the CVODE failure (flag, time) if the integrator gives up, Interrupted when options.stop asks.
LandingRun simulate_landing(const GearModel& model, const SolverOptions& options = {},
                            const ShimmyCriterion& criterion = {});

/// The inputs of a landing driven step by step (LandingStepper): the forward speed V [m/s] and
/// the brake torque command [N m], the anti-skid's T_max (landing_gear.hpp, LandingScenario).
struct LandingInputs {
  double forward_speed_mps = 70.0;  ///< V [m/s]
  double brake_torque_nm = 0.0;     ///< T_max [N m]; 0: brake off
};

/// A landing integrated piecewise by a host that drives it (the gear's Co-Simulation FMU): the
/// same CVODE set-up, events, mode switches and interpolated outputs as simulate_landing, with the
/// forward speed and the brake command as inputs held over each step instead of the scenario's
/// constant speed and brake events (scenario.braking, brake_on_s, brake_off_s and
/// brake_max_torque_nm are not used; the brake acts while the command is > 0, through the
/// scenario's anti-skid). A change of the inputs restarts the integrator where it stands.
class LandingStepper {
 public:
  /// Starts at t = 0 in the model's initial state. Throws InvalidArgument for a bad
  /// configuration, solver option (relative_tolerance, max_steps) or input.
  LandingStepper(const GearModel& model, const SolverOptions& options, const LandingInputs& inputs);
  ~LandingStepper();                                          ///< frees the integrator
  LandingStepper(const LandingStepper&) = delete;             ///< not copyable
  LandingStepper& operator=(const LandingStepper&) = delete;  ///< not copyable

  /// Throws InvalidArgument for a speed outside scenario.forward_speed_mps's range or a negative
  /// or non-finite torque.
  void set_inputs(const LandingInputs& inputs);
  /// Integrates from time() to t > time(), through the events on the way. Throws
  /// InvalidArgument for a t that is not finite or not after time(), and as simulate_landing
  /// does when the integrator gives up or options.stop asks.
  void advance_to(double t);

  double time() const;             ///< where the stepper stands [s]
  const GearState& state() const;  ///< the state at time()
  const GearMode& mode() const;    ///< the mode at time()
  LandingSample sample() const;    ///< time, state, contact and rolling flag at time()
  const GearModel& model() const;  ///< with the current inputs
  /// The events so far, the input's brake switches among them.
  const std::vector<LandingEvent>& events() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contensou
