// Gross errors: found in the residual, named by line and channel, and left out so that the
// reported fit is that of the clean rows; clean data (also with a smooth misfit of the model)
// name none.
#include <gtest/gtest.h>

#include "seed_tire_law.hpp"

#include <cmath>
#include <random>
#include <set>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/identification/identify.hpp"
#include "contensou/identification/outliers.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

FractionalLaw<double> truth() {
  return test::seed_tire_law();
}

MeasuredData two_sweeps(std::uint64_t seed) {
  MeasuredData d;
  for (double direction : {0.0, 1.5707963}) {
    DiagramSpec s;
    s.radius_m = 0.087;
    s.points = 50;
    s.direction_rad = direction;
    s.noise = SimulatedNoise::additive_gaussian;
    s.noise_level = 0.01;
    s.seed = seed + static_cast<std::uint64_t>(direction * 10);
    for (MeasuredPoint p : simulate_diagrams(truth(), s).points) {
      p.line = static_cast<int>(d.points.size()) + 2;  // as if read from a file with a header
      d.points.push_back(p);
    }
  }
  return d;
}

IdentifyOptions fit_only() {
  IdentifyOptions o;
  o.fit.radius_m = 0.087;
  return o;
}

}  // namespace

TEST(Outliers, CleanDataNameNone) {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    const MeasuredData d = two_sweeps(seed);
    const Identification r = identify(d, fit_only());
    EXPECT_TRUE(r.outliers.empty())
        << "seed " << seed << ": " << r.outliers.front().describe("data");
    EXPECT_EQ(r.fitted.points.size(), d.points.size());
  }
  // The exact integrals fitted by the fractional law: a smooth misfit 3.5 times the noise.
  const ContactPatch patch =
      ContactPatch::from_normal_load(0.087, 4993.6, uniform_profile(), 0.3);  // p* = 210 kPa
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = 60;
  s.noise_level = 0.01;
  const MeasuredData exact = simulate_diagrams(make_exact_model(patch), s);
  EXPECT_TRUE(identify(exact, fit_only()).outliers.empty());
}

TEST(Outliers, GlitchesAreNamedAndTheFitIsTheCleanOne) {
  const MeasuredData clean = two_sweeps(7);
  MeasuredData glitched = clean;
  // A sign flip of a large lateral force, a 40-sigma spike in Mz, a dropped digit in Fx.
  std::set<std::pair<int, int>> injected;
  auto largest = [&](int c, int from) {
    int best = from;
    for (int i = from; i < from + 50; ++i)
      if (std::abs(*clean.points[i].force[c]) > std::abs(*clean.points[best].force[c])) best = i;
    return best;
  };
  const int flip = largest(1, 50), spike = 20, drop = largest(0, 0);
  *glitched.points[flip].force[1] *= -1.0;
  *glitched.points[spike].force[2] += 40.0 * 0.01 * 71.8;
  *glitched.points[drop].force[0] /= 10.0;
  injected = {{glitched.points[flip].line, 1},
              {glitched.points[spike].line, 2},
              {glitched.points[drop].line, 0}};

  const Identification with = identify(glitched, fit_only());
  std::set<std::pair<int, int>> named;
  for (const Outlier& o : with.outliers) named.insert({o.line, o.channel});
  EXPECT_EQ(named, injected);
  // Left out: the parameters are the clean set's within its intervals.
  const Identification reference = identify(clean, fit_only());
  for (const ParameterEstimate& p : reference.fit.parameters) {
    ASSERT_TRUE(p.ci95);
    const ParameterEstimate* q = with.fit.parameter(p.name);
    ASSERT_NE(q, nullptr);
    EXPECT_GE(q->value, (*p.ci95)[0]) << p.name;
    EXPECT_LE(q->value, (*p.ci95)[1]) << p.name;
  }
  // Without the rule the same glitches pull the fit out of the clean intervals.
  IdentifyOptions keep = fit_only();
  keep.leave_out_outliers = false;
  const Identification pulled = identify(glitched, keep);
  int outside = 0;
  for (const ParameterEstimate& p : reference.fit.parameters) {
    const double v = pulled.fit.parameter(p.name)->value;
    outside += v < (*p.ci95)[0] || v > (*p.ci95)[1];
  }
  EXPECT_GT(outside, 0);
}

// The scatter between neighbouring rows is the noise scale of Gaussian noise (the rms of the
// smaller 98 % of d over 1.067): constant noise of scale 2 on one long sweep, and noise that
// grows with the value, sigma_i = 0.1 + 0.02 |y_i| (with the row scale, so that the 2 % left
// out are not the loudest rows), against the rms of sigma_i. The residual's rms is what the
// report compares it with: the two agree within 5 % at 4000 rows.
TEST(Outliers, TheNeighbourScatterIsTheNoiseScaleOfGaussianNoise) {
  MeasuredData d;
  std::vector<Resultants<double>> prediction;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss;
  const int n = 4000;
  std::vector<double> sigma(n);
  double ss = 0.0;
  for (int i = 0; i < n; ++i) {
    MeasuredPoint p;
    const double psi = 0.01 * std::pow(1e4, i / (n - 1.0));
    p.kinematics = {psi, 0.0, 10.0};
    const double y = 1000.0 * psi / (1.0 + psi);  // rises from ~0 to ~1000 along the sweep
    sigma[static_cast<std::size_t>(i)] = 0.1 + 0.02 * y;
    ss += sigma[static_cast<std::size_t>(i)] * sigma[static_cast<std::size_t>(i)];
    p.force = {y + 2.0 * gauss(rng), y + sigma[static_cast<std::size_t>(i)] * gauss(rng),
               std::nullopt};
    d.points.push_back(p);
    prediction.push_back({y, y, 0.0});
  }
  const std::array<double, kChannels> scale = neighbour_scatter(
      d, prediction, [&](int c, std::size_t i) { return c == 0 ? 2.0 : sigma[i]; });
  EXPECT_NEAR(scale[0], 2.0, 0.05 * 2.0);
  const double rms_sigma = std::sqrt(ss / n);
  EXPECT_NEAR(scale[1], rms_sigma, 0.05 * rms_sigma);
  EXPECT_EQ(scale[2], 0.0);  // not measured
}
