/// \file
/// From the tire test to the gear (docs/shimmy.md, section 6.4): the
/// coupled law's dimensionless coefficients identified from measured diagrams
/// (contensou-identify's report: F0, a, M0, m, kx with their covariance) carried to the gear,
/// and a Monte Carlo over that covariance of the gear's eigenvalue growth rate.
///
/// What carries over from the test tire to the gear's tire: the shapes a and m, the rolling shift
/// kx and the spin-torque ratio M0 / (F0 R) (= A^2 / A^1 for a pressure profile, theory.md
/// section 4); the friction level f(w) and the patch size stay the gear's (the test ran at other
/// loads and speeds).
#pragma once

#include <Eigen/Core>
#include <array>
#include <functional>
#include <string>
#include <vector>

#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "contensou/gear/stability_map.hpp"

namespace contensou {

/// The coupled law's dimensionless coefficients a gear takes from a tire test.
struct TireLawCoefficients {
  double a = 1.0;           ///< sliding shape
  double m = 1.0;           ///< spin shape
  double kx = 0.0;          ///< rolling shift
  double spin_ratio = 0.5;  ///< M0 / (F0 R), R the test patch's radius
};

/// The identified parameters (F0 [N], a, M0 [N m], m, kx) as a normal distribution.
struct TireLawDistribution {
  /// The parameters' names, in the order of mean and covariance.
  static constexpr std::array<const char*, 5> kNames{"F0_N", "a", "M0_Nm", "m", "kx"};
  /// The mean (F0 [N], a, M0 [N m], m, kx).
  Eigen::Matrix<double, 5, 1> mean = Eigen::Matrix<double, 5, 1>::Zero();
  /// Their covariance, in the same order and units (symmetric positive semi-definite).
  Eigen::Matrix<double, 5, 5> covariance = Eigen::Matrix<double, 5, 5>::Zero();
  double radius_m = 0.1;  ///< the test patch's radius R [m]
};

/// The coefficients of one parameter vector (F0, a, M0, m, kx) of a test patch of radius R [m].
TireLawCoefficients tire_law_coefficients(const Eigen::Matrix<double, 5, 1>& p, double radius_m);

/// The gear model with the coupled law's a, m, kx and M0 / (F0 R) replaced (M0 / (F0 R) as
/// GearModel::moment_ratio_2, which the decoupled model's spin torque reads too).
GearModel with_tire_law(const GearModel& base, const TireLawCoefficients& law);

/// What draw_tire_laws() returns.
struct TireLawDraws {
  std::vector<TireLawCoefficients> draws;  ///< the accepted draws, n of them
  int rejected = 0;                        ///< how many were redrawn
};
/// n draws from the distribution with a std::mt19937_64 seeded by `seed` (a square root of the
/// covariance by its eigen-decomposition, so a semi-definite covariance is fine); draws with
/// a <= 0, m <= 0, |kx| >= 1, F0 <= 0 or M0 <= 0 are redrawn (their count is reported). Throws
/// InvalidArgument for n < 1, a radius that is not positive, a mean or covariance that is not
/// finite, a covariance that is not symmetric positive semi-definite, or more than 100 n
/// rejected draws.
TireLawDraws draw_tire_laws(const TireLawDistribution& d, int n, unsigned seed);

/// The eigenvalue growth rate (linear_growth_rate) of the phase over the draws [1/s]: median, the
/// central 95 % band (2.5 and 97.5 percentiles) and the share of draws with growth > 0; a draw
/// that fails or does not converge is not counted.
struct GrowthBand {
  /// The median growth rate [1/s]; NaN if no draw counted (so are low and high).
  double median = 0.0, low = 0.0, high = 0.0;  ///< the 97.5 percentile [1/s]
  /// \var contensou::GrowthBand::low
  /// The 2.5 percentile of the growth rate [1/s].
  double shimmy_probability = 0.0;  ///< share of the counted draws with growth > 0
  int draws = 0;                    ///< the draws counted
};
/// The band over `draws`, on `threads` threads (0: all cores); `progress(done, total)` from the
/// calling thread.
GrowthBand growth_band(const GearModel& base, const std::vector<TireLawCoefficients>& draws,
                       StabilityPhase phase, unsigned threads = 0,
                       const std::function<void(int, int)>& progress = {});

/// An eigenvalue map whose cells give the median growth rate over the draws (growth_rate_per_s)
/// and the probability of shimmy (shimmy_probability); shimmy = probability >= 0.5. Throws
/// InvalidArgument without draws or for bad axes (evaluate_map).
StabilityMap probability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                             StabilityPhase phase, const std::vector<TireLawCoefficients>& draws,
                             unsigned threads = 0,
                             const std::function<void(int, int)>& progress = {});

}  // namespace contensou
