// contensou-shimmy --tire: a contensou-identify report (JSON) as the gear's tire law
// (docs/shimmy.md, "Tire uncertainty").
#pragma once

#include <string>

#include "contensou/gear/tire_uncertainty.hpp"

namespace contensou::app {

// The final model's F0_N, a, M0_Nm, m, kx (value and std_error; a fixed parameter has no
// std_error and no variance), their correlation matrix and the test patch's radius
// (input.radius_m). Errors name the file and the missing or bad key.
TireLawDistribution read_tire_report(const std::string& path);

}  // namespace contensou::app
