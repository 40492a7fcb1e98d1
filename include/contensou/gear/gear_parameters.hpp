/// \file
/// The gear's configuration keys, one table: every field of GearConfig by its dotted name
/// ("structure.offset_m"), with its type, SI unit, valid range and a line of help. validate(),
/// gear_parameter() and gear_parameter_names() read it, and so does the shimmy app's configuration
/// (parsing, --print-config, --set, --print-keys and docs/shimmy.md's key table, Python's
/// LandingConfig).
#pragma once

#include <span>
#include <string>
#include <string_view>

namespace contensou {

struct GearConfig;

/// The type of a key's value.
enum class ParameterType : unsigned char {
  number,  ///< a double
  flag,    ///< true or false
  choice   ///< one of a few names (`choices`)
};

/// The values a number may take; a value outside throws InvalidArgument naming the key.
struct ParameterRange {
  /// How the value is checked.
  enum Kind : unsigned char {
    /// Any value (a relation with another key may check it, GearParameter::relation).
    unchecked,
    finite,    ///< require_finite: "must be finite"
    positive,  ///< require_positive: > 0, finite and a normal double
    /// lo <= v (lo < v when lo_open) and v < hi, else `rule` (`rule_above` at or above hi, when
    /// given); `finite_first`: "must be finite" for inf and NaN first.
    interval
  };
  Kind kind = finite;  ///< the check; finite unless set
  /// An interval's lower end, in the key's unit.
  double lo = 0.0, hi = 0.0;  ///< an interval's upper end (always open), in the key's unit
  bool lo_open = false;       ///< an interval open at lo (lo < v)
  bool finite_first = false;  ///< an interval checks finiteness before its ends
  /// An interval's message for a value below lo (and at or above hi without rule_above).
  std::string_view rule = {}, rule_above = {};  ///< its message at or above hi, if not empty
};

/// When a range is checked: always, or only while a switch of the gear is on.
enum class ParameterSwitch : unsigned char {
  always,   ///< every configuration
  braking,  ///< scenario.braking
  carcass   ///< either carcass stiffness > 0 (GearStructure::carcass_compliance)
};

/// One key of the table: its name, type, unit, valid values, help and the field it names.
struct GearParameter {
  std::string_view name = {};                      ///< dotted, the JSON configuration's nesting
  ParameterType type = ParameterType::number;      ///< number, flag or choice
  std::string_view unit = {};                      ///< SI; "1" for a pure number, empty otherwise
  ParameterRange range = {};                       ///< numbers only
  ParameterSwitch when = ParameterSwitch::always;  ///< when range and relation are checked
  /// A rule that reads another key (scenario.sliding_slip > scenario.rolling_slip): throws
  /// InvalidArgument naming the key it is about; nullptr if none. `relation_text` says it in words.
  void (*relation)(const GearConfig&) = nullptr;
  std::string_view relation_text = {};  ///< the relation in words; empty if none
  std::string_view choices = {};        ///< a choice's names, separated by '|'
  std::string_view help = {};           ///< one line: the symbol and what the key means
  /// The field of a number key (nullptr for the other types); the next two likewise.
  double& (*number)(GearConfig&) = nullptr;
  bool& (*flag)(GearConfig&) = nullptr;         ///< the field of a flag key
  std::string& (*text)(GearConfig&) = nullptr;  ///< the field of a choice key
};

/// Every key of GearConfig, section by section (structure, tire, rolling, scenario), in the order
/// validate() checks them.
std::span<const GearParameter> gear_parameters();

/// The entry of a dotted name; nullptr if unknown.
const GearParameter* find_gear_parameter(std::string_view name);

/// Throws InvalidArgument naming the key if config's value of `p` is outside its range, is not
/// one of its choices or breaks its relation (nothing while its switch is off).
void check_gear_parameter(const GearParameter& p, const GearConfig& config);

/// The valid values in words, for the help and the docs: "> 0", "[0, 1)", "finite", "fitted,
/// asymptotic or seed", "any", with the relation and the switch ("... while scenario.braking",
/// "... with carcass compliance"); without the unit.
std::string describe_range(const GearParameter& p);

}  // namespace contensou
