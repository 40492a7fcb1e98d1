/// \file
/// Stability maps of the landing gear: a grid over two parameters, one simulated landing (or one
/// eigenvalue analysis) per cell, run on several threads (docs/shimmy.md, section 6.2, "Maps").
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/linear_stability.hpp"

namespace contensou {

/// One axis of a map or sweep: a number key varied over evenly spaced points, from first to last.
struct MapAxis {
  std::string parameter;  ///< a name from gear_parameter_names()
  /// The first value, in the key's unit.
  double from = 0.0, to = 1.0;  ///< the last value, in the key's unit
  int points = 50;              ///< how many values, 1..10000 (check_map_axis)
  /// The i-th value, from + (to - from) i / (points - 1); `from` for a single point.
  double value(int i) const { return points == 1 ? from : from + (to - from) * i / (points - 1); }
};

/// One cell of a map.
struct MapCell {
  /// The x axis' parameter value.
  double x = 0.0, y = 0.0;  ///< the y axis' parameter value
  /// Simulated: the torsion's fitted growth rate on the window; eigenvalues: linear_growth_rate;
  /// probability maps: the median over the draws [1/s].
  double growth_rate_per_s = 0.0;
  double frequency_hz = 0.0;        ///< of the same oscillation or mode [Hz]; 0 in probability maps
  double last_amplitude_rad = 0.0;  ///< the torsion's last amplitude [rad]; simulated maps only
  /// Simulated: ShimmyMetrics::shimmy; eigenvalues: valid and growth rate > 0; probability maps:
  /// shimmy_probability at least 0.5.
  bool shimmy = false;
  /// Simulated: enough oscillation to estimate a growth rate; eigenvalues: the quasi-steady state
  /// was found; probability maps: at least one draw gave a growth rate.
  bool valid = false;
  double shimmy_probability = 0.0;  ///< probability maps (tire_uncertainty.hpp) only
  std::string error;                ///< what the cell threw (bad values, a failed integration)
};

/// A grid of cells over two axes.
struct StabilityMap {
  /// The x axis (the cells' index i).
  MapAxis x, y;                                  ///< the y axis (the cells' index j)
  ContactModel contact = ContactModel::coupled;  ///< the model of every cell
  bool linear = false;  ///< eigenvalue map (linear_stability_map), else simulated landings
  StabilityPhase phase = StabilityPhase::braked_slide;  ///< of an eigenvalue map
  /// Row-major: cells[j * x.points + i] at (x.value(i), y.value(j)).
  std::vector<MapCell> cells;
};

/// Throws InvalidArgument naming the axis (`name`, e.g. "map x") unless its parameter is a number
/// key of the gear, 1..10000 points, both ends and their span finite, and both ends inside the
/// key's valid values (gear_parameters.hpp; checked at `config` with the end set), and two
/// different ends for more than one point (equal ends would repeat one value).
void check_map_axis(const GearConfig& config, const MapAxis& axis, const std::string& name);

/// check_map_axis for a bifurcation sweep's axis, which also needs at least 2 points (the sweep
/// is a diagram along the parameter); InvalidArgument named "sweep".
void check_sweep_axis(const GearConfig& config, const MapAxis& axis);
/// Both axes ("map x", "map y"), and that they are two different keys.
void check_map_axes(const GearConfig& config, const MapAxis& x, const MapAxis& y);

/// Runs x.points * y.points landings of `base` with the two parameters set, on `threads`
/// threads (0: all cores). `progress(done, total)` is called from the calling thread only.
/// Throws InvalidArgument for an unknown parameter, a bad axis or one key on both axes,
/// Interrupted when solver.stop asks; a landing that fails leaves its error in its cell.
StabilityMap stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                           const SolverOptions& solver, const ShimmyCriterion& criterion,
                           unsigned threads = 0,
                           const std::function<void(int, int)>& progress = {});

/// The grid with `cell_fn(model, cell)` run for every cell (the model with the two parameters set
/// and validated; an exception goes into cell.error, except Interrupted, which stops the map and
/// is rethrown), on `threads` threads (0: all cores). Throws InvalidArgument for bad axes.
StabilityMap evaluate_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                          unsigned threads, const std::function<void(int, int)>& progress,
                          const std::function<void(const GearModel&, MapCell&)>& cell_fn);

/// The same grid judged by eigenvalues (linear_stability.hpp): each cell's growth rate is
/// the largest real part of an oscillatory eigenvalue of the linearisation about the phase's
/// quasi-steady state (worst frozen slip at touchdown, as linear_growth_rate); shimmy = growth
/// rate > 0; valid = the quasi-steady state was found. Much cheaper than simulating (no
/// amplitude threshold).
StabilityMap linear_stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                                  StabilityPhase phase, unsigned threads = 0,
                                  const std::function<void(int, int)>& progress = {});

}  // namespace contensou
