#include "contensou/friction/exact_resultants.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace contensou {
namespace {

struct ChebyshevFit {
  std::vector<double> coefficients;
  double error = 0.0;  // bound on the truncation error (sum of dropped |c_k|, or sampled)
};

// Chebyshev interpolation of q(t), t in [0, 1], at n first-kind points.
std::vector<double> chebyshev_coefficients(const std::function<double(double)>& q, int n) {
  std::vector<double> fx(n), c(n, 0.0);
  for (int j = 0; j < n; ++j) fx[j] = q(0.5 * (1.0 + std::cos(std::numbers::pi * (j + 0.5) / n)));
  for (int k = 0; k < n; ++k) {
    double s = 0.0;
    for (int j = 0; j < n; ++j) s += fx[j] * std::cos(std::numbers::pi * k * (j + 0.5) / n);
    c[k] = (k == 0 ? 1.0 : 2.0) * s / n;
  }
  return c;
}

// Smallest Chebyshev series (16 ... 512 terms) that represents q to `tol` relative to its
// largest coefficient: by the tail of the coefficients for a smooth q, else (a clipped kink, a
// tabulated cubic) by the deviation sampled on a fine grid, which then bounds the error.
ChebyshevFit fit_chebyshev(const std::function<double(double)>& q, double tol) {
  ChebyshevFit fit;
  for (int n = 16; n <= 512; n *= 2) {
    std::vector<double> c = chebyshev_coefficients(q, n);
    double cmax = 0.0;
    for (double v : c) cmax = std::max(cmax, std::abs(v));
    const double floor = tol * std::max(cmax, 1e-300);
    double tail = 0.0;
    for (int k = n - 4; k < n; ++k) tail = std::max(tail, std::abs(c[k]));
    double dropped = 0.0;
    while (c.size() > 1 && std::abs(c.back()) <= floor) {
      dropped += std::abs(c.back());
      c.pop_back();
    }
    if (tail <= floor) {
      fit.coefficients = std::move(c);
      fit.error = dropped;
      return fit;
    }
    ExactModel<double> probe;
    probe.chebyshev = c;
    double dev = 0.0;
    for (int i = 0; i <= 4000; ++i) {
      const double t = i / 4000.0;
      dev = std::max(dev, std::abs(q(t) - detail::chebyshev_sum(probe.chebyshev, t)));
    }
    if (dev <= floor || n == 512) {
      fit.coefficients = std::move(c);
      fit.error = 2.0 * dev;  // the grid can miss the worst point by a little
      return fit;
    }
  }
  return fit;
}

}  // namespace

namespace {

// Clips a piecewise cubic at zero: each piece is split at its sign changes (scan and
// bisection to rounding), and the negative parts become zero pieces, so that the pieces stay
// polynomials and the exact integrals stay exact for max(p, 0).
void clip_pieces(std::vector<double>& knot, std::vector<std::array<double, 4>>& piece) {
  auto value = [](const std::array<double, 4>& c, double s) {
    return c[0] + s * (c[1] + s * (c[2] + s * c[3]));
  };
  // The same cubic written about a point s0 to its right: c_j(s0) = sum_i C(i, j) s0^(i-j) c_i.
  auto shifted = [](const std::array<double, 4>& c, double s0) {
    return std::array<double, 4>{c[0] + s0 * (c[1] + s0 * (c[2] + s0 * c[3])),
                                 c[1] + s0 * (2.0 * c[2] + 3.0 * s0 * c[3]), c[2] + 3.0 * s0 * c[3],
                                 c[3]};
  };
  std::vector<double> out_knot;
  std::vector<std::array<double, 4>> out_piece;
  for (std::size_t k = 0; k < piece.size(); ++k) {
    const double a = knot[k], h = knot[k + 1] - a;
    std::vector<double> cuts{0.0};
    constexpr int kScan = 16;
    double s0 = 0.0, f0 = value(piece[k], 0.0);
    for (int i = 1; i <= kScan; ++i) {
      const double s1 = h * i / kScan, f1 = value(piece[k], s1);
      if ((f0 < 0.0) != (f1 < 0.0)) {
        double lo = s0, hi = s1;
        for (int it = 0; it < 100 && hi - lo > 1e-16 * h; ++it) {
          const double mid = 0.5 * (lo + hi);
          ((value(piece[k], mid) < 0.0) == (f0 < 0.0) ? lo : hi) = mid;
        }
        cuts.push_back(0.5 * (lo + hi));
      }
      s0 = s1;
      f0 = f1;
    }
    cuts.push_back(h);
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
      if (!(cuts[j + 1] > cuts[j])) continue;
      const bool negative = value(piece[k], 0.5 * (cuts[j] + cuts[j + 1])) < 0.0;
      out_knot.push_back(a + cuts[j]);
      out_piece.push_back(negative ? std::array<double, 4>{0.0, 0.0, 0.0, 0.0}
                                   : shifted(piece[k], cuts[j]));
    }
  }
  out_knot.push_back(knot.back());
  knot = std::move(out_knot);
  piece = std::move(out_piece);
}

}  // namespace

namespace detail {
namespace {

// Far-field moments of a table's pieces on a binary tree (level 0: the pieces, level s: runs
// of 2^s pieces). A node over [t_l, t_r], centre c, half width H, stores
//   mu_m = integral_{t_l}^{t_r} p(t) u^m dt,  u = (t - c) / H,  m < kMoments,
// and for t_f with x = H / (c - t_f) <= 1/3 (the node "separated" from t_f):
//   integral p (t - t_f)^(-1/2) dt = (c - t_f)^(-1/2) sum_m binom(-1/2, m) mu_m x^m,
//   integral p (t - t_f)^(1/2) dt  = (c - t_f)^(1/2)  sum_m binom(1/2, m) mu_m x^m.
// Every term is bounded by x^m integral |p|: no cancellation, whatever the size of the pieces'
// coefficients; the dropped tail is below 3^-36 = 7e-18 of integral |p|.
constexpr int kMoments = 36;

struct MomentNode {
  double c, H;
  std::array<double, kMoments> mu;
};

MomentNode leaf_moments(const std::array<double, 4>& c, double ta, double tb) {
  // p(c + H u) = sum_j c_j H^j (1 + u)^j = sum_i e_i u^i; mu_m = H sum_i e_i integral u^(m+i).
  MomentNode node{0.5 * (ta + tb), 0.5 * (tb - ta), {}};
  const double H = node.H;
  const double e[4] = {c[0] + H * (c[1] + H * (c[2] + H * c[3])),
                       H * (c[1] + H * (2.0 * c[2] + 3.0 * H * c[3])),
                       H * H * (c[2] + 3.0 * H * c[3]), H * H * H * c[3]};
  for (int m = 0; m < kMoments; ++m)
    for (int i = 0; i < 4; ++i)
      if ((m + i) % 2 == 0) node.mu[m] += H * e[i] * 2.0 / (m + i + 1);
  return node;
}

// Adds a child's moments to its parent's: (t - c_p)/H_p = alpha u + beta, alpha = H/H_p,
// beta = (c - c_p)/H_p, so mu_p,m += sum_i C(m, i) alpha^i beta^(m-i) mu_i (|alpha| + |beta| <= 1).
void add_child(const MomentNode& child, MomentNode& parent) {
  const double alpha = child.H / parent.H, beta = (child.c - parent.c) / parent.H;
  std::array<double, kMoments> row{};  // C(m, i) alpha^i beta^(m-i), row m built from row m-1
  row[0] = 1.0;
  for (int m = 0; m < kMoments; ++m) {
    if (m > 0)
      for (int i = m; i >= 0; --i) row[i] = (i > 0 ? alpha * row[i - 1] : 0.0) + beta * row[i];
    double sum = 0.0;
    for (int i = 0; i <= m; ++i) sum += row[i] * child.mu[i];
    parent.mu[m] += sum;
  }
}

using MomentTree = std::vector<std::vector<MomentNode>>;

MomentTree build_moment_tree(const std::vector<double>& knot,
                             const std::vector<std::array<double, 4>>& piece) {
  MomentTree tree(1);
  for (std::size_t k = 0; k < piece.size(); ++k)
    tree[0].push_back(leaf_moments(piece[k], knot[k], knot[k + 1]));
  while (tree.back().size() > 1) {
    const std::vector<MomentNode>& below = tree.back();
    std::vector<MomentNode> level;
    for (std::size_t i = 0; i < below.size(); i += 2) {
      const double lo = below[i].c - below[i].H;
      const double hi =
          i + 1 < below.size() ? below[i + 1].c + below[i + 1].H : below[i].c + below[i].H;
      MomentNode node{0.5 * (lo + hi), 0.5 * (hi - lo), {}};
      add_child(below[i], node);
      if (i + 1 < below.size()) add_child(below[i + 1], node);
      level.push_back(node);
    }
    tree.push_back(std::move(level));
  }
  return tree;
}

// The nodes covering the pieces from `first` on, each separated from every t_f <= b
// (c - b >= 3 H); a piece that is not is integrated exactly (node == nullptr).
struct CoverEntry {
  const MomentNode* node;
  std::size_t piece;
};

void cover_far_pieces(const MomentTree& tree, std::size_t first, double b,
                      std::vector<CoverEntry>& out) {
  out.clear();
  auto separated = [b](const MomentNode& n) { return n.c - b >= 3.0 * n.H; };
  const std::size_t n = tree[0].size();
  for (std::size_t j = first; j < n;) {
    std::size_t s = 0;
    while (s + 1 < tree.size() && (j >> (s + 1)) << (s + 1) == j &&
           separated(tree[s + 1][j >> (s + 1)]))
      ++s;
    const MomentNode& node = tree[s][j >> s];
    out.push_back({s > 0 || separated(node) ? &node : nullptr, j});
    j += std::size_t{1} << s;
  }
}

// The far sums at t_f (< knot[first]): the integrals of the pieces from `first` on, plus, if
// the near knots are knot terms, the antiderivative of the piece below knot[first] from t_f to
// it (update_far_sums).
void far_sums_at(const std::vector<double>& knot, const std::vector<std::array<double, 4>>& piece,
                 std::size_t first, bool knot_terms, const std::vector<CoverEntry>& cover,
                 double t_f, double& M0, double& M2) {
  M0 = M2 = 0.0;
  double a0, a2;
  if (knot_terms && first < knot.size())
    cubic_moments(piece[first - 1], knot[first - 1], t_f, knot[first], t_f, true, M0, M2);
  for (const CoverEntry& e : cover) {
    if (e.node == nullptr) {
      cubic_moments(piece[e.piece], knot[e.piece], knot[e.piece], knot[e.piece + 1], t_f, false, a0,
                    a2);
      M0 += a0;
      M2 += a2;
      continue;
    }
    const double dist = e.node->c - t_f, x = e.node->H / dist;
    double s0 = 0.0, s2 = 0.0, b0 = 1.0, b2 = 1.0, xm = 1.0;
    for (int m = 0; m < kMoments && xm > 1e-18; ++m) {
      s0 += b0 * e.node->mu[m] * xm;
      s2 += b2 * e.node->mu[m] * xm;
      b0 *= -(2.0 * m + 1.0) / (2.0 * m + 2.0);  // binom(-1/2, m + 1) / binom(-1/2, m)
      b2 *= (1.0 - 2.0 * m) / (2.0 * m + 2.0);   // binom(1/2, m + 1) / binom(1/2, m)
      xm *= x;
    }
    const double r = std::sqrt(dist);
    M0 += s0 / r;
    M2 += s2 * r;
  }
}

// Chebyshev coefficients (kFarTerms) of the far sums on [a, b]; returns the largest deviation
// of the series from the sums at test points.
double fit_far_series(const std::vector<double>& knot,
                      const std::vector<std::array<double, 4>>& piece, std::size_t first,
                      bool knot_terms, const std::vector<CoverEntry>& cover, double a, double b,
                      double* c0, double* c2) {
  constexpr int N = kFarTerms;
  double v0[N], v2[N];
  for (int j = 0; j < N; ++j) {
    const double z = std::cos(std::numbers::pi * (j + 0.5) / N);
    far_sums_at(knot, piece, first, knot_terms, cover, 0.5 * (a + b) + 0.5 * (b - a) * z, v0[j],
                v2[j]);
  }
  for (int i = 0; i < N; ++i) {
    double s0 = 0.0, s2 = 0.0;
    for (int j = 0; j < N; ++j) {
      const double w = std::cos(std::numbers::pi * i * (j + 0.5) / N);
      s0 += v0[j] * w;
      s2 += v2[j] * w;
    }
    c0[i] = (i == 0 ? 1.0 : 2.0) / N * s0;
    c2[i] = (i == 0 ? 1.0 : 2.0) / N * s2;
  }
  double dev = 0.0;
  for (double z : {-1.0, -0.77, -0.31, 0.13, 0.58, 0.93, 1.0}) {
    double e0, e2;
    far_sums_at(knot, piece, first, knot_terms, cover, 0.5 * (a + b) + 0.5 * (b - a) * z, e0, e2);
    double s0 = 0.0, s2 = 0.0, tp = 1.0, tc = z;
    for (int i = 0; i < N; ++i) {
      const double t = i == 0 ? 1.0 : (i == 1 ? z : 2.0 * z * tc - tp);
      if (i >= 2) {
        tp = tc;
        tc = t;
      }
      s0 += c0[i] * t;
      s2 += c2[i] * t;
    }
    dev = std::max({dev, std::abs(s0 - e0), std::abs(s2 - e2)});
  }
  return dev;
}

}  // namespace

double update_far_sums(const std::vector<double>& knot,
                       const std::vector<std::array<double, 4>>& piece, std::vector<double>& far0,
                       std::vector<double>& far2, std::vector<std::size_t>& far_from,
                       std::vector<unsigned char>& near_integrated) {
  const std::size_t n = knot.size() - 1;  // intervals
  far0.assign(n * kFarTerms, 0.0);
  far2.assign(n * kFarTerms, 0.0);
  far_from.assign(n, 0);
  near_integrated.assign(n, 0);
  const MomentTree tree = build_moment_tree(knot, piece);
  std::vector<CoverEntry> cover;
  double dev = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = knot[k], b = knot[k + 1];
    std::size_t first = k + 2;
    while (first < knot.size() && first < k + 1 + kMaxNear && knot[first] - b < b - a) ++first;
    far_from[k] = first;
    // Knot terms only if no near piece is narrower than 1/8 of its reach from the interval.
    const double reach = knot[std::min(first, n)] - a;
    for (std::size_t j = k; j < std::min(first, n); ++j)
      if (8.0 * (knot[j + 1] - knot[j]) < reach) near_integrated[k] = 1;
    cover_far_pieces(tree, first, b, cover);
    dev = std::max(dev, fit_far_series(knot, piece, first, !near_integrated[k], cover, a, b,
                                       &far0[k * kFarTerms], &far2[k * kFarTerms]));
  }
  return dev;
}

}  // namespace detail

ExactModel<double> make_exact_model(const ContactPatch& patch, double representation_tolerance) {
  if (!(representation_tolerance > 0.0 && representation_tolerance < 1e-3))
    throw InvalidArgument("representation_tolerance", format_value(representation_tolerance),
                          "must lie in (0, 1e-3)");
  validate(patch);
  ExactModel<double> m;
  const PressureProfile& prof = patch.profile;
  double rho_max = 1.0;
  // A negative pressure would make friction generate energy there: refuse it unless the
  // caller chose to clip it or to keep it (PressureProfile).
  if (!prof.clip_negative && !prof.keep_negative && negative_load_share(prof) > 1e-12) {
    const auto neg = negative_intervals(prof);
    throw InvalidArgument("profile", describe(prof),
                          "negative on rho in (" + format_value(neg.front().first) + ", " +
                              format_value(neg.front().second) +
                              "): friction there would generate energy; set clip_negative to clip "
                              "the pressure at zero, keep_negative to use it as given, or "
                              "correct the profile");
  }
  const bool table = std::holds_alternative<TabulatedShape>(prof.shape);
  if (prof.clip_negative && !table) {  // a table is clipped piece by piece below
    const auto neg = negative_intervals(prof);
    if (neg.size() == 1 && neg.front().second >= 1.0 && neg.front().first > 0.0)
      rho_max = neg.front().first;  // negative only at the rim: shrink the disk exactly
  }
  m.radius = patch.radius_m * rho_max;
  m.pressure = patch.reference_pressure_pa;
  m.friction = patch.friction;
  m.kappa = patch.kappa;
  m.kx = prof.kx * rho_max;
  m.ky = prof.ky * rho_max;
  if (std::holds_alternative<UniformShape>(prof.shape)) {
    m.chebyshev = {1.0};
  } else if (std::holds_alternative<HertzShape>(prof.shape)) {
    m.chebyshev = {1.0};
    m.sqrt_edge = true;
  } else if (const auto* cs = std::get_if<ChebyshevShape>(&prof.shape); cs && rho_max == 1.0) {
    m.chebyshev = cs->c;  // already a series in t = rho^2: exact
  } else if (const auto* tab = std::get_if<TabulatedShape>(&prof.shape)) {
    // A table: its cubic pieces in t = rho^2 as they are (exact for the interpolant).
    if (tab->rho.front() > 0.0) {  // constant below the first knot
      m.knot.push_back(0.0);
      m.piece.push_back({tab->p.front(), 0.0, 0.0, 0.0});
    }
    for (std::size_t k = 0; k + 1 < tab->rho.size(); ++k) {
      const double ta = tab->rho[k] * tab->rho[k], tb = tab->rho[k + 1] * tab->rho[k + 1];
      const double h = tb - ta, del = (tab->p[k + 1] - tab->p[k]) / h;
      const double d0 = tab->slope[k], d1 = tab->slope[k + 1];
      m.knot.push_back(ta);
      m.piece.push_back(
          {tab->p[k], d0, (3.0 * del - 2.0 * d0 - d1) / h, (d0 + d1 - 2.0 * del) / (h * h)});
    }
    m.knot.push_back(1.0);
    if (prof.clip_negative) clip_pieces(m.knot, m.piece);
    // The far-knot series' deviation, as a bound on the chord integrals' error (in units of
    // the profile times the chord length, as a profile representation error is).
    detail::update_knot_terms(m.knot, m.piece, m.knot_m0, m.knot_m2);
    m.representation_error =
        detail::update_far_sums(m.knot, m.piece, m.far_m0, m.far_m2, m.far_from, m.near_integrated);
  } else {
    const ChebyshevFit fit =
        fit_chebyshev([&](double t) { return shape_value(prof, rho_max * std::sqrt(t)); },
                      representation_tolerance);
    m.chebyshev = fit.coefficients;
    m.representation_error = fit.error;
  }
  if (patch.slip_speed_friction) {
    m.slip_speed = patch.slip_speed_friction;
    m.friction_scale = std::max(patch.slip_speed_friction->static_coefficient,
                                patch.slip_speed_friction->kinetic_coefficient);
  } else {
    m.friction_scale = patch.friction;
  }
  if (m.friction_scale == 0.0) m.friction_scale = 1.0;  // frictionless: tolerance scale only
  if (m.piece.empty()) update_chord_transforms(m);
  m.load_area = 2.0 * std::numbers::pi * patch.radius_m * patch.radius_m * moment(prof, 1);
  if (!(m.load_area > 0.0))
    throw InvalidArgument("profile", describe(prof), "its load integral A^1 must be positive");
  return m;
}

ExactResult<double> exact_resultants(const ContactPatch& patch, const Kinematics<double>& k,
                                     const ExactOptions& options) {
  return exact_resultants(make_exact_model(patch), k, options);
}

template ExactResult<double> exact_resultants<double>(const ExactModel<double>&,
                                                      const Kinematics<double>&,
                                                      const ExactOptions&);

}  // namespace contensou
