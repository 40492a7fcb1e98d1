// Time to fit the fractional law to a 120-value set (40 points x Fx, Fy, Mz), against the
// same fit with the noise scales given (a single Ceres solve, no scale iteration) as the
// in-process baseline; the closed loop on small sets and on 10^3 and 10^4 rows.
#include <benchmark/benchmark.h>

#include <algorithm>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/identify.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

// 40 points of the seed tire (kx = 0.14), psi = 0.01 ... 100, 1 % noise, from `model`.
template <class Model>
MeasuredData seed_diagrams(const Model& model) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = 40;
  s.noise_level = 0.01;
  return simulate_diagrams(model, s);
}

ContactPatch rolling_seed_tire() {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = 0.14;
  return p;
}

void BM_Fit(benchmark::State& state, bool given_scales) {
  const MeasuredData d = seed_diagrams(fractional_law_from_patch(rolling_seed_tire()));
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.normal_load_n = 4535;
  if (given_scales) o.noise_scale = std::array<double, 3>{13.6, 0.95, 0.72};
  for (auto _ : state) benchmark::DoNotOptimize(fit_fractional_law(d, o));
  state.counters["values"] = d.count(0) + d.count(1) + d.count(2);
}

}  // namespace

// The whole closed loop on a 120-value set of the seed tire from the exact integrals (40 points,
// 1 % noise) with the profile given, all candidates scored: the base fit is the baseline.
void BM_ClosedLoop(benchmark::State& state) {
  const MeasuredData d = seed_diagrams(make_exact_model(rolling_seed_tire()));
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.profile = seed_tire_profile();
  o.normal_load_n = 4535;
  for (auto _ : state) benchmark::DoNotOptimize(close_the_loop(d, o));
}

// The closed loop on what a rig measures on a tabulated tire (issue 11): a 101-point table
// with a kink near the rim, friction falling with slip speed (Stribeck, inside the exact
// integrals: f = 0.3 at rest to 0.21, w_s = 5 m/s), three sweeps of 36 points (sliding along
// x, y and at 45 degrees, u = 3 m/s) plus pure spin both ways and pure sliding along x and y,
// 1 % noise: 112 points. Counters: whether the loop named speed_dependence and shape, and
// the largest final channel rms over its noise scale.
void BM_ClosedLoopTableWithSpeedLaw(benchmark::State& state, bool speed_inside) {
  std::vector<double> rho, pv;
  for (int i = 0; i <= 100; ++i) {
    const double r = i / 100.0;
    rho.push_back(r);
    pv.push_back(r < 0.9 ? 1.0 + 0.4 * r * r - 0.9 * r * r * r * r : 0.7439 - 4.0 * (r - 0.9));
  }
  ContactPatch p = rolling_seed_tire();
  p.profile = tabulated_profile(rho, pv);
  p.profile.kx = 0.14;
  p.slip_speed_friction = SlipSpeedFriction<double>{0.3, 0.21, 5.0, 1.0};
  const ExactModel<double> model = make_exact_model(p);
  MeasuredData d;
  DiagramSpec s;
  s.radius_m = p.radius_m;
  s.points = 36;
  s.spin_speed_mps = 3.0;
  s.noise_level = 0.01;
  for (int sweep = 0; sweep < 3; ++sweep) {
    s.direction_rad = sweep == 2 ? 0.785398 : sweep * 1.570796;
    s.seed = 11 + static_cast<std::uint64_t>(sweep);
    for (const MeasuredPoint& q : simulate_diagrams(model, s).points) d.points.push_back(q);
  }
  const double u = 3.0 / p.radius_m;
  for (const Kinematics<double>& k :
       {Kinematics<double>{0.0, 0.0, u}, {0.0, 0.0, -u}, {3.0, 0.0, 0.0}, {0.0, 3.0, 0.0}}) {
    MeasuredPoint q;
    q.kinematics = k;
    const Resultants<double> r = exact_resultants(model, k, {1e-10}).resultants;
    // 1 % of the sweeps' channel peaks as noise, a fixed draw.
    q.force = {r.Fx + 0.7 * 0.01 * 1300.0, r.Fy - 0.4 * 0.01 * 1300.0, r.Mz + 0.2 * 0.01 * 70.0};
    d.points.push_back(q);
  }
  IdentificationOptions o;
  o.radius_m = p.radius_m;
  o.profile = p.profile;
  ClosedLoopOptions loop;
  loop.speed_inside_integrals = speed_inside;
  ClosedLoopReport r;
  for (auto _ : state) r = close_the_loop(d, o, loop);
  const auto& acc = r.accepted_effects;
  const bool named = std::find(acc.begin(), acc.end(), "speed_dependence") != acc.end() &&
                     std::find(acc.begin(), acc.end(), "shape") != acc.end();
  double worst = 0.0;
  for (const ChannelDiagnostics& c : r.final_fit.channels)
    worst = std::max(worst, c.rms / c.noise_scale);
  state.counters["points"] = static_cast<double>(d.points.size());
  state.counters["named_speed_and_shape"] = named ? 1.0 : 0.0;
  state.counters["effects"] = static_cast<double>(acc.size());
  state.counters["white"] = r.final_fit.residual_white ? 1.0 : 0.0;
  state.counters["rms/noise"] = worst;
  // The injected law: f_k / f_s = 0.7 (beta = 0.3), w_s = 5 m/s.
  for (const ParameterEstimate& e : r.final_fit.parameters) {
    if (e.name == "speed_drop") state.counters["beta"] = e.value;
    if (e.name == "speed_ref_mps") state.counters["w_s"] = e.value;
  }
}

// identify() on a rig's file as contensou-identify runs it: the seed tire from the exact
// integrals (kx = 0.14) at three loads (3, 4.5, 6 kN, pressure in proportion) in two sliding
// directions, 1 % additive noise, psi = 0.01 ... 100. Arguments: rows, the profile given (1) or
// identified (0), the selection sample (IdentifyOptions::selection_rows; 0: every row, the
// baseline the sample is compared with). Counters: rows, effects accepted, rows selected on.
// Timed once.
void BM_IdentifyRows(benchmark::State& state) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = static_cast<int>(state.range(0) / 6);
  s.noise_level = 0.01;
  MeasuredData d;
  for (double load : {3000.0, 4500.0, 6000.0})
    for (double direction : {0.0, 1.5707963267948966}) {
      ContactPatch patch = rolling_seed_tire();
      patch.reference_pressure_pa *= load / 4535.02;
      s.direction_rad = direction;
      s.seed = static_cast<std::uint64_t>(load + 10.0 * direction);
      for (MeasuredPoint p : simulate_diagrams(make_exact_model(patch), s).points) {
        p.normal_load = load;
        p.line = static_cast<int>(d.points.size()) + 2;
        d.points.push_back(p);
      }
    }
  IdentifyOptions o;
  o.fit.radius_m = 0.087;
  if (state.range(1) != 0) o.fit.profile = seed_tire_profile();
  o.loop = ClosedLoopOptions{};
  o.selection_rows = static_cast<std::size_t>(state.range(2));
  Identification r;
  for (auto _ : state) r = identify(d, o);
  state.counters["rows"] = static_cast<double>(d.points.size());
  state.counters["effects"] = static_cast<double>(r.loop->accepted_effects.size());
  state.counters["selected_on"] =
      static_cast<double>(r.loop->selection_rows ? r.loop->selection_rows : d.points.size());
}

BENCHMARK_CAPTURE(BM_Fit, estimated_noise_scales, false)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClosedLoop)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ClosedLoopTableWithSpeedLaw, local_speed, true)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_ClosedLoopTableWithSpeedLaw, effective_speed, false)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Fit, given_noise_scales_baseline, true)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IdentifyRows)
    ->Args({10000, 1, 0})  // the baseline: every row through the loop
    ->Args({10000, 1, 4000})
    ->Args({100000, 1, 4000})
    ->Args({10000, 0, 4000})
    ->Args({100000, 0, 4000})
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_MAIN();
