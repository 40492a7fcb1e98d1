// The shimmy demo's configuration keys, one table: the gear's (contensou/gear/gear_parameters.hpp:
// type, SI unit, range, help) and the app's own (solver, shimmy criterion, models, maps, gear).
// It serves reading and validating a configuration (config.cpp), --print-config (to_json),
// --set (overrides.cpp: the keys and the closest one), --print-keys and docs/shimmy.md's key
// table, and Python's LandingConfig.keys().
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/gear/gear_parameters.hpp"

namespace contensou::app {

struct ShimmyConfig;

// A configuration's text and where it came from, to name the file, line and column of a key in
// errors (nlohmann::json keeps no positions: the key's first quoted occurrence).
struct ConfigText {
  std::string path, text;
  [[noreturn]] void fail_at_key(const std::string& key, const std::string& message,
                                bool name_key = true) const;
  // ParseError at byte offset `pos` of the text (npos: its start).
  [[noreturn]] void fail_at(std::size_t pos, const std::string& message) const;
  double number(const nlohmann::json& j, const std::string& key) const;
};

struct ConfigKey {
  std::string_view name = {};  // dotted, the JSON file's nesting
  std::string_view type = {};  // "number", "true or false", "name", "list of names", "list of maps"
  std::string_view unit = {};  // SI ("1" for a pure number); empty for names and lists
  std::string_view help = {};
  const GearParameter* gear = nullptr;  // a key of GearConfig: its field, range and relation
  // The app's own keys: the valid values (numbers: `range`, checked after the gear's) and how
  // the key is read from and written to JSON.
  ParameterRange range = {};
  std::string_view values = {};  // names and lists: the valid values in words
  double& (*number)(ShimmyConfig&) = nullptr;
  void (*read)(const ConfigText&, const std::string& key, const nlohmann::json&,
               ShimmyConfig&) = nullptr;
  nlohmann::json (*write)(const ShimmyConfig&) = nullptr;
};

// Every key: the gear's in the order of its structs, then the app's.
std::vector<ConfigKey> config_keys();

// Sets config's value of `key` from JSON (errors name the key, through `source`).
void read_key(const ConfigKey& key, const ConfigText& source, const nlohmann::json& value,
              ShimmyConfig& config);

// config's value of `key` as JSON (null for an empty list, which is left out). Reads config only
// (the fields are reached through the same non-const accessors as read_key's).
nlohmann::json write_key(const ConfigKey& key, ShimmyConfig& config);

// The gear's validate() and the app's numbers' ranges; throws InvalidArgument naming the key.
void validate_keys(const ShimmyConfig& config);

// The valid values in words ("> 0", "[0, 1) rad", "adams or bdf", ...).
std::string valid_values(const ConfigKey& key);

// The key table of docs/shimmy.md (Markdown; contensou-shimmy --print-keys): key, type, unit,
// valid values, default, meaning.
std::string config_keys_markdown();

}  // namespace contensou::app
