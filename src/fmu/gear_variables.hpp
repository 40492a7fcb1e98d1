// The gear FMU's variables, generated from the shimmy demo's tables rather than typed here: the
// parameters are the configuration keys of apps/shimmy/config_keys.hpp (names, types, units,
// help, start values of the default gear), the outputs the columns of a landing's time history
// (apps/shimmy/history.hpp) and the torque-link load. The exporter writes modelDescription.xml
// from this list and the FMU binary serves the same list, so the two agree by construction; the
// guid is a hash of the list, which instantiation checks.
#pragma once

#include <string>
#include <vector>

#include "fmu_model.hpp"

namespace contensou::fmu {

struct GearVariable {
  Variable variable;  // reference, name (points into `name`), causality, type
  std::string name, unit, description;
  std::string start;        // the start value as text ("" for outputs)
  std::string key;          // a parameter's configuration key (dotted); "" otherwise
  int history_column = -1;  // an output's column of history_row(); -1: the torque-link load
};

// Value references: the two inputs, then the outputs, then the parameters.
inline constexpr unsigned kGearForwardSpeed = 0, kGearBrakeTorque = 1, kGearFirstOutput = 2;

// The configuration keys the inputs replace or the FMU has no use for (the analysis window, the
// shimmy criterion, the recorded history, maps): not parameters of the FMU.
bool gear_key_excluded(const std::string& key);

// Every variable, in value-reference order (built once, thread-safe).
const std::vector<GearVariable>& gear_variables();
const std::vector<Variable>& gear_variable_table();  // their Variable parts, for the glue

// "{8-4-4-4-12}" from a hash of the variables' names, types, causalities and units.
std::string gear_guid();

}  // namespace contensou::fmu
