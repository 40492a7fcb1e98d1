// The outer rule's partition for a tabulated profile (theory.md section 2): a chord's foot
// t_foot crosses a knot t_k where the chord integrals have a (t_k - t_foot)^(5/2) kink; the
// outer integral is broken there at first and bisected at crossings (integrate_table).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/quadrature.hpp"

namespace contensou::detail {

// Knot crossings of a table's outer integral: at first at most kMaxCrossings break points per
// half range (a finer table gets every m-th knot as a break point; adaptivity, splitting at
// crossings, does the rest) and kPiecewiseCapacity intervals, on the stack; if that runs out
// (constant f), every crossing and kCrossingCapacity intervals per crossing, on the heap.
inline constexpr std::size_t kMaxCrossings = 256;
inline constexpr int kPiecewiseCapacity = 640;
inline constexpr int kCrossingCapacity = 4;

// The number of interior knots with t_k < s_max^2: those a chord's foot crosses.
inline std::size_t knots_inside(const std::vector<double>& knot, double s_max) {
  if (!(s_max > 0.0) || knot.size() < 3) return 0;
  return static_cast<std::size_t>(
      std::lower_bound(knot.begin() + 1, knot.end() - 1, s_max * s_max) - (knot.begin() + 1));
}

// The outer intervals of a table, broken where a chord's foot crosses a knot, at x = asin(
// sqrt(t_k) / s_max) on [0, pi/2] for every stride-th knot inside (at most max_breaks), then
// mirrored to [pi/2, pi] (mirror = pi: x -> pi - x) or to [-pi/2, 0] (mirror = 0: x -> -x).
// out has room for 2 (min(max_breaks, knots_inside) + 1) intervals. Returns their number.
inline int crossing_intervals(const std::vector<double>& knot, double s_max, std::size_t max_breaks,
                              double mirror, TaggedInterval* out) {
  const std::size_t inside = max_breaks > 0 ? knots_inside(knot, s_max) : 0;
  const std::size_t stride =
      std::max<std::size_t>(1, (inside + max_breaks - 1) / std::max<std::size_t>(max_breaks, 1));
  const double half_pi = 0.5 * std::numbers::pi;
  int nb = 0;
  double prev = 0.0;
  std::size_t count = 0;
  for (std::size_t k = 1; k <= inside && count < max_breaks; k += stride, ++count) {
    const double x = std::asin(std::min(1.0, std::sqrt(knot[k]) / s_max));
    if (x > prev) out[nb++] = {prev, x, 0};
    prev = x;
  }
  if (half_pi > prev) out[nb++] = {prev, half_pi, 0};
  for (int j = nb - 1; j >= 0; --j) {
    const double a = mirror == 0.0 ? -out[j].b : mirror - out[j].b;
    const double b = mirror == 0.0 ? -out[j].a : mirror - out[j].a;
    out[nb + (nb - 1 - j)] = {a, b, 0};
  }
  return 2 * nb;
}

// Bisection of a table's outer interval at the knot crossing nearest its midpoint, so that
// kinks become interval ends (between crossings the integrand is analytic); at the midpoint if
// no crossing lies inside, away from the ends. Crossings: s_max^2 sin^2 x = t_k on [0, pi/2],
// mirrored as in crossing_intervals.
struct KnotCrossingSplit {
  const std::vector<double>* knot;
  double s_max;
  double mirror;
  double operator()(double a, double b) const {
    const double mid = 0.5 * (a + b), half_pi = 0.5 * std::numbers::pi;
    const bool flip = mirror == 0.0 ? b <= 0.0 : a >= half_pi;
    const double lo = flip ? (mirror == 0.0 ? -b : mirror - b) : a;
    const double hi = flip ? (mirror == 0.0 ? -a : mirror - a) : b;
    if (!(lo >= 0.0 && hi <= half_pi)) return mid;
    const double xm = 0.5 * (lo + hi), sm = s_max * std::sin(xm), margin = 0.05 * (hi - lo);
    const std::vector<double>& k = *knot;
    const std::size_t up = std::upper_bound(k.begin(), k.end(), sm * sm) - k.begin();
    double best = xm, gap = 2.0 * half_pi;
    for (std::size_t j : {up - 1, up}) {
      if (j < 1 || j + 1 >= k.size()) continue;  // interior knots only
      const double x = std::asin(std::min(1.0, std::sqrt(k[j]) / s_max));
      if (x > lo + margin && x < hi - margin && std::abs(x - xm) < gap) {
        gap = std::abs(x - xm);
        best = x;
      }
    }
    return flip ? (mirror == 0.0 ? -best : mirror - best) : best;
  }
};

// A table's outer integral: broken at knot crossings (every m-th, at most max_breaks per half
// range) and bisected at crossings, with the intervals on the stack; if that runs out with
// constant f, again from every crossing with kCrossingCapacity intervals per crossing on the
// heap (a kink at every knot: noisy data, steps). The evaluations of both attempts count.
template <class T, class F>
AdaptiveResult<T, 3> integrate_table(F& f, const ExactModel<T>& m, double s_max, double mirror,
                                     std::size_t max_breaks, const std::array<double, 3>& tol) {
  const KnotCrossingSplit split{&m.table()->knot, s_max, mirror};
  std::array<TaggedInterval, 2 * kMaxCrossings + 2> breaks;
  const int nb = crossing_intervals(m.table()->knot, s_max, std::min(max_breaks, kMaxCrossings),
                                    mirror, breaks.data());
  auto r =
      integrate_adaptive_batch<T, 3, kPiecewiseCapacity, kGK15>(f, breaks.data(), nb, tol, split);
  if (r.converged || m.slip_speed) return r;
  const std::size_t inside = knots_inside(m.table()->knot, s_max);
  std::vector<TaggedInterval> all(2 * inside + 2);
  const int na = crossing_intervals(m.table()->knot, s_max, inside, mirror, all.data());
  const int spent = r.evaluations;
  r = integrate_adaptive_batch_heap<T, 3, kGK15>(
      f, all.data(), na, tol, kCrossingCapacity * na + kPiecewiseCapacity, split);
  r.evaluations += spent;
  return r;
}

}  // namespace contensou::detail
