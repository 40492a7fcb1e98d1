// Whether a torsional oscillation has settled on a limit cycle, from its samples: the half swing
// of psi over each of the last kTrendPeriods periods, the least-squares trend of its logarithm,
// and the band a settled amplitude's trend lies in, scaled by the linear growth rate
// (docs/shimmy.md, "Limit cycles").
#pragma once

#include <vector>

#include "contensou/gear/landing_gear.hpp"

namespace contensou {

inline constexpr int kTrendPeriods = 8;

// How the oscillation ends its window.
enum class CycleState {
  not_measured,   // fewer than kTrendPeriods periods in the window
  limit_cycle,    // settled above the amplitude threshold
  settled_small,  // settled below the threshold (e.g. inside a freeplay, or decayed away)
  growing,        // trend above the band
  decaying        // trend below the band
};
const char* to_string(CycleState s);

// A tenth of the linear growth rate's size, and at least 0.03 1/s (3 % per second).
double settling_band(double eigen_growth_per_s);

struct CycleTrend {
  CycleState state = CycleState::not_measured;
  bool measured = false;
  double amplitude_rad = 0.0;          // half the psi swing over the last period
  double earlier_amplitude_rad = 0.0;  // over the first of the kTrendPeriods periods
  double trend_per_s = 0.0;            // d ln(half swing)/dt, least squares over the periods
  double band_per_s = 0.0;             // settled: |trend| <= band
  double torque_link_nm = 0.0;  // half the swing of k_psi psi + c_psi psi' over the last period
};

// The oscillation's period and the window its samples are read over.
struct CycleWindow {
  double period_s = 0.0;
  double start_s = 0.0, end_s = 0.0;
};

// From samples (t ascending, psi, psi') over the window; `threshold_rad` tells a limit cycle
// from a settled small motion.
CycleTrend cycle_trend(const std::vector<double>& t, const std::vector<double>& psi,
                       const std::vector<double>& psi_rate, const GearStructure& structure,
                       const CycleWindow& window, double eigen_growth_per_s, double threshold_rad);

}  // namespace contensou
