// From the tire test to the gear (issue 12, item 5): the draws follow the report's normal
// distribution (sample moments against the given ones), a degenerate distribution gives the
// deterministic growth rate, probability maps agree with single assessments, bad covariances
// are refused by name.
#include <gtest/gtest.h>

#include <cmath>

#include "contensou/friction/error.hpp"
#include "contensou/gear/tire_uncertainty.hpp"

using namespace contensou;

namespace {

TireLawDistribution seed_like() {
  TireLawDistribution d;
  d.radius_m = 0.087;
  d.mean << 1375.6, 0.62, 74.8, 6.55, 0.135;
  const Eigen::Matrix<double, 5, 1> se(11.8, 0.0475, 0.92, 0.31, 0.0018);
  Eigen::Matrix<double, 5, 5> corr = Eigen::Matrix<double, 5, 5>::Identity();
  corr(1, 3) = corr(3, 1) = 0.6;   // a with m
  corr(0, 2) = corr(2, 0) = -0.3;  // F0 with M0
  d.covariance = se.asDiagonal() * corr * se.asDiagonal();
  return d;
}

}  // namespace

TEST(TireUncertainty, DrawsHaveTheReportsMeanVarianceAndCorrelation) {
  const TireLawDistribution d = seed_like();
  const int n = 20000;
  const TireLawDraws t = draw_tire_laws(d, n, 7);
  ASSERT_EQ(static_cast<int>(t.draws.size()), n);
  EXPECT_EQ(t.rejected, 0);  // every parameter is many standard errors from its bound
  double ma = 0, mm = 0, mk = 0;
  for (const TireLawCoefficients& c : t.draws) {
    ma += c.a;
    mm += c.m;
    mk += c.kx;
  }
  ma /= n;
  mm /= n;
  mk /= n;
  double va = 0, vm = 0, cam = 0;
  for (const TireLawCoefficients& c : t.draws) {
    va += (c.a - ma) * (c.a - ma);
    vm += (c.m - mm) * (c.m - mm);
    cam += (c.a - ma) * (c.m - mm);
  }
  va /= n - 1;
  vm /= n - 1;
  cam /= n - 1;
  const double sa = std::sqrt(d.covariance(1, 1)), sm = std::sqrt(d.covariance(3, 3));
  EXPECT_NEAR(ma, d.mean[1], 4 * sa / std::sqrt(n));
  EXPECT_NEAR(mm, d.mean[3], 4 * sm / std::sqrt(n));
  EXPECT_NEAR(mk, d.mean[4], 4 * std::sqrt(d.covariance(4, 4) / n));
  EXPECT_NEAR(va, sa * sa, 0.05 * sa * sa);
  EXPECT_NEAR(vm, sm * sm, 0.05 * sm * sm);
  EXPECT_NEAR(cam / std::sqrt(va * vm), 0.6, 0.03);
  // The spin ratio M0 / (F0 R) of the mean.
  const TireLawCoefficients mean = tire_law_coefficients(d.mean, d.radius_m);
  EXPECT_DOUBLE_EQ(mean.spin_ratio, 74.8 / (1375.6 * 0.087));
}

TEST(TireUncertainty, ADegenerateDistributionGivesTheDeterministicGrowthRate) {
  TireLawDistribution d = seed_like();
  d.covariance.setZero();
  const TireLawDraws t = draw_tire_laws(d, 12, 1);
  const GearModel base = make_gear_model(GearConfig{}, ContactModel::coupled);
  const double expected = linear_growth_rate(
      with_tire_law(base, tire_law_coefficients(d.mean, d.radius_m)), StabilityPhase::braked_slide);
  const GrowthBand b = growth_band(base, t.draws, StabilityPhase::braked_slide, 2);
  EXPECT_EQ(b.draws, 12);
  EXPECT_DOUBLE_EQ(b.median, expected);
  EXPECT_DOUBLE_EQ(b.low, expected);
  EXPECT_DOUBLE_EQ(b.high, expected);
  EXPECT_EQ(b.shimmy_probability, expected > 0 ? 1.0 : 0.0);
  // The law is really replaced: a much smaller spin shape m changes the growth rate.
  TireLawCoefficients other = tire_law_coefficients(d.mean, d.radius_m);
  other.m = 1.0;
  EXPECT_GT(std::abs(linear_growth_rate(with_tire_law(base, other), StabilityPhase::braked_slide) -
                     expected),
            1e-3);
}

TEST(TireUncertainty, ProbabilityMapCellsAreSharesOfSingleAssessments) {
  const TireLawDraws t = draw_tire_laws(seed_like(), 8, 3);
  const GearModel base = make_gear_model(GearConfig{}, ContactModel::coupled);
  const MapAxis x{"scenario.forward_speed_mps", 50.0, 70.0, 2};
  const MapAxis y{"structure.offset_m", 0.3, 0.5, 2};
  const StabilityMap map = probability_map(base, x, y, StabilityPhase::braked_slide, t.draws, 2);
  ASSERT_EQ(map.cells.size(), 4u);
  for (const MapCell& cell : map.cells) {
    GearModel m = base;
    m.config.scenario.forward_speed_mps = cell.x;
    m.config.structure.offset_m = cell.y;
    int unstable = 0;
    for (const TireLawCoefficients& c : t.draws)
      unstable += linear_growth_rate(with_tire_law(m, c), StabilityPhase::braked_slide) > 0;
    EXPECT_DOUBLE_EQ(cell.shimmy_probability, unstable / 8.0) << cell.x << ", " << cell.y;
  }
}

TEST(TireUncertainty, BadCovariancesAndCountsAreRefused) {
  TireLawDistribution d = seed_like();
  EXPECT_THROW(draw_tire_laws(d, 0, 1), InvalidArgument);
  d.covariance(1, 1) = -1.0;
  EXPECT_THROW(draw_tire_laws(d, 10, 1), InvalidArgument);
  d = seed_like();
  d.covariance(1, 3) += 1.0;  // asymmetric
  EXPECT_THROW(draw_tire_laws(d, 10, 1), InvalidArgument);
  d = seed_like();
  d.mean[1] = -5.0;  // almost every draw has a <= 0
  EXPECT_THROW(draw_tire_laws(d, 10, 1), InvalidArgument);
}
