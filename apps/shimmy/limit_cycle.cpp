#include "limit_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace contensou::app {

namespace {

// Why the amplitude is not settled: its trend outside the band, or within it while the
// amplitude still moved more than kSettledChange since the window's middle (a slow drift).
std::string trend_words(const LimitCycle& c) {
  char buf[300];
  if (c.drifting)
    std::snprintf(buf, sizeof buf,
                  "%s %.1f %% from +-%.3g rad at %.3g s (trend %+.3f 1/s over the last %d periods, "
                  "within +-%.3f, yet a slow drift; eigenvalue %+.3f 1/s)",
                  c.amplitude_rad > c.midway_amplitude_rad ? "up" : "down",
                  100.0 * std::abs(c.amplitude_rad / c.midway_amplitude_rad - 1.0),
                  c.midway_amplitude_rad, c.midway_s, c.trend_per_s, kTrendPeriods, c.band_per_s,
                  c.eigen_growth_per_s);
  else
    std::snprintf(buf, sizeof buf, "trend %+.3f 1/s (outside +-%.3f; eigenvalue %+.3f 1/s)",
                  c.trend_per_s, c.band_per_s, c.eigen_growth_per_s);
  return buf;
}

std::string describe(const LimitCycle& c, const ShimmyCriterion& k) {
  char buf[400];
  const double e = c.eigen_growth_per_s;
  switch (c.state) {
    case CycleState::not_measured:
      return "no limit cycle measured (the window holds fewer than " +
             std::to_string(kTrendPeriods) + " periods)";
    case CycleState::limit_cycle: {
      std::string how;
      if (e <= 0.0) {
        how = ": stable to small motions, the swing the landing left is past an unstable cycle";
      } else if (c.start_amplitude_rad > (1.0 + kSettledChange) * c.amplitude_rad) {
        std::snprintf(buf, sizeof buf, ", reached from above: the window began at +-%.3g rad",
                      c.start_amplitude_rad);
        how = buf;
      }
      std::snprintf(buf, sizeof buf,
                    "%s: a limit cycle of +-%.3g rad (torque link +-%.3g N m), settled by %.3g s "
                    "(trend %+.3f 1/s within +-%.3f over %d periods, %+.1f %% since %.3g s; "
                    "eigenvalue %+.3f 1/s%s)",
                    e > 0.0 ? "shimmy" : "shimmy held by a nonlinearity", c.amplitude_rad,
                    c.torque_link_nm, c.run_end_s, c.trend_per_s, c.band_per_s, kTrendPeriods,
                    100.0 * (c.amplitude_rad / c.midway_amplitude_rad - 1.0), c.midway_s, e,
                    how.c_str());
      return buf;
    }
    case CycleState::settled_small:
      std::snprintf(buf, sizeof buf,
                    "settled at +-%.3g rad, below the threshold %.3g rad, by %.3g s (trend "
                    "%+.3f 1/s within +-%.3f; eigenvalue %+.3f 1/s)",
                    c.amplitude_rad, k.amplitude_threshold_rad, c.run_end_s, c.trend_per_s,
                    c.band_per_s, e);
      return buf;
    case CycleState::growing:
    case CycleState::decaying: {
      const bool up = c.state == CycleState::growing;
      const char* what = up ? (e > 0.0 ? "shimmy, still growing" : "still growing") : "decaying";
      std::snprintf(buf, sizeof buf, "%s: +-%.3g rad at %.3g s, %s", what, c.amplitude_rad,
                    c.run_end_s, trend_words(c).c_str());
      std::string out = buf;
      if (!up && e > 0.0)
        out +=
            ": unstable by eigenvalues, the landing's swing decays onto a cycle it has not "
            "reached yet";
      if (up && c.run_end_s >= kLongestRun) out += "; not settled within the longest run";
      return out;
    }
  }
  return "";
}

}  // namespace

LimitCycle assess_limit_cycle(const LandingRun& run, const GearStructure& structure,
                              double eigen_growth_per_s, double frequency_hz,
                              const ShimmyCriterion& criterion) {
  LimitCycle c;
  c.eigen_growth_per_s = eigen_growth_per_s;
  c.run_end_s = run.samples.empty() ? 0.0 : run.samples.back().t;
  if (!(frequency_hz > 0.0) && run.metrics.torsion.valid())
    frequency_hz = run.metrics.torsion.frequency_hz;
  std::vector<double> t, psi, rate;
  for (const LandingSample& s : run.samples) {
    if (s.t < run.window_start_s || s.t > run.window_end_s) continue;
    t.push_back(s.t);
    psi.push_back(s.x[kPsi]);
    rate.push_back(s.x[kPsiDot]);
  }
  static_cast<CycleTrend&>(c) = cycle_trend(
      t, psi, rate, structure,
      {frequency_hz > 0.0 ? 1.0 / frequency_hz : 0.0, run.window_start_s, run.window_end_s},
      eigen_growth_per_s, criterion.amplitude_threshold_rad);
  c.verdict = describe(c, criterion);
  return c;
}

bool worth_extending(const LimitCycle& c, const ShimmyCriterion& criterion) {
  if (c.state == CycleState::growing) return true;
  return c.state == CycleState::decaying && c.amplitude_rad > criterion.amplitude_threshold_rad;
}

LandingScenario extended_run(const LandingScenario& s, double end_s) {
  LandingScenario e = s;
  const double shift = end_s - s.end_time_s;
  e.end_time_s = end_s;
  // A braked slide that lasts to (near) the end goes on to the new end; so does an explicit
  // window that ends there.
  if (s.braking && s.brake_off_s >= s.end_time_s - 0.1) e.brake_off_s = s.brake_off_s + shift;
  if (s.window_end_s >= 0.0 && s.window_end_s >= s.end_time_s - 0.1)
    e.window_end_s = s.window_end_s + shift;
  return e;
}

}  // namespace contensou::app
