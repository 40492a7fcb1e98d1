// contensou-engine-coefficients: MuJoCo, Chrono, Bullet and Gazebo spin-friction coefficients
// for a contact patch, with their definitions and worst errors against the exact integrals
// (coefficients.hpp). Usage:
//   contensou-engine-coefficients --profile uniform --radius 0.05 --friction 0.5 [--json]
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <iostream>

#include "coefficients.hpp"

namespace {
std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
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
      ->capture_default_str();
  app.add_option("--radius", radius, "patch radius R [m]")->required();
  app.add_option("--friction", friction, "friction coefficient f")->required();
  app.add_flag("--json", json, "print JSON instead of the table");
  CLI11_PARSE(app, argc, argv);
  try {
    using namespace contensou::engines;
    const auto patch = named_patch(profile, radius, friction);
    const auto rows = engine_coefficients(patch);
    if (json) {
      std::printf("{\"profile\": %s, \"radius\": %.17g, \"friction\": %.17g, \"rows\": [\n",
                  json_string(profile).c_str(), radius, friction);
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const auto& r = rows[i];
        std::printf(
            " {\"engine\": %s, \"parameter\": %s, \"value\": %.17g, \"unit\": %s, "
            "\"definition\": %s, \"worst_force_error\": %.17g, \"worst_torque_error\": %.17g, "
            "\"snippet\": %s}%s\n",
            json_string(r.engine).c_str(), json_string(r.parameter).c_str(), r.value,
            json_string(r.unit).c_str(), json_string(r.definition).c_str(), r.worst_force_error,
            r.worst_torque_error, json_string(r.snippet).c_str(), i + 1 < rows.size() ? "," : "");
      }
      std::printf("]}\n");
      return 0;
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
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "contensou-engine-coefficients: " << e.what() << "\n";
    return 2;
  }
}
