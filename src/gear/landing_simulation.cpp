#include "contensou/gear/landing_simulation.hpp"

#include "cvode_handles.hpp"
#include "serial_kernels.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/gear_parameters.hpp"

namespace contensou {

std::pair<double, double> analysis_window(const LandingScenario& s) {
  double start = s.touchdown_time_s + s.load_ramp_s, end = s.end_time_s;
  if (s.braking) {
    start = std::max(start, s.brake_on_s + 0.1);
    end = std::min(end, s.brake_off_s);
  }
  if (s.window_start_s >= 0.0) start = s.window_start_s;
  if (s.window_end_s >= 0.0) end = s.window_end_s;
  if (!(end > start)) {  // e.g. a gear that never lands: the whole run
    start = 0.0;
    end = s.end_time_s;
  }
  return {start, end};
}

void require_relative_tolerance(const std::string& name, double rtol) {
  if (!(rtol >= kTightestRelativeTolerance && rtol < kLoosestRelativeTolerance))
    throw InvalidArgument(name, format_value(rtol),
                          "must lie in [1e-14, 0.1): CVODE cannot meet a tighter relative "
                          "tolerance in double precision, and a looser one is no integration");
}

namespace {

enum Root : int { kLoadOnset = 0, kFullLoad, kSpinUp, kSliding, kBrakeOn, kBrakeOff, kRoots };

// The states CVODE integrates: the optional ones (fore-aft x, x'; a twin's Omega2) only when
// switched on, so that a one-wheel gear pays nothing for them.
struct Problem {
  const GearModel* model;
  GearMode mode;
  std::vector<int> active;
  // The string tire (von_schlippe) slides on its friction circle until its slip ratio first falls
  // below rolling_slip; that instant is its spin-up (an event only: its forces do not switch).
  bool string_spun_up = false;
  int size() const { return static_cast<int>(active.size()); }
};

std::vector<int> active_states(const GearModel& m) {
  std::vector<int> a{kY, kYDot, kPsi, kPsiDot, kSpin, kLambda};
  if (m.config.structure.fore_aft_stiffness_n_per_m > 0.0) {
    a.push_back(kX);
    a.push_back(kXDot);
  }
  if (m.config.structure.wheel_spacing_m > 0.0) a.push_back(kSpin2);
  if (m.config.structure.carcass_compliance()) {
    a.push_back(kCarcassY);
    a.push_back(kCarcassPsi);
  }
  if (m.config.tire.longitudinal_relaxation_length_m > 0.0) {
    a.push_back(kSlipX);
    if (m.config.structure.wheel_spacing_m > 0.0) a.push_back(kSlipX2);
  }
  return a;
}

GearState to_state(const Problem& p, N_Vector v) {
  GearState x = GearState::Zero();
  for (int k = 0; k < p.size(); ++k) x[p.active[static_cast<std::size_t>(k)]] = NV_Ith_S(v, k);
  return x;
}

void from_state(const Problem& p, const GearState& x, N_Vector v) {
  for (int k = 0; k < p.size(); ++k) NV_Ith_S(v, k) = x[p.active[static_cast<std::size_t>(k)]];
}

int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  const Problem& p = *static_cast<const Problem*>(data);
  const GearState dx = gear_rhs(*p.model, p.mode, t, to_state(p, y));
  for (int k = 0; k < p.size(); ++k) {
    const double d = dx[p.active[static_cast<std::size_t>(k)]];
    if (!std::isfinite(d)) return 1;  // recoverable: CVODE retries with a smaller step
    NV_Ith_S(ydot, k) = d;
  }
  return 0;
}

int jacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector,
             N_Vector) {
  const Problem& p = *static_cast<const Problem*>(data);
  const GearJacobian A = gear_jacobian(*p.model, p.mode, t, to_state(p, y));
  if (!A.allFinite()) return 1;  // recoverable
  for (int j = 0; j < p.size(); ++j)
    for (int i = 0; i < p.size(); ++i)
      SM_ELEMENT_D(J, i, j) =
          A(p.active[static_cast<std::size_t>(i)], p.active[static_cast<std::size_t>(j)]);
  return 0;
}

// Event functions; an event that cannot happen in the current mode returns 1 (no crossing).
int roots(sunrealtype t, N_Vector y, sunrealtype* g, void* data) {
  const Problem& p = *static_cast<const Problem*>(data);
  const LandingScenario& s = p.model->config.scenario;
  const bool switching = p.model->contact != ContactModel::von_schlippe;
  // The patch's slip ratio vx / V from the kinematics alone (no friction law per event check).
  const GearStructure& gs = p.model->config.structure;
  const GearState x = to_state(p, y);
  const double psi = x[kPsi], V = s.forward_speed_mps;
  // A twin gear's mean wheel speed.
  const double spin = gs.wheel_spacing_m > 0.0 ? 0.5 * (x[kSpin] + x[kSpin2]) : x[kSpin];
  const double ratio =
      ((V + x[kXDot]) * std::cos(psi) + (x[kYDot] + s.drift_speed_mps) * std::sin(psi) -
       gs.offset_m * x[kPsiDot] - spin * gs.wheel_radius_m) /
      V;
  g[kLoadOnset] = t - s.touchdown_time_s;
  g[kFullLoad] = t - (s.touchdown_time_s + s.load_ramp_s);
  const bool spinning_up =
      switching ? p.mode.loaded && !p.mode.rolling : p.mode.loaded && !p.string_spun_up;
  g[kSpinUp] = spinning_up ? ratio - s.rolling_slip : 1.0;
  g[kSliding] = switching && p.mode.rolling ? ratio - s.sliding_slip : -1.0;
  g[kBrakeOn] = s.braking ? t - s.brake_on_s : -1.0;
  g[kBrakeOff] = s.braking ? t - s.brake_off_s : -1.0;
  return 0;
}

using Cvode = detail::CvodeHandles;

void check(int flag, const char* what, double t) {
  if (flag < 0)
    throw std::runtime_error(std::string("CVODE ") + what + " failed with flag " +
                             std::to_string(flag) + " at t = " + std::to_string(t) + " s");
}

// The parameters furthest from the default gear's, by orders of magnitude (at least 100x, at
// most three): the likely cause of a failed integration, named in its message.
std::string unusual_parameters(const GearConfig& given) {
  GearConfig g = given, reference;
  std::vector<std::pair<double, std::string>> far;
  for (const std::string& name : gear_parameter_names()) {
    const double given_value = *gear_parameter(g, name),
                 default_value = *gear_parameter(reference, name);
    if (given_value < 0.0 && default_value > 0.0) {  // a damping that feeds energy, say: first
      far.emplace_back(1e9, name + " = " + format_value(given_value) +
                                " (negative; the default is " + format_value(default_value) + ")");
      continue;
    }
    const double a = std::abs(given_value), b = std::abs(default_value);
    if (a == b || !(a > 0.0 && b > 0.0)) continue;
    const double decades = std::abs(std::log10(a / b));
    if (decades >= 2.0)
      far.emplace_back(decades, name + " = " + format_value(*gear_parameter(g, name)));
  }
  std::sort(far.rbegin(), far.rend());
  std::string out;
  for (std::size_t i = 0; i < std::min<std::size_t>(far.size(), 3); ++i)
    out += (i ? ", " : "") + far[i].second +
           (far[i].first >= 1e9
                ? std::string()
                : " (1e" + std::to_string(static_cast<int>(far[i].first)) + "x off the default)");
  return out;
}

// A failed step of the integrator: what CVODE's flag means and which inputs look responsible.
void check_step(int flag, const char* what, double t, const GearConfig& config) {
  if (flag >= 0) return;
  char* name = CVodeGetReturnFlagName(flag);
  const std::string meaning =
      flag == CV_TOO_MUCH_WORK ? "too many steps (the motion has become far stiffer or faster "
                                 "than a landing gear's: a gear driven unstable, say)"
      : flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE
          ? "the step size fell to its minimum: the state grows without bound or jumps"
          : "the integrator stopped";
  const std::string unusual = unusual_parameters(config);
  std::string message = std::string("CVODE ") + what + " failed at t = " + format_value(t) +
                        " s with " + (name ? std::string(name) : "flag " + std::to_string(flag)) +
                        ": " + meaning +
                        (unusual.empty() ? "" : "; inputs far from the default gear's: " + unusual);
  std::free(name);  // CVodeGetReturnFlagName allocates
  throw std::runtime_error(message);
}

// The samples of the analysis window: time, torsion rate psi', torsion psi.
struct Window {
  std::vector<double> t, rate, psi;
};

ShimmyMetrics assess(const Window& window, double peak_torsion, double peak_lateral,
                     const ShimmyCriterion& criterion) {
  ShimmyMetrics m;
  m.torsion = analyse_oscillation(window.t, window.rate, window.psi);
  m.peak_torsion_rad = peak_torsion;
  m.peak_lateral_m = peak_lateral;
  const double a = m.torsion.last_amplitude, thr = criterion.amplitude_threshold_rad;
  m.shimmy = m.torsion.valid() && a > thr &&
             m.torsion.growth_rate_per_s > criterion.sustained_growth_rate_per_s;
  return m;
}

// The solver options a landing needs (the gear's own are validate()'s): positive tolerance and
// interval, at most 1e6 samples, at least one step between outputs.
void check_options(const GearModel& model, const SolverOptions& options) {
  require_relative_tolerance("solver.relative_tolerance", options.relative_tolerance);
  require_positive("solver.output_interval_s", options.output_interval_s);
  // The time history is kept in memory (and written by the apps): bounded, with the number.
  constexpr double kMostSamples = 1e6;
  const double samples = model.config.scenario.end_time_s / options.output_interval_s;
  if (!(samples <= kMostSamples)) {
    char count[32];
    std::snprintf(count, sizeof count, "%.3g", samples);
    throw InvalidArgument(
        "solver.output_interval_s", format_value(options.output_interval_s),
        "with scenario.end_time_s = " + format_value(model.config.scenario.end_time_s) +
            " it asks for " + count +
            " samples; at most 1e6 are kept (a longer interval or a shorter "
            "run)");
  }
  if (options.max_steps < 1)
    throw InvalidArgument("solver.max_steps", std::to_string(options.max_steps), "must be >= 1");
  if (options.max_total_steps < 0)
    throw InvalidArgument("solver.max_total_steps", std::to_string(options.max_total_steps),
                          "must be >= 0 (0: no bound)");
}

// CVODE on the problem's active states from x at t = 0: vectors, tolerances (relative_tolerance
// times each state's scale, landing_simulation.hpp), method, dense linear solver, Jacobian,
// events.
void start_cvode(Cvode& cv, Problem& problem, const GearState& x, const SolverOptions& options) {
  const int n = problem.size();
  check(SUNContext_Create(nullptr, &cv.ctx), "SUNContext_Create", 0.0);
  cv.y = N_VNew_Serial(n, cv.ctx);
  cv.atol = N_VNew_Serial(n, cv.ctx);
  cv.out = N_VNew_Serial(n, cv.ctx);
  // CVODE's vector arithmetic and LU compiled with the project (serial_kernels.hpp); its clones
  // of y and atol inherit the operations.
  detail::use_compiled_vector_ops(cv.y);
  detail::use_compiled_vector_ops(cv.atol);
  detail::use_compiled_vector_ops(cv.out);
  from_state(problem, x, cv.y);
  for (int k = 0; k < n; ++k) {
    NV_Ith_S(cv.atol, k) =
        options.relative_tolerance *
        kStateScale[static_cast<std::size_t>(problem.active[static_cast<std::size_t>(k)])];
  }
  cv.mem = CVodeCreate(options.method == Integrator::bdf ? CV_BDF : CV_ADAMS, cv.ctx);
  const double t = 0.0;
  check(CVodeInit(cv.mem, rhs, t, cv.y), "CVodeInit", t);
  check(CVodeSVtolerances(cv.mem, options.relative_tolerance, cv.atol), "CVodeSVtolerances", t);
  cv.A = SUNDenseMatrix(n, n, cv.ctx);
  cv.LS = detail::compiled_dense_solver(cv.y, cv.A, cv.ctx);
  if (!cv.LS) throw std::runtime_error("CVODE linear solver could not be created");
  check(CVodeSetLinearSolver(cv.mem, cv.LS, cv.A), "CVodeSetLinearSolver", t);
  if (options.analytic_jacobian) check(CVodeSetJacFn(cv.mem, jacobian), "CVodeSetJacFn", t);
  check(CVodeSetUserData(cv.mem, &problem), "CVodeSetUserData", t);
  check(CVodeRootInit(cv.mem, kRoots, roots), "CVodeRootInit", t);
  std::array<int, kRoots> direction{1, 1, -1, 1, 1, 1};
  check(CVodeSetRootDirection(cv.mem, direction.data()), "CVodeSetRootDirection", t);
  check(CVodeSetNoInactiveRootWarn(cv.mem), "CVodeSetNoInactiveRootWarn", t);
}

// What a landing keeps of each output sample: the analysis window (what assess() reads: t, psi',
// psi), the peaks after touchdown and, with options.record, the time history.
class Recorder {
 public:
  Recorder(const Problem& problem, const SolverOptions& options, LandingRun& run)
      : problem_(problem), options_(options), run_(run) {
    const LandingScenario& s = problem.model->config.scenario;
    const auto expected = static_cast<std::size_t>(std::clamp(
        (run.window_end_s - run.window_start_s) / options.output_interval_s + 2.0, 0.0, 1e6));
    window_.t.reserve(expected);
    window_.rate.reserve(expected);
    window_.psi.reserve(expected);
    if (options.record)
      run.samples.reserve(static_cast<std::size_t>(
          std::clamp(s.end_time_s / options.output_interval_s + 8.0, 0.0, 1e6)));
  }

  void operator()(double time, N_Vector v) {
    const GearModel& model = *problem_.model;
    LandingSample sample{time, to_state(problem_, v), {}, problem_.mode.rolling};
    // The contact is kept for the time histories only; the analysis needs the state alone.
    if (options_.record) sample.contact = contact_state(model, problem_.mode, time, sample.x);
    if (time >= model.config.scenario.touchdown_time_s) {
      peak_torsion_ = std::max(peak_torsion_, std::abs(sample.x[kPsi]));
      peak_lateral_ = std::max(peak_lateral_, std::abs(sample.x[kY]));
    }
    if (time >= run_.window_start_s && time <= run_.window_end_s) {
      window_.t.push_back(time);
      window_.rate.push_back(sample.x[kPsiDot]);
      window_.psi.push_back(sample.x[kPsi]);
    }
    if (options_.record) run_.samples.push_back(sample);
  }

  ShimmyMetrics metrics(const ShimmyCriterion& criterion) const {
    return assess(window_, peak_torsion_, peak_lateral_, criterion);
  }

 private:
  const Problem& problem_;
  const SolverOptions& options_;
  LandingRun& run_;
  Window window_;
  double peak_torsion_ = 0.0, peak_lateral_ = 0.0;
};

// The integrator's counters, added to the run's: they restart at each CVodeReInit.
void add_counters(void* mem, LandingRun& run) {
  long steps = 0, rhs = 0, lin_rhs = 0, jac = 0, setups = 0, iters = 0, fails = 0, conv = 0;
  CVodeGetNumSteps(mem, &steps);
  CVodeGetNumRhsEvals(mem, &rhs);
  CVodeGetNumLinRhsEvals(mem, &lin_rhs);
  CVodeGetNumJacEvals(mem, &jac);
  CVodeGetNumLinSolvSetups(mem, &setups);
  CVodeGetNumNonlinSolvIters(mem, &iters);
  CVodeGetNumErrTestFails(mem, &fails);
  CVodeGetNumNonlinSolvConvFails(mem, &conv);
  run.steps += steps;
  run.rhs_evaluations += rhs + lin_rhs;
  run.jacobian_evaluations += jac;
  run.linear_setups += setups;
  run.newton_iterations += iters;
  run.error_test_failures += fails;
  run.convergence_failures += conv;
}

// The events CVODE found at its root t: the mode switches, the log and the state to restart
// from (x, changed at the end of spin-up so that Fy is continuous). Returns the event's time: a
// time event (load onset, full load, brake on/off) is located by CVODE to within rounding, either
// side of its instant; the instant itself is taken, so that whether the sample there (e.g. at
// brake off, the analysis window's end) counts does not hang on the root finder.
double apply_events(Problem& problem, const std::array<int, kRoots>& found, double t, GearState& x,
                    LandingRun& run) {
  const GearModel& model = *problem.model;
  const LandingScenario& s = model.config.scenario;
  if (!found[kSpinUp] && !found[kSliding]) {
    if (found[kLoadOnset]) t = s.touchdown_time_s;
    if (found[kFullLoad]) t = s.touchdown_time_s + s.load_ramp_s;
    if (found[kBrakeOn]) t = s.brake_on_s;
    if (found[kBrakeOff]) t = s.brake_off_s;
  }
  GearMode& mode = problem.mode;
  if (found[kLoadOnset]) {
    mode.loaded = true;
    run.events.push_back({t, "load onset"});
  }
  if (found[kFullLoad]) run.events.push_back({t, "full load"});
  if (found[kSpinUp] && model.contact == ContactModel::von_schlippe) {
    problem.string_spun_up = true;
    if (!run.spin_up_s) run.spin_up_s = t - s.touchdown_time_s;
    run.events.push_back({t, "spin-up"});
  } else if (found[kSpinUp]) {
    // The string takes the sliding lateral force over, so Fy is continuous.
    const ContactState cs = contact_state(model, mode, t, x);
    mode.rolling = true;
    x[kLambda] = string_deflection_for_force(model, t, x, cs.force.Fy);
    if (!run.spin_up_s) run.spin_up_s = t - s.touchdown_time_s;
    run.events.push_back({t, "spin-up"});
  }
  if (found[kSliding]) {
    mode.rolling = false;
    run.events.push_back({t, "sliding"});
  }
  if (found[kBrakeOn]) {
    mode.brake_command = true;
    run.events.push_back({t, "brake on"});
  }
  if (found[kBrakeOff]) {
    mode.brake_command = false;
    run.events.push_back({t, "brake off"});
  }
  return t;
}

// Where the integrator stands between outputs.
struct Progress {
  double reached = 0.0;  // the integrator's time t_n
  bool root = false;     // a root found at root_t and not handled yet
  double root_t = 0.0;
  long steps_since_output = 0;
  long total_steps = 0;
};

// CVODE steps (CV_ONE_STEP) until it passes tout or finds a root; solver.max_steps bounds the
// steps between two outputs, as CVodeSetMaxNumSteps does in CV_NORMAL, and
// solver.max_total_steps those of the whole landing.
void step_to(Cvode& cv, double tout, const GearModel& model, const SolverOptions& options,
             Progress& p) {
  while (!p.root && p.reached < tout) {
    if (++p.steps_since_output > options.max_steps)
      check_step(CV_TOO_MUCH_WORK, "CVode (solver.max_steps between outputs)", p.reached,
                 model.config);
    if (options.max_total_steps > 0 && ++p.total_steps > options.max_total_steps)
      check_step(CV_TOO_MUCH_WORK,
                 ("CVode (solver.max_total_steps = " + std::to_string(options.max_total_steps) +
                  " in one landing, which takes a few thousand)")
                     .c_str(),
                 p.reached, model.config);
    throw_if_stopped(options.stop);
    double returned = p.reached;
    const int flag = CVode(cv.mem, tout, cv.y, &returned, CV_ONE_STEP);
    check_step(flag, "CVode", returned, model.config);
    check(CVodeGetCurrentTime(cv.mem, &p.reached), "CVodeGetCurrentTime", returned);
    if (flag == CV_ROOT_RETURN) {
      p.root = true;
      p.root_t = returned;
    }
  }
}

// From t = 0 to the scenario's end: the samples on the output grid are CVODE's interpolant there
// (CVodeGetDky), which is what CV_NORMAL would return, without a call and a root search split at
// every grid point; an event is handled when the output reaches it, and CVODE restarts there.
void integrate(Cvode& cv, Problem& problem, const SolverOptions& options, Recorder& record,
               LandingRun& run) {
  const GearModel& model = *problem.model;
  const double end = model.config.scenario.end_time_s, dt = options.output_interval_s;
  double t = 0.0;
  long grid = 1;
  Progress p;
  while (t < end) {
    const double tout = std::min(static_cast<double>(grid) * dt, end);
    if (tout - t < 1e-9 * dt) {  // an event fell on the grid point
      record(t, cv.y);
      ++grid;
      continue;
    }
    step_to(cv, tout, model, options, p);
    if (!p.root || tout < p.root_t) {
      check(CVodeGetDky(cv.mem, tout, 0, cv.out), "CVodeGetDky", tout);
      t = tout;
      record(t, cv.out);
      p.steps_since_output = 0;
      ++grid;
      continue;
    }
    // The event: cv.y holds the state at the root.
    p.root = false;
    std::array<int, kRoots> found{};
    check(CVodeGetRootInfo(cv.mem, found.data()), "CVodeGetRootInfo", p.root_t);
    GearState x = to_state(problem, cv.y);
    t = apply_events(problem, found, p.root_t, x, run);
    add_counters(cv.mem, run);
    from_state(problem, x, cv.y);
    check(CVodeReInit(cv.mem, t, cv.y), "CVodeReInit", t);
    p.reached = t;
  }
  add_counters(cv.mem, run);
}

// The stepper's integration from its time to tout: CVODE's interpolant at tout, or the events
// on the way (the same handling as integrate()).
struct Stepping {
  GearModel model;
  SolverOptions options;
  Problem problem;
  Cvode cv;
  Progress progress;
  LandingRun run;  // events and counters
  double t = 0.0;
  GearState x = GearState::Zero();
};

void restart(Stepping& s) {
  from_state(s.problem, s.x, s.cv.y);
  check(CVodeReInit(s.cv.mem, s.t, s.cv.y), "CVodeReInit", s.t);
  s.progress = Progress{};
  s.progress.reached = s.t;
}

void advance(Stepping& s, double tout) {
  while (s.t < tout) {
    // An event within rounding of tout: its state stands for tout's (as integrate() records it).
    if (tout - s.t <= 1e-12 * std::max(1.0, std::abs(tout))) {
      s.t = tout;
      return;
    }
    step_to(s.cv, tout, s.model, s.options, s.progress);
    Progress& p = s.progress;
    if (!p.root || tout < p.root_t) {
      check(CVodeGetDky(s.cv.mem, tout, 0, s.cv.out), "CVodeGetDky", tout);
      s.x = to_state(s.problem, s.cv.out);
      s.t = tout;
      p.steps_since_output = 0;
      return;
    }
    p.root = false;
    std::array<int, kRoots> found{};
    check(CVodeGetRootInfo(s.cv.mem, found.data()), "CVodeGetRootInfo", p.root_t);
    s.x = to_state(s.problem, s.cv.y);
    s.t = apply_events(s.problem, found, p.root_t, s.x, s.run);
    add_counters(s.cv.mem, s.run);
    restart(s);
  }
}

}  // namespace

std::string unusual_gear_inputs(const GearConfig& config) {
  return unusual_parameters(config);
}

struct LandingStepper::Impl : Stepping {};

LandingStepper::LandingStepper(const GearModel& model, const SolverOptions& options,
                               const LandingInputs& inputs)
    : impl_(std::make_unique<Impl>()) {
  Stepping& s = *impl_;
  s.model = model;
  s.model.config.scenario.braking = false;  // the brake is the input's
  s.options = options;
  s.options.max_total_steps = 0;  // a stepped run (the FMU) has no end; max_steps bounds a step
  validate(s.model.config);
  require_relative_tolerance("solver.relative_tolerance", options.relative_tolerance);
  if (options.max_steps < 1)
    throw InvalidArgument("solver.max_steps", std::to_string(options.max_steps), "must be >= 1");
  s.problem = Problem{&s.model, initial_mode(s.model), active_states(s.model)};
  s.x = initial_state(s.model);
  start_cvode(s.cv, s.problem, s.x, options);
  set_inputs(inputs);
}

LandingStepper::~LandingStepper() = default;

void LandingStepper::set_inputs(const LandingInputs& inputs) {
  Stepping& s = *impl_;
  LandingScenario& scenario = s.model.config.scenario;
  if (inputs.forward_speed_mps == scenario.forward_speed_mps &&
      inputs.brake_torque_nm == scenario.brake_max_torque_nm &&
      s.problem.mode.brake_command == (inputs.brake_torque_nm > 0.0))
    return;
  GearConfig trial = s.model.config;
  trial.scenario.forward_speed_mps = inputs.forward_speed_mps;
  check_gear_parameter(*find_gear_parameter("scenario.forward_speed_mps"), trial);
  require_finite("brake_torque_nm", inputs.brake_torque_nm);
  require_non_negative("brake_torque_nm", inputs.brake_torque_nm);
  scenario.forward_speed_mps = inputs.forward_speed_mps;
  scenario.brake_max_torque_nm = inputs.brake_torque_nm;
  const bool brake = inputs.brake_torque_nm > 0.0;
  if (brake != s.problem.mode.brake_command)
    s.run.events.push_back({s.t, brake ? "brake on" : "brake off"});
  s.problem.mode.brake_command = brake;
  restart(s);  // the right-hand side jumps: CVODE starts afresh from the state at time()
}

void LandingStepper::advance_to(double t) {
  require_finite("t", t);
  if (!(t > impl_->t))
    throw InvalidArgument("t", format_value(t),
                          "must be after the stepper's time " + format_value(impl_->t) + " s");
  const double from = impl_->t;
  try {
    advance(*impl_, t);
  } catch (const Interrupted&) {
    throw;  // asked for: not a failure of the step
  } catch (const std::runtime_error& e) {
    // The step itself is context the host needs (a communication step of 1e300 s, say).
    const bool budget = impl_->progress.steps_since_output > impl_->options.max_steps;
    throw std::runtime_error(std::string(e.what()) + "; in a step of " + format_value(t - from) +
                             " s from t = " + format_value(from) + " s" +
                             (budget ? ": take shorter steps, or raise solver.max_steps" : ""));
  }
}

double LandingStepper::time() const {
  return impl_->t;
}
const GearState& LandingStepper::state() const {
  return impl_->x;
}
const GearMode& LandingStepper::mode() const {
  return impl_->problem.mode;
}
const GearModel& LandingStepper::model() const {
  return impl_->model;
}
const std::vector<LandingEvent>& LandingStepper::events() const {
  return impl_->run.events;
}

LandingSample LandingStepper::sample() const {
  const Stepping& s = *impl_;
  return {s.t, s.x, contact_state(s.model, s.problem.mode, s.t, s.x), s.problem.mode.rolling};
}

LandingRun simulate_landing(const GearModel& model, const SolverOptions& options,
                            const ShimmyCriterion& criterion) {
  const auto clock_start = std::chrono::steady_clock::now();
  validate(model.config);
  check_options(model, options);
  LandingRun run;
  run.contact = model.contact;
  std::tie(run.window_start_s, run.window_end_s) = analysis_window(model.config.scenario);
  Problem problem{&model, initial_mode(model), active_states(model)};
  Cvode cv;
  start_cvode(cv, problem, initial_state(model), options);
  Recorder record(problem, options, run);
  record(0.0, cv.y);
  integrate(cv, problem, options, record, run);
  run.metrics = record.metrics(criterion);
  run.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return run;
}

}  // namespace contensou
