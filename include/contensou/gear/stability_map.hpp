// Stability maps of the landing gear: a grid over two parameters, one simulated landing per
// cell, run on several threads (docs/shimmy.md, "Stability maps").
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/linear_stability.hpp"

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
  bool valid = false;               // enough oscillation to estimate a growth rate
  double shimmy_probability = 0.0;  // probability maps (tire_uncertainty.hpp) only
  std::string error;                // set if the integration failed
};

struct StabilityMap {
  MapAxis x, y;
  ContactModel contact = ContactModel::coupled;
  bool linear = false;  // eigenvalue map (linear_stability_map), else simulated landings
  StabilityPhase phase = StabilityPhase::braked_slide;  // of an eigenvalue map
  std::vector<MapCell> cells;  // row-major: cells[j * x.points + i] at (x.value(i), y.value(j))
};

// Throws InvalidArgument naming the axis (`name`, e.g. "map x") unless its parameter is a number
// key of the gear, 1..10000 points, both ends and their span finite, and both ends inside the
// key's valid values (gear_parameters.hpp; checked at `config` with the end set).
void check_map_axis(const GearConfig& config, const MapAxis& axis, const std::string& name);
// Both axes, and that they are two different keys.
void check_map_axes(const GearConfig& config, const MapAxis& x, const MapAxis& y);

// Runs x.points * y.points landings of `base` with the two parameters set, on `threads`
// threads (0: all cores). `progress(done, total)` is called from the calling thread only.
// Throws InvalidArgument for an unknown parameter or a bad axis.
StabilityMap stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                           const SolverOptions& solver, const ShimmyCriterion& criterion,
                           unsigned threads = 0,
                           const std::function<void(int, int)>& progress = {});

// The grid with `cell_fn(model, cell)` run for every cell (the model with the two parameters set
// and validated; an exception goes into cell.error), on `threads` threads (0: all cores).
StabilityMap evaluate_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                          unsigned threads, const std::function<void(int, int)>& progress,
                          const std::function<void(const GearModel&, MapCell&)>& cell_fn);

// The same grid judged by eigenvalues (linear_stability.hpp): each cell's growth rate is
// linear_growth_rate(model, phase), the largest real part of an oscillatory eigenvalue of the
// linearisation about the phase's quasi-steady state; shimmy = growth rate > 0; valid = the
// quasi-steady state was found. Much cheaper than simulating (no amplitude threshold).
StabilityMap linear_stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                                  StabilityPhase phase, unsigned threads = 0,
                                  const std::function<void(int, int)>& progress = {});

}  // namespace contensou
