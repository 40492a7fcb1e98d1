#include "simulate.hpp"

#include <algorithm>
#include <stdexcept>

#include "axis_label.hpp"
#include "contensou/friction/error.hpp"
#include "tire_report.hpp"

namespace contensou::app {

TireInput read_tire_input(const std::string& path, int draws, unsigned seed) {
  TireInput tire;
  tire.path = path;
  TireReport report = read_tire_report(path);
  tire.distribution = report.distribution;
  tire.model = report.model;
  tire.note = report.note;
  tire.mean = tire_law_coefficients(tire.distribution.mean, tire.distribution.radius_m);
  try {
    tire.draws = draw_tire_laws(tire.distribution, draws, seed);
  } catch (const InvalidArgument& e) {
    throw std::runtime_error("--tire " + path + ": " + e.what());
  }
  return tire;
}

GearModel gear_model(const ShimmyConfig& config, ContactModel cm, const TireInput* tire) {
  const GearModel m = make_gear_model(config.gear, cm);
  return tire ? with_tire_law(m, tire->mean) : m;
}

void require_landing(const LandingScenario& s) {
  if (!(s.touchdown_time_s + s.load_ramp_s < s.end_time_s))
    throw InvalidArgument("scenario.touchdown_time_s", format_value(s.touchdown_time_s),
                          "with load_ramp_s = " + format_value(s.load_ramp_s) +
                              " the gear is not fully loaded before end_time_s = " +
                              format_value(s.end_time_s) + ": there is no landing to analyse");
}

namespace {

// One landing; a solver failure names the contact model and the tolerance it ran at (the
// failure itself says where and why).
LandingRun landing_of(const GearModel& model, ContactModel cm, const SolverOptions& solver,
                      const ShimmyCriterion& criterion) {
  try {
    return simulate_landing(model, solver, criterion);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(std::string("the landing with the ") + to_string(cm) +
                             " tire (relative tolerance " +
                             format_value(solver.relative_tolerance) + "): " + e.what());
  }
}

}  // namespace

Landings simulate_landings(const ShimmyConfig& config, const TireInput* tire) {
  require_landing(config.gear.scenario);
  Landings out;
  for (ContactModel cm : config.models) {
    const GearModel model = gear_model(config, cm, tire);
    out.runs.push_back(landing_of(model, cm, config.solver, config.criterion));
    // Convergence: the same landing at a 100 times tighter tolerance.
    SolverOptions tight = config.solver;
    tight.relative_tolerance *= 1e-2;
    tight.record = false;
    out.tight.push_back(landing_of(model, cm, tight, config.criterion));
    out.tight_relative_tolerance = tight.relative_tolerance;
  }
  return out;
}

namespace {

// The axes a map runs with: its own, or `map_size` points each when given; the probability map's
// at most 25 x 25 unless --map-size.
std::pair<MapAxis, MapAxis> run_axes(const MapSpec& spec, int map_size, bool probability) {
  MapAxis x = spec.x, y = spec.y;
  if (map_size > 0) x.points = y.points = map_size;
  if (probability && map_size <= 0) {
    x.points = std::min(x.points, 25);
    y.points = std::min(y.points, 25);
  }
  return {x, y};
}

}  // namespace

void check_map_work(const ShimmyConfig& config, int map_size, const TireInput* tire) {
  long eigen = 0, landings = 0, draws = 0;
  const long models = static_cast<long>(config.models.size());
  const bool coupled = std::find(config.models.begin(), config.models.end(),
                                 ContactModel::coupled) != config.models.end();
  for (const MapSpec& spec : config.maps) {
    const auto [x, y] = run_axes(spec, map_size, false);
    const long cells = static_cast<long>(x.points) * y.points;
    (spec.method == "simulation" ? landings : eigen) += cells * models;
    if (tire && coupled && spec.method != "simulation") {
      const auto [px, py] = run_axes(spec, map_size, true);
      draws +=
          static_cast<long>(px.points) * py.points * static_cast<long>(tire->draws.draws.size());
    }
  }
  const std::string what = map_size > 0 ? "--map-size" : "maps";
  const std::string value =
      map_size > 0 ? std::to_string(map_size) : std::to_string(config.maps.size()) + " maps";
  const std::string shape =
      " (" + std::to_string(config.maps.size()) + " maps x " + std::to_string(models) + " models)";
  if (eigen > kMostEigenCells)
    throw InvalidArgument(what, value,
                          "the maps would take " + std::to_string(eigen) + " eigenvalue cells" +
                              shape + "; at most " + std::to_string(kMostEigenCells) +
                              " in one run (about a minute on two cores): fewer points or maps");
  if (landings > kMostLandingCells)
    throw InvalidArgument(what, value,
                          "the simulated maps would take " + std::to_string(landings) +
                              " landings" + shape + "; at most " +
                              std::to_string(kMostLandingCells) +
                              " in one run (about a minute on two cores): fewer points or maps");
  if (draws > kMostDrawCells)
    throw InvalidArgument(what, value,
                          "the probability maps would take " + std::to_string(draws) +
                              " linearisations (cells x --draws); at most " +
                              std::to_string(kMostDrawCells) +
                              " in one run: fewer points, maps or --draws");
}

std::vector<ComputedMap> compute_maps(const ShimmyConfig& config, int map_size, unsigned threads,
                                      const TireInput* tire, const Progress& progress) {
  std::vector<ComputedMap> out;
  for (const MapSpec& spec : config.maps) {
    const auto [x, y] = run_axes(spec, map_size, false);
    for (ContactModel cm : config.models) {
      const GearModel model = gear_model(config, cm, tire);
      const std::string label = std::string(to_string(cm)) + " " + short_name(x.parameter) + " x " +
                                short_name(y.parameter);
      const auto bar = [&](int done, int total) { progress(label, done, total); };
      ComputedMap m{spec.method == "simulation"
                        ? stability_map(model, x, y, config.solver, config.criterion, threads, bar)
                        : linear_stability_map(model, x, y, spec.phase, threads, bar),
                    std::nullopt};
      GearConfig probe = config.gear;
      m.operating_x = *gear_parameter(probe, x.parameter);
      m.operating_y = *gear_parameter(probe, y.parameter);
      if (tire && cm == ContactModel::coupled && spec.method != "simulation") {
        // A draw per cell costs a linearisation: at most 25 x 25 cells unless --map-size.
        const auto [px, py] = run_axes(spec, map_size, true);
        m.probability = probability_map(
            make_gear_model(config.gear, cm), px, py, spec.phase, tire->draws.draws, threads,
            [&](int done, int total) { progress("P(shimmy) " + label, done, total); });
      }
      out.push_back(std::move(m));
    }
  }
  return out;
}

}  // namespace contensou::app
