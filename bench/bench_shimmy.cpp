// The shimmy demo's speed: a one-second landing of each contact model (wall time and the
// real-time factor: simulated seconds per second), with the structured Jacobian and with
// CVODE's difference quotients, with the default Adams-Moulton integrator and with BDF (the
// integrator before), and a 50 x 50 stability map on 2 threads against the same map on 1 thread
// as the in-process baseline (the ratio is the speed-up). Each landing's counters say where its
// time goes: steps, right-hand sides, Jacobians, LU factorisations, and the time its right-hand
// sides and Jacobians take by themselves (rhs_ms, jac_ms; the rest is CVODE's). The coupled
// landing at relative tolerances 1e-5 to 1e-9 says what a looser tolerance buys and costs in
// accuracy (its growth and frequency against the landing at 1e-10).
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "contensou/gear/stability_map.hpp"

using namespace contensou;

namespace {

void BM_Landing(benchmark::State& state, ContactModel contact, bool exact, bool analytic,
                Integrator method = Integrator::adams) {
  GearConfig c;
  c.tire.exact_integrals = exact;
  const GearModel m = make_gear_model(c, contact);
  SolverOptions o;
  o.record = false;
  o.analytic_jacobian = analytic;
  o.method = method;
  LandingRun run;
  for (auto _ : state) run = simulate_landing(m, o);
  state.counters["steps"] = static_cast<double>(run.steps);
  state.counters["rhs"] = static_cast<double>(run.rhs_evaluations);
  state.counters["jacobians"] = static_cast<double>(run.jacobian_evaluations);
  state.counters["newton"] = static_cast<double>(run.newton_iterations);
  state.counters["lu"] = static_cast<double>(run.linear_setups);
  state.counters["err_fails"] = static_cast<double>(run.error_test_failures);
  state.counters["realtime_factor"] = benchmark::Counter(
      c.scenario.end_time_s * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  // Where the time goes: the model's share, as many right-hand sides and Jacobians as the landing
  // took, timed at the braked slide's quasi-steady state (the rest is CVODE's own step, error
  // test, interpolation, root checks and LU).
  const QuasiSteadyState q = quasi_steady_state(m, StabilityPhase::braked_slide);
  const auto start = std::chrono::steady_clock::now();
  for (long k = 0; k < run.rhs_evaluations; ++k)
    benchmark::DoNotOptimize(gear_rhs(m, q.mode, q.t, q.x));
  const auto middle = std::chrono::steady_clock::now();
  for (long k = 0; analytic && k < run.jacobian_evaluations; ++k)
    benchmark::DoNotOptimize(gear_jacobian(m, q.mode, q.t, q.x));
  const auto end = std::chrono::steady_clock::now();
  state.counters["rhs_ms"] = std::chrono::duration<double, std::milli>(middle - start).count();
  state.counters["jac_ms"] = std::chrono::duration<double, std::milli>(end - middle).count();
}

// The default coupled landing at relative tolerance 10^-range(0): its time, steps, and how far
// its window's fitted growth rate and frequency lie from the same landing at 1e-10 (the
// accuracy the time buys; a looser tolerance is faster only at the accuracy it reports).
void BM_LandingTolerance(benchmark::State& state) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  SolverOptions o;
  o.record = false;
  o.relative_tolerance = 1e-10;
  const OscillationEstimate reference = simulate_landing(m, o).metrics.torsion;
  o.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  LandingRun run;
  for (auto _ : state) run = simulate_landing(m, o);
  const OscillationEstimate& e = run.metrics.torsion;
  state.counters["steps"] = static_cast<double>(run.steps);
  state.counters["growth_diff_per_s"] = std::abs(e.growth_rate_per_s - reference.growth_rate_per_s);
  state.counters["freq_rel_diff"] = std::abs(e.frequency_hz / reference.frequency_hz - 1.0);
}

void BM_Map(benchmark::State& state) {
  const unsigned threads = static_cast<unsigned>(state.range(0));
  const int n = static_cast<int>(state.range(1));
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  const MapAxis x{"scenario.forward_speed_mps", 30.0, 90.0, n};
  const MapAxis y{"structure.torsional_damping_nms_per_rad", 0.0, 400.0, n};
  for (auto _ : state) benchmark::DoNotOptimize(stability_map(m, x, y, {}, {}, threads));
  state.counters["cells"] = n * n;
  state.counters["threads"] = threads;
}

// The same 50 x 50 grid judged by eigenvalues (braked slide), one thread.
void BM_LinearMap(benchmark::State& state) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  const MapAxis x{"scenario.forward_speed_mps", 30.0, 90.0, 50};
  const MapAxis y{"structure.offset_m", 0.0, 0.5, 50};
  for (auto _ : state)
    benchmark::DoNotOptimize(linear_stability_map(m, x, y, StabilityPhase::braked_slide, 1));
  state.counters["cells"] = 2500;
}

// Where a landing's time goes: one right-hand side and one structured Jacobian at the braked
// slide's quasi-steady state (the landing's counters say how many of each it takes; the rest is
// CVODE's own step, error test and LU).
void BM_Rhs(benchmark::State& state, ContactModel contact) {
  const GearModel m = make_gear_model(GearConfig{}, contact);
  const QuasiSteadyState q = quasi_steady_state(m, StabilityPhase::braked_slide);
  for (auto _ : state) benchmark::DoNotOptimize(gear_rhs(m, q.mode, q.t, q.x));
}

void BM_Jacobian(benchmark::State& state, ContactModel contact) {
  const GearModel m = make_gear_model(GearConfig{}, contact);
  const QuasiSteadyState q = quasi_steady_state(m, StabilityPhase::braked_slide);
  for (auto _ : state) benchmark::DoNotOptimize(gear_jacobian(m, q.mode, q.t, q.x));
}

}  // namespace

BENCHMARK_CAPTURE(BM_Rhs, coupled, ContactModel::coupled)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Rhs, decoupled, ContactModel::decoupled)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Rhs, von_schlippe, ContactModel::von_schlippe)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Jacobian, coupled, ContactModel::coupled)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Jacobian, von_schlippe, ContactModel::von_schlippe)
    ->Unit(benchmark::kMicrosecond);

// Each landing with the structured Jacobian (gear_jacobian) and with CVODE's difference
// quotients ("_dq"), in the same binary; "_bdf": CVODE's BDF instead of Adams-Moulton.
BENCHMARK_CAPTURE(BM_Landing, coupled, ContactModel::coupled, false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, coupled_dq, ContactModel::coupled, false, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, coupled_bdf, ContactModel::coupled, false, true, Integrator::bdf)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, decoupled, ContactModel::decoupled, false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, decoupled_dq, ContactModel::decoupled, false, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, von_schlippe, ContactModel::von_schlippe, false, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, von_schlippe_dq, ContactModel::von_schlippe, false, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, coupled_exact_integrals, ContactModel::coupled, true, true)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, coupled_exact_integrals_dq, ContactModel::coupled, true, false)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Landing, coupled_exact_integrals_bdf, ContactModel::coupled, true, true,
                  Integrator::bdf)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LandingTolerance)->DenseRange(5, 9)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LinearMap)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Map)
    ->Args({2, 50})
    ->Args({1, 50})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();
BENCHMARK_MAIN();
