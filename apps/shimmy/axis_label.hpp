// Axis labels of the shimmy demo's maps: configuration keys with their unit suffix spelled out.
#pragma once

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace contensou::app {

// "structure.offset_m" -> "offset_m".
inline std::string short_name(const std::string& parameter) {
  return parameter.substr(parameter.rfind('.') + 1);
}

// "structure.offset_m" -> "offset [m]": a configuration key as an axis label, its unit suffix
// spelled out ("[-]" for a pure number).
inline std::string parameter_axis_label(const std::string& parameter) {
  static const std::vector<std::pair<std::string, std::string>> units{{"_nms_per_rad", "N m s/rad"},
                                                                      {"_nm_per_rad", "N m/rad"},
                                                                      {"_nm2_per_rad", "N m^2/rad"},
                                                                      {"_ns_per_m", "N s/m"},
                                                                      {"_n_per_m", "N/m"},
                                                                      {"_kgm2", "kg m^2"},
                                                                      {"_mps", "m/s"},
                                                                      {"_nm", "N m"},
                                                                      {"_kg", "kg"},
                                                                      {"_pa", "Pa"},
                                                                      {"_rad", "rad"},
                                                                      {"_n", "N"},
                                                                      {"_m", "m"},
                                                                      {"_s", "s"}};
  std::string name = short_name(parameter), unit = "-";
  for (const auto& [suffix, u] : units)
    if (name.size() > suffix.size() &&
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
      name.erase(name.size() - suffix.size());
      unit = u;
      break;
    }
  std::replace(name.begin(), name.end(), '_', ' ');
  return name + " [" + unit + "]";
}

}  // namespace contensou::app
