// contensou-shimmy --map, the report of the maps: each map's CSV (a row per cell), its boundary
// CSV and PNG, the probability maps of --tire, and the overlays of the models' boundaries,
// written from the computed maps (simulate.hpp) and the overlays' analysis
// (boundary_overlay.hpp).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "boundary_overlay.hpp"
#include "output_folder.hpp"
#include "simulate.hpp"

namespace contensou::app {

// Writes every map (and probability map) into `out` and their summaries into summary["maps"]
// and summary["probability_maps"], then the overlays into summary["overlays"].
void report_maps(const OutputDir& out, const std::vector<ComputedMap>& maps,
                 const std::vector<Overlay>& overlays, nlohmann::json& summary);

}  // namespace contensou::app
