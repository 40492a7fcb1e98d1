#include "gear_variables.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "config.hpp"
#include "config_keys.hpp"
#include "history.hpp"

namespace contensou::fmu {

namespace {

std::string start_text(const nlohmann::json& v) {
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_string()) return v.get<std::string>();
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v.get<double>());
  return buf;
}

std::vector<GearVariable> build() {
  std::vector<GearVariable> out;
  auto add = [&](std::string name, Causality c, VariableType t, std::string unit,
                 std::string description, std::string start) -> GearVariable& {
    GearVariable v;
    v.variable = {static_cast<unsigned>(out.size()), "", c, t};
    v.name = std::move(name);
    v.unit = std::move(unit);
    v.description = std::move(description);
    v.start = std::move(start);
    out.push_back(std::move(v));
    return out.back();
  };
  app::ShimmyConfig defaults;
  char speed[40];
  std::snprintf(speed, sizeof speed, "%.17g", defaults.gear.scenario.forward_speed_mps);
  add("forward_speed_mps", Causality::input, VariableType::real, "m/s",
      "forward speed V of the aircraft (replaces scenario.forward_speed_mps)", speed);
  add("brake_torque_command_nm", Causality::input, VariableType::real, "N m",
      "brake torque command, the anti-skid's T_max; 0: brake off (replaces scenario.braking, "
      "brake_on_s, brake_off_s, brake_max_torque_nm)",
      "0");
  const auto& columns = app::history_column_table();
  for (std::size_t k = 1; k < columns.size(); ++k) {  // t_s is the FMU's time
    GearVariable& v = add(columns[k].name, Causality::output, VariableType::real, columns[k].unit,
                          columns[k].quantity, "");
    v.history_column = static_cast<int>(k);
  }
  add("contact_model", Causality::parameter, VariableType::string, "",
      "the tire-ground law: coupled, decoupled or von_schlippe", "coupled");
  for (const app::ConfigKey& key : app::config_keys()) {
    const std::string name(key.name), type(key.type);
    if (gear_key_excluded(name) || type.rfind("list", 0) == 0) continue;
    const VariableType t = type == "number"          ? VariableType::real
                           : type == "true or false" ? VariableType::boolean
                                                     : VariableType::string;
    std::string help(key.help);
    const std::string range = app::valid_values(key);
    if (!range.empty()) help += " (valid: " + range + ")";
    GearVariable& v = add(name, Causality::parameter, t, std::string(key.unit), help,
                          start_text(app::write_key(key, defaults)));
    v.key = name;
  }
  for (GearVariable& v : out) v.variable.name = v.name.c_str();
  return out;
}

}  // namespace

bool gear_key_excluded(const std::string& key) {
  static const char* const excluded[] = {"scenario.forward_speed_mps",
                                         "scenario.braking",
                                         "scenario.brake_on_s",
                                         "scenario.brake_off_s",
                                         "scenario.brake_max_torque_nm",
                                         "scenario.end_time_s",
                                         "scenario.window_start_s",
                                         "scenario.window_end_s",
                                         "solver.output_interval_s",
                                         "models",
                                         "maps"};
  for (const char* e : excluded)
    if (key == e) return true;
  return key.rfind("shimmy.", 0) == 0;
}

const std::vector<GearVariable>& gear_variables() {
  static const std::vector<GearVariable> variables = build();
  return variables;
}

const std::vector<Variable>& gear_variable_table() {
  static const std::vector<Variable> table = [] {
    std::vector<Variable> t;
    for (const GearVariable& v : gear_variables()) t.push_back(v.variable);
    return t;
  }();
  return table;
}

std::string gear_guid() {
  std::string text = "contensou gear FMU 1\n";
  for (const GearVariable& v : gear_variables())
    text += v.name + ' ' + std::to_string(int(v.variable.causality)) + ' ' +
            std::to_string(int(v.variable.type)) + ' ' + v.unit + ' ' + v.start + '\n';
  return guid_of(text);
}

}  // namespace contensou::fmu
