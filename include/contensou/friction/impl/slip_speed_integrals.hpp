// The slip-speed-dependent part of the friction coefficient on a chord (theory.md section 2):
// with f(w) = f_k + (f_s - f_k) g(w), g(w) = exp(-(w / w_s)^delta), w = |omega| |tau - tau_c|,
// the f_k part is the closed form of impl/chord_integrals.hpp and only the falling part
// (f_s - f_k) g needs an inner adaptive rule along the chord (chord_moments_falling).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/chord_integrals.hpp"
#include "contensou/friction/impl/profile_representation.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// df/dw of the slip-speed law at w > 0: -(f_s - f_k) delta (w/w_s)^delta exp(-(w/w_s)^delta) / w.
template <class T>
T friction_slope_at(const SlipSpeedFriction<T>& law, const T& w) {
  using std::exp;
  using std::pow;
  const T z = pow(w / law.reference_speed, law.exponent);
  return -(law.static_coefficient - law.kinetic_coefficient) * law.exponent * z * exp(-z) / w;
}

// Requested tolerances from which a table's chords are broken at knot crossings (f(w) inside).
inline constexpr double kBreakChordsTolerance = 1e-5;

// The falling part's integrand on a chord at n nodes x (theory.md section 2):
//   sigma g(w) (tau - tau_c) {1, x, y} / p* = p (A + B tau/R) (tau - tau_c) g(w) {1, fx + tau ex,
//   fy + tau ey},  w = |omega| |tau - tau_c|,
// in tau, or for a Hertz edge in the chord angle theta: tau = h sin(theta), dtau = h cos(theta)
// dtheta, sqrt(1 - t) = h cos(theta) / R (then the edge is smooth). The profile series is summed
// to `terms` terms.
template <class T>
struct FallingIntegrand {
  const ExactModel<T>& m;
  const Chord<T>& c;
  const T& abs_omega;
  std::size_t terms;
  T A;  // shift factor at the foot, 1 + (k . foot) / R
  T B;  // its slope per unit w = tau / R, k . e

  void operator()(const double* x, int n, int, Sample<T, 3>* out) const {
    const double R = m.radius;
    const bool angle = m.sqrt_edge();
    std::array<T, kKronrodPoints> tau, jac, p;
    // {}: GCC 12 at -O1 with sanitizers reports a false maybe-uninitialized (-Werror).
    std::array<T, kKronrodPoints> t{};
    for (int i = 0; i < n; ++i) {
      if (angle) {
        const double cs = std::cos(x[i]);
        tau[i] = c.h * std::sin(x[i]);
        jac[i] = c.h * cs;
        const T edge = jac[i] / R;  // sqrt(1 - t)
        t[i] = 1.0 - edge * edge;
      } else {
        tau[i] = T(x[i]);
        jac[i] = T(1.0);
        t[i] = c.t_foot + (tau[i] / R) * (tau[i] / R);
      }
    }
    profile_batch(m, t.data(), n, terms, p.data());
    for (int i = 0; i < n; ++i) {
      if (angle) p[i] *= jac[i] / R;
      const T arm = tau[i] - c.tau_c;
      const T w = abs_omega * (value_of(arm) < 0.0 ? -arm : arm);
      const T v = p[i] * (A + B * (tau[i] / R)) * arm * slip_speed_decay(*m.slip_speed, w) * jac[i];
      out[i].value = {v, v * (c.fx + tau[i] * c.ex), v * (c.fy + tau[i] * c.ey)};
    }
  }
};

// The falling part's range on a chord and its kink at the centre of sliding (|tau - tau_c|):
// tau in [-h, h], mid = tau_c clamped; for a Hertz edge theta in [-pi/2, pi/2], mid =
// asin(tau_c / h).
struct ChordRange {
  double lo, hi, mid;
};

template <class T>
ChordRange falling_range(const ExactModel<T>& m, const Chord<T>& c) {
  if (m.sqrt_edge()) {
    const double ratio = std::clamp(value_of(c.tau_c) / std::max(value_of(c.h), 1e-300), -1.0, 1.0);
    return {-0.5 * std::numbers::pi, 0.5 * std::numbers::pi, std::asin(ratio)};
  }
  const double hi = value_of(c.h), lo = -hi;
  return {lo, hi, std::clamp(value_of(c.tau_c), lo, hi)};
}

// Whether g is below 1e-3 on the whole chord, the centre of sliding off it: w >= |omega|
// (|tau_c| - h) there (then the falling part is small and one G15K31 panel usually suffices).
template <class T>
bool falls_off_on_chord(const ExactModel<T>& m, const Chord<T>& c, const T& abs_omega) {
  const double w_min =
      value_of(abs_omega) * std::max(0.0, std::abs(value_of(c.tau_c)) - value_of(c.h));
  return value_of(slip_speed_decay(*m.slip_speed, T(w_min))) < 1e-3;
}

// Break points of a table's chord: it crosses knot t_k at tau = +-R (t_k - t_foot)^(1/2), where
// the profile is only C1. At most kChordBreaks per half chord, every m-th knot (4 let the inner
// rule run out of intervals at 1e-6, 16 to 32 cost more for no gain on a 101-point table).
inline constexpr std::size_t kChordBreaks = 8;
using ChordParts = std::array<TaggedInterval, 2 * kChordBreaks + 4>;

// The pieces of a table's chord (range r) between knot crossings, also broken at the centre of
// sliding r.mid: on each the profile is one cubic in t, a polynomial of degree 6 in tau.
// Returns their number.
template <class T>
int knot_crossing_parts(const ExactModel<T>& m, const Chord<T>& c, const ChordRange& r,
                        ChordParts& parts) {
  const double R = m.radius, lo = r.lo, hi = r.hi, mid = r.mid;
  std::array<double, kChordBreaks> cross;
  const double tf = value_of(c.t_foot);
  const std::vector<double>& knot = m.table()->knot;
  const std::size_t first_knot = std::upper_bound(knot.begin(), knot.end(), tf) - knot.begin();
  const std::size_t inside = first_knot + 1 < knot.size() ? knot.size() - 1 - first_knot : 0;
  const std::size_t stride = std::max<std::size_t>(1, (inside + kChordBreaks - 1) / kChordBreaks);
  std::size_t nc = 0;
  for (std::size_t k = first_knot; k + 1 < knot.size() && nc < kChordBreaks; k += stride)
    cross[nc++] = R * std::sqrt(knot[k] - tf);
  std::array<double, 2 * kChordBreaks + 3> pts;
  std::size_t np = 0;
  pts[np++] = lo;
  for (std::size_t j = nc; j-- > 0;)
    if (-cross[j] > lo) pts[np++] = -cross[j];
  for (std::size_t j = 0; j < nc; ++j)
    if (cross[j] < hi) pts[np++] = cross[j];
  pts[np++] = hi;
  int count = 0;
  for (std::size_t j = 0; j + 1 < np; ++j) {
    const double a = pts[j], b = pts[j + 1];
    if (mid > a && mid < b) {
      parts[count++] = {a, mid, 0};
      parts[count++] = {mid, b, 0};
    } else if (b > a) {
      parts[count++] = {a, b, 0};
    }
  }
  return count;
}

// The falling part of a slip-speed law on one chord: integral sigma g(w) (tau - tau_c)
// {1, x, y} dtau / p* (FallingIntegrand). Adaptive G15K31 on the two sides of the centre of
// sliding (falling_range), the profile series summed to `terms` terms. break_at_knots (loose
// tolerances only, kBreakChordsTolerance): a table's chords are broken at knot crossings, G7K15
// on each piece (knot_crossing_parts), unless g falls off on the whole chord and one panel
// converges.
template <class T>
std::array<T, 3> chord_moments_falling(const ExactModel<T>& m, const Chord<T>& c,
                                       const T& abs_omega, std::size_t terms,
                                       std::array<double, 3>& inner_error,
                                       const std::array<double, 3>& tol, bool break_at_knots) {
  const double R = m.radius;
  inner_error = {0.0, 0.0, 0.0};
  const FallingIntegrand<T> f{
      m, c, abs_omega, terms, 1.0 + (m.kx * c.fx + m.ky * c.fy) / R, m.kx * c.ex + m.ky * c.ey};
  const ChordRange range = falling_range(m, c);
  const TaggedInterval halves[2] = {{range.lo, range.mid, 0}, {range.mid, range.hi, 1}};
  const int first = range.mid > range.lo ? 0 : 1;
  const int sides = (range.mid < range.hi ? 2 : 1) - first;
  if (!m.table() || !break_at_knots) {
    const auto r = integrate_adaptive_batch<T, 3, 48, kGK31>(f, halves + first, sides, tol);
    inner_error = r.error;
    return r.value;
  }
  if (sides == 1 && falls_off_on_chord(m, c, abs_omega)) {
    const auto r = integrate_adaptive_batch<T, 3, 2, kGK31>(f, halves + first, 1, tol);
    if (r.converged) {
      inner_error = r.error;
      return r.value;
    }
  }
  ChordParts parts;
  const int count = knot_crossing_parts(m, c, range, parts);
  const auto r =
      integrate_adaptive_batch<T, 3, 4 * kChordBreaks, kGK15>(f, parts.data(), count, tol);
  inner_error = r.error;
  return r.value;
}

}  // namespace contensou::detail
