// Limit cycles and their continuation (docs/shimmy.md, "Limit cycles", "Bifurcation
// diagrams"): the amplitude trend of a synthetic oscillation, one quasi-steady state for the
// eigenvalues and the simulated landings (the drift kept in both: the landings either side of
// the eigenvalue boundary grow and decay), and a small bifurcation sweep against its own
// eigenvalues and against the torque link's spring.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/bifurcation.hpp"
#include "contensou/gear/cycle_trend.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "contensou/gear/stability_map.hpp"

using namespace contensou;

namespace {

constexpr double kPi = std::numbers::pi;

// psi = A e^{s t} sin(2 pi f t) sampled every 0.5 ms over [0, T].
struct Synthetic {
  std::vector<double> t, psi, rate;
};
Synthetic damped_sine(double A, double s, double f, double T) {
  Synthetic out;
  const double w = 2 * kPi * f;
  for (double t = 0.0; t <= T; t += 5e-4) {
    out.t.push_back(t);
    out.psi.push_back(A * std::exp(s * t) * std::sin(w * t));
    out.rate.push_back(A * std::exp(s * t) * (s * std::sin(w * t) + w * std::cos(w * t)));
  }
  return out;
}

}  // namespace

// Oracle: the trend of a sampled A e^{st} sin(wt) is s; its state follows the band 0.1 |eigen|
// (at least 0.03 1/s); the torque link is k A e^{sT} to the damper's share.
TEST(CycleTrend, RecoversTheGrowthOfASineAndClassifiesItAgainstTheBand) {
  GearStructure g;
  for (const double s : {-1.0, -0.2, 0.0, 0.02, 0.34, 2.0}) {
    const Synthetic x = damped_sine(0.03, s, 32.0, 1.0);
    const CycleTrend c = cycle_trend(x.t, x.psi, x.rate, g, {1.0 / 32.0, 0.3, 1.0}, 0.41, 1e-3);
    ASSERT_TRUE(c.measured);
    EXPECT_NEAR(c.trend_per_s, s, 0.02 + 0.01 * std::abs(s)) << "s = " << s;
    EXPECT_NEAR(c.band_per_s, 0.041, 1e-12);
    const CycleState want = std::abs(s) <= 0.041 ? CycleState::limit_cycle
                            : s > 0.0            ? CycleState::growing
                                                 : CycleState::decaying;
    EXPECT_EQ(c.state, want) << "s = " << s;
    // The last period's half swing: the envelope half a period before the end, to 1 %.
    const double envelope = 0.03 * std::exp(s * (1.0 - 0.5 / 32.0));
    EXPECT_NEAR(c.amplitude_rad, envelope, 0.01 * envelope) << "s = " << s;
    const double w = 2 * kPi * 32.0;
    EXPECT_NEAR(c.torque_link_nm,
                c.amplitude_rad * std::hypot(g.torsional_stiffness_nm_per_rad,
                                             g.torsional_damping_nms_per_rad * w),
                0.01 * g.torsional_stiffness_nm_per_rad * c.amplitude_rad);
  }
  // The case: a trend of +0.34 1/s against an eigenvalue of +0.41 1/s is not settled.
  const Synthetic x = damped_sine(0.03, 0.34, 32.0, 1.0);
  EXPECT_EQ(cycle_trend(x.t, x.psi, x.rate, g, {1.0 / 32.0, 0.3, 1.0}, 0.41, 1e-3).state,
            CycleState::growing);
  // Fewer than kTrendPeriods periods in the window: not measured.
  EXPECT_FALSE(cycle_trend(x.t, x.psi, x.rate, g, {1.0 / 32.0, 0.9, 1.0}, 0.41, 1e-3).measured);
  // A settled swing below the threshold is not a limit cycle.
  const Synthetic small = damped_sine(1e-4, 0.0, 32.0, 1.0);
  EXPECT_EQ(
      cycle_trend(small.t, small.psi, small.rate, g, {1.0 / 32.0, 0.3, 1.0}, -2.0, 1e-3).state,
      CycleState::settled_small);
}

// Oracle: a drift too slow for the last kTrendPeriods periods to show (s = 0.02 1/s, inside the
// band 0.041) moves the amplitude by e^{0.02 * 3.85} - 1 = 8 % between the window's middle and
// its end: growing (or decaying), not settled; the same sine with s = 0 settles.
TEST(CycleTrend, ASlowDriftOverTheWindowIsNotSettled) {
  GearStructure g;
  for (const double s : {0.02, -0.02, 0.0}) {
    const Synthetic x = damped_sine(0.03, s, 32.0, 8.0);
    const CycleTrend c = cycle_trend(x.t, x.psi, x.rate, g, {1.0 / 32.0, 0.3, 8.0}, 0.41, 1e-3);
    ASSERT_TRUE(c.measured);
    EXPECT_LE(std::abs(c.trend_per_s), c.band_per_s) << "s = " << s;
    EXPECT_NEAR(c.midway_s, 4.15, 1e-12);
    const double midway = 0.03 * std::exp(s * (4.15 - 0.5 / 32.0));
    EXPECT_NEAR(c.midway_amplitude_rad, midway, 0.01 * midway) << "s = " << s;
    EXPECT_EQ(c.drifting, s != 0.0) << "s = " << s;
    const CycleState want = s > 0.0   ? CycleState::growing
                            : s < 0.0 ? CycleState::decaying
                                      : CycleState::limit_cycle;
    EXPECT_EQ(c.state, want) << "s = " << s;
  }
}

namespace {

// The coupled braked slide at 60 m/s with the offset `l`, run to `end` s with the brake on to
// the end: the torsion's growth fitted on [window_start, end].
LandingRun long_braked_slide(double l, double end, double window_start) {
  GearConfig c;
  c.scenario.forward_speed_mps = 60.0;
  c.structure.offset_m = l;
  c.scenario.end_time_s = end;
  c.scenario.brake_off_s = end;
  c.scenario.window_start_s = window_start;
  c.scenario.window_end_s = end;
  SolverOptions o;
  o.record = false;
  return simulate_landing(make_gear_model(c, ContactModel::coupled), o);
}

}  // namespace

// One state: the eigenvalue boundary over the offset (drift kept, as the landings have it) and
// simulated landings one cell either side: below it the torsion decays, above it does not.
TEST(OneState, LandingsEitherSideOfTheEigenvalueBoundaryDecayAndGrow) {
  GearConfig c;
  c.scenario.forward_speed_mps = 60.0;
  const MapAxis x{"scenario.forward_speed_mps", 60.0, 60.0, 1};
  const MapAxis y{"structure.offset_m", 0.30, 0.46, 9};  // cells 0.02 m apart
  const StabilityMap m = linear_stability_map(make_gear_model(c, ContactModel::coupled), x, y,
                                              StabilityPhase::braked_slide, 1);
  int below = -1;
  for (int j = 0; j + 1 < y.points; ++j)
    if (m.cells[static_cast<std::size_t>(j)].valid &&
        !m.cells[static_cast<std::size_t>(j)].shimmy &&
        m.cells[static_cast<std::size_t>(j + 1)].shimmy) {
      below = j;
      break;
    }
  ASSERT_GE(below, 1) << "the boundary must lie inside the offset axis";
  ASSERT_LT(below + 2, y.points);
  // One cell further out on each side, so that the landings' side is not decided by the cell
  // that holds the boundary itself.
  const LandingRun stable = long_braked_slide(y.value(below - 1), 4.0, 1.5);
  const LandingRun unstable = long_braked_slide(y.value(below + 2), 4.0, 1.5);
  ASSERT_TRUE(stable.metrics.torsion.valid());
  ASSERT_TRUE(unstable.metrics.torsion.valid());
  EXPECT_LT(stable.metrics.torsion.growth_rate_per_s, 0.0) << "offset " << y.value(below - 1);
  // Above it the oscillation grows until a nonlinearity holds it (with the longitudinal
  // relaxation the coupled gear reaches its limit cycle, about 0.024 rad, within 0.3 s): it does
  // not decay, and it stays far above the stable side's.
  EXPECT_GT(unstable.metrics.torsion.growth_rate_per_s, -0.01) << "offset " << y.value(below + 2);
  EXPECT_GT(unstable.metrics.torsion.last_amplitude, 10.0 * stable.metrics.torsion.last_amplitude)
      << "offset " << y.value(below + 2);
}

// A small sweep of the offset: each point's eigenvalue growth is linear_growth_rate's at that
// value, the linear boundary lies between points of opposite sign, the up sweep has no cycle
// below it and settles on one well above it, and the torque-link load is the spring's k A to
// the damper's share.
TEST(Bifurcation, SweepAgreesWithItsEigenvaluesAndTheTorqueLinkSpring) {
  GearConfig c;
  c.scenario.forward_speed_mps = 58.0;
  const GearModel model = make_gear_model(c, ContactModel::coupled);
  const MapAxis axis{"structure.offset_m", 0.30, 0.54, 4};
  SweepOptions o;
  o.settle_s = 0.5;
  o.longest_s = 4.0;
  const BifurcationSweep s = bifurcation_sweep(model, axis, o);
  ASSERT_EQ(s.up.size(), 4u);
  ASSERT_EQ(s.down.size(), 4u);
  ASSERT_TRUE(std::isfinite(s.linear_boundary));
  EXPECT_GT(s.linear_boundary, axis.from);
  EXPECT_LT(s.linear_boundary, axis.to);
  const GearStructure& g = c.structure;
  for (const auto* points : {&s.up, &s.down})
    for (const SweepPoint& p : *points) {
      ASSERT_TRUE(p.valid) << p.error;
      GearModel at = model;
      at.config.structure.offset_m = p.value;
      EXPECT_NEAR(p.eigen_growth_per_s, linear_growth_rate(at, StabilityPhase::braked_slide), 1e-9);
      if (p.state == CycleState::limit_cycle) {
        EXPECT_NEAR(p.torque_link_nm, g.torsional_stiffness_nm_per_rad * p.amplitude_rad,
                    0.1 * g.torsional_stiffness_nm_per_rad * p.amplitude_rad);
        EXPECT_LE(std::abs(p.trend_per_s), settling_band(p.eigen_growth_per_s));
      }
    }
  EXPECT_LT(s.up.front().amplitude_rad, o.amplitude_threshold_rad) << "stable end: no cycle";
  EXPECT_EQ(s.up.back().state, CycleState::limit_cycle) << "well past the boundary: a cycle";
  // The first cycle of the up sweep grows from the kick: its time to onset is measured (by its
  // own run from the kick, within the longest run, whatever the sweep point ran when it carried
  // the cycle in), and it lies past the linear boundary.
  const auto first = std::find_if(s.up.begin(), s.up.end(), [](const SweepPoint& p) {
    return p.state == CycleState::limit_cycle;
  });
  ASSERT_NE(first, s.up.end());
  EXPECT_GT(first->value, s.linear_boundary);
  EXPECT_GT(first->onset_s, 0.0);
  EXPECT_LT(first->onset_s, o.longest_s);
  // Oracle for the time to onset: linear growth from the kick's swing psi' / (2 pi f) to the
  // threshold, ln(threshold 2 pi f / kick) / growth, to 20 % and a period (the last period's
  // swing is read at its end); none where the up sweep decays.
  int timed = 0;
  for (const SweepPoint& p : s.up) {
    if (p.eigen_growth_per_s <= 0.0) {
      EXPECT_TRUE(std::isnan(p.onset_s)) << p.value;
      continue;
    }
    if (!std::isfinite(p.onset_s)) continue;
    const double w = 2 * kPi * p.eigen_frequency_hz;
    const double linear =
        std::log(o.amplitude_threshold_rad * w / o.seed_rate_radps) / p.eigen_growth_per_s;
    EXPECT_NEAR(p.onset_s, linear, 0.2 * linear + 1.0 / p.eigen_frequency_hz) << p.value;
    ++timed;
  }
  EXPECT_GE(timed, 2);
  // A bad axis is refused by name.
  EXPECT_THROW(bifurcation_sweep(model, MapAxis{"structure.offset_m", -1e308, 1e308, 3}, o),
               InvalidArgument);
}
