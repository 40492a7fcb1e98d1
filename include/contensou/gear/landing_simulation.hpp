// Integration of the landing-gear model with SUNDIALS CVODE (Adams-Moulton or BDF with Newton
// iterations on a dense direct solver) and
// root-finding for the events: load onset, full load, end of spin-up (sliding -> rolling),
// renewed sliding (rolling -> sliding), brake on, brake off (docs/shimmy.md).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/oscillation.hpp"

namespace contensou {

// CVODE's linear multistep family. Adams-Moulton (orders 1-12) takes fewer steps than BDF
// (orders 1-5) on the landing's lightly damped 16-32 Hz modes at a given tolerance and is more
// accurate there (docs/shimmy.md, "Numerics"); its Newton iterations use the same Jacobian. BDF
// is for configurations much stiffer than the default gear (stiff struts, dampers of
// 1e4 1/s and more), where Adams' bounded stability region would force tiny steps.
enum class Integrator { adams, bdf };

// The absolute tolerance of each state is relative_tolerance times a scale: 1 mm, 0.1 m/s,
// 1 mrad, 0.1 rad/s, 100 rad/s, 1 mm, 1 mm, 0.1 m/s, 100 rad/s (y, y', psi, psi', Omega,
// lambda, x, x', Omega2).
struct SolverOptions {
  double relative_tolerance = 1e-7;
  double output_interval_s = 5e-4;  // samples for the time history and the shimmy analysis
  bool record = true;               // keep the samples (the analysis runs either way)
  long max_steps = 1000000;         // steps between two outputs
  // CVODE's Newton matrix from gear_jacobian (structured, analytic where the law allows), or
  // from CVODE's own difference quotients (one right-hand side per state) when false.
  bool analytic_jacobian = true;
  Integrator method = Integrator::adams;
  // Polled before every integrator step: the landing (and a map of them) throws Interrupted
  // once it returns true (error.hpp).
  StopRequest stop{};
};

struct LandingSample {
  double t = 0.0;
  GearState x = GearState::Zero();
  ContactState contact;
  bool rolling = false;
};

struct LandingEvent {
  double t = 0.0;
  std::string what;  // "load onset", "full load", "spin-up", "sliding", "brake on", "brake off"
};

// docs/shimmy.md, "What counts as shimmy": on the analysis window, the torsional oscillation
// grows or holds (fitted growth rate above sustained_growth_rate_per_s, which admits a
// saturated limit cycle) and ends above amplitude_threshold_rad.
struct ShimmyCriterion {
  double amplitude_threshold_rad = 1e-3;
  double sustained_growth_rate_per_s = -0.1;
};

struct ShimmyMetrics {
  bool shimmy = false;
  OscillationEstimate torsion;    // on the window
  double peak_torsion_rad = 0.0;  // max |psi| after touchdown
  double peak_lateral_m = 0.0;    // max |y| after touchdown
};

struct LandingRun {
  ContactModel contact = ContactModel::coupled;
  std::vector<LandingSample> samples;  // empty unless options.record
  std::vector<LandingEvent> events;
  std::optional<double>
      spin_up_s;  // touchdown to the end of spin-up (slip ratio below rolling_slip)
  double window_start_s = 0.0, window_end_s = 0.0;
  ShimmyMetrics metrics;
  long steps = 0;
  long rhs_evaluations = 0;       // by the integrator, including those of difference quotients
  long jacobian_evaluations = 0;  // Jacobians formed (analytic or by difference quotients)
  long linear_setups = 0;         // LU factorisations of the Newton matrix I - gamma J
  long newton_iterations = 0;
  long error_test_failures = 0;
  long convergence_failures = 0;  // of the Newton iteration
  double wall_s = 0.0;
};

// The analysis window of a scenario: the braked sliding phase [brake on + 0.1 s, brake off]
// when braking, else [full load, end]; explicit window_start_s / window_end_s override.
std::pair<double, double> analysis_window(const LandingScenario& scenario);

// Integrates from t = 0 to scenario.end_time_s. Throws InvalidArgument for a bad
// configuration or solver option, std::runtime_error naming the CVODE failure (flag, time) if
// the integrator gives up.
LandingRun simulate_landing(const GearModel& model, const SolverOptions& options = {},
                            const ShimmyCriterion& criterion = {});

// The inputs of a landing driven step by step (LandingStepper): the forward speed V [m/s] and
// the brake torque command [N m], the anti-skid's T_max (landing_gear.hpp, LandingScenario).
struct LandingInputs {
  double forward_speed_mps = 70.0;
  double brake_torque_nm = 0.0;  // 0: brake off
};

// A landing integrated piecewise by a host that drives it (the gear's Co-Simulation FMU): the
// same CVODE set-up, events, mode switches and interpolated outputs as simulate_landing, with the
// forward speed and the brake command as inputs held over each step instead of the scenario's
// constant speed and brake events (scenario.braking, brake_on_s, brake_off_s and
// brake_max_torque_nm are not used; the brake acts while the command is > 0, through the
// scenario's anti-skid). A change of the inputs restarts the integrator where it stands.
class LandingStepper {
 public:
  // Throws InvalidArgument for a bad configuration, solver option or input.
  LandingStepper(const GearModel& model, const SolverOptions& options, const LandingInputs& inputs);
  ~LandingStepper();
  LandingStepper(const LandingStepper&) = delete;
  LandingStepper& operator=(const LandingStepper&) = delete;

  // Throws InvalidArgument for a speed outside scenario.forward_speed_mps's range or a negative
  // or non-finite torque.
  void set_inputs(const LandingInputs& inputs);
  // Integrates from time() to t > time(), through the events on the way. Throws as
  // simulate_landing does when the integrator gives up.
  void advance_to(double t);

  double time() const;
  const GearState& state() const;
  const GearMode& mode() const;
  LandingSample sample() const;    // time, state, contact and mode at time()
  const GearModel& model() const;  // with the current inputs
  const std::vector<LandingEvent>& events() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contensou
