// Dense tabulated profiles (table_far_sums.cpp): the far-knot series of a table, fitted top-down on
// a tree of its pieces in O(n) (update_far_sums), against the quadratic sums they replace; a
// 10^5-point table (its model and its exact law) against a 10^4-point one of the same function; the
// limit on the number of points.
#include <gtest/gtest.h>

#include "temp_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/pressure_profile.hpp"

using namespace contensou;

namespace {

// A smooth profile with a kink: p = 1 - rho^2 + 0.3 max(rho - 0.6, 0) (the slope changes by 0.3
// at rho = 0.6, between knots for the n used here), sampled at n even points in rho.
PressureProfile kinked_profile(int n) {
  std::vector<double> rho, p;
  for (int i = 0; i < n; ++i) {
    const double r = static_cast<double>(i) / (n - 1);
    rho.push_back(r);
    p.push_back(1.0 - r * r + 0.3 * std::max(r - 0.6, 0.0));
  }
  return tabulated_profile(rho, p);
}

// 200 random knots (intervals from ~1e-5 to ~3e-2 side by side) with 5 % noise: near pieces
// integrated, uneven far pieces.
PressureProfile random_knot_profile() {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<double> rho{0.0, 1.0}, p;
  for (int i = 0; i < 198; ++i) rho.push_back(U(rng));
  std::sort(rho.begin(), rho.end());
  for (double r : rho)
    p.push_back(1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) + 0.05 * (U(rng) - 0.5));
  return tabulated_profile(rho, p);
}

ContactPatch patch_of(PressureProfile profile) {
  ContactPatch c = seed_tire_patch();
  c.profile = std::move(profile);
  c.profile.kx = 0.1;
  c.profile.ky = -0.05;
  return c;
}

// The chord integrals M0, M2 at t_f (theory.md section 2) summed over every piece above t_f,
// one by one (the piece under the foot from the foot): no series, no knot terms.
void brute_force_chord_moments(const ExactModel<double>& m, double t_f, double& M0, double& M2) {
  M0 = M2 = 0.0;
  const TablePieces& tp = *m.table();
  for (std::size_t j = 0; j < tp.piece.size(); ++j) {
    if (tp.knot[j + 1] <= t_f) continue;
    const bool foot = tp.knot[j] <= t_f;
    double a0, a2;
    detail::cubic_moments(tp.piece[j], tp.knot[j], foot ? t_f : tp.knot[j], tp.knot[j + 1], t_f,
                          foot, a0, a2);
    M0 += a0;
    M2 += a2;
  }
}

// The far-knot series as they were first summed (test-only reference): on every knot interval
// k, the far sums at the kFarTerms Chebyshev points are the integrals of every piece from
// far_from[k] on, one by one, plus (with knot terms) the antiderivative of the piece below
// knot far_from[k] from t_f to it: O(n) a point, O(n^2) for the table.
void quadratic_far_series(const ExactModel<double>& m, std::vector<double>& far0,
                          std::vector<double>& far2) {
  constexpr int N = detail::kFarTerms;
  const double pi = std::numbers::pi;
  const TablePieces& tp = *m.table();
  const std::size_t n = tp.piece.size();
  far0.assign(n * N, 0.0);
  far2.assign(n * N, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = tp.knot[k], b = tp.knot[k + 1];
    const std::size_t first = tp.far_from[k];
    double v0[N], v2[N];
    for (int j = 0; j < N; ++j) {
      const double t = 0.5 * (a + b) + 0.5 * (b - a) * std::cos(pi * (j + 0.5) / N);
      v0[j] = v2[j] = 0.0;
      double a0, a2;
      if (!tp.near_integrated[k] && first <= n) {
        detail::cubic_moments(tp.piece[first - 1], tp.knot[first - 1], t, tp.knot[first], t, true,
                              a0, a2);
        v0[j] += a0;
        v2[j] += a2;
      }
      for (std::size_t p = first; p < n; ++p) {
        detail::cubic_moments(tp.piece[p], tp.knot[p], tp.knot[p], tp.knot[p + 1], t, false, a0,
                              a2);
        v0[j] += a0;
        v2[j] += a2;
      }
    }
    for (int i = 0; i < N; ++i) {
      double s0 = 0.0, s2 = 0.0;
      for (int j = 0; j < N; ++j) {
        s0 += v0[j] * std::cos(pi * i * (j + 0.5) / N);
        s2 += v2[j] * std::cos(pi * i * (j + 0.5) / N);
      }
      far0[k * N + i] = (i == 0 ? 1.0 : 2.0) / N * s0;
      far2[k * N + i] = (i == 0 ? 1.0 : 2.0) / N * s2;
    }
  }
}

Kinematics<double> kinematics(double ratio, double angle, double R) {
  const double w = 20.0, v = ratio * w * R;
  return {v * std::cos(angle), v * std::sin(angle), w};
}

}  // namespace

// On 200-point tables (even knots with a kink; random knots with noise) the O(n) fits give the
// chord integrals of the quadratic sums: against the brute-force sum over every piece at 4,000
// feet within 1e-14 of their largest value (3e-15 on both), and the resultants
// of the model equal, to 1e-13 of f N (f N R), those of the same model with its far series
// refitted from the quadratic sums.
TEST(DenseProfile, FarSeriesMatchTheQuadraticSums) {
  for (const PressureProfile& profile : {kinked_profile(200), random_knot_profile()}) {
    const ContactPatch patch = patch_of(profile);
    const ExactModel<double> m = make_exact_model(patch);
    EXPECT_LT(m.representation_error(), 1e-13) << describe(profile);
    double scale0 = 0.0, scale2 = 0.0, worst0 = 0.0, worst2 = 0.0;
    for (int i = 0; i < 4000; ++i) {
      const double t = (i + 0.5) / 4000.0;
      double M0, M2, B0, B2;
      detail::piecewise_chord_moments(m, t, M0, M2);
      brute_force_chord_moments(m, t, B0, B2);
      scale0 = std::max(scale0, std::abs(B0));
      scale2 = std::max(scale2, std::abs(B2));
      worst0 = std::max(worst0, std::abs(M0 - B0));
      worst2 = std::max(worst2, std::abs(M2 - B2));
    }
    EXPECT_LT(worst0, 1e-14 * scale0) << describe(profile);
    EXPECT_LT(worst2, 1e-14 * scale2) << describe(profile);

    TablePieces pieces = *m.table();
    quadratic_far_series(m, pieces.far_m0, pieces.far_m2);
    ExactModel<double> reference = m;
    reference.set_table(std::move(pieces), m.representation_error());
    const double fN = m.friction_scale * normal_load(patch), R = patch.radius_m;
    for (double ratio : {0.3, 0.999, 1.001, 2.0, 50.0}) {
      for (double angle : {0.0, 0.61, 2.0}) {
        const Kinematics<double> k = kinematics(ratio, angle, R);
        const auto a = exact_resultants(m, k, {1e-12}).resultants;
        const auto b = exact_resultants(reference, k, {1e-12}).resultants;
        EXPECT_NEAR(a.Fx, b.Fx, 1e-13 * fN) << describe(profile) << " " << ratio << " " << angle;
        EXPECT_NEAR(a.Fy, b.Fy, 1e-13 * fN) << describe(profile) << " " << ratio << " " << angle;
        EXPECT_NEAR(a.Mz, b.Mz, 1e-13 * fN * R)
            << describe(profile) << " " << ratio << " " << angle;
      }
    }
  }
}

// A 10^5-point table builds (docs/speed.md, "Dense tables") and agrees with the 10^4-point
// table of the same function
// to the interpolation error of the coarser one: their loads differ by 2.4e-10, their
// resultants by 2e-10 of f N (f N R) at most; checked to 2e-9. Their exact laws (rings summed
// on a tree of the pieces' moments) agree
// with the integrator within their certified bounds on 40 kinematics (every regime and
// direction; the 10^4-point law), and with each other within the two bounds and 2e-9.
TEST(DenseProfile, TenToTheFiveKnotsAgreeWithTenToTheFour) {
  ContactPatch coarse = patch_of(kinked_profile(10'000)), fine = patch_of(kinked_profile(100'000));
  coarse.kappa = fine.kappa = 0.8;
  const ExactModel<double> mc = make_exact_model(coarse), mf = make_exact_model(fine);
  EXPECT_EQ(mf.table()->piece.size(), 99'999u);
  EXPECT_LT(mc.representation_error(), 1e-13);
  EXPECT_LT(mf.representation_error(), 1e-13);
  const double fN = mc.friction_scale * normal_load(coarse), R = coarse.radius_m;
  EXPECT_NEAR(normal_load(fine), normal_load(coarse), 2e-9 * normal_load(coarse));
  for (double ratio : {0.3, 1.0, 2.0, 50.0}) {
    const Kinematics<double> k = kinematics(ratio, 0.61, R);
    const auto c = exact_resultants(mc, k, {1e-10});
    const auto f = exact_resultants(mf, k, {1e-10});
    EXPECT_TRUE(c.converged && f.converged) << ratio;
    EXPECT_NEAR(f.resultants.Fx, c.resultants.Fx, 2e-9 * fN) << ratio;
    EXPECT_NEAR(f.resultants.Fy, c.resultants.Fy, 2e-9 * fN) << ratio;
    EXPECT_NEAR(f.resultants.Mz, c.resultants.Mz, 2e-9 * fN * R) << ratio;
  }
  ExactLawOptions one_core;
  one_core.threads = 1;
  const ExactLaw lc = make_exact_law(mc, one_core), lf = make_exact_law(mf, one_core);
  EXPECT_TRUE(lc.reached);
  EXPECT_TRUE(lf.reached);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    const double angle = std::numbers::pi * U(rng), ratio = std::exp(5.0 * U(rng));
    Kinematics<double> k = kinematics(ratio, angle, R);
    if (i % 2) k.omega = -k.omega;
    const Resultants<double> a = exact_law_resultants(lc, k), b = exact_law_resultants(lf, k);
    const Resultants<double> e = exact_resultants(mc, k, {1e-12}).resultants;
    const double bound = lc.achieved + 1e-11, both = lc.achieved + lf.achieved + 2e-9;
    EXPECT_NEAR(a.Fx, e.Fx, bound * fN) << ratio << " " << angle;
    EXPECT_NEAR(a.Fy, e.Fy, bound * fN) << ratio << " " << angle;
    EXPECT_NEAR(a.Mz, e.Mz, bound * fN * R) << ratio << " " << angle;
    EXPECT_NEAR(b.Fx, a.Fx, both * fN) << ratio << " " << angle;
    EXPECT_NEAR(b.Fy, a.Fy, both * fN) << ratio << " " << angle;
    EXPECT_NEAR(b.Mz, a.Mz, both * fN * R) << ratio << " " << angle;
  }
}

// More than kMaxProfilePoints points: an error that names the number and the limit, from the
// table, a shape filled by hand, and a CSV (at the first row beyond the limit).
TEST(DenseProfile, TooManyPointsIsAClearError) {
  const std::size_t n = kMaxProfilePoints + 1;
  std::vector<double> rho(n), p(n, 1.0);
  for (std::size_t i = 0; i < n; ++i) rho[i] = static_cast<double>(i) / (n - 1);
  const std::string count = std::to_string(n), limit = std::to_string(kMaxProfilePoints);
  try {
    tabulated_profile(rho, p);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(count + " points"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("at most " + limit), std::string::npos) << e.what();
  }
  ContactPatch by_hand = seed_tire_patch();
  by_hand.profile.shape = TabulatedShape{rho, p, std::vector<double>(n, 0.0)};
  try {
    make_exact_model(by_hand);
    ADD_FAILURE() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(count + " points"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("at most " + limit), std::string::npos) << e.what();
  }
  const std::string path = contensou::test::temp_path("dense_profile_too_many.csv");
  {
    std::ofstream out(path);
    out.precision(17);
    out << "rho,pressure_Pa\n";
    for (std::size_t i = 0; i < n; ++i) out << rho[i] << ",2e5\n";
  }
  try {
    read_profile_csv(path);
    ADD_FAILURE() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), static_cast<int>(kMaxProfilePoints) + 2);  // header, then the rows
    EXPECT_NE(std::string(e.what()).find(count + " rows"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("at most " + limit), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
  // At the limit: accepted.
  rho.pop_back();
  p.pop_back();
  rho.back() = 1.0;
  EXPECT_NO_THROW(tabulated_profile(rho, p));
}
