// contensou-shimmy --bifurcation: the braked slide's bifurcation diagrams (contensou/gear/
// bifurcation.hpp) for every model over config.sweeps, their CSVs and pictures: amplitude and
// torque-link load against each parameter, swept up and down, with each model's linear boundary;
// for the forward speed also the growth rate, the frequencies and the time to onset.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "config.hpp"
#include "contensou/gear/bifurcation.hpp"
#include "output_folder.hpp"
#include "simulate.hpp"

namespace contensou::app {

// At most this many sweep points (points x models x 2 directions) in one run.
inline constexpr long kMostSweepPoints = 4000;
void check_sweep_work(const ShimmyConfig& config);

// The sweeps' options: the solver's tolerance and output interval, the criterion's threshold.
SweepOptions sweep_options(const ShimmyConfig& config);

std::vector<BifurcationSweep> compute_sweeps(const ShimmyConfig& config, unsigned threads,
                                             const TireInput* tire, const Progress& progress);

// Writes the sweeps' CSVs and PNGs into `out`; their summaries into summary["bifurcation"].
// `options` are those the sweeps ran with (sweep_options(config)).
void report_sweeps(const OutputDir& out, const std::vector<BifurcationSweep>& sweeps,
                   const SweepOptions& options, nlohmann::json& summary);

}  // namespace contensou::app
