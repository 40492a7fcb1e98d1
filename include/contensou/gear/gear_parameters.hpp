// The gear's configuration keys, one table: every field of GearConfig by its dotted name
// ("structure.offset_m"), with its type, SI unit, valid range and a line of help. validate(),
// gear_parameter() and gear_parameter_names() read it, and so does the shimmy app's configuration
// (parsing, --print-config, --set, --print-keys and docs/shimmy.md's key table, Python's
// LandingConfig).
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace contensou {

struct GearConfig;

enum class ParameterType : unsigned char {
  number,  // a double
  flag,    // true or false
  choice   // one of a few names (`choices`)
};

// The values a number may take; a value outside throws InvalidArgument naming the key.
struct ParameterRange {
  enum Kind : unsigned char {
    unchecked,  // any value (a relation with another key may check it, GearParameter::relation)
    finite,     // require_finite: "must be finite"
    positive,   // require_positive: > 0, finite and a normal double
    interval    // lo <= v (lo < v when lo_open) and v < hi, else `rule` (`rule_above` at or
                // above hi, when given); `finite_first`: "must be finite" for inf and NaN first
  };
  Kind kind = finite;
  double lo = 0.0, hi = 0.0;
  bool lo_open = false;
  bool finite_first = false;
  std::string_view rule = {}, rule_above = {};
};

// When a range is checked: always, or only while a switch of the gear is on.
enum class ParameterSwitch : unsigned char {
  always,
  braking,  // scenario.braking
  carcass   // either carcass stiffness > 0 (GearStructure::carcass_compliance)
};

struct GearParameter {
  std::string_view name = {};  // dotted, the JSON configuration's nesting
  ParameterType type = ParameterType::number;
  std::string_view unit = {};  // SI; "1" for a pure number
  ParameterRange range = {};   // numbers
  ParameterSwitch when = ParameterSwitch::always;
  // A rule that reads another key (scenario.sliding_slip > scenario.rolling_slip): throws
  // InvalidArgument naming this key; nullptr if none. `relation_text` says it in words.
  void (*relation)(const GearConfig&) = nullptr;
  std::string_view relation_text = {};
  std::string_view choices = {};  // a choice's names, separated by '|'
  std::string_view help = {};
  // The field, by type (the other two are nullptr).
  double& (*number)(GearConfig&) = nullptr;
  bool& (*flag)(GearConfig&) = nullptr;
  std::string& (*text)(GearConfig&) = nullptr;
};

// Every key of GearConfig, section by section (structure, tire, rolling, scenario), in the order
// validate() checks them.
std::span<const GearParameter> gear_parameters();

// The entry of a dotted name; nullptr if unknown.
const GearParameter* find_gear_parameter(std::string_view name);

// Throws InvalidArgument naming the key if config's value of `p` is outside its range or breaks
// its relation (nothing while its switch is off).
void check_gear_parameter(const GearParameter& p, const GearConfig& config);

// The valid values in words, for the help and the docs: "> 0", "[0, 1) rad", "finite", "fitted,
// asymptotic or seed", with the relation and the switch ("... while scenario.braking").
std::string describe_range(const GearParameter& p);

}  // namespace contensou
