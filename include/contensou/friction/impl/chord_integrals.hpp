// The chord integrals of the exact model (theory.md section 2): on a chord through the centre
// of sliding, r = foot + tau e, the moments integral sigma (tau - tau_c) {1, x, y} dtau / p*
// follow from M0 = integral p dw and M2 = integral p w^2 dw (w = tau / R), which for a series
// profile are the chord transforms Q0, Q2 at the foot (closed form) and for a table the
// piecewise sums of impl/table_pieces.hpp.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <utility>
#include <vector>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/profile_representation.hpp"
#include "contensou/friction/impl/table_pieces.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou {
namespace detail {

// A chord of the disk through the centre of sliding: points r = foot + tau e, tau in
// [-h, h], the centre of sliding at tau_c. foot is the point of the chord nearest to O.
template <class T>
struct Chord {
  T fx, fy;  // foot
  T ex, ey;  // unit direction
  T h;       // half-length [m]
  T tau_c;   // position of r_c on the chord [m]
  T t_foot;  // |foot|^2 / R^2
};

// Recomputes the chord transforms Q0, Q2 of the model's profile polynomial:
//   integral_{-h}^{h} p(t_f + w^2) {1, w^2} dw = {h^(1+e) Q0(t_f), h^(3+e) Q2(t_f)},
// h = (1 - t_f)^(1/2), e = 1 with a Hertz edge (p = sqrt(1 - t) P(t)), else 0. Q0 and Q2 are
// polynomials of the same degree as P; they are stored as Chebyshev series in t_f. Call after
// changing the series (ExactModel::set_series does).
template <class T>
void update_chord_transforms(ExactModel<T>& m) {
  const std::size_t deg = m.chebyshev().size() - 1, n = deg + 1;
  // Rule in u on [-1, 1] exact for degree 2 deg + 2: Gauss-Legendre, or Gauss-Chebyshev of
  // the second kind (weight sqrt(1 - u^2)) for a Hertz edge.
  std::vector<double> un, uw;
  const std::size_t nq = deg + 2;
  if (m.sqrt_edge()) {
    for (std::size_t i = 1; i <= nq; ++i) {
      const double a = std::numbers::pi * static_cast<double>(i) / static_cast<double>(nq + 1);
      un.push_back(std::cos(a));
      uw.push_back(std::numbers::pi / static_cast<double>(nq + 1) * std::sin(a) * std::sin(a));
    }
  } else {
    const GaussLegendreRule g = gauss_legendre(static_cast<int>(nq));
    un = g.nodes;
    uw = g.weights;
  }
  std::vector<T> q0(n, T(0.0)), q2(n, T(0.0));
  for (std::size_t j = 0; j < n; ++j) {
    // Chebyshev points in t_f and the transforms there (h^2 = 1 - t_f).
    const double zj =
        std::cos(std::numbers::pi * (static_cast<double>(j) + 0.5) / static_cast<double>(n));
    const double tf = 0.5 * (1.0 + zj), h2 = 1.0 - tf;
    T s0(0.0), s2(0.0);
    for (std::size_t i = 0; i < un.size(); ++i) {
      const T p = detail::chebyshev_sum(m.chebyshev(), tf + h2 * un[i] * un[i]);
      s0 += uw[i] * p;
      s2 += (uw[i] * un[i] * un[i]) * p;
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double ck = (k == 0 ? 1.0 : 2.0) / static_cast<double>(n) *
                        std::cos(std::numbers::pi * static_cast<double>(k) *
                                 (static_cast<double>(j) + 0.5) / static_cast<double>(n));
      q0[k] += ck * s0;
      q2[k] += ck * s2;
    }
  }
  m.chord_tail_.assign(n + 1, 0.0);
  for (std::size_t k = n; k-- > 0;)
    m.chord_tail_[k] = m.chord_tail_[k + 1] + std::abs(value_of(q0[k])) + std::abs(value_of(q2[k]));
  m.chord_q0_ = std::move(q0);
  m.chord_q2_ = std::move(q2);
}

// The chord's moments {integral sigma (tau - tau_c) {1, x, y} dtau} / p* from
// M0 = integral p dw and M2 = integral p w^2 dw over the chord (w = tau / R):
//   sigma (tau - tau_c) = R p (A + B w)(w - w_c), x = fx + R ex w.
template <class T>
void chord_moments_from(const ExactModel<T>& m, const Chord<T>& ch, const T& M0, const T& M2,
                        std::array<T, 3>& I) {
  const double R = m.radius, R2 = R * R;
  const T wc = ch.tau_c / R;
  const T A = 1.0 + (m.kx * ch.fx + m.ky * ch.fy) / R;  // shift factor at the foot
  const T B = m.kx * ch.ex + m.ky * ch.ey;              // its slope per unit w
  const T odd = A - B * wc;                             // coefficient of w in (A + B w)(w - w_c)
  I = {R2 * (B * M2 - A * wc * M0), R2 * ((odd * R * ch.ex + B * ch.fx) * M2 - A * wc * ch.fx * M0),
       R2 * ((odd * R * ch.ey + B * ch.fy) * M2 - A * wc * ch.fy * M0)};
}

// Closed-form moments of n <= 21 chords at once (no slip-speed law): the Clenshaw sums of
// the two chord transforms run across the chords, independent chains that vectorise.
//   sigma (tau - tau_c) = R p (A + B w)(w - w_c), x = fx + R ex w, w = tau / R.
// Only the first `terms` coefficients of the transforms are summed.
template <class T>
void chord_moments_closed_form(const ExactModel<T>& m, std::size_t terms, const Chord<T>* c, int n,
                               std::array<T, 3>* I) {
  constexpr int kMax = kKronrodPoints;
  const double R = m.radius;
  if (m.table()) {
    for (int i = 0; i < n; ++i) {
      T M0, M2;
      piecewise_chord_moments(m, c[i].t_foot, M0, M2);
      chord_moments_from(m, c[i], M0, M2, I[i]);
    }
    return;
  }
  std::array<T, kMax> z, a1, a2, b1, b2;
  for (int i = 0; i < n; ++i) {
    z[i] = 2.0 * c[i].t_foot - 1.0;
    a1[i] = a2[i] = b1[i] = b2[i] = T(0.0);
  }
  const T* q0 = m.chord_q0().data();
  const T* q2 = m.chord_q2().data();
  for (std::size_t k = terms - 1; k >= 1; --k) {
    for (int i = 0; i < n; ++i) {
      const T a0 = q0[k] + 2.0 * z[i] * a1[i] - a2[i];
      const T b0 = q2[k] + 2.0 * z[i] * b1[i] - b2[i];
      a2[i] = a1[i];
      a1[i] = a0;
      b2[i] = b1[i];
      b1[i] = b0;
    }
  }
  for (int i = 0; i < n; ++i) {
    const Chord<T>& ch = c[i];
    const T hp = ch.h / R;
    T M0 = hp * (q0[0] + z[i] * a1[i] - a2[i]);
    T M2 = hp * hp * hp * (q2[0] + z[i] * b1[i] - b2[i]);
    if (m.sqrt_edge()) {
      M0 *= hp;
      M2 *= hp;
    }
    chord_moments_from(m, ch, M0, M2, I[i]);
  }
}

}  // namespace detail
}  // namespace contensou
