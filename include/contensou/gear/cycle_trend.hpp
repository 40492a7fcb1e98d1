/// \file
/// Whether a torsional oscillation has settled on a limit cycle, from its samples: the half swing
/// of psi over each of the last kTrendPeriods periods, the least-squares trend of its logarithm,
/// and the band a settled amplitude's trend lies in, scaled by the linear growth rate
/// (docs/shimmy.md, "Limit cycles").
#pragma once

#include <vector>

#include "contensou/gear/landing_gear.hpp"

namespace contensou {

/// The number of periods, counted back from the window's end, that cycle_trend() measures.
inline constexpr int kTrendPeriods = 8;

/// The most a settled amplitude may change between the window's middle and its end (5 %): a trend
/// within the band over the last kTrendPeriods periods is not enough where a slow drift, too slow
/// for those periods to show, still moves the amplitude over the window.
inline constexpr double kSettledChange = 0.05;

/// How the oscillation ends its window.
enum class CycleState {
  not_measured,   ///< fewer than kTrendPeriods periods in the window (or no period or samples)
  limit_cycle,    ///< settled above the amplitude threshold
  settled_small,  ///< settled at or below the threshold (e.g. inside a freeplay, or decayed away)
  growing,        ///< trend above the band, or within it with the amplitude up > kSettledChange
  decaying        ///< trend below the band, or within it with the amplitude down > kSettledChange
};
/// "not_measured", "limit_cycle", "settled_below_threshold", "still_growing" or "decaying".
const char* to_string(CycleState s);

/// The band of a settled trend [1/s]: a tenth of the linear growth rate's size, and at least
/// 0.03 1/s (3 % per second).
double settling_band(double eigen_growth_per_s);

/// What cycle_trend() measured; the numbers stay 0 while not `measured`.
struct CycleTrend {
  CycleState state = CycleState::not_measured;  ///< the verdict
  bool measured = false;               ///< the window held kTrendPeriods periods and was measured
  double amplitude_rad = 0.0;          ///< half the psi swing over the last period [rad]
  double earlier_amplitude_rad = 0.0;  ///< the same over the first of the kTrendPeriods [rad]
  double trend_per_s = 0.0;  ///< d ln(half swing)/dt, least squares over the periods [1/s]
  double band_per_s = 0.0;   ///< settling_band(): settled when abs(trend) is within it [1/s]
  /// Half the psi swing over the window's first period [rad].
  double start_amplitude_rad = 0.0;
  /// Half the psi swing over the period that ends at the window's middle [rad].
  double midway_amplitude_rad = 0.0;
  double midway_s = 0.0;  ///< the window's middle [s]
  /// The trend is within the band but the amplitude moved more than kSettledChange since
  /// midway_s: a slow drift, so growing or decaying rather than settled.
  bool drifting = false;
  /// Half the swing of k_psi psi + c_psi psi' over the last period [N m].
  double torque_link_nm = 0.0;
};

/// The oscillation's period and the window its samples are read over.
struct CycleWindow {
  double period_s = 0.0;  ///< the oscillation's period [s]; 0 or less: not measured
  /// The window's start [s]: the kTrendPeriods periods before end_s must all lie after it.
  double start_s = 0.0, end_s = 0.0;  ///< the window's end [s], the periods counted back from it
};

/// From samples (t ascending [s], psi [rad], psi' [rad/s]) over the window; the torque-link load
/// uses the structure's k_psi and c_psi, the band eigen_growth_per_s [1/s], and `threshold_rad`
/// tells a limit cycle from a settled small motion. Settled (limit_cycle or settled_small) means
/// both: the trend within the band and the last period's half swing within kSettledChange of the
/// half swing over the period ending at the window's middle.
CycleTrend cycle_trend(const std::vector<double>& t, const std::vector<double>& psi,
                       const std::vector<double>& psi_rate, const GearStructure& structure,
                       const CycleWindow& window, double eigen_growth_per_s, double threshold_rad);

}  // namespace contensou
