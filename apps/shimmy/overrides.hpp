// --set KEY=VALUE: one configuration value from the command line, by the JSON file's key.
#pragma once

#include <string>
#include <vector>

#include "config.hpp"

namespace contensou::app {

// Applies each "section.key=value" of `assignments` (the names of the JSON configuration:
// structure.offset_m=0.45, scenario.forward_speed_mps=58, models=["coupled"]) to `config`, in
// order, and validates the result once, as a configuration file would be. VALUE is JSON (a number,
// true/false, a list) or else a plain string. Throws std::runtime_error naming the assignment:
// an unknown key (with the closest known one), a malformed assignment or a bad value.
ShimmyConfig apply_overrides(const ShimmyConfig& config,
                             const std::vector<std::string>& assignments);

}  // namespace contensou::app
