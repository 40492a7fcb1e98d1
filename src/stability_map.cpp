#include "contensou/stability_map.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <thread>
#include <utility>

#include "contensou/error.hpp"

namespace contensou {

namespace {

template <class F>
void for_each_parameter(GearConfig& c, F&& f) {
  GearStructure& g = c.structure;
  f("structure.lateral_mass_kg", g.lateral_mass_kg);
  f("structure.lateral_stiffness_n_per_m", g.lateral_stiffness_n_per_m);
  f("structure.lateral_damping_ns_per_m", g.lateral_damping_ns_per_m);
  f("structure.torsional_inertia_kgm2", g.torsional_inertia_kgm2);
  f("structure.torsional_stiffness_nm_per_rad", g.torsional_stiffness_nm_per_rad);
  f("structure.torsional_damping_nms_per_rad", g.torsional_damping_nms_per_rad);
  f("structure.trail_m", g.trail_m);
  f("structure.offset_m", g.offset_m);
  f("structure.wheel_radius_m", g.wheel_radius_m);
  f("structure.wheel_inertia_kgm2", g.wheel_inertia_kgm2);
  SlidingTire& t = c.tire;
  f("tire.inflation_pressure_pa", t.inflation_pressure_pa);
  f("tire.rolling_shift", t.rolling_shift);
  f("tire.friction.static_coefficient", t.friction.static_coefficient);
  f("tire.friction.kinetic_coefficient", t.friction.kinetic_coefficient);
  f("tire.friction.reference_speed", t.friction.reference_speed);
  f("tire.friction.exponent", t.friction.exponent);
  f("tire.regularization_speed", t.regularization_speed);
  RollingTire& r = c.rolling;
  f("rolling.relaxation_length_m", r.relaxation_length_m);
  f("rolling.cornering_coefficient", r.cornering_coefficient);
  f("rolling.aligning_coefficient_m", r.aligning_coefficient_m);
  f("rolling.tread_moment_nm2_per_rad", r.tread_moment_nm2_per_rad);
  f("rolling.longitudinal_slip_coefficient", r.longitudinal_slip_coefficient);
  LandingScenario& s = c.scenario;
  f("scenario.forward_speed_mps", s.forward_speed_mps);
  f("scenario.drift_speed_mps", s.drift_speed_mps);
  f("scenario.static_load_n", s.static_load_n);
  f("scenario.touchdown_time_s", s.touchdown_time_s);
  f("scenario.load_ramp_s", s.load_ramp_s);
  f("scenario.end_time_s", s.end_time_s);
  f("scenario.initial_torsion_rad", s.initial_torsion_rad);
  f("scenario.initial_lateral_m", s.initial_lateral_m);
  f("scenario.rolling_slip", s.rolling_slip);
  f("scenario.sliding_slip", s.sliding_slip);
  f("scenario.brake_on_s", s.brake_on_s);
  f("scenario.brake_off_s", s.brake_off_s);
  f("scenario.brake_max_torque_nm", s.brake_max_torque_nm);
  f("scenario.brake_target_slip", s.brake_target_slip);
  f("scenario.brake_slip_band", s.brake_slip_band);
  f("scenario.window_start_s", s.window_start_s);
  f("scenario.window_end_s", s.window_end_s);
}

}  // namespace

double* gear_parameter(GearConfig& config, std::string_view name) {
  double* found = nullptr;
  for_each_parameter(config, [&](std::string_view n, double& v) {
    if (n == name) found = &v;
  });
  return found;
}

std::vector<std::string> gear_parameter_names() {
  GearConfig c;
  std::vector<std::string> names;
  for_each_parameter(c, [&](std::string_view n, double&) { names.emplace_back(n); });
  return names;
}

StabilityMap stability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                           const SolverOptions& solver, const ShimmyCriterion& criterion,
                           unsigned threads, const std::function<void(int, int)>& progress) {
  for (const MapAxis* a : {&x, &y}) {
    GearConfig probe = base.config;
    if (!gear_parameter(probe, a->parameter))
      throw InvalidArgument("map parameter", a->parameter, "is not a gear parameter");
    if (a->points < 1 || a->points > 10000)
      throw InvalidArgument("map points", std::to_string(a->points), "must lie in 1..10000");
    detail::require_finite("map from", a->from);
    detail::require_finite("map to", a->to);
  }
  StabilityMap map{x, y, base.contact, {}};
  const int total = x.points * y.points;
  map.cells.resize(static_cast<std::size_t>(total));
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  std::atomic<int> next{0}, done{0};
  SolverOptions quiet = solver;
  quiet.record = false;
  auto work = [&] {
    for (int k = next++; k < total; k = next++) {
      MapCell& cell = map.cells[static_cast<std::size_t>(k)];
      cell.x = x.value(k % x.points);
      cell.y = y.value(k / x.points);
      GearModel model = base;  // shares the exact model, if any (read-only)
      *gear_parameter(model.config, x.parameter) = cell.x;
      *gear_parameter(model.config, y.parameter) = cell.y;
      try {
        validate(model.config);
        const LandingRun run = simulate_landing(model, quiet, criterion);
        cell.growth_rate_per_s = run.metrics.torsion.growth_rate_per_s;
        cell.frequency_hz = run.metrics.torsion.frequency_hz;
        cell.last_amplitude_rad = run.metrics.torsion.last_amplitude;
        cell.shimmy = run.metrics.shimmy;
        cell.valid = run.metrics.torsion.valid();
      } catch (const std::exception& e) {
        cell.error = e.what();
      }
      ++done;
    }
  };
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < threads; ++i) pool.emplace_back(work);
  if (progress) {
    // The calling thread reports progress and joins the work when the pool is busy.
    std::thread last(work);
    while (done.load() < total) {
      progress(done.load(), total);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    last.join();
    progress(total, total);
  } else {
    work();
  }
  for (std::thread& t : pool) t.join();
  return map;
}

}  // namespace contensou
