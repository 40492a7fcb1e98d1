// Adaptive piecewise Chebyshev interpolation (piecewise_chebyshev.hpp).
#include "contensou/friction/piecewise_chebyshev.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <stdexcept>

namespace contensou {

namespace {

constexpr int kMaxDegree = 40;

struct Piece {
  double a, b;
  std::vector<double> coefficients;  // [function][k]
  double error;
  double worst_t;
};

// Chebyshev coefficients from the values at the Lobatto points x_j = cos(j pi / n):
//   c_k = (2 / n) sum''_j f_j cos(j k pi / n), the first and last terms halved, c_0 and c_n
//   halved again; cos_jk[j (n + 1) + k] = cos(j k pi / n).
void lobatto_coefficients(int n, const std::vector<double>& cos_jk, const double* values,
                          int stride, double* c) {
  for (int k = 0; k <= n; ++k) {
    double s = 0.0;
    for (int j = 0; j <= n; ++j) {
      const double w = (j == 0 || j == n) ? 0.5 : 1.0;
      s += w * values[j * stride] * cos_jk[j * (n + 1) + k];
    }
    c[k] = (k == 0 || k == n ? 1.0 : 2.0) * s / n;
  }
}

double clenshaw(const double* c, int n, double x) {
  double b1 = 0.0, b2 = 0.0;
  for (int k = n; k >= 1; --k) {
    const double b0 = c[k] + 2.0 * x * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + x * b1 - b2;
}

class Builder {
 public:
  Builder(int m, const ChebyshevBatchSampler& sample, const PiecewiseChebyshevOptions& o)
      : m_(m), n_(o.degree), sample_(sample), scale_(o.scale), weight_(o.weight) {
    if (scale_.empty()) scale_.assign(m, 1.0);
    for (int j = 0; j <= n_; ++j)
      for (int k = 0; k <= n_; ++k) cos_jk_.push_back(std::cos(std::numbers::pi * j * k / n_));
  }

  // Fits [a, b] from its Lobatto points (the ends sampled once for both neighbours) and checks
  // it at the points between them; one batch call of the sampler for all new points.
  Piece fit(double a, double b) {
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    std::vector<double> nodes(n_ + 1), wanted;
    for (int j = 0; j <= n_; ++j) {
      nodes[j] = j == 0 ? b : j == n_ ? a : mid + half * std::cos(std::numbers::pi * j / n_);
      if (!cache_.contains(nodes[j])) wanted.push_back(nodes[j]);
    }
    for (int j = 0; j < n_; ++j)
      wanted.push_back(mid + half * std::cos(std::numbers::pi * (j + 0.5) / n_));
    std::vector<double> sampled(wanted.size() * m_);
    sample_(wanted, sampled.data());
    samples_ += static_cast<int>(wanted.size());
    const std::size_t checks = wanted.size() - n_;
    for (std::size_t k = 0; k < checks; ++k)
      cache_.emplace(wanted[k],
                     std::vector<double>(sampled.begin() + k * m_, sampled.begin() + (k + 1) * m_));
    std::vector<double> values((n_ + 1) * m_);
    for (int j = 0; j <= n_; ++j) {
      const std::vector<double>& v = cache_.at(nodes[j]);
      std::copy(v.begin(), v.end(), values.begin() + j * m_);
    }
    Piece p{a, b, std::vector<double>((n_ + 1) * m_), 0.0, mid};
    for (int i = 0; i < m_; ++i)
      lobatto_coefficients(n_, cos_jk_, values.data() + i, m_,
                           p.coefficients.data() + i * (n_ + 1));
    std::vector<double> w(m_, 1.0);
    for (int j = 0; j < n_; ++j) {
      const double x = std::cos(std::numbers::pi * (j + 0.5) / n_);
      const double* v = sampled.data() + (checks + j) * m_;
      if (weight_) weight_(mid + half * x, w.data());
      for (int i = 0; i < m_; ++i) {
        const double e = std::abs(clenshaw(p.coefficients.data() + i * (n_ + 1), n_, x) - v[i]) *
                         w[i] / scale_[i];
        if (!(e <= p.error)) {  // also catches NaN
          p.error = std::isnan(e) ? INFINITY : e;
          p.worst_t = mid + half * x;
        }
      }
    }
    return p;
  }

  int samples() const { return samples_; }

 private:
  int m_, n_;
  const ChebyshevBatchSampler& sample_;
  std::vector<double> scale_;
  std::function<void(double, double*)> weight_;
  std::vector<double> cos_jk_;  // cos(j k pi / n), j, k = 0..n (lobatto_coefficients)
  std::map<double, std::vector<double>> cache_;
  int samples_ = 0;
};

}  // namespace

std::vector<double> graded_breaks(int levels) {
  std::vector<double> b{-1.0};
  for (int l = 1; l <= levels; ++l) b.push_back(-std::ldexp(1.0, -l));
  b.push_back(0.0);
  for (int l = levels; l >= 1; --l) b.push_back(std::ldexp(1.0, -l));
  b.push_back(1.0);
  return b;
}

PiecewiseChebyshevBuild build_piecewise_chebyshev(int m, const ChebyshevSampler& sample,
                                                  const PiecewiseChebyshevOptions& o) {
  return build_piecewise_chebyshev_batch(
      m,
      [&](const std::vector<double>& ts, double* values) {
        for (std::size_t k = 0; k < ts.size(); ++k) sample(ts[k], values + k * m);
      },
      o);
}

namespace {

// Splits [a, b] (which missed the tolerance with `error`) into halves; or, if it ends at one of
// the singular points, geometrically towards that point into the d halvings after which the
// error, shrinking like the width squared there, meets the tolerance: d = ceil(log2(error /
// tolerance) / 2). Those are the pieces repeated bisection reaches, without fitting the ones in
// between. `pieces` is the number of pieces done or waiting.
void split_piece(double a, double b, double error, const PiecewiseChebyshevOptions& o, int pieces,
                 std::vector<std::pair<double, double>>& work) {
  const double mid = 0.5 * (a + b), w = b - a;
  const auto at = [&](double x) {
    return std::find(o.singular_points.begin(), o.singular_points.end(), x) !=
           o.singular_points.end();
  };
  int d = 1;
  if (std::isfinite(error) && (at(a) || at(b)))
    d = std::clamp(static_cast<int>(std::ceil(0.5 * std::log2(error / o.tolerance))), 1, 8);
  while (d > 1 && (std::ldexp(w, -d) < 2.0 * o.smallest_width || pieces + d + 1 > o.max_pieces))
    --d;
  if (d == 1) {
    work.emplace_back(mid, b);
    work.emplace_back(a, mid);
    return;
  }
  const double toward = at(a) ? a : b, step = at(a) ? w : -w;  // from the singular end
  for (int j = 1; j <= d; ++j) {  // [toward + step 2^-j, toward + step 2^-(j-1)]
    const double near = toward + std::ldexp(step, -j), far = toward + std::ldexp(step, 1 - j);
    work.emplace_back(std::min(near, far), std::max(near, far));
  }
  const double last = toward + std::ldexp(step, -d);
  work.emplace_back(std::min(toward, last), std::max(toward, last));
}

}  // namespace

PiecewiseChebyshevBuild build_piecewise_chebyshev_batch(int m, const ChebyshevBatchSampler& sample,
                                                        const PiecewiseChebyshevOptions& o) {
  if (m < 1) throw std::invalid_argument("piecewise Chebyshev: no functions");
  if (o.degree < 2 || o.degree > kMaxDegree)
    throw std::invalid_argument("piecewise Chebyshev: degree must lie in [2, 40]");
  Builder builder(m, sample, o);
  std::vector<double> initial = o.breaks.empty() ? graded_breaks(12) : o.breaks;
  std::vector<std::pair<double, double>> work;
  for (std::size_t i = initial.size() - 1; i-- > 0;) work.emplace_back(initial[i], initial[i + 1]);
  std::vector<Piece> done;
  PiecewiseChebyshevBuild out;
  while (!work.empty()) {
    const auto [a, b] = work.back();
    work.pop_back();
    Piece p = builder.fit(a, b);
    const bool small = b - a < 2.0 * o.smallest_width;
    const bool full = static_cast<int>(done.size() + work.size()) + 2 > o.max_pieces;
    if (p.error <= o.tolerance || small || full) {
      if (p.error > o.tolerance) out.reached = false;
      done.push_back(std::move(p));
    } else {
      split_piece(a, b, p.error, o, static_cast<int>(done.size() + work.size()), work);
    }
  }
  std::sort(done.begin(), done.end(), [](const Piece& x, const Piece& y) { return x.a < y.a; });
  PiecewiseChebyshev& t = out.table;
  t.functions = m;
  t.degree = o.degree;
  t.breaks.push_back(done.front().a);
  const int n = o.degree;
  for (const Piece& p : done) {
    t.breaks.push_back(p.b);
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i < m; ++i) t.coefficients.push_back(p.coefficients[i * (n + 1) + k]);
    if (p.error > out.achieved) {
      out.achieved = p.error;
      out.worst_t = p.worst_t;
    }
  }
  // End slopes: T_k'(1) = k^2, T_k'(-1) = (-1)^(k+1) k^2, times dx/dt = 2 / (b - a).
  const Piece& first = done.front();
  const Piece& last = done.back();
  for (int i = 0; i < m; ++i) {
    double s0 = 0.0, s1 = 0.0;
    for (int k = 1; k <= n; ++k) {
      s0 += (k % 2 ? 1.0 : -1.0) * k * k * first.coefficients[i * (n + 1) + k];
      s1 += k * k * last.coefficients[i * (n + 1) + k];
    }
    t.slope_at_start.push_back(s0 * 2.0 / (first.b - first.a));
    t.slope_at_end.push_back(s1 * 2.0 / (last.b - last.a));
  }
  index_pieces(t);
  out.samples = builder.samples();
  return out;
}

void index_pieces(PiecewiseChebyshev& table) {
  const int n = table.pieces();
  table.map.resize(2 * n);
  for (int k = 0; k < n; ++k) {  // x = (2 t - a - b) / (b - a)
    const double a = table.breaks[k], b = table.breaks[k + 1];
    table.map[2 * k] = 2.0 / (b - a);
    table.map[2 * k + 1] = -(a + b) / (b - a);
  }
  // Each cell points at the piece holding a t just left of the cell (found by bisection on
  // cell_of, monotone in t), from which piece_of scans right.
  std::vector<std::uint16_t> index(2 * detail::kCellsPerSide, 0);
  table.index.clear();
  if (n > 65535) return;  // the binary search then
  int k = 0;
  for (int c = 0; c < 2 * detail::kCellsPerSide; ++c) {
    double lo = -1.0, hi = 1.0;
    if (detail::cell_of(lo) < c) {
      for (int it = 0; it < 200; ++it) {
        const double mid = lo + 0.5 * (hi - lo);
        (detail::cell_of(mid) >= c ? hi : lo) = mid;
      }
    }
    while (k + 1 < n && table.breaks[k + 1] <= lo) ++k;
    index[c] = static_cast<std::uint16_t>(k);
  }
  table.index = std::move(index);
}

namespace {

// T_0..T_n and T_0'..T_n' at x by the three-term recurrences (T_j' = j U_(j-1)).
void chebyshev_basis(double x, int n, double* T, double* D) {
  T[0] = 1.0;
  T[1] = x;
  D[0] = 0.0;
  D[1] = 1.0;
  double u_prev = 1.0, u = 2.0 * x;  // U_0, U_1
  for (int j = 2; j <= n; ++j) {
    T[j] = 2.0 * x * T[j - 1] - T[j - 2];
    D[j] = j * u;
    const double u_next = 2.0 * x * u - u_prev;
    u_prev = u;
    u = u_next;
  }
}

}  // namespace

void evaluate_chebyshev(const PiecewiseChebyshev& p, double t, double* out) {
  double slope[64];
  if (p.functions <= 64) {
    evaluate_chebyshev(p, t, out, slope);
    return;
  }
  std::vector<double> s(p.functions);
  evaluate_chebyshev(p, t, out, s.data());
}

namespace detail {

void chebyshev_sums(const double* c, int m, int n, double x, double* out, double* slope) {
  if (const ChebyshevKernel k = chebyshev_kernel(m, n, slope != nullptr)) {
    k(c, x, out, slope);
    return;
  }
  std::array<double, kMaxDegree + 1> T, D;
  contensou::chebyshev_basis(x, n, T.data(), D.data());
  for (int i = 0; i < m; ++i) out[i] = 0.0;
  if (slope)
    for (int i = 0; i < m; ++i) slope[i] = 0.0;
  for (int j = 0; j <= n; ++j, c += m)
    for (int i = 0; i < m; ++i) {
      out[i] += c[i] * T[j];
      if (slope) slope[i] += c[i] * D[j];
    }
}

}  // namespace detail

void evaluate_chebyshev(const PiecewiseChebyshev& p, double t, double* out, double* slope) {
  double x, dxdt;
  const double* c = detail::locate_piece(p, t, x, dxdt);
  const int n = p.degree, m = p.functions;
  std::array<double, kMaxDegree + 1> T, D;
  chebyshev_basis(x, n, T.data(), D.data());
  for (int i = 0; i < m; ++i) out[i] = slope[i] = 0.0;
  for (int j = 0; j <= n; ++j, c += m)
    for (int i = 0; i < m; ++i) {
      out[i] += c[i] * T[j];
      slope[i] += c[i] * D[j];
    }
  for (int i = 0; i < m; ++i) slope[i] *= dxdt;
}

}  // namespace contensou
