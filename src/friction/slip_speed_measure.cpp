// The slip-speed quadrature of a patch (slip_speed_measure.hpp).
#include "contensou/friction/slip_speed_measure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/quadrature.hpp"

namespace contensou {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kRingCapacity = 640;

// The profile at n points t (with its Hertz edge).
void profile_at(const ExactModel<double>& m, const double* t, int n, double* p) {
  detail::profile_batch(m, t, n, m.chebyshev.size(), p);
  if (m.sqrt_edge)
    for (int i = 0; i < n; ++i) p[i] *= std::sqrt(std::max(0.0, 1.0 - t[i]));
}

// The six ring weights at a point of the half ring with cos(phi) = c, sin^2(phi) = s2 and
// y = eps - s cos(phi), times w: cos(phi), s sin^2(phi), y cos(phi), s^2 sin^2(phi) cos(phi),
// s y sin^2(phi), y^2 cos(phi) (slip_speed_measure.hpp).
void add_ring_point(double w, double c, double s2, double y, double s, SlipMoments& out) {
  out[0] += w * c;
  out[1] += w * s * s2;
  out[2] += w * y * c;
  out[3] += w * s * s * s2 * c;
  out[4] += w * s * y * s2;
  out[5] += w * y * y * c;
}

// The ring weights of a constant profile p_c over phi in [0, phi_end], in closed form:
// integrals of cos, s sin^2, y cos, s^2 sin^2 cos, s y sin^2 and y^2 cos with y = eps - s cos.
SlipMoments constant_ring(double p_c, double s, double eps, double phi_end) {
  const double sn = std::sin(phi_end), cs = std::cos(phi_end);
  const double s3 = sn * sn * sn;
  const double sin2 = 0.5 * phi_end - 0.5 * sn * cs;  // integral sin^2
  const double cos2 = 0.5 * phi_end + 0.5 * sn * cs;  // integral cos^2
  const double cos3 = sn - s3 / 3.0;                  // integral cos^3
  return {p_c * sn,
          p_c * s * sin2,
          p_c * (eps * sn - s * cos2),
          p_c * s * s * s3 / 3.0,
          p_c * s * (eps * sin2 - s * s3 / 3.0),
          p_c * (eps * eps * sn - 2.0 * eps * s * cos2 + s * s * cos3)};
}

// The rules of a table's ring pieces (half_ring_table): Gauss-Legendre of 1..coarse_max nodes
// (gauss[n] has n) for the pieces away from both ends of the ring's range, `fine` for the others.
struct RingRules {
  std::vector<GaussLegendreRule> gauss;
  std::vector<double> reach;  // plain_piece_nodes
  GaussLegendreRule fine;
  int coarse_min = 3, coarse_max = 6;
};

// The nodes of a ring's pieces before the sums (half_ring_table): the node's share of the
// integral without the square root of its far end (f), lo = t - t_min, and the factor whose
// inverse square root f still needs (1 where it has none). Padded to whole blocks of four.
struct RingNodes {
  std::vector<double> f, lo, far;
  std::size_t size = 0;
  void reserve(std::size_t n) {
    if (f.size() < n) {
      f.resize(n);
      lo.resize(n);
      far.resize(n);
    }
  }
};

// Nodes of the Gauss rule for the piece [va, vb] of v (v = sqrt(t - t_min) or sqrt(t_max - t))
// whose integrand, analytic in v, is singular at v = +-root (the far end of the ring's range): the
// error of n nodes is about B^(-2n), B = r + sqrt(r^2 - 1), r the distance of root from the
// piece's middle in half widths (the Bernstein ellipse through it). rules.reach[n] is the r from
// which n nodes leave below about 1e-16 of the piece.
int plain_piece_nodes(double va, double vb, double root, const RingRules& rules) {
  const double half = 0.5 * (vb - va), mid = 0.5 * (va + vb), gap = std::min(root - mid, mid);
  int n = rules.coarse_min;
  while (n < rules.coarse_max && gap < rules.reach[n] * half) ++n;
  return n;
}

// What the pieces of one table ring share (half_ring_table): the ring's range of t = |r|^2,
// t_min = (s - eps)^2 to t_max = (s + eps)^2, its span and the square root of the span, and the
// profile's value p_c at the middle of the range.
struct TableRing {
  double t_min, t_max, span, root_span, p_c;
};

// The plain pieces of a table ring with the same number of nodes (half_ring_table), structure
// of arrays padded to whole blocks of kLanes: each piece's v at its start (va) and half width
// (dv), |r|^2 - t_min = base + sign v^2, its ends a, b, its knot tk and its cubic's coefficients
// (c0 minus the profile's value p_c at the middle of the ring's range).
constexpr int kLanes = 8;
// The lane loops also for AVX2 + FMA and AVX-512, chosen at load time (the rest of the file keeps
// the baseline instruction set).
#if defined(__x86_64__) && defined(__GNUC__) && defined(__ELF__)
#define CONTENSOU_LANE_CLONES [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
#else
#define CONTENSOU_LANE_CLONES
#endif
struct PlainPieces {
  enum Field { kVa, kDv, kBase, kSign, kA, kB, kKnot, kC0, kC1, kC2, kC3, kFields };
  std::array<std::vector<double>, kFields> field;
  std::size_t size = 0;
  void push(const std::array<double, kFields>& v) {
    if (field[0].size() < size + kLanes)
      for (auto& f : field) f.resize(2 * size + 2 * kLanes);
    for (int i = 0; i < kFields; ++i) field[i][size] = v[i];
    ++size;
  }
  // Pads to whole blocks with pieces of no width (their nodes weigh 0).
  void pad(double t_min) {
    for (; size % kLanes != 0; ++size)
      for (int i = 0; i < kFields; ++i)
        field[i][size] = i == kA || i == kB || i == kKnot ? t_min : 0.0;
  }
};

// The sums S_l = sum f lambda^l (l = 0..3) of ring_node_sums over the nodes of `pieces`, the
// n-point rule g on each, added to S: v = va + dv (1 + x_i), |r|^2 = t_min + base + sign v^2,
// f = 2 dv w_i (p - p_c) / sqrt(span - v^2) (the far end's square root), lambda = (|r|^2 - t_min)
// / D. Branch-free across kLanes pieces at a time (the compiler vectorises the lanes).
CONTENSOU_LANE_CLONES void plain_piece_sums(const PlainPieces& pieces, const GaussLegendreRule& g,
                                            double t_min, double span, double inv_d, double S[4]) {
  const int n = static_cast<int>(g.nodes.size());
  const auto& F = pieces.field;
  double acc[4][kLanes] = {};
  for (std::size_t j = 0; j < pieces.size; j += kLanes) {
    for (int i = 0; i < n; ++i) {
      const double x = 1.0 + g.nodes[i], w = 2.0 * g.weights[i];
      for (int l = 0; l < kLanes; ++l) {
        const std::size_t q = j + l;
        const double dv = F[PlainPieces::kDv][q], v = F[PlainPieces::kVa][q] + dv * x, v2 = v * v;
        const double lo = F[PlainPieces::kBase][q] + F[PlainPieces::kSign][q] * v2;
        const double far = span - v2, root = std::sqrt(far > 0.0 ? far : 1.0);
        const double y =
            std::min(std::max(t_min + lo, F[PlainPieces::kA][q]), F[PlainPieces::kB][q]) -
            F[PlainPieces::kKnot][q];
        const double p = F[PlainPieces::kC0][q] +
                         y * (F[PlainPieces::kC1][q] +
                              y * (F[PlainPieces::kC2][q] + y * F[PlainPieces::kC3][q]));
        const double f = (far > 0.0 ? w : 0.0) * dv * p / root;  // 0 where far is 0
        const double lambda = lo * inv_d, f1 = f * lambda, f2 = f1 * lambda;
        acc[0][l] += f;
        acc[1][l] += f1;
        acc[2][l] += f2;
        acc[3][l] += f2 * lambda;
      }
    }
  }
  for (int k = 0; k < 4; ++k) {
    double sum = 0.0;
    for (int l = 0; l < kLanes; ++l) sum += acc[k][l];
    S[k] += sum;
  }
}

// Piece k of the table (the cubic about knot k) on [a, b] of the ring's range (half_ring_table):
// far from both ends of the range it goes to the plain pieces of its node count (v = sqrt(t -
// t_min) on the lower half, sqrt(t_max - t) on the upper: dt / sqrt(t - t_min) = 2 dv, the near
// square root gone, the far one smooth; root_a, root_b: the square roots of a and b from the near
// end); near both, its nodes in the angle phi itself go to `nodes`: t = t_min + (t_max - t_min)
// sin^2(phi / 2), dt / sqrt((t - t_min)(t_max - t)) = d phi, with the fine rule.
void add_ring_piece(const ExactModel<double>& m, std::size_t k, double a, double b,
                    const double root_a[2], const double root_b[2], const TableRing& ring,
                    const RingRules& rules, RingNodes& nodes, std::vector<PlainPieces>& plain) {
  const double t_min = ring.t_min, span = ring.span;
  const bool lower = (a - t_min) <= (ring.t_max - b);
  const double far = lower ? ring.t_max - b : a - t_min;
  const std::array<double, 4>& c = m.piece[k];
  const double tk = m.knot[k], c0 = c[0] - ring.p_c;
  if (!(far < 4.0 * (b - a))) {
    const double va = lower ? root_a[0] : root_b[1], vb = lower ? root_b[0] : root_a[1];
    const int n = plain_piece_nodes(va, vb, ring.root_span, rules);
    plain[n].push({va, 0.5 * (vb - va), lower ? 0.0 : span, lower ? 1.0 : -1.0, a, b, tk, c0, c[1],
                   c[2], c[3]});
    return;
  }
  // phi at a and b: sin^2(phi / 2) = (t - t_min) / span
  const double va = 2.0 * std::asin(std::sqrt(std::clamp((a - t_min) / span, 0.0, 1.0)));
  const double vb = 2.0 * std::asin(std::sqrt(std::clamp((b - t_min) / span, 0.0, 1.0)));
  const GaussLegendreRule& g = rules.fine;
  const int n = static_cast<int>(g.nodes.size());
  nodes.reserve(nodes.size + n + 4);
  double* f = nodes.f.data() + nodes.size;
  double* lo = nodes.lo.data() + nodes.size;
  double* fr = nodes.far.data() + nodes.size;
  const double dv = 0.5 * (vb - va);
  for (int i = 0; i < n; ++i) {  // dt / root = d phi, times the piece's cubic minus p_c
    const double h = std::sin(0.5 * (va + dv * (1.0 + g.nodes[i])));
    lo[i] = span * h * h;
    fr[i] = 1.0;
    const double x = std::min(std::max(t_min + lo[i], a), b) - tk;
    f[i] = dv * g.weights[i] * (c0 + x * (c[1] + x * (c[2] + x * c[3])));
  }
  nodes.size += n;
}

// The sums S_l = sum f lambda^l (l = 0..3) over the nodes, lambda = lo / D in [0, 2] (four at a
// time), added to S.
void ring_node_sums(RingNodes& nodes, double D, double S[4]) {
  const std::size_t n = (nodes.size + 3) / 4 * 4;
  nodes.reserve(n);
  for (std::size_t i = nodes.size; i < n; ++i) nodes.f[i] = nodes.lo[i] = 0.0, nodes.far[i] = 1.0;
  const double inv_d = 1.0 / D;
  double acc[4][4] = {};
  for (std::size_t i = 0; i < n; i += 4) {
    for (int l = 0; l < 4; ++l) {
      const double q = nodes.far[i + l];
      const double f = (q > 0.0 ? nodes.f[i + l] : 0.0) / std::sqrt(q > 0.0 ? q : 1.0);
      const double lambda = nodes.lo[i + l] * inv_d;
      const double f1 = f * lambda, f2 = f1 * lambda;
      acc[0][l] += f;
      acc[1][l] += f1;
      acc[2][l] += f2;
      acc[3][l] += f2 * lambda;
    }
  }
  for (int k = 0; k < 4; ++k) S[k] += (acc[k][0] + acc[k][1]) + (acc[k][2] + acc[k][3]);
}

// The six ring weights (add_ring_point) from the sums S_l = sum f lambda^l: with D = 2 eps s and
// span = 2 D, cos(phi) = 1 - lambda, sin^2(phi) = lambda (2 - lambda), y = y0 + s lambda (y0 =
// eps - s), so each weight is a cubic in lambda (theory.md section 2, the slip direction about
// r_c):
//   c -> S0 - S1,  s sin^2 -> s (2 S1 - S2),  y c -> y0 S0 + (s - y0) S1 - s S2,
//   s^2 sin^2 c -> s^2 (2 S1 - 3 S2 + S3),  s y sin^2 -> s (2 y0 S1 + (2 s - y0) S2 - s S3),
//   y^2 c -> y0^2 S0 + y0 (2 s - y0) S1 + s (s - 2 y0) S2 - s^2 S3.
SlipMoments ring_moments(const double S[4], double eps, double s) {
  const double y0 = eps - s;
  return {S[0] - S[1],
          s * (2.0 * S[1] - S[2]),
          y0 * S[0] + (s - y0) * S[1] - s * S[2],
          s * s * (2.0 * S[1] - 3.0 * S[2] + S[3]),
          s * (2.0 * y0 * S[1] + (2.0 * s - y0) * S[2] - s * S[3]),
          y0 * y0 * S[0] + y0 * (2.0 * s - y0) * S[1] + s * (s - 2.0 * y0) * S[2] - s * s * S[3]};
}

// The half ring of a table in the variable t = |r|^2 = C - D cos(phi) (C = s^2 + eps^2,
// D = 2 eps s), broken at the knots, where the profile is a cubic: d phi = dt / sqrt((t - t_min)
// (t_max - t)), t_min = (s - eps)^2, t_max = (s + eps)^2; the square roots at t_min (and at
// t_max for a ring inside the disk) are removed by t = t_min + w u^2 on the end pieces.
SlipMoments half_ring_table(const ExactModel<double>& m, double s, double eps,
                            const RingRules& rules) {
  TableRing ring;
  ring.t_min = (s - eps) * (s - eps);
  ring.t_max = (s + eps) * (s + eps);
  ring.span = ring.t_max - ring.t_min;
  ring.root_span = std::sqrt(ring.span);
  const double t_end = std::min(1.0, ring.t_max), D = 2.0 * eps * s;
  const auto first = std::upper_bound(m.knot.begin(), m.knot.end(), ring.t_min);
  // The profile's value at the middle of the ring's range, in closed form; the rule takes only
  // the rest, p - p_c, which is O(eps s) on the ring: its error shrinks with the centre's
  // distance from O (the functions are divided by sigma ~ eps near pure spin).
  double t_c = std::min(s * s + eps * eps, 1.0);
  profile_at(m, &t_c, 1, &ring.p_c);
  const double phi_end =
      t_end == ring.t_max
          ? std::numbers::pi
          : 2.0 * std::asin(std::sqrt(std::clamp((1.0 - ring.t_min) / ring.span, 0.0, 1.0)));
  const SlipMoments closed = constant_ring(ring.p_c, s, eps, phi_end);
  thread_local RingNodes nodes;
  thread_local std::vector<PlainPieces> plain;
  nodes.size = 0;
  plain.resize(rules.gauss.size());
  for (PlainPieces& p : plain) p.size = 0;
  // The pieces between t_min, the knots inside the range and t_end; the first is the table's
  // piece holding t_min. The square roots of each break from both ends of the range, once.
  std::size_t k =
      std::min<std::size_t>(std::max<std::ptrdiff_t>(first - m.knot.begin(), 1), m.piece.size()) -
      1;
  double a = ring.t_min;
  double root_a[2] = {0.0, std::sqrt(std::max(0.0, ring.span))};
  for (auto it = first;; ++it) {
    const bool last = it == m.knot.end() || !(*it < t_end);
    const double b = last ? t_end : *it;
    const double root_b[2] = {std::sqrt(b - ring.t_min), std::sqrt(std::max(0.0, ring.t_max - b))};
    if (b > a) add_ring_piece(m, k, a, b, root_a, root_b, ring, rules, nodes, plain);
    if (last) break;
    a = b;
    root_a[0] = root_b[0];
    root_a[1] = root_b[1];
    k = std::min(k + 1, m.piece.size() - 1);
  }
  double S[4] = {};
  for (std::size_t n = 0; n < plain.size(); ++n) {
    if (plain[n].size == 0) continue;
    plain[n].pad(ring.t_min);
    plain_piece_sums(plain[n], rules.gauss[n], ring.t_min, ring.span, 1.0 / D, S);
  }
  ring_node_sums(nodes, D, S);
  SlipMoments out = ring_moments(S, eps, s);
  for (int i = 0; i < 6; ++i) out[i] += closed[i];
  return out;
}

// m_i(s) / (2 s): the half-ring integral over phi = beta + pi/2 in [0, theta_w] of p(|r|^2)
// times the ring weights (add_ring_point), with |r|^2 = (s - eps)^2 + 4 eps s sin^2(phi/2) and
// y = (eps - s) + 2 s sin^2(phi/2) (no cancellation for a far centre). A table whose knots the
// ring crosses goes to half_ring_table.
SlipMoments half_ring(const ExactModel<double>& m, double s, double eps, double tol,
                      const RingRules& g) {
  const double dsq = (s - eps) * (s - eps);
  SlipMoments out{};
  if (!(dsq < 1.0)) return out;
  const double four_es = 4.0 * eps * s;
  if (!(four_es > 0.0)) {  // a ring about O: |r| = s (only a and b survive)
    double t = s * s, p = 0.0;
    profile_at(m, &t, 1, &p);
    out[1] = p * s * 0.5 * kPi;
    out[2] = -p * s * 0.5 * kPi;
    return out;
  }
  if (!m.piece.empty() && four_es > 1e-6) {
    const double t_end = std::min(1.0, (s + eps) * (s + eps));
    const auto it = std::upper_bound(m.knot.begin(), m.knot.end(), dsq);
    if (it != m.knot.end() && *it < t_end) return half_ring_table(m, s, eps, g);
  }
  // Arc end: |r|^2 = 1 at sin^2(theta_w / 2) = (1 - dsq) / (4 eps s).
  const double theta_w =
      four_es <= 1.0 - dsq ? kPi : 2.0 * std::asin(std::sqrt((1.0 - dsq) / four_es));
  const bool edge = m.sqrt_edge && theta_w < kPi;  // sqrt(1 - |r|^2) at the arc end
  auto f = [&](const double* x, int n, int, detail::Sample<double, 6>* values) {
    double tr[detail::kKronrodPoints], p[detail::kKronrodPoints], phi[detail::kKronrodPoints],
        jac[detail::kKronrodPoints];
    for (int i = 0; i < n; ++i) {
      // phi = theta_w sin(psi) removes the square root of a Hertz edge at the arc end.
      phi[i] = edge ? theta_w * std::sin(x[i]) : x[i];
      jac[i] = edge ? theta_w * std::cos(x[i]) : 1.0;
      const double h = std::sin(0.5 * phi[i]);
      tr[i] = std::min(1.0, dsq + four_es * h * h);
    }
    profile_at(m, tr, n, p);
    for (int i = 0; i < n; ++i) {
      const double h = std::sin(0.5 * phi[i]), sn = std::sin(phi[i]);
      SlipMoments v{};
      add_ring_point(p[i] * jac[i], std::cos(phi[i]), sn * sn, (eps - s) + 2.0 * s * h * h, s, v);
      values[i].value = v;
    }
  };
  const detail::TaggedInterval whole{0.0, edge ? 0.5 * kPi : theta_w, 0};
  const std::array<double, 6> t6{tol, tol, tol, tol, tol, tol};
  return detail::integrate_adaptive_batch<double, 6, kRingCapacity, detail::kGK21>(f, &whole, 1, t6)
      .value;
}

struct Panel {
  double a, b;
  // -1: nu = a + w u^2 (towards a), +1: nu = b - w u^2 (towards b), 2: nu = a + w (1 - cos(pi u))
  // / 2 (towards both), 0: plain
  int squeeze;
};

// Panels on [a, b] graded by halving towards a down to width min_a (and towards b down to
// min_b); the innermost panels squeeze their rule towards the end point.
void graded_panels(double a, double b, double min_a, double min_b, std::vector<Panel>& out) {
  if (!(b > a)) return;
  const double mid = 0.5 * (a + b);
  std::vector<double> left{mid}, right{mid};
  for (double h = 0.5 * (mid - a); h > min_a && left.size() < 60; h *= 0.5) left.push_back(a + h);
  for (double h = 0.5 * (b - mid); h > min_b && right.size() < 60; h *= 0.5) right.push_back(b - h);
  std::vector<double> pts{a};
  for (std::size_t i = left.size(); i-- > 0;) pts.push_back(left[i]);
  for (std::size_t i = 1; i < right.size(); ++i) pts.push_back(right[i]);
  pts.push_back(b);
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const int squeeze = i == 0 ? -1 : (i + 2 == pts.size() ? 1 : 0);
    if (pts[i + 1] > pts[i]) out.push_back({pts[i], pts[i + 1], squeeze});
  }
}

// A point nu of a panel from u in [0, 1] (squeezed towards the end point where the panel says),
// with d nu / du; and the inverse.
double panel_point(const Panel& p, double u, double& dnu) {
  const double w = p.b - p.a;
  if (p.squeeze == 0) {
    dnu = w;
    return p.a + w * u;
  }
  if (p.squeeze == 2) {
    dnu = 0.5 * w * kPi * std::sin(kPi * u);
    return p.a + 0.5 * w * (1.0 - std::cos(kPi * u));
  }
  dnu = 2.0 * w * u;
  return p.squeeze < 0 ? p.a + w * u * u : p.b - w * u * u;
}

double panel_coordinate(const Panel& p, double nu) {
  const double w = p.b - p.a;
  if (p.squeeze == 0) return (nu - p.a) / w;
  return std::sqrt(std::clamp(p.squeeze < 0 ? (nu - p.a) / w : (p.b - nu) / w, 0.0, 1.0));
}

// What the panels of one t share: the profile, the centre of sliding eps = sigma / eta, eta, the
// ring tolerance, the ring rules, and for a table the knot tangencies `cuts` with the rules of
// table_panel_rule (a panel's own, its target, and a piece's between two cuts).
struct PanelContext {
  const ExactModel<double>& model;
  double eps, eta, tol;
  const RingRules& ring_rule;
  const GaussLegendreRule& panel;
  std::vector<double> cuts;
  GaussLegendreRule target, piece;
};

// The ring weights W(G) = integral G(nu) 2 s ring(s) ds (s = nu / eta) of the points of panel p
// under rule g, appended to out.
void panel_rule(const PanelContext& ctx, const Panel& p, const GaussLegendreRule& g,
                SlipSpeedMeasure& out) {
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    double dnu;
    const double x = panel_point(p, 0.5 * (1.0 + g.nodes[i]), dnu), s = x / ctx.eta;
    const SlipMoments ring = half_ring(ctx.model, s, ctx.eps, ctx.tol, ctx.ring_rule);
    const double w = 0.5 * g.weights[i] * dnu * 2.0 * s / ctx.eta;
    SlipMoments wk;
    for (int c = 0; c < 6; ++c) wk[c] = w * ring[c];
    out.nu.push_back(x);
    out.weight.push_back(wk);
  }
}

// Adds to the weights of the target's points (at u[j] of panel p, from `base` on in out) the
// points of `fine` moved onto them by Lagrange interpolation in u, in the first barycentric
// form: l_j(x) = prod_i (x - u_i) lambda_j / (x - u_j), lambda_j = 1 / prod_(i != j) (u_j - u_i).
void move_onto_target(const Panel& p, const std::vector<double>& u, const SlipSpeedMeasure& fine,
                      std::size_t base, SlipSpeedMeasure& out) {
  const std::size_t n = u.size();
  std::vector<double> lambda(n, 1.0), l(n);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t i = 0; i < n; ++i)
      if (i != j) lambda[j] /= u[j] - u[i];
  for (std::size_t k = 0; k < fine.nu.size(); ++k) {
    const double x = panel_coordinate(p, fine.nu[k]);
    double all = 1.0;
    std::size_t at = n;  // a node x equals
    for (std::size_t i = 0; i < n; ++i) {
      if (x == u[i]) at = i;
      all *= x - u[i];
    }
    for (std::size_t j = 0; j < n; ++j)
      l[j] = at < n ? (j == at ? 1.0 : 0.0) : all * lambda[j] / (x - u[j]);
    for (std::size_t j = 0; j < n; ++j)
      for (int c = 0; c < 6; ++c) out.weight[base + j][c] += l[j] * fine.weight[k][c];
  }
}

// A table's panel: its pieces between the knot tangencies in it (nu = eta |rho_k - eps| and
// eta (rho_k + eps), where m(s) is only C2) each get a short rule, and their points are moved
// onto the target, a rule of the panel, by Lagrange interpolation in its coordinate u (exact for
// G a polynomial in u of the target's degree: the panels are graded for G, the pieces for m; the
// target has twice the nodes of the panel's own rule, as interpolation has half the order of
// Gauss quadrature).
void table_panel_rule(const PanelContext& ctx, const Panel& p, SlipSpeedMeasure& out) {
  const std::vector<double>& cuts = ctx.cuts;
  auto lo = std::upper_bound(cuts.begin(), cuts.end(), p.a);
  auto hi = std::lower_bound(cuts.begin(), cuts.end(), p.b);
  if (lo == hi) return panel_rule(ctx, p, ctx.panel, out);
  SlipSpeedMeasure fine;
  double a = p.a;
  for (auto it = lo; it <= hi; ++it) {
    const double b = it == hi ? p.b : *it;
    if (b - a <= 1e-12 * (p.b - p.a)) continue;
    // m(s) is C2 with a (s - s_k)^(5/2) term at the tangencies: squeezed towards both ends.
    panel_rule(ctx, Panel{a, b, 2}, ctx.piece, fine);
    a = b;
  }
  const std::size_t n = ctx.target.nodes.size(), base = out.nu.size();
  std::vector<double> u(n);
  for (std::size_t j = 0; j < n; ++j) {
    double dnu;
    u[j] = 0.5 * (1.0 + ctx.target.nodes[j]);
    out.nu.push_back(panel_point(p, u[j], dnu));
    out.weight.push_back(SlipMoments{});
  }
  move_onto_target(p, u, fine, base, out);
}

}  // namespace

SlipSpeedMeasure slip_speed_measure(const ExactModel<double>& model, double t,
                                    const SlipSpeedMeasureOptions& o) {
  SlipSpeedMeasure out;
  const double sigma = 0.5 * (1.0 + t), eta = 0.5 * (1.0 - t);
  const double load = model.load_area / (model.radius * model.radius);
  if (!(eta > 0.0)) {  // pure sliding: u_hat = x everywhere, |vc| = |v|
    // A = integral p = L, alpha = d = integral p x^2 = L A^3 / (2 A^1); a = b = c = 0.
    const auto A = detail::representation_moments(model);
    const double second = kPi * value_of(A[1]);
    out.nu.push_back(1.0);
    out.weight.push_back({load, 0.0, 0.0, second, 0.0, second});
    return out;
  }
  const double eps = sigma / eta;
  const double layer = 1e-3 / o.largest_q;  // panels this narrow at the smallest slip speed
  // Structural points (nu = 0 or t, |t|, 1) with their grading, then the knot tangencies of a
  // table (nu = eta |rho_k - eps| and eta (rho_k + eps), where m(s) is only C2).
  std::vector<Panel> panels;
  if (t < 0.0) {  // centre inside: nu from 0; the ring touches the rim from inside at -t
    graded_panels(0.0, -t, layer, 1e-3 * (-t), panels);
    graded_panels(-t, 1.0, 1e-3 * (1.0 + t), 1e-3 * (1.0 + t), panels);
  } else {  // centre on or outside the rim: nu from t (the ring touches the rim from outside)
    graded_panels(t, 1.0, layer, 1e-3 * (1.0 - t), panels);
  }
  const GaussLegendreRule g = gauss_legendre(o.nodes);
  RingRules ring_rule;
  for (int n = 0; n <= o.ring_nodes; ++n)
    ring_rule.gauss.push_back(n < 1 ? GaussLegendreRule{} : gauss_legendre(n));
  ring_rule.fine = gauss_legendre(2 * o.ring_nodes + 4);
  ring_rule.coarse_max = o.ring_nodes;
  ring_rule.coarse_min = std::min(3, o.ring_nodes);
  // B^(-2n) = 1e-2 ring_tolerance (the default: about 1e-15): r = cosh(-ln(B^(-2n)) / (2 n))
  // (plain_piece_nodes).
  const double exponent = -0.5 * std::log(std::clamp(1e-2 * o.ring_tolerance, 1e-16, 1e-6));
  for (int n = 0; n <= o.ring_nodes; ++n)
    ring_rule.reach.push_back(n < 1 ? INFINITY : std::cosh(exponent / n));
  PanelContext ctx{model, eps, eta, o.ring_tolerance * load, ring_rule, g, {}, {}, {}};
  if (model.piece.empty()) {
    for (const Panel& p : panels) panel_rule(ctx, p, g, out);
    return out;
  }
  for (std::size_t k = 1; k + 1 < model.knot.size(); ++k) {
    const double rho = std::sqrt(model.knot[k]);
    ctx.cuts.push_back(eta * std::abs(rho - eps));
    ctx.cuts.push_back(eta * (rho + eps));
  }
  std::sort(ctx.cuts.begin(), ctx.cuts.end());
  ctx.piece = gauss_legendre(o.piece_nodes);
  ctx.target = gauss_legendre(2 * o.nodes);
  for (const Panel& p : panels) table_panel_rule(ctx, p, out);
  return out;
}

}  // namespace contensou
