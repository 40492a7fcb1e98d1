// Which fractional laws a non-negative pressure gives (admissible_shape.hpp): against the
// library's own moments of random non-negative profiles, against measures of two atoms (the
// extreme points of the moment space, where the torque ratio reaches its bounds), and the
// reasons given for shapes no patch produces.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "contensou/friction/admissible_shape.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/pressure_profile.hpp"

using namespace contensou;

namespace {

// The law's shapes of moments mu0..mu3: a = (2 mu1/mu0)^2, m = (2 mu2/mu3)^2, q = mu2 / mu1.
struct Shapes {
  double a, m, q;
};
Shapes shapes_of(const std::array<double, 4>& mu) {
  return {std::pow(2.0 * mu[1] / mu[0], 2), std::pow(2.0 * mu[2] / mu[3], 2), mu[2] / mu[1]};
}

// Moments of the measure w0 delta(x0) + w1 delta(x1).
std::array<double, 4> two_atoms(double x0, double w0, double x1, double w1) {
  std::array<double, 4> mu{};
  for (int n = 0; n < 4; ++n) mu[n] = w0 * std::pow(x0, n) + w1 * std::pow(x1, n);
  return mu;
}

}  // namespace

// Oracle: the library's moments A^n of random non-negative tabulated profiles (pressure_profile:
// an independent integration) always give an admissible law, with the torque ratio inside the
// range computed for its a and m.
TEST(AdmissibleShape, EveryNonNegativeProfileGivesAnAdmissibleLaw) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> rho, p;
    const int knots = 3 + trial % 12;
    for (int k = 0; k < knots; ++k) {
      rho.push_back(static_cast<double>(k) / (knots - 1));
      p.push_back(U(rng) < 0.3 ? 0.0 : std::pow(U(rng), 3));  // zeros: rings, gaps
    }
    if (*std::max_element(p.begin(), p.end()) == 0.0) p.back() = 1.0;
    const PressureProfile profile = tabulated_profile(rho, p);
    const std::array<double, 4> mu = {moment(profile, 0), moment(profile, 1), moment(profile, 2),
                                      moment(profile, 3)};
    const Shapes s = shapes_of(mu);
    const ShapeAdmissibility a = shape_admissibility(s.a, s.m, s.q);
    EXPECT_TRUE(a.admissible) << "trial " << trial << ": " << a.reason;
    EXPECT_LE(s.a, 4.0 + 1e-12);
    EXPECT_GE(s.m, 4.0 - 1e-12);
    EXPECT_LE(s.a * s.m, 16.0 + 1e-9);
    EXPECT_GE(s.q, a.q_min - 1e-12);
    EXPECT_LE(s.q, a.q_max + 1e-12);
  }
}

// Oracle: theory.md section 4's uniform and Hertz constants and a ring at the rim (a = m = 4,
// on the boundary: admissible).
TEST(AdmissibleShape, KnownProfilesAndTheRing) {
  EXPECT_TRUE(shape_admissibility(1.0, 64.0 / 9.0, 2.0 / 3.0).admissible);
  const double pi = std::acos(-1.0);
  EXPECT_TRUE(
      shape_admissibility(std::pow(8.0 / (3.0 * pi), 2), std::pow(15.0 * pi / 16.0, 2)).admissible);
  EXPECT_TRUE(shape_admissibility(4.0, 4.0, 1.0).admissible);
  for (double rho0 : {0.1, 0.5, 0.9})  // a ring at rho0: t = q = r = rho0
    EXPECT_TRUE(shape_admissibility(4 * rho0 * rho0, 4 / (rho0 * rho0), rho0).admissible) << rho0;
}

// Oracle: the extreme measures. Atoms at c and 1 make (1 - x) d mu a single atom: the torque
// ratio is the smallest that t and r allow (q_min); atoms at 0 and d make x d mu one atom: the
// largest (q = r = d). Both are computed here from the atoms, not from the conditions.
TEST(AdmissibleShape, TheTorqueRatioRangeIsReachedByTwoAtomMeasures) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(0.02, 0.98);
  for (int trial = 0; trial < 500; ++trial) {
    const double c = U(rng), w = U(rng);
    const Shapes low = shapes_of(two_atoms(c, w, 1.0, 1.0 - w));
    const ShapeAdmissibility lo = shape_admissibility(low.a, low.m, low.q);
    ASSERT_TRUE(lo.admissible) << lo.reason;
    EXPECT_NEAR(lo.q_min, low.q, 1e-9) << "c = " << c << ", w = " << w;
    const Shapes high = shapes_of(two_atoms(0.0, w, c, 1.0 - w));
    const ShapeAdmissibility hi = shape_admissibility(high.a, high.m, high.q);
    ASSERT_TRUE(hi.admissible) << hi.reason;
    EXPECT_NEAR(hi.q_max, high.q, 1e-12);
    // Just outside either end: refused, with the ratio and its limit named.
    EXPECT_FALSE(shape_admissibility(low.a, low.m, low.q * (1 - 1e-4)).admissible);
    const ShapeAdmissibility above = shape_admissibility(high.a, high.m, high.q * (1 + 1e-4));
    EXPECT_FALSE(above.admissible);
    EXPECT_NE(above.reason.find("more spin torque"), std::string::npos) << above.reason;
  }
}

// Shapes no patch gives: each refused with its number and the bound it breaks.
TEST(AdmissibleShape, ShapesNoPatchGivesAreNamed) {
  const ShapeAdmissibility m_small = shape_admissibility(1e-12, 0.25);
  EXPECT_FALSE(m_small.admissible);
  EXPECT_NE(m_small.reason.find("m = 0.25 < 4"), std::string::npos) << m_small.reason;
  const ShapeAdmissibility a_big = shape_admissibility(5.0, 8.0);
  EXPECT_FALSE(a_big.admissible);
  EXPECT_NE(a_big.reason.find("a = 5 > 4"), std::string::npos) << a_big.reason;
  const ShapeAdmissibility joint = shape_admissibility(3.0, 6.0);  // each alone fine
  EXPECT_FALSE(joint.admissible);
  EXPECT_NE(joint.reason.find("a m = 18 > 16"), std::string::npos) << joint.reason;
  EXPECT_TRUE(shape_admissibility(2.0, 8.0).admissible);  // a m = 16: a ring at rho = 1/sqrt(2)
  EXPECT_THROW(shape_admissibility(std::nan(""), 8.0), InvalidArgument);
  EXPECT_THROW(shape_admissibility(1.0, -1.0), InvalidArgument);
  EXPECT_THROW(shape_admissibility(1.0, 8.0, 0.0), InvalidArgument);
  EXPECT_THROW(shape_admissibility(1.0, 8.0, INFINITY), InvalidArgument);
}
