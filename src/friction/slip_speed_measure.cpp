// The slip-speed quadrature of a patch (slip_speed_measure.hpp).
#include "contensou/friction/slip_speed_measure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>
#include <utility>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/quadrature.hpp"
#include "lane_loops.hpp"

namespace contensou {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kRingCapacity = 640;

// The profile at n points t (with its Hertz edge).
void profile_at(const ExactModel<double>& m, const double* t, int n, double* p) {
  detail::profile_batch(m, t, n, m.chebyshev().size(), p);
  if (m.sqrt_edge())
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

// The rules of a table's ring pieces (half_rings_table): Gauss-Legendre of 1..coarse_max nodes
// (gauss[n] has n) for the pieces away from both ends of the ring's range, `fine` for the others.
struct RingRules {
  std::vector<GaussLegendreRule> gauss;
  std::vector<double> reach;  // piece_lanes
  GaussLegendreRule fine;
  int coarse_min = 3, coarse_max = 6;
};

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

// Rings of a table are integrated kLanes at a time, one ring a lane (half_rings_table), in
// lane loops (lane_loops.hpp; their square roots vectorise with -fno-math-errno).
using detail::kLanes;
using Lanes = double[kLanes];

// Up to kLanes rings of a table about the centre of sliding (0, eps) (half_rings_table): per
// lane its radius s, its range of t = |r|^2 from t_min = (s - eps)^2 to t_max = (s + eps)^2,
// the end of that range in the disk t_end = min(1, t_max), span = t_max - t_min = 2 D (D =
// 2 eps s), the root of the span, 1 / D, and the profile's value p_c at the middle of the range.
// The lanes past the last ring repeat it.
struct RingLanes {
  Lanes s, t_min, t_max, t_end, span, root_span, inv_d, p_c;
};

// One cubic piece of the table, [t_k, t_k+1] with p = c0 + c1 y + c2 y^2 + c3 y^3 (y = t - t_k),
// cut to each lane's range (half_rings_table): in the lane, [a, b] (of no width where the piece
// lies outside the ring's range), the variable v of its nodes from va over 2 dv (v = sqrt(t -
// t_min) on the lower half of the range, sqrt(t_max - t) on the upper: t - t_min = base + sign
// v^2), and the square roots of b from both ends of the range (those of a came from the piece
// before). `nodes` is the most any lane's piece needs (piece_lanes); `plain` is false when
// a lane's piece reaches near both ends of its range (then all take the fine rule in phi).
struct PieceLanes {
  Lanes a, b, va, dv, base, sign, root_a0, root_a1, root_b0, root_b1;
  double tk, c[4];
  int nodes;
  bool plain;
};

// The lanes of piece k (PieceLanes), from the roots of its start (root_a0 = sqrt(a - t_min),
// root_a1 = sqrt(t_max - a), set by the piece before). The nodes of a lane's piece: far from
// the far end of the range (at v = root_span, where the integrand in v has its square-root
// singularity), Gauss-Legendre of n nodes errs by about B^(-2n), B = r + sqrt(r^2 - 1), r the
// distance of the singularity (or of v = 0) from the piece's middle in half widths: n is the
// least with rules.reach[n] <= r (rules.reach[n]: B^(-2n) below about 1e-2 of the ring tolerance).
CONTENSOU_LANE_INLINE void piece_lanes(const ExactModel<double>& m, std::size_t k,
                                       const RingLanes& r, const RingRules& rules, PieceLanes& q) {
  const double lo = m.table()->knot[k], hi = m.table()->knot[k + 1];
  Lanes gap, far;
  for (int l = 0; l < kLanes; ++l) {
    const double a = std::min(std::max(lo, r.t_min[l]), r.t_end[l]);
    const double b = std::min(std::max(hi, r.t_min[l]), r.t_end[l]);
    const double b0 = std::sqrt(b - r.t_min[l]), b1 = std::sqrt(std::max(0.0, r.t_max[l] - b));
    const bool lower = (a - r.t_min[l]) <= (r.t_max[l] - b);
    const double va = lower ? q.root_a0[l] : b1, vb = lower ? b0 : q.root_a1[l];
    const double mid = 0.5 * (va + vb);
    far[l] = (lower ? r.t_max[l] - b : a - r.t_min[l]) - 4.0 * (b - a);
    gap[l] = std::min(r.root_span[l] - mid, mid);
    q.a[l] = a;
    q.b[l] = b;
    q.va[l] = va;
    q.dv[l] = 0.5 * (vb - va);
    q.base[l] = lower ? 0.0 : r.span[l];
    q.sign[l] = lower ? 1.0 : -1.0;
    q.root_b0[l] = b0;
    q.root_b1[l] = b1;
  }
  Lanes need;
  for (int l = 0; l < kLanes; ++l) need[l] = rules.coarse_min;
  for (int j = rules.coarse_min; j < rules.coarse_max; ++j)
    for (int l = 0; l < kLanes; ++l) need[l] += gap[l] < rules.reach[j] * q.dv[l] ? 1.0 : 0.0;
  double most = 0.0, nearest = INFINITY;
  for (int l = 0; l < kLanes; ++l) {
    most = std::max(most, need[l]);
    nearest = std::min(nearest, far[l]);
  }
  q.nodes = static_cast<int>(most);
  q.plain = !(nearest < 0.0);
  q.tk = lo;
  for (int j = 0; j < 4; ++j) q.c[j] = m.table()->piece[k][j];
}

// The sums S_l = sum f lambda^l (l = 0..3, lambda = (t - t_min) / D) of a piece's nodes under
// the n-point rule g, added to S: v = va + dv (1 + x_i), t - t_min = base + sign v^2, f = 2 dv
// w_i (p - p_c) / sqrt(span - v^2) (dt / sqrt((t - t_min)(t_max - t)) = 2 dv / sqrt(span - v^2),
// the near square root gone with the variable, the far one smooth on the piece).
CONTENSOU_LANE_INLINE void plain_lanes(const PieceLanes& q, const RingLanes& r,
                                       const GaussLegendreRule& g, double S[4][kLanes]) {
  const int n = static_cast<int>(g.nodes.size());
  for (int i = 0; i < n; ++i) {
    const double x = 1.0 + g.nodes[i], w = 2.0 * g.weights[i];
    for (int l = 0; l < kLanes; ++l) {
      const double v = q.va[l] + q.dv[l] * x, v2 = v * v;
      const double lo = q.base[l] + q.sign[l] * v2;
      const double far = r.span[l] - v2, root = std::sqrt(far > 0.0 ? far : 1.0);
      const double y = std::min(std::max(r.t_min[l] + lo, q.a[l]), q.b[l]) - q.tk;
      const double p = (q.c[0] - r.p_c[l]) + y * (q.c[1] + y * (q.c[2] + y * q.c[3]));
      const double f = (far > 0.0 ? w : 0.0) * q.dv[l] * p / root;  // 0 where far is 0
      const double lambda = lo * r.inv_d[l], f1 = f * lambda, f2 = f1 * lambda;
      S[0][l] += f;
      S[1][l] += f1;
      S[2][l] += f2;
      S[3][l] += f2 * lambda;
    }
  }
}

// The same sums for a piece near both ends of a lane's range, in the angle phi itself: t = t_min
// + span sin^2(phi / 2), dt / sqrt((t - t_min)(t_max - t)) = d phi, with the rule `fine`.
void fine_lanes(const PieceLanes& q, const RingLanes& r, const GaussLegendreRule& g,
                double S[4][kLanes]) {
  for (int l = 0; l < kLanes; ++l) {
    const double span = r.span[l], t_min = r.t_min[l];
    const double va = 2.0 * std::asin(std::sqrt(std::clamp((q.a[l] - t_min) / span, 0.0, 1.0)));
    const double vb = 2.0 * std::asin(std::sqrt(std::clamp((q.b[l] - t_min) / span, 0.0, 1.0)));
    const double dv = 0.5 * (vb - va);
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
      const double h = std::sin(0.5 * (va + dv * (1.0 + g.nodes[i])));
      const double lo = span * h * h;
      const double y = std::min(std::max(t_min + lo, q.a[l]), q.b[l]) - q.tk;
      const double f =
          dv * g.weights[i] * ((q.c[0] - r.p_c[l]) + y * (q.c[1] + y * (q.c[2] + y * q.c[3])));
      const double lambda = lo * r.inv_d[l], f1 = f * lambda, f2 = f1 * lambda;
      S[0][l] += f;
      S[1][l] += f1;
      S[2][l] += f2;
      S[3][l] += f2 * lambda;
    }
  }
}

// The sums S_l of half_rings_table over the pieces first..last of the table (each lane's own
// pieces among them; the others have no width in it).
CONTENSOU_LANE_CLONES void table_ring_sums(const ExactModel<double>& m, std::size_t first,
                                           std::size_t last, const RingLanes& r,
                                           const RingRules& rules, double S[4][kLanes]) {
  PieceLanes q;
  for (int l = 0; l < kLanes; ++l) {
    const double a = std::min(std::max(m.table()->knot[first], r.t_min[l]), r.t_end[l]);
    q.root_a0[l] = std::sqrt(a - r.t_min[l]);
    q.root_a1[l] = std::sqrt(std::max(0.0, r.t_max[l] - a));
  }
  for (std::size_t k = first; k <= last; ++k) {
    piece_lanes(m, k, r, rules, q);
    if (q.plain)
      plain_lanes(q, r, rules.gauss[q.nodes], S);
    else
      fine_lanes(q, r, rules.fine, S);
    for (int l = 0; l < kLanes; ++l) {
      q.root_a0[l] = q.root_b0[l];
      q.root_a1[l] = q.root_b1[l];
    }
  }
}

// The table's piece holding t (its first piece below knot[1], its last from the last knot but
// one), with `above` the piece k with knot[k] < t <= knot[k + 1] instead.
std::size_t piece_of(const ExactModel<double>& m, double t, bool above) {
  const std::vector<double>& knot = m.table()->knot;
  const auto it = above ? std::lower_bound(knot.begin(), knot.end(), t)
                        : std::upper_bound(knot.begin(), knot.end(), t);
  const auto pieces = static_cast<std::ptrdiff_t>(m.table()->piece.size());
  const std::ptrdiff_t k = std::clamp<std::ptrdiff_t>(it - knot.begin(), 1, pieces);
  return static_cast<std::size_t>(k - 1);
}

// Up to kLanes half rings of a table (radii s[ring[j]], j < count; ring_kind says kTable), each in
// the variable t = |r|^2 = C - D cos(phi) (C = s^2 + eps^2, D = 2 eps s), broken at the knots,
// where the profile is a cubic: d phi = dt / sqrt((t - t_min)(t_max - t)). The profile's value
// p_c at the middle of the range is integrated in closed form (constant_ring); the rule takes
// only the rest, p - p_c, which is O(eps s) on the ring: its error shrinks with the centre's
// distance from O (the functions are divided by sigma ~ eps near pure spin). Results to
// value[ring[j]].
void half_rings_table(const ExactModel<double>& m, double eps, const std::size_t* ring, int count,
                      const std::vector<double>& s, const RingRules& rules,
                      std::vector<SlipMoments>& value) {
  RingLanes r;
  double t_c[kLanes];
  std::size_t first = m.table()->piece.size(), last = 0;
  for (int l = 0; l < kLanes; ++l) {
    const double sl = s[ring[std::min(l, count - 1)]];
    r.s[l] = sl;
    r.t_min[l] = (sl - eps) * (sl - eps);
    r.t_max[l] = (sl + eps) * (sl + eps);
    r.t_end[l] = std::min(1.0, r.t_max[l]);
    r.span[l] = r.t_max[l] - r.t_min[l];
    r.root_span[l] = std::sqrt(r.span[l]);
    r.inv_d[l] = 1.0 / (2.0 * eps * sl);
    t_c[l] = std::min(sl * sl + eps * eps, 1.0);
    first = std::min(first, piece_of(m, r.t_min[l], false));
    last = std::max(last, piece_of(m, r.t_end[l], true));
  }
  profile_at(m, t_c, kLanes, r.p_c);
  double S[4][kLanes] = {};
  table_ring_sums(m, first, last, r, rules, S);
  for (int l = 0; l < count; ++l) {
    const double phi_end =
        r.t_end[l] == r.t_max[l]
            ? kPi
            : 2.0 * std::asin(std::sqrt(std::clamp((1.0 - r.t_min[l]) / r.span[l], 0.0, 1.0)));
    const double sums[4] = {S[0][l], S[1][l], S[2][l], S[3][l]};
    SlipMoments out = ring_moments(sums, eps, r.s[l]);
    const SlipMoments closed = constant_ring(r.p_c[l], r.s[l], eps, phi_end);
    for (int i = 0; i < 6; ++i) out[i] += closed[i];
    value[ring[l]] = out;
  }
}

// How a half ring of radius s about (0, eps) is integrated (half_ring): outside the disk (0), a
// ring about O, a table's ring that crosses a knot (half_rings_table), or adaptively.
enum class RingKind { kOutside, kAboutOrigin, kTable, kAdaptive };

RingKind ring_kind(const ExactModel<double>& m, double s, double eps) {
  const double dsq = (s - eps) * (s - eps), four_es = 4.0 * eps * s;
  if (!(dsq < 1.0)) return RingKind::kOutside;
  if (!(four_es > 0.0)) return RingKind::kAboutOrigin;
  if (m.table() && four_es > 1e-6) {
    const double t_end = std::min(1.0, (s + eps) * (s + eps));
    const auto it = std::upper_bound(m.table()->knot.begin(), m.table()->knot.end(), dsq);
    if (it != m.table()->knot.end() && *it < t_end) return RingKind::kTable;
  }
  return RingKind::kAdaptive;
}

// m_i(s) / (2 s) of a ring that is not a table's (ring_kind): the half-ring integral over phi =
// beta + pi/2 in [0, theta_w] of p(|r|^2) times the ring weights (add_ring_point), with |r|^2 =
// (s - eps)^2 + 4 eps s sin^2(phi/2) and y = (eps - s) + 2 s sin^2(phi/2) (no cancellation for
// a far centre).
SlipMoments half_ring(const ExactModel<double>& m, double s, double eps, double tol,
                      RingKind kind) {
  const double dsq = (s - eps) * (s - eps);
  SlipMoments out{};
  if (kind == RingKind::kOutside) return out;
  const double four_es = 4.0 * eps * s;
  if (kind == RingKind::kAboutOrigin) {  // |r| = s (only a and b survive)
    double t = s * s, p = 0.0;
    profile_at(m, &t, 1, &p);
    out[1] = p * s * 0.5 * kPi;
    out[2] = -p * s * 0.5 * kPi;
    return out;
  }
  // Arc end: |r|^2 = 1 at sin^2(theta_w / 2) = (1 - dsq) / (4 eps s).
  const double theta_w =
      four_es <= 1.0 - dsq ? kPi : 2.0 * std::asin(std::sqrt((1.0 - dsq) / four_es));
  const bool edge = m.sqrt_edge() && theta_w < kPi;  // sqrt(1 - |r|^2) at the arc end
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

// The half rings m_i(s) / (2 s) at radii s (value[j] for s[j]): a table's rings that cross a
// knot kLanes at a time in the order given (neighbours cross nearly the same knots), the others
// one by one (half_ring).
void half_rings(const ExactModel<double>& m, double eps, double tol, const RingRules& rules,
                const std::vector<double>& s, std::vector<SlipMoments>& value) {
  value.assign(s.size(), SlipMoments{});
  std::vector<std::size_t> table;
  for (std::size_t j = 0; j < s.size(); ++j) {
    const RingKind kind = ring_kind(m, s[j], eps);
    if (kind == RingKind::kTable)
      table.push_back(j);
    else
      value[j] = half_ring(m, s[j], eps, tol, kind);
  }
  for (std::size_t j = 0; j < table.size(); j += kLanes) {
    const int count = static_cast<int>(std::min<std::size_t>(kLanes, table.size() - j));
    half_rings_table(m, eps, table.data() + j, count, s, rules, value);
  }
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

// What the panels of one t share: the profile, the centre of sliding eps = sigma / eta, eta, and
// the panel's own rule; for a table the knot tangencies (table_panel_points): `onsets`, nu =
// eta |rho_k - eps| (and the structural points where the support of m begins: nu = 0 or t, and
// |t|), where the ring begins to cross the circle |r| = rho_k (the rim), so m is singular on
// their right only; `exits`, nu = eta (rho_k + eps) (and 1), where it stops, singular on their
// left only; `cuts`, both, sorted. `pieces`: Gauss-Legendre rules of 1..piece_nodes nodes
// (pieces[n] has n), `target` the rule a cut panel's points are moved onto, and `log_target`
// ln(1 / the error a piece's rule is chosen for) (piece_points).
struct PanelContext {
  const ExactModel<double>& model;
  double eps, eta;
  const GaussLegendreRule& panel;
  std::vector<double> onsets, exits, cuts;
  std::vector<GaussLegendreRule> pieces;
  GaussLegendreRule target;
  double log_target = 0.0;
};

// The points of a measure before their rings are known (slip_speed_measure): point j at nu[j]
// weighs w[j] times the half ring at s = nu[j] / eta. A group's points are the panel's own, or
// (target) points of its pieces to be moved onto its target rule (table_panel_points).
struct PendingMeasure {
  struct Group {
    Panel panel;
    std::size_t first, last;
    bool target;
  };
  std::vector<double> nu, w;
  std::vector<Group> groups;
};

// The points of panel p under rule g: W(G) = integral G(nu) 2 s ring(s) ds, s = nu / eta.
void panel_points(const PanelContext& ctx, const Panel& p, const GaussLegendreRule& g,
                  PendingMeasure& out) {
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    double dnu;
    const double x = panel_point(p, 0.5 * (1.0 + g.nodes[i]), dnu), s = x / ctx.eta;
    out.nu.push_back(x);
    out.w.push_back(0.5 * g.weights[i] * dnu * 2.0 * s / ctx.eta);
  }
}

// rho of the Bernstein ellipse (foci -1 and 1) through z: Gauss-Legendre of n nodes on [-1, 1]
// errs by about rho^(-2n) for an integrand analytic inside it.
double bernstein_rho(std::complex<double> z) {
  const std::complex<double> w = std::sqrt(z * z - 1.0);
  return std::max(std::abs(z + w), std::abs(z - w));
}

// How a piece's rule treats one of its ends (panel_point): plain, squeezed towards this end
// (nu - end = w u^2), or towards the other end.
enum class EndMap { kPlain, kHere, kThere };

// rho (bernstein_rho) of a piece's rule, in x = 2u - 1, for a singular point beyond one end at q
// piece widths from it: plain, x = -1 - 2q; squeezed here, nu - end = w u^2 = -q w gives
// u = i sqrt(q); squeezed there, (1 + q) w = w u^2.
double end_rho(double q, EndMap map) {
  if (!(q < 1e6)) return 1e6;  // none near
  if (map == EndMap::kHere) return bernstein_rho({-1.0, 2.0 * std::sqrt(q)});
  if (map == EndMap::kThere) return bernstein_rho({2.0 * std::sqrt(1.0 + q) - 1.0, 0.0});
  return bernstein_rho({-1.0 - 2.0 * q, 0.0});
}

// The nearest point of a sorted list below x (-inf if none) and above x (+inf).
double point_below(const std::vector<double>& v, double x) {
  const auto it = std::lower_bound(v.begin(), v.end(), x);
  return it == v.begin() ? -INFINITY : *(it - 1);
}
double point_above(const std::vector<double>& v, double x) {
  const auto it = std::upper_bound(v.begin(), v.end(), x);
  return it == v.end() ? INFINITY : *it;
}

// The points of the piece [a, b] of a table's panel p, between two knot tangencies (or the
// panel's ends). m(s) is analytic on the piece and C2 at its ends, with a (s - s_k)^(5/2) term on
// one side of each tangency only: right of an onset, left of an exit (PanelContext). The rule
// is squeezed towards an end where m is singular, or where the nearest point beyond it at which
// the piece's m is singular lies within a piece width: the onsets left of a, the exits right of
// b, and the panel's squeezed end (a square root of its coordinate). Squeezed towards both ends
// (the cosine map) it has piece_nodes nodes; otherwise the fewest (3 at least) for which
// rho^(-2n) is below exp(-log_target), rho (bernstein_rho) that of those nearest points and of
// G: the panel's own 10-node rule resolves G within its Bernstein ellipse rho = 5 (5^-20 =
// 1e-14), taken as points 2.2 panel half widths off the piece's middle.
void piece_points(const PanelContext& ctx, const Panel& p, double a, double b,
                  PendingMeasure& out) {
  // Points closer than tiny (a few ulp at least) are the same point.
  const double w = b - a, tiny = std::max(1e-12 * w, 1e-15 * b);
  auto near = [tiny](const std::vector<double>& v, double x) {
    const auto it = std::lower_bound(v.begin(), v.end(), x - tiny);
    return it != v.end() && *it <= x + tiny;
  };
  double dl = a - point_below(ctx.onsets, a - tiny), dr = point_above(ctx.exits, b + tiny) - b;
  if (p.squeeze == -1 && a > p.a) dl = std::min(dl, a - p.a);
  if (p.squeeze == 1 && b < p.b) dr = std::min(dr, p.b - b);
  const bool left = (a == p.a && p.squeeze == -1) || near(ctx.onsets, a) || dl < w;
  const bool right = (b == p.b && p.squeeze == 1) || near(ctx.exits, b) || dr < w;
  const int most = static_cast<int>(ctx.pieces.size()) - 1;
  if (left && right) return panel_points(ctx, Panel{a, b, 2}, ctx.pieces[most], out);
  const EndMap ml = left ? EndMap::kHere : (right ? EndMap::kThere : EndMap::kPlain);
  const EndMap mr = right ? EndMap::kHere : (left ? EndMap::kThere : EndMap::kPlain);
  const double rho = std::min(
      {end_rho(dl / w, ml), end_rho(dr / w, mr), bernstein_rho({0.0, 2.2 * (p.b - p.a) / w})});
  const double n = std::ceil(ctx.log_target / (2.0 * std::log(rho)));
  const int nodes = n > most ? most : std::max(std::min(3, most), static_cast<int>(n));
  panel_points(ctx, Panel{a, b, left ? -1 : (right ? 1 : 0)}, ctx.pieces[nodes], out);
}

// A table's panel: the pieces between the knot tangencies in it each get their rule
// (piece_points), and their points are moved onto the target, a rule of the panel, by Lagrange
// interpolation in its coordinate u (exact for G a polynomial in u of the target's degree: the
// panels are graded for G, the pieces for m; the target has twice the nodes of the panel's own
// rule, as interpolation has half the order of Gauss quadrature). A panel without tangencies
// takes its own rule.
void table_panel_points(const PanelContext& ctx, const Panel& p, PendingMeasure& out) {
  const std::vector<double>& cuts = ctx.cuts;
  const double tiny = std::max(1e-12 * (p.b - p.a), 1e-15 * p.b);
  const auto lo = std::upper_bound(cuts.begin(), cuts.end(), p.a + tiny);
  const auto hi = std::lower_bound(cuts.begin(), cuts.end(), p.b - tiny);
  const std::size_t first = out.nu.size();
  if (lo == hi) {
    panel_points(ctx, p, ctx.panel, out);
    out.groups.push_back({p, first, out.nu.size(), false});
    return;
  }
  double a = p.a;
  for (auto it = lo; it <= hi; ++it) {
    const double b = it == hi ? p.b : *it;
    if (b - a <= tiny) continue;
    piece_points(ctx, p, a, b, out);
    a = b;
  }
  out.groups.push_back({p, first, out.nu.size(), true});
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

// The measure from the pending points and their half rings: a group's own points as they are,
// a target group's moved onto the target rule of its panel (move_onto_target).
void assemble(const PanelContext& ctx, const PendingMeasure& pending,
              const std::vector<SlipMoments>& ring, SlipSpeedMeasure& out) {
  auto weight = [&](std::size_t k) {
    SlipMoments wk;
    for (int c = 0; c < 6; ++c) wk[c] = pending.w[k] * ring[k][c];
    return wk;
  };
  for (const PendingMeasure::Group& g : pending.groups) {
    if (!g.target) {
      for (std::size_t k = g.first; k < g.last; ++k) {
        out.nu.push_back(pending.nu[k]);
        out.weight.push_back(weight(k));
      }
      continue;
    }
    SlipSpeedMeasure fine;
    for (std::size_t k = g.first; k < g.last; ++k) {
      fine.nu.push_back(pending.nu[k]);
      fine.weight.push_back(weight(k));
    }
    const std::size_t n = ctx.target.nodes.size(), base = out.nu.size();
    std::vector<double> u(n);
    for (std::size_t j = 0; j < n; ++j) {
      double dnu;
      u[j] = 0.5 * (1.0 + ctx.target.nodes[j]);
      out.nu.push_back(panel_point(g.panel, u[j], dnu));
      out.weight.push_back(SlipMoments{});
    }
    move_onto_target(g.panel, u, fine, base, out);
  }
}

// The table's part of the context at t (PanelContext): the knot tangencies (onsets and exits)
// and the rules of the pieces; a piece's rule aims at 1e2 ring_tolerance relative to it.
void add_table_context(PanelContext& ctx, double t, const SlipSpeedMeasureOptions& o) {
  const ExactModel<double>& model = ctx.model;
  for (std::size_t k = 1; k + 1 < model.table()->knot.size(); ++k) {
    const double rho = std::sqrt(model.table()->knot[k]);
    ctx.onsets.push_back(ctx.eta * std::abs(rho - ctx.eps));
    ctx.exits.push_back(ctx.eta * (rho + ctx.eps));
  }
  ctx.cuts = ctx.onsets;
  ctx.cuts.insert(ctx.cuts.end(), ctx.exits.begin(), ctx.exits.end());
  std::sort(ctx.cuts.begin(), ctx.cuts.end());
  ctx.onsets.push_back(t < 0.0 ? 0.0 : t);  // where the support of m begins
  ctx.onsets.push_back(std::abs(t));        // the ring touches the rim from inside (t < 0)
  ctx.exits.push_back(1.0);                 // the ring leaves the disk
  std::sort(ctx.onsets.begin(), ctx.onsets.end());
  std::sort(ctx.exits.begin(), ctx.exits.end());
  for (int n = 0; n <= std::max(o.piece_nodes, 3); ++n)
    ctx.pieces.push_back(n < 1 ? GaussLegendreRule{} : gauss_legendre(n));
  ctx.target = gauss_legendre(2 * o.nodes);
  ctx.log_target = -std::log(std::clamp(1e2 * o.ring_tolerance, 1e-16, 1e-3));
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
  // Structural points (nu = 0 or t, |t|, 1) with their grading; for a table also its knot
  // tangencies (add_table_context).
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
  // (piece_lanes).
  const double exponent = -0.5 * std::log(std::clamp(1e-2 * o.ring_tolerance, 1e-16, 1e-6));
  for (int n = 0; n <= o.ring_nodes; ++n)
    ring_rule.reach.push_back(n < 1 ? INFINITY : std::cosh(exponent / n));
  PanelContext ctx{model, eps, eta, g, {}, {}, {}, {}, {}, 0.0};
  PendingMeasure pending;
  if (!model.table()) {
    for (const Panel& p : panels) panel_points(ctx, p, g, pending);
    pending.groups.push_back({Panel{0.0, 1.0, 0}, 0, pending.nu.size(), false});
  } else {
    add_table_context(ctx, t, o);
    for (const Panel& p : panels) table_panel_points(ctx, p, pending);
  }
  std::vector<double> s(pending.nu.size());
  for (std::size_t j = 0; j < s.size(); ++j) s[j] = pending.nu[j] / eta;
  std::vector<SlipMoments> ring;
  half_rings(model, eps, o.ring_tolerance * load, ring_rule, s, ring);
  assemble(ctx, pending, ring, out);
  return out;
}

}  // namespace contensou
