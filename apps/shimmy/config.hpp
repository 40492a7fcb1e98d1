// The shimmy demo's configuration: a JSON file whose keys mirror GearConfig (docs/shimmy.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/stability_map.hpp"

namespace contensou::app {

struct ShimmyConfig {
  GearConfig gear;
  std::vector<ContactModel> models{ContactModel::coupled, ContactModel::decoupled,
                                   ContactModel::nonholonomic};
  SolverOptions solver;
  ShimmyCriterion criterion;
  // Each map: two axes; every model gets its own map.
  std::vector<std::pair<MapAxis, MapAxis>> maps{
      {{"scenario.forward_speed_mps", 30.0, 90.0, 50},
       {"structure.torsional_damping_nms_per_rad", 0.0, 400.0, 50}},
      {{"structure.offset_m", 0.0, 0.4, 50},
       {"structure.torsional_damping_nms_per_rad", 0.0, 400.0, 50}}};
};

// The default configuration as JSON (every key, with its value).
nlohmann::json to_json(const ShimmyConfig& config);

// Reads a configuration; keys left out keep their defaults. Errors name the file, line and
// column (for syntax errors and unknown keys) and the bad value.
ShimmyConfig read_shimmy_config(const std::string& path);

// The same from text in memory; `path` stands for the file in error messages (the Python
// package reads its configuration objects through this).
ShimmyConfig parse_shimmy_config(const std::string& text, const std::string& path);

}  // namespace contensou::app
