#include "limit_cycle.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace contensou::app {

namespace {

// Half the swing of psi and of the strut's torsional moment over samples with t in [from, to].
std::pair<double, double> half_swings(const LandingRun& run, const GearStructure& g, double from,
                                      double to) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, mlo = lo, mhi = -lo;
  for (const LandingSample& s : run.samples) {
    if (s.t < from || s.t > to) continue;
    const double psi = s.x[kPsi];
    const double moment =
        g.torsional_stiffness_nm_per_rad * psi + g.torsional_damping_nms_per_rad * s.x[kPsiDot];
    lo = std::min(lo, psi);
    hi = std::max(hi, psi);
    mlo = std::min(mlo, moment);
    mhi = std::max(mhi, moment);
  }
  if (!(lo <= hi)) return {0.0, 0.0};
  return {0.5 * (hi - lo), 0.5 * (mhi - mlo)};
}

std::string describe(const LimitCycle& c, double eigen_growth, const ShimmyCriterion& k) {
  char buf[320];
  const bool unstable = eigen_growth > 0.0, above = c.amplitude_rad > k.amplitude_threshold_rad;
  const bool steady = std::abs(c.trend_per_s) <= 0.5;
  if (unstable && above && steady)
    std::snprintf(buf, sizeof buf, "shimmy: a limit cycle of +-%.3g rad (torque link +-%.3g N m)%s",
                  c.amplitude_rad, c.torque_link_nm,
                  c.trend_per_s < 0 ? ", reached from above: the spin-up left a larger swing" : "");
  else if (unstable && above)
    std::snprintf(buf, sizeof buf,
                  "shimmy: %s at +-%.3g rad (trend %+.2f 1/s; torque link +-%.3g N m)",
                  c.trend_per_s > 0 ? "still growing" : "settling toward a limit cycle",
                  c.amplitude_rad, c.trend_per_s, c.torque_link_nm);
  else if (unstable)
    std::snprintf(buf, sizeof buf,
                  "unstable by eigenvalues, but +-%.3g rad at the window's end is below the "
                  "threshold %.3g rad: it grows too slowly to show in the window",
                  c.amplitude_rad, k.amplitude_threshold_rad);
  else if (above && c.trend_per_s > -0.5)
    std::snprintf(buf, sizeof buf,
                  "stable by eigenvalues; +-%.3g rad held by a nonlinearity the linearisation "
                  "does not see (trend %+.2f 1/s)",
                  c.amplitude_rad, c.trend_per_s);
  else
    std::snprintf(buf, sizeof buf, "stable: +-%.3g rad at the window's end, trend %+.2f 1/s",
                  c.amplitude_rad, c.trend_per_s);
  return buf;
}

}  // namespace

LimitCycle assess_limit_cycle(const LandingRun& run, const GearStructure& structure,
                              double eigen_growth_per_s, double frequency_hz,
                              const ShimmyCriterion& criterion) {
  LimitCycle c;
  const double period = frequency_hz > 0.0 ? 1.0 / frequency_hz : 0.0;
  const double end = run.window_end_s, span = 3.0 * period;
  if (period <= 0.0 || run.samples.empty() || end - 2.0 * span < run.window_start_s) {
    c.verdict = "no limit cycle measured (the window holds fewer than six periods)";
    return c;
  }
  c.measured = true;
  std::tie(c.amplitude_rad, c.torque_link_nm) = half_swings(run, structure, end - span, end);
  c.earlier_amplitude_rad = half_swings(run, structure, end - 2.0 * span, end - span).first;
  if (c.amplitude_rad > 0.0 && c.earlier_amplitude_rad > 0.0)
    c.trend_per_s = std::log(c.amplitude_rad / c.earlier_amplitude_rad) / span;
  c.verdict = describe(c, eigen_growth_per_s, criterion);
  return c;
}

}  // namespace contensou::app
