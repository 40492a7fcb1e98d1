// The shimmy demo's configuration: a JSON file whose keys mirror GearConfig (docs/shimmy.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/stability_map.hpp"
#include "history.hpp"

namespace contensou::app {

// One map: two axes; every model gets its own map. "eigenvalues" maps (the default) colour the
// largest real part of an oscillatory eigenvalue at the phase's quasi-steady state
// (linear_stability_map); "simulation" maps simulate a landing per cell (stability_map).
struct MapSpec {
  MapAxis x, y;
  std::string method = "eigenvalues";  // or "simulation"
  StabilityPhase phase = StabilityPhase::braked_slide;
};

struct ShimmyConfig {
  std::string gear_name = "default";  // the named gear the file's values start from
  GearConfig gear;
  std::vector<ContactModel> models{ContactModel::coupled, ContactModel::decoupled,
                                   ContactModel::von_schlippe};
  SolverOptions solver;
  ShimmyCriterion criterion;
  std::vector<MapSpec> maps{
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"structure.torsional_damping_nms_per_rad", 0.0, 400.0, 50},
       "eigenvalues",
       StabilityPhase::touchdown},
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"scenario.brake_target_slip", 0.03, 0.3, 50}},
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"tire.friction.kinetic_coefficient", 0.2, 0.8, 50}},
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50}, {"structure.offset_m", 0.0, 0.5, 50}},
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"structure.offset_m", 0.0, 0.5, 50},
       "eigenvalues",
       StabilityPhase::touchdown},
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"structure.torsional_damping_nms_per_rad", 0.0, 400.0, 50}},
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"scenario.static_load_n", 20.0e3, 140.0e3, 50}}};
  // Bifurcation sweeps of the braked slide (--bifurcation): one parameter each, every model,
  // swept up and down (contensou/gear/bifurcation.hpp).
  std::vector<MapAxis> sweeps{{"scenario.forward_speed_mps", 30.0, 90.0, 21},
                              {"structure.offset_m", 0.2, 0.6, 21},
                              {"structure.torsional_damping_nms_per_rad", 0.0, 400.0, 21}};
};

// The default configuration as JSON (every key, with its value).
nlohmann::json to_json(const ShimmyConfig& config);

// Reads a configuration; keys left out keep the values of the named gear (key "gear": default or
// legacy; otherwise `gear_name`). Errors name the file, line and column (for syntax errors and
// unknown keys) and the bad value.
ShimmyConfig read_shimmy_config(const std::string& path, const std::string& gear_name = "default");

// The same from text in memory; `path` stands for the file in error messages (the Python
// package reads its configuration objects through this).
// nlohmann::json::parse that refuses a key given twice in one object (ParseError naming the
// dotted key, at its second occurrence); other errors as nlohmann::json throws them.
nlohmann::json parse_json_without_duplicates(const std::string& text, const std::string& path);

ShimmyConfig parse_shimmy_config(const std::string& text, const std::string& path,
                                 const std::string& gear_name = "default");

}  // namespace contensou::app
