// How far the classical tire's verdict rests on its assumed numbers (docs/shimmy.md, "Like for
// like"): the classical (von_schlippe) model with its relaxation length, longitudinal slip,
// cornering and aligning coefficients, tread moment and the longitudinal relaxation length (every
// model's) varied one at a time, judged by
// eigenvalues: the touchdown's critical torsional damping, the braked slide's growth rate at the
// configuration, and the braked slide's lowest unstable offset over a few speeds; the coupled
// model as configured beside it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "config.hpp"
#include "simulate.hpp"

namespace contensou::app {

struct SensitivityRow {
  std::string model;                          // "von_schlippe" or "coupled" (the reference row)
  std::string change;                         // in words, e.g. "sigma = 0.150 m (= R)"
  double critical_damping_nms_per_rad = 0.0;  // classical touchdown (NaN for the coupled row)
  double braked_growth_per_s = 0.0;           // braked slide at the configuration
  double boundary_offset_m = 0.0;             // lowest unstable offset (NaN: none up to 1 m)
  double boundary_speed_mps = 0.0;            // the speed it is lowest at
};

std::vector<SensitivityRow> classical_sensitivity(const ShimmyConfig& config,
                                                  const TireInput* tire);

// Prints the table and puts it into summary["classical_sensitivity"].
void report_sensitivity(const std::vector<SensitivityRow>& rows, nlohmann::json& summary);

}  // namespace contensou::app
