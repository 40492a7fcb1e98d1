// Global adaptive Gauss-Kronrod (G10K21) integration of a small vector of integrands over a
// set of tagged intervals, with a fixed-capacity interval store (no heap allocation).
#pragma once

#include <array>
#include <cmath>

#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// One sample of a vector integrand; inner_error carries the error of a nested integral.
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

// Largest number of nodes of a rule used here (G15K31).
inline constexpr int kKronrodPoints = 31;

// Integrates a batch integrand f(const double* x, int n, int tag, Sample<T, Dim>* out), which
// evaluates n <= 21 points at once, over the union of the given intervals until the estimated
// absolute error of every component c is <= tolerance[c], bisecting the interval with the
// largest scaled error. Capacity bounds the number of intervals kept.
template <class T, int Dim, int Capacity = 160, const auto& Rule = kGK21, class F>
AdaptiveResult<T, Dim> integrate_adaptive_batch(F&& f, const TaggedInterval* initial, int n_initial,
                                                const std::array<double, Dim>& tolerance) {
  struct Piece {
    double a, b;
    int tag;
    std::array<T, Dim> value;
    std::array<double, Dim> error;
  };
  std::array<Piece, Capacity> pieces;
  int n = 0;
  AdaptiveResult<T, Dim> out;

  auto evaluate = [&](double a, double b, int tag) {
    Piece p{a, b, tag, {}, {}};
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
    out.evaluations += points;
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
  };

  auto scaled = [&](const Piece& p) {
    double e = 0.0;
    for (int c = 0; c < Dim; ++c) e = std::max(e, p.error[c] / tolerance[c]);
    return e;
  };

  for (int i = 0; i < n_initial && n < Capacity; ++i)
    pieces[n++] = evaluate(initial[i].a, initial[i].b, initial[i].tag);

  while (true) {
    std::array<double, Dim> total{};
    for (int i = 0; i < n; ++i)
      for (int c = 0; c < Dim; ++c) total[c] += pieces[i].error[c];
    bool ok = true;
    for (int c = 0; c < Dim; ++c) ok = ok && total[c] <= tolerance[c];
    if (ok || n + 1 > Capacity) {
      out.converged = ok;
      out.error = total;
      break;
    }
    int worst = 0;
    double worst_e = -1.0;
    for (int i = 0; i < n; ++i) {
      const double e = scaled(pieces[i]);
      if (e > worst_e) {
        worst_e = e;
        worst = i;
      }
    }
    const Piece parent = pieces[worst];
    const double m = 0.5 * (parent.a + parent.b);
    if (!(m > parent.a && m < parent.b)) {  // interval at machine resolution
      out.converged = false;
      out.error = total;
      break;
    }
    pieces[worst] = evaluate(parent.a, m, parent.tag);
    pieces[n++] = evaluate(m, parent.b, parent.tag);
  }
  for (auto& v : out.value) v = T(0);
  for (int i = 0; i < n; ++i)
    for (int c = 0; c < Dim; ++c) out.value[c] += pieces[i].value[c];
  out.intervals = n;
  return out;
}

// The same for a point integrand f(double x, int tag) -> Sample<T, Dim>.
template <class T, int Dim, int Capacity = 160, const auto& Rule = kGK21, class F>
AdaptiveResult<T, Dim> integrate_adaptive(F&& f, const TaggedInterval* initial, int n_initial,
                                          const std::array<double, Dim>& tolerance) {
  auto batch = [&f](const double* x, int n, int tag, Sample<T, Dim>* out) {
    for (int i = 0; i < n; ++i) out[i] = f(x[i], tag);
  };
  return integrate_adaptive_batch<T, Dim, Capacity, Rule>(batch, initial, n_initial, tolerance);
}

}  // namespace contensou::detail
