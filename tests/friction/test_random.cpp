// The random numbers of simulated data (contensou/friction/random.hpp) pinned to the bit: the
// values below were computed by an independent Python implementation of std::mt19937_64 (its
// 10000th output checked against the standard's), the 53-bit uniform and the polar method,
// with Python's math.log (glibc's, correctly rounded).
#include "contensou/friction/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace contensou {
namespace {

TEST(Random, EngineIsTheStandardOne) {
  std::mt19937_64 rng;  // default seed 5489
  rng.discard(9999);
  EXPECT_EQ(rng(), 9981545732273789042ull);
}

TEST(Random, UniformTakesTheHigh53Bits) {
  std::mt19937_64 rng(42);
  EXPECT_EQ(uniform_01(rng), 0.755155532954539);
  EXPECT_EQ(uniform_01(rng), 0.6390313938546974);
  EXPECT_EQ(uniform_01(rng), 0.7521452007480266);
  std::mt19937_64 again(42);
  EXPECT_EQ(uniform_pm1(again), 2.0 * 0.755155532954539 - 1.0);
}

TEST(Random, NormalDrawsArePinned) {
  // EXPECT_DOUBLE_EQ (4 ulps): std::log may differ from glibc's in its last bit elsewhere.
  std::mt19937_64 rng(42);
  StandardNormal normal;
  const double pinned[] = {1.2938204232729367, 0.7049882664208599, 0.3979773961837887,
                           -0.5740948067202614, 1.118555052457478};
  for (double expected : pinned) EXPECT_DOUBLE_EQ(normal(rng), expected);
  std::mt19937_64 one(1);
  StandardNormal n1;
  const double pinned1[] = {-0.039399956754155314, -0.38683176162103955, -0.24894784633514516,
                            0.6868236391793252};
  for (double expected : pinned1) EXPECT_DOUBLE_EQ(n1(one), expected);
}

TEST(Random, NormalHasUnitVarianceAndZeroMean) {
  std::mt19937_64 rng(7);
  StandardNormal normal;
  const int n = 200000;
  double sum = 0.0, sum2 = 0.0, sum4 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double z = normal(rng);
    sum += z;
    sum2 += z * z;
    sum4 += z * z * z * z;
  }
  const double mean = sum / n, var = sum2 / n - mean * mean;
  // Standard errors: 1/sqrt(n) = 0.0022 for the mean, sqrt(2/n) = 0.0032 for the variance,
  // sqrt(96/n) = 0.022 for the fourth moment (3); five of each.
  EXPECT_NEAR(mean, 0.0, 0.011);
  EXPECT_NEAR(var, 1.0, 0.016);
  EXPECT_NEAR(sum4 / n, 3.0, 0.11);
}

}  // namespace
}  // namespace contensou
