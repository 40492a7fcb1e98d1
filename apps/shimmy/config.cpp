#include "config.hpp"

#include "config_keys.hpp"

#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include "contensou/friction/error.hpp"

namespace contensou::app {

nlohmann::json to_json(const ShimmyConfig& config) {
  ShimmyConfig c = config;  // read only (write_key reaches the fields by non-const accessors)
  nlohmann::json j;
  for (const ConfigKey& key : config_keys()) {
    nlohmann::json value = write_key(key, c);
    if (value.is_null()) continue;  // an empty list of models
    nlohmann::json* node = &j;
    std::string_view rest = key.name;
    for (std::size_t dot; (dot = rest.find('.')) != std::string_view::npos;
         rest = rest.substr(dot + 1))
      node = &(*node)[std::string(rest.substr(0, dot))];
    (*node)[std::string(rest)] = std::move(value);
  }
  return j;
}

ShimmyConfig read_shimmy_config(const std::string& path, const std::string& gear_name) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the configuration file");
  std::stringstream buf;
  buf << in.rdbuf();
  return parse_shimmy_config(buf.str(), path, gear_name);
}

nlohmann::json parse_json_without_duplicates(const std::string& text, const std::string& path) {
  // JSON allows a key twice in an object and nlohmann::json keeps the last; a configuration
  // that sets a value twice is a mistake to report, not to resolve silently.
  std::vector<std::set<std::string>> keys;
  std::vector<std::string> where, last;  // each open object's dotted name and latest key
  std::string duplicate;
  const auto dotted = [](const std::string& a, const std::string& b) {
    return a.empty() ? b : a + "." + b;
  };
  const nlohmann::json::parser_callback_t check = [&](int, nlohmann::json::parse_event_t event,
                                                      nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start) {
      keys.emplace_back();
      where.push_back(where.empty() ? std::string() : dotted(where.back(), last.back()));
      last.emplace_back();
    } else if (event == E::object_end && !keys.empty()) {
      keys.pop_back();
      where.pop_back();
      last.pop_back();
    } else if (event == E::key && !keys.empty()) {
      last.back() = parsed.get<std::string>();
      if (!keys.back().insert(last.back()).second && duplicate.empty())
        duplicate = dotted(where.back(), last.back());
    }
    return true;
  };
  nlohmann::json j = nlohmann::json::parse(text, check);
  if (!duplicate.empty()) {
    // Positions are not kept: point at the second quoted occurrence of the key's last part.
    const std::string quoted = "\"" + duplicate.substr(duplicate.rfind('.') + 1) + "\"";
    const std::size_t first = text.find(quoted);
    const std::size_t second = first == std::string::npos ? first : text.find(quoted, first + 1);
    ConfigText{path, text}.fail_at(second, "the key '" + duplicate +
                                               "' appears twice in one object (JSON keeps only "
                                               "one): remove one of them");
  }
  return j;
}

namespace {

// The text as JSON; its errors as ParseError with the line and column.
nlohmann::json parse_json_or_fail(const ConfigText& r) {
  try {
    return parse_json_without_duplicates(r.text, r.path);
  } catch (const nlohmann::json::parse_error& e) {
    const std::string what = e.what();
    const std::size_t colon = what.rfind(": ");
    r.fail_at(e.byte > 0 ? e.byte - 1 : 0,
              "invalid JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2)));
  } catch (const nlohmann::json::out_of_range& e) {
    // A number beyond the range of a double ("1e400"): no position given, locate its text.
    const std::string what = e.what(), number = what.substr(what.find('\'') + 1);
    r.fail_at(r.text.find(number.substr(0, number.find('\''))),
              "invalid JSON: " + what.substr(what.find("] ") + 2));
  }
}

// The named gear the file's values change: "gear" in the file, else `gear_name`.
void read_gear(const ConfigText& r, const nlohmann::json& j, const std::string& gear_name,
               ShimmyConfig& c) {
  c.gear_name = gear_name;
  if (j.contains("gear")) {
    if (!j["gear"].is_string()) r.fail_at_key("gear", "expected default or legacy");
    c.gear_name = j["gear"].get<std::string>();
  }
  try {
    c.gear = gear_config_by_name(c.gear_name);
  } catch (const InvalidArgument& e) {
    r.fail_at_key("gear", e.what(), false);
  }
}

// Every leaf of the JSON object `node` by its dotted name, through the key table. A key the
// table reads itself (the app's keys, names and flags) is read whatever its value; an object
// elsewhere is a section (also under a number's name, where it holds no key); a number's key
// is read as a number; anything else is unknown.
void read_section(const ConfigText& r, const std::vector<ConfigKey>& keys,
                  const nlohmann::json& node, const std::string& prefix, ShimmyConfig& c) {
  for (auto it = node.begin(); it != node.end(); ++it) {
    const std::string name = prefix.empty() ? it.key() : prefix + "." + it.key();
    const ConfigKey* key = nullptr;
    for (const ConfigKey& k : keys)
      if (k.name == name) key = &k;
    const bool gear_number = key && key->gear && key->gear->number;
    if (key && !gear_number)
      read_key(*key, r, it.value(), c);
    else if (it.value().is_object())
      read_section(r, keys, it.value(), name, c);
    else if (key)
      read_key(*key, r, it.value(), c);
    else
      r.fail_at_key(name, "unknown key (contensou-shimmy --print-config lists them all)");
  }
}

}  // namespace

ShimmyConfig parse_shimmy_config(const std::string& text, const std::string& path,
                                 const std::string& gear_name) {
  const ConfigText r{path, text};
  const nlohmann::json j = parse_json_or_fail(r);
  if (!j.is_object()) throw ParseError(path, 1, 1, "the configuration must be a JSON object");
  ShimmyConfig c;
  read_gear(r, j, gear_name, c);
  read_section(r, config_keys(), j, "", c);
  try {
    validate_keys(c);
  } catch (const InvalidArgument& e) {
    r.fail_at_key(e.parameter(), e.what(), false);
  }
  return c;
}

}  // namespace contensou::app
