#include "contensou/gear/bifurcation.hpp"
#include "contensou/gear/landing_simulation.hpp"

#include "cvode_handles.hpp"
#include "parallel_cells.hpp"
#include "serial_kernels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>

#include "contensou/gear/gear_parameters.hpp"
#include "contensou/gear/oscillation.hpp"

namespace contensou {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The states' scales (landing_gear.hpp, kStateScale).
constexpr const std::array<double, kStateSize>& kScale = kStateScale;

// The braked slide's fixed mode on the quasi-steady state's active states.
struct FixedProblem {
  const GearModel* model;
  const QuasiSteadyState* q;
  GearState full(N_Vector y) const {
    GearState x = q->x;
    for (std::size_t k = 0; k < q->states.size(); ++k)
      x[q->states[k]] = NV_Ith_S(y, static_cast<sunindextype>(k));
    return x;
  }
};

int fixed_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  const FixedProblem& p = *static_cast<const FixedProblem*>(data);
  const GearState dx = gear_rhs(*p.model, p.q->mode, t, p.full(y));
  for (std::size_t k = 0; k < p.q->states.size(); ++k) {
    const double d = dx[p.q->states[k]];
    if (!std::isfinite(d)) return 1;  // recoverable: CVODE retries with a smaller step
    NV_Ith_S(ydot, static_cast<sunindextype>(k)) = d;
  }
  return 0;
}

int fixed_jacobian(sunrealtype t, N_Vector y, N_Vector, SUNMatrix J, void* data, N_Vector, N_Vector,
                   N_Vector) {
  const FixedProblem& p = *static_cast<const FixedProblem*>(data);
  const GearJacobian A = gear_jacobian(*p.model, p.q->mode, t, p.full(y));
  if (!A.allFinite()) return 1;
  const std::vector<int>& s = p.q->states;
  for (std::size_t j = 0; j < s.size(); ++j)
    for (std::size_t i = 0; i < s.size(); ++i)
      SM_ELEMENT_D(J, static_cast<sunindextype>(i), static_cast<sunindextype>(j)) = A(s[i], s[j]);
  return 0;
}

void check(int flag, const char* what, double t) {
  if (flag < 0)
    throw std::runtime_error(std::string("CVODE ") + what + " failed with flag " +
                             std::to_string(flag) + " at t = " + format_value(t) +
                             " s (bifurcation sweep)");
}

// Samples of psi and psi' over a run of the fixed mode.
struct Samples {
  std::vector<double> t, psi, rate;
};

// CVODE (Adams-Moulton, structured Jacobian) on the fixed mode from x0 at q.t; advance() adds
// samples on the output grid.
class FixedModeRun {
 public:
  FixedModeRun(const GearModel& model, const QuasiSteadyState& q, const GearState& x0,
               const SweepOptions& o)
      : problem_{&model, &q}, options_(o), t_(q.t) {
    const auto n = static_cast<sunindextype>(q.states.size());
    check(SUNContext_Create(nullptr, &cv_.ctx), "SUNContext_Create", t_);
    cv_.y = N_VNew_Serial(n, cv_.ctx);
    cv_.atol = N_VNew_Serial(n, cv_.ctx);
    detail::use_compiled_vector_ops(cv_.y);
    detail::use_compiled_vector_ops(cv_.atol);
    for (std::size_t k = 0; k < q.states.size(); ++k) {
      NV_Ith_S(cv_.y, static_cast<sunindextype>(k)) = x0[q.states[k]];
      NV_Ith_S(cv_.atol, static_cast<sunindextype>(k)) =
          o.relative_tolerance * kScale[static_cast<std::size_t>(q.states[k])];
    }
    cv_.mem = CVodeCreate(CV_ADAMS, cv_.ctx);
    check(CVodeInit(cv_.mem, fixed_rhs, t_, cv_.y), "CVodeInit", t_);
    check(CVodeSVtolerances(cv_.mem, o.relative_tolerance, cv_.atol), "CVodeSVtolerances", t_);
    cv_.A = SUNDenseMatrix(n, n, cv_.ctx);
    cv_.LS = detail::compiled_dense_solver(cv_.y, cv_.A, cv_.ctx);
    if (!cv_.LS) throw std::runtime_error("CVODE linear solver could not be created (sweep)");
    check(CVodeSetLinearSolver(cv_.mem, cv_.LS, cv_.A), "CVodeSetLinearSolver", t_);
    check(CVodeSetJacFn(cv_.mem, fixed_jacobian), "CVodeSetJacFn", t_);
    check(CVodeSetUserData(cv_.mem, &problem_), "CVodeSetUserData", t_);
    check(CVodeSetMaxNumSteps(cv_.mem, 100000), "CVodeSetMaxNumSteps", t_);
  }

  // Integrates `duration` further, appending the samples.
  void advance(double duration, Samples& s) {
    const double dt = options_.output_interval_s, t0 = t_;
    const long n = std::lround(duration / dt);
    for (long k = 1; k <= n; ++k) {
      throw_if_stopped(options_.stop);
      double reached = t_;
      check(CVode(cv_.mem, t0 + static_cast<double>(k) * dt, cv_.y, &reached, CV_NORMAL), "CVode",
            t_);
      t_ = reached;
      const GearState x = problem_.full(cv_.y);
      s.t.push_back(t_);
      s.psi.push_back(x[kPsi]);
      s.rate.push_back(x[kPsiDot]);
    }
  }

  GearState state() const { return problem_.full(cv_.y); }

 private:
  FixedProblem problem_;
  SweepOptions options_;
  double t_;
  detail::CvodeHandles cv_;
};

// The first time after `start` at which a period's half swing reaches `level` (NaN if never).
double first_reaching(const Samples& s, double period, double level, double start) {
  if (!(period > 0.0) || s.t.empty()) return kNaN;
  double lo = s.psi.front(), hi = lo, from = s.t.front();
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    lo = std::min(lo, s.psi[i]);
    hi = std::max(hi, s.psi[i]);
    if (s.t[i] - from >= period) {
      if (0.5 * (hi - lo) >= level) return s.t[i] - start;
      lo = hi = s.psi[i];
      from = s.t[i];
    }
  }
  return kNaN;
}

// Where a direction's point starts: the deviation of the previous end state from its
// quasi-steady state (over the states both have), and that motion's amplitude.
struct Carry {
  GearState deviation = GearState::Zero();
  double amplitude_rad = 0.0;
  bool any = false;
};

// Whether a run from a small kick can have a time to onset: it settled on a cycle or still grows.
bool reaches_shimmy(CycleState s) {
  return s == CycleState::limit_cycle || s == CycleState::growing;
}

// Runs the fixed mode from x0 until settled (or longest_s); fills the point's cycle numbers.
void run_to_settled(const GearModel& model, const StabilityReport& rep, const GearState& x0,
                    const SweepOptions& o, SweepPoint& p, Carry& carry) {
  FixedModeRun run(model, rep.state, x0, o);
  Samples all;
  double segment = o.settle_s, total = 0.0;
  CycleTrend trend;
  double period = rep.frequency_hz > 0.0 ? 1.0 / rep.frequency_hz : 0.0;
  while (true) {
    const std::size_t first = all.t.size();
    run.advance(segment, all);
    total += segment;
    const auto tail = [&](const std::vector<double>& v) {
      return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(first), v.end());
    };
    const Samples seg{tail(all.t), tail(all.psi), tail(all.rate)};
    const OscillationEstimate osc = analyse_oscillation(seg.t, seg.rate, seg.psi);
    p.frequency_hz = osc.valid() ? osc.frequency_hz : 0.0;
    if (osc.valid()) period = 1.0 / osc.frequency_hz;
    trend = cycle_trend(seg.t, seg.psi, seg.rate, model.config.structure,
                        {period, seg.t.front(), seg.t.back()}, rep.growth_rate_per_s,
                        o.amplitude_threshold_rad);
    const bool done =
        trend.state == CycleState::limit_cycle || trend.state == CycleState::settled_small ||
        trend.state == CycleState::not_measured ||
        (trend.state == CycleState::decaying && trend.amplitude_rad < o.amplitude_threshold_rad);
    if (done || total >= o.longest_s - 1e-9) break;
    segment = std::min(total, o.longest_s - total);
  }
  p.state = trend.state;
  p.amplitude_rad = trend.amplitude_rad;
  p.torque_link_nm = trend.torque_link_nm;
  p.trend_per_s = trend.trend_per_s;
  p.run_s = total;
  p.valid = true;
  carry.deviation = run.state() - rep.state.x;
  carry.amplitude_rad = trend.amplitude_rad;
  carry.any = true;
}

// The time to onset: from a kick of seed_rate_radps at the quasi-steady state until a period's
// half swing first reaches the threshold, run in steps of settle_s / 2 up to longest_s (NaN if
// it does not).
double onset_from_kick(const GearModel& model, const StabilityReport& rep, const SweepOptions& o) {
  GearState kicked = rep.state.x;
  kicked[kPsiDot] += o.seed_rate_radps;
  FixedModeRun run(model, rep.state, kicked, o);
  const double period = rep.frequency_hz > 0.0 ? 1.0 / rep.frequency_hz : 0.0;
  Samples all;
  for (double total = 0.0; total < o.longest_s - 1e-9;) {
    const double step = std::min(0.5 * o.settle_s, o.longest_s - total);
    run.advance(step, all);
    total += step;
    const double t = first_reaching(all, period, o.amplitude_threshold_rad, rep.state.t);
    if (std::isfinite(t)) return t;
  }
  return kNaN;
}

// One point of a direction: the parameter set, the linearisation, the run from the carried
// motion (up: a small kick where it has died out; down, first point: a large twist).
SweepPoint sweep_point(const GearModel& base, const MapAxis& axis, int i, bool up,
                       const SweepOptions& o, Carry& carry) {
  SweepPoint p;
  p.value = axis.value(i);
  p.onset_s = kNaN;
  GearModel model = base;
  *gear_parameter(model.config, axis.parameter) = p.value;
  try {
    validate(model.config);
    StabilityOptions so;
    so.simulate_perturbation = false;
    const StabilityReport rep = assess_stability(model, StabilityPhase::braked_slide, so);
    p.eigen_growth_per_s = rep.growth_rate_per_s;
    p.eigen_frequency_hz = rep.frequency_hz;
    if (!rep.state.converged) {
      p.error = "no quasi-steady braked slide (the brake cannot hold its target slip)";
      carry = Carry{};
      return p;
    }
    GearState x0 = rep.state.x;
    if (carry.any)
      for (int s : rep.state.states) x0[s] += carry.deviation[s];
    // Up: a kick where the motion has all but died out; the time to onset, where the point
    // settles on a cycle or still grows, by a run of its own from the kick.
    const double before = carry.any ? carry.amplitude_rad : 0.0;
    if (up && before < 0.1 * o.amplitude_threshold_rad) x0[kPsiDot] += o.seed_rate_radps;
    if (!up && !carry.any) x0[kPsi] += o.start_amplitude_rad;
    run_to_settled(model, rep, x0, o, p, carry);
    if (up && reaches_shimmy(p.state)) p.onset_s = onset_from_kick(model, rep, o);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::exception& e) {
    p.valid = false;
    p.error = e.what();
    carry = Carry{};
  }
  return p;
}

std::vector<SweepPoint> sweep_direction(const GearModel& base, const MapAxis& axis, bool up,
                                        const SweepOptions& o) {
  std::vector<SweepPoint> points(static_cast<std::size_t>(axis.points));
  Carry carry;
  for (int k = 0; k < axis.points; ++k) {
    const int i = up ? k : axis.points - 1 - k;
    points[static_cast<std::size_t>(i)] = sweep_point(base, axis, i, up, o, carry);
  }
  return points;
}

std::vector<double> linear_boundaries(const std::vector<SweepPoint>& points) {
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    const SweepPoint &a = points[k], &b = points[k + 1];
    if (a.error.empty() && b.error.empty() &&
        (a.eigen_growth_per_s > 0.0) != (b.eigen_growth_per_s > 0.0))
      out.push_back(a.value + (b.value - a.value) * a.eigen_growth_per_s /
                                  (a.eigen_growth_per_s - b.eigen_growth_per_s));
  }
  return out;
}

void check_options(const SweepOptions& o) {
  require_positive("sweep settle_s", o.settle_s);
  require_positive("sweep longest_s", o.longest_s);
  require_relative_tolerance("sweep relative_tolerance", o.relative_tolerance);
  require_positive("sweep output_interval_s", o.output_interval_s);
  require_positive("sweep amplitude_threshold_rad", o.amplitude_threshold_rad);
  require_finite("sweep seed_rate_radps", o.seed_rate_radps);
  require_finite("sweep start_amplitude_rad", o.start_amplitude_rad);
  if (o.longest_s < o.settle_s)
    throw InvalidArgument("sweep longest_s", format_value(o.longest_s), "must be >= settle_s");
  if (o.longest_s / o.output_interval_s > 1e6)
    throw InvalidArgument("sweep output_interval_s", format_value(o.output_interval_s),
                          "with longest_s it asks for more than 1e6 samples a point");
}

}  // namespace

BifurcationSweep bifurcation_sweep(const GearModel& base, const MapAxis& axis,
                                   const SweepOptions& options) {
  return bifurcation_sweeps({base}, {axis}, options, 1, {}).front();
}

std::vector<BifurcationSweep> bifurcation_sweeps(const std::vector<GearModel>& models,
                                                 const std::vector<MapAxis>& axes,
                                                 const SweepOptions& options, unsigned threads,
                                                 const std::function<void(int, int)>& progress) {
  check_options(options);
  for (const GearModel& m : models)
    for (const MapAxis& a : axes) check_sweep_axis(m.config, a);
  std::vector<BifurcationSweep> out(models.size() * axes.size());
  for (std::size_t m = 0; m < models.size(); ++m)
    for (std::size_t a = 0; a < axes.size(); ++a) {
      out[m * axes.size() + a].contact = models[m].contact;
      out[m * axes.size() + a].axis = axes[a];
    }
  const int tasks = static_cast<int>(2 * out.size());
  std::exception_ptr failure;
  std::mutex lock;
  detail::run_cells_in_parallel(tasks, threads, progress, [&](int k) {
    const std::size_t s = static_cast<std::size_t>(k / 2);
    const bool up = k % 2 == 0;
    try {
      std::vector<SweepPoint> points =
          sweep_direction(models[s / axes.size()], axes[s % axes.size()], up, options);
      (up ? out[s].up : out[s].down) = std::move(points);
    } catch (...) {
      const std::lock_guard<std::mutex> guard(lock);
      if (!failure) failure = std::current_exception();
    }
  });
  if (failure) std::rethrow_exception(failure);
  for (BifurcationSweep& s : out) {
    s.linear_boundaries = linear_boundaries(s.up);
    s.linear_boundary = s.linear_boundaries.empty() ? kNaN : s.linear_boundaries.front();
  }
  return out;
}

}  // namespace contensou
