#include "overrides.hpp"

#include "config_keys.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace contensou::app {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The known key closest to `key` (edit distance below half its length plus two), in the key
// table's names sorted (the order of --print-config); "" if none is that close.
std::string closest_key(const std::string& key) {
  std::vector<std::string> keys;
  for (const ConfigKey& k : config_keys()) keys.emplace_back(k.name);
  std::sort(keys.begin(), keys.end());
  std::string best;
  std::size_t best_distance = key.size() / 2 + 2;
  for (const std::string& k : keys)
    if (const std::size_t d = edit_distance(k, key); d < best_distance) {
      best = k;
      best_distance = d;
    }
  return best;
}

// The value at the dotted path, which must exist and not be a section.
nlohmann::json& leaf_at(nlohmann::json& root, const std::string& key, const std::string& what) {
  nlohmann::json* node = &root;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? dot : dot - start);
    if (!node->is_object() || !node->contains(part)) {
      const std::string close = closest_key(key);
      throw std::runtime_error(what + ": unknown key '" + key + "'" +
                               (close.empty() ? "" : " (did you mean '" + close + "'?)") +
                               "; --print-config lists every key");
    }
    node = &(*node)[part];
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  if (node->is_object())
    throw std::runtime_error(what + ": '" + key + "' is a section; set one of its keys");
  return *node;
}

// The message of a configuration error without the "file:line:column: " of the JSON text.
std::string without_location(const std::string& message, const std::string& path) {
  if (message.rfind(path, 0) != 0) return message;
  const std::size_t space = message.find(": ");
  return space == std::string::npos ? message : message.substr(space + 2);
}

}  // namespace

ShimmyConfig apply_overrides(const ShimmyConfig& config,
                             const std::vector<std::string>& assignments) {
  if (assignments.empty()) return config;
  nlohmann::json j = to_json(config);
  for (const std::string& a : assignments) {
    const std::string what = "--set " + a;
    const std::size_t eq = a.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == a.size())
      throw std::runtime_error(what + ": expected KEY=VALUE, e.g. structure.offset_m=0.45");
    const std::string key = a.substr(0, eq), text = a.substr(eq + 1);
    if (key == "gear")
      throw std::runtime_error(what + ": the gear is chosen with --gear (it sets every value)");
    nlohmann::json& leaf = leaf_at(j, key, what);
    nlohmann::json value = nlohmann::json::parse(text, nullptr, false);
    leaf = value.is_discarded() ? nlohmann::json(text) : value;
  }
  // Validated together: keys that depend on each other (both carcass stiffnesses) may be set
  // one by one. The errors name the key.
  const std::string path = "--set";
  try {
    return parse_shimmy_config(j.dump(), path, config.gear_name);
  } catch (const std::exception& e) {
    std::string all;
    for (const std::string& a : assignments) all += (all.empty() ? "" : " ") + a;
    throw std::runtime_error("--set " + all + ": " + without_location(e.what(), path));
  }
}

}  // namespace contensou::app
