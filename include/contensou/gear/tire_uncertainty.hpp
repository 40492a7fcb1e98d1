// From the tire test to the gear (docs/shimmy.md, "Tire uncertainty"): the
// coupled law's dimensionless coefficients identified from measured diagrams
// (contensou-identify's report: F0, a, M0, m, kx with their covariance) carried to the gear,
// and a Monte Carlo over that covariance of the gear's eigenvalue growth rate.
//
// What carries over from the test tire to the gear's tire: the shapes a and m, the rolling shift
// kx and the spin-torque ratio M0 / (F0 R) (= A^2 / A^1 for a pressure profile, theory.md
// section 4); the friction level f(w) and the patch size stay the gear's (the test ran at other
// loads and speeds).
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

struct TireLawCoefficients {
  double a = 1.0;           // sliding shape
  double m = 1.0;           // spin shape
  double kx = 0.0;          // rolling shift
  double spin_ratio = 0.5;  // M0 / (F0 R)
};

// The identified parameters (F0 [N], a, M0 [N m], m, kx) as a normal distribution.
struct TireLawDistribution {
  static constexpr std::array<const char*, 5> kNames{"F0_N", "a", "M0_Nm", "m", "kx"};
  Eigen::Matrix<double, 5, 1> mean = Eigen::Matrix<double, 5, 1>::Zero();
  Eigen::Matrix<double, 5, 5> covariance = Eigen::Matrix<double, 5, 5>::Zero();
  double radius_m = 0.1;  // the test patch's radius R
};

// The coefficients of one parameter vector (F0, a, M0, m, kx) of a test patch of radius R.
TireLawCoefficients tire_law_coefficients(const Eigen::Matrix<double, 5, 1>& p, double radius_m);

// The gear model with the coupled law's a, m, kx and M0 / (F0 R) replaced.
GearModel with_tire_law(const GearModel& base, const TireLawCoefficients& law);

// n draws from the distribution (a square root of the covariance by its eigen-decomposition, so
// a semi-definite covariance is fine); draws with a <= 0, m <= 0, |kx| >= 1, F0 <= 0 or M0 <= 0
// are redrawn (their share is reported). Throws InvalidArgument for n < 1 or a covariance that
// is not symmetric positive semi-definite.
struct TireLawDraws {
  std::vector<TireLawCoefficients> draws;
  int rejected = 0;
};
TireLawDraws draw_tire_laws(const TireLawDistribution& d, int n, unsigned seed);

// The eigenvalue growth rate (linear_growth_rate) of the phase over the draws: median, the
// central 95 % band (2.5 and 97.5 percentiles) and the share of draws with growth > 0.
struct GrowthBand {
  double median = 0.0, low = 0.0, high = 0.0;
  double shimmy_probability = 0.0;
  int draws = 0;
};
GrowthBand growth_band(const GearModel& base, const std::vector<TireLawCoefficients>& draws,
                       StabilityPhase phase, unsigned threads = 0,
                       const std::function<void(int, int)>& progress = {});

// An eigenvalue map whose cells give the median growth rate over the draws (growth_rate_per_s)
// and the probability of shimmy (shimmy_probability); shimmy = probability >= 0.5.
StabilityMap probability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                             StabilityPhase phase, const std::vector<TireLawCoefficients>& draws,
                             unsigned threads = 0,
                             const std::function<void(int, int)>& progress = {});

}  // namespace contensou
