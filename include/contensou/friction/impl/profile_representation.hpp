// The model's representation of the pressure profile p(t), t = rho^2 (theory.md section 2):
// a Chebyshev series in z = 2 t - 1 (times sqrt(1 - t) for a Hertz edge, applied by the
// callers) or a table's cubic pieces in t; its values, one at a time or in batches, and its
// load moments.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// Clenshaw sum of a Chebyshev series in z = 2 t - 1 (its first `terms` terms; 0: all).
template <class T, class S>
T chebyshev_sum(const std::vector<T>& c, const S& t, std::size_t terms = 0) {
  const S z = 2.0 * t - 1.0;
  T b1(0.0), b2(0.0);
  const std::size_t n = terms == 0 ? c.size() : std::min(terms, c.size());
  for (std::size_t k = n - 1; k >= 1; --k) {
    const T b0 = c[k] + 2.0 * z * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + z * b1 - b2;
}

// The profile of a model at t = rho^2 (Chebyshev series, its first `terms` terms if given; or
// piecewise).
template <class T, class S>
T profile_at(const ExactModel<T>& m, const S& t, std::size_t terms = 0) {
  if (!m.table()) return chebyshev_sum(m.chebyshev(), t, terms);
  const double tv = std::clamp(value_of(t), 0.0, 1.0);
  const std::vector<double>& knot = m.table()->knot;
  std::size_t k = std::upper_bound(knot.begin(), knot.end(), tv) - knot.begin();
  k = std::min(std::max<std::size_t>(k, 1), m.table()->piece.size()) - 1;
  const auto& c = m.table()->piece[k];
  const S s = t - knot[k];
  return T(c[0] + s * (c[1] + s * (c[2] + s * c[3])));
}

// The profile at n points t[i] (batch: the Clenshaw chains of a series run side by side).
template <class T>
void profile_batch(const ExactModel<T>& m, const T* t, int n, std::size_t terms, T* out) {
  if (m.table()) {
    for (int i = 0; i < n; ++i) out[i] = profile_at(m, t[i]);
    return;
  }
  constexpr int kMax = kKronrodPoints;
  std::array<T, kMax> z, b1, b2;
  for (int i = 0; i < n; ++i) {
    z[i] = 2.0 * t[i] - 1.0;
    b1[i] = b2[i] = T(0.0);
  }
  const std::size_t nt = std::min(std::max<std::size_t>(terms, 1), m.chebyshev().size());
  for (std::size_t k = nt - 1; k >= 1; --k) {
    const T& c = m.chebyshev()[k];
    for (int i = 0; i < n; ++i) {
      const T b0 = c + 2.0 * z[i] * b1[i] - b2[i];
      b2[i] = b1[i];
      b1[i] = b0;
    }
  }
  for (int i = 0; i < n; ++i) out[i] = m.chebyshev()[0] + z[i] * b1[i] - b2[i];
}

// Moments of the representation: {integral_0^1 p rho d rho, integral_0^1 p rho^3 d rho}.
template <class T>
std::array<T, 2> representation_moments(const ExactModel<T>& m) {
  // t = rho^2; with a sqrt edge substitute t = 1 - u^2 (dt = 2u du) to keep it polynomial.
  std::array<T, 2> a{T(0.0), T(0.0)};
  if (m.table()) {  // (1/2) integral p {1, t} dt, piece by piece (cubic: exact)
    const TablePieces& tp = *m.table();
    for (std::size_t k = 0; k < tp.piece.size(); ++k) {
      const auto& c = tp.piece[k];
      const double h = tp.knot[k + 1] - tp.knot[k], t0 = tp.knot[k];
      const double i0 = h * (c[0] + h * (c[1] / 2 + h * (c[2] / 3 + h * c[3] / 4)));
      const double i1 = h * h * (c[0] / 2 + h * (c[1] / 3 + h * (c[2] / 4 + h * c[3] / 5)));
      a[0] += T(0.5 * i0);
      a[1] += T(0.5 * (t0 * i0 + i1));
    }
    return a;
  }
  const GaussLegendreRule g = gauss_legendre(static_cast<int>(m.chebyshev().size()) + 3);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const double x = 0.5 * (1.0 + g.nodes[i]), w = 0.5 * g.weights[i];
    double t = x, jac = 1.0;
    if (m.sqrt_edge()) {
      t = 1.0 - x * x;
      jac = 2.0 * x * x;  // sqrt(1 - t) = u, dt = 2 u du
    }
    const T p = chebyshev_sum(m.chebyshev(), t) * (w * jac);
    a[0] += 0.5 * p;
    a[1] += 0.5 * p * t;
  }
  return a;
}

}  // namespace contensou::detail
