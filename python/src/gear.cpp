// Gear: a thin layer over the shimmy app's JSON configuration (apps/shimmy/config.cpp and its key
// table config_keys.cpp, compiled into this module) and the gear module's public functions:
// simulate_landing and stability_map. Configurations cross the boundary as JSON text, so that this
// file knows no gear parameter by name and the Python side can ship a cell of a map to a Dask
// worker as plain data.
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include <tuple>

#include "common.hpp"
#include "config.hpp"
#include "config_keys.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/gear.hpp"

namespace contensou::python {
namespace {

using namespace nb::literals;
using Axis = std::tuple<std::string, double, double, int>;  // parameter, from, to, points
using Cell = std::tuple<double, double, double, double, double, bool, bool, std::string>;

app::ShimmyConfig parse(const std::string& text) {
  return app::parse_shimmy_config(text, "<configuration>");
}

MapAxis axis_of(const Axis& a) {
  return MapAxis{std::get<0>(a), std::get<1>(a), std::get<2>(a), std::get<3>(a)};
}

Cell cell_of(const MapCell& c) {
  return {c.x,     c.y,    c.growth_rate_per_s, c.frequency_hz, c.last_amplitude_rad, c.shimmy,
          c.valid, c.error};
}

nb::dict simulate(const std::string& text, const std::string& model, bool record) {
  const app::ShimmyConfig c = parse(text);
  const ContactModel cm = contact_model_from_string(model);
  SolverOptions solver = c.solver;
  solver.record = record;
  const LandingRun r = run_interruptible([&](const StopRequest& stop) {
    SolverOptions with_stop = solver;
    with_stop.stop = stop;
    return simulate_landing(make_gear_model(c.gear, cm), with_stop, c.criterion);
  });
  const std::size_t n = r.samples.size(), w = app::history_columns().size();
  std::vector<double> h;
  h.reserve(n * w);
  for (const LandingSample& s : r.samples) {
    const std::vector<double> row = app::history_row(s, c.gear.structure);
    h.insert(h.end(), row.begin(), row.end());
  }
  nb::dict d;
  d["columns"] = app::history_columns();
  d["history"] = to_numpy(std::move(h), {n, w});
  nb::list events;
  for (const LandingEvent& e : r.events) events.append(nb::make_tuple(e.t, e.what));
  d["events"] = events;
  const OscillationEstimate& o = r.metrics.torsion;
  nb::dict metrics;
  metrics["shimmy"] = r.metrics.shimmy;
  metrics["valid"] = o.valid();
  metrics["frequency_hz"] = o.frequency_hz;
  metrics["growth_rate_per_s"] = o.growth_rate_per_s;
  metrics["first_amplitude_rad"] = o.first_amplitude;
  metrics["last_amplitude_rad"] = o.last_amplitude;
  metrics["half_cycles"] = o.half_cycles;
  metrics["peak_torsion_rad"] = r.metrics.peak_torsion_rad;
  metrics["peak_lateral_m"] = r.metrics.peak_lateral_m;
  metrics["spin_up_s"] = r.spin_up_s ? nb::cast(*r.spin_up_s) : nb::none();
  metrics["window_s"] = nb::make_tuple(r.window_start_s, r.window_end_s);
  metrics["steps"] = r.steps;
  metrics["wall_s"] = r.wall_s;
  d["metrics"] = metrics;
  d["contact"] = std::string(to_string(r.contact));
  return d;
}

// Cell (i, j) of the map over x and y: the C++ stability_map on the one-cell grid at
// (x.value(i), y.value(j)), so the cell is computed exactly as in a whole map.
Cell map_cell(const std::string& text, const std::string& model, const Axis& xa, const Axis& ya,
              int i, int j) {
  const app::ShimmyConfig c = parse(text);
  const MapAxis x = axis_of(xa), y = axis_of(ya);
  if (i < 0 || i >= x.points || j < 0 || j >= y.points)
    throw std::invalid_argument("cell (" + std::to_string(i) + ", " + std::to_string(j) +
                                ") is outside the " + std::to_string(x.points) + " x " +
                                std::to_string(y.points) + " map");
  const MapAxis x1{x.parameter, x.value(i), x.value(i), 1};
  const MapAxis y1{y.parameter, y.value(j), y.value(j), 1};
  return run_interruptible([&](const StopRequest& stop) {
    const GearModel base = make_gear_model(c.gear, contact_model_from_string(model));
    SolverOptions solver = c.solver;
    solver.stop = stop;
    const StabilityMap m = stability_map(base, x1, y1, solver, c.criterion, 1);
    return cell_of(m.cells.at(0));
  });
}

// The whole map by the C++ stability_map on `threads` threads (row-major cells).
std::vector<Cell> map_cpp(const std::string& text, const std::string& model, const Axis& xa,
                          const Axis& ya, unsigned threads) {
  const app::ShimmyConfig c = parse(text);
  return run_interruptible([&](const StopRequest& stop) {
    const GearModel base = make_gear_model(c.gear, contact_model_from_string(model));
    SolverOptions solver = c.solver;
    solver.stop = stop;
    const StabilityMap m =
        stability_map(base, axis_of(xa), axis_of(ya), solver, c.criterion, threads);
    std::vector<Cell> out;
    for (const MapCell& cell : m.cells) out.push_back(cell_of(cell));
    return out;
  });
}

// One row of a bifurcation sweep: direction, value, state, amplitude [rad], torque link [N m],
// trend [1/s], frequency [Hz], eigenvalue growth [1/s] and frequency [Hz], onset [s], run [s],
// valid, error.
using SweepRow = std::tuple<std::string, double, std::string, double, double, double, double,
                            double, double, double, double, bool, std::string>;

// The braked slide's bifurcation sweep of one model over one axis (contensou/gear/
// bifurcation.hpp), as contensou-shimmy --bifurcation runs it: up rows, then down rows, each in
// increasing parameter order; the linear boundary (NaN if none) last.
std::tuple<std::vector<SweepRow>, double> sweep(const std::string& text, const std::string& model,
                                                const Axis& a, unsigned threads) {
  const app::ShimmyConfig c = parse(text);
  return run_interruptible([&](const StopRequest& stop) {
    SweepOptions o;
    o.relative_tolerance = c.solver.relative_tolerance;
    o.output_interval_s = c.solver.output_interval_s;
    o.amplitude_threshold_rad = c.criterion.amplitude_threshold_rad;
    o.stop = stop;
    const GearModel base = make_gear_model(c.gear, contact_model_from_string(model));
    const BifurcationSweep s = bifurcation_sweeps({base}, {axis_of(a)}, o, threads, {}).front();
    std::vector<SweepRow> rows;
    for (const auto& [name, points] : {std::pair{"up", &s.up}, std::pair{"down", &s.down}})
      for (const SweepPoint& p : *points)
        rows.emplace_back(name, p.value, to_string(p.state), p.amplitude_rad, p.torque_link_nm,
                          p.trend_per_s, p.frequency_hz, p.eigen_growth_per_s, p.eigen_frequency_hz,
                          p.onset_s, p.run_s, p.valid, p.error);
    return std::tuple{rows, s.linear_boundary};
  });
}

}  // namespace

void bind_gear(nb::module_& m) {
  m.def(
      "_default_config",
      [] {
        static const app::ShimmyConfig defaults;  // a named object: GCC 12 at -O3 warns
        return app::to_json(defaults).dump();     // (maybe-uninitialized) on a temporary
      },
      "contensou-shimmy --print-config, as compact JSON text");
  m.def(
      "_normalise_config",
      [](const std::string& text, const std::string& name) {
        return app::to_json(app::parse_shimmy_config(text, name)).dump();
      },
      "text"_a, "name"_a = "<configuration>",
      "reads a configuration as contensou-shimmy --config does (defaults for keys left out, "
      "ValueError naming `name`, line, column and the bad key or value) and writes it back with "
      "every key");
  m.def("_gear_parameter_names", &gear_parameter_names);
  m.def(
      "_contact_model",
      [](const std::string& name) {
        return std::string(to_string(contact_model_from_string(name)));
      },
      "name"_a,
      "the contact model's name for a name contensou-shimmy takes (its aliases too); "
      "ValueError for another");
  m.def(
      "_config_keys",
      [] {
        app::ShimmyConfig defaults;
        nb::list keys;
        for (const app::ConfigKey& k : app::config_keys()) {
          nb::dict d;
          d["name"] = std::string(k.name);
          d["type"] = std::string(k.type);
          d["unit"] = std::string(k.unit);
          d["values"] = app::valid_values(k);
          d["default"] = app::write_key(k, defaults).dump();
          d["help"] = std::string(k.help);
          keys.append(d);
        }
        return keys;
      },
      "the configuration's keys (contensou-shimmy --print-keys): name, type, unit, valid values, "
      "default (JSON text) and help");
  m.def("_simulate_landing", &simulate, "config"_a, "model"_a, "record"_a);
  m.def("_map_cell", &map_cell, "config"_a, "model"_a, "x"_a, "y"_a, "i"_a, "j"_a);
  m.def("_stability_map_cpp", &map_cpp, "config"_a, "model"_a, "x"_a, "y"_a, "threads"_a);
  m.def("_bifurcation_sweep", &sweep, "config"_a, "model"_a, "axis"_a, "threads"_a);
}

}  // namespace contensou::python
