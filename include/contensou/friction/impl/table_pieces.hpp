// The chord integrals of a tabulated profile, piece by piece (theory.md section 2): a table's
// cubic pieces in t = rho^2 give M0(t_f) = integral p (t - t_f)^(-1/2) dt and M2(t_f) =
// integral p (t - t_f)^(1/2) dt in closed form, the near pieces as knot terms or Gauss sums,
// the far ones as Chebyshev series fitted once a build (update_far_sums, exact_resultants.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// The knot terms of a piecewise profile's chord integrals (theory.md section 2):
//   M0(t_f) = integral_{-h}^{h} p(t_f + w^2) dw = integral_{t_f}^1 p(t) (t - t_f)^(-1/2) dt,
//   M2(t_f) = integral_{-h}^{h} p(t_f + w^2) w^2 dw = integral_{t_f}^1 p(t) (t - t_f)^(1/2) dt.
// With a piece written about a point t*, p = sum_j c_j (t - t*)^j, the antiderivative from
// t_f takes at t* the value (t* - t_f)^(1/2) sum_j kappa_j c_j (t* - t_f)^j, kappa_j =
// sum_i C(j, i) (-1)^(j-i) / (i + 1/2) (and (t* - t_f)^(3/2) sum_j lambda_j c_j (t* - t_f)^j,
// lambda_j with i + 3/2, for M2). Each knot above t_f then adds, with delta = knot - t_f,
//   M0 += delta^(1/2) sum_j knot_m0[k][j] delta^j,  M2 += delta^(3/2) sum_j knot_m2[k][j] delta^j,
// knot_m[k][j] = kappa_j (c_j of the piece below, about the knot - c_j of the piece above):
// within a knot no term is differenced against another of its size, and a C1 table leaves only
// j = 2, 3. Across knots they cancel: a piece's integral, ~ |c_3| h^4 delta^(-1/2), is the
// difference of two knot terms ~ |c_3| delta^(7/2); so they serve only the near knots, and only
// where no near piece is narrower than 1/8 of the distance (update_far_sums); elsewhere the
// pieces are integrated (cubic_moments).
inline void update_knot_terms(TablePieces& table) {
  const std::vector<double>& knot = table.knot;
  const std::vector<std::array<double, 4>>& piece = table.piece;
  std::vector<std::array<double, 4>>& m0 = table.knot_m0;
  std::vector<std::array<double, 4>>& m2 = table.knot_m2;
  std::array<double, 4> kappa{}, lambda{};
  for (int j = 0; j < 4; ++j) {
    double binom = 1.0;
    for (int i = j; i >= 0; --i) {  // C(j, i) for i = j, j-1, ...
      const double sign = (j - i) % 2 ? -1.0 : 1.0;
      kappa[j] += sign * binom / (i + 0.5);
      lambda[j] += sign * binom / (i + 1.5);
      binom = binom * i / (j - i + 1);
    }
  }
  const std::size_t n = piece.size();
  m0.assign(n + 1, {0.0, 0.0, 0.0, 0.0});
  m2.assign(n + 1, {0.0, 0.0, 0.0, 0.0});
  for (std::size_t k = 1; k <= n; ++k) {
    // The piece below, re-expanded about its upper end knot[k]: c_j(up) = sum_i C(i, j) h^(i-j)
    // c_i.
    const std::array<double, 4>& c = piece[k - 1];
    const double h = knot[k] - knot[k - 1];
    const std::array<double, 4> up = {c[0] + h * (c[1] + h * (c[2] + h * c[3])),
                                      c[1] + h * (2.0 * c[2] + 3.0 * h * c[3]),
                                      c[2] + 3.0 * h * c[3], c[3]};
    for (int j = 0; j < 4; ++j) {
      const double diff = up[j] - (k < n ? piece[k][j] : 0.0);
      m0[k][j] = kappa[j] * diff;
      m2[k][j] = lambda[j] * diff;
    }
  }
}

// Chebyshev terms of the far pieces' series on each knot interval (update_far_sums).
inline constexpr int kFarTerms = 18;

// The chord integrals of a piecewise profile (theory.md section 2):
//   M0(t_f) = integral_{-h}^{h} p(t_f + w^2) dw = integral_{t_f}^1 p(t) (t - t_f)^(-1/2) dt,
//   M2(t_f) = integral_{-h}^{h} p(t_f + w^2) w^2 dw = integral_{t_f}^1 p(t) (t - t_f)^(1/2) dt.
// Over a piece [lo, hi] of the cubic q = sum_j c_j (t - t0)^j (t_f <= lo), with t = t_f + w^2,
// they are integral 2 q dw and integral 2 q w^2 dw, polynomials of degree 6 and 8 in w: 5-point
// Gauss-Legendre in w is exact, s = t - t0 = (lo - t0) + (w - w_lo)(w + w_lo); from_foot: lo =
// t_f (w_lo = 0, so no square root of 0 is differentiated). Every node's term is bounded by
// the cubic's values on the piece: no cancellation (the antiderivatives at the knots, of size
// |c_3| (t_k - t_f)^(7/2), cancelled to 1e-7 of the profile on a 10,001-point table).
// The same from w_lo = (lo - t_f)^(1/2), w_hi = (hi - t_f)^(1/2) and base = (lo or t_f) - t0,
// for callers that form those differences themselves (update_far_sums).
template <class T>
void cubic_moments_between(const std::array<double, 4>& c, const T& wl, const T& wh, const T& base,
                           T& M0, T& M2) {
  constexpr double x[5] = {-0.90617984593866399280, -0.53846931010568309104, 0.0,
                           0.53846931010568309104, 0.90617984593866399280};
  constexpr double wt[5] = {0.23692688505618908751, 0.47862867049936646804, 0.56888888888888888889,
                            0.47862867049936646804, 0.23692688505618908751};
  const T mid = 0.5 * (wl + wh), half = 0.5 * (wh - wl);
  M0 = T(0.0);
  M2 = T(0.0);
  for (int i = 0; i < 5; ++i) {
    const T w = mid + half * x[i];
    const T s = base + (w - wl) * (w + wl);
    const T q = 2.0 * wt[i] * half * (c[0] + s * (c[1] + s * (c[2] + s * c[3])));
    M0 += q;
    M2 += q * w * w;
  }
}

template <class T>
void cubic_moments(const std::array<double, 4>& c, double t0, double lo, double hi, const T& t_f,
                   bool from_foot, T& M0, T& M2) {
  using std::sqrt;
  const T wl = from_foot ? T(0.0) : T(sqrt(lo - t_f)), wh = sqrt(hi - t_f);
  const T base = from_foot ? T(t_f - t0) : T(lo - t0);
  cubic_moments_between(c, wl, wh, base, M0, M2);
}

// On the knot interval [knot[k], knot[k+1]] the pieces from the first knot at least one
// interval width beyond its upper end (knot far_from[k], at most kMaxNear knots on) are far:
// their integrals are smooth there (the nearest singularity lies a width away, so a Chebyshev
// series converges like 5.8^-n) and stored as a series of kFarTerms terms. The near ones are
// summed at each call: as knot terms (one or two on an even table), or, where a near piece is
// narrower than 1/8 of the distance from the interval (uneven knots: the knot terms would
// cancel), integrated (cubic_moments; near_integrated[k] = 1). With knot terms the series also
// holds the antiderivative of the piece below knot far_from[k] (which they leave out), so that
// its (knot - t_f)^(1/2) singularity cancels. A chord thus costs a few knot terms or pieces and
// two short series, whatever the number of knots. The series are fitted top-down on a binary
// tree of the pieces (table_far_sums.cpp): a node's (or interval's) far sums are its
// parent's series plus the few pieces between the two, summed from the pieces' moments, so
// that every fit sums a bounded number of terms: O(n) in the number of knots (docs/speed.md,
// "Dense tables"). Returns the largest deviation of the series from those sums at test
// points (M0 and M2), the deviations of its ancestors' series added.
inline constexpr std::size_t kMaxNear = 512;
double update_far_sums(TablePieces& table);

// M0 and M2 of a piecewise profile at t_f: the near knot terms or pieces above t_f, the far
// pieces from the series of t_f's interval.
template <class T>
void piecewise_chord_moments(const ExactModel<T>& m, const T& t_f, T& M0, T& M2) {
  using std::sqrt;
  const TablePieces& tp = *m.table();
  const std::vector<double>& knot = tp.knot;
  const double tv = value_of(t_f);
  M0 = T(0.0);
  M2 = T(0.0);
  if (!(tv < 1.0)) return;
  const std::size_t n = knot.size() - 1;
  std::size_t k = std::upper_bound(knot.begin(), knot.end(), tv) - knot.begin();
  k = std::min(std::max<std::size_t>(k, 1), n) - 1;  // t_f in [knot[k], knot[k+1])
  if (tp.near_integrated[k]) {
    for (std::size_t j = k; j < std::min(tp.far_from[k], n); ++j) {
      T a0, a2;
      cubic_moments(tp.piece[j], knot[j], knot[j], knot[j + 1], t_f, j == k, a0, a2);
      M0 += a0;
      M2 += a2;
    }
  } else {
    for (std::size_t j = k + 1; j < tp.far_from[k]; ++j) {
      const T d = knot[j] - t_f;
      const T r = sqrt(d);
      const auto& a = tp.knot_m0[j];
      const auto& b = tp.knot_m2[j];
      M0 += r * (a[0] + d * (a[1] + d * (a[2] + d * a[3])));
      M2 += r * d * (b[0] + d * (b[1] + d * (b[2] + d * b[3])));
    }
  }
  const double lo = knot[k], hi = knot[k + 1];
  const T z = (2.0 * t_f - lo - hi) / (hi - lo);
  const double* c0 = tp.far_m0.data() + k * kFarTerms;
  const double* c2 = tp.far_m2.data() + k * kFarTerms;
  T p1(0.0), p2(0.0), q1(0.0), q2(0.0);
  for (int i = kFarTerms - 1; i >= 1; --i) {
    const T p0 = c0[i] + 2.0 * z * p1 - p2;
    const T q0 = c2[i] + 2.0 * z * q1 - q2;
    p2 = p1;
    p1 = p0;
    q2 = q1;
    q1 = q0;
  }
  M0 += c0[0] + z * p1 - p2;
  M2 += c2[0] + z * q1 - q2;
}

}  // namespace contensou::detail
