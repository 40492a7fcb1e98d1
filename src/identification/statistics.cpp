#include "contensou/identification/statistics.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>

#include "contensou/friction/error.hpp"

namespace contensou {
namespace {

namespace bm = boost::math;

void require_probability(double p) {
  if (!(p > 0.0 && p < 1.0)) throw InvalidArgument("p", format_value(p), "must be in (0, 1)");
}

// P(X > x) of a distribution on [0, inf): 1 at and below 0, 0 at inf, NaN for NaN (Boost.Math
// refuses x outside the support and NaN).
template <class Distribution>
double survival_on_half_line(const Distribution& d, double x) {
  if (std::isnan(x)) return std::numeric_limits<double>::quiet_NaN();
  if (x <= 0.0) return 1.0;
  if (std::isinf(x)) return 0.0;
  return bm::cdf(bm::complement(d, x));
}

}  // namespace

double student_t_cdf(double t, double nu) {
  require_positive("nu", nu);
  if (std::isnan(t)) return t;
  if (std::isinf(t)) return t > 0.0 ? 1.0 : 0.0;
  return bm::cdf(bm::students_t_distribution<double>(nu), t);
}

double student_t_quantile(double p, double nu) {
  require_probability(p);
  require_positive("nu", nu);
  return bm::quantile(bm::students_t_distribution<double>(nu), p);
}

double normal_cdf(double z) {
  if (std::isnan(z)) return z;
  if (std::isinf(z)) return z > 0.0 ? 1.0 : 0.0;
  return bm::cdf(bm::normal_distribution<double>(), z);
}

double normal_quantile(double p) {
  require_probability(p);
  return bm::quantile(bm::normal_distribution<double>(), p);
}

double chi2_survival(double x, double k) {
  require_positive("k", k);
  return survival_on_half_line(bm::chi_squared_distribution<double>(k), x);
}

double chi2_quantile(double p, double k) {
  require_probability(p);
  require_positive("k", k);
  return bm::quantile(bm::chi_squared_distribution<double>(k), p);
}

double fisher_f_survival(double x, double d1, double d2) {
  require_positive("d1", d1);
  require_positive("d2", d2);
  return survival_on_half_line(bm::fisher_f_distribution<double>(d1, d2), x);
}

double fisher_f_quantile(double p, double d1, double d2) {
  require_probability(p);
  require_positive("d1", d1);
  require_positive("d2", d2);
  return bm::quantile(bm::fisher_f_distribution<double>(d1, d2), p);
}

RunsTest runs_test(const std::vector<double>& sequence) {
  RunsTest r;
  int last = 0;
  for (double v : sequence) {
    if (v == 0.0 || !std::isfinite(v)) continue;
    const int s = v > 0.0 ? 1 : -1;
    (s > 0 ? r.positive : r.negative)++;
    if (s != last) ++r.runs;
    last = s;
  }
  const double n1 = r.positive, n2 = r.negative, n = n1 + n2;
  if (n1 < 1 || n2 < 1 || n < 3) return r;  // too few signs to test: p = 1
  const double mean = 2.0 * n1 * n2 / n + 1.0;
  const double var = 2.0 * n1 * n2 * (2.0 * n1 * n2 - n) / (n * n * (n - 1.0));
  if (!(var > 0.0)) return r;
  r.z = (r.runs - mean) / std::sqrt(var);
  r.p_value = 2.0 * normal_cdf(-std::abs(r.z));
  return r;
}

double lag1_autocorrelation(const std::vector<double>& x) {
  if (x.size() < 3) return 0.0;
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    den += (x[i] - mean) * (x[i] - mean);
    if (i > 0) num += (x[i] - mean) * (x[i - 1] - mean);
  }
  return den > 0.0 ? num / den : 0.0;
}

double durbin_watson(const std::vector<double>& x) {
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    den += x[i] * x[i];
    if (i > 0) num += (x[i] - x[i - 1]) * (x[i] - x[i - 1]);
  }
  return den > 0.0 ? num / den : 2.0;
}

}  // namespace contensou
