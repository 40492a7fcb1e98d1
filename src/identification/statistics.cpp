#include "contensou/identification/statistics.hpp"

#include <cmath>
#include <limits>

#include "contensou/friction/error.hpp"

namespace contensou {
namespace {

// Continued fraction for I_x(a, b) (modified Lentz), valid for x < (a + 1)/(a + b + 2).
double beta_fraction(double a, double b, double x) {
  constexpr double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::abs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 1000; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a + m2 - 1.0) * (a + m2));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + m2 + 1.0));
    d = 1.0 + aa * d;
    if (std::abs(d) < tiny) d = tiny;
    c = 1.0 + aa / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-15) break;
  }
  return h;
}

}  // namespace

double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double lbt =
      std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x < (a + 1.0) / (a + b + 2.0)) return std::exp(lbt) * beta_fraction(a, b, x) / a;
  return 1.0 - std::exp(lbt) * beta_fraction(b, a, 1.0 - x) / b;
}

double student_t_cdf(double t, double nu) {
  require_positive("nu", nu);
  const double x = nu / (nu + t * t);
  const double tail = 0.5 * incomplete_beta(0.5 * nu, 0.5, x);
  return t >= 0.0 ? 1.0 - tail : tail;
}

double student_t_quantile(double p, double nu) {
  if (!(p > 0.0 && p < 1.0)) throw InvalidArgument("p", format_value(p), "must be in (0, 1)");
  require_positive("nu", nu);
  // Bracket and bisect the monotone CDF (robust for every nu).
  double lo = -1.0, hi = 1.0;
  while (student_t_cdf(lo, nu) > p) lo *= 2.0;
  while (student_t_cdf(hi, nu) < p) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * (1.0 + std::abs(lo)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (student_t_cdf(mid, nu) < p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double normal_cdf(double z) {
  return 0.5 * std::erfc(-z / std::sqrt(2.0));
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

namespace contensou {

double upper_incomplete_gamma(double a, double x) {
  require_positive("a", a);
  if (x <= 0.0) return 1.0;
  const double log_front = -x + a * std::log(x) - std::lgamma(a);
  if (x < a + 1.0) {  // series for P(a, x)
    double term = 1.0 / a, sum = term;
    for (int n = 1; n < 1000; ++n) {
      term *= x / (a + n);
      sum += term;
      if (std::abs(term) < 1e-16 * std::abs(sum)) break;
    }
    return 1.0 - sum * std::exp(log_front);
  }
  // Continued fraction for Q(a, x) (modified Lentz).
  constexpr double tiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::abs(c) < tiny) c = tiny;
    d = 1.0 / d;
    const double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-16) break;
  }
  return std::exp(log_front) * h;
}

double chi2_survival(double x, double k) {
  require_positive("k", k);
  return upper_incomplete_gamma(0.5 * k, 0.5 * x);
}

}  // namespace contensou
