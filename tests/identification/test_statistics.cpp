// The statistics the identification uses (contensou/identification/statistics.hpp): Boost.Math's
// distributions behind them, checked where the fit and the closed loop read them (the Student-t
// quantile of the 95 % intervals, the chi-square survival of the likelihood-ratio and score
// tests, the normal CDF of the residual tests) against tabulated values and closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/identification/statistics.hpp"

namespace contensou {
namespace {

// |a - b| <= tol |b|: agreement to `tol` relative.
::testing::AssertionResult Near(double a, double b, double tol) {
  if (std::abs(a - b) <= tol * std::abs(b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << a << " vs " << b << " (relative " << std::abs(a - b) / std::abs(b) << ")";
}

TEST(Statistics, StudentTQuantilesOfTheIntervals) {
  // Two-sided 95 % (p = 0.975) and one-sided 95 %, tabulated to 13 digits.
  EXPECT_TRUE(Near(student_t_quantile(0.975, 10), 2.228138851986, 1e-12));
  EXPECT_TRUE(Near(student_t_quantile(0.975, 1), 12.706204736175, 1e-12));
  EXPECT_TRUE(Near(student_t_quantile(0.975, 30), 2.042272456301, 1e-12));
  EXPECT_TRUE(Near(student_t_quantile(0.95, 5), 2.015048373333, 1e-12));
  // Symmetric, and the CDF inverts it.
  EXPECT_TRUE(Near(student_t_quantile(0.025, 10), -2.228138851986, 1e-12));
  EXPECT_NEAR(student_t_cdf(2.228138851986, 10), 0.975, 1e-13);
  // Many degrees of freedom: the normal quantile.
  EXPECT_TRUE(Near(student_t_quantile(0.975, 1e8), normal_quantile(0.975), 1e-7));
  EXPECT_EQ(student_t_cdf(std::numeric_limits<double>::infinity(), 3), 1.0);
}

TEST(Statistics, NormalOfTheResidualTests) {
  EXPECT_TRUE(Near(normal_quantile(0.975), 1.959963984540054, 1e-14));
  EXPECT_TRUE(Near(normal_quantile(0.995), 2.575829303548901, 1e-14));
  EXPECT_NEAR(normal_cdf(1.959963984540054), 0.975, 1e-15);
  EXPECT_NEAR(2.0 * normal_cdf(-1.959963984540054), 0.05, 1e-15);  // two-sided p
  EXPECT_EQ(normal_cdf(0.0), 0.5);
  EXPECT_EQ(normal_cdf(-std::numeric_limits<double>::infinity()), 0.0);
}

TEST(Statistics, ChiSquareOfTheLikelihoodRatioTests) {
  EXPECT_TRUE(Near(chi2_quantile(0.95, 1), 3.841458820694124, 1e-13));
  EXPECT_TRUE(Near(chi2_quantile(0.95, 10), 18.307038053275146, 1e-13));
  EXPECT_TRUE(Near(chi2_quantile(0.99, 3), 11.344866730144373, 1e-13));
  // Closed forms: 2 degrees of freedom, P(X > x) = exp(-x / 2); 1, erfc(sqrt(x / 2)).
  EXPECT_TRUE(Near(chi2_quantile(0.95, 2), -2.0 * std::log(0.05), 1e-14));
  for (double x : {1e-6, 0.3, 2.0, 9.0, 60.0}) {
    EXPECT_TRUE(Near(chi2_survival(x, 2), std::exp(-x / 2), 1e-13)) << x;
    EXPECT_TRUE(Near(chi2_survival(x, 1), std::erfc(std::sqrt(x / 2)), 1e-13)) << x;
  }
  EXPECT_NEAR(chi2_survival(3.841458820694124, 1), 0.05, 1e-15);
  // The loop's statistics are max(0, ...): zero is no evidence, p = 1.
  EXPECT_EQ(chi2_survival(0.0, 3), 1.0);
  EXPECT_EQ(chi2_survival(std::numeric_limits<double>::infinity(), 3), 0.0);
  EXPECT_TRUE(std::isnan(chi2_survival(std::numeric_limits<double>::quiet_NaN(), 3)));
}

TEST(Statistics, FisherF) {
  // F(1, nu) is t(nu) squared; F(2, d2) has P(X > x) = (1 + 2 x / d2)^(-d2 / 2).
  EXPECT_TRUE(Near(fisher_f_quantile(0.95, 1, 10), std::pow(2.228138851986, 2), 1e-12));
  for (double x : {0.1, 1.0, 4.0})
    EXPECT_TRUE(Near(fisher_f_survival(x, 2, 12), std::pow(1 + x / 6, -6), 1e-13));
  EXPECT_TRUE(
      Near(fisher_f_quantile(0.99, 2, 12), 6.0 * (std::pow(0.01, -1.0 / 6.0) - 1.0), 1e-13));
  EXPECT_EQ(fisher_f_survival(0.0, 3, 20), 1.0);
}

TEST(Statistics, BadArgumentsNameThemselves) {
  EXPECT_THROW(student_t_quantile(1.0, 10), InvalidArgument);
  EXPECT_THROW(student_t_quantile(0.5, 0.0), InvalidArgument);
  EXPECT_THROW(normal_quantile(0.0), InvalidArgument);
  EXPECT_THROW(chi2_survival(1.0, -1.0), InvalidArgument);
  EXPECT_THROW(fisher_f_quantile(0.9, 1.0, std::numeric_limits<double>::quiet_NaN()),
               InvalidArgument);
  try {
    student_t_quantile(1.5, 3);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()), "p = 1.5: must be in (0, 1)");
  }
}

TEST(Statistics, RunsTestPValue) {
  // Alternating signs: 10 runs of 10 values, z = (10 - 6) / sqrt(2.222...), two-sided p.
  const std::vector<double> alternating{1, -1, 1, -1, 1, -1, 1, -1, 1, -1};
  const RunsTest r = runs_test(alternating);
  EXPECT_EQ(r.runs, 10);
  const double z = (10.0 - 6.0) / std::sqrt(2.0 * 25.0 * (50.0 - 10.0) / (100.0 * 9.0));
  EXPECT_NEAR(r.z, z, 1e-14);
  EXPECT_NEAR(r.p_value, std::erfc(z / std::sqrt(2.0)), 1e-15);
}

}  // namespace
}  // namespace contensou
