// Noise that grows with the value (load cells): the affine noise model sigma = a + b |y| per
// channel (fit.hpp), its coverage and estimates, and the closed loop's choice between it and
// one constant scale per channel (closed_loop.hpp). Also the loop's retry from other starts.
#include <gtest/gtest.h>

#include "seed_tire_law.hpp"

#include <chrono>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

constexpr double kLoad = 4535.0;

FractionalLaw<double> tire_truth() {
  FractionalLaw<double> law = test::seed_tire_law();
  law.regularization_speed = 1e-6;
  return law;
}

// Load-cell noise: sigma_c = level max|y_c| + growth |y| with growth |y| ten times the floor
// at the channel's peak.
constexpr double kLevel = 0.002, kGrowth = 0.02;

DiagramSpec load_cell_spec(std::uint64_t seed, int points) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = points;
  s.noise = SimulatedNoise::load_cell;
  s.noise_level = kLevel;
  s.noise_growth = kGrowth;
  s.seed = seed;
  return s;
}

IdentificationOptions tire_options(NoiseModel noise) {
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.normal_load_n = kLoad;
  o.noise_model = noise;
  return o;
}

double truth_of(const FractionalLaw<double>& law, const std::string& name) {
  if (name == "F0_N") return law.F0;
  if (name == "a") return law.a;
  if (name == "M0_Nm") return law.M0;
  if (name == "m") return law.m;
  if (name == "kx") return law.kx;
  return law.F0 / kLoad;  // f
}

// One replica's affine fit into the tallies: which 95 % intervals cover the truth, and the
// noise scales a and slopes b averaged over the replicas.
void tally(const FractionalLaw<double>& law, const FitReport& r, int replicas,
           std::map<std::string, int>& covered, std::array<double, kChannels>& mean_a,
           std::array<double, kChannels>& mean_b) {
  for (const ParameterEstimate& p : r.parameters) {
    ASSERT_TRUE(p.ci95.has_value()) << p.name;
    const double t = truth_of(law, p.name);
    covered[p.name] += (*p.ci95)[0] <= t && t <= (*p.ci95)[1];
  }
  for (int c = 0; c < kChannels; ++c) {
    mean_a[c] += r.noise_scale[c] / replicas;
    mean_b[c] += r.noise_slope[c] / replicas;
  }
}

// Two sweeps (longitudinal, then lateral sliding), 20 points each, 0.5 s apart, from the
// fractional law with the shape constants the identification assumes without a profile.
FractionalLaw<double> uniform_constants_law() {
  FractionalLaw<double> law = fractional_law_from_patch([] {
    ContactPatch p = seed_tire_patch();
    p.profile.kx = 0.14;
    return p;
  }());
  law.c = 4.0;
  law.a_k = 1.0;
  law.Mk = 0.375 * law.M0;
  return law;
}

// The two sweeps with noise sigma_c = level max|y_c| + growth |y| per channel, max|y_c| over
// both sweeps (growth 0: one constant scale per channel).
MeasuredData two_sweeps(const FractionalLaw<double>& law, double level, double growth,
                        std::uint64_t seed) {
  DiagramSpec s = load_cell_spec(seed, 20);
  s.noise = SimulatedNoise::none;
  s.time_step_s = 0.5;
  MeasuredData d;
  std::array<double, kChannels> peak{};
  for (int sweep = 0; sweep < 2; ++sweep) {
    s.direction_rad = sweep * 0.5 * std::numbers::pi;
    for (MeasuredPoint p : simulate_diagrams(law, s).points) {
      *p.time += 20.0 * sweep;
      for (int c = 0; c < kChannels; ++c) peak[c] = std::max(peak[c], std::abs(*p.force[c]));
      d.points.push_back(p);
    }
  }
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c)
      *p.force[c] += (level * peak[c] + growth * std::abs(*p.force[c])) * normal(rng);
  return d;
}

const LoopStep* noise_step(const ClosedLoopReport& r) {
  for (const LoopStep& st : r.steps)
    if (st.effect == kNoiseGrowthEffect) return &st;
  return nullptr;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// The coverage test of the constant scale (test_identification.cpp), on load-cell noise: with
// the affine model the 95 % intervals cover the truth in 90-99 % of 200 replicas, and the
// estimated a and b average within 15 % of the truth.
TEST(NoiseModel, AffineIntervalsCoverTheTruthOnLoadCellNoise) {
  const FractionalLaw<double> law = tire_truth();
  const int replicas = 200;
  std::map<std::string, int> covered, covered_additive;
  std::array<double, kChannels> peak{}, mean_a{}, mean_b{};
  DiagramSpec clean = load_cell_spec(1, 40);
  clean.noise = SimulatedNoise::none;
  for (const MeasuredPoint& p : simulate_diagrams(law, clean).points)
    for (int c = 0; c < kChannels; ++c) peak[c] = std::max(peak[c], std::abs(*p.force[c]));
  const auto t0 = std::chrono::steady_clock::now();
  for (int seed = 1; seed <= replicas; ++seed) {
    const MeasuredData d = simulate_diagrams(law, load_cell_spec(seed, 40));
    const FitReport r = fit_fractional_law(d, tire_options(NoiseModel::affine));
    EXPECT_EQ(r.noise_model, NoiseModel::affine);
    tally(law, r, replicas, covered, mean_a, mean_b);
    const FitReport add = fit_fractional_law(d, tire_options(NoiseModel::additive));
    for (const ParameterEstimate& p : add.parameters) {
      const double t = truth_of(law, p.name);
      covered_additive[p.name] += p.ci95 && (*p.ci95)[0] <= t && t <= (*p.ci95)[1];
    }
  }
  std::printf("200 replicas, affine and additive fits: %.1f s\n", seconds_since(t0));
  for (const auto& [name, n] : covered) {
    const double coverage = static_cast<double>(n) / replicas;
    std::printf("coverage %-6s affine %.3f, additive %.3f\n", name.c_str(), coverage,
                static_cast<double>(covered_additive[name]) / replicas);
    EXPECT_GE(coverage, 0.90) << name;
    EXPECT_LE(coverage, 0.99) << name;
  }
  for (int c = 0; c < kChannels; ++c) {
    std::printf("%s: a %.4g (truth %.4g), b %.4g (truth %.4g)\n", kChannelColumns[c], mean_a[c],
                kLevel * peak[c], mean_b[c], kGrowth);
    EXPECT_NEAR(mean_a[c], kLevel * peak[c], 0.15 * kLevel * peak[c]) << kChannelColumns[c];
    EXPECT_NEAR(mean_b[c], kGrowth, 0.15 * kGrowth) << kChannelColumns[c];
  }
}

// Purely relative noise, y (1 + 0.01 n) as `simulate --noise relative-gaussian` writes it, is
// the affine model's edge a = 0: fitted affine, b averages within 7 % of 0.01 and a stays below
// 0.5 % of the noise at the channel's peak (a search that stops at a = 1 % of it, as the
// estimate once did, gives b 10-13 % low), and the 95 % intervals cover the truth in 90-99 % of
// 200 replicas.
TEST(NoiseModel, AffineModelReachesPurelyRelativeNoise) {
  const FractionalLaw<double> law = tire_truth();
  const int replicas = 200;
  constexpr double kRelative = 0.01;
  std::map<std::string, int> covered;
  std::array<double, kChannels> peak{}, mean_a{}, mean_b{};
  DiagramSpec spec = load_cell_spec(1, 40);
  spec.noise = SimulatedNoise::none;
  for (const MeasuredPoint& p : simulate_diagrams(law, spec).points)
    for (int c = 0; c < kChannels; ++c) peak[c] = std::max(peak[c], std::abs(*p.force[c]));
  spec.noise = SimulatedNoise::relative_gaussian;
  spec.noise_level = kRelative;
  for (int seed = 1; seed <= replicas; ++seed) {
    spec.seed = static_cast<std::uint64_t>(seed);
    const FitReport r =
        fit_fractional_law(simulate_diagrams(law, spec), tire_options(NoiseModel::affine));
    tally(law, r, replicas, covered, mean_a, mean_b);
  }
  for (const auto& [name, n] : covered) {
    const double coverage = static_cast<double>(n) / replicas;
    std::printf("coverage %-6s %.3f\n", name.c_str(), coverage);
    EXPECT_GE(coverage, 0.90) << name;
    EXPECT_LE(coverage, 0.99) << name;
  }
  for (int c = 0; c < kChannels; ++c) {
    std::printf("%s: a %.4g (truth 0; noise at the peak %.4g), b %.4g (truth %.4g)\n",
                kChannelColumns[c], mean_a[c], kRelative * peak[c], mean_b[c], kRelative);
    EXPECT_LT(mean_a[c], 0.005 * kRelative * peak[c]) << kChannelColumns[c];
    EXPECT_NEAR(mean_b[c], kRelative, 0.07 * kRelative) << kChannelColumns[c];
  }
}

// The closed loop, asked to choose the noise model, takes the growing scale on load-cell data
// (and no effect: the data come from the law itself), and keeps one constant scale per channel
// on white constant noise.
TEST(NoiseModel, TheLoopChoosesTheGrowingScaleOnLoadCellDataOnly) {
  const FractionalLaw<double> law = uniform_constants_law();
  IdentificationOptions o = tire_options(NoiseModel::additive);
  ClosedLoopOptions lo;
  lo.max_steps = 3;
  lo.choose_noise_model = true;
  const int replicas = 5;
  int chosen = 0, kept = 0, effects = 0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int seed = 1; seed <= replicas; ++seed) {
    for (const bool load_cell : {true, false}) {
      const MeasuredData d =
          load_cell ? two_sweeps(law, kLevel, kGrowth, seed) : two_sweeps(law, 0.01, 0.0, seed);
      const ClosedLoopReport r = close_the_loop(d, o, lo);
      const LoopStep* st = noise_step(r);
      ASSERT_NE(st, nullptr);
      EXPECT_EQ(st->lr_dof, 3);
      EXPECT_EQ(st->threshold, lo.alpha);
      EXPECT_FALSE(step_fit_failed(*st));
      EXPECT_EQ(r.noise_model, st->accepted ? NoiseModel::affine : NoiseModel::additive);
      EXPECT_EQ(r.final_fit.noise_model, r.noise_model);
      std::printf("seed %d %s: LR %.1f (p %.2e), BIC %.1f -> %.1f, %s, effects %zu\n", seed,
                  load_cell ? "load-cell" : "constant ", st->lr, st->lr_p_value, st->bic_before,
                  st->bic_after, st->accepted ? "accepted" : "rejected", r.accepted_effects.size());
      (load_cell ? chosen : kept) += load_cell == st->accepted;
      effects += static_cast<int>(r.accepted_effects.size());
    }
  }
  std::printf("%d loops: %.1f s\n", 2 * replicas, seconds_since(t0));
  EXPECT_EQ(chosen, replicas);
  EXPECT_EQ(kept, replicas);
  EXPECT_LE(effects, 1);
}
