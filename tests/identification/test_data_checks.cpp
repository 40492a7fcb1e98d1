// What the data can determine before a fit (data_checks.hpp): rows of centred axisymmetric
// patches (the exact integrals) pass every check; rows with more torque than the rim ring gives,
// a torque that drives the spin, or a force turned as a slip-angle offset turns it are counted
// and named.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "contensou/friction/coulomb_envelope.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/identification/data_checks.hpp"

using namespace contensou;

namespace {

constexpr double kR = 0.05;

// Rows of a patch of profile `profile` at random sliding directions, spin senses and
// eps = |v| / (|omega| R) over 0.05..50 (log-uniform).
MeasuredData exact_rows(const PressureProfile& profile, int n, unsigned seed) {
  ContactPatch patch = ContactPatch::from_normal_load(kR, 10.0, profile, 0.3);
  const ExactModel<double> model = make_exact_model(patch);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  MeasuredData d;
  for (int i = 0; i < n; ++i) {
    const double eps = std::exp(std::log(0.05) + U(rng) * std::log(1000.0));
    const double dir = 2 * std::acos(-1.0) * U(rng), omega = U(rng) < 0.5 ? -0.4 : 0.4;
    const double v = eps * std::abs(omega) * kR;
    MeasuredPoint p;
    p.kinematics = {v * std::cos(dir), v * std::sin(dir), omega};
    const Resultants<double> r = exact_resultants(model, p.kinematics, {1e-9}).resultants;
    p.force = {r.Fx, r.Fy, r.Mz};
    d.points.push_back(p);
  }
  return d;
}

bool says(const DataChecks& c, const std::string& text) {
  for (const std::string& f : c.findings)
    if (f.find(text) != std::string::npos) return true;
  return false;
}

}  // namespace

// Oracle: the bounds hold for every centred axisymmetric pressure (coulomb_envelope.hpp): the
// exact integrals of uniform and Hertz pressure leave nothing to report, and their force angle
// is zero.
TEST(DataChecks, CentredPatchesPassEveryCheck) {
  for (const PressureProfile& profile : {uniform_profile(), hertz_profile()}) {
    const DataChecks c = check_data(exact_rows(profile, 300, 3), kR);
    EXPECT_EQ(c.rows, 300);
    EXPECT_GT(c.ratio_rows, 30);
    EXPECT_EQ(c.above_axisymmetric, 0);
    EXPECT_EQ(c.above_any_patch, 0);
    EXPECT_EQ(c.drives_spin, 0);
    EXPECT_EQ(c.angle_outside, 0);
    EXPECT_NEAR(c.median_angle_deg, 0.0, 1e-6);
    EXPECT_FALSE(c.angle_offset_shown());
    EXPECT_TRUE(c.findings.empty()) << ::testing::PrintToString(c.findings);
  }
}

// Oracle: the rim ring's envelope Lambda(eps) (closed form). Rows whose torque is 1.5 times the
// envelope are all counted above it, and the finding says the coupling cannot be identified.
TEST(DataChecks, TorqueAboveTheRimRingIsCountedAndNamed) {
  MeasuredData d = exact_rows(uniform_profile(), 200, 5);
  int expected = 0;
  for (MeasuredPoint& p : d.points) {
    const double eps = sliding_spin_ratio(p.kinematics, kR);
    if (!(eps > 1.0 && eps < 10.0)) continue;
    const double F = std::hypot(*p.force[0], *p.force[1]);
    p.force[2] = std::copysign(1.5 * axisymmetric_torque_ratio_envelope(eps) * F * kR, *p.force[2]);
    ++expected;
  }
  const DataChecks c = check_data(d, kR);
  EXPECT_EQ(c.ratio_rows, expected);
  EXPECT_EQ(c.above_axisymmetric, expected);
  EXPECT_TRUE(says(c, "more torque than any pressure centred on the patch can"));
  EXPECT_TRUE(says(c, "coupling cannot be identified"));
  EXPECT_NE(data_checks_text(c).find("the data say:"), std::string::npos);
}

// A torque with the spin's sign (a centred patch always resists spin) is counted; a force
// turned by 5 degrees (a slip-angle offset) shows in the median angle, with 0 outside its
// interval.
TEST(DataChecks, TorqueWithTheSpinAndATurnedForceAreShown) {
  MeasuredData d = exact_rows(hertz_profile(), 400, 9);
  const double turn = 5.0 * std::acos(-1.0) / 180.0;
  int with_spin = 0;
  for (MeasuredPoint& p : d.points) {
    const double fx = *p.force[0], fy = *p.force[1];
    p.force[0] = fx * std::cos(turn) - fy * std::sin(turn);
    p.force[1] = fx * std::sin(turn) + fy * std::cos(turn);
    const double u = std::abs(p.kinematics.omega) * kR;
    if (with_spin < 100 && u >= 0.1 * std::hypot(p.kinematics.vx, p.kinematics.vy)) {
      p.force[2] = -*p.force[2];
      ++with_spin;
    }
  }
  const DataChecks c = check_data(d, kR);
  EXPECT_EQ(c.drives_spin, with_spin);
  EXPECT_TRUE(says(c, "torque that drives the spin"));
  EXPECT_NEAR(c.median_angle_deg, 5.0, 1e-6);
  EXPECT_TRUE(c.angle_offset_shown());
}

// Rows without Fy or Mz, rows at rest and a single row: counted where they can be, no NaN.
TEST(DataChecks, MissingChannelsRestAndBadInput) {
  MeasuredData d = exact_rows(uniform_profile(), 20, 1);
  for (MeasuredPoint& p : d.points) p.force[1].reset();
  MeasuredPoint rest;
  rest.kinematics = {0.0, 0.0, 0.0};
  rest.force = {0.1, 0.0, 0.0};
  d.points.push_back(rest);
  const DataChecks c = check_data(d, kR);
  EXPECT_EQ(c.rows, 20);
  EXPECT_EQ(c.angle_rows, 0);
  EXPECT_EQ(c.ratio_rows, 0);
  EXPECT_EQ(c.sliding_rows, 0);
  EXPECT_FALSE(c.angle_offset_shown());
  EXPECT_EQ(data_checks_text(c).find("nan"), std::string::npos) << data_checks_text(c);
  EXPECT_THROW(check_data(d, 0.0), InvalidArgument);
  EXPECT_THROW(check_data(d, std::nan("")), InvalidArgument);
  EXPECT_EQ(check_data(MeasuredData{}, kR).rows, 0);
}
