// contensou-shimmy, third step of config -> simulate -> analyse -> report: what the landings
// mean. Per model the convergence check against the tighter run, the stability of both phases
// (eigenvalues of the linearisation, the growth after the standard kick) with a verdict in
// words, and the oscillation at the end of the analysis window against them; with --tire the
// Monte Carlo over the report's covariance. Nothing here prints or writes files.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contensou/gear/linear_stability.hpp"
#include "limit_cycle.hpp"
#include "simulate.hpp"

namespace contensou::app {

// The landing against the same landing at a 100 times tighter tolerance.
struct Convergence {
  double tight_relative_tolerance = 0.0;
  bool measurable = false;                    // both runs oscillate above the noise floor
  double growth_rate_change_per_s = 0.0;      // 0 unless measurable
  double peak_torsion_relative_change = 0.0;  // |peak - tight peak| / tight peak
  bool converged = false;
};

// One phase's stability (docs/shimmy.md, "Stability criterion") and its verdict in words.
struct PhaseStability {
  StabilityReport report;
  std::string verdict;
};

struct ModelAnalysis {
  Convergence convergence;
  PhaseStability touchdown, braked_slide;
  // The oscillation at the end of the window against the eigenvalues of the phase the run is
  // in (braked_slide when braking, else touchdown).
  const char* limit_cycle_phase = "touchdown";
  LimitCycle limit_cycle;
};

// The Monte Carlo over the tire report's covariance (coupled model): the draws' standard
// deviations and the growth band of both phases.
struct TireAnalysis {
  double sd_a = 0.0, sd_m = 0.0, sd_kx = 0.0, sd_spin_ratio = 0.0;
  GrowthBand touchdown, braked_slide;
};

struct LandingAnalysis {
  std::vector<ModelAnalysis> models;  // parallel to the landings' runs
  std::optional<TireAnalysis> tire;
};

LandingAnalysis analyse_landings(const ShimmyConfig& config, const Landings& landings,
                                 const TireInput* tire, unsigned threads, const Progress& progress);

}  // namespace contensou::app
