// Small statistics toolkit for identification and residual diagnostics. The distributions are
// Boost.Math's (students_t, normal, chi_squared, fisher_f; header-only, used in the .cpp only):
// these functions check their arguments (InvalidArgument naming the bad one) and name the use.
#pragma once

#include <vector>

namespace contensou {

// Student t distribution with nu degrees of freedom: CDF and quantile (inverse CDF), p in (0, 1).
double student_t_cdf(double t, double nu);
double student_t_quantile(double p, double nu);

// Standard normal CDF and quantile, p in (0, 1).
double normal_cdf(double z);
double normal_quantile(double p);

// Chi-square with k degrees of freedom: the survival P(X > x) (1 for x <= 0, NaN for NaN) and
// the quantile, p in (0, 1).
double chi2_survival(double x, double k);
double chi2_quantile(double p, double k);

// Fisher's F with (d1, d2) degrees of freedom: the survival P(X > x) (1 for x <= 0, NaN for NaN)
// and the quantile, p in (0, 1).
double fisher_f_survival(double x, double d1, double d2);
double fisher_f_quantile(double p, double d1, double d2);

// Wald-Wolfowitz runs test on the signs of a sequence (zeros dropped): the number of runs,
// its z score under independence and the two-sided p value (normal approximation).
struct RunsTest {
  int runs = 0;
  int positive = 0;
  int negative = 0;
  double z = 0.0;
  double p_value = 1.0;
};
RunsTest runs_test(const std::vector<double>& sequence);

// Lag-1 autocorrelation (about the mean) and the Durbin-Watson statistic (about zero).
double lag1_autocorrelation(const std::vector<double>& x);
double durbin_watson(const std::vector<double>& x);

}  // namespace contensou
