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
#include "output_folder.hpp"
#include "simulate.hpp"

namespace contensou::app {

// What feeds the dominant mode of `model` in `phase` (energy per cycle, linear_stability.hpp):
// "offset drag", "spin torque" ("aligning torque" for the string tire), "lateral forces",
// "fore-aft (gear walk)" or "" if nothing does.
std::string feeding_source(const GearModel& model, StabilityPhase phase);

// One overlay: the eigenvalue maps of several models with the same axes and phase. For each,
// its unstable cells, the unstable cell nearest the region's centre (nullptr if none) and what
// feeds the mode there; and the cell nearest the centre of the region stable in every model.
struct OverlayLobe {
  const MapCell* cell = nullptr;  // the lobe's cell nearest its centroid (map_geometry.hpp)
  std::string source;             // feeding_source there ("" if none)
};
struct OverlayModel {
  int map = 0;  // index into the maps
  long unstable = 0;
  const MapCell* label_cell = nullptr;  // the largest lobe's centre (nullptr if none)
  std::string source;                   // feeding_source at label_cell ("" if none)
  std::vector<OverlayLobe> lobes;       // every unstable lobe, largest first
};
struct Overlay {
  std::vector<OverlayModel> models;
  const MapCell* stable_cell = nullptr;
};

// Groups the eigenvalue maps in `maps` by axes and phase (groups of at least two models) and
// analyses each group; `model_of(contact)` gives the model whose parameters the maps varied.
// The overlays point into `maps`.
std::vector<Overlay> analyse_overlays(const std::vector<ComputedMap>& maps,
                                      const std::function<GearModel(ContactModel)>& model_of);

// Writes overlay_<x>_<y>_<phase>.png (and .gp) in `dir` for each overlay, reading the maps'
// boundary CSVs (base names in `bases`, parallel to `maps`). Returns a summary per overlay.
nlohmann::json write_boundary_overlays(const OutputDir& dir, const std::vector<ComputedMap>& maps,
                                       const std::vector<std::string>& bases,
                                       const std::vector<Overlay>& overlays);

}  // namespace contensou::app
