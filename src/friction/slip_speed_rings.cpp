// The ring integrals of the slip-speed quadrature (slip_speed_rings.hpp).
#include "slip_speed_rings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "contensou/friction/adaptive_integration.hpp"
#include "lane_loops.hpp"

namespace contensou::detail {
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

}  // namespace

RingRules ring_rules(const SlipSpeedMeasureOptions& o) {
  RingRules r;
  for (int n = 0; n <= o.ring_nodes; ++n)
    r.gauss.push_back(n < 1 ? GaussLegendreRule{} : gauss_legendre(n));
  r.fine = gauss_legendre(2 * o.ring_nodes + 4);
  r.coarse_max = o.ring_nodes;
  r.coarse_min = std::min(3, o.ring_nodes);
  const double exponent = -0.5 * std::log(std::clamp(1e-2 * o.ring_tolerance, 1e-16, 1e-6));
  for (int n = 0; n <= o.ring_nodes; ++n)
    r.reach.push_back(n < 1 ? INFINITY : std::cosh(exponent / n));
  return r;
}

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

}  // namespace contensou::detail
