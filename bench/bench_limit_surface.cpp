// Cost of the set-valued law (issue 15): projection of a trial wrench onto the exact limit
// surface of the seed tire (kx = 0.14) and onto its fitted ellipsoid, in the metric of a
// Moreau-Jean step (300 kg body, h = 1 ms), for a trial inside (stick), just outside and far
// outside; and the pieces (D with gradient and Hessian, the gauge).
#include <benchmark/benchmark.h>

#include "contensou/friction/limit_surface.hpp"

using namespace contensou;
using Vec3 = Eigen::Vector3d;

namespace {

struct Setup {
  LimitSurface exact;
  EllipsoidalLimitSurface ellipsoid;
  Eigen::Matrix3d metric;
  Vec3 inside, near, far;
  Setup() {
    ContactPatch p = seed_tire_patch();
    p.profile.keep_negative = true;
    p.profile.kx = 0.14;
    exact = make_limit_surface(p);
    ellipsoid = fit_ellipsoid(exact);
    const double R = exact.radius, h = 1e-3, m = 300.0, J = m * R * R / 2;
    metric = Vec3(h / m, h / m, h / J).asDiagonal();
    const Vec3 b = surface_point(exact, Vec3(0.6, -0.3, 2.0 / R));
    inside = 0.5 * b;
    near = 1.05 * b;
    far = 20.0 * b;
  }
};
const Setup& setup() {
  static const Setup s;
  return s;
}

template <class S>
void run_projection(benchmark::State& state, const S& surface, const Vec3& trial) {
  const Setup& s = setup();
  int it = 0;
  for (auto _ : state) {
    const Projection p = project(surface, trial, s.metric);
    it = p.iterations;
    benchmark::DoNotOptimize(p.wrench.data());
  }
  state.counters["newton_iterations"] = it;
}

void BM_ProjectExact(benchmark::State& state) {
  const Setup& s = setup();
  const Vec3 t[] = {s.inside, s.near, s.far};
  run_projection(state, s.exact, t[state.range(0)]);
}
void BM_ProjectEllipsoid(benchmark::State& state) {
  const Setup& s = setup();
  const Vec3 t[] = {s.inside, s.near, s.far};
  run_projection(state, s.ellipsoid, t[state.range(0)]);
}
void BM_DissipationWithDerivatives(benchmark::State& state) {
  const Setup& s = setup();
  for (auto _ : state) {
    const Dissipation d = dissipation_with_derivatives(s.exact, Vec3(0.6, -0.3, 20.0));
    benchmark::DoNotOptimize(d.hessian.data());
  }
}
void BM_GaugeExact(benchmark::State& state) {
  const Setup& s = setup();
  for (auto _ : state) {
    const Gauge g = gauge(s.exact, s.near);
    benchmark::DoNotOptimize(g.value);
  }
}

}  // namespace

// Argument: 0 = inside (stick), 1 = 5 % outside, 2 = 20 times outside.
BENCHMARK(BM_ProjectExact)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ProjectEllipsoid)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DissipationWithDerivatives)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_GaugeExact)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
