// The stability boundaries of several contact models in one figure: for each pair of map axes
// and phase that the models share, every model's boundary and its unstable region labelled by
// the source that feeds the mode there.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/stability_map.hpp"

namespace contensou::app {

// What feeds the dominant mode of `model` in `phase` (energy per cycle, linear_stability.hpp):
// "offset drag", "spin torque" ("aligning torque" for the string tire), "lateral forces",
// "fore-aft (gear walk)" or "" if nothing does.
std::string feeding_source(const GearModel& model, StabilityPhase phase);

// For each group of eigenvalue maps in `maps` with the same axes and phase and at least two
// models, writes overlay_<x>_<y>_<phase>.png (and .gp) in `dir`, reading the maps' boundary
// CSVs (base names in `bases`, parallel to `maps`); `model_of(contact)` gives the model whose
// parameters the maps varied. Returns a summary per overlay.
nlohmann::json write_boundary_overlays(const std::string& dir,
                                       const std::vector<StabilityMap>& maps,
                                       const std::vector<std::string>& bases,
                                       const std::function<GearModel(ContactModel)>& model_of);

}  // namespace contensou::app
