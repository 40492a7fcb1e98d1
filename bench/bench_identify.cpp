// Time to fit the fractional law to a 120-value set (40 points x Fx, Fy, Mz), against the
// same fit with the noise scales given (a single Ceres solve, no scale iteration) as the
// in-process baseline.
#include <benchmark/benchmark.h>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
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

BENCHMARK_CAPTURE(BM_Fit, estimated_noise_scales, false)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ClosedLoop)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Fit, given_noise_scales_baseline, true)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
