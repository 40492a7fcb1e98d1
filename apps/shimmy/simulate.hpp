// contensou-shimmy, second step of config -> simulate -> analyse -> report: every contact
// model's landing, the same landing at a tighter tolerance for the convergence check, and the
// maps' cells. Nothing here prints or writes files.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "config.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/stability_map.hpp"
#include "contensou/gear/tire_uncertainty.hpp"

namespace contensou::app {

// The tire from a contensou-identify report (--tire), if any: its mean law and the draws.
struct TireInput {
  std::string path;
  std::string model = "final";  // the report's model the law comes from ("final" or "base")
  std::string note;             // what of the report the gear's tire cannot carry (tire_report.hpp)
  TireLawDistribution distribution;
  TireLawCoefficients mean;
  TireLawDraws draws;
};

// Reads --tire's report and draws `draws` laws from its covariance with `seed`.
TireInput read_tire_input(const std::string& path, int draws, unsigned seed);

// The gear model of a contact model, with the report's mean tire law when given.
GearModel gear_model(const ShimmyConfig& config, ContactModel cm, const TireInput* tire);

// A progress report: the label of the task, cells or draws done and in all (stderr on a
// terminal; the steps take it so that they need not know where it goes).
using Progress = std::function<void(const std::string& label, int done, int total)>;

// The demo analyses a landing: the gear must be fully loaded before the run ends (the library
// also simulates a gear that never lands, as free vibration; the demo would call it "stable").
void require_landing(const LandingScenario& s);

// Every contact model's landing (config.models, in order) as configured (recorded: its samples
// are the CSV history), and the same landings at a 100 times tighter relative tolerance (not
// recorded).
struct Landings {
  std::vector<LandingRun> runs;
  std::vector<LandingRun> tight;
  double tight_relative_tolerance = 0.0;
};

Landings simulate_landings(const ShimmyConfig& config, const TireInput* tire);

// One map of the configuration for one model: eigenvalues (linear_stability_map) or simulated
// landings (stability_map) per cell, and with --tire, for the coupled model's eigenvalue maps,
// the probability of shimmy over the draws per cell.
struct ComputedMap {
  StabilityMap map;
  std::optional<StabilityMap> probability;
  // The configuration's values of the two parameters: the operating point the pictures mark.
  double operating_x = 0.0, operating_y = 0.0;
};

// The work bounds of one run's maps, checked before any map starts: at most kMostEigenCells
// eigenvalue cells, kMostLandingCells simulated landings and kMostDrawCells probability-map
// linearisations (cells x draws) over every map and model; throws InvalidArgument naming the
// option and what the maps would take.
inline constexpr long kMostEigenCells = 500000;
inline constexpr long kMostLandingCells = 20000;
inline constexpr long kMostDrawCells = 2000000;
void check_map_work(const ShimmyConfig& config, int map_size, const TireInput* tire);

// Every map of config.maps for every model, in that order; `map_size` > 0 sets the points per
// axis.
std::vector<ComputedMap> compute_maps(const ShimmyConfig& config, int map_size, unsigned threads,
                                      const TireInput* tire, const Progress& progress);

}  // namespace contensou::app
