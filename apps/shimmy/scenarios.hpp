// The demo's named scenarios: what a landing-gear engineer would try first, each a list of
// configuration overrides (the --set names) on top of the chosen gear.
#pragma once

#include <string>
#include <vector>

#include "contensou/gear/linear_stability.hpp"

namespace contensou::app {

struct NamedScenario {
  std::string name;                    // "large-offset"
  std::string description;             // one line, in words
  std::vector<std::string> overrides;  // "structure.offset_m=0.45", ...
  StabilityPhase phase;                // the phase whose eigenvalues judge it
};

// touchdown, braked-slide, large-offset (in that order).
const std::vector<NamedScenario>& named_scenarios();

// The scenario called `name`; throws std::runtime_error listing the names if there is none.
const NamedScenario& named_scenario(const std::string& name);

// "touchdown, braked-slide, large-offset".
std::string scenario_names();

}  // namespace contensou::app
