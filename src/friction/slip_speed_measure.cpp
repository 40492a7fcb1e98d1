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
#include "slip_speed_rings.hpp"

namespace contensou {

namespace {

constexpr double kPi = std::numbers::pi;

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
  const detail::RingRules ring_rule = detail::ring_rules(o);
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
  detail::half_rings(model, eps, o.ring_tolerance * load, ring_rule, s, ring);
  assemble(ctx, pending, ring, out);
  return out;
}

}  // namespace contensou
