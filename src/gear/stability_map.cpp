#include "contensou/gear/stability_map.hpp"

#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <utility>

#include "contensou/friction/error.hpp"
#include "contensou/gear/gear_parameters.hpp"
#include "parallel_cells.hpp"

namespace contensou {

void check_map_axis(const GearConfig& config, const MapAxis& a, const std::string& name) {
  const GearParameter* p = find_gear_parameter(a.parameter);
  if (!p || !p->number)
    throw InvalidArgument(name + ".parameter", a.parameter, "is not a gear parameter");
  if (a.points < 1 || a.points > 10000)
    throw InvalidArgument(name + ".points", std::to_string(a.points), "must lie in 1..10000");
  require_finite((name + ".from").c_str(), a.from);
  require_finite((name + ".to").c_str(), a.to);
  if (a.points > 1 && a.from == a.to)
    throw InvalidArgument(name,
                          a.parameter + " from " + format_value(a.from) + " to " +
                              format_value(a.to) + " in " + std::to_string(a.points) + " points",
                          "the ends are equal: every point would repeat one value; give two "
                          "different ends (or points = 1)");
  // The cells lie between the ends: their difference must be finite too (-1e308 to 1e308
  // would give inf and nan cells).
  if (!std::isfinite(a.to - a.from))
    throw InvalidArgument(
        name, a.parameter + " from " + format_value(a.from) + " to " + format_value(a.to),
        "the span to - from overflows: choose ends within the key's range");
  // Every range of the key table is an interval, so both ends inside means every cell inside.
  for (const double v : {a.from, a.to}) {
    GearConfig probe = config;
    p->number(probe) = v;
    try {
      check_gear_parameter(*p, probe);
    } catch (const InvalidArgument& e) {
      throw InvalidArgument(
          name, a.parameter + " from " + format_value(a.from) + " to " + format_value(a.to),
          "leaves the key's valid values " + describe_range(*p) + " (" + e.what() + ")");
    }
  }
}

void check_sweep_axis(const GearConfig& config, const MapAxis& a) {
  check_map_axis(config, a, "sweep");
  if (a.points < 2)
    throw InvalidArgument("sweep.points", std::to_string(a.points),
                          "a sweep is a diagram along " + a.parameter + ": give at least 2 points");
}

void check_map_axes(const GearConfig& config, const MapAxis& x, const MapAxis& y) {
  check_map_axis(config, x, "map x");
  check_map_axis(config, y, "map y");
  if (x.parameter == y.parameter)
    throw InvalidArgument("map y.parameter", y.parameter,
                          "is also the x axis' parameter: a map needs two different keys");
}

StabilityMap evaluate_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                          unsigned threads, const std::function<void(int, int)>& progress,
                          const std::function<void(const GearModel&, MapCell&)>& cell_fn) {
  check_map_axes(base.config, x, y);
  StabilityMap map{x, y, base.contact, false, StabilityPhase::braked_slide, {}};
  const int total = x.points * y.points;
  map.cells.resize(static_cast<std::size_t>(total));
  // A cell stopped by the caller (Interrupted) is not an error of that cell: the map stops,
  // no further cell starts, and the interruption is rethrown here.
  std::atomic<bool> interrupted{false};
  std::exception_ptr interruption;
  std::mutex lock;
  detail::run_cells_in_parallel(total, threads, progress, [&](int k) {
    if (interrupted.load()) return;
    MapCell& cell = map.cells[static_cast<std::size_t>(k)];
    cell.x = x.value(k % x.points);
    cell.y = y.value(k / x.points);
    GearModel model = base;  // shares the exact model, if any (read-only)
    *gear_parameter(model.config, x.parameter) = cell.x;
    *gear_parameter(model.config, y.parameter) = cell.y;
    try {
      validate(model.config);
      cell_fn(model, cell);
    } catch (const Interrupted&) {
      const std::lock_guard<std::mutex> guard(lock);
      if (!interruption) interruption = std::current_exception();
      interrupted = true;
    } catch (const std::exception& e) {
      cell.error = e.what();
    }
  });
  if (interruption) std::rethrow_exception(interruption);
  return map;
}

StabilityMap stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                           const SolverOptions& solver, const ShimmyCriterion& criterion,
                           unsigned threads, const std::function<void(int, int)>& progress) {
  SolverOptions quiet = solver;
  quiet.record = false;
  return evaluate_map(base, x, y, threads, progress, [&](const GearModel& model, MapCell& cell) {
    const LandingRun run = simulate_landing(model, quiet, criterion);
    cell.growth_rate_per_s = run.metrics.torsion.growth_rate_per_s;
    cell.frequency_hz = run.metrics.torsion.frequency_hz;
    cell.last_amplitude_rad = run.metrics.torsion.last_amplitude;
    cell.shimmy = run.metrics.shimmy;
    cell.valid = run.metrics.torsion.valid() && std::isfinite(cell.growth_rate_per_s) &&
                 std::isfinite(cell.frequency_hz);
  });
}

StabilityMap linear_stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                                  StabilityPhase phase, unsigned threads,
                                  const std::function<void(int, int)>& progress) {
  StabilityMap map =
      evaluate_map(base, x, y, threads, progress, [&](const GearModel& model, MapCell& cell) {
        StabilityOptions o;
        o.simulate_perturbation = false;
        const StabilityReport r = phase == StabilityPhase::touchdown
                                      ? assess_touchdown(model, o)
                                      : assess_stability(model, phase, o);
        cell.valid = r.state.converged && std::isfinite(r.growth_rate_per_s) &&
                     std::isfinite(r.frequency_hz);
        cell.growth_rate_per_s = r.growth_rate_per_s;
        cell.frequency_hz = r.frequency_hz;
        cell.shimmy = cell.valid && r.growth_rate_per_s > 0.0;
      });
  map.linear = true;
  map.phase = phase;
  return map;
}

}  // namespace contensou
