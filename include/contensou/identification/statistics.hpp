/// \file
/// Small statistics toolkit for identification and residual diagnostics. The distributions are
/// Boost.Math's (students_t, normal, chi_squared, fisher_f; header-only, used in the .cpp only):
/// these functions check their arguments (InvalidArgument naming the bad one) and name the use.
#pragma once

#include <vector>

namespace contensou {

/// Student t distribution with `nu` degrees of freedom: P(X <= t) (0 or 1 at -inf or +inf, NaN
/// for NaN). Throws InvalidArgument unless nu is positive and finite.
double student_t_cdf(double t, double nu);
/// Student t quantile (inverse CDF) at p. Throws InvalidArgument unless p is in (0, 1) and nu
/// is positive and finite.
double student_t_quantile(double p, double nu);

/// Standard normal CDF P(Z <= z) (0 or 1 at -inf or +inf, NaN for NaN).
double normal_cdf(double z);
/// Standard normal quantile at p. Throws InvalidArgument unless p is in (0, 1).
double normal_quantile(double p);

/// Chi-square with `k` degrees of freedom: the survival P(X > x) (1 for x <= 0, 0 at +inf, NaN
/// for NaN). Throws InvalidArgument unless k is positive and finite.
double chi2_survival(double x, double k);
/// Chi-square quantile at p. Throws InvalidArgument unless p is in (0, 1) and k is positive
/// and finite.
double chi2_quantile(double p, double k);

/// Fisher's F with (d1, d2) degrees of freedom: the survival P(X > x) (1 for x <= 0, 0 at +inf,
/// NaN for NaN). Throws InvalidArgument unless d1 and d2 are positive and finite.
double fisher_f_survival(double x, double d1, double d2);
/// Fisher's F quantile at p. Throws InvalidArgument unless p is in (0, 1) and d1 and d2 are
/// positive and finite.
double fisher_f_quantile(double p, double d1, double d2);

/// Wald-Wolfowitz runs test on the signs of a sequence (zeros and non-finite values dropped):
/// the number of runs, its z score under independence and the two-sided p value (normal
/// approximation). With fewer than 3 signs, or only one sign, z = 0 and p = 1.
struct RunsTest {
  int runs = 0;          ///< runs of equal sign
  int positive = 0;      ///< positive values
  int negative = 0;      ///< negative values
  double z = 0.0;        ///< (runs - mean) / standard deviation under independence
  double p_value = 1.0;  ///< two-sided p value of z
};
/// The runs test of `sequence` (RunsTest).
RunsTest runs_test(const std::vector<double>& sequence);

/// Lag-1 autocorrelation about the mean, sum (x_i - m)(x_(i-1) - m) / sum (x_i - m)^2; 0 for
/// fewer than 3 values or a constant sequence.
double lag1_autocorrelation(const std::vector<double>& x);
/// Durbin-Watson statistic about zero, sum (x_i - x_(i-1))^2 / sum x_i^2 (2 for no residual:
/// empty or all zero); near 2 for independent values.
double durbin_watson(const std::vector<double>& x);

}  // namespace contensou
