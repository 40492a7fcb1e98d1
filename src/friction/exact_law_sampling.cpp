// Samplers of the exact law's tables (exact_law_sampling.hpp).
#include "exact_law_sampling.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>

#include "contensou/friction/quadrature.hpp"
#include "lane_loops.hpp"

namespace contensou::detail {

namespace {
constexpr double kPi = std::numbers::pi;

// x^d; x itself for d = 1 (the same value, without the call).
double power(double x, double d) {
  return d == 1.0 ? x : std::pow(x, d);
}
}  // namespace

double profile_integral(const ExactModel<double>& m, const std::function<double(double)>& h,
                        double layer) {
  // Panels in x (x = rho, or theta with rho = sin(theta) for a Hertz edge), graded towards 0.
  const double top = m.sqrt_edge() ? 0.5 * kPi : 1.0;
  std::vector<double> cuts{0.0};
  for (double x = std::min(layer, top); x < top; x *= 2.0) cuts.push_back(x);
  if (m.table())
    for (std::size_t k = 1; k + 1 < m.table()->knot.size(); ++k)
      cuts.push_back(std::sqrt(m.table()->knot[k]));
  cuts.push_back(top);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  const int nodes = !m.table() ? static_cast<int>(m.chebyshev().size()) + 16 : 8;
  const GaussLegendreRule g = gauss_legendre(nodes);
  double sum = 0.0;
  for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
    const double a = cuts[j], b = cuts[j + 1];
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * g.nodes[i];
      const double w = 0.5 * (b - a) * g.weights[i];
      const double rho = m.sqrt_edge() ? std::sin(x) : x;
      const double jac = m.sqrt_edge() ? std::cos(x) : 1.0;
      double p = profile_at(m, rho * rho);
      if (m.sqrt_edge()) p *= std::sqrt(std::max(0.0, 1.0 - rho * rho));
      sum += w * jac * p * h(rho);
    }
  }
  return sum;
}

ExactModel<double> unit_model(const ExactModel<double>& model) {
  ExactModel<double> unit = model;
  unit.radius = 1.0;
  unit.pressure = 1.0;
  unit.friction = 1.0;
  unit.slip_speed.reset();
  unit.kx = unit.ky = 0.0;
  unit.kappa = 1.0;
  unit.associated_orthotropy = false;
  unit.load_area = model.load_area / (model.radius * model.radius);
  unit.friction_scale = 1.0;
  return unit;
}

void law_functions_from_moments(const SlipMoments& raw, double sigma, double load, double* g) {
  const auto [A, a, b, alpha, c, d] = raw;
  const double den = sigma * load;
  g[kLawSlide] = A / den;
  g[kLawSpin] = a / load;
  g[kLawSpinSum] = (a + b) / den;
  g[kLawShiftCross] = (alpha - c) / den;
  g[kLawShiftDiff] = (c - d) / den;
  g[kLawShiftSum] = (c + d) / den;
}

namespace {

// The series of P_m below in k^2: P_m = pi/2 sum_j C(2j, j) 4^-j w_(m+j) k^(2j),
// w_n = C(2n, n) 4^-n (coefficient[j][m]), to kSeriesTerms terms (k^2 <= 1/5: below 1e-18).
constexpr int kSeriesTerms = 27;
struct EllipticSeries {
  double coefficient[kSeriesTerms][4];
  EllipticSeries() {
    double c = 1.0, w[kSeriesTerms + 4];
    w[0] = 1.0;
    for (int n = 0; n + 1 < kSeriesTerms + 4; ++n)
      w[n + 1] = w[n] * (2.0 * n + 1.0) / (2.0 * n + 2.0);
    for (int j = 0; j < kSeriesTerms; ++j) {
      for (int m = 0; m < 4; ++m) coefficient[j][m] = 0.5 * kPi * c * w[m + j];
      c *= (2.0 * j + 1.0) / (2.0 * j + 2.0);
    }
  }
};

// P_m = integral_0^(pi/2) sin^(2m)(psi) / sqrt(1 - k^2 sin^2(psi)) d psi, m = 0..3, from k^2 and
// k' = sqrt(1 - k^2) (given apart: it is accurate where k^2 is near 1). k^2 <= 1/5: the
// hypergeometric series; above: the arithmetic-geometric mean for K and K - E, then
// (2m + 1) k^2 P_(m+1) = 2m (1 + k^2) P_m - (2m - 1) P_(m-1) (it loses below 1e-15 from 1/5 on).
void elliptic_moments(double k2, double kp, double* P) {
  if (k2 <= 0.2) {
    static const EllipticSeries series;
    double sum[4] = {0.0, 0.0, 0.0, 0.0};
    for (int j = kSeriesTerms - 1; j >= 0; --j)
      for (int m = 0; m < 4; ++m) sum[m] = sum[m] * k2 + series.coefficient[j][m];
    for (int m = 0; m < 4; ++m) P[m] = sum[m];
    return;
  }
  // a_n, b_n -> AGM(1, k'); K - E = K sum_n 2^(n-1) c_n^2, c_0 = k, c_(n+1) = (a_n - b_n) / 2.
  double a = 1.0, b = kp, s = 0.5 * k2, scale = 0.5;
  for (int i = 0; i < 40; ++i) {
    const double c = 0.5 * (a - b), an = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = an;
    scale *= 2.0;
    s += scale * c * c;
    if (c < 1e-9 * a) break;  // the next c is below 1e-18
  }
  const double K = 0.5 * kPi / a;
  P[0] = K;
  P[1] = K * s / k2;
  P[2] = (2.0 * (1.0 + k2) * P[1] - P[0]) / (3.0 * k2);
  P[3] = (4.0 * (1.0 + k2) * P[2] - 3.0 * P[1]) / (5.0 * k2);
}

// The six ring integrals (over theta in [0, 2 pi]) at radius rho about O, centre of sliding
// (0, e), u_hat = (e - y, x) / |r - r_c| (slip_speed_measure.hpp): with sin(theta) = 2 x - 1,
// x = sin^2(psi), |r - r_c| = (rho + e) sqrt(1 - k^2 x), k^2 = 4 rho e / (rho + e)^2, each is
// 4 / (rho + e) times a polynomial in x integrated as P_m. d = rho - e (exact near the ring
// through the centre).
void ring_about_origin(double rho, double e, double d, double* out) {
  const double sum = rho + e, kp = std::abs(d) / sum, k2 = 4.0 * rho * e / (sum * sum);
  double P[4];
  elliptic_moments(k2, kp, P);
  const double f = 4.0 / sum, r2 = rho * rho;
  out[0] = f * (sum * P[0] - 2.0 * rho * P[1]);
  out[1] = f * 4.0 * r2 * (P[1] - P[2]);
  out[2] = f * rho * (-sum * P[0] + (2.0 * e + 4.0 * rho) * P[1] - 4.0 * rho * P[2]);
  out[3] = f * 4.0 * r2 * (sum * P[1] - (e + 3.0 * rho) * P[2] + 2.0 * rho * P[3]);
  out[4] = f * 4.0 * r2 * rho * (-P[1] + 3.0 * P[2] - 2.0 * P[3]);
  out[5] = f * r2 *
           (sum * P[0] - (4.0 * e + 6.0 * rho) * P[1] + (4.0 * e + 12.0 * rho) * P[2] -
            8.0 * rho * P[3]);
}

// The rules of ring_moments: Gauss-Legendre of 4..16 nodes, and tanh-sinh (step 1/8, nodes
// as offsets from the ends, down to 1e-20 of the width) for intervals at the centre's ring.
struct RingQuadrature {
  std::vector<GaussLegendreRule> gauss;  // gauss[n] has n nodes
  std::vector<double> offset, weight;    // of one half of [-1, 1], offset from its end
  RingQuadrature() {
    for (int n = 0; n <= 16; ++n) gauss.push_back(n < 4 ? GaussLegendreRule{} : gauss_legendre(n));
    const double h = 0.125;
    for (int j = 0;; ++j) {
      const double u = 0.5 * kPi * std::sinh(j * h), e2u = std::exp(2.0 * u);
      const double off = 2.0 / (1.0 + e2u);  // 1 - tanh(u)
      if (off < 1e-20) break;
      const double c = std::cosh(u);
      offset.push_back(off);
      weight.push_back(h * 0.5 * kPi * std::cosh(j * h) / (c * c));
    }
  }
};

const RingQuadrature& ring_quadrature() {
  static const RingQuadrature q;
  return q;
}

// Adds the integral over rho in [a, b] (one cubic piece c of the table about t0) of
// rho p(rho^2) times the six ring integrals.
void add_ring_interval(const std::array<double, 4>& c, double t0, double a, double b, double e,
                       SlipMoments& out) {
  const RingQuadrature& q = ring_quadrature();
  auto add = [&](double rho, double d, double w) {
    const double s = rho * rho - t0;
    const double p = c[0] + s * (c[1] + s * (c[2] + s * c[3]));
    double r[6];
    ring_about_origin(rho, e, d, r);
    for (int i = 0; i < 6; ++i) out[i] += w * rho * p * r[i];
  };
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  // Distance of the nearest singularity (rho = e, and rho = -e near O) in half widths.
  const double r = std::min(std::abs(mid - e), mid + e) / half;
  if (r >= 3.0) {  // Gauss-Legendre: error ~ (r + sqrt(r^2 - 1))^(-2n)
    const double B = r + std::sqrt(r * r - 1.0);
    const int n = std::clamp(static_cast<int>(std::ceil(20.0 / std::log(B))), 6, 16);
    const GaussLegendreRule& g = q.gauss[n];
    for (int i = 0; i < n; ++i) {
      const double rho = mid + half * g.nodes[i];
      add(rho, rho - e, half * g.weights[i]);
    }
    return;
  }
  // Near the centre's ring (a log singularity at or beyond an end): tanh-sinh.
  for (std::size_t j = 0; j < q.offset.size(); ++j) {
    const double off = half * q.offset[j], w = half * q.weight[j];
    add(a + off, (a - e) + off, w);
    if (j > 0) add(b - off, (b - e) - off, w);
  }
}

}  // namespace

namespace {

// The moments of piece k: rho p(rho^2) T_m(u) is a polynomial of degree 7 + m <= 30 in rho, so
// 16-point Gauss-Legendre is exact; its nodes are the u of T_m (T[i][m] = T_m(x_i)).
RingNode piece_ring_moments(const ExactModel<double>& unit, std::size_t k,
                            const GaussLegendreRule& g,
                            const std::vector<std::array<double, kRingTerms>>& T) {
  RingNode node{std::sqrt(unit.table()->knot[k]), std::sqrt(unit.table()->knot[k + 1]), {}};
  const double half = 0.5 * (node.b - node.a), mid = 0.5 * (node.a + node.b);
  const std::array<double, 4>& c = unit.table()->piece[k];
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const double rho = mid + half * g.nodes[i], s = rho * rho - unit.table()->knot[k];
    const double w = half * g.weights[i] * rho * (c[0] + s * (c[1] + s * (c[2] + s * c[3])));
    for (int m = 0; m < kRingTerms; ++m) node.mu[m] += w * T[i][m];
  }
  return node;
}

// Adds a child's moments to its parent's. On the child, u_parent = alpha u + beta (alpha =
// (b - a) / (B - A), beta = (a + b - A - B) / (B - A), |alpha| + |beta| <= 1) and
// T_m(alpha u + beta) = sum_k E_mk T_k(u), the rows by T_(m+1) = 2 (alpha u + beta) T_m - T_(m-1)
// with u T_0 = T_1, u T_k = (T_(k+1) + T_(k-1)) / 2; then mu_parent,m += sum_k E_mk mu_k.
void add_ring_child(const RingNode& child, RingNode& parent) {
  const double W = parent.b - parent.a;
  if (!(W > 0.0)) return;
  const double alpha = (child.b - child.a) / W;
  const double beta = ((child.a - parent.a) + (child.b - parent.b)) / W;
  std::array<double, kRingTerms + 2> prev{}, row{}, next{};
  row[0] = 1.0;
  for (int m = 0; m < kRingTerms; ++m) {
    double sum = 0.0;
    for (int k = 0; k <= m; ++k) sum += row[k] * child.mu[k];
    parent.mu[m] += sum;
    const double f = m == 0 ? 1.0 : 2.0;  // T_1 = alpha u + beta, then the recurrence
    for (int k = 0; k <= m + 1; ++k) {
      const double u_row = k == 0   ? 0.5 * row[1]
                           : k == 1 ? row[0] + 0.5 * row[2]
                                    : 0.5 * (row[k - 1] + row[k + 1]);
      next[k] = f * (alpha * u_row + beta * row[k]) - prev[k];
    }
    prev = row;
    row = next;
  }
}

// Adds the integral over a tree node far from the centre's ring, where the ring functions are
// analytic: interpolated at the n Chebyshev points z_j of the node, r_i = sum_m a_im T_m(u), so
// that integral rho p r_i d rho = sum_m a_im mu_m = sum_j W_j r_i(rho_j) with the node's own
// weights W_j = (1/n) sum_m (m ? 2 : 1) mu_m cos(pi m (j + 1/2) / n).
void add_ring_node(const RingTree& tree, const RingNode& node, int n, double e, SlipMoments& out) {
  const std::vector<double>& cs = tree.cosines[n];
  const double half = 0.5 * (node.b - node.a), mid = 0.5 * (node.a + node.b);
  for (int j = 0; j < n; ++j) {
    double W = node.mu[0] * cs[j];
    for (int m = 1; m < n; ++m) W += 2.0 * node.mu[m] * cs[m * n + j];
    const double z = cs[n + j], rho = mid + half * z;
    double r[6];
    ring_about_origin(rho, e, (node.a - e) + half * (1.0 + z), r);
    for (int i = 0; i < 6; ++i) out[i] += W / n * r[i];
  }
}

// Adds a piece's rings, split at the centre's ring if it crosses it (add_ring_interval).
void add_piece_rings(const ExactModel<double>& unit, std::size_t k, double e, SlipMoments& out) {
  const double a = std::sqrt(unit.table()->knot[k]), b = std::sqrt(unit.table()->knot[k + 1]);
  if (!(b > a)) return;
  if (e > a && e < b) {
    add_ring_interval(unit.table()->piece[k], unit.table()->knot[k], a, e, e, out);
    add_ring_interval(unit.table()->piece[k], unit.table()->knot[k], e, b, e, out);
  } else {
    add_ring_interval(unit.table()->piece[k], unit.table()->knot[k], a, b, e, out);
  }
}

// Adds the rings of node i of level s: by its moments where it lies 3 half widths from the
// singularities at rho = e and -e (the interpolation then converges like B^-n, B = r +
// sqrt(r^2 - 1), r the distance in half widths: n = 38 / ln B points leave e^-38 = 3e-17, as
// the pieces' Gauss rules), else by its children, down to the pieces.
void add_ring_subtree(const RingTree& tree, const ExactModel<double>& unit, std::size_t s,
                      std::size_t i, double e, SlipMoments& out) {
  if (s == 0) return add_piece_rings(unit, i, e, out);
  const RingNode& node = tree.level[s][i];
  const double half = 0.5 * (node.b - node.a), mid = 0.5 * (node.a + node.b);
  const double r = std::min(std::abs(mid - e), mid + e) / half;
  if (r >= 3.0) {
    const double B = r + std::sqrt(r * r - 1.0);
    const int n = std::clamp(static_cast<int>(std::ceil(38.0 / std::log(B))), 8, kRingTerms);
    return add_ring_node(tree, node, n, e, out);
  }
  for (std::size_t c = 2 * i; c < std::min(2 * i + 2, tree.level[s - 1].size()); ++c)
    add_ring_subtree(tree, unit, s - 1, c, e, out);
}

}  // namespace

RingTree ring_tree(const ExactModel<double>& unit) {
  RingTree tree;
  const GaussLegendreRule g = gauss_legendre(16);
  std::vector<std::array<double, kRingTerms>> T(g.nodes.size());
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    T[i][0] = 1.0;
    T[i][1] = g.nodes[i];
    for (int m = 2; m < kRingTerms; ++m) T[i][m] = 2.0 * g.nodes[i] * T[i][m - 1] - T[i][m - 2];
  }
  tree.level.emplace_back();
  for (std::size_t k = 0; k < unit.table()->piece.size(); ++k)
    tree.level[0].push_back(piece_ring_moments(unit, k, g, T));
  while (tree.level.back().size() > 1) {
    const std::vector<RingNode>& below = tree.level.back();
    std::vector<RingNode> up;
    for (std::size_t i = 0; i < below.size(); i += 2) {
      RingNode node{below[i].a, (i + 1 < below.size() ? below[i + 1] : below[i]).b, {}};
      add_ring_child(below[i], node);
      if (i + 1 < below.size()) add_ring_child(below[i + 1], node);
      up.push_back(node);
    }
    tree.level.push_back(std::move(up));
  }
  tree.cosines.resize(kRingTerms + 1);
  for (int n = 2; n <= kRingTerms; ++n)
    for (int m = 0; m < n; ++m)
      for (int j = 0; j < n; ++j) tree.cosines[n].push_back(std::cos(kPi * m * (j + 0.5) / n));
  return tree;
}

SlipMoments table_ring_moments(const RingTree& tree, const ExactModel<double>& unit, double e) {
  SlipMoments out{};
  if (!tree.level.empty() && !tree.level[0].empty())
    add_ring_subtree(tree, unit, tree.level.size() - 1, 0, e, out);
  return out;
}

// Samples the six functions of t from five adaptive integrals of the unit model in the sliding
// frame, v = sigma x, omega = eta > 0 (sigma + eta = 1):
//   P1 kappa = 1, k = 0:            Fx = -A,  Mz = -(a - b)
//   P2 kappa = 2, k = 0:            Mz = -(2a - b)
//   P3 kappa = 1, k = (0, 1):       Mz = -(a - b) - (c - d)
//   P4 kappa = 2, k = (0, 1):       Mz = -(2a - b) - 3/2 (c - d) - 1/2 (c + d)
//   P5 kappa = 2, k = e = 45 deg:   Mz = -(3a - 3/2 (a + b)) - 1/2 (alpha - c)
// At t = -1 the limits of exact_law.hpp (moments A^0, A^1, A^2 of the representation).
ConstantSampler::ConstantSampler(const ExactModel<double>& model, double tolerance)
    : unit_(unit_model(model)),
      rings_(!unit_.table() ? RingTree{} : ring_tree(unit_)),
      tol_(tolerance) {
  const double A0 = profile_integral(unit_, [](double) { return 1.0; });
  const double A1 = profile_integral(unit_, [](double r) { return r; });
  const double A2 = profile_integral(unit_, [](double r) { return r * r; });
  slide_limit_ = A0 / (2.0 * A1);
  shift_limit_ = A2 / (4.0 * A1);
}

Resultants<double> ConstantSampler::probe(double kappa, double kx, double ky,
                                          const Kinematics<double>& k) const {
  // The model's coefficients are shared read-only (promote copies them for a new scalar only).
  ExactModel<double> m = unit_;
  m.kappa = kappa;
  m.kx = kx;
  m.ky = ky;
  return exact_resultants(m, k, {tol_}).resultants;
}

void ConstantSampler::operator()(double t, double* g) const {
  const double sigma = 0.5 * (1.0 + t), eta = 0.5 * (1.0 - t), h = std::sqrt(0.5);
  // A table: its rings about O in closed form (away from the limits).
  if (unit_.table() && sigma > 0.0 && eta > 0.0) {
    law_functions_from_moments(table_ring_moments(rings_, unit_, sigma / eta), sigma,
                               unit_.load_area, g);
    return;
  }
  const Resultants<double> p1 = probe(1.0, 0.0, 0.0, {sigma, 0.0, eta});
  const double Mz2 = probe(2.0, 0.0, 0.0, {sigma, 0.0, eta}).Mz;
  const double Mz3 = probe(1.0, 0.0, 1.0, {sigma, 0.0, eta}).Mz;
  const double Mz4 = probe(2.0, 0.0, 1.0, {sigma, 0.0, eta}).Mz;
  const double Mz5 = probe(2.0, h, h, {h * sigma, h * sigma, eta}).Mz;
  const double a = p1.Mz - Mz2, b = a + p1.Mz;
  const double cd_diff = -(Mz3 - p1.Mz);
  const double cd_sum = -2.0 * (Mz4 - Mz2) - 3.0 * cd_diff;
  const double cross = -2.0 * Mz5 - 6.0 * a + 3.0 * (a + b);
  if (sigma == 0.0) {  // pure spin: the limits (exact_law.hpp)
    g[kLawSpin] = a / unit_.load_area;
    g[kLawSlide] = slide_limit_;
    g[kLawShiftCross] = g[kLawShiftSum] = shift_limit_;
    g[kLawSpinSum] = g[kLawShiftDiff] = 0.0;
    return;
  }
  // alpha - c and c + d are what the probes give; write them as alpha, c, d with c = (cd_sum +
  // cd_diff) / 2, d = (cd_sum - cd_diff) / 2, alpha = cross + c.
  const double c = 0.5 * (cd_sum + cd_diff), d = 0.5 * (cd_sum - cd_diff);
  law_functions_from_moments({-p1.Fx, a, b, cross + c, c, d}, sigma, unit_.load_area, g);
}

namespace {

// At t = -1 (v = 0) with G(rho) = exp(-z rho^delta) (the weight at |vc| = omega rho, unit
// speed), the first-order turn of the slip direction and of |vc| about r_c = (0, eps) gives
//   A / sigma -> pi int p G (1 - delta z rho^delta),   a -> pi int p G rho^2,
//   (alpha - c) / sigma = (c + d) / sigma -> pi/2 int p rho^2 G (1 - delta z rho^delta),
//   (c - d) / sigma -> pi delta z int p rho^(2 + delta) G,   (a + b) / sigma -> 0
// (integrals d rho over [0, 1]; z = 0 gives the constant-friction limits).
void spin_limits(const ExactModel<double>& unit, double d, double z, double* g) {
  // Panels graded towards rho = 0 (the layer of G for large z, and rho^delta).
  const double layer = 1e-6 * std::min(1.0, std::pow(std::max(z, 1e-300), -1.0 / d));
  auto G = [&](double r) { return std::exp(-z * power(r, d)); };
  auto slope = [&](double r) { return 1.0 - d * z * power(r, d); };
  const double slide = profile_integral(
      unit, [&](double r) { return G(r) * slope(r); }, layer);
  const double spin = profile_integral(
      unit, [&](double r) { return G(r) * r * r; }, layer);
  const double shift = profile_integral(
      unit, [&](double r) { return r * r * G(r) * slope(r); }, layer);
  const double diff = profile_integral(
      unit, [&](double r) { return std::pow(r, 2.0 + d) * G(r); }, layer);
  const double L = unit.load_area;
  g[kLawSlide] = kPi * slide / L;
  g[kLawSpin] = kPi * spin / L;
  g[kLawSpinSum] = 0.0;
  g[kLawShiftCross] = g[kLawShiftSum] = 0.5 * kPi * shift / L;
  g[kLawShiftDiff] = kPi * d * z * diff / L;
}

// 1 / i!, i = 0..13.
constexpr std::array<double, 14> kInverseFactorial = [] {
  std::array<double, 14> c{1.0};
  for (int i = 1; i < 14; ++i) c[i] = c[i - 1] / i;
  return c;
}();

// exp(-x) for x in [0, 46], branch-free (it vectorises in a lane loop, std::exp does not):
// exp(-x) = 2^k exp(r), k = round(-x / ln 2), r = -x - k ln 2 in [-ln 2 / 2, ln 2 / 2] (ln 2 in
// two parts, Cody and Waite: k ln2_hi is exact), exp(r) by its Taylor series to r^13 (the rest
// below 5e-18 relative), 2^k from the bits of k + 1.5 2^52 (its low bits hold k + 2^51).
// Within one ulp of std::exp.
CONTENSOU_LANE_INLINE double exp_minus(double x) {
  constexpr double kLog2e = 1.4426950408889634, kShift = 0x1.8p52;
  constexpr double kLn2Hi = 6.93147180369123816490e-01, kLn2Lo = 1.90821492927058770002e-10;
  const double kd = kShift - x * kLog2e;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(kd);
  const double k = kd - kShift;
  const double r = (-x - k * kLn2Hi) - k * kLn2Lo;
  double p = kInverseFactorial[13];
  for (int i = 12; i >= 0; --i) p = p * r + kInverseFactorial[i];
  return p * std::bit_cast<double>((bits + 1023) << 52);
}

// sum_i w[c][i] exp(-z mu[i]) (c = 0..5, w[c][i] = w[c * stride + i]) over the first `blocks`
// blocks of kLanes nodes, mu ascending, the nodes with z mu > 46 left out (exp(-46) = 1e-20):
// lane l sums the nodes i = l mod kLanes.
CONTENSOU_LANE_CLONES SlipMoments falling_sums(const double* mu, const double* w,
                                               std::size_t stride, std::size_t blocks, double z) {
  double acc[6][kLanes] = {};
  for (std::size_t b = 0; b < blocks; ++b) {
    for (int l = 0; l < kLanes; ++l) {
      const std::size_t i = b * kLanes + l;
      const double x = z * mu[i], e = exp_minus(std::min(x, 46.0));
      const double g = x <= 46.0 ? e : 0.0;
      for (int c = 0; c < 6; ++c) acc[c][l] += w[c * stride + i] * g;
    }
  }
  SlipMoments sum{};
  for (int c = 0; c < 6; ++c)
    for (int l = 0; l < kLanes; ++l) sum[c] += acc[c][l];
  return sum;
}

}  // namespace

void falling_functions(const ExactModel<double>& unit, double delta,
                       const SlipSpeedMeasureOptions& options, double t,
                       const std::vector<double>& zs, double* out) {
  if (t <= -1.0) {
    for (std::size_t k = 0; k < zs.size(); ++k) spin_limits(unit, delta, zs[k], out + 6 * k);
    return;
  }
  const SlipSpeedMeasure m = slip_speed_measure(unit, t, options);
  // mu = nu^delta in increasing order, so that the sums stop where exp(-z mu) < 1e-20; the
  // weights by component (structure of arrays), padded to whole blocks with weights 0.
  std::vector<std::size_t> order(m.nu.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto i, auto j) { return m.nu[i] < m.nu[j]; });
  const std::size_t n = order.size(), stride = (n + kLanes - 1) / kLanes * kLanes;
  std::vector<double> mu(stride, 0.0), w(6 * stride, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    mu[i] = power(m.nu[order[i]], delta);
    for (int c = 0; c < 6; ++c) w[c * stride + i] = m.weight[order[i]][c];
  }
  const double sigma = 0.5 * (1.0 + t);
  for (std::size_t k = 0; k < zs.size(); ++k) {
    // The nodes up to the first with z mu > 46 (one more against rounding; falling_sums drops it).
    const double z = zs[k];
    const std::size_t used =
        z > 0.0 ? std::min<std::size_t>(
                      n, std::upper_bound(mu.begin(), mu.begin() + n, 46.0 / z) - mu.begin() + 1)
                : n;
    const SlipMoments sum =
        falling_sums(mu.data(), w.data(), stride, (used + kLanes - 1) / kLanes, z);
    law_functions_from_moments(sum, sigma, unit.load_area, out + 6 * k);
  }
}

}  // namespace contensou::detail
