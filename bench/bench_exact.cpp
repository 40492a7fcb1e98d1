// Exact resultants against a general-purpose baseline, and the fractional law.
//
// Baseline: libcubature's hcubature (h-adaptive, genz-malik) on the plain (r, theta)
// parametrisation of the disk, at the same tolerance as contensou's: tol f N on the forces and
// tol f N R on the torque (its integrand carries Mz / R, so that one absolute tolerance tol f N
// with ERROR_INDIVIDUAL serves all three), capped at kBaselineMaxEval integrand evaluations.
// Both report the error actually achieved against a reference computed by contensou at 1e-13
// (relative to f N and f N R). After the run a table of times (medians with
// --benchmark_repetitions) and ratios is printed.
#include <benchmark/benchmark.h>
#include <cubature.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "contensou/contensou.hpp"

using namespace contensou;

namespace {

constexpr std::size_t kBaselineMaxEval = 2'000'000;

struct Regime {
  const char* name;
  double ratio;  // |v| / (|omega| R): < 1 centre inside, > 1 outside
};
constexpr Regime kRegimes[] = {{"inside", 0.5},        {"rim_inside", 0.999}, {"rim", 1.0},
                               {"rim_outside", 1.001}, {"outside", 2.0},      {"far", 100.0}};

ContactPatch seed_patch() {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = 0.14;
  return p;
}

Kinematics<double> kinematics(double ratio, double R) {
  const double w = 20.0, v = ratio * w * R;  // sliding at 35 degrees
  return {v * std::cos(0.61), v * std::sin(0.61), w};
}

struct Data {
  std::string name;
  ContactPatch patch;
  ExactModel<double> model;
  double fN = 0.0;
  explicit Data(std::string n, ContactPatch p)
      : name(std::move(n)),
        patch(std::move(p)),
        model(make_exact_model(patch)),
        fN(model.friction_scale * normal_load(patch)) {}
};

// An n-point table with a kink near the rim (a finite-element profile, p in units of p*).
ContactPatch table_patch(int n = 101) {
  std::vector<double> rho, p;
  for (int i = 0; i < n; ++i) {
    const double r = static_cast<double>(i) / (n - 1);
    rho.push_back(r);
    p.push_back(r < 0.9 ? 1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) : 0.7439 - 4.0 * (r - 0.9));
  }
  ContactPatch c = seed_patch();
  c.profile = tabulated_profile(rho, p);
  c.profile.kx = 0.14;
  return c;
}

// The profiles of the benchmark: the seed series (the baseline of the ratios), the same series
// clipped at zero, the 101-, 1,001- and 10,001-point tables, and the seed series and the
// 101-point table with f(w) inside the integrals.
const std::vector<Data>& variants() {
  static const std::vector<Data> v = [] {
    std::vector<Data> out;
    out.emplace_back("seed", seed_patch());
    ContactPatch clipped = seed_patch();
    clipped.profile.clip_negative = true;
    out.emplace_back("clipped", clipped);
    out.emplace_back("table101", table_patch());
    out.emplace_back("table1001", table_patch(1001));
    out.emplace_back("table10001", table_patch(10001));
    ContactPatch fw = seed_patch();
    fw.slip_speed_friction = SlipSpeedFriction<double>{0.3, 0.2, 5.0, 1.0};
    out.emplace_back("f(w)", fw);
    ContactPatch table_fw = table_patch();
    table_fw.slip_speed_friction = fw.slip_speed_friction;
    out.emplace_back("table101+f(w)", table_fw);
    return out;
  }();
  return v;
}
const Data& data() {
  return variants().front();
}

double achieved(const Resultants<double>& r, const Resultants<double>& ref, double fN, double R) {
  return std::max({std::abs(r.Fx - ref.Fx) / fN, std::abs(r.Fy - ref.Fy) / fN,
                   std::abs(r.Mz - ref.Mz) / (fN * R)});
}

void BM_Exact(benchmark::State& state, const Data* variant, Regime regime, double tol) {
  const Data& d = *variant;
  const Kinematics<double> k = kinematics(regime.ratio, d.patch.radius_m);
  const auto ref = exact_resultants(d.model, k, {1e-13}).resultants;
  ExactResult<double> r;
  for (auto _ : state) {
    r = exact_resultants(d.model, k, {tol});
    benchmark::DoNotOptimize(r);
  }
  state.counters["evals"] = r.evaluations;
  state.counters["achieved"] = achieved(r.resultants, ref, d.fN, d.patch.radius_m);
  state.counters["estimate"] =
      std::max({r.error.Fx / d.fN, r.error.Fy / d.fN, r.error.Mz / (d.fN * d.patch.radius_m)});
}

struct BaselineData {
  const ContactPatch* patch;
  Kinematics<double> k;
  std::size_t evals = 0;
};

int baseline_integrand(unsigned, const double* x, void* p, unsigned, double* f) {
  auto* b = static_cast<BaselineData*>(p);
  const ContactPatch& c = *b->patch;
  const double R = c.radius_m, r = x[0], th = x[1];
  const double px = r * std::cos(th), py = r * std::sin(th);
  const double sigma = c.reference_pressure_pa * shape_value(c.profile, r / R) *
                       (1 + c.profile.kx * px / R + c.profile.ky * py / R);
  const double cx = b->k.vx - b->k.omega * py, cy = b->k.vy + b->k.omega * px;
  const double w = std::hypot(cx, cy);
  ++b->evals;
  if (w == 0.0) {
    f[0] = f[1] = f[2] = 0.0;
    return 0;
  }
  const double tx = -c.friction * sigma * cx / w, ty = -c.friction * c.kappa * sigma * cy / w;
  f[0] = tx * r;
  f[1] = ty * r;
  f[2] = (px * ty - py * tx) * r / R;  // Mz / R: the forces' tolerance is the torque's / R
  return 0;
}

void BM_Baseline(benchmark::State& state, Regime regime, double tol) {
  const Data& d = data();
  const double R = d.patch.radius_m;
  BaselineData b{&d.patch, kinematics(regime.ratio, R)};
  const auto ref = exact_resultants(d.model, b.k, {1e-13}).resultants;
  const double lo[2] = {0.0, 0.0}, hi[2] = {R, 2 * std::numbers::pi};
  double val[3], err[3];
  for (auto _ : state) {
    b.evals = 0;
    hcubature(3, baseline_integrand, &b, 2, lo, hi, kBaselineMaxEval, tol * d.fN, 0.0,
              ERROR_INDIVIDUAL, val, err);
    benchmark::DoNotOptimize(val);
  }
  val[2] *= R;
  err[2] *= R;
  state.counters["evals"] = double(b.evals);
  state.counters["achieved"] = achieved({val[0], val[1], val[2]}, ref, d.fN, R);
  state.counters["estimate"] = std::max({err[0] / d.fN, err[1] / d.fN, err[2] / (d.fN * R)});
}

void BM_Fractional(benchmark::State& state) {
  const FractionalLaw<double> law = fractional_law_from_patch(data().patch);
  Kinematics<double> k{1.3, 0.4, 25.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(k);
    benchmark::DoNotOptimize(fractional_resultants(law, k));
  }
}

void BM_FractionalWithJacobian(benchmark::State& state) {
  const FractionalLaw<double> law = fractional_law_from_patch(data().patch);
  Kinematics<double> k{1.3, 0.4, 25.0};
  for (auto _ : state) {
    benchmark::DoNotOptimize(k);
    benchmark::DoNotOptimize(fractional_resultants_with_jacobian(law, k));
  }
}

// The exact law (exact_law.hpp) beside the fractional law, on the same 1024 kinematics (ratios
// |v|/(|omega| R) log-uniform over 1e-3 ... 1e3, a tenth within 1 % of the rim, every
// direction, |omega| R up to 60 m/s): per evaluation, with and without the Jacobian; and the
// build of each variant.
struct LawCase {
  std::string name;
  ContactPatch patch;
  ExactLaw law;
  double measured = 0.0;  // largest error on the points against the integrator at 1e-12
};

const std::vector<Kinematics<double>>& law_points() {
  static const std::vector<Kinematics<double>> points = [] {
    std::vector<Kinematics<double>> out;
    unsigned state = 12345u;
    auto uniform = [&state] {  // [-1, 1), a linear congruential generator: same on every platform
      state = 1664525u * state + 1013904223u;
      return 2.0 * (state >> 8) / 16777216.0 - 1.0;
    };
    for (int i = 0; i < 1024; ++i) {
      const double angle = std::numbers::pi * uniform();
      const double ratio = i % 10 == 0 ? std::exp(0.01 * uniform()) : std::exp(6.9 * uniform());
      const double w = 60.0 * (0.1 + 0.9 * std::abs(uniform())) / 0.087;
      const double v = ratio * w * 0.087;
      out.push_back({v * std::cos(angle), v * std::sin(angle), uniform() > 0 ? w : -w});
    }
    return out;
  }();
  return points;
}

std::vector<LawCase>& law_cases() {
  static std::vector<LawCase> cases = [] {
    const SlipSpeedFriction<double> falling{0.3, 0.2, 5.0, 1.0};
    std::vector<std::pair<std::string, ContactPatch>> specs;
    ContactPatch shifted = seed_patch();
    shifted.profile.ky = 0.05;
    specs.emplace_back("kappa=1+shift", shifted);
    ContactPatch ortho = shifted;
    ortho.kappa = 0.8;
    specs.emplace_back("kappa=0.8", ortho);
    ContactPatch fw = shifted;
    fw.slip_speed_friction = falling;
    specs.emplace_back("f(w)", fw);
    ContactPatch both = ortho;
    both.slip_speed_friction = falling;
    specs.emplace_back("kappa=0.8+f(w)", both);
    specs.emplace_back("table101", table_patch());
    std::vector<LawCase> out;
    for (auto& [name, patch] : specs) {
      const ExactModel<double> model = make_exact_model(patch);
      LawCase c{name, patch, make_exact_law(model), 0.0};
      const double fN = model.friction_scale * normal_load(patch), R = model.radius;
      for (std::size_t i = 0; i < law_points().size(); i += 8) {
        const Kinematics<double>& k = law_points()[i];
        const auto ref = exact_resultants(model, k, {1e-12}).resultants;
        c.measured = std::max(c.measured, achieved(exact_law_resultants(c.law, k), ref, fN, R));
      }
      out.push_back(std::move(c));
    }
    return out;
  }();
  return cases;
}

void BM_Law(benchmark::State& state, std::size_t which, bool jacobian) {
  const ExactLaw& law = law_cases()[which].law;
  const auto& points = law_points();
  std::size_t i = 0;
  for (auto _ : state) {
    const Kinematics<double>& k = points[i++ & 1023];
    if (jacobian)
      benchmark::DoNotOptimize(exact_law_resultants_with_jacobian(law, k));
    else
      benchmark::DoNotOptimize(exact_law_resultants(law, k));
  }
}

void BM_FractionalOnPoints(benchmark::State& state, bool jacobian) {
  const FractionalLaw<double> law = fractional_law_from_patch(law_cases().front().patch);
  const auto& points = law_points();
  std::size_t i = 0;
  for (auto _ : state) {
    const Kinematics<double>& k = points[i++ & 1023];
    if (jacobian)
      benchmark::DoNotOptimize(fractional_resultants_with_jacobian(law, k));
    else
      benchmark::DoNotOptimize(fractional_resultants(law, k));
  }
}

void BM_LawBuild(benchmark::State& state, std::size_t which) {
  const ExactModel<double> model = make_exact_model(law_cases()[which].patch);
  ExactLawOptions one_core;
  one_core.threads = 1;
  for (auto _ : state) benchmark::DoNotOptimize(make_exact_law(model, one_core));
}

// Builds that are too slow to sit beside the evaluation rows (no reference errors at 1e-12): the
// 101-point table with f(w) inside, at the law's default tolerance and at the identification's.
ContactPatch table_falling_patch() {
  ContactPatch p = table_patch();
  p.slip_speed_friction = SlipSpeedFriction<double>{0.3, 0.2, 5.0, 1.0};
  return p;
}

void BM_LawBuildTableFalling(benchmark::State& state, double tolerance) {
  const ExactModel<double> model = make_exact_model(table_falling_patch());
  ExactLawOptions one_core;
  one_core.threads = 1;
  one_core.tolerance = tolerance;
  double achieved_error = 0.0, bytes = 0.0;
  for (auto _ : state) {
    const ExactLaw law = make_exact_law(model, one_core);
    achieved_error = law.achieved;
    bytes = static_cast<double>(law.bytes());
  }
  state.counters["achieved"] = achieved_error;
  state.counters["KB"] = bytes / 1024.0;
}

// The build of a dense table's exact model and law (issue 22): make_exact_model for the kinked
// profile p = 1 - rho^2 + 0.3 max(rho - 0.6, 0) sampled at n even points in rho, n = 10^3, 10^4,
// 10^5, and make_exact_law of that model; the table after the run gives the ratios (10 for an
// O(n) build, 13 for O(n log n); the law's samples, O(log n) each, weigh more at 10^3).
ContactPatch dense_patch(int n) {
  std::vector<double> rho, p;
  for (int i = 0; i < n; ++i) {
    const double r = static_cast<double>(i) / (n - 1);
    rho.push_back(r);
    p.push_back(1.0 - r * r + 0.3 * std::max(r - 0.6, 0.0));
  }
  ContactPatch c = seed_patch();
  c.profile = tabulated_profile(rho, p);
  c.profile.kx = 0.14;
  return c;
}

void BM_DenseModelBuild(benchmark::State& state) {
  const ContactPatch patch = dense_patch(static_cast<int>(state.range(0)));
  double error = 0.0;
  for (auto _ : state) {
    const ExactModel<double> model = make_exact_model(patch);
    error = model.representation_error();
    benchmark::DoNotOptimize(model);
  }
  state.counters["representation_error"] = error;
}

// The exact law of the same tables (constant f, default tolerance, one core), the model built.
void BM_DenseLawBuild(benchmark::State& state) {
  const ExactModel<double> model = make_exact_model(dense_patch(static_cast<int>(state.range(0))));
  ExactLawOptions one_core;
  one_core.threads = 1;
  double achieved = 0.0;
  for (auto _ : state) {
    const ExactLaw law = make_exact_law(model, one_core);
    achieved = law.achieved;
    benchmark::DoNotOptimize(law);
  }
  state.counters["achieved"] = achieved;
}

template <class Runs>
void print_dense_table(const Runs& runs) {
  auto ms = [&runs](const char* what, int n) {
    const auto it = runs.find(std::string("build:dense_") + what + "/" + std::to_string(n));
    return it == runs.end() ? 0.0 : it->second.GetAdjustedRealTime();
  };
  auto ratio = [](double now, double before, char* out) {
    if (now > 0.0 && before > 0.0)
      std::snprintf(out, 32, "%.1fx", now / before);
    else
      out[0] = 0;
  };
  if (ms("model", 1000) == 0.0 && ms("law", 1000) == 0.0) return;
  std::printf(
      "\n| knots | model build [ms] | / 10x fewer knots | law build [ms] | / 10x fewer knots "
      "|\n|---|---|---|---|---|\n");
  for (int n : {1000, 10000, 100000}) {
    char rm[32], rl[32];
    ratio(ms("model", n), n > 1000 ? ms("model", n / 10) : 0.0, rm);
    ratio(ms("law", n), n > 1000 ? ms("law", n / 10) : 0.0, rl);
    std::printf("| %d | %.1f | %s | %.1f | %s |\n", n, ms("model", n), rm, ms("law", n), rl);
  }
}

void register_law_benchmarks() {
  benchmark::RegisterBenchmark("build:dense_model", BM_DenseModelBuild)
      ->Arg(1000)
      ->Arg(10000)
      ->Arg(100000)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("build:dense_law", BM_DenseLawBuild)
      ->Arg(1000)
      ->Arg(10000)
      ->Arg(100000)
      ->Unit(benchmark::kMillisecond);
  for (double tol : {1e-8, 1e-6})
    benchmark::RegisterBenchmark(
        (std::string("build:table101+f(w)/tol:") + (tol > 1e-7 ? "1e-6" : "1e-8")).c_str(),
        BM_LawBuildTableFalling, tol)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(1);
  for (bool j : {false, true}) {
    const std::string suffix = j ? "+jacobian" : "";
    benchmark::RegisterBenchmark(("law:fractional" + suffix).c_str(), BM_FractionalOnPoints, j)
        ->Unit(benchmark::kNanosecond);
    for (std::size_t c = 0; c < law_cases().size(); ++c)
      benchmark::RegisterBenchmark(("law:" + law_cases()[c].name + suffix).c_str(), BM_Law, c, j)
          ->Unit(benchmark::kNanosecond);
  }
  for (std::size_t c = 0; c < law_cases().size(); ++c)
    benchmark::RegisterBenchmark(("build:" + law_cases()[c].name).c_str(), BM_LawBuild, c)
        ->Unit(benchmark::kMillisecond)
        ->Iterations(law_cases()[c].patch.slip_speed_friction ? 1 : 5);
}

template <class Runs>
void print_law_table(const Runs& runs) {
  const auto frac = runs.find("law:fractional"), frac_j = runs.find("law:fractional+jacobian");
  if (frac == runs.end() || frac_j == runs.end()) return;
  std::printf(
      "\n| exact law | ns | / fractional | with Jacobian [ns] | / fractional | build [ms, one "
      "core] | tables [KB] | certified | measured |\n|---|---|---|---|---|---|---|---|---|\n");
  std::printf("| fractional law | %.1f | 1 | %.1f | 1 | | | | |\n",
              frac->second.GetAdjustedRealTime(), frac_j->second.GetAdjustedRealTime());
  for (const LawCase& c : law_cases()) {
    const auto v = runs.find("law:" + c.name), j = runs.find("law:" + c.name + "+jacobian");
    const auto b = runs.find("build:" + c.name);
    if (v == runs.end() || j == runs.end()) continue;
    const double tv = v->second.GetAdjustedRealTime(), tj = j->second.GetAdjustedRealTime();
    std::printf("| %s | %.1f | %.2f | %.1f | %.2f | %.0f | %.0f | %.1e | %.1e |\n", c.name.c_str(),
                tv, tv / frac->second.GetAdjustedRealTime(), tj,
                tj / frac_j->second.GetAdjustedRealTime(),
                b == runs.end() ? 0.0 : b->second.GetAdjustedRealTime(),
                static_cast<double>(c.law.bytes()) / 1024.0, c.law.achieved, c.measured);
  }
}

// Collects the runs so that main can print ratios against the baseline.
class TableReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, Run> runs;
  void ReportRuns(const std::vector<Run>& report) override {
    for (const Run& r : report) {
      if (!r.aggregate_name.empty() && r.aggregate_name != "median") continue;
      std::string name = r.run_name.str();
      const auto it = name.find("/iterations:");
      if (it != std::string::npos) name.erase(it);
      runs[name] = r;
    }
    ConsoleReporter::ReportRuns(report);
  }
};

}  // namespace

int main(int argc, char** argv) {
  for (double tol : {1e-6, 1e-10}) {
    for (const Regime& r : kRegimes) {
      const std::string suffix = std::string(r.name) + "/tol:" + (tol > 1e-8 ? "1e-6" : "1e-10");
      benchmark::RegisterBenchmark(("exact/" + suffix).c_str(), BM_Exact, &data(), r, tol)
          ->Unit(benchmark::kMicrosecond);
      for (std::size_t v = 1; v < variants().size(); ++v)
        benchmark::RegisterBenchmark(("profile:" + variants()[v].name + "/" + suffix).c_str(),
                                     BM_Exact, &variants()[v], r, tol)
            ->Unit(benchmark::kMicrosecond);
      benchmark::RegisterBenchmark(("hcubature/" + suffix).c_str(), BM_Baseline, r, tol)
          ->Unit(benchmark::kMillisecond)
          ->Iterations(tol > 1e-8 ? 20 : 2);
    }
  }
  benchmark::RegisterBenchmark("fractional", BM_Fractional)->Unit(benchmark::kNanosecond);
  benchmark::RegisterBenchmark("fractional+jacobian", BM_FractionalWithJacobian)
      ->Unit(benchmark::kNanosecond);
  register_law_benchmarks();
  benchmark::Initialize(&argc, argv);
  TableReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf(
      "\n| regime | tol | contensou [us] | rays | achieved | estimate | hcubature [ms] | evals | "
      "achieved | estimate | speed-up |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, run] : reporter.runs) {
    if (name.rfind("exact/", 0) != 0) continue;
    const std::string rest = name.substr(6);
    const auto it = reporter.runs.find("hcubature/" + rest);
    if (it == reporter.runs.end()) continue;
    const double ours = run.GetAdjustedRealTime() * 1e-6;         // us -> s
    const double base = it->second.GetAdjustedRealTime() * 1e-3;  // ms -> s
    const auto slash = rest.find('/');
    const auto& c = run.counters;
    const auto& b = it->second.counters;
    std::printf("| %s | %s | %.1f | %.0f | %.1e | %.1e | %.1f | %.0f | %.1e | %.1e | %.0fx |\n",
                rest.substr(0, slash).c_str(), rest.substr(slash + 5).c_str(), ours * 1e6,
                c.at("evals").value, c.at("achieved").value, c.at("estimate").value, base * 1e3,
                b.at("evals").value, b.at("achieved").value, b.at("estimate").value, base / ours);
  }
  std::printf(
      "\n| profile | regime | tol | contensou [us] | rays | achieved | estimate | time / seed "
      "series |\n|---|---|---|---|---|---|---|---|\n");
  for (const auto& [name, run] : reporter.runs) {
    if (name.rfind("profile:", 0) != 0) continue;
    const auto slash = name.find('/');
    const std::string rest = name.substr(slash + 1);
    const auto seed = reporter.runs.find("exact/" + rest);  // absent if filtered out: "-"
    char ratio[32] = "-";
    if (seed != reporter.runs.end())
      std::snprintf(ratio, sizeof ratio, "%.1fx",
                    run.GetAdjustedRealTime() / seed->second.GetAdjustedRealTime());
    const auto slash2 = rest.find('/');
    std::printf("| %s | %s | %s | %.1f | %.0f | %.1e | %.1e | %s |\n",
                name.substr(8, slash - 8).c_str(), rest.substr(0, slash2).c_str(),
                rest.substr(slash2 + 5).c_str(), run.GetAdjustedRealTime(),
                run.counters.at("evals").value, run.counters.at("achieved").value,
                run.counters.at("estimate").value, ratio);
  }
  print_law_table(reporter.runs);
  print_dense_table(reporter.runs);
  benchmark::Shutdown();
  return 0;
}
