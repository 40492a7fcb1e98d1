#include "analysis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace contensou::app {
namespace {

Convergence check_convergence(const LandingRun& r, const LandingRun& t, double tight_tolerance,
                              const ShimmyCriterion& criterion) {
  Convergence c;
  c.tight_relative_tolerance = tight_tolerance;
  // A growth rate is compared only where there is an oscillation to measure: both runs see
  // one, above a noise floor of 1e-3 of the shimmy amplitude threshold (a torsion stuck by
  // Coulomb spin friction leaves crossings of integration noise only).
  const double floor = 1e-3 * criterion.amplitude_threshold_rad;
  c.measurable =
      r.metrics.torsion.valid() && t.metrics.torsion.valid() &&
      std::min(r.metrics.torsion.last_amplitude, t.metrics.torsion.last_amplitude) > floor;
  c.growth_rate_change_per_s =
      c.measurable
          ? std::abs(r.metrics.torsion.growth_rate_per_s - t.metrics.torsion.growth_rate_per_s)
          : 0.0;
  c.peak_torsion_relative_change =
      std::abs(r.metrics.peak_torsion_rad - t.metrics.peak_torsion_rad) /
      std::max(t.metrics.peak_torsion_rad, 1e-12);
  c.converged =
      c.growth_rate_change_per_s <= 0.05 + 0.02 * std::abs(t.metrics.torsion.growth_rate_per_s) &&
      c.peak_torsion_relative_change <= 0.02 && r.metrics.shimmy == t.metrics.shimmy;
  return c;
}

// The touchdown verdict: for the classical tire against its critical torsional damping, else
// the growth over the spin-up.
std::string touchdown_verdict(const ShimmyConfig& config, const GearModel& model,
                              const LandingRun& run, const StabilityReport& r) {
  char buf[200];
  if (run.contact == ContactModel::von_schlippe) {
    const double crit = classical_critical_damping(model);
    const double c = config.gear.structure.torsional_damping_nms_per_rad;
    if (crit > 0)
      std::snprintf(buf, sizeof buf, "%s; classical critical damping %.1f N m s/rad, margin %.2f",
                    r.stable() ? "stable" : "SHIMMY", crit, c / crit);
    else
      std::snprintf(buf, sizeof buf, "%s; stable without torsional damping",
                    r.stable() ? "stable" : "SHIMMY");
    return buf;
  }
  const double T = run.spin_up_s.value_or(0.0);
  const double growth = std::exp(r.growth_rate_per_s * T);
  std::snprintf(buf, sizeof buf,
                "%s: x%.3g over the %.3f s spin-up (%.1f cycles), worst at slip %.1f",
                r.growth_rate_per_s <= 0       ? "stable"
                : r.growth_rate_per_s * T >= 1 ? "GROWS within spin-up"
                                               : "grows, too slowly to matter",
                growth, T, r.frequency_hz * T, r.state.touchdown_slip);
  std::string verdict = buf;
  if (r.growth_rate_per_s > 0) verdict += " (" + r.mode_kind + " mode)";
  return verdict;
}

std::string braked_verdict(const StabilityReport& r) {
  if (r.stable()) return "stable";
  if (r.mode_kind == "fore-aft")
    return "UNSTABLE while braking: fore-aft mode (gear walk), not shimmy";
  return "SHIMMY while braking (" + r.mode_kind + " mode)";
}

// The oscillation at the end of the window; while it has not settled, the same landing run
// twice as long (up to kLongestRun), so that a limit cycle is declared only once it has.
LimitCycle settled_cycle(const ShimmyConfig& config, const GearModel& model, const LandingRun& run,
                         const StabilityReport& st) {
  LimitCycle c = assess_limit_cycle(run, config.gear.structure, st.growth_rate_per_s,
                                    st.frequency_hz, config.criterion);
  double end = config.gear.scenario.end_time_s, window_end = run.window_end_s;
  double finished = end;  // the end of the last run that finished
  while (worth_extending(c, config.criterion) && end < kLongestRun) {
    end = std::min(2.0 * end, kLongestRun);
    GearModel longer = model;
    longer.config.scenario = extended_run(config.gear.scenario, end);
    LandingRun r;
    try {
      r = simulate_landing(longer, config.solver, config.criterion);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::runtime_error& e) {
      // The verdict stays the finished run's, and says why it was not looked at longer.
      c.verdict += "; a run extended to " + format_value(end) +
                   " s to see it settle did not finish, so this is the " + format_value(finished) +
                   " s run's verdict (" + e.what() + ")";
      break;
    }
    if (!(r.window_end_s > window_end)) break;  // the window does not grow with the run
    finished = end;
    window_end = r.window_end_s;
    c = assess_limit_cycle(r, config.gear.structure, st.growth_rate_per_s, st.frequency_hz,
                           config.criterion);
  }
  return c;
}

// The stability verdicts of both phases (docs/shimmy.md, "Stability criterion"), by the
// eigenvalues of the linearisation and the growth after the standard perturbation.
ModelAnalysis analyse_model(const ShimmyConfig& config, const LandingRun& run,
                            const Convergence& convergence, const TireInput* tire) {
  const GearModel model = gear_model(config, run.contact, tire);
  ModelAnalysis a;
  a.convergence = convergence;
  a.touchdown.report = assess_touchdown(model);
  a.braked_slide.report = assess_stability(model, StabilityPhase::braked_slide);
  const char* no_state = "no quasi-steady state found";
  a.touchdown.verdict = a.touchdown.report.state.converged
                            ? touchdown_verdict(config, model, run, a.touchdown.report)
                            : no_state;
  a.braked_slide.verdict =
      a.braked_slide.report.state.converged ? braked_verdict(a.braked_slide.report) : no_state;
  const bool braking = config.gear.scenario.braking;
  a.limit_cycle_phase = braking ? "braked_slide" : "touchdown";
  const StabilityReport& st = braking ? a.braked_slide.report : a.touchdown.report;
  a.limit_cycle = settled_cycle(config, model, run, st);
  return a;
}

// The sample standard deviation of one coefficient over the draws.
template <class Get>
double draws_sd(const TireLawDraws& draws, Get get) {
  double m = 0, q = 0;
  for (const TireLawCoefficients& d : draws.draws) m += get(d);
  m /= static_cast<double>(draws.draws.size());
  for (const TireLawCoefficients& d : draws.draws) q += (get(d) - m) * (get(d) - m);
  return std::sqrt(q / static_cast<double>(std::max<std::size_t>(draws.draws.size() - 1, 1)));
}

// The Monte Carlo over the report's covariance: growth band and P(shimmy) of both phases for
// the coupled model at the configuration.
TireAnalysis analyse_tire(const ShimmyConfig& config, const TireInput& tire, unsigned threads,
                          const Progress& progress) {
  TireAnalysis t;
  t.sd_a = draws_sd(tire.draws, [](const TireLawCoefficients& d) { return d.a; });
  t.sd_m = draws_sd(tire.draws, [](const TireLawCoefficients& d) { return d.m; });
  t.sd_kx = draws_sd(tire.draws, [](const TireLawCoefficients& d) { return d.kx; });
  t.sd_spin_ratio = draws_sd(tire.draws, [](const TireLawCoefficients& d) { return d.spin_ratio; });
  const GearModel base = make_gear_model(config.gear, ContactModel::coupled);
  for (StabilityPhase phase : {StabilityPhase::touchdown, StabilityPhase::braked_slide}) {
    const std::string label = std::string("monte carlo ") + to_string(phase);
    (phase == StabilityPhase::touchdown ? t.touchdown : t.braked_slide) =
        growth_band(base, tire.draws.draws, phase, threads,
                    [&](int done, int total) { progress(label, done, total); });
  }
  return t;
}

}  // namespace

LandingAnalysis analyse_landings(const ShimmyConfig& config, const Landings& landings,
                                 const TireInput* tire, unsigned threads,
                                 const Progress& progress) {
  LandingAnalysis a;
  for (std::size_t k = 0; k < landings.runs.size(); ++k) {
    const Convergence c = check_convergence(landings.runs[k], landings.tight[k],
                                            landings.tight_relative_tolerance, config.criterion);
    a.models.push_back(analyse_model(config, landings.runs[k], c, tire));
  }
  if (tire) a.tire = analyse_tire(config, *tire, threads, progress);
  return a;
}

}  // namespace contensou::app
