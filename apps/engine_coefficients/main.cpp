// contensou-engine-coefficients: MuJoCo, Chrono, Bullet and Gazebo spin-friction coefficients
// for a contact patch, with their definitions and worst errors against the exact integrals
// (coefficients.hpp). Usage:
//   contensou-engine-coefficients --profile uniform --radius 0.05 --friction 0.5 [--json]
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <new>

#include "cli.hpp"
#include "coefficients.hpp"
#include "run_guard.hpp"

namespace {
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {  // control characters as \u00XX
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// A JSON number; JSON has no infinity or NaN, so a value that is not finite is null (an error
// that is unbounded: the engine cannot represent the patch at all).
std::string json_number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Spin-friction coefficients of MuJoCo, Chrono, Bullet and Gazebo for a contact "
      "patch, with worst errors against the exact integrals over psi in [1e-3, 1e3]"};
  std::string profile = "uniform";
  double radius = 0.0, friction = 0.0;
  bool json = false;
  app.add_option("--profile", profile, "pressure profile: uniform, hertz or seed-tire")
      ->capture_default_str()
      ->check(contensou::app::one_of({"uniform", "hertz", "seed-tire"}));
  app.add_option("--radius", radius, "patch radius R [m]")->required();
  app.add_option("--friction", friction, "friction coefficient f")->required();
  app.add_flag("--json", json, "print JSON instead of the table");
  contensou::app::add_conventions(app, "contensou-engine-coefficients");
  contensou::app::prepare_output();
  if (const std::optional<int> status = contensou::app::parse(app, argc, argv)) return *status;
  try {
    using namespace contensou::engines;
    const auto patch = named_patch(profile, radius, friction);
    const auto rows = engine_coefficients(patch);
    if (json) {
      std::printf("{\"profile\": %s, \"radius\": %s, \"friction\": %s, \"rows\": [\n",
                  json_string(profile).c_str(), json_number(radius).c_str(),
                  json_number(friction).c_str());
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        std::printf(
            " {\"engine\": %s, \"parameter\": %s, \"value\": %s, \"unit\": %s, "
            "\"definition\": %s, \"worst_force_error\": %s, \"worst_torque_error\": %s, "
            "\"snippet\": %s}%s\n",
            json_string(r.engine).c_str(), json_string(r.parameter).c_str(),
            json_number(r.value).c_str(), json_string(r.unit).c_str(),
            json_string(r.definition).c_str(), json_number(r.worst_force_error).c_str(),
            json_number(r.worst_torque_error).c_str(), json_string(r.snippet).c_str(),
            i + 1 < rows.size() ? "," : "");
      }
      std::printf("]}\n");
      return contensou::app::finish_output(0);
    }
    std::printf(
        "patch: %s pressure, R = %g m, f = %g; errors over psi = v/(omega R) in "
        "[1e-3, 1e3], relative to f N and the exact pure-spin torque\n",
        profile.c_str(), radius, friction);
    std::printf("%-34s %-30s %12s  %11s %11s  %s\n", "engine", "parameter", "value [m]",
                "worst F err", "worst M err", "definition");
    for (const auto& r : rows)
      std::printf("%-34s %-30s %12.6g  %11.4f %11.4f  %s\n", r.engine.c_str(), r.parameter.c_str(),
                  r.value, r.worst_force_error, r.worst_torque_error, r.definition.c_str());
    std::printf("\nsnippets:\n");
    for (const auto& r : rows) std::printf("  %s: %s\n", r.engine.c_str(), r.snippet.c_str());
    return contensou::app::finish_output(0);
  } catch (const std::bad_alloc&) {
    std::cerr << "contensou-engine-coefficients: error: out of memory computing the coefficients "
                 "(the machine's memory or ulimit -v)\n";
    return contensou::app::kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "contensou-engine-coefficients: " << e.what() << "\n";
    return contensou::app::kExitFailure;
  }
}
