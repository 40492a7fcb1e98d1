/// \file
/// Global adaptive Gauss-Kronrod (G10K21) integration of a small vector of integrands over a
/// set of tagged intervals, with a fixed-capacity interval store on the stack (no heap
/// allocation; integrate_adaptive_batch_heap for a store too large for it).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

/// One sample of a vector integrand; inner_error carries the error of a nested integral.
template <class T, int Dim>
struct Sample {
  std::array<T, Dim> value{};
  std::array<double, Dim> inner_error{};
};

template <class T, int Dim>
struct AdaptiveResult {
  std::array<T, Dim> value{};
  std::array<double, Dim> error{};
  int evaluations = 0;
  int intervals = 0;
  bool converged = false;
};

struct TaggedInterval {
  double a;
  double b;
  int tag;
};

/// Largest number of nodes of a rule used here (G15K31).
inline constexpr int kKronrodPoints = 31;

/// Where an interval is bisected: its midpoint (a table's outer rule splits at kinks instead).
struct MidpointSplit {
  double operator()(double a, double b) const { return 0.5 * (a + b); }
};

/// An interval of the adaptive rule with its estimate, and its place in the bisection order
/// (the largest error relative to the tolerance; a max-heap of these picks the next interval).
template <class T, int Dim>
struct AdaptivePiece {
  double a, b;
  int tag;
  std::array<T, Dim> value;
  std::array<double, Dim> error;
};

struct PieceRank {
  double scaled;
  int index;
  bool operator<(const PieceRank& o) const { return scaled < o.scaled; }
};

/// The Kronrod rule on [a, b] with the error estimate of QUADPACK (kronrod_error), the nested
/// integrals' errors and a rounding term 4e-16 |value|.
template <class T, int Dim, const auto& Rule, class F>
AdaptivePiece<T, Dim> evaluate_piece(F& f, double a, double b, int tag, int& evaluations) {
  AdaptivePiece<T, Dim> p{a, b, tag, {}, {}};
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  std::array<T, Dim> kron{}, gauss{};
  std::array<double, Dim> kron_d{}, inner{}, absdev{};
  std::array<std::array<double, Dim>, kKronrodPoints> plain{};
  std::array<double, kKronrodPoints> xs{};
  std::array<Sample<T, Dim>, kKronrodPoints> ys{};
  for (auto& v : kron) v = T(0);
  for (auto& v : gauss) v = T(0);
  int idx = 0;
  constexpr int points = kronrod_points(Rule);
  for (const KronrodNode& node : Rule) {
    xs[idx++] = mid + half * node.x;
    if (node.x != 0.0) xs[idx++] = mid - half * node.x;
  }
  f(xs.data(), points, tag, ys.data());
  idx = 0;
  for (const KronrodNode& node : Rule) {
    const int signs = node.x == 0.0 ? 1 : 2;
    for (int s = 0; s < signs; ++s) {
      const Sample<T, Dim>& y = ys[idx];
      for (int c = 0; c < Dim; ++c) {
        kron[c] += node.kronrod * y.value[c];
        if (node.gauss != 0.0) gauss[c] += node.gauss * y.value[c];
        plain[idx][c] = value_of(y.value[c]);
        kron_d[c] += node.kronrod * plain[idx][c];
        inner[c] += node.kronrod * y.inner_error[c];
      }
      ++idx;
    }
  }
  evaluations += points;
  idx = 0;
  for (const KronrodNode& node : Rule) {
    const int signs = node.x == 0.0 ? 1 : 2;
    for (int s = 0; s < signs; ++s, ++idx)
      for (int c = 0; c < Dim; ++c)
        absdev[c] += node.kronrod * std::abs(plain[idx][c] - 0.5 * kron_d[c]);
  }
  for (int c = 0; c < Dim; ++c) {
    p.value[c] = half * kron[c];
    const double diff = half * (value_of(kron[c]) - value_of(gauss[c]));
    p.error[c] = kronrod_error(diff, std::abs(half) * absdev[c]) + std::abs(half) * inner[c] +
                 4.0e-16 * std::abs(value_of(p.value[c]));
  }
  return p;
}

/// Sums the pieces' values into out (in index order) and records their number.
template <class T, int Dim>
AdaptiveResult<T, Dim> sum_pieces(AdaptiveResult<T, Dim>& out, const AdaptivePiece<T, Dim>* pieces,
                                  int n) {
  for (auto& v : out.value) v = T(0);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < Dim; ++c) out.value[c] += pieces[i].value[c];
  out.intervals = n;
  return out;
}

/// The adaptive loop over caller-provided storage for `capacity` pieces and ranks: bisects the
/// interval of largest scaled error (at split(a, b)) until every component's total error is
/// <= tolerance[c], the store is full, or an interval reaches machine resolution. The total is
/// kept by differences and summed afresh before it is trusted.
template <class T, int Dim, const auto& Rule, class F, class Split>
AdaptiveResult<T, Dim> adaptive_loop(F& f, const TaggedInterval* initial, int n_initial,
                                     const std::array<double, Dim>& tolerance, const Split& split,
                                     AdaptivePiece<T, Dim>* pieces, PieceRank* ranks,
                                     int capacity) {
  AdaptiveResult<T, Dim> out;
  int n = 0;
  auto scaled = [&](const AdaptivePiece<T, Dim>& p) {
    double e = 0.0;
    for (int c = 0; c < Dim; ++c) e = std::max(e, p.error[c] / tolerance[c]);
    return e;
  };
  auto met = [&](const std::array<double, Dim>& total) {
    for (int c = 0; c < Dim; ++c)
      if (!(total[c] <= tolerance[c])) return false;
    return true;
  };
  auto exact_total = [&] {
    std::array<double, Dim> total{};
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < Dim; ++c) total[c] += pieces[i].error[c];
    return total;
  };
  for (int i = 0; i < n_initial && n < capacity; ++i, ++n) {
    pieces[n] = evaluate_piece<T, Dim, Rule>(f, initial[i].a, initial[i].b, initial[i].tag,
                                             out.evaluations);
    ranks[n] = {scaled(pieces[n]), n};
  }
  std::make_heap(ranks, ranks + n);
  std::array<double, Dim> total = exact_total();
  while (!(met(total) && met(total = exact_total())) && n + 1 <= capacity) {
    std::pop_heap(ranks, ranks + n);
    const int worst = ranks[n - 1].index;
    const AdaptivePiece<T, Dim> parent = pieces[worst];
    const double m = split(parent.a, parent.b);
    if (!(m > parent.a && m < parent.b)) {  // interval at machine resolution
      out.converged = false;
      out.error = exact_total();
      return sum_pieces(out, pieces, n);
    }
    pieces[worst] = evaluate_piece<T, Dim, Rule>(f, parent.a, m, parent.tag, out.evaluations);
    pieces[n] = evaluate_piece<T, Dim, Rule>(f, m, parent.b, parent.tag, out.evaluations);
    for (int c = 0; c < Dim; ++c)
      total[c] += (pieces[worst].error[c] - parent.error[c]) + pieces[n].error[c];
    ranks[n - 1] = {scaled(pieces[worst]), worst};
    std::push_heap(ranks, ranks + n);
    ranks[n] = {scaled(pieces[n]), n};
    std::push_heap(ranks, ranks + ++n);
  }
  out.error = exact_total();
  out.converged = met(out.error);
  return sum_pieces(out, pieces, n);
}

/// Integrates a batch integrand f(const double* x, int n, int tag, Sample<T, Dim>* out), which
/// evaluates n <= 31 points at once, over the union of the given intervals until the estimated
/// absolute error of every component c is <= tolerance[c], bisecting the interval with the
/// largest scaled error at split(a, b) (the midpoint by default). Capacity bounds the number of
/// intervals kept (on the stack).
template <class T, int Dim, int Capacity = 160, const auto& Rule = kGK21, class F,
          class Split = MidpointSplit>
AdaptiveResult<T, Dim> integrate_adaptive_batch(F&& f, const TaggedInterval* initial, int n_initial,
                                                const std::array<double, Dim>& tolerance,
                                                const Split& split = Split{}) {
  std::array<AdaptivePiece<T, Dim>, Capacity> pieces;
  std::array<PieceRank, Capacity> ranks;
  return adaptive_loop<T, Dim, Rule>(f, initial, n_initial, tolerance, split, pieces.data(),
                                     ranks.data(), Capacity);
}

/// The same with the store on the heap, for `capacity` intervals: the one heap allocation of
/// the exact resultants, for a table whose kinks exhaust the stack store (exact_resultants.hpp).
template <class T, int Dim, const auto& Rule = kGK21, class F, class Split = MidpointSplit>
AdaptiveResult<T, Dim> integrate_adaptive_batch_heap(F&& f, const TaggedInterval* initial,
                                                     int n_initial,
                                                     const std::array<double, Dim>& tolerance,
                                                     int capacity, const Split& split = Split{}) {
  const std::unique_ptr<AdaptivePiece<T, Dim>[]> pieces(new AdaptivePiece<T, Dim>[capacity]);
  const std::unique_ptr<PieceRank[]> ranks(new PieceRank[capacity]);
  return adaptive_loop<T, Dim, Rule>(f, initial, n_initial, tolerance, split, pieces.get(),
                                     ranks.get(), capacity);
}

/// The same for a point integrand f(double x, int tag) -> Sample<T, Dim>.
template <class T, int Dim, int Capacity = 160, const auto& Rule = kGK21, class F>
AdaptiveResult<T, Dim> integrate_adaptive(F&& f, const TaggedInterval* initial, int n_initial,
                                          const std::array<double, Dim>& tolerance) {
  auto batch = [&f](const double* x, int n, int tag, Sample<T, Dim>* out) {
    for (int i = 0; i < n; ++i) out[i] = f(x[i], tag);
  };
  return integrate_adaptive_batch<T, Dim, Capacity, Rule>(batch, initial, n_initial, tolerance);
}

}  // namespace contensou::detail
