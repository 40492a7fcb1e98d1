// contensou-shimmy, last step of config -> simulate -> analyse -> report: the tables on stdout,
// the summary JSON, the CSV time histories and their pictures, written from the landings and
// their analysis (it simulates and analyses nothing itself).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "analysis.hpp"
#include "config.hpp"
#include "output_folder.hpp"
#include "simulate.hpp"

namespace contensou::app {

// One configuration: the landing table and the stability verdicts on stdout (a warning on
// stderr for a landing that did not converge), each model's CSV history and the pictures in
// `out`; returns the summary (without writing it).
nlohmann::json report_landings(const ShimmyConfig& config, const Landings& landings,
                               const LandingAnalysis& analysis, const TireInput* tire,
                               const OutputDir& out);

// The table that closes a run of scenarios, from their summaries (scenario name -> its
// "summary" and the rest, as contensou-shimmy writes them): the simulated verdict, the
// eigenvalue verdict of the scenario's phase, the energy balance of its dominant mode, the
// limit cycles and the seed's claim.
void print_scenario_table(const nlohmann::json& scenarios);

}  // namespace contensou::app
