#include "config_keys.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include "config.hpp"
#include "contensou/friction/error.hpp"

namespace contensou::app {

namespace {

// Line and column (1-based) of byte offset `pos` in `text`.
std::pair<int, int> line_column(const std::string& text, std::size_t pos) {
  int line = 1, col = 1;
  for (std::size_t i = 0; i < std::min(pos, text.size()); ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else {
      ++col;
    }
  }
  return {line, col};
}

// "gear": read before every other key (it picks the values the others change), by
// parse_shimmy_config.
void read_gear_name(const ConfigText&, const std::string&, const nlohmann::json&, ShimmyConfig&) {}
nlohmann::json write_gear_name(const ShimmyConfig& c) {
  return c.gear_name;
}

void read_models(const ConfigText& r, const std::string& key, const nlohmann::json& v,
                 ShimmyConfig& c) {
  if (!v.is_array() || v.empty()) r.fail_at_key(key, "expected a non-empty array");
  c.models.clear();
  for (const auto& m : v) {
    if (!m.is_string()) r.fail_at_key(key, "expected model names, got " + m.dump());
    ContactModel model = ContactModel::coupled;
    try {
      model = contact_model_from_string(m.get<std::string>());
    } catch (const InvalidArgument& e) {
      r.fail_at_key(key, e.what());
    }
    // Each model once: a list repeating one would run (and write) the same landing again.
    if (std::find(c.models.begin(), c.models.end(), model) != c.models.end())
      r.fail_at_key(key, std::string("the model ") + to_string(model) +
                             " is listed twice (each model runs once: at most coupled, "
                             "decoupled and von_schlippe)");
    c.models.push_back(model);
  }
}
nlohmann::json write_models(const ShimmyConfig& c) {
  nlohmann::json j;
  for (ContactModel m : c.models) j.push_back(to_string(m));
  return j;
}

// A map's "method" and "phase" (its "x" and "y" are read_axis's).
void read_map_options(const ConfigText& r, const std::string& key, const nlohmann::json& m,
                      MapSpec& spec) {
  for (auto f = m.begin(); f != m.end(); ++f) {
    const std::string fk = key + "." + f.key();
    if (f.key() == "method") {
      if (!f.value().is_string() || (f.value() != "eigenvalues" && f.value() != "simulation"))
        r.fail_at_key(fk, "expected eigenvalues or simulation, got " + f.value().dump());
      spec.method = f.value().get<std::string>();
    } else if (f.key() == "phase") {
      if (!f.value().is_string() || (f.value() != "touchdown" && f.value() != "braked_slide"))
        r.fail_at_key(fk, "expected touchdown or braked_slide, got " + f.value().dump());
      spec.phase =
          f.value() == "touchdown" ? StabilityPhase::touchdown : StabilityPhase::braked_slide;
    } else if (f.key() != "x" && f.key() != "y") {
      r.fail_at_key(fk, "unknown key (x, y, method, phase)");
    }
  }
}

// A map's axis `name` ("x" or "y"): a gear parameter, from, to, points.
void read_axis(const ConfigText& r, const std::string& key, const char* name,
               const nlohmann::json& m, MapAxis& axis) {
  if (!m.is_object() || !m.contains(name) || !m[name].is_object())
    r.fail_at_key(key, std::string("each map needs an object '") + name + "'");
  const nlohmann::json& a = m[name];
  for (auto f = a.begin(); f != a.end(); ++f) {
    const std::string fk = key + "." + name + "." + f.key();
    if (f.key() == "parameter") {
      if (!f.value().is_string()) r.fail_at_key(fk, "expected a parameter name");
      axis.parameter = f.value().get<std::string>();
      GearConfig probe;
      if (!gear_parameter(probe, axis.parameter))
        r.fail_at_key(fk, "unknown parameter '" + axis.parameter + "'");
    } else if (f.key() == "from") {
      axis.from = r.number(f.value(), fk);
    } else if (f.key() == "to") {
      axis.to = r.number(f.value(), fk);
    } else if (f.key() == "points") {
      if (!f.value().is_number_integer() || f.value().get<int>() < 1)
        r.fail_at_key(fk, "expected a positive integer, got " + f.value().dump());
      axis.points = f.value().get<int>();
    } else {
      r.fail_at_key(fk, "unknown key (parameter, from, to, points)");
    }
  }
  if (axis.parameter.empty()) r.fail_at_key(key + "." + name, "each axis needs a 'parameter'");
  for (const char* end : {"from", "to"})
    if (!a.contains(end))
      r.fail_at_key(key + "." + name, std::string("each axis needs '") + end + "' (its " +
                                          (end[0] == 'f' ? "first" : "last") +
                                          " value, in the key's unit)");
}

void read_maps(const ConfigText& r, const std::string& key, const nlohmann::json& v,
               ShimmyConfig& c) {
  if (!v.is_array()) r.fail_at_key(key, "expected an array of {x, y}");
  c.maps.clear();
  for (const auto& m : v) {
    MapSpec spec;
    if (m.is_object()) read_map_options(r, key, m, spec);
    read_axis(r, key, "x", m, spec.x);
    read_axis(r, key, "y", m, spec.y);
    c.maps.push_back(spec);
  }
}
nlohmann::json write_maps(const ShimmyConfig& c) {
  nlohmann::json maps = nlohmann::json::array();  // an empty list stays empty (not the defaults)
  for (const MapSpec& spec : c.maps) {
    nlohmann::json m;
    for (const auto& [key, a] : {std::pair{"x", &spec.x}, std::pair{"y", &spec.y}})
      m[key] = {
          {"parameter", a->parameter}, {"from", a->from}, {"to", a->to}, {"points", a->points}};
    m["method"] = spec.method;
    m["phase"] = to_string(spec.phase);
    maps.push_back(m);
  }
  return maps;
}

void read_sweeps(const ConfigText& r, const std::string& key, const nlohmann::json& v,
                 ShimmyConfig& c) {
  if (!v.is_array()) r.fail_at_key(key, "expected an array of {parameter, from, to, points}");
  c.sweeps.clear();
  for (const auto& a : v) {
    MapAxis axis;
    read_axis(r, key, "axis", nlohmann::json{{"axis", a}}, axis);
    c.sweeps.push_back(axis);
  }
}
nlohmann::json write_sweeps(const ShimmyConfig& c) {
  nlohmann::json sweeps = nlohmann::json::array();
  for (const MapAxis& a : c.sweeps)
    sweeps.push_back(
        {{"parameter", a.parameter}, {"from", a.from}, {"to", a.to}, {"points", a.points}});
  return sweeps;
}

// CVODE's linear multistep method (docs/shimmy.md section 5): Adams-Moulton (the default, for
// this lightly damped gear) or BDF (for a much stiffer configuration).
void read_solver_method(const ConfigText& r, const std::string& key, const nlohmann::json& v,
                        ShimmyConfig& c) {
  if (!v.is_string() || (v != "adams" && v != "bdf"))
    r.fail_at_key(key, "expected adams or bdf, got " + v.dump());
  c.solver.method = v == "bdf" ? Integrator::bdf : Integrator::adams;
}
nlohmann::json write_solver_method(const ShimmyConfig& c) {
  return c.solver.method == Integrator::bdf ? "bdf" : "adams";
}

constexpr ParameterRange kPositive{ParameterRange::positive};
constexpr ParameterRange kFinite{ParameterRange::finite};

// The app's own keys, after the gear's; the numbers are validated in this order.
std::array<ConfigKey, 9> app_keys() {
  ConfigKey gear{"gear", "name", "", "the named gear the other values change"};
  gear.values = "default or legacy";
  gear.read = read_gear_name;
  gear.write = write_gear_name;
  ConfigKey models{"models", "list of names", "", "the contact models to run"};
  models.values = "coupled, decoupled, von_schlippe (alias nonholonomic)";
  models.read = read_models;
  models.write = write_models;
  ConfigKey maps{"maps", "list of maps", "",
                 "stability maps (--map): x and y {parameter, from, to, points}, method, phase"};
  maps.values = "method eigenvalues or simulation, phase touchdown or braked_slide";
  maps.read = read_maps;
  maps.write = write_maps;
  ConfigKey sweeps{"sweeps", "list of axes", "",
                   "bifurcation sweeps of the braked slide (--bifurcation): {parameter, from, to, "
                   "points}, each swept up and down for every model"};
  sweeps.values = "a gear parameter from and to within its valid values";
  sweeps.read = read_sweeps;
  sweeps.write = write_sweeps;
  ConfigKey method{"solver.method", "name", "", "CVODE's method: Adams-Moulton or BDF"};
  method.values = "adams or bdf";
  method.read = read_solver_method;
  method.write = write_solver_method;
  ConfigKey rtol{"solver.relative_tolerance", "number", "1",
                 "CVODE's relative tolerance (absolute: times each state's scale)"};
  // The convergence check reruns each landing at 1/100 of it: 1e-12 keeps that within what
  // CVODE can meet (require_relative_tolerance).
  rtol.range = ParameterRange{ParameterRange::interval,
                              1e-12,
                              0.1,
                              false,
                              true,
                              "must lie in [1e-12, 0.1): the convergence check runs at 1/100 of "
                              "it, and CVODE cannot meet less than 1e-14 in double precision",
                              "must lie in [1e-12, 0.1): a looser tolerance is no integration"};
  rtol.number = [](ShimmyConfig& c) -> double& { return c.solver.relative_tolerance; };
  ConfigKey interval{"solver.output_interval_s", "number", "s",
                     "time between samples of the histories and the analysis"};
  interval.range = kPositive;
  interval.number = [](ShimmyConfig& c) -> double& { return c.solver.output_interval_s; };
  ConfigKey amplitude{"shimmy.amplitude_threshold_rad", "number", "rad",
                      "shimmy: the torsion's last amplitude above this"};
  amplitude.range = kPositive;
  amplitude.number = [](ShimmyConfig& c) -> double& { return c.criterion.amplitude_threshold_rad; };
  ConfigKey growth{"shimmy.sustained_growth_rate_per_s", "number", "1/s",
                   "shimmy: the torsion's growth rate above this"};
  growth.range = kFinite;
  growth.number = [](ShimmyConfig& c) -> double& {
    return c.criterion.sustained_growth_rate_per_s;
  };
  return {gear, models, maps, sweeps, method, rtol, interval, amplitude, growth};
}

std::string_view gear_type(const GearParameter& p) {
  switch (p.type) {
    case ParameterType::flag:
      return "true or false";
    case ParameterType::choice:
      return "name";
    case ParameterType::number:
      break;
  }
  return "number";
}

void check_app_range(const ConfigKey& k, double v) {
  const std::string name(k.name);
  if (k.range.kind == ParameterRange::positive) require_positive(name.c_str(), v);
  if (k.range.kind == ParameterRange::finite) require_finite(name.c_str(), v);
  if (k.range.kind != ParameterRange::interval) return;
  if (k.range.finite_first) require_finite(name.c_str(), v);
  if (!(k.range.lo_open ? v > k.range.lo : v >= k.range.lo))
    throw InvalidArgument(name, format_value(v), std::string(k.range.rule));
  if (!(v < k.range.hi))
    throw InvalidArgument(
        name, format_value(v),
        std::string(k.range.rule_above.empty() ? k.range.rule : k.range.rule_above));
}

// A default value for the key table: numbers shortest, lists by their length.
std::string default_text(const nlohmann::json& v) {
  if (v.is_number()) return format_value(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_array() && !v.empty() && v.front().is_object())
    return std::to_string(v.size()) + " (--print-config)";
  if (v.is_array()) {
    std::string out;
    for (const auto& e : v) out += (out.empty() ? "" : ", ") + default_text(e);
    return out;
  }
  return v.dump();
}

}  // namespace

void ConfigText::fail_at_key(const std::string& key, const std::string& message,
                             bool name_key) const {
  // nlohmann::json keeps no positions: locate the key's first quoted occurrence.
  const std::string leaf = key.substr(key.rfind('.') + 1);
  fail_at(text.find("\"" + leaf + "\""), name_key ? key + ": " + message : message);
}

void ConfigText::fail_at(std::size_t pos, const std::string& message) const {
  const auto [line, col] = line_column(text, pos == std::string::npos ? 0 : pos);
  throw ParseError(path, line, col, message);
}

double ConfigText::number(const nlohmann::json& j, const std::string& key) const {
  if (!j.is_number()) fail_at_key(key, "expected a number, got " + j.dump());
  return j.get<double>();
}

std::vector<ConfigKey> config_keys() {
  std::vector<ConfigKey> keys;
  for (const GearParameter& p : gear_parameters()) {
    ConfigKey k{p.name, gear_type(p), p.unit, p.help};
    k.gear = &p;
    keys.push_back(k);
  }
  for (const ConfigKey& k : app_keys()) keys.push_back(k);
  return keys;
}

void read_key(const ConfigKey& key, const ConfigText& source, const nlohmann::json& value,
              ShimmyConfig& c) {
  const std::string name(key.name);
  if (key.read) return key.read(source, name, value, c);
  if (key.number) {
    key.number(c) = source.number(value, name);
    return;
  }
  const GearParameter& p = *key.gear;
  if (p.number) {
    p.number(c.gear) = source.number(value, name);
  } else if (p.flag) {
    if (!value.is_boolean())
      source.fail_at_key(name, "expected true or false, got " + value.dump());
    p.flag(c.gear) = value.get<bool>();
  } else {
    // The name is checked by validate() with the others (an error naming the value).
    if (!value.is_string()) source.fail_at_key(name, "expected " + describe_range(p));
    p.text(c.gear) = value.get<std::string>();
  }
}

nlohmann::json write_key(const ConfigKey& key, ShimmyConfig& c) {
  if (key.write) return key.write(c);
  if (key.number) return key.number(c);
  const GearParameter& p = *key.gear;
  if (p.number) return p.number(c.gear);
  if (p.flag) return p.flag(c.gear);
  return p.text(c.gear);
}

void validate_keys(const ShimmyConfig& config) {
  validate(config.gear);
  ShimmyConfig c = config;  // read only (the accessors take it non-const)
  for (const ConfigKey& k : app_keys())
    if (k.number) check_app_range(k, k.number(c));
  // Every map's axes: known keys, finite ends and span inside the key's valid values, two
  // different keys (stability_map.hpp, check_map_axes).
  for (std::size_t k = 0; k < config.maps.size(); ++k) {
    try {
      check_map_axes(config.gear, config.maps[k].x, config.maps[k].y);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(
          "maps", "map " + std::to_string(k + 1) + " of " + std::to_string(config.maps.size()),
          e.what());
    }
  }
  for (std::size_t k = 0; k < config.sweeps.size(); ++k) {
    try {
      check_sweep_axis(config.gear, config.sweeps[k]);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(
          "sweeps",
          "sweep " + std::to_string(k + 1) + " of " + std::to_string(config.sweeps.size()),
          e.what());
    }
  }
}

std::string valid_values(const ConfigKey& key) {
  if (key.gear) return describe_range(*key.gear);
  if (!key.values.empty()) return std::string(key.values);
  if (key.range.kind == ParameterRange::interval)
    return std::string(key.range.lo_open ? "(" : "[") + format_value(key.range.lo) + ", " +
           format_value(key.range.hi) + ")";
  return key.range.kind == ParameterRange::positive ? "> 0" : "finite";
}

std::string config_keys_markdown() {
  ShimmyConfig defaults;
  std::string out =
      "| key | type | unit | valid values | default | meaning |\n"
      "|---|---|---|---|---|---|\n";
  for (const ConfigKey& k : config_keys()) {
    out += "| `" + std::string(k.name) + "` | " + std::string(k.type) + " | " +
           std::string(k.unit) + " | " + valid_values(k) + " | " +
           default_text(write_key(k, defaults)) + " | " + std::string(k.help) + " |\n";
  }
  return out;
}

}  // namespace contensou::app
