#include "contensou/gear/tire_uncertainty.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "contensou/friction/error.hpp"
#include "contensou/friction/random.hpp"
#include "parallel_cells.hpp"

namespace contensou {

TireLawCoefficients tire_law_coefficients(const Eigen::Matrix<double, 5, 1>& p, double radius_m) {
  // (F0, a, M0, m, kx); the spin-torque ratio M0 / (F0 R) is A^2 / A^1 for a profile
  // (theory.md section 4: M0 = f N R A^2 / A^1, F0 = f N).
  return {p[1], p[3], p[4], p[2] / (p[0] * radius_m)};
}

GearModel with_tire_law(const GearModel& base, const TireLawCoefficients& law) {
  GearModel m = base;
  m.law_a = law.a;
  m.law_m = law.m;
  m.config.tire.rolling_shift = law.kx;
  m.moment_ratio_2 = law.spin_ratio;
  return m;
}

TireLawDraws draw_tire_laws(const TireLawDistribution& d, int n, unsigned seed) {
  if (n < 1) throw InvalidArgument("draws", std::to_string(n), "must be at least 1");
  require_positive("tire radius_m", d.radius_m);
  if (!d.mean.allFinite() || !d.covariance.allFinite())
    throw InvalidArgument("tire covariance", "non-finite", "mean and covariance must be finite");
  if ((d.covariance - d.covariance.transpose()).cwiseAbs().maxCoeff() >
      1e-9 * std::max(d.covariance.cwiseAbs().maxCoeff(), 1e-300))
    throw InvalidArgument("tire covariance", "asymmetric", "must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 5, 5>> es(d.covariance);
  const double largest = es.eigenvalues().cwiseAbs().maxCoeff();
  if (es.eigenvalues().minCoeff() < -1e-8 * largest)
    throw InvalidArgument("tire covariance", "indefinite", "must be positive semi-definite");
  // Square root S with S S^T = C.
  const Eigen::Matrix<double, 5, 5> S =
      es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  std::mt19937_64 rng(seed);
  StandardNormal normal;  // the same draws with every standard library (friction/random.hpp)
  TireLawDraws out;
  out.draws.reserve(static_cast<std::size_t>(n));
  while (static_cast<int>(out.draws.size()) < n) {
    Eigen::Matrix<double, 5, 1> z;
    for (int i = 0; i < 5; ++i) z[i] = normal(rng);
    const Eigen::Matrix<double, 5, 1> p = d.mean + S * z;
    const bool ok = p[0] > 0 && p[1] > 0 && p[2] > 0 && p[3] > 0 && std::abs(p[4]) < 1.0;
    if (!ok) {
      if (++out.rejected > 100 * n)
        throw InvalidArgument(
            "tire covariance", "too wide",
            "almost every draw has a <= 0, m <= 0, F0 <= 0, M0 <= 0 or |kx| >= 1");
      continue;
    }
    out.draws.push_back(tire_law_coefficients(p, d.radius_m));
  }
  return out;
}

namespace {

// The value at probability q of sorted values (linear interpolation between order statistics).
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  const double pos = q * static_cast<double>(sorted.size() - 1);
  const std::size_t i = static_cast<std::size_t>(pos);
  if (i + 1 >= sorted.size()) return sorted.back();
  return sorted[i] + (pos - static_cast<double>(i)) * (sorted[i + 1] - sorted[i]);
}

GrowthBand summarise(std::vector<double> growth) {
  GrowthBand b;
  growth.erase(
      std::remove_if(growth.begin(), growth.end(), [](double g) { return !std::isfinite(g); }),
      growth.end());
  std::sort(growth.begin(), growth.end());
  b.draws = static_cast<int>(growth.size());
  b.median = quantile(growth, 0.5);
  b.low = quantile(growth, 0.025);
  b.high = quantile(growth, 0.975);
  const auto unstable = std::count_if(growth.begin(), growth.end(), [](double g) { return g > 0; });
  b.shimmy_probability =
      growth.empty() ? 0.0 : static_cast<double>(unstable) / static_cast<double>(growth.size());
  return b;
}

}  // namespace

GrowthBand growth_band(const GearModel& base, const std::vector<TireLawCoefficients>& draws,
                       StabilityPhase phase, unsigned threads,
                       const std::function<void(int, int)>& progress) {
  const int total = static_cast<int>(draws.size());
  std::vector<double> growth(draws.size(), std::numeric_limits<double>::quiet_NaN());
  detail::run_cells_in_parallel(total, threads, progress, [&](int k) {
    try {
      growth[static_cast<std::size_t>(k)] =
          linear_growth_rate(with_tire_law(base, draws[static_cast<std::size_t>(k)]), phase);
    } catch (const std::exception&) {
      // left NaN: not counted
    }
  });
  return summarise(growth);
}

StabilityMap probability_map(const GearModel& base, const MapAxis& x, const MapAxis& y,
                             StabilityPhase phase, const std::vector<TireLawCoefficients>& draws,
                             unsigned threads, const std::function<void(int, int)>& progress) {
  if (draws.empty()) throw InvalidArgument("draws", "0", "must be at least 1");
  StabilityMap map =
      evaluate_map(base, x, y, threads, progress, [&](const GearModel& model, MapCell& cell) {
        std::vector<double> growth;
        growth.reserve(draws.size());
        for (const TireLawCoefficients& d : draws)
          growth.push_back(linear_growth_rate(with_tire_law(model, d), phase));
        const GrowthBand b = summarise(growth);
        cell.valid = b.draws > 0;
        cell.growth_rate_per_s = b.median;
        cell.shimmy_probability = b.shimmy_probability;
        cell.shimmy = b.shimmy_probability >= 0.5;
      });
  map.linear = true;
  map.phase = phase;
  return map;
}

}  // namespace contensou
