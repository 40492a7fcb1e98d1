/// \file
/// Where a fit's residual has structure: each channel's standardised residual tested against
/// every variable the data record (the load, the time or the row order, each recorded column)
/// and the kinematics (slip speed, the sliding-spin ratio psi, the sliding direction, the spin
/// speed), so that a report can say what the residual follows instead of only that it is not
/// white.
///
/// Tests, per channel and variable, both rank-based (robust to a few wild values):
///  - Spearman's rank correlation rho_s (a monotone trend), p from Student's t with n - 2
///    degrees of freedom, t = rho_s sqrt((n - 2) / (1 - rho_s^2));
///  - Kruskal-Wallis' H over k quantile bins of the variable (any trend; k = n / 30 within
///    3..10; the sliding direction gets this one only, an angle has no order), p from
///    chi-square with k - 1 degrees of freedom (k the bins formed: rows with equal values of
///    the variable share a bin, so there may be fewer).
/// Multiple comparisons: Holm's step-down over every test of the family (channels x variables
/// x tests), at level alpha. Size: epsilon^2 = H / (n - 1) (the share of the residual's rank
/// variance the bins explain) and the spread of the bins' mean residual in noise scales.
#pragma once

#include <string>
#include <vector>

#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

struct FitReport;

/// The variables of the data friction may follow (effect_model.hpp's Covariate): the load when
/// it varies (three distinct values at least, the largest above 1.01 times the smallest), the
/// time when every row has one (else the row order), and each recorded column with at least
/// three distinct values; scaled to [-1, 1] over the data.
std::vector<Covariate> covariates_of(const MeasuredData& data);

/// One test of a channel's standardised residual against a variable.
struct TracedVariable {
  std::string channel;      ///< "Fx_N"
  std::string variable;     ///< "T [degC]", "Fz_N", "t_s", "row order", "slip speed", "psi", ...
  bool kinematic = false;   ///< a kinematic variable (slip speed, psi, spin speed, direction)
  int covariate = -1;       ///< index into the covariates given to trace_residual (-1: kinematic)
  std::string test;         ///< "Spearman" or "Kruskal-Wallis"
  double statistic = 0.0;   ///< rho_s or H
  double p_value = 1.0;     ///< unadjusted
  double p_adjusted = 1.0;  ///< Holm
  double size = 0.0;        ///< effect size: epsilon^2 = H / (n - 1), or rho_s^2 for Spearman's
  /// Max - min of the bins' mean residual (Kruskal-Wallis' bins, for both tests), in noise
  /// scales.
  double spread_sigma = 0.0;
  /// "Fx_N follows T [degC] (Spearman rho = +0.41, p = 3e-12, bins span 2.1 sigma)", p the
  /// Holm-adjusted one.
  std::string describe() const;
};

/// What a fit's residual follows: the tests that stay significant after Holm's adjustment.
struct ResidualTrace {
  int tests = 0;        ///< the family's size (0: nothing tested)
  double alpha = 0.01;  ///< its level
  /// The tests with p_adjusted below alpha, strongest (size) first, the stronger of the two
  /// tests only for each channel and variable.
  std::vector<TracedVariable> followed;
  /// The variables the residual follows, each with its channels ("T [degC] (Fx_N, Mz_Nm);
  /// Fz_N (Fx_N)"; empty if none).
  std::string where() const;
};

/// The trace of a fit's residual (FitReport::residual, scaled by its noise scales) over the
/// variables of `covariates` and the kinematics (radius for psi, [m]). A channel and variable
/// pair is tested when at least 12 rows have both, with three distinct values of the variable.
/// An empty trace (no tests) when the fit's residual or prediction does not match the data.
ResidualTrace trace_residual(const MeasuredData& data, const FitReport& fit, double radius_m,
                             const std::vector<Covariate>& covariates, double alpha = 0.01);

}  // namespace contensou
