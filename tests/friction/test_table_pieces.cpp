// Tabulated profiles in the exact resultants (impl/table_pieces.hpp, impl/table_partition.hpp):
// exact for the interpolant against annulus and ring oracles, dense and uneven tables, kinks
// at every knot, f(w) inside, Jets through the pieces.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "exact_oracles.hpp"

using namespace contensou;
using namespace contensou::test_support;

// Oracle for a tabulated profile: Gauss-Legendre in r on each annulus between knots (where
// the interpolant is smooth) and the trapezoid rule in the polar angle (spectral for a smooth
// periodic integrand: the centre of sliding must lie outside the patch).
Resultants<double> annulus_oracle(const ContactPatch& p, const std::vector<double>& rho_knots,
                                  const Kinematics<double>& k, int nt = 2048) {
  Resultants<double> out;
  const double R = p.radius_m;
  const GaussLegendreRule g = gauss_legendre(12);
  std::vector<double> edges{0.0};
  for (double r : rho_knots)
    if (r > 0.0) edges.push_back(r);
  for (std::size_t a = 0; a + 1 < edges.size(); ++a) {
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const double rho =
          0.5 * (edges[a] + edges[a + 1]) + 0.5 * (edges[a + 1] - edges[a]) * g.nodes[i];
      const double wr = 0.5 * (edges[a + 1] - edges[a]) * g.weights[i] * R * (rho * R);
      const double pr = p.reference_pressure_pa * shape_value(p.profile, rho);
      for (int j = 0; j < nt; ++j) {
        const double th = 2 * kPi * j / nt;
        const double x = rho * R * std::cos(th), y = rho * R * std::sin(th);
        const double sigma = pr * (1 + p.profile.kx * x / R + p.profile.ky * y / R);
        const double cx = k.vx - k.omega * y, cy = k.vy + k.omega * x, w = std::hypot(cx, cy);
        const double dA = wr * 2 * kPi / nt;
        const double tx = -sigma * p.friction * cx / w, ty = -sigma * p.friction * p.kappa * cy / w;
        out.Fx += tx * dA;
        out.Fy += ty * dA;
        out.Mz += (x * ty - y * tx) * dA;
      }
    }
  }
  return out;
}

// A 101-point table with a kink near the rim (a finite-element profile): the exact integrals
// take its pieces exactly (the only representation error is the far-knot series', ~1e-12);
// they agree with an independent annulus
// oracle of the same interpolant to the requested tolerance (centre of sliding outside), with
// the midpoint brute force elsewhere, and their estimate bounds the difference.
TEST(ExactResultants, TabulatedProfileIsExactForItsInterpolant) {
  std::vector<double> rho, pv;
  for (int i = 0; i <= 100; ++i) {
    const double r = i / 100.0;
    rho.push_back(r);
    pv.push_back(r < 0.9 ? 1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) : 0.7439 - 4.0 * (r - 0.9));
  }
  ContactPatch p = uniform_patch();
  p.profile = tabulated_profile(rho, pv);
  p.profile.kx = 0.12;
  p.kappa = 0.85;
  const ExactModel<double> m = make_exact_model(p);
  EXPECT_TRUE(m.table().has_value());
  EXPECT_LT(m.representation_error(), 1e-11);  // the far-knot series only
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  for (double ratio : {1.3, 4.0}) {
    const Kinematics<double> k{0.6 * ratio * 8.0, -0.8 * ratio * 8.0, 8.0 / R};
    const auto e = exact_resultants(m, k, {1e-10});
    const auto o = annulus_oracle(p, rho, k);
    EXPECT_NEAR(e.resultants.Fx, o.Fx, 1e-9 * fN) << ratio;
    EXPECT_NEAR(e.resultants.Fy, o.Fy, 1e-9 * fN) << ratio;
    EXPECT_NEAR(e.resultants.Mz, o.Mz, 1e-9 * fN * R) << ratio;
  }
  expect_matches_brute_force(p, m, {0.0, 0.3, 0.98});
  // With friction falling with slip speed inside the integrals (at 1e-7 the chords unbroken);
  // 1e-7: at 1e-10 a 101-point table with f(w) runs out of intervals.
  p.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 1.0, 1.0};
  expect_matches_brute_force(p, make_exact_model(p), {0.3, 1.02, 4.0}, 1e-7);
}

// A table with f(w) inside: its chords are broken at knot crossings from 1e-5 up (a single
// G15K31 panel first where g < 1e-3 on the whole chord), unbroken below; on random kinematics
// the estimate bounds the achieved error against the same integrals at 1e-8 (converged, their
// own estimate ~2.5e-9 f N added to the bound; 1e-13 costs 0.7 s per point) on every branch.
TEST(ExactResultants, TableWithSpeedLawErrorEstimateBoundsTheErrorOnEveryPartition) {
  std::vector<double> rho, pv;
  for (int i = 0; i <= 100; ++i) {
    rho.push_back(i / 100.0);
    const double r = rho.back();
    pv.push_back(r < 0.9 ? 1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) : 0.7439 - 4.0 * (r - 0.9));
  }
  ContactPatch p = seed_patch();
  p.profile = tabulated_profile(rho, pv);
  p.profile.kx = 0.14;
  p.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 1.0, 1.0};
  const ExactModel<double> m = make_exact_model(p);
  const double R = p.radius_m, fN = m.friction_scale * normal_load(p);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int i = 0; i < 16; ++i) {
    double ratio = std::pow(10.0, -2.0 + 4.0 * U(rng));
    if (i % 4 == 0) ratio = 1.0 + (U(rng) - 0.5) * 1e-2;
    const double dir = 2.0 * kPi * U(rng), w = (U(rng) < 0.5 ? -20.0 : 20.0);
    const double v = ratio * std::abs(w) * R;
    const Kinematics<double> k{v * std::cos(dir), v * std::sin(dir), w};
    const auto reference = exact_resultants(m, k, {1e-8});
    ASSERT_TRUE(reference.converged) << ratio;
    const Resultants<double>& ref = reference.resultants;
    const ResultantErrors& ref_err = reference.error;
    for (double tol : {1e-3, 1e-4, 1e-6}) {
      const auto r = exact_resultants(m, k, {tol});
      EXPECT_LE(r.error.Fx, tol * fN) << ratio << " " << tol;
      ASSERT_LE(std::abs(r.resultants.Fx - ref.Fx), r.error.Fx + ref_err.Fx) << ratio << " " << tol;
      ASSERT_LE(std::abs(r.resultants.Fy - ref.Fy), r.error.Fy + ref_err.Fy) << ratio << " " << tol;
      ASSERT_LE(std::abs(r.resultants.Mz - ref.Mz), r.error.Mz + ref_err.Mz) << ratio << " " << tol;
    }
  }
}

// A 201-point sampling of the seed series reproduces the series' resultants to the
// interpolation error (a cubic in t with monotone slopes: about 1e-6 of f N here).
TEST(ExactResultants, TabulatedSeedSeriesReproducesTheSeries) {
  ContactPatch series = seed_patch();
  series.profile.kx = 0.14;
  std::vector<double> rho, pv;
  for (int i = 0; i <= 200; ++i) {
    rho.push_back(i / 200.0);
    pv.push_back(shape_value(series.profile, rho.back()));
  }
  ContactPatch table = series;
  table.profile = tabulated_profile(rho, pv);
  table.profile.kx = 0.14;
  table.profile.keep_negative = true;
  const ExactModel<double> ms = make_exact_model(series), mt = make_exact_model(table);
  const double fN = series.friction * normal_load(series), R = series.radius_m;
  for (double ratio : {0.0, 0.2, 1.0, 5.0}) {
    const Kinematics<double> k{ratio * 1.0, 0.3 * ratio, 1.0 / R};
    const auto a = exact_resultants(ms, k, {1e-10}).resultants;
    const auto b = exact_resultants(mt, k, {1e-10}).resultants;
    EXPECT_NEAR(a.Fx, b.Fx, 1e-5 * fN) << ratio;
    EXPECT_NEAR(a.Fy, b.Fy, 1e-5 * fN) << ratio;
    EXPECT_NEAR(a.Mz, b.Mz, 1e-5 * fN * R) << ratio;
  }
}

// Oracle for a piecewise profile in every regime: rings about O, a decomposition unlike the
// integrator's chords through the centre of sliding r_c (d = |r_c|, gamma its direction). On a
// ring of radius r the integrand of psi = theta - gamma is analytic but for poles at psi =
// +-i |ln(r/d)|: 20-point Gauss-Legendre on panels doubling from psi = 0 (pi/4 2^-j, the
// first no wider than that distance) to pi, on both sides. In r: the knots and d are edges
// (the profile is a polynomial of degree 6 in r between knots; the ring through r_c has a
// log-singular slope), every interval is halved until it lies at least its width from d, and
// 8-point Gauss-Legendre on each. It matches Contensou's closed forms to ~1e-14 of f N.
Resultants<double> ring_oracle(const ContactPatch& p, const std::vector<double>& rho_knots,
                               const Kinematics<double>& k) {
  const double R = p.radius_m;
  const double rcx = -k.vy / k.omega, rcy = k.vx / k.omega;
  const double d = std::hypot(rcx, rcy), gamma = std::atan2(rcy, rcx);
  const GaussLegendreRule ga = gauss_legendre(20), gr = gauss_legendre(8);
  struct Node {
    double c, s, w;  // cos, sin of theta; weight
  };
  std::map<int, std::vector<Node>> grids;  // angular grids by level j
  auto grid = [&](int j) -> const std::vector<Node>& {
    if (const auto it = grids.find(j); it != grids.end()) return it->second;
    std::vector<double> e{0.0};
    for (double x = 0.25 * kPi * std::ldexp(1.0, -j); x < kPi; x *= 2.0) e.push_back(x);
    e.push_back(kPi);
    std::vector<Node> nodes;
    for (std::size_t a = 0; a + 1 < e.size(); ++a)
      for (std::size_t i = 0; i < ga.nodes.size(); ++i) {
        const double psi = 0.5 * (e[a] + e[a + 1]) + 0.5 * (e[a + 1] - e[a]) * ga.nodes[i];
        const double w = 0.5 * (e[a + 1] - e[a]) * ga.weights[i];
        for (double sg : {1.0, -1.0})
          nodes.push_back({std::cos(gamma + sg * psi), std::sin(gamma + sg * psi), w});
      }
    return grids.emplace(j, std::move(nodes)).first->second;
  };
  std::vector<double> edges{0.0, R};
  for (double r : rho_knots)
    if (r > 0.0 && r < 1.0) edges.push_back(r * R);
  if (d > 0.0 && d < R) edges.push_back(d);
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<double, double>> todo, parts;
  for (std::size_t a = 0; a + 1 < edges.size(); ++a)
    if (edges[a + 1] > edges[a]) todo.push_back({edges[a], edges[a + 1]});
  while (!todo.empty()) {
    const auto [a, b] = todo.back();
    todo.pop_back();
    const double dist = d >= b ? d - b : (d <= a ? a - d : 0.0);
    if (dist >= b - a || b - a < 1e-15 * R) {
      parts.push_back({a, b});
      continue;
    }
    const double mid = 0.5 * (a + b);
    todo.push_back({a, mid});
    todo.push_back({mid, b});
  }
  // Per ring a plain sum, over the rings a compensated one (Neumaier): ~10^5 rings.
  std::array<double, 3> sum{}, carry{};
  auto add = [&](int c, double v) {
    const double t = sum[c] + v;
    carry[c] += std::abs(sum[c]) >= std::abs(v) ? (sum[c] - t) + v : (v - t) + sum[c];
    sum[c] = t;
  };
  for (const auto& [a, b] : parts) {
    for (std::size_t i = 0; i < gr.nodes.size(); ++i) {
      const double r = 0.5 * (a + b) + 0.5 * (b - a) * gr.nodes[i];
      const double wr = 0.5 * (b - a) * gr.weights[i] * r;
      const double pr = p.reference_pressure_pa * shape_value(p.profile, r / R);
      const double delta = d > 0.0 ? std::abs(std::log(r / d)) : 1e300;
      const int j =
          static_cast<int>(std::clamp(std::ceil(std::log2(0.25 * kPi / delta)), 0.0, 60.0));
      double fx = 0.0, fy = 0.0, mz = 0.0;
      for (const Node& n : grid(j)) {
        const double x = r * n.c, y = r * n.s;
        const double sigma = pr * (1 + p.profile.kx * x / R + p.profile.ky * y / R);
        const double cx = k.vx - k.omega * y, cy = k.vy + k.omega * x, w = std::hypot(cx, cy);
        if (w == 0.0) continue;
        const double tx = -sigma * p.friction * cx / w, ty = -sigma * p.friction * p.kappa * cy / w;
        fx += n.w * tx;
        fy += n.w * ty;
        mz += n.w * (x * ty - y * tx);
      }
      add(0, wr * fx);
      add(1, wr * fy);
      add(2, wr * mz);
    }
  }
  return {sum[0] + carry[0], sum[1] + carry[1], sum[2] + carry[2]};
}

// A dense table with a kink near the rim (test_support::kinked_table_profile), kx = 0.14.
ContactPatch dense_table_patch(int n, std::vector<double>& rho) {
  ContactPatch p = seed_patch();
  p.profile = test_support::kinked_table_profile(n, &rho);
  p.profile.kx = 0.14;
  return p;
}

// The regimes |v| / (|omega| R) of the dense-table tests, sliding at 35 degrees.
constexpr double kDenseRatios[] = {0.5, 0.999, 1.0, 1.001, 2.0, 100.0};

Kinematics<double> dense_kinematics(double ratio, double R) {
  const double w = 20.0, v = ratio * w * R;
  return {v * std::cos(0.61), v * std::sin(0.61), w};
}

bool estimate_meets(const ExactResult<double>& r, double tol, double fN, double R) {
  return r.error.Fx <= tol * fN && r.error.Fy <= tol * fN && r.error.Mz <= tol * fN * R;
}

TEST(ExactResultants, RingOracleMatchesContensouClosedForms) {
  const ContactPatch p = uniform_patch();
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  for (double eps : {0.5, 0.999, 1.0, 1.001, 2.0}) {
    const Kinematics<double> k{eps * 0.7 * std::cos(0.61), eps * 0.7 * std::sin(0.61), -0.7 / R};
    const Resultants<double> o = ring_oracle(p, {}, k);
    const auto [fpar, mz] = uniform_closed_form(eps);
    EXPECT_NEAR(-(o.Fx * std::cos(0.61) + o.Fy * std::sin(0.61)) / fN, fpar, 1e-13) << eps;
    EXPECT_NEAR(o.Mz / (fN * R), mz, 1e-13) << eps;
  }
}

// The converged flag agrees with the estimate: true exactly when every component of the
// estimate (floor and representation error included) meets the tolerance, on dense tables in
// every regime (a 10,001-point table at 1e-6 reported converged with an estimate of 2.3e-6 of
// f N, a 1,001-point one at 1e-10 with 1.5e-9) and on the other profile kinds.
TEST(ExactResultants, ConvergedFlagAgreesWithTheEstimate) {
  std::vector<double> rho;
  std::vector<ContactPatch> patches = {dense_table_patch(1001, rho), dense_table_patch(10001, rho),
                                       seed_patch(), uniform_patch()};
  ContactPatch hertz = uniform_patch();
  hertz.profile = hertz_profile();
  patches.push_back(hertz);
  ContactPatch speed = seed_patch();
  speed.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 5.0, 1.0};
  patches.push_back(speed);
  for (const ContactPatch& p : patches) {
    const ExactModel<double> m = make_exact_model(p);
    const double fN = m.friction_scale * normal_load(p), R = p.radius_m;
    for (double ratio : kDenseRatios) {
      for (double tol : {1e-6, 1e-8, 1e-10, 1e-12}) {
        if (p.slip_speed_friction && tol < 1e-10) continue;  // f(w) at 1e-12: slow
        const auto r = exact_resultants(m, dense_kinematics(ratio, R), {tol});
        EXPECT_EQ(r.converged, estimate_meets(r, tol, fN, R))
            << describe(p.profile) << " ratio " << ratio << " tol " << tol << " estimate "
            << r.error.Fx / fN << " " << r.error.Fy / fN << " " << r.error.Mz / (fN * R);
      }
    }
    // Pure sliding and no motion: the same rule.
    for (const Kinematics<double>& k : {Kinematics<double>{1.0, 0.5, 0.0}, Kinematics<double>{}}) {
      const auto r = exact_resultants(m, k, {1e-12});
      EXPECT_EQ(r.converged, estimate_meets(r, 1e-12, fN, R)) << describe(p.profile);
    }
  }
}

// Dense tables reach the requested tolerance in every regime, against the ring oracle (which
// does not use the integrator's chords or far-knot series), converged and with an estimate
// that bounds the achieved error. While the far-knot sums were antiderivatives at the knots,
// which cancel, the 1,001- and 10,001-point tables stopped at 3e-11 and 1e-8 of f N.
TEST(ExactResultants, DenseTablesReachTheToleranceAgainstTheRingOracle) {
  for (int n : {1001, 10001}) {
    std::vector<double> rho;
    const ContactPatch p = dense_table_patch(n, rho);
    const ExactModel<double> m = make_exact_model(p);
    const double fN = p.friction * normal_load(p), R = p.radius_m;
    for (double ratio : kDenseRatios) {
      const Kinematics<double> k = dense_kinematics(ratio, R);
      const Resultants<double> o = ring_oracle(p, rho, k);
      for (double tol : {1e-6, 1e-8, 1e-10, 1e-12}) {
        const auto r = exact_resultants(m, k, {tol});
        std::ostringstream where;
        where << n << " points, ratio " << ratio << ", tol " << tol;
        const std::string at = where.str();
        EXPECT_TRUE(r.converged) << at;
        const Resultants<double> e{std::abs(r.resultants.Fx - o.Fx),
                                   std::abs(r.resultants.Fy - o.Fy),
                                   std::abs(r.resultants.Mz - o.Mz)};
        EXPECT_LE(e.Fx, tol * fN) << at;
        EXPECT_LE(e.Fy, tol * fN) << at;
        EXPECT_LE(e.Mz, tol * fN * R) << at;
        // The oracle's own error (~1e-14 of f N) added to the estimate.
        EXPECT_LE(e.Fx, r.error.Fx + 1e-14 * fN) << at;
        EXPECT_LE(e.Fy, r.error.Fy + 1e-14 * fN) << at;
        EXPECT_LE(e.Mz, r.error.Mz + 1e-14 * fN * R) << at;
      }
    }
  }
}

// A table with a kink at every knot (1,001 points of noisy data: 1 % noise on the smooth part):
// the thinned crossings and the 640 intervals on the stack do not suffice (unconverged at
// 1e-10, 5e-11 ... 1.5e-9 achieved); the outer rule then starts again from every crossing with
// its intervals on the heap and meets the tolerance in every regime, converged, the estimate
// bounding the error against the ring oracle.
TEST(ExactResultants, TableWithAKinkAtEveryKnotReachesTheTolerance) {
  std::vector<double> rho, pv;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int i = 0; i <= 1000; ++i) {
    const double r = i / 1000.0;
    rho.push_back(r);
    pv.push_back(1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) + 0.01 * U(rng));
  }
  ContactPatch p = seed_patch();
  p.profile = tabulated_profile(rho, pv);
  p.profile.kx = 0.14;
  const ExactModel<double> m = make_exact_model(p);
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  for (double ratio : kDenseRatios) {
    const Kinematics<double> k = dense_kinematics(ratio, R);
    const Resultants<double> o = ring_oracle(p, rho, k);
    for (double tol : {1e-6, 1e-10}) {
      const auto r = exact_resultants(m, k, {tol});
      EXPECT_TRUE(r.converged) << ratio << " " << tol;
      EXPECT_LE(std::abs(r.resultants.Fx - o.Fx), std::min(tol * fN, r.error.Fx + 1e-14 * fN))
          << ratio << " " << tol;
      EXPECT_LE(std::abs(r.resultants.Fy - o.Fy), std::min(tol * fN, r.error.Fy + 1e-14 * fN))
          << ratio << " " << tol;
      EXPECT_LE(std::abs(r.resultants.Mz - o.Mz),
                std::min(tol * fN * R, r.error.Mz + 1e-14 * fN * R))
          << ratio << " " << tol;
    }
  }
}

// 1,001 random knots (intervals from 1e-7 to 1e-2 wide side by side) with 5 % noise.
ContactPatch random_knot_patch(std::vector<double>& rho) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  rho = {0.0, 1.0};
  for (int i = 0; i < 999; ++i) rho.push_back(U(rng));
  std::sort(rho.begin(), rho.end());
  std::vector<double> pv;
  for (double r : rho)
    pv.push_back(1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) + 0.05 * (U(rng) - 0.5));
  ContactPatch p = seed_patch();
  p.profile = tabulated_profile(rho, pv);
  return p;
}

// Tables with uneven knots: 1,001 random knots with 5 % noise (intervals from 1e-7 to 1e-2
// wide side by side) and 401 knots from rho = 0.3 after one at the centre with the same value
// (a constant piece below them, one wide interval).
// Where a chord's near pieces are much narrower than their distance they are integrated, not
// summed as antiderivatives at the knots (with those the random table's far-knot series
// deviated by 1e-9); at 1e-12 in three regimes against the ring oracle.
TEST(ExactResultants, TablesWithUnevenKnotsStayExact) {
  std::vector<std::vector<double>> rhos(2), ps(2);
  rhos[1].push_back(0.0);
  ps[1].push_back(1.0 + 0.4 * 0.09 - 0.9 * std::pow(0.3, 4));  // the value at rho = 0.3
  for (int i = 0; i <= 400; ++i) {
    rhos[1].push_back(0.3 + 0.7 * i / 400.0);
    ps[1].push_back(1.0 + 0.4 * std::pow(rhos[1].back(), 2) - 0.9 * std::pow(rhos[1].back(), 4));
  }
  for (int t = 0; t < 2; ++t) {
    ContactPatch p = t == 0 ? random_knot_patch(rhos[0]) : seed_patch();
    if (t == 1) p.profile = tabulated_profile(rhos[t], ps[t]);
    p.profile.kx = 0.1;
    p.profile.ky = -0.05;
    p.kappa = 0.8;
    const ExactModel<double> m = make_exact_model(p);
    EXPECT_LT(m.representation_error(), 1e-13) << t;
    const double fN = p.friction * normal_load(p), R = p.radius_m;
    for (double ratio : {0.5, 1.001, 2.0}) {
      const Kinematics<double> k = dense_kinematics(ratio, R);
      const Resultants<double> o = ring_oracle(p, rhos[t], k);
      const auto r = exact_resultants(m, k, {1e-12});
      EXPECT_TRUE(r.converged) << t << " " << ratio;
      EXPECT_NEAR(r.resultants.Fx, o.Fx, 1e-12 * fN) << t << " " << ratio;
      EXPECT_NEAR(r.resultants.Fy, o.Fy, 1e-12 * fN) << t << " " << ratio;
      EXPECT_NEAR(r.resultants.Mz, o.Mz, 1e-12 * fN * R) << t << " " << ratio;
    }
  }
}

// Jets through a dense table's chords (knot terms on the even table; on the random one also
// integrated near pieces, whose Gauss nodes move with the foot, the piece under the foot from
// w = 0, no square root of 0 differentiated) match central differences in (vx, vy, omega).
TEST(ExactResultants, DenseTableJetsMatchCentralDifferences) {
  using J = ceres::Jet<double, 3>;
  std::vector<double> rho;
  for (const ContactPatch& p : {dense_table_patch(1001, rho), random_knot_patch(rho)}) {
    const ExactModel<double> m = make_exact_model(p);
    const ExactModel<J> mj = promote<J>(m);
    const double fN = p.friction * normal_load(p), R = p.radius_m;
    for (double ratio : {0.5, 2.0}) {
      const Kinematics<double> k = dense_kinematics(ratio, R);
      const auto rj =
          exact_resultants(mj, Kinematics<J>{J(k.vx, 0), J(k.vy, 1), J(k.omega, 2)}, {1e-12});
      const J rows[3] = {rj.resultants.Fx, rj.resultants.Fy, rj.resultants.Mz};
      const double h[3] = {1e-6 * 20.0 * R, 1e-6 * 20.0 * R, 1e-6 * 20.0};
      for (int j = 0; j < 3; ++j) {
        double xp[3] = {k.vx, k.vy, k.omega}, xm[3] = {k.vx, k.vy, k.omega};
        xp[j] += h[j];
        xm[j] -= h[j];
        const auto rp = exact_resultants(m, {xp[0], xp[1], xp[2]}, {1e-13}).resultants;
        const auto rm = exact_resultants(m, {xm[0], xm[1], xm[2]}, {1e-13}).resultants;
        const double fd[3] = {(rp.Fx - rm.Fx) / (2 * h[j]), (rp.Fy - rm.Fy) / (2 * h[j]),
                              (rp.Mz - rm.Mz) / (2 * h[j])};
        // Row scales: f N per unit of the variable (times R for Mz).
        const double per = j < 2 ? 1.0 / (20.0 * R) : 1.0 / 20.0;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(rows[c].v[j], fd[c], 1e-7 * fN * per * (c == 2 ? R : 1.0))
              << describe(p.profile) << " " << ratio << " row " << c << " col " << j;
      }
    }
  }
}
