#include "contensou/identification/exact_law_cache.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/quadrature.hpp"

namespace contensou {

namespace {

// phi_k = 1 + T_k(x), x = 2 t - 1 (k = 1, 2), and its derivative in t.
double basis_value(int k, double t) {
  const double x = 2.0 * t - 1.0;
  return k == 1 ? 1.0 + x : 2.0 * x * x;
}
double basis_slope(int k, double t) {
  return k == 1 ? 2.0 : 8.0 * (2.0 * t - 1.0);
}

// A^1 = (1/2) integral_0^1 sqrt(1 - t) P(t) dt of a series P in x = 2 t - 1, with t = 1 - u^2:
// integral_0^1 u^2 P(1 - u^2) du, a polynomial in u (Gauss-Legendre, exact for the degree).
double edge_series_moment(const std::vector<double>& c) {
  const GaussLegendreRule rule = gauss_legendre(static_cast<int>(c.size()) + 4);
  double sum = 0.0;
  for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
    const double u = 0.5 * (rule.nodes[i] + 1.0), x = 1.0 - 2.0 * u * u;
    double tm = 1.0, tk = x, p = c[0];  // Chebyshev recurrence T_k+1 = 2 x T_k - T_k-1
    for (std::size_t k = 1; k < c.size(); ++k) {
      p += c[k] * tk;
      const double next = 2.0 * x * tk - tm;
      tm = tk;
      tk = next;
    }
    sum += 0.5 * rule.weights[i] * u * u * p;
  }
  return sum;
}

// The model of a given profile times phi_k (t = rho^2 over the model's radius). A series times
// phi_k is a series, T_j T_k = (T_j+k + T_|j-k|) / 2 (exact); a table is the cubic Hermite
// interpolant of the product at its knots (its values and slopes by the product rule).
ExactModel<double> times_basis(const ExactModel<double>& m, int k) {
  if (const std::optional<TablePieces>& table = m.table()) {
    TabulatedShape tab;
    for (std::size_t i = 0; i < table->knot.size(); ++i) {
      const double t = table->knot[i];
      const std::size_t j = std::min(i, table->piece.size() - 1);
      const std::array<double, 4>& a = table->piece[j];
      const double h = t - table->knot[j];
      const double v = a[0] + h * (a[1] + h * (a[2] + h * a[3]));
      const double d = a[1] + h * (2.0 * a[2] + 3.0 * h * a[3]);
      tab.rho.push_back(i + 1 == table->knot.size() ? 1.0 : std::sqrt(t));
      tab.p.push_back(v * basis_value(k, t));
      tab.slope.push_back(d * basis_value(k, t) + v * basis_slope(k, t));
    }
    ContactPatch patch;
    patch.radius_m = m.radius;
    patch.reference_pressure_pa = 1.0;
    patch.friction = 1.0;
    patch.profile.shape = std::move(tab);
    patch.profile.keep_negative = true;  // a table's rounding at a zero rim
    return make_exact_model(patch, 1e-6);
  }
  const std::vector<double>& c = m.chebyshev();
  const std::size_t n = static_cast<std::size_t>(k);
  std::vector<double> d(c.size() + n, 0.0);
  for (std::size_t j = 0; j < c.size(); ++j) {
    d[j] += c[j];
    d[j + n] += 0.5 * c[j];
    d[j > n ? j - n : n - j] += 0.5 * c[j];
  }
  ExactModel<double> out = m;
  out.set_series(d, m.sqrt_edge(), 2.0 * m.representation_error());
  double a1 = 0.0;  // A^1 of a series: (1/2) sum over even j of d_j / (1 - j^2)
  if (m.sqrt_edge()) {
    a1 = edge_series_moment(d);
  } else {
    for (std::size_t j = 0; j < d.size(); j += 2) a1 += d[j] / (1.0 - static_cast<double>(j * j));
    a1 *= 0.5;
  }
  out.load_area = 2.0 * std::numbers::pi * m.radius * m.radius * a1;
  return out;
}

}  // namespace

ExactLawCache::ExactLawCache(double radius_m, std::optional<ExactModel<double>> profile,
                             double tolerance)
    : radius_m_(radius_m), tolerance_(tolerance), profile_(std::move(profile)) {}

const std::vector<ExactLaw>& ExactLawCache::laws(bool slip_speed, const StopRequest& stop,
                                                 int degree) const {
  // A given profile: its law at degree 0, with its products by 1 + T1, 1 + T2 at degree 2;
  // the parametric profile's degree 4 reuses the three laws of degree 2 and adds 1 + T3, 1 + T4.
  const int which = (slip_speed ? 1 : 0) + ((profile_ ? degree == 2 : degree == 4) ? 2 : 0);
  std::call_once(once_[which], [this, which, slip_speed, &stop] {
    // Any f_s != f_k builds the falling table; the fit sets f_s = 1, f_k = 1 - beta, w_s.
    std::optional<SlipSpeedFriction<double>> slip;
    if (slip_speed) slip = SlipSpeedFriction<double>{1.0, 0.5, 1.0, 1.0};
    ExactLawOptions options{tolerance_};
    options.stop = stop;
    std::vector<ExactLaw> laws;  // moved in when complete: an interrupted build leaves none
    if (profile_) {
      ExactModel<double> m = *profile_;
      m.slip_speed = slip;
      m.friction = 1.0;
      m.friction_scale = 1.0;
      laws.push_back(make_exact_law(m, options));
      for (int k = 1; k <= 2 && which >= 2; ++k) {
        ExactModel<double> mk = times_basis(m, k);
        mk.slip_speed = slip;
        mk.friction = 1.0;
        mk.friction_scale = 1.0;
        laws.push_back(make_exact_law(mk, options));
      }
      laws_[which] = std::move(laws);
      return;
    }
    std::size_t first = 0;
    if (which >= 2) {
      laws = this->laws(slip_speed, stop, 2);
      first = laws.size();
    }
    const std::vector<std::vector<double>> basis = {
        {1.0}, {1.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 1.0}, {1.0, 0.0, 0.0, 0.0, 1.0}};
    const std::size_t count = which >= 2 ? 5 : 3;
    for (std::size_t b = first; b < count; ++b) {
      ContactPatch patch;
      patch.radius_m = radius_m_;
      patch.reference_pressure_pa = 1.0;
      patch.friction = 1.0;
      patch.profile.shape = ChebyshevShape{basis[b]};
      patch.slip_speed_friction = slip;
      laws.push_back(make_exact_law(make_exact_model(patch), options));
    }
    laws_[which] = std::move(laws);
  });
  return laws_[which];
}

}  // namespace contensou
