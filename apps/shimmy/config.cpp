#include "config.hpp"

#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

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

struct Reader {
  std::string path, text;

  [[noreturn]] void fail_at_key(const std::string& key, const std::string& message,
                                bool name_key = true) const {
    // nlohmann::json keeps no positions: locate the key's first quoted occurrence.
    const std::string leaf = key.substr(key.rfind('.') + 1);
    const std::size_t pos = text.find("\"" + leaf + "\"");
    const auto [line, col] = line_column(text, pos == std::string::npos ? 0 : pos);
    throw ParseError(path, line, col, name_key ? key + ": " + message : message);
  }

  double number(const nlohmann::json& j, const std::string& key) const {
    if (!j.is_number()) fail_at_key(key, "expected a number, got " + j.dump());
    return j.get<double>();
  }
};

}  // namespace

nlohmann::json to_json(const ShimmyConfig& c) {
  nlohmann::json j;
  j["gear"] = c.gear_name;
  GearConfig g = c.gear;
  for (const std::string& name : gear_parameter_names()) {
    nlohmann::json* node = &j;
    std::string rest = name;
    for (std::size_t dot; (dot = rest.find('.')) != std::string::npos; rest = rest.substr(dot + 1))
      node = &(*node)[rest.substr(0, dot)];
    (*node)[rest] = *gear_parameter(g, name);
  }
  j["tire"]["law_coefficients"] = g.tire.law_coefficients;
  j["tire"]["exact_integrals"] = g.tire.exact_integrals;
  j["scenario"]["braking"] = g.scenario.braking;
  for (ContactModel m : c.models) j["models"].push_back(to_string(m));
  j["solver"]["relative_tolerance"] = c.solver.relative_tolerance;
  j["solver"]["method"] = c.solver.method == Integrator::bdf ? "bdf" : "adams";
  j["solver"]["output_interval_s"] = c.solver.output_interval_s;
  j["shimmy"]["amplitude_threshold_rad"] = c.criterion.amplitude_threshold_rad;
  j["shimmy"]["sustained_growth_rate_per_s"] = c.criterion.sustained_growth_rate_per_s;
  j["maps"] = nlohmann::json::array();  // an empty list stays empty (not the defaults)
  for (const MapSpec& spec : c.maps) {
    nlohmann::json m;
    for (const auto& [key, a] : {std::pair{"x", &spec.x}, std::pair{"y", &spec.y}})
      m[key] = {
          {"parameter", a->parameter}, {"from", a->from}, {"to", a->to}, {"points", a->points}};
    m["method"] = spec.method;
    m["phase"] = to_string(spec.phase);
    j["maps"].push_back(m);
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
    const auto [line, col] = line_column(text, second == std::string::npos ? 0 : second);
    throw ParseError(path, line, col,
                     "the key '" + duplicate +
                         "' appears twice in one object (JSON keeps only "
                         "one): remove one of them");
  }
  return j;
}

ShimmyConfig parse_shimmy_config(const std::string& text, const std::string& path,
                                 const std::string& gear_name) {
  Reader r{path, text};
  nlohmann::json j;
  try {
    j = parse_json_without_duplicates(r.text, path);
  } catch (const nlohmann::json::parse_error& e) {
    const auto [line, col] = line_column(r.text, e.byte > 0 ? e.byte - 1 : 0);
    std::string what = e.what();
    const std::size_t colon = what.rfind(": ");
    throw ParseError(
        path, line, col,
        "invalid JSON: " + (colon == std::string::npos ? what : what.substr(colon + 2)));
  } catch (const nlohmann::json::out_of_range& e) {
    // A number beyond the range of a double ("1e400"): no position given, locate its text.
    const std::string what = e.what(), number = what.substr(what.find('\'') + 1);
    const std::size_t pos = r.text.find(number.substr(0, number.find('\'')));
    const auto [line, col] = line_column(r.text, pos == std::string::npos ? 0 : pos);
    throw ParseError(path, line, col, "invalid JSON: " + what.substr(what.find("] ") + 2));
  }
  if (!j.is_object()) throw ParseError(path, 1, 1, "the configuration must be a JSON object");

  ShimmyConfig c;
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
  // Walks nested objects; leaves are looked up by their dotted name.
  const std::function<void(const nlohmann::json&, const std::string&)> walk =
      [&](const nlohmann::json& node, const std::string& prefix) {
        for (auto it = node.begin(); it != node.end(); ++it) {
          const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
          const nlohmann::json& v = it.value();
          if (key == "gear") {
            // read above
          } else if (key == "models") {
            if (!v.is_array() || v.empty()) r.fail_at_key(key, "expected a non-empty array");
            c.models.clear();
            for (const auto& m : v) {
              if (!m.is_string()) r.fail_at_key(key, "expected model names, got " + m.dump());
              try {
                c.models.push_back(contact_model_from_string(m.get<std::string>()));
              } catch (const InvalidArgument& e) {
                r.fail_at_key(key, e.what());
              }
            }
          } else if (key == "maps") {
            if (!v.is_array()) r.fail_at_key(key, "expected an array of {x, y}");
            c.maps.clear();
            for (const auto& m : v) {
              MapSpec spec;
              if (m.is_object()) {
                for (auto f = m.begin(); f != m.end(); ++f) {
                  const std::string fk = key + "." + f.key();
                  if (f.key() == "method") {
                    if (!f.value().is_string() ||
                        (f.value() != "eigenvalues" && f.value() != "simulation"))
                      r.fail_at_key(fk,
                                    "expected eigenvalues or simulation, got " + f.value().dump());
                    spec.method = f.value().get<std::string>();
                  } else if (f.key() == "phase") {
                    if (!f.value().is_string() ||
                        (f.value() != "touchdown" && f.value() != "braked_slide"))
                      r.fail_at_key(fk,
                                    "expected touchdown or braked_slide, got " + f.value().dump());
                    spec.phase = f.value() == "touchdown" ? StabilityPhase::touchdown
                                                          : StabilityPhase::braked_slide;
                  } else if (f.key() != "x" && f.key() != "y") {
                    r.fail_at_key(fk, "unknown key (x, y, method, phase)");
                  }
                }
              }
              for (const auto& [name, axis] : {std::pair{"x", &spec.x}, std::pair{"y", &spec.y}}) {
                if (!m.is_object() || !m.contains(name) || !m[name].is_object())
                  r.fail_at_key(key, std::string("each map needs an object '") + name + "'");
                const nlohmann::json& a = m[name];
                for (auto f = a.begin(); f != a.end(); ++f) {
                  const std::string fk = key + "." + name + "." + f.key();
                  if (f.key() == "parameter") {
                    if (!f.value().is_string()) r.fail_at_key(fk, "expected a parameter name");
                    axis->parameter = f.value().get<std::string>();
                    GearConfig probe;
                    if (!gear_parameter(probe, axis->parameter))
                      r.fail_at_key(fk, "unknown parameter '" + axis->parameter + "'");
                  } else if (f.key() == "from") {
                    axis->from = r.number(f.value(), fk);
                  } else if (f.key() == "to") {
                    axis->to = r.number(f.value(), fk);
                  } else if (f.key() == "points") {
                    if (!f.value().is_number_integer() || f.value().get<int>() < 1)
                      r.fail_at_key(fk, "expected a positive integer, got " + f.value().dump());
                    axis->points = f.value().get<int>();
                  } else {
                    r.fail_at_key(fk, "unknown key (parameter, from, to, points)");
                  }
                }
                if (axis->parameter.empty())
                  r.fail_at_key(key + "." + name, "each axis needs a 'parameter'");
              }
              c.maps.push_back(spec);
            }
          } else if (key == "tire.law_coefficients") {
            if (!v.is_string()) r.fail_at_key(key, "expected fitted, asymptotic or seed");
            c.gear.tire.law_coefficients = v.get<std::string>();
          } else if (key == "tire.exact_integrals" || key == "scenario.braking") {
            if (!v.is_boolean()) r.fail_at_key(key, "expected true or false, got " + v.dump());
            (key == "scenario.braking" ? c.gear.scenario.braking : c.gear.tire.exact_integrals) =
                v.get<bool>();
          } else if (key == "solver.method") {
            // CVODE's linear multistep method (docs/shimmy.md section 5): Adams-Moulton (the
            // default, for this lightly damped gear) or BDF (for a much stiffer configuration).
            if (!v.is_string() || (v != "adams" && v != "bdf"))
              r.fail_at_key(key, "expected adams or bdf, got " + v.dump());
            c.solver.method = v == "bdf" ? Integrator::bdf : Integrator::adams;
          } else if (key == "solver.relative_tolerance") {
            c.solver.relative_tolerance = r.number(v, key);
          } else if (key == "solver.output_interval_s") {
            c.solver.output_interval_s = r.number(v, key);
          } else if (key == "shimmy.amplitude_threshold_rad") {
            c.criterion.amplitude_threshold_rad = r.number(v, key);
          } else if (key == "shimmy.sustained_growth_rate_per_s") {
            c.criterion.sustained_growth_rate_per_s = r.number(v, key);
          } else if (v.is_object()) {
            walk(v, key);
          } else if (double* p = gear_parameter(c.gear, key)) {
            *p = r.number(v, key);
          } else {
            r.fail_at_key(key, "unknown key (contensou-shimmy --print-config lists them all)");
          }
        }
      };
  walk(j, "");
  try {
    validate(c.gear);
    require_positive("solver.relative_tolerance", c.solver.relative_tolerance);
    require_positive("solver.output_interval_s", c.solver.output_interval_s);
    require_positive("shimmy.amplitude_threshold_rad", c.criterion.amplitude_threshold_rad);
    require_finite("shimmy.sustained_growth_rate_per_s", c.criterion.sustained_growth_rate_per_s);
  } catch (const InvalidArgument& e) {
    r.fail_at_key(e.parameter(), e.what(), false);
  }
  return c;
}

}  // namespace contensou::app
