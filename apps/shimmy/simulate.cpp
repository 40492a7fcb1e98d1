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
  tire.distribution = read_tire_report(path);
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

Landings simulate_landings(const ShimmyConfig& config, const TireInput* tire) {
  require_landing(config.gear.scenario);
  Landings out;
  for (ContactModel cm : config.models) {
    const GearModel model = gear_model(config, cm, tire);
    out.runs.push_back(simulate_landing(model, config.solver, config.criterion));
    // Convergence: the same landing at a 100 times tighter tolerance.
    SolverOptions tight = config.solver;
    tight.relative_tolerance *= 1e-2;
    tight.record = false;
    out.tight.push_back(simulate_landing(model, tight, config.criterion));
    out.tight_relative_tolerance = tight.relative_tolerance;
  }
  return out;
}

std::vector<ComputedMap> compute_maps(const ShimmyConfig& config, int map_size, unsigned threads,
                                      const TireInput* tire, const Progress& progress) {
  std::vector<ComputedMap> out;
  for (const MapSpec& spec : config.maps) {
    MapAxis x = spec.x, y = spec.y;
    if (map_size > 0) x.points = y.points = map_size;
    for (ContactModel cm : config.models) {
      const GearModel model = gear_model(config, cm, tire);
      const std::string label = std::string(to_string(cm)) + " " + short_name(x.parameter) + " x " +
                                short_name(y.parameter);
      const auto bar = [&](int done, int total) { progress(label, done, total); };
      ComputedMap m{spec.method == "simulation"
                        ? stability_map(model, x, y, config.solver, config.criterion, threads, bar)
                        : linear_stability_map(model, x, y, spec.phase, threads, bar),
                    std::nullopt};
      if (tire && cm == ContactModel::coupled && spec.method != "simulation") {
        // A draw per cell costs a linearisation: at most 25 x 25 cells unless --map-size.
        MapAxis px = x, py = y;
        if (map_size <= 0) {
          px.points = std::min(px.points, 25);
          py.points = std::min(py.points, 25);
        }
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
