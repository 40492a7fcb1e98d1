// The torsional oscillation at the end of a landing's analysis window, read from its samples:
// amplitude, its trend, the torque-link load, and a verdict that reconciles the simulation with
// the eigenvalues of the linearisation. A limit cycle is declared only when the amplitude has
// settled (contensou/gear/cycle_trend.hpp): its trend within a band scaled by the linear growth
// rate over kTrendPeriods periods; the app runs a landing that has not settled again, longer
// (extended_run), up to kLongestRun.
#pragma once

#include <string>

#include "contensou/gear/cycle_trend.hpp"
#include "contensou/gear/landing_simulation.hpp"

namespace contensou::app {

struct LimitCycle : CycleTrend {
  double run_end_s = 0.0;           // the landing's end (extended runs: longer than configured)
  double eigen_growth_per_s = 0.0;  // the linearisation's dominant oscillatory mode
  std::string verdict;              // in words, with the numbers
};

// The longest landing a limit cycle is looked for in [s] (the run is doubled up to it).
inline constexpr double kLongestRun = 16.0;

// `eigen_growth_per_s` and `frequency_hz` are the linearisation's (its dominant oscillatory
// mode; the landing's own frequency when that is 0); the amplitude threshold is the criterion's.
LimitCycle assess_limit_cycle(const LandingRun& run, const GearStructure& structure,
                              double eigen_growth_per_s, double frequency_hz,
                              const ShimmyCriterion& criterion);

// Whether a longer run could change the verdict: the amplitude has not settled and is not a
// decay already below the threshold.
bool worth_extending(const LimitCycle& c, const ShimmyCriterion& criterion);

// The scenario run to `end_s`: the end time, and with it a braked slide's brake-off and an
// explicit window end that sat at (within 0.1 s of) the configured end.
LandingScenario extended_run(const LandingScenario& s, double end_s);

}  // namespace contensou::app
