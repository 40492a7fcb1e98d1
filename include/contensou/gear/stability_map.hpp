// Stability maps of the landing gear: a grid over two parameters, one simulated landing per
// cell, run on several threads (docs/shimmy.md, "Stability maps").
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/gear/landing_simulation.hpp"

namespace contensou {

struct MapAxis {
  std::string parameter;  // a name from gear_parameter_names()
  double from = 0.0, to = 1.0;
  int points = 50;
  double value(int i) const { return points == 1 ? from : from + (to - from) * i / (points - 1); }
};

struct MapCell {
  double x = 0.0, y = 0.0;
  double growth_rate_per_s = 0.0;
  double frequency_hz = 0.0;
  double last_amplitude_rad = 0.0;
  bool shimmy = false;
  bool valid = false;  // enough oscillation to estimate a growth rate
  std::string error;   // set if the integration failed
};

struct StabilityMap {
  MapAxis x, y;
  ContactModel contact = ContactModel::coupled;
  std::vector<MapCell> cells;  // row-major: cells[j * x.points + i] at (x.value(i), y.value(j))
};

// Runs x.points * y.points landings of `base` with the two parameters set, on `threads`
// threads (0: all cores). `progress(done, total)` is called from the calling thread only.
// Throws InvalidArgument for an unknown parameter or a bad axis.
StabilityMap stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                           const SolverOptions& solver, const ShimmyCriterion& criterion,
                           unsigned threads = 0,
                           const std::function<void(int, int)>& progress = {});

}  // namespace contensou
