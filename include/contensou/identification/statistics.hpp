// Small statistics toolkit for identification and residual diagnostics.
#pragma once

#include <vector>

namespace contensou {

// Regularised incomplete beta function I_x(a, b) (continued fraction, Lentz's method).
double incomplete_beta(double a, double b, double x);

// Student t distribution with nu degrees of freedom: CDF and quantile (inverse CDF).
double student_t_cdf(double t, double nu);
double student_t_quantile(double p, double nu);

// Standard normal CDF.
double normal_cdf(double z);

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

namespace contensou {

// Regularised upper incomplete gamma Q(a, x) and the chi-square survival P(X > x), k dof.
double upper_incomplete_gamma(double a, double x);
double chi2_survival(double x, double k);

}  // namespace contensou
