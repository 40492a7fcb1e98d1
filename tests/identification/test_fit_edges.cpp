// Issue 10, items 1 and 2: the rows a rig produces (pure spin, pure sliding, v = omega = 0,
// negative omega, any sliding direction) give finite values and finite, correct derivatives
// in the parameters through every path of the fitted model (fractional law, every effect of
// the catalogue, the exact integrals, speed dependence in both forms), and fit.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "jet_checks.hpp"

#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <random>
#include <string>

#include "contensou/identification.hpp"

using namespace contensou;

namespace {

constexpr double kSpin = 11.49425287;  // u = omega R = 1 m/s on the seed tire

using contensou::test_support::all_finite;

}  // namespace

// --- The model of the closed loop: every path, Jets in the parameters --------------------

namespace {

constexpr int K = kModelParameters;
using JK = ceres::Jet<double, K>;

std::array<double, K> edge_theta() {
  std::array<double, K> t{};
  for (int i = 0; i < K; ++i) t[i] = parameter_info(i).null_value;
  t[kF0] = 1360.0;
  t[kA] = 1.03;
  t[kM0] = 72.0;
  t[kMShape] = 9.28;
  t[kKx] = 0.14;
  t[kKy] = 0.03;
  t[kKappa] = 0.9;
  t[kSpeedDrop] = 0.2;
  t[kSpeedRef] = 2.0;
  for (int c = 0; c < 3; ++c) t[offset_parameter(c)] = 3.0;
  for (int i = kXFxFy; i <= kXMzFy; ++i) t[i] = 0.01;
  t[kShapeBlend] = 0.4;
  t[kProfileW1] = 0.1;
  t[kProfileW2] = -0.05;
  return t;
}

struct Path {
  const char* name;
  ModelSpec spec;
};

std::vector<Path> every_path() {
  const double R = 0.087;
  ModelSpec law = base_model_spec(R, std::nullopt);
  law.exact_tolerance = 1e-12;
  ModelSpec blend = law;  // law + exact integrals over the parametric profile
  blend.free[kShapeBlend] = blend.free[kProfileW1] = blend.free[kProfileW2] = true;
  ModelSpec exact = law;  // exact integrals over the seed profile only
  ContactPatch patch = seed_tire_patch();
  patch.friction = 1.0;
  exact.profile_model = make_exact_model(patch, 1e-10);
  exact.exact_only = true;
  ModelSpec inside = exact;  // friction falling with the local slip speed
  inside.speed_in_exact = true;
  ModelSpec inside_blend = blend;
  inside_blend.speed_in_exact = true;
  return {{"fractional law", law},
          {"shape blend", blend},
          {"exact over the profile", exact},
          {"speed inside the exact integrals", inside},
          {"speed inside, parametric profile", inside_blend}};
}

}  // namespace

// Every effect of the catalogue is on (offsets, crosstalk, speed drop, shift, anisotropy,
// blend, profile), at every row a rig produces: values and Jets finite, Jets = differences.
TEST(ModelEdges, EveryPathHasFiniteCorrectDerivativesAtTheEdges) {
  const std::array<double, K> theta = edge_theta();
  const Kinematics<double> rows[] = {{0.0, 0.0, kSpin},  {0.0, 0.0, -kSpin}, {0.5, 0.0, 0.0},
                                     {0.0, -0.4, 0.0},   {-0.3, 0.4, 0.0},   {0.0, 0.0, 0.0},
                                     {0.2, 0.0, -kSpin}, {1e-200, 0.0, 0.0}, {1e-12, 0.0, kSpin}};
  std::array<JK, K> tj;
  for (int i = 0; i < K; ++i) tj[i] = JK(theta[i], i);
  for (const Path& path : every_path()) {
    for (const Kinematics<double>& k : rows) {
      const std::string what = std::string(path.name) + " at (" + std::to_string(k.vx) + ", " +
                               std::to_string(k.vy) + ", " + std::to_string(k.omega) + ")";
      const Resultants<JK> rj = evaluate_model(path.spec, tj.data(), k);
      ASSERT_TRUE(all_finite(rj)) << what;
      const Resultants<double> r = evaluate_model(path.spec, theta.data(), k);
      EXPECT_NEAR(rj.Fx.a, r.Fx, 1e-9 * 1360.0) << what;
      const JK out[3] = {rj.Fx, rj.Fy, rj.Mz};
      for (int i = 0; i < K; ++i) {
        const double h = 1e-6 * std::max(1.0, std::abs(theta[i]));
        std::array<double, K> tp = theta, tm = theta;
        tp[i] += h;
        tm[i] -= h;
        const Eigen::Vector3d fd = (evaluate_model(path.spec, tp.data(), k).vector() -
                                    evaluate_model(path.spec, tm.data(), k).vector()) /
                                   (2 * h);
        for (int c = 0; c < 3; ++c) {
          const double scale = std::max(std::abs(fd(c)), 1e-6);
          // Differencing noise: ~1e-16 of the ~1.4 kN resultants, over h.
          EXPECT_NEAR(out[c].v[i], fd(c), 1e-5 * scale + 1e-13 * 1400.0 / h)
              << what << " d/d" << parameter_info(i).name << " channel " << c;
        }
      }
    }
  }
}

// --- Identification from data with exact zeros (the library; the app: tests/cli) --------

TEST(IdentificationEdges, FitsDiagramsWithPureSpinSlideAndRestRows) {
  const MeasuredData data = read_measured_csv(CONTENSOU_TEST_DATA_DIR "/seed_tire_edge_rows.csv");
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.profile = seed_tire_profile();
  const FitReport fit = fit_fractional_law(data, o);
  EXPECT_TRUE(fit.converged) << fit.solver_summary;
  for (const ParameterEstimate& p : fit.parameters) {
    EXPECT_TRUE(std::isfinite(p.value)) << p.name;
    EXPECT_TRUE(p.ci95.has_value()) << p.name;
  }
  EXPECT_NEAR(fit.parameter("kx")->value, 0.14, 0.02);
  // The exact model (what the closed loop accepts for these data) on the same rows.
  ModelSpec spec = base_spec_for(data, o);
  spec.exact_only = true;
  spec.free[kA] = spec.free[kM0] = spec.free[kMShape] = false;
  const FitReport exact = fit_model(data, spec, noise_settings_for(o));
  EXPECT_TRUE(exact.converged) << exact.solver_summary;
  EXPECT_NEAR(exact.parameter("F0_N")->value, 0.3 * 4535.02, 15.0);
  EXPECT_TRUE(exact.parameter("kx")->ci95.has_value());
}

// Item 2: a fit never goes on from a failed solve or a bad parameter; it says which.
TEST(IdentificationEdges, BadFixedValueIsReportedByNameNotAsACrash) {
  const MeasuredData data = read_measured_csv(CONTENSOU_TEST_DATA_DIR "/seed_tire_edge_rows.csv");
  IdentificationOptions o;
  o.radius_m = 0.087;
  ModelSpec spec = base_spec_for(data, o);
  spec.value[kKappa] = -1.0;  // friction that would generate energy
  try {
    fit_model(data, spec, noise_settings_for(o));
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "kappa");
  }
}

// A channel measured as exact zeros (Fy of a symmetric tire sliding straight, or a rig that
// writes 0 for a channel it did not record) must not take over the fit: its noise scale has a
// floor, the covariance is computed on normalised columns, and every parameter keeps an
// interval of honest width.
TEST(IdentificationEdges, ChannelOfExactZerosKeepsEveryIntervalHonest) {
  ContactPatch patch = seed_tire_patch();  // kx = 0: Fy = 0 when sliding along x
  const FractionalLaw<double> law = fractional_law_from_patch(patch);
  DiagramSpec s;
  s.radius_m = patch.radius_m;
  s.points = 40;
  s.noise_level = 0.01;
  s.seed = 7;
  MeasuredData d = simulate_diagrams(law, s);
  for (MeasuredPoint& p : d.points) p.force[1] = 0.0;
  IdentificationOptions o;
  o.radius_m = patch.radius_m;
  const FitReport r = fit_fractional_law(d, o);
  const double truth[] = {law.F0, law.a, law.M0, law.m};
  const char* names[] = {"F0_N", "a", "M0_Nm", "m"};
  for (int i = 0; i < 4; ++i) {
    const ParameterEstimate* e = r.parameter(names[i]);
    ASSERT_NE(e, nullptr);
    ASSERT_TRUE(e->determined) << names[i];
    ASSERT_TRUE(e->ci95.has_value()) << names[i];
    EXPECT_GT(e->std_error, 1e-6 * std::abs(e->value)) << names[i];  // not a zero-width interval
    EXPECT_LT(std::abs(e->value - truth[i]), 5.0 * e->std_error) << names[i];
  }
  EXPECT_LT(std::abs(r.parameter("kx")->value), 1e-6);
  EXPECT_TRUE(std::isfinite(r.error));
}

// --- A caller's stop request (issue 22, Bounds): Interrupted, from the start or mid-way ----

namespace {

MeasuredData seed_rows(int points) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = points;
  s.noise_level = 0.01;
  ContactPatch p = seed_tire_patch();
  p.profile.kx = 0.14;
  return simulate_diagrams(make_exact_model(p), s);
}

// A stop request that fires on its `after`-th poll and stays on; counts the polls.
struct CountingStop {
  std::shared_ptr<std::atomic<int>> polls = std::make_shared<std::atomic<int>>(0);
  int after = 0;
  bool operator()() const { return ++*polls > after; }
};

}  // namespace

TEST(Interrupt, AStopAlreadyRequestedStopsTheFitAndTheLoop) {
  const MeasuredData d = seed_rows(40);
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.stop = [] { return true; };
  EXPECT_THROW(fit_fractional_law(d, o), Interrupted);
  EXPECT_THROW(close_the_loop(d, o), Interrupted);
  o.stop = [] { return false; };  // never fires: the fit is the fit without a request
  IdentificationOptions plain = o;
  plain.stop = nullptr;
  EXPECT_DOUBLE_EQ(fit_fractional_law(d, o).bic, fit_fractional_law(d, plain).bic);
}

TEST(Interrupt, AStopRequestedDuringAFitStopsIt) {
  const MeasuredData d = seed_rows(40);
  IdentificationOptions o;
  o.radius_m = 0.087;
  CountingStop never{};
  never.after = 1 << 30;
  o.stop = never;
  fit_fractional_law(d, o);  // counts the polls of a whole fit (its iterations and rounds)
  const int polls = never.polls->load();
  ASSERT_GT(polls, 10);
  CountingStop midway{};
  midway.after = polls / 2;
  o.stop = midway;
  EXPECT_THROW(fit_fractional_law(d, o), Interrupted);
  EXPECT_LE(midway.polls->load(), polls / 2 + 2);  // stopped at the poll that fired, or next
}

TEST(Interrupt, AStoppedExactLawBuildLeavesNothingAndBuildsAgain) {
  const ExactLawCache cache(0.087, std::nullopt, 1e-6);
  EXPECT_THROW(cache.laws(false, [] { return true; }), Interrupted);
  EXPECT_EQ(cache.laws(false).size(), 3u);
}

// --- The parametric profile: Bernstein weights in Chebyshev terms ----------------------------

namespace {

// p(rho) from the basis-law coefficients (1, 1 + T1, ..., 1 + T4), x = 2 rho^2 - 1.
double profile_from_basis(const std::array<double, 5>& b, double rho) {
  const double x = 2.0 * rho * rho - 1.0;
  double p = b[0];
  for (int j = 1; j < 5; ++j)
    p += b[static_cast<std::size_t>(j)] * (1.0 + std::cos(j * std::acos(x)));
  return p;
}

// p(rho) straight from the Bernstein form, sum_k w_k C(n,k) s^k (1-s)^(n-k), s = rho^2.
double bernstein(const std::vector<double>& w, double rho) {
  const double s = rho * rho;
  const int n = static_cast<int>(w.size()) - 1;
  double p = 0.0;
  for (int k = 0; k <= n; ++k)
    p += w[static_cast<std::size_t>(k)] * std::tgamma(n + 1.0) /
         (std::tgamma(k + 1.0) * std::tgamma(n - k + 1.0)) * std::pow(s, k) *
         std::pow(1.0 - s, n - k);
  return p;
}

}  // namespace

// The coefficient matrices against the Bernstein form itself, at degree 2 and 4; the quadratic
// raised to degree 4 by hand (two elevations) is the same profile; non-negative weights give a
// non-negative profile.
TEST(ParametricProfile, BernsteinWeightsGiveTheirPolynomialAndStayNonNegative) {
  std::array<double, K> th{};
  th[kProfileW1] = 0.7;
  th[kProfileW2] = 0.2;
  th[kProfileW3] = 1.9;
  th[kProfileW4] = 0.05;
  const auto b2 = detail::parametric_profile_coefficients(th.data(), 2);
  const auto b4 = detail::parametric_profile_coefficients(th.data(), 4);
  // Degree 2 -> 3 -> 4 by the elevation rule w'_k = k/(n+1) w_(k-1) + (1 - k/(n+1)) w_k.
  const std::vector<double> q{1.0, 0.7, 0.2};
  const std::vector<double> c{1.0, (1.0 + 2.0 * 0.7) / 3.0, (2.0 * 0.7 + 0.2) / 3.0, 0.2};
  const std::vector<double> e{1.0, 0.25 + 0.75 * c[1], 0.5 * (c[1] + c[2]),
                              0.75 * c[2] + 0.25 * c[3], c[3]};
  std::array<double, K> raised{};
  for (int k = 0; k < 4; ++k) raised[kProfileW1 + k] = e[static_cast<std::size_t>(k + 1)];
  const auto b_raised = detail::parametric_profile_coefficients(raised.data(), 4);
  for (double rho = 0.0; rho <= 1.0; rho += 0.05) {
    EXPECT_NEAR(profile_from_basis(b2, rho), bernstein(q, rho), 1e-14) << rho;
    EXPECT_NEAR(profile_from_basis(b4, rho), bernstein({1.0, 0.7, 0.2, 1.9, 0.05}, rho), 1e-14)
        << rho;
    EXPECT_NEAR(profile_from_basis(b_raised, rho), bernstein(q, rho), 1e-14) << rho;
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> weight(0.0, 20.0);
  for (int trial = 0; trial < 200; ++trial) {
    for (int k = 0; k < 4; ++k) th[kProfileW1 + k] = trial % 7 == 0 ? 0.0 : weight(rng);
    for (int degree : {2, 4}) {
      const auto b = detail::parametric_profile_coefficients(th.data(), degree);
      for (double rho = 0.0; rho <= 1.0; rho += 0.01)
        EXPECT_GE(profile_from_basis(b, rho), -1e-12) << "degree " << degree << " rho " << rho;
    }
  }
  th.fill(0.0);
  th[kProfileW1] = th[kProfileW2] = th[kProfileW3] = th[kProfileW4] = 1.0;
  for (int degree : {2, 4})
    for (double rho = 0.0; rho <= 1.0; rho += 0.1)
      EXPECT_NEAR(
          profile_from_basis(detail::parametric_profile_coefficients(th.data(), degree), rho), 1.0,
          1e-14)
          << "uniform at unit weights, degree " << degree;
}

// --- Bounds: a parameter the data press against its bound ---------------------------------

// The seed tire (kx = 0.14) fitted with the parametric profile (three basis shapes): the
// quadratic cannot follow its published series, and one Bernstein weight goes to its bound 0.
// The bounded fit must end at the optimum, whose oracle is the same fit with that weight fixed
// on the bound (an unconstrained problem): the same cost, the same parameters. Ceres' trust region
// alone crawled along the bound (its radius shrinking at every clipped step) and stopped short: on
// 1,000 points 12 units of -2 log L above the optimum.
namespace {

// The seed tire rolling (kx = 0.14): its diagrams at `points` points, 1 % noise, from the exact
// integrals or the fractional law.
MeasuredData rolling_seed_tire_diagrams(int points, bool exact) {
  ContactPatch patch = seed_tire_patch();
  patch.profile.kx = 0.14;
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = points;
  s.noise_level = 0.01;
  return exact ? simulate_diagrams(make_exact_model(patch), s)
               : simulate_diagrams(fractional_law_from_patch(patch), s);
}

}  // namespace

TEST(FitBounds, ReachesTheOptimumWithAParameterOnItsBound) {
  const MeasuredData data = rolling_seed_tire_diagrams(300, true);
  IdentificationOptions o;
  o.radius_m = 0.087;
  ModelSpec spec = base_spec_for(data, o);
  spec.exact_only = true;
  spec.free[kA] = spec.free[kM0] = spec.free[kMShape] = spec.free[kShapeBlend] = false;
  spec.value[kShapeBlend] = 1.0;
  spec.free[kProfileW1] = spec.free[kProfileW2] = true;
  NoiseSettings noise = noise_settings_for(o);
  noise.given = std::array<double, 3>{15.0, 1.0, 1.0};  // one weighting for both fits
  const FitReport bounded = fit_model(data, spec, noise);
  ASSERT_TRUE(bounded.converged) << bounded.solver_summary;
  int pinned = -1, other = -1;
  for (int i : {kProfileW1, kProfileW2}) {
    const ParameterEstimate* e = bounded.parameter(parameter_info(i).name);
    ASSERT_NE(e, nullptr) << parameter_info(i).name << " not reported";
    (e->value == parameter_bounds(i).lower ? pinned : other) = i;
  }
  ASSERT_GE(pinned, 0) << "no profile weight on its bound: the bound is not active here";
  ASSERT_GE(other, 0) << "both weights on their bounds";
  ModelSpec on_bound = spec;
  on_bound.free[pinned] = false;
  on_bound.value[pinned] = parameter_bounds(pinned).lower;
  const FitReport oracle = fit_model(data, on_bound, noise);
  EXPECT_NEAR(bounded.chi2, oracle.chi2, 1e-7 * oracle.chi2);
  for (const char* name : {"F0_N", "kx", parameter_info(other).name})
    EXPECT_NEAR(bounded.parameter(name)->value, oracle.parameter(name)->value,
                1e-5 * std::abs(oracle.parameter(name)->value))
        << name;
}

// --- Force scale: the same fit in any unit inside the range, a clear refusal outside -------

namespace {

MeasuredData scaled_forces(MeasuredData d, double k) {
  for (MeasuredPoint& p : d.points)
    for (auto& f : p.force)
      if (f) *f *= k;
  return d;
}

}  // namespace

// The fractional law's a, m, kx are ratios: the same for the data in N, mN or kN, and F0, M0
// scale with the data. Outside 1e-6 to 1e8 N the fit is refused, naming the range (there, on
// the bundled set scaled by 1e-20 or 1e9, fits went wrong without a word); zero forces too.
TEST(FitForceScale, SameFitInAnyUnitInsideTheRangeAndARefusalOutside) {
  const MeasuredData data = rolling_seed_tire_diagrams(40, false);
  IdentificationOptions o;
  o.radius_m = 0.087;
  const FitReport base = fit_fractional_law(data, o);
  for (double k : {1e-8, 1e-3, 1e4}) {
    const FitReport f = fit_fractional_law(scaled_forces(data, k), o);
    for (const char* name : {"a", "m", "kx"})
      EXPECT_NEAR(f.parameter(name)->value, base.parameter(name)->value,
                  1e-4 * std::abs(base.parameter(name)->value))
          << name << " at " << k;
    for (const char* name : {"F0_N", "M0_Nm"})
      EXPECT_NEAR(f.parameter(name)->value / k, base.parameter(name)->value,
                  1e-4 * base.parameter(name)->value)
          << name << " at " << k;
  }
  for (double k : {1e-12, 1e6, 1e250}) {
    try {
      fit_fractional_law(scaled_forces(data, k), o);
      ADD_FAILURE() << "forces scaled by " << k << " were fitted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("outside the range a fit is made for, 1e-06 to 1e+08 N"),
                std::string::npos)
          << e.what();
    }
  }
  try {
    fit_fractional_law(scaled_forces(data, 0.0), o);
    ADD_FAILURE() << "zero forces were fitted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no friction to fit"), std::string::npos) << e.what();
  }
}

// --- Noise scales started from an earlier fit ---------------------------------------------

// A fit whose noise scales start from an earlier fit's (close_the_loop_on_sample starts the fits
// on every row from the sample's) ends where the default start ends: the same parameters and
// scales to the rounds' tolerance, for the constant and the affine noise.
TEST(FitNoiseStart, AStartFromAnEarlierFitEndsWhereTheDefaultStartEnds) {
  const MeasuredData data = rolling_seed_tire_diagrams(200, false);
  IdentificationOptions o;
  o.radius_m = 0.087;
  const ModelSpec spec = base_spec_for(data, o);
  for (NoiseModel model : {NoiseModel::additive, NoiseModel::affine}) {
    NoiseSettings noise = noise_settings_for(o);
    noise.model = model;
    const FitReport plain = fit_model(data, spec, noise);
    noise.start = plain.noise_scales();
    for (double& s : noise.start->scale) s *= 1.3;  // a sample's estimate, a little off
    const FitReport started = fit_model(data, spec, noise);
    for (const char* name : {"F0_N", "a", "M0_Nm", "m", "kx"})
      EXPECT_NEAR(started.parameter(name)->value, plain.parameter(name)->value,
                  1e-3 * plain.parameter(name)->std_error)
          << name << " " << noise_model_name(model);
    for (int c = 0; c < kChannels; ++c)
      EXPECT_NEAR(started.noise_scale[c], plain.noise_scale[c], 2e-3 * plain.noise_scale[c])
          << c << " " << noise_model_name(model);
  }
}
