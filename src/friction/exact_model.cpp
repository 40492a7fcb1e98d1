// make_exact_model: a patch's profile as a Chebyshev series (fitted or exact) or a table's
// cubic pieces with their chord-integral terms (exact_model.hpp; theory.md §2).
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/profile_representation.hpp"
#include "contensou/friction/impl/table_pieces.hpp"

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
    double dev = 0.0;
    for (int i = 0; i <= 4000; ++i) {
      const double t = i / 4000.0;
      dev = std::max(dev, std::abs(q(t) - detail::chebyshev_sum(c, t)));
    }
    if (dev <= floor || n == 512) {
      fit.coefficients = std::move(c);
      fit.error = 2.0 * dev;  // the grid can miss the worst point by a little
      return fit;
    }
  }
  return fit;
}

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

// A table's cubic pieces in t = rho^2 as they are (exact for the interpolant), clipped at zero
// if asked, with their knot terms and far sums (impl/table_pieces.hpp): on [t_k, t_k+1], h =
// t_k+1 - t_k, del = (p_k+1 - p_k) / h, the Hermite cubic p_k + d_k s + (3 del - 2 d_k -
// d_k+1) s^2 / h + (d_k + d_k+1 - 2 del) s^3 / h^2, s = t - t_k.
TablePieces table_pieces(const TabulatedShape& tab, bool clip, double& error) {
  TablePieces m;
  if (tab.rho.front() > 0.0) {  // constant below the first knot
    m.knot.push_back(0.0);
    m.piece.push_back({tab.p.front(), 0.0, 0.0, 0.0});
  }
  for (std::size_t k = 0; k + 1 < tab.rho.size(); ++k) {
    const double ta = tab.rho[k] * tab.rho[k], tb = tab.rho[k + 1] * tab.rho[k + 1];
    const double h = tb - ta, del = (tab.p[k + 1] - tab.p[k]) / h;
    const double d0 = tab.slope[k], d1 = tab.slope[k + 1];
    m.knot.push_back(ta);
    m.piece.push_back(
        {tab.p[k], d0, (3.0 * del - 2.0 * d0 - d1) / h, (d0 + d1 - 2.0 * del) / (h * h)});
  }
  m.knot.push_back(1.0);
  if (clip) clip_pieces(m.knot, m.piece);
  // The far-knot series' deviation, as a bound on the chord integrals' error (in units of
  // the profile times the chord length, as a profile representation error is).
  detail::update_knot_terms(m);
  error = detail::update_far_sums(m);
  return m;
}

// The Hermite cubic on [ta, tb] through (ta, pa) and (tb, pb) with slopes da, db, at t: the
// form of every piece of a table (table_pieces).
double hermite(double ta, double tb, double pa, double pb, double da, double db, double t) {
  const double h = tb - ta, s = t - ta, del = (pb - pa) / h;
  return pa +
         s * (da + s * ((3.0 * del - 2.0 * da - db) / h + s * (da + db - 2.0 * del) / (h * h)));
}

// The largest deviation of the cubic over the table's knots i..j (its values and slopes at i
// and j) from the table's own pieces, at the knots between and the quarter points of each piece.
double gap_deviation(const TabulatedShape& tab, std::size_t i, std::size_t j) {
  const double ti = tab.rho[i] * tab.rho[i], tj = tab.rho[j] * tab.rho[j];
  double worst = 0.0;
  for (std::size_t k = i; k < j; ++k) {
    const double ta = tab.rho[k] * tab.rho[k], tb = tab.rho[k + 1] * tab.rho[k + 1];
    for (const double f : {0.0, 0.25, 0.5, 0.75}) {
      if (k == i && f == 0.0) continue;  // the gap's own end: equal by construction
      const double t = ta + f * (tb - ta);
      const double table =
          hermite(ta, tb, tab.p[k], tab.p[k + 1], tab.slope[k], tab.slope[k + 1], t);
      const double thin = hermite(ti, tj, tab.p[i], tab.p[j], tab.slope[i], tab.slope[j], t);
      worst = std::max(worst, std::abs(thin - table));
    }
  }
  return worst;
}

// A dense table (a finite-element or film profile of thousands of knots) thinned for the
// integrals, whose cost grows with the knots: the knots kept by bisection of the index range
// until the Hermite cubics through the kept knots (the table's own values and slopes there) stay
// within `tol` of the table's pieces (gap_deviation). `deviation` is the largest deviation left;
// the table itself (deviation 0) when thinning would not halve it.
TabulatedShape thinned_table(const TabulatedShape& tab, double tol, double& deviation) {
  const std::size_t n = tab.rho.size();
  std::vector<char> keep(n, 0);
  keep.front() = keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> gaps{{0, n - 1}};
  double worst = 0.0;
  while (!gaps.empty()) {
    const auto [i, j] = gaps.back();
    gaps.pop_back();
    if (j - i < 2) continue;
    const double e = gap_deviation(tab, i, j);
    if (e <= tol) {
      worst = std::max(worst, e);
      continue;
    }
    const std::size_t mid = i + (j - i) / 2;
    keep[mid] = 1;
    gaps.push_back({i, mid});
    gaps.push_back({mid, j});
  }
  TabulatedShape out;
  for (std::size_t k = 0; k < n; ++k)
    if (keep[k]) {
      out.rho.push_back(tab.rho[k]);
      out.p.push_back(tab.p[k]);
      out.slope.push_back(tab.slope[k]);
    }
  deviation = 0.0;
  if (2 * out.rho.size() > n) return tab;
  deviation = worst;
  return out;
}

}  // namespace

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
    m.set_series({1.0}, false, 0.0);
  } else if (std::holds_alternative<HertzShape>(prof.shape)) {
    m.set_series({1.0}, true, 0.0);
  } else if (const auto* cs = std::get_if<ChebyshevShape>(&prof.shape); cs && rho_max == 1.0) {
    m.set_series(cs->c, false, 0.0);  // already a series in t = rho^2: exact
  } else if (const auto* tab = std::get_if<TabulatedShape>(&prof.shape)) {
    // A table of more than kThinFromKnots knots is thinned when the caller allows a
    // representation error (from kThinTolerance up; the default keeps the table as it is), to
    // that tolerance relative to its largest value; its deviation, doubled as a margin for the
    // points between those checked, joins the representation error.
    constexpr std::size_t kThinFromKnots = 256;
    constexpr double kThinTolerance = 1e-12;
    double largest = 0.0, thinning = 0.0, error = 0.0;
    for (double v : tab->p) largest = std::max(largest, std::abs(v));
    const TabulatedShape used =
        tab->rho.size() > kThinFromKnots && representation_tolerance >= kThinTolerance
            ? thinned_table(*tab, 0.5 * representation_tolerance * largest, thinning)
            : *tab;
    TablePieces pieces = table_pieces(used, prof.clip_negative, error);
    m.set_table(std::move(pieces), error + 2.0 * thinning);
  } else {
    ChebyshevFit fit =
        fit_chebyshev([&](double t) { return shape_value(prof, rho_max * std::sqrt(t)); },
                      representation_tolerance);
    m.set_series(std::move(fit.coefficients), false, fit.error);
  }
  if (patch.slip_speed_friction) {
    m.slip_speed = patch.slip_speed_friction;
    m.friction_scale = std::max(patch.slip_speed_friction->static_coefficient,
                                patch.slip_speed_friction->kinetic_coefficient);
  } else {
    m.friction_scale = patch.friction;
  }
  if (m.friction_scale == 0.0) m.friction_scale = 1.0;  // frictionless: tolerance scale only
  m.load_area = 2.0 * std::numbers::pi * patch.radius_m * patch.radius_m * moment(prof, 1);
  if (!(m.load_area > 0.0))
    throw InvalidArgument("profile", describe(prof), "its load integral A^1 must be positive");
  return m;
}

}  // namespace contensou
