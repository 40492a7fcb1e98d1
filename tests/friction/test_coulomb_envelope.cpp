// What any rigid Coulomb patch can produce (coulomb_envelope.hpp): the ring's closed forms
// against quadrature, the envelope's limits and maximiser, the exact integrals of axisymmetric
// and shifted pressures against the bounds, point contacts, and the row check's edges.
#include "contensou/friction/coulomb_envelope.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "closed_forms.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "patches.hpp"

using namespace contensou;
using namespace contensou::test_support;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Adaptive 5-point Gauss-Legendre of a pair of integrands on [a, b] (whole vs halves).
using Pair = std::pair<double, double>;
Pair gauss5(const std::function<Pair(double)>& f, double a, double b) {
  static constexpr double x[] = {0.0, 0.5384693101056831, 0.9061798459386640};
  static constexpr double w[] = {0.5688888888888889, 0.4786286704993665, 0.2369268850561891};
  const double m = 0.5 * (a + b), h = 0.5 * (b - a);
  Pair s = f(m);
  s.first *= w[0];
  s.second *= w[0];
  for (int i = 1; i < 3; ++i) {
    const Pair l = f(m - h * x[i]), r = f(m + h * x[i]);
    s.first += w[i] * (l.first + r.first);
    s.second += w[i] * (l.second + r.second);
  }
  return {h * s.first, h * s.second};
}
Pair adaptive(const std::function<Pair(double)>& f, double a, double b, const Pair& whole,
              double tol, int depth) {
  const double m = 0.5 * (a + b);
  const Pair l = gauss5(f, a, m), r = gauss5(f, m, b);
  const Pair both{l.first + r.first, l.second + r.second};
  if (depth > 50 ||
      (std::abs(both.first - whole.first) < tol && std::abs(both.second - whole.second) < tol))
    return both;
  const Pair L = adaptive(f, a, m, l, 0.5 * tol, depth + 1);
  const Pair R = adaptive(f, m, b, r, 0.5 * tol, depth + 1);
  return {L.first + R.first, L.second + R.second};
}

// The ring straight from its definition (v along +x, omega > 0, unit radius): the means over
// the ring angle t of (s - sin t)/D and (1 - s sin t)/D, D = |vc| = sqrt(1 + s^2 - 2 s sin t),
// split at t = pi/2 where D may vanish (s = 1: the integrands are bounded but kinked there).
Pair ring_by_quadrature(double s) {
  const auto f = [s](double t) -> Pair {
    const double st = std::sin(t), ct = std::cos(t);
    const double cx = s - st, cy = ct, d = std::hypot(cx, cy);  // vc / (omega a)
    if (d == 0.0) return {0.0, 0.0};
    return {cx / d, (1.0 - s * st) / d};  // -F_x per unit load, -Mz / a per unit load
  };
  const double a = -0.5 * kPi, m = 0.5 * kPi, b = 1.5 * kPi;
  const Pair l = adaptive(f, a, m, gauss5(f, a, m), 1e-13, 0);
  const Pair r = adaptive(f, m, b, gauss5(f, m, b), 1e-13, 0);
  return {(l.first + r.first) / (2 * kPi), (l.second + r.second) / (2 * kPi)};
}

// eps over 0.05 ... 20, log-spaced, and the points about eps = 1.
std::vector<double> eps_grid() {
  std::vector<double> e;
  for (int i = 0; i < 25; ++i) e.push_back(0.05 * std::pow(400.0, i / 24.0));
  for (double x : {0.999, 1.0, 1.001}) e.push_back(x);
  return e;
}

// A patch of the given profile with the round numbers of uniform_patch (R = 0.1 m).
ContactPatch patch_with(const PressureProfile& profile) {
  ContactPatch p = uniform_patch();
  p.profile = profile;
  return p;
}

// Kinematics at ratio eps, sliding direction phi, spin sign; omega R = 0.7 m/s.
Kinematics<double> twist(double eps, double phi, double spin_sign, double R) {
  const double u = 0.7, v = eps * u;
  return {v * std::cos(phi), v * std::sin(phi), spin_sign * u / R};
}

// Force and torque of point contacts with weights w at points r (friction on the body).
Resultants<double> point_contacts(const Kinematics<double>& k,
                                  const std::vector<std::pair<double, double>>& r,
                                  const std::vector<double>& w) {
  Resultants<double> out;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const auto [x, y] = r[i];
    const double cx = k.vx - k.omega * y, cy = k.vy + k.omega * x, n = std::hypot(cx, cy);
    const double tx = -w[i] * cx / n, ty = -w[i] * cy / n;
    out.Fx += tx;
    out.Fy += ty;
    out.Mz += x * ty - y * tx;
  }
  return out;
}

}  // namespace

TEST(CoulombEnvelope, RingClosedFormsMatchQuadratureOverTheRingAngle) {
  for (double s : {0.0, 1e-3, 0.05, 0.3, 0.7, 0.9, 0.999, 1.0, 1.001, 1.1, 1.5, 3.0, 20.0, 1e3}) {
    const RingResultants ring = ring_resultants(s);
    const Pair q = ring_by_quadrature(s);
    EXPECT_NEAR(ring.force, q.first, 1e-11) << "s = " << s;
    EXPECT_NEAR(ring.torque, q.second, 1e-11) << "s = " << s;
  }
  // Limits: P -> s/2, Q -> 1 (s -> 0); P -> 1, Q -> 1/(2s) (s -> inf); duality P(1/s) = Q(s).
  EXPECT_NEAR(ring_resultants(1e-4).force / 0.5e-4, 1.0, 1e-7);
  EXPECT_NEAR(ring_resultants(1e-4).torque, 1.0, 1e-8);
  EXPECT_NEAR(ring_resultants(1e4).force, 1.0, 1e-8);
  EXPECT_NEAR(ring_resultants(1e4).torque * 2e4, 1.0, 1e-7);
  EXPECT_NEAR(ring_resultants(kInf).force, 1.0, 1e-15);
  EXPECT_EQ(ring_resultants(kInf).torque, 0.0);
  for (double s : {0.01, 0.2, 0.6, 0.95}) {
    EXPECT_NEAR(ring_resultants(1 / s).force, ring_resultants(s).torque, 1e-14) << s;
    EXPECT_NEAR(ring_resultants(1 / s).torque, ring_resultants(s).force, 1e-14) << s;
  }
}

TEST(CoulombEnvelope, EnvelopeLimitsDualityAndValues) {
  EXPECT_NEAR(axisymmetric_torque_ratio_envelope(1.0), 1.0, 1e-15);
  for (double e : eps_grid()) {
    EXPECT_NEAR(axisymmetric_torque_ratio_envelope(e) * axisymmetric_torque_ratio_envelope(1 / e),
                1.0, 1e-13)
        << e;
    EXPECT_NEAR(axisymmetric_torque_ratio_envelope(e), ring_torque_ratio(e, 1.0), 1e-13 / e) << e;
  }
  EXPECT_NEAR(1e-5 * axisymmetric_torque_ratio_envelope(1e-5), 2.0, 1e-8);
  EXPECT_NEAR(2e5 * axisymmetric_torque_ratio_envelope(1e5), 1.0, 1e-8);
  EXPECT_EQ(axisymmetric_torque_ratio_envelope(0.0), kInf);
  EXPECT_EQ(axisymmetric_torque_ratio_envelope(kInf), 0.0);
  // The ring of radius 1 by quadrature: rho Q / P at rho = 1.
  for (double e : {0.5, 1.5, 2.0, 3.0, 5.0, 10.0}) {
    const Pair q = ring_by_quadrature(e);
    EXPECT_NEAR(axisymmetric_torque_ratio_envelope(e), q.second / q.first, 1e-9) << e;
  }
  EXPECT_NEAR(axisymmetric_torque_ratio_envelope(2.0), 0.276871789, 1e-9);
  EXPECT_NEAR(axisymmetric_torque_ratio_envelope(0.5), 3.611780042, 1e-9);
}

// The best ring is the rim ring: a grid of 4000 radii and a golden-section refinement about
// the grid's best find nothing above ring_torque_ratio(eps, 1).
TEST(CoulombEnvelope, BestRingIsAtTheRim) {
  for (double e : eps_grid()) {
    double best = 0.0, best_rho = 0.0, prev = 0.0;
    for (int i = 1; i <= 4000; ++i) {
      const double rho = i / 4000.0, g = ring_torque_ratio(e, rho);
      EXPECT_GE(g, prev * (1 - 1e-14)) << "not increasing at eps = " << e << ", rho = " << rho;
      prev = g;
      if (g > best) best = g, best_rho = rho;
    }
    double a = std::max(1e-6, best_rho - 1e-3), b = std::min(1.0, best_rho + 1e-3);
    const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
    for (int it = 0; it < 60; ++it) {
      const double c = b - gr * (b - a), d = a + gr * (b - a);
      if (ring_torque_ratio(e, c) > ring_torque_ratio(e, d)) {
        b = d;
      } else {
        a = c;
      }
    }
    best = std::max(best, ring_torque_ratio(e, 0.5 * (a + b)));
    EXPECT_EQ(best_rho, 1.0) << e;
    EXPECT_LE(best, axisymmetric_torque_ratio_envelope(e) * (1 + 1e-14)) << e;
  }
}

// Uniform, Hertz, random tables and clipped random cosine series: the exact integrals stay
// inside every bound at eps over 0.05 ... 20 (any direction, both spins): angle 0, ratio below
// Lambda(eps), Mz omega < 0, no flag.
TEST(CoulombEnvelope, ExactIntegralsOfAxisymmetricPressuresStayInside) {
  std::mt19937 rng(20240611);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::pair<std::string, PressureProfile>> profiles = {{"uniform", uniform_profile()},
                                                                   {"Hertz", hertz_profile()}};
  for (int i = 0; i < 4; ++i) {
    std::vector<double> rho, p;
    for (int j = 0; j <= 8; ++j) rho.push_back(j / 8.0), p.push_back(2.0 * unit(rng));
    profiles.push_back({"table " + std::to_string(i), tabulated_profile(rho, p)});
  }
  for (int i = 0; i < 3; ++i) {  // a_0 >= sum |a_k|: non-negative everywhere
    std::vector<double> a{0.0};
    for (int j = 0; j < 5; ++j) a.push_back(unit(rng) - 0.5), a[0] += std::abs(a.back());
    a[0] *= 1.0 + 0.2 * unit(rng);
    profiles.push_back({"series " + std::to_string(i), cosine_series_profile(0.5 + unit(rng), a)});
  }
  for (const auto& [name, profile] : profiles) {
    const ContactPatch patch = patch_with(profile);
    const ExactModel<double> m = make_exact_model(patch);
    const double R = patch.radius_m, fNR = patch.friction * normal_load(patch) * R;
    for (double e : eps_grid()) {
      const Kinematics<double> k = twist(e, 2 * kPi * unit(rng), unit(rng) < 0.5 ? -1.0 : 1.0, R);
      const ExactResult<double> r = exact_resultants(m, k, {1e-11});
      ASSERT_TRUE(r.converged) << name << " " << e;
      const Resultants<double>& w = r.resultants;
      const RowEnvelopeCheck c = check_row_against_patches(k, w.Fx, w.Fy, w.Mz, R);
      ASSERT_TRUE(c.angle_checked && c.torque_ratio_checked && c.torque_sign_checked);
      EXPECT_NEAR(c.force_angle_rad, 0.0, 1e-9) << name << " eps = " << e;
      EXPECT_LE(c.torque_ratio, c.axisymmetric_torque_bound) << name << " eps = " << e;
      EXPECT_LT(w.Mz * k.omega, 0.0) << name << " eps = " << e;
      EXPECT_LT(w.Mz * std::copysign(1.0, k.omega), -1e-4 * fNR) << name << " eps = " << e;
      EXPECT_FALSE(c.outside_any_patch || c.above_axisymmetric_torque || c.torque_drives_spin)
          << name << " eps = " << e;
    }
  }
}

// Pressure only in a band at the rim, rho in [1 - delta, 1]: its ratio approaches Lambda from
// below as the band narrows (the rim ring is the maximiser).
TEST(CoulombEnvelope, RimHeavyPressureApproachesTheEnvelope) {
  for (double e : {0.1, 0.5, 0.9, 1.0, 1.2, 2.0, 5.0, 15.0}) {
    double gap_prev = kInf;
    for (double delta : {0.05, 0.01, 0.002}) {
      const ContactPatch patch =
          patch_with(tabulated_profile({0.0, 1.0 - delta, 1.0}, {0.0, 0.0, 1.0}));
      const ExactModel<double> m = make_exact_model(patch);
      const Kinematics<double> k = twist(e, 0.4, 1.0, patch.radius_m);
      const Resultants<double> w = exact_resultants(m, k, {1e-11}).resultants;
      const RowEnvelopeCheck c = check_row_against_patches(k, w.Fx, w.Fy, w.Mz, patch.radius_m);
      const double lambda = axisymmetric_torque_ratio_envelope(e);
      const double gap = (lambda - c.torque_ratio) / lambda;
      EXPECT_GT(gap, 0.0) << "eps = " << e << " delta = " << delta;
      EXPECT_LT(gap, 3.0 * delta) << "eps = " << e << " delta = " << delta;
      EXPECT_LT(gap, gap_prev) << "eps = " << e << " delta = " << delta;
      gap_prev = gap;
    }
  }
}

// Contensou's closed forms (theory.md section 3): the uniform patch's ratio is strictly below
// Lambda, and above 1 for eps < 1 (so no bound of 1 can hold there).
TEST(CoulombEnvelope, UniformClosedFormsLieStrictlyBelowTheEnvelope) {
  for (double e : eps_grid()) {
    const auto [fpar, mz] = uniform_closed_form(e);
    const double lambda = axisymmetric_torque_ratio_envelope(e);
    EXPECT_LT(mz / fpar, 0.6 * lambda) << e;
    EXPECT_GT(mz / fpar, 0.25 * lambda) << e;
    if (e < 0.6) {
      EXPECT_GT(mz / fpar, 1.0) << e;
    }
    const RowEnvelopeCheck c =
        check_row_against_patches({e, 0.0, 1.0}, -fpar, 0.0, -mz, 1.0);  // R = 1, omega R = 1
    EXPECT_FALSE(c.outside_any_patch || c.above_axisymmetric_torque || c.torque_drives_spin) << e;
  }
}

// Point contacts and their positive combinations anywhere in the disk lie inside "any patch"
// (eps >= 1: angle within asin(1/eps), ratio <= 1); the bounds are reached.
TEST(CoulombEnvelope, PointContactsAndTheirCombinationsLieInsideAnyPatch) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double R = 0.1;
  EnvelopeCheckOptions rounding;
  rounding.angle_margin_rad = 1e-12;
  rounding.ratio_margin = 1e-12;
  for (int trial = 0; trial < 4000; ++trial) {
    const double e =
        trial % 4 == 0 ? 1.0 : (trial % 4 == 1 ? 0.05 + unit(rng) : 1 + 19 * unit(rng));
    const Kinematics<double> k = twist(e, 2 * kPi * unit(rng), unit(rng) < 0.5 ? -1.0 : 1.0, R);
    std::vector<std::pair<double, double>> pts;
    std::vector<double> w;
    const int n = 1 + trial % 3;
    for (int i = 0; i < n; ++i) {
      const double rr = R * (unit(rng) < 0.5 ? 1.0 : std::sqrt(unit(rng))),
                   th = 2 * kPi * unit(rng);
      pts.push_back({rr * std::cos(th), rr * std::sin(th)});
      w.push_back(0.1 + unit(rng));
    }
    const Resultants<double> f = point_contacts(k, pts, w);
    const RowEnvelopeCheck c = check_row_against_patches(k, f.Fx, f.Fy, f.Mz, R, rounding);
    EXPECT_FALSE(c.outside_any_patch)
        << "eps = " << e << " ratio " << c.torque_ratio << " angle " << c.force_angle_rad;
  }
  // Reached: a rim scan at eps = 2 finds |theta| = asin(1/2) and ratio 1.
  const Kinematics<double> k = twist(2.0, 0.0, 1.0, R);
  double max_angle = 0.0, max_ratio = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double th = 2 * kPi * i / 100000;
    const Resultants<double> f = point_contacts(k, {{R * std::cos(th), R * std::sin(th)}}, {1.0});
    const RowEnvelopeCheck c = check_row_against_patches(k, f.Fx, f.Fy, f.Mz, R);
    max_angle = std::max(max_angle, std::abs(c.force_angle_rad));
    max_ratio = std::max(max_ratio, c.torque_ratio);
  }
  EXPECT_NEAR(max_angle, std::asin(0.5), 1e-6);
  EXPECT_NEAR(max_ratio, 1.0, 1e-9);
}

// A point contact at the rim (F = -e_vc): outside the axisymmetric envelope, inside any patch;
// on the side where the rim moves with the sliding it drives the spin.
TEST(CoulombEnvelope, RimPointContactIsAboveTheAxisymmetricEnvelopeOnly) {
  const double R = 0.2;
  EnvelopeCheckOptions rounding;  // the row sits on the bound 1: allow its rounding
  rounding.ratio_margin = 1e-12;
  for (double e : {1.5, 3.0, 10.0}) {
    const Kinematics<double> k = twist(e, 0.0, 1.0, R);  // v along +x, omega > 0
    for (double y : {-R, R}) {
      const Resultants<double> f = point_contacts(k, {{0.0, y}}, {3.0});
      const RowEnvelopeCheck c = check_row_against_patches(k, f.Fx, f.Fy, f.Mz, R, rounding);
      EXPECT_NEAR(c.torque_ratio, 1.0, 1e-12);
      EXPECT_NEAR(c.force_angle_rad, 0.0, 1e-15);
      EXPECT_FALSE(c.outside_any_patch) << e;
      EXPECT_TRUE(c.above_axisymmetric_torque) << e;
      EXPECT_EQ(c.torque_drives_spin, y > 0) << e << " y = " << y;
    }
  }
}

TEST(CoulombEnvelope, RowsBeyondTheBoundsAreOutsideAnyPatch) {
  const double R = 0.1;
  const Kinematics<double> k{2.0 * 0.7, 0.0, 0.7 / R};  // eps = 2
  // Ratio 1.2, force along -v.
  RowEnvelopeCheck c = check_row_against_patches(k, -10.0, 0.0, -1.2 * 10.0 * R, R);
  EXPECT_NEAR(c.torque_ratio, 1.2, 1e-12);
  EXPECT_TRUE(c.outside_any_patch);
  EXPECT_TRUE(c.above_axisymmetric_torque);
  EXPECT_FALSE(c.torque_drives_spin);
  EXPECT_FALSE(check_row_against_patches(k, -10.0, 0.0, -1.2 * 10.0 * R, R, {0.0, 0.25, 1e-6})
                   .outside_any_patch);  // within the margin
  // Angle 0.6 > asin(1/2) = 0.5236 (counter-clockwise from v to -F), no torque.
  c = check_row_against_patches(k, -std::cos(0.6), -std::sin(0.6), 0.0, R);
  EXPECT_NEAR(c.force_angle_rad, 0.6, 1e-15);
  EXPECT_NEAR(c.force_angle_bound_rad, std::asin(0.5), 1e-15);
  EXPECT_TRUE(c.outside_any_patch);
  EXPECT_FALSE(
      check_row_against_patches(k, -std::cos(0.5), -std::sin(0.5), 0.0, R).outside_any_patch);
  // The same rows at eps = 0.5: no bound of any patch.
  const Kinematics<double> slow{0.5 * 0.7, 0.0, 0.7 / R};
  EXPECT_FALSE(check_row_against_patches(slow, -10.0, 0.0, -1.2 * 10.0 * R, R).outside_any_patch);
  EXPECT_FALSE(
      check_row_against_patches(slow, -std::cos(2.0), -std::sin(2.0), 0.0, R).outside_any_patch);
}

// A linear shift of the pressure across the sliding (ky > 0, v along +x, omega > 0) gives
// Mz omega > 0 at large eps: as omega -> 0, Mz -> pi ky f p* R^3 A^3 (header, point 3).
TEST(CoulombEnvelope, ShiftedPressureCanDriveTheSpin) {
  ContactPatch patch = uniform_patch();
  patch.profile.ky = 0.5;
  const ExactModel<double> m = make_exact_model(patch);
  const double R = patch.radius_m, fNR = patch.friction * normal_load(patch) * R;
  const double limit = kPi * 0.5 * patch.friction * patch.reference_pressure_pa * std::pow(R, 3) *
                       moment(patch.profile, 3);
  const Resultants<double> far = exact_resultants(m, twist(1e6, 0.0, 1.0, R)).resultants;
  EXPECT_NEAR(far.Mz, limit, 1e-5 * fNR);
  for (double e : {4.0, 10.0, 100.0}) {
    const Kinematics<double> k = twist(e, 0.0, 1.0, R);
    const Resultants<double> w = exact_resultants(m, k, {1e-11}).resultants;
    EXPECT_GT(w.Mz * k.omega, 0.0) << e;
    const RowEnvelopeCheck c = check_row_against_patches(k, w.Fx, w.Fy, w.Mz, R);
    EXPECT_TRUE(c.torque_drives_spin) << e;
    EXPECT_FALSE(c.outside_any_patch) << e;
  }
  // Mirror: ky < 0 with omega < 0 drives it as well; ky > 0 with omega < 0 does not.
  patch.profile.ky = -0.5;
  const ExactModel<double> mirror = make_exact_model(patch);
  const Kinematics<double> k = twist(10.0, 0.0, -1.0, R);
  EXPECT_GT(exact_resultants(mirror, k).resultants.Mz * k.omega, 0.0);
  EXPECT_LT(exact_resultants(m, k).resultants.Mz * k.omega, 0.0);
}

TEST(CoulombEnvelope, MissingChannelsAndDegenerateRowsAreNotChecked) {
  const double R = 0.1, nan = std::numeric_limits<double>::quiet_NaN();
  const Kinematics<double> k{1.4, 0.0, 7.0};  // eps = 2
  const auto no_nan = [](const RowEnvelopeCheck& c) {
    return !std::isnan(c.eps) && !std::isnan(c.force_angle_rad) &&
           !std::isnan(c.force_angle_bound_rad) && !std::isnan(c.torque_ratio) &&
           !std::isnan(c.any_patch_torque_bound) && !std::isnan(c.axisymmetric_torque_bound);
  };
  RowEnvelopeCheck c = check_row_against_patches(k, -10.0, nan, 0.5, R);  // Fy missing
  EXPECT_FALSE(c.angle_checked);
  EXPECT_FALSE(c.torque_ratio_checked);
  EXPECT_TRUE(c.torque_sign_checked);
  EXPECT_TRUE(c.torque_drives_spin);
  EXPECT_TRUE(no_nan(c));
  c = check_row_against_patches(k, -10.0, 0.0, nan, R);  // Mz missing
  EXPECT_TRUE(c.angle_checked);
  EXPECT_FALSE(c.torque_ratio_checked || c.torque_sign_checked || c.torque_drives_spin);
  EXPECT_TRUE(no_nan(c));
  c = check_row_against_patches({0.0, 0.0, 0.0}, -1.0, 2.0, 3.0, R);  // at rest
  EXPECT_TRUE(c.at_rest);
  EXPECT_FALSE(c.angle_checked || c.torque_ratio_checked || c.torque_sign_checked);
  EXPECT_FALSE(c.outside_any_patch || c.above_axisymmetric_torque || c.torque_drives_spin);
  EXPECT_TRUE(no_nan(c));
  c = check_row_against_patches(k, 0.0, 0.0, -0.3, R);  // |F| = 0
  EXPECT_FALSE(c.angle_checked || c.torque_ratio_checked);
  EXPECT_TRUE(c.torque_sign_checked);
  EXPECT_FALSE(c.outside_any_patch);
  EXPECT_TRUE(no_nan(c));
  c = check_row_against_patches({0.0, 0.0, 7.0}, 0.1, 0.0, -0.3, R);  // pure spin: eps = 0
  EXPECT_EQ(c.eps, 0.0);
  EXPECT_FALSE(c.angle_checked);
  EXPECT_TRUE(c.torque_ratio_checked);
  EXPECT_EQ(c.axisymmetric_torque_bound, kInf);
  EXPECT_FALSE(c.outside_any_patch || c.above_axisymmetric_torque);
  EXPECT_TRUE(no_nan(c));
  c = check_row_against_patches({1.0, 0.0, 0.0}, -1.0, 0.0, 0.0, R);  // pure sliding
  EXPECT_EQ(c.eps, kInf);
  EXPECT_EQ(c.force_angle_bound_rad, 0.0);
  EXPECT_FALSE(c.torque_sign_checked || c.outside_any_patch || c.above_axisymmetric_torque);
  EXPECT_TRUE(check_row_against_patches({1.0, 0.0, 0.0}, -1.0, 0.01, 0.0, R).outside_any_patch);
  // Spin far below the sliding: the sign is not checked.
  EXPECT_FALSE(check_row_against_patches({1.0, 0.0, 1e-6}, -1.0, 0.0, 0.1, R).torque_sign_checked);
}

TEST(CoulombEnvelope, BadInputIsRefusedNamingTheArgument) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const auto parameter = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return "(nothing thrown)";
  };
  const Kinematics<double> k{1.0, 0.0, 3.0};
  EXPECT_EQ(parameter([&] { check_row_against_patches({nan, 0, 1}, -1, 0, 0, 0.1); }), "vx");
  EXPECT_EQ(parameter([&] { check_row_against_patches({0, kInf, 1}, -1, 0, 0, 0.1); }), "vy");
  EXPECT_EQ(parameter([&] { check_row_against_patches({0, 0, nan}, -1, 0, 0, 0.1); }), "omega");
  EXPECT_EQ(parameter([&] { check_row_against_patches(k, -1, 0, 0, 0.0); }), "radius_m");
  EXPECT_EQ(parameter([&] { check_row_against_patches(k, -1, 0, 0, -0.1); }), "radius_m");
  EXPECT_EQ(parameter([&] { check_row_against_patches(k, -1, 0, 0, nan); }), "radius_m");
  EXPECT_EQ(parameter([&] { check_row_against_patches(k, -kInf, 0, 0, 0.1); }), "Fx");
  EXPECT_EQ(parameter([&] { check_row_against_patches(k, -1, kInf, 0, 0.1); }), "Fy");
  EXPECT_EQ(parameter([&] { check_row_against_patches(k, -1, 0, -kInf, 0.1); }), "Mz");
  EXPECT_EQ(parameter([&] {
              check_row_against_patches(k, -1, 0, 0, 0.1, {-1e-3, 0, 0});
            }),
            "angle_margin_rad");
  EXPECT_EQ(parameter([&] {
              check_row_against_patches(k, -1, 0, 0, 0.1, {0, nan, 0});
            }),
            "ratio_margin");
  EXPECT_EQ(parameter([&] {
              check_row_against_patches(k, -1, 0, 0, 0.1, {0, 0, -1});
            }),
            "min_spin_fraction");
  EXPECT_EQ(parameter([] { axisymmetric_torque_ratio_envelope(-0.1); }), "eps");
  EXPECT_EQ(parameter([] { axisymmetric_torque_ratio_envelope(nan); }), "eps");
  EXPECT_EQ(parameter([] { force_angle_bound(nan); }), "eps");
  EXPECT_EQ(parameter([] { any_patch_torque_ratio_bound(-1.0); }), "eps");
  EXPECT_EQ(parameter([] { ring_resultants(-1.0); }), "s");
  EXPECT_EQ(parameter([] { ring_torque_ratio(1.0, 0.0); }), "rho");
  EXPECT_EQ(parameter([] { ring_torque_ratio(1.0, 1.5); }), "rho");
  EXPECT_EQ(parameter([] { sliding_spin_ratio({1.0, 0.0, 1.0}, -1.0); }), "radius_m");
  try {
    check_row_against_patches(k, -1, 0, 0, -0.1);
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("-0.1"), std::string::npos) << e.what();
  }
}
