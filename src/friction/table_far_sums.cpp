// The far-field sums of a table's chord integrals (impl/table_pieces.hpp, update_far_sums): a
// binary tree of the pieces' moments and Chebyshev series of the far sums fitted top-down on it
// (docs/theory.md, "Tabulated profiles").
#include <algorithm>
#include <cmath>
#include <numbers>

#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/table_pieces.hpp"

namespace contensou {
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

// The pieces [first, last) as the largest nodes (of two pieces or more) separated from every
// t_f <= b (c - b >= 3 H), and single pieces, integrated exactly (node == nullptr: five Gauss
// points, cheaper than the moments).
struct CoverEntry {
  const MomentNode* node;
  std::size_t piece;
};

void cover_far_pieces(const MomentTree& tree, std::size_t first, std::size_t last, double b,
                      std::vector<CoverEntry>& out) {
  out.clear();
  auto separated = [b](const MomentNode& n) { return n.c - b >= 3.0 * n.H; };
  const std::size_t n = tree[0].size();
  last = std::min(last, n);
  for (std::size_t j = first; j < last;) {
    std::size_t s = 0;
    while (s + 1 < tree.size() && (j >> (s + 1)) << (s + 1) == j &&
           std::min(j + (std::size_t{2} << s), n) <= last && separated(tree[s + 1][j >> (s + 1)]))
      ++s;
    const MomentNode& node = tree[s][j >> s];
    out.push_back({s > 0 ? &node : nullptr, j});
    j += std::size_t{1} << s;
  }
}

// A foot t_f = anchor + offset, the anchor a knot. Differences from the foot are formed as
// (x - anchor) - offset, so that they keep their relative accuracy however small the node: a
// foot rounded to a double moves by up to 1e-16, and the far sums, whose slope grows as
// width^(-1/2) when the far pieces near, with it (as anchor + offset the series of a
// 10^5-point table stay within 1.3e-15 of the sums piece by piece; test_table_far_sums).
struct Foot {
  double anchor, offset;
  double from(double x) const { return (x - anchor) - offset; }  // x - t_f
};

// The direct far sums at t_f (< knot[first]): the integrals of the covered pieces, plus, if
// the near knots are knot terms, the antiderivative of the piece below knot[first] from t_f to
// it (update_far_sums).
void far_sums_at(const std::vector<double>& knot, const std::vector<std::array<double, 4>>& piece,
                 std::size_t first, bool knot_terms, const std::vector<CoverEntry>& cover,
                 const Foot& f, double& M0, double& M2) {
  M0 = M2 = 0.0;
  double a0, a2;
  if (knot_terms && first < knot.size())
    cubic_moments_between(piece[first - 1], 0.0, std::sqrt(f.from(knot[first])),
                          -f.from(knot[first - 1]), M0, M2);
  for (const CoverEntry& e : cover) {
    if (e.node == nullptr) {
      cubic_moments_between(piece[e.piece], std::sqrt(f.from(knot[e.piece])),
                            std::sqrt(f.from(knot[e.piece + 1])), 0.0, a0, a2);
      M0 += a0;
      M2 += a2;
      continue;
    }
    const double dist = f.from(e.node->c), x = e.node->H / dist;
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

// Terms of the series of the tree's inner nodes (the knot intervals' keep kFarTerms): a node's
// far pieces start one node width beyond it, so its series converges like 5.8^-n, as the
// intervals' do (nearest singularity at z = 3: 3 + sqrt(8) = 5.8), and 24 terms leave
// 5.8^-24 = 5e-19 of the nearest pieces' sums.
constexpr int kNodeTerms = 24;

// A Chebyshev series of the far sums M0, M2 on [lo, lo + w], in z = 2 (t - lo) / w - 1.
struct FarSeries {
  double lo = 0.0, w = 1.0;
  std::array<double, kNodeTerms> c0{}, c2{};
  double achieved = 0.0;  // largest deviation found, its own and its ancestors' (see fit_far)
};

// sum_{i < n} c_i T_i(z) by Clenshaw.
double clenshaw(const double* c, int n, double z) {
  double b1 = 0.0, b2 = 0.0;
  for (int i = n - 1; i >= 1; --i) {
    const double b0 = c[i] + 2.0 * z * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + z * b1 - b2;
}

// The first-kind Chebyshev points z_j = cos(pi (j + 1/2) / n) and the cosines of the
// interpolation, cos(pi i (j + 1/2) / n), for n terms: computed once a build.
struct ChebyshevGrid {
  int n;
  std::vector<double> z, cosines;  // cosines[i * n + j]
  explicit ChebyshevGrid(int terms) : n(terms), z(terms), cosines(terms * terms) {
    for (int j = 0; j < n; ++j) z[j] = std::cos(std::numbers::pi * (j + 0.5) / n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        cosines[i * n + j] = std::cos(std::numbers::pi * i * (j + 0.5) / n);
  }
};

// What the series of a node (or knot interval) interpolates: the far sums of the pieces from
// `first` on = its parent's series (the pieces far from the parent, from the parent's `first`
// on; none at the root) + the sums of the pieces in between, direct (far_sums_at on `cover`).
struct FarTarget {
  const std::vector<double>& knot;
  const std::vector<std::array<double, 4>>& piece;
  std::size_t first;
  bool knot_terms;
  const std::vector<CoverEntry>& cover;
  const FarSeries* parent;  // nullptr: the direct sums cover every far piece
  void at(const Foot& f, double& M0, double& M2) const {
    far_sums_at(knot, piece, first, knot_terms, cover, f, M0, M2);
    if (parent == nullptr) return;
    const double z = 2.0 * ((f.anchor - parent->lo) + f.offset) / parent->w - 1.0;
    M0 += clenshaw(parent->c0.data(), kNodeTerms, z);
    M2 += clenshaw(parent->c2.data(), kNodeTerms, z);
  }
};

// Chebyshev interpolation of a target on [lo, lo + w] at g.n points (g.n coefficients in c0,
// c2); returns the largest deviation of the series from the target at test points (M0 and
// M2). The mean is taken out before the transform: the far sums are O(1) and nearly constant on
// a small node, and the transform's rounding (~ n eps |value|) then scales with their variation
// instead (with the values as they are, the 24-term fits handed down 13 levels of a
// 10,000-point table lost 4e-14 of the sums).
double fit_far(const FarTarget& f, const ChebyshevGrid& g, double lo, double w, double* c0,
               double* c2) {
  const int N = g.n;
  double v0[kNodeTerms], v2[kNodeTerms];
  double mean0 = 0.0, mean2 = 0.0;
  for (int j = 0; j < N; ++j) {
    f.at({lo, 0.5 * w * (1.0 + g.z[j])}, v0[j], v2[j]);
    mean0 += v0[j] / N;
    mean2 += v2[j] / N;
  }
  for (int j = 0; j < N; ++j) {
    v0[j] -= mean0;
    v2[j] -= mean2;
  }
  for (int i = 0; i < N; ++i) {
    double s0 = 0.0, s2 = 0.0;
    for (int j = 0; j < N; ++j) {
      s0 += v0[j] * g.cosines[i * N + j];
      s2 += v2[j] * g.cosines[i * N + j];
    }
    c0[i] = (i == 0 ? 1.0 : 2.0) / N * s0;
    c2[i] = (i == 0 ? 1.0 : 2.0) / N * s2;
  }
  c0[0] += mean0;
  c2[0] += mean2;
  double dev = 0.0;
  for (double z : {-1.0, -0.77, -0.31, 0.13, 0.58, 0.93, 1.0}) {
    double e0, e2;
    f.at({lo, 0.5 * w * (1.0 + z)}, e0, e2);
    dev = std::max({dev, std::abs(clenshaw(c0, N, z) - e0), std::abs(clenshaw(c2, N, z) - e2)});
  }
  return dev;
}

// The first piece far from the knot range [lo, hi] that ends at knot `end`: the first knot at
// least one range width beyond hi, and at least one piece on (n: none). The test is the knot
// intervals' own (update_far_sums), so that a parent's first is never below its children's.
std::size_t node_first(const std::vector<double>& knot, std::size_t end, double lo, double hi) {
  const std::size_t n = knot.size() - 1;
  const auto from = knot.begin() + static_cast<std::ptrdiff_t>(std::min(end + 1, n + 1));
  const auto it =
      std::partition_point(from, knot.end(), [&](double x) { return x - hi < hi - lo; });
  return std::min(static_cast<std::size_t>(it - knot.begin()), n);
}

// What one level of inner nodes shares (update_far_sums).
struct FarLevels {
  const std::vector<double>& knot;
  const std::vector<std::array<double, 4>>& piece;
  const MomentTree& tree;
  const ChebyshevGrid& grid;
};

// The series of the inner nodes of level s from those of level s + 1 (`above`, with their
// first far pieces `above_first`): a node's far sums are its parent's (its series, exact for
// the parent's degree) plus the sums of the pieces between its own first and its parent's, a
// node width or two, summed directly (a few tree nodes). The root has no far pieces.
void fit_node_level(const FarLevels& L, std::size_t s, const std::vector<FarSeries>& above,
                    const std::vector<std::size_t>& above_first, std::vector<FarSeries>& level,
                    std::vector<std::size_t>& first) {
  const std::size_t n = L.piece.size(), count = L.tree[s].size();
  level.assign(count, FarSeries{});
  first.assign(count, n);
  std::vector<CoverEntry> cover;
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t start = i << s, end = std::min(start + (std::size_t{1} << s), n);
    FarSeries& node = level[i];
    const double hi = L.knot[end];
    node.lo = L.knot[start];
    node.w = hi - node.lo;
    const FarSeries& parent = above[i / 2];
    const std::size_t parent_first = above_first[i / 2];
    first[i] = std::min(node_first(L.knot, end, node.lo, hi), parent_first);
    cover_far_pieces(L.tree, first[i], parent_first, hi, cover);
    const FarTarget target{L.knot, L.piece, first[i], false, cover, &parent};
    node.achieved =
        parent.achieved + fit_far(target, L.grid, node.lo, node.w, node.c0.data(), node.c2.data());
  }
}

}  // namespace

double update_far_sums(TablePieces& table) {
  const std::vector<double>& knot = table.knot;
  const std::vector<std::array<double, 4>>& piece = table.piece;
  std::vector<double>& far0 = table.far_m0;
  std::vector<double>& far2 = table.far_m2;
  std::vector<std::size_t>& far_from = table.far_from;
  std::vector<unsigned char>& near_integrated = table.near_integrated;
  const std::size_t n = knot.size() - 1;  // intervals
  far0.assign(n * kFarTerms, 0.0);
  far2.assign(n * kFarTerms, 0.0);
  far_from.assign(n, 0);
  near_integrated.assign(n, 0);
  const MomentTree tree = build_moment_tree(knot, piece);
  const ChebyshevGrid node_grid(kNodeTerms), grid(kFarTerms);
  const FarLevels levels{knot, piece, tree, node_grid};
  // The inner nodes' series from the root down (the root: no far pieces), then the knot
  // intervals (level 0) from their parents'. Each fit sums a bounded number of tree nodes at
  // a bounded number of points: O(n) for the whole table (summing every interval's far pieces
  // on the tree would be O(n log n), the knot terms alone O(n^2)).
  std::vector<FarSeries> above(1), level;
  std::vector<std::size_t> above_first(1, n), first_of;
  for (std::size_t s = tree.size() - 1; s-- > 1;) {
    fit_node_level(levels, s, above, above_first, level, first_of);
    above.swap(level);
    above_first.swap(first_of);
  }
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
    // The parent's series holds the pieces from its first on (never below this interval's:
    // node_first; else, which the test in node_first excludes, every piece is summed here).
    const bool root = tree.size() == 1;
    const FarSeries* parent = root ? nullptr : &above[k / 2];
    const std::size_t parent_first = root ? n : above_first[k / 2];
    const bool inherit = parent != nullptr && parent_first >= std::min(first, n);
    cover_far_pieces(tree, first, inherit ? parent_first : n, b, cover);
    const FarTarget target{
        knot, piece, first, !near_integrated[k], cover, inherit ? parent : nullptr};
    dev = std::max(dev,
                   (inherit ? parent->achieved : 0.0) +
                       fit_far(target, grid, a, b - a, &far0[k * kFarTerms], &far2[k * kFarTerms]));
  }
  return dev;
}

}  // namespace detail

}  // namespace contensou
