// contensou-shimmy --tire: a contensou-identify report (JSON) as the gear's tire law
// (docs/shimmy.md, "Tire uncertainty").
#pragma once

#include <string>

#include "contensou/gear/tire_uncertainty.hpp"

namespace contensou::app {

// What the gear takes from a report: the law's distribution, the report's model it comes from
// and, in words, what of the report the gear's tire cannot carry.
struct TireReport {
  TireLawDistribution distribution;
  std::string model = "final";  // "final" or "base" (the report's key)
  std::string note;             // empty when the gear carries the whole final model
};

// The fractional law's F0_N, a, M0_Nm, m, kx (value and std_error; a fixed parameter has no
// std_error and no variance), their correlation matrix and the test patch's radius
// (input.radius_m), from every report contensou-identify writes: the plain fit (--no-loop; its
// final model is the base fit) and the closed loop, whatever model it ends with. The final
// model when it has the five parameters (its further effects, if any, named in the note: the
// gear's tire has none of them); otherwise (the loop ended with the parametric profile's b1, b2
// or the exact law) the report's base fit, the fractional law fitted to the same data, with the
// note saying why. Errors name the file and the missing or bad key.
TireReport read_tire_report(const std::string& path);

}  // namespace contensou::app
