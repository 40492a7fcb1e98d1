// Exact resultants of coupled sliding-spinning dry friction over a circular patch
// (theory.md section 2; seed eqs. 1-4), by adaptive cubature with an error estimate.
//
//   F  = integral_S tau dS,   Mz = integral_S (x tau_y - y tau_x) dS,
//   tau = -sigma(r) f(|vc|) diag(1, kappa) vc / |vc|,   vc = v + omega z x r
// (or the associated orthotropic law tau = -sigma f D^2 vc/|D vc|, D = diag(1, kappa), with
// ExactModel::associated_orthotropy; limit_surface.hpp).
//
// The integral is taken in polar coordinates (s, beta) about the instantaneous centre of
// sliding r_c = (-vy, vx)/omega, where vc/|vc| = sign(omega) z x e(beta) depends on beta alone.
// Rays at beta and beta + pi make one chord and u(beta + pi) = -u(beta), so
//   F = -p* sign(omega) integral dbeta D (z x e) integral_chord f sigma/p* (tau - tau_c) dtau
// (and the same with weights x, y for Mz), tau the position on the chord, tau_c that of r_c.
// With p a polynomial P in t = rho^2 (a Chebyshev fit to 1e-15, or exact), the chord integrals
// are closed forms through two precomputed transforms of P (update_chord_transforms); only a
// slip-speed-dependent f needs an adaptive inner rule. The outer integral over beta is adaptive
// Gauss-Kronrod (G15K31): centre inside (|v| < |omega| R): beta - gamma in [0, pi] with a
// breakpoint at the chord that nearly touches the rim as the centre nears it; centre outside:
// the wedge of chords, parametrised by the chord angle phi (sin theta = (R/d) sin phi), which
// removes the square root at the tangent rays. omega = 0 (pure sliding) is in closed form, with
// its first order in omega so that d/domega is right there too.
// Derivatives (ceres::Jet) are finite at every finite input: the result is smooth in v at v = 0
// for omega != 0 (no |r_c| is differentiated), and at v = omega = 0, where Coulomb friction is
// set-valued, the convention is zero resultants with zero derivatives (0 is in the set; the
// fractional law's regularisation gives the same value).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou {

// The integration-ready form of a ContactPatch. Build it once (make_exact_model), evaluate
// many times: exact_resultants does no heap allocation (but for a table whose kinks exhaust
// the stack store of its outer rule: integrate_table).
template <class T>
struct ExactModel;
template <class T>
void update_chord_transforms(ExactModel<T>& m);
template <class T = double>
struct ExactModel {
  double radius = 0.0;  // integration radius [m] (the positive part of a clipped profile)
  T pressure{};         // p* [Pa]
  T friction{};         // f (unused if slip_speed is set)
  T kappa{1.0};
  // Orthotropy (kappa != 1): false, the law of theory.md section 2, tau = -sigma f D vc/|vc|,
  // D = diag(1, kappa); true, the associated (maximum-dissipation) law on the same local
  // ellipse of tractions, tau = -sigma f D^2 vc/|D vc|, the gradient of sigma f |D vc| with
  // respect to vc (the limit surface's law, limit_surface.hpp). The same for kappa = 1.
  bool associated_orthotropy = false;
  T kx{0.0}, ky{0.0};  // shift relative to `radius`
  // p = [sqrt(1 - t) if sqrt_edge] * sum_k chebyshev[k] T_k(2 t - 1), t = (r / radius)^2.
  std::vector<T> chebyshev;
  bool sqrt_edge = false;
  std::optional<SlipSpeedFriction<T>> slip_speed;
  // A table (TabulatedShape) instead: p = sum_j piece[k][j] (t - knot[k])^j on
  // [knot[k], knot[k+1]], knot from 0 to 1, and the knot terms of the chord integrals
  // (knot_m0, knot_m2; update_knot_terms). Exact for the interpolant: no representation error
  // but that of the far pieces' series (update_far_sums).
  std::vector<double> knot;
  std::vector<std::array<double, 4>> piece;
  std::vector<std::array<double, 4>> knot_m0, knot_m2;
  std::vector<double> far_m0, far_m2;  // per knot interval: Chebyshev series of the far knots
  std::vector<unsigned char> near_integrated;  // per knot interval: near pieces integrated
  std::vector<std::size_t> far_from;           // per knot interval: its first far knot
  std::vector<T> chord_q0, chord_q2;           // chord transforms (update_chord_transforms)
  std::vector<double> chord_tail;              // sum_{j >= k} |q0_j| + |q2_j|: truncation bound
  double representation_error = 0.0;           // bound on |p - representation| (dimensionless)
  double load_area = 0.0;                      // N / p* = 2 pi R^2 A^1 [m^2]
  double friction_scale = 0.0;                 // f, or max(f_s, f_k)
};

// Builds the model: Chebyshev fit of p in t = rho^2 to representation_tolerance relative to
// the profile (exact for uniform and Hertz; a smooth profile such as the cosine series reaches
// 1e-15 with ~24 terms, a tabulated C1 cubic needs many more: loosen the tolerance for speed,
// the representation error enters every error estimate), shrinking the disk to the positive
// part if a clipped profile is negative only near the rim. Validates the patch (throws
// InvalidArgument).
ExactModel<double> make_exact_model(const ContactPatch& patch,
                                    double representation_tolerance = 1e-15);

// Casts a model to another scalar (e.g. ceres::Jet) with zero derivatives.
template <class T>
ExactModel<T> promote(const ExactModel<double>& m) {
  ExactModel<T> out;
  out.radius = m.radius;
  out.pressure = T(m.pressure);
  out.friction = T(m.friction);
  out.kappa = T(m.kappa);
  out.associated_orthotropy = m.associated_orthotropy;
  out.kx = T(m.kx);
  out.ky = T(m.ky);
  out.chebyshev.reserve(m.chebyshev.size());
  for (double c : m.chebyshev) out.chebyshev.push_back(T(c));
  out.sqrt_edge = m.sqrt_edge;
  if (m.slip_speed) {
    const auto& s = *m.slip_speed;
    out.slip_speed = SlipSpeedFriction<T>{T(s.static_coefficient), T(s.kinetic_coefficient),
                                          T(s.reference_speed), T(s.exponent)};
  }
  out.knot = m.knot;
  out.piece = m.piece;
  out.knot_m0 = m.knot_m0;
  out.knot_m2 = m.knot_m2;
  out.far_m0 = m.far_m0;
  out.far_m2 = m.far_m2;
  out.far_from = m.far_from;
  out.near_integrated = m.near_integrated;
  for (double c : m.chord_q0) out.chord_q0.push_back(T(c));
  for (double c : m.chord_q2) out.chord_q2.push_back(T(c));
  out.chord_tail = m.chord_tail;
  out.representation_error = m.representation_error;
  out.load_area = m.load_area;
  out.friction_scale = m.friction_scale;
  return out;
}

struct ExactOptions {
  // Requested accuracy, relative to f N for the forces and f N R for the torque.
  double tolerance = 1e-10;
};

// The estimated absolute errors of the exact resultants: one per component, not one number.
// max() is the largest of the three, for the common question "is it small?"; it compares N
// with N m as plain numbers (the torque's error scales with R), so to weigh them use the
// components, or ExactResult::converged (each against its own scale, f N or f N R).
struct ResultantErrors {
  double Fx = 0.0;  // [N]
  double Fy = 0.0;  // [N]
  double Mz = 0.0;  // [N m]

  double max() const { return std::max({Fx, Fy, Mz}); }
};

template <class T = double>
struct ExactResult {
  Resultants<T> resultants;
  ResultantErrors error;  // estimated absolute error of each component [N, N, N m]
  int evaluations = 0;    // rays evaluated (outer integrand evaluations)
  // true only if every component of `error` meets the requested tolerance (tol f N, tol f N R;
  // representation error and floor included); false if the estimate exceeds it (the interval
  // budget ran out, or the profile's representation alone is coarser than the tolerance).
  bool converged = true;
};

namespace detail {

// Clenshaw sum of a Chebyshev series in z = 2 t - 1 (its first `terms` terms; 0: all).
template <class T, class S>
T chebyshev_sum(const std::vector<T>& c, const S& t, std::size_t terms = 0) {
  const S z = 2.0 * t - 1.0;
  T b1(0.0), b2(0.0);
  const std::size_t n = terms == 0 ? c.size() : std::min(terms, c.size());
  for (std::size_t k = n - 1; k >= 1; --k) {
    const T b0 = c[k] + 2.0 * z * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return c[0] + z * b1 - b2;
}

// df/dw of the slip-speed law at w > 0: -(f_s - f_k) delta (w/w_s)^delta exp(-(w/w_s)^delta) / w.
template <class T>
T friction_slope_at(const SlipSpeedFriction<T>& law, const T& w) {
  using std::exp;
  using std::pow;
  const T z = pow(w / law.reference_speed, law.exponent);
  return -(law.static_coefficient - law.kinetic_coefficient) * law.exponent * z * exp(-z) / w;
}

// A chord of the disk through the centre of sliding: points r = foot + tau e, tau in
// [-h, h], the centre of sliding at tau_c. foot is the point of the chord nearest to O.
template <class T>
struct Chord {
  T fx, fy;  // foot
  T ex, ey;  // unit direction
  T h;       // half-length [m]
  T tau_c;   // position of r_c on the chord [m]
  T t_foot;  // |foot|^2 / R^2
};

}  // namespace detail

// Recomputes the chord transforms Q0, Q2 of the model's profile polynomial:
//   integral_{-h}^{h} p(t_f + w^2) {1, w^2} dw = {h^(1+e) Q0(t_f), h^(3+e) Q2(t_f)},
// h = (1 - t_f)^(1/2), e = 1 with a Hertz edge (p = sqrt(1 - t) P(t)), else 0. Q0 and Q2 are
// polynomials of the same degree as P; they are stored as Chebyshev series in t_f. Call after
// changing `chebyshev` (make_exact_model does).
template <class T>
void update_chord_transforms(ExactModel<T>& m) {
  const std::size_t deg = m.chebyshev.size() - 1, n = deg + 1;
  // Rule in u on [-1, 1] exact for degree 2 deg + 2: Gauss-Legendre, or Gauss-Chebyshev of
  // the second kind (weight sqrt(1 - u^2)) for a Hertz edge.
  std::vector<double> un, uw;
  const std::size_t nq = deg + 2;
  if (m.sqrt_edge) {
    for (std::size_t i = 1; i <= nq; ++i) {
      const double a = std::numbers::pi * static_cast<double>(i) / static_cast<double>(nq + 1);
      un.push_back(std::cos(a));
      uw.push_back(std::numbers::pi / static_cast<double>(nq + 1) * std::sin(a) * std::sin(a));
    }
  } else {
    const GaussLegendreRule g = gauss_legendre(static_cast<int>(nq));
    un = g.nodes;
    uw = g.weights;
  }
  std::vector<T> q0(n, T(0.0)), q2(n, T(0.0));
  for (std::size_t j = 0; j < n; ++j) {
    // Chebyshev points in t_f and the transforms there (h^2 = 1 - t_f).
    const double zj =
        std::cos(std::numbers::pi * (static_cast<double>(j) + 0.5) / static_cast<double>(n));
    const double tf = 0.5 * (1.0 + zj), h2 = 1.0 - tf;
    T s0(0.0), s2(0.0);
    for (std::size_t i = 0; i < un.size(); ++i) {
      const T p = detail::chebyshev_sum(m.chebyshev, tf + h2 * un[i] * un[i]);
      s0 += uw[i] * p;
      s2 += (uw[i] * un[i] * un[i]) * p;
    }
    for (std::size_t k = 0; k < n; ++k) {
      const double ck = (k == 0 ? 1.0 : 2.0) / static_cast<double>(n) *
                        std::cos(std::numbers::pi * static_cast<double>(k) *
                                 (static_cast<double>(j) + 0.5) / static_cast<double>(n));
      q0[k] += ck * s0;
      q2[k] += ck * s2;
    }
  }
  m.chord_tail.assign(n + 1, 0.0);
  for (std::size_t k = n; k-- > 0;)
    m.chord_tail[k] = m.chord_tail[k + 1] + std::abs(value_of(q0[k])) + std::abs(value_of(q2[k]));
  m.chord_q0 = std::move(q0);
  m.chord_q2 = std::move(q2);
}

namespace detail {

// The knot terms of a piecewise profile's chord integrals (theory.md section 2):
//   M0(t_f) = integral_{-h}^{h} p(t_f + w^2) dw = integral_{t_f}^1 p(t) (t - t_f)^(-1/2) dt,
//   M2(t_f) = integral_{-h}^{h} p(t_f + w^2) w^2 dw = integral_{t_f}^1 p(t) (t - t_f)^(1/2) dt.
// With a piece written about a point t*, p = sum_j c_j (t - t*)^j, the antiderivative from
// t_f takes at t* the value (t* - t_f)^(1/2) sum_j kappa_j c_j (t* - t_f)^j, kappa_j =
// sum_i C(j, i) (-1)^(j-i) / (i + 1/2) (and (t* - t_f)^(3/2) sum_j lambda_j c_j (t* - t_f)^j,
// lambda_j with i + 3/2, for M2). Each knot above t_f then adds, with delta = knot - t_f,
//   M0 += delta^(1/2) sum_j knot_m0[k][j] delta^j,  M2 += delta^(3/2) sum_j knot_m2[k][j] delta^j,
// knot_m[k][j] = kappa_j (c_j of the piece below, about the knot - c_j of the piece above):
// within a knot no term is differenced against another of its size, and a C1 table leaves only
// j = 2, 3. Across knots they cancel: a piece's integral, ~ |c_3| h^4 delta^(-1/2), is the
// difference of two knot terms ~ |c_3| delta^(7/2); so they serve only the near knots, and only
// where no near piece is narrower than 1/8 of the distance (update_far_sums); elsewhere the
// pieces are integrated (cubic_moments).
inline void update_knot_terms(std::vector<double> const& knot,
                              std::vector<std::array<double, 4>> const& piece,
                              std::vector<std::array<double, 4>>& m0,
                              std::vector<std::array<double, 4>>& m2) {
  std::array<double, 4> kappa{}, lambda{};
  for (int j = 0; j < 4; ++j) {
    double binom = 1.0;
    for (int i = j; i >= 0; --i) {  // C(j, i) for i = j, j-1, ...
      const double sign = (j - i) % 2 ? -1.0 : 1.0;
      kappa[j] += sign * binom / (i + 0.5);
      lambda[j] += sign * binom / (i + 1.5);
      binom = binom * i / (j - i + 1);
    }
  }
  const std::size_t n = piece.size();
  m0.assign(n + 1, {0.0, 0.0, 0.0, 0.0});
  m2.assign(n + 1, {0.0, 0.0, 0.0, 0.0});
  for (std::size_t k = 1; k <= n; ++k) {
    // The piece below, re-expanded about its upper end knot[k]: c_j(up) = sum_i C(i, j) h^(i-j)
    // c_i.
    const std::array<double, 4>& c = piece[k - 1];
    const double h = knot[k] - knot[k - 1];
    const std::array<double, 4> up = {c[0] + h * (c[1] + h * (c[2] + h * c[3])),
                                      c[1] + h * (2.0 * c[2] + 3.0 * h * c[3]),
                                      c[2] + 3.0 * h * c[3], c[3]};
    for (int j = 0; j < 4; ++j) {
      const double diff = up[j] - (k < n ? piece[k][j] : 0.0);
      m0[k][j] = kappa[j] * diff;
      m2[k][j] = lambda[j] * diff;
    }
  }
}

// Knot crossings of a table's outer integral: at first at most kMaxCrossings break points per
// half range (a finer table gets every m-th knot as a break point; adaptivity, splitting at
// crossings, does the rest) and kPiecewiseCapacity intervals, on the stack; if that runs out
// (constant f), every crossing and kCrossingCapacity intervals per crossing, on the heap.
inline constexpr std::size_t kMaxCrossings = 256;
inline constexpr int kPiecewiseCapacity = 640;
inline constexpr int kCrossingCapacity = 4;

// The number of interior knots with t_k < s_max^2: those a chord's foot crosses.
inline std::size_t knots_inside(const std::vector<double>& knot, double s_max) {
  if (!(s_max > 0.0) || knot.size() < 3) return 0;
  return static_cast<std::size_t>(
      std::lower_bound(knot.begin() + 1, knot.end() - 1, s_max * s_max) - (knot.begin() + 1));
}

// The outer intervals of a table, broken where a chord's foot crosses a knot, at x = asin(
// sqrt(t_k) / s_max) on [0, pi/2] for every stride-th knot inside (at most max_breaks), then
// mirrored to [pi/2, pi] (mirror = pi: x -> pi - x) or to [-pi/2, 0] (mirror = 0: x -> -x).
// out has room for 2 (min(max_breaks, knots_inside) + 1) intervals. Returns their number.
inline int crossing_intervals(const std::vector<double>& knot, double s_max, std::size_t max_breaks,
                              double mirror, TaggedInterval* out) {
  const std::size_t inside = max_breaks > 0 ? knots_inside(knot, s_max) : 0;
  const std::size_t stride =
      std::max<std::size_t>(1, (inside + max_breaks - 1) / std::max<std::size_t>(max_breaks, 1));
  const double half_pi = 0.5 * std::numbers::pi;
  int nb = 0;
  double prev = 0.0;
  std::size_t count = 0;
  for (std::size_t k = 1; k <= inside && count < max_breaks; k += stride, ++count) {
    const double x = std::asin(std::min(1.0, std::sqrt(knot[k]) / s_max));
    if (x > prev) out[nb++] = {prev, x, 0};
    prev = x;
  }
  if (half_pi > prev) out[nb++] = {prev, half_pi, 0};
  for (int j = nb - 1; j >= 0; --j) {
    const double a = mirror == 0.0 ? -out[j].b : mirror - out[j].b;
    const double b = mirror == 0.0 ? -out[j].a : mirror - out[j].a;
    out[nb + (nb - 1 - j)] = {a, b, 0};
  }
  return 2 * nb;
}

// Bisection of a table's outer interval at the knot crossing nearest its midpoint, so that
// kinks become interval ends (between crossings the integrand is analytic); at the midpoint if
// no crossing lies inside, away from the ends. Crossings: s_max^2 sin^2 x = t_k on [0, pi/2],
// mirrored as in crossing_intervals.
struct KnotCrossingSplit {
  const std::vector<double>* knot;
  double s_max;
  double mirror;
  double operator()(double a, double b) const {
    const double mid = 0.5 * (a + b), half_pi = 0.5 * std::numbers::pi;
    const bool flip = mirror == 0.0 ? b <= 0.0 : a >= half_pi;
    const double lo = flip ? (mirror == 0.0 ? -b : mirror - b) : a;
    const double hi = flip ? (mirror == 0.0 ? -a : mirror - a) : b;
    if (!(lo >= 0.0 && hi <= half_pi)) return mid;
    const double xm = 0.5 * (lo + hi), sm = s_max * std::sin(xm), margin = 0.05 * (hi - lo);
    const std::vector<double>& k = *knot;
    const std::size_t up = std::upper_bound(k.begin(), k.end(), sm * sm) - k.begin();
    double best = xm, gap = 2.0 * half_pi;
    for (std::size_t j : {up - 1, up}) {
      if (j < 1 || j + 1 >= k.size()) continue;  // interior knots only
      const double x = std::asin(std::min(1.0, std::sqrt(k[j]) / s_max));
      if (x > lo + margin && x < hi - margin && std::abs(x - xm) < gap) {
        gap = std::abs(x - xm);
        best = x;
      }
    }
    return flip ? (mirror == 0.0 ? -best : mirror - best) : best;
  }
};

// Chebyshev terms of the far pieces' series on each knot interval (update_far_sums).
inline constexpr int kFarTerms = 18;

// The chord integrals of a piecewise profile (theory.md section 2):
//   M0(t_f) = integral_{-h}^{h} p(t_f + w^2) dw = integral_{t_f}^1 p(t) (t - t_f)^(-1/2) dt,
//   M2(t_f) = integral_{-h}^{h} p(t_f + w^2) w^2 dw = integral_{t_f}^1 p(t) (t - t_f)^(1/2) dt.
// Over a piece [lo, hi] of the cubic q = sum_j c_j (t - t0)^j (t_f <= lo), with t = t_f + w^2,
// they are integral 2 q dw and integral 2 q w^2 dw, polynomials of degree 6 and 8 in w: 5-point
// Gauss-Legendre in w is exact, s = t - t0 = (lo - t0) + (w - w_lo)(w + w_lo); from_foot: lo =
// t_f (w_lo = 0, so no square root of 0 is differentiated). Every node's term is bounded by
// the cubic's values on the piece: no cancellation (the antiderivatives at the knots, of size
// |c_3| (t_k - t_f)^(7/2), cancelled to 1e-7 of the profile on a 10,001-point table).
// The same from w_lo = (lo - t_f)^(1/2), w_hi = (hi - t_f)^(1/2) and base = (lo or t_f) - t0,
// for callers that form those differences themselves (update_far_sums).
template <class T>
void cubic_moments_between(const std::array<double, 4>& c, const T& wl, const T& wh, const T& base,
                           T& M0, T& M2) {
  constexpr double x[5] = {-0.90617984593866399280, -0.53846931010568309104, 0.0,
                           0.53846931010568309104, 0.90617984593866399280};
  constexpr double wt[5] = {0.23692688505618908751, 0.47862867049936646804, 0.56888888888888888889,
                            0.47862867049936646804, 0.23692688505618908751};
  const T mid = 0.5 * (wl + wh), half = 0.5 * (wh - wl);
  M0 = T(0.0);
  M2 = T(0.0);
  for (int i = 0; i < 5; ++i) {
    const T w = mid + half * x[i];
    const T s = base + (w - wl) * (w + wl);
    const T q = 2.0 * wt[i] * half * (c[0] + s * (c[1] + s * (c[2] + s * c[3])));
    M0 += q;
    M2 += q * w * w;
  }
}

template <class T>
void cubic_moments(const std::array<double, 4>& c, double t0, double lo, double hi, const T& t_f,
                   bool from_foot, T& M0, T& M2) {
  using std::sqrt;
  const T wl = from_foot ? T(0.0) : T(sqrt(lo - t_f)), wh = sqrt(hi - t_f);
  const T base = from_foot ? T(t_f - t0) : T(lo - t0);
  cubic_moments_between(c, wl, wh, base, M0, M2);
}

// On the knot interval [knot[k], knot[k+1]] the pieces from the first knot at least one
// interval width beyond its upper end (knot far_from[k], at most kMaxNear knots on) are far:
// their integrals are smooth there (the nearest singularity lies a width away, so a Chebyshev
// series converges like 5.8^-n) and stored as a series of kFarTerms terms. The near ones are
// summed at each call: as knot terms (one or two on an even table), or, where a near piece is
// narrower than 1/8 of the distance from the interval (uneven knots: the knot terms would
// cancel), integrated (cubic_moments; near_integrated[k] = 1). With knot terms the series also
// holds the antiderivative of the piece below knot far_from[k] (which they leave out), so that
// its (knot - t_f)^(1/2) singularity cancels. A chord thus costs a few knot terms or pieces and
// two short series, whatever the number of knots. The series are fitted top-down on a binary
// tree of the pieces (exact_resultants.cpp): a node's (or interval's) far sums are its
// parent's series plus the few pieces between the two, summed from the pieces' moments, so
// that every fit sums a bounded number of terms: O(n) in the number of knots (0.3 s for 10^4
// knots, 3 s for 10^5). Returns the largest deviation of the series from those sums at test
// points (M0 and M2), the deviations of its ancestors' series added.
inline constexpr std::size_t kMaxNear = 512;
double update_far_sums(const std::vector<double>& knot,
                       const std::vector<std::array<double, 4>>& piece, std::vector<double>& far0,
                       std::vector<double>& far2, std::vector<std::size_t>& far_from,
                       std::vector<unsigned char>& near_integrated);

// M0 and M2 of a piecewise profile at t_f: the near knot terms or pieces above t_f, the far
// pieces from the series of t_f's interval.
template <class T>
void piecewise_chord_moments(const ExactModel<T>& m, const T& t_f, T& M0, T& M2) {
  using std::sqrt;
  const std::vector<double>& knot = m.knot;
  const double tv = value_of(t_f);
  M0 = T(0.0);
  M2 = T(0.0);
  if (!(tv < 1.0)) return;
  const std::size_t n = knot.size() - 1;
  std::size_t k = std::upper_bound(knot.begin(), knot.end(), tv) - knot.begin();
  k = std::min(std::max<std::size_t>(k, 1), n) - 1;  // t_f in [knot[k], knot[k+1])
  if (m.near_integrated[k]) {
    for (std::size_t j = k; j < std::min(m.far_from[k], n); ++j) {
      T a0, a2;
      cubic_moments(m.piece[j], knot[j], knot[j], knot[j + 1], t_f, j == k, a0, a2);
      M0 += a0;
      M2 += a2;
    }
  } else {
    for (std::size_t j = k + 1; j < m.far_from[k]; ++j) {
      const T d = knot[j] - t_f;
      const T r = sqrt(d);
      const auto& a = m.knot_m0[j];
      const auto& b = m.knot_m2[j];
      M0 += r * (a[0] + d * (a[1] + d * (a[2] + d * a[3])));
      M2 += r * d * (b[0] + d * (b[1] + d * (b[2] + d * b[3])));
    }
  }
  const double lo = knot[k], hi = knot[k + 1];
  const T z = (2.0 * t_f - lo - hi) / (hi - lo);
  const double* c0 = m.far_m0.data() + k * kFarTerms;
  const double* c2 = m.far_m2.data() + k * kFarTerms;
  T p1(0.0), p2(0.0), q1(0.0), q2(0.0);
  for (int i = kFarTerms - 1; i >= 1; --i) {
    const T p0 = c0[i] + 2.0 * z * p1 - p2;
    const T q0 = c2[i] + 2.0 * z * q1 - q2;
    p2 = p1;
    p1 = p0;
    q2 = q1;
    q1 = q0;
  }
  M0 += c0[0] + z * p1 - p2;
  M2 += c2[0] + z * q1 - q2;
}

// The profile of a model at t = rho^2 (Chebyshev series, its first `terms` terms if given; or
// piecewise).
template <class T, class S>
T profile_at(const ExactModel<T>& m, const S& t, std::size_t terms = 0) {
  if (m.piece.empty()) return chebyshev_sum(m.chebyshev, t, terms);
  const double tv = std::clamp(value_of(t), 0.0, 1.0);
  std::size_t k = std::upper_bound(m.knot.begin(), m.knot.end(), tv) - m.knot.begin();
  k = std::min(std::max<std::size_t>(k, 1), m.piece.size()) - 1;
  const auto& c = m.piece[k];
  const S s = t - m.knot[k];
  return T(c[0] + s * (c[1] + s * (c[2] + s * c[3])));
}

// The chord's moments {integral sigma (tau - tau_c) {1, x, y} dtau} / p* from
// M0 = integral p dw and M2 = integral p w^2 dw over the chord (w = tau / R):
//   sigma (tau - tau_c) = R p (A + B w)(w - w_c), x = fx + R ex w.
template <class T>
void chord_moments_from(const ExactModel<T>& m, const Chord<T>& ch, const T& M0, const T& M2,
                        std::array<T, 3>& I) {
  const double R = m.radius, R2 = R * R;
  const T wc = ch.tau_c / R;
  const T A = 1.0 + (m.kx * ch.fx + m.ky * ch.fy) / R;  // shift factor at the foot
  const T B = m.kx * ch.ex + m.ky * ch.ey;              // its slope per unit w
  const T odd = A - B * wc;                             // coefficient of w in (A + B w)(w - w_c)
  I = {R2 * (B * M2 - A * wc * M0), R2 * ((odd * R * ch.ex + B * ch.fx) * M2 - A * wc * ch.fx * M0),
       R2 * ((odd * R * ch.ey + B * ch.fy) * M2 - A * wc * ch.fy * M0)};
}

// Closed-form moments of n <= 21 chords at once (no slip-speed law): the Clenshaw sums of
// the two chord transforms run across the chords, independent chains that vectorise.
//   sigma (tau - tau_c) = R p (A + B w)(w - w_c), x = fx + R ex w, w = tau / R.
// Only the first `terms` coefficients of the transforms are summed.
template <class T>
void chord_moments_closed_form(const ExactModel<T>& m, std::size_t terms, const Chord<T>* c, int n,
                               std::array<T, 3>* I) {
  constexpr int kMax = kKronrodPoints;
  const double R = m.radius;
  if (!m.piece.empty()) {
    for (int i = 0; i < n; ++i) {
      T M0, M2;
      piecewise_chord_moments(m, c[i].t_foot, M0, M2);
      chord_moments_from(m, c[i], M0, M2, I[i]);
    }
    return;
  }
  std::array<T, kMax> z, a1, a2, b1, b2;
  for (int i = 0; i < n; ++i) {
    z[i] = 2.0 * c[i].t_foot - 1.0;
    a1[i] = a2[i] = b1[i] = b2[i] = T(0.0);
  }
  const T* q0 = m.chord_q0.data();
  const T* q2 = m.chord_q2.data();
  for (std::size_t k = terms - 1; k >= 1; --k) {
    for (int i = 0; i < n; ++i) {
      const T a0 = q0[k] + 2.0 * z[i] * a1[i] - a2[i];
      const T b0 = q2[k] + 2.0 * z[i] * b1[i] - b2[i];
      a2[i] = a1[i];
      a1[i] = a0;
      b2[i] = b1[i];
      b1[i] = b0;
    }
  }
  for (int i = 0; i < n; ++i) {
    const Chord<T>& ch = c[i];
    const T hp = ch.h / R;
    T M0 = hp * (q0[0] + z[i] * a1[i] - a2[i]);
    T M2 = hp * hp * hp * (q2[0] + z[i] * b1[i] - b2[i]);
    if (m.sqrt_edge) {
      M0 *= hp;
      M2 *= hp;
    }
    chord_moments_from(m, ch, M0, M2, I[i]);
  }
}

// The profile at n points t[i] (batch: the Clenshaw chains of a series run side by side).
template <class T>
void profile_batch(const ExactModel<T>& m, const T* t, int n, std::size_t terms, T* out) {
  if (!m.piece.empty()) {
    for (int i = 0; i < n; ++i) out[i] = profile_at(m, t[i]);
    return;
  }
  constexpr int kMax = kKronrodPoints;
  std::array<T, kMax> z, b1, b2;
  for (int i = 0; i < n; ++i) {
    z[i] = 2.0 * t[i] - 1.0;
    b1[i] = b2[i] = T(0.0);
  }
  const std::size_t nt = std::min(std::max<std::size_t>(terms, 1), m.chebyshev.size());
  for (std::size_t k = nt - 1; k >= 1; --k) {
    const T& c = m.chebyshev[k];
    for (int i = 0; i < n; ++i) {
      const T b0 = c + 2.0 * z[i] * b1[i] - b2[i];
      b2[i] = b1[i];
      b1[i] = b0;
    }
  }
  for (int i = 0; i < n; ++i) out[i] = m.chebyshev[0] + z[i] * b1[i] - b2[i];
}

// Requested tolerances from which a table's chords are broken at knot crossings (f(w) inside).
inline constexpr double kBreakChordsTolerance = 1e-5;

// The falling part of a slip-speed law on one chord: integral sigma g(w) (tau - tau_c)
// {1, x, y} dtau / p*, g(w) = exp(-(w / w_s)^delta), w = |omega| |tau - tau_c| (f = f_k + (f_s -
// f_k) g; the constant part f_k is in closed form). Adaptive G15K31 on the two sides of the
// centre of sliding (a kink of |tau - tau_c|), in tau, or for a Hertz edge in the chord angle
// theta, tau = h sin(theta) (then R^2 - |r|^2 = h^2 cos^2(theta) and the edge is smooth); the
// profile series is summed to `terms` terms. break_at_knots: a table's chords are broken at
// knot crossings (for loose tolerances only, see below).
template <class T>
std::array<T, 3> chord_moments_falling(const ExactModel<T>& m, const Chord<T>& c,
                                       const T& abs_omega, std::size_t terms,
                                       std::array<double, 3>& inner_error,
                                       const std::array<double, 3>& tol, bool break_at_knots) {
  const double R = m.radius;
  inner_error = {0.0, 0.0, 0.0};
  const T A = 1.0 + (m.kx * c.fx + m.ky * c.fy) / R;  // shift factor at the foot
  const T B = m.kx * c.ex + m.ky * c.ey;              // its slope per unit w = tau / R
  const bool angle = m.sqrt_edge;
  auto f = [&](const double* x, int n, int, Sample<T, 3>* out) {
    std::array<T, kKronrodPoints> tau, jac, p;
    // {}: GCC 12 at -O1 with sanitizers reports a false maybe-uninitialized (-Werror).
    std::array<T, kKronrodPoints> t{};
    for (int i = 0; i < n; ++i) {
      if (angle) {
        const double cs = std::cos(x[i]);
        tau[i] = c.h * std::sin(x[i]);
        jac[i] = c.h * cs;
        const T edge = jac[i] / R;  // sqrt(1 - t)
        t[i] = 1.0 - edge * edge;
      } else {
        tau[i] = T(x[i]);
        jac[i] = T(1.0);
        t[i] = c.t_foot + (tau[i] / R) * (tau[i] / R);
      }
    }
    profile_batch(m, t.data(), n, terms, p.data());
    for (int i = 0; i < n; ++i) {
      if (angle) p[i] *= jac[i] / R;
      const T arm = tau[i] - c.tau_c;
      const T w = abs_omega * (value_of(arm) < 0.0 ? -arm : arm);
      const T v = p[i] * (A + B * (tau[i] / R)) * arm * slip_speed_decay(*m.slip_speed, w) * jac[i];
      out[i].value = {v, v * (c.fx + tau[i] * c.ex), v * (c.fy + tau[i] * c.ey)};
    }
  };
  double lo, hi, mid;
  if (angle) {
    const double ratio = std::clamp(value_of(c.tau_c) / std::max(value_of(c.h), 1e-300), -1.0, 1.0);
    lo = -0.5 * std::numbers::pi;
    hi = 0.5 * std::numbers::pi;
    mid = std::asin(ratio);
  } else {
    hi = value_of(c.h);
    lo = -hi;
    mid = std::clamp(value_of(c.tau_c), lo, hi);
  }
  const TaggedInterval halves[2] = {{lo, mid, 0}, {mid, hi, 1}};
  const int first = mid > lo ? 0 : 1;
  const int sides = (mid < hi ? 2 : 1) - first;
  if (m.piece.empty() || !break_at_knots) {
    const auto r = integrate_adaptive_batch<T, 3, 48, kGK31>(f, halves + first, sides, tol);
    inner_error = r.error;
    return r.value;
  }
  // Centre of sliding off the chord and g below 1e-3 on all of it (w >= |omega| (|tau_c| - h)):
  // the falling part is small, one G15K31 panel (or its halves) usually suffices; else break.
  if (sides == 1) {
    const double w_min =
        value_of(abs_omega) * std::max(0.0, std::abs(value_of(c.tau_c)) - value_of(c.h));
    if (value_of(slip_speed_decay(*m.slip_speed, T(w_min))) < 1e-3) {
      const auto r = integrate_adaptive_batch<T, 3, 2, kGK31>(f, halves + first, 1, tol);
      if (r.converged) {
        inner_error = r.error;
        return r.value;
      }
    }
  }
  // A table: the chord crosses knot t_k at tau = +-R (t_k - t_foot)^(1/2), where the profile
  // is only C1. Break there (at most kChordBreaks = 8 per half chord, every m-th knot: 4 let the
  // inner rule run out of intervals at 1e-6, 16 to 32 cost more for no gain on a 101-point table),
  // and at the centre of sliding; G7K15 on each piece, where p is a polynomial of degree 6.
  constexpr std::size_t kChordBreaks = 8;
  std::array<double, kChordBreaks> cross;
  const double tf = value_of(c.t_foot);
  const std::size_t first_knot =
      std::upper_bound(m.knot.begin(), m.knot.end(), tf) - m.knot.begin();
  const std::size_t inside = first_knot + 1 < m.knot.size() ? m.knot.size() - 1 - first_knot : 0;
  const std::size_t stride = std::max<std::size_t>(1, (inside + kChordBreaks - 1) / kChordBreaks);
  std::size_t nc = 0;
  for (std::size_t k = first_knot; k + 1 < m.knot.size() && nc < kChordBreaks; k += stride)
    cross[nc++] = R * std::sqrt(m.knot[k] - tf);
  std::array<double, 2 * kChordBreaks + 3> pts;
  std::size_t np = 0;
  pts[np++] = lo;
  for (std::size_t j = nc; j-- > 0;)
    if (-cross[j] > lo) pts[np++] = -cross[j];
  for (std::size_t j = 0; j < nc; ++j)
    if (cross[j] < hi) pts[np++] = cross[j];
  pts[np++] = hi;
  std::array<TaggedInterval, 2 * kChordBreaks + 4> parts;
  int count = 0;
  for (std::size_t j = 0; j + 1 < np; ++j) {
    const double a = pts[j], b = pts[j + 1];
    if (mid > a && mid < b) {
      parts[count++] = {a, mid, 0};
      parts[count++] = {mid, b, 0};
    } else if (b > a) {
      parts[count++] = {a, b, 0};
    }
  }
  const auto r =
      integrate_adaptive_batch<T, 3, 4 * kChordBreaks, kGK15>(f, parts.data(), count, tol);
  inner_error = r.error;
  return r.value;
}

// Moments of the representation: {integral_0^1 p rho d rho, integral_0^1 p rho^3 d rho}.
template <class T>
std::array<T, 2> representation_moments(const ExactModel<T>& m) {
  // t = rho^2; with a sqrt edge substitute t = 1 - u^2 (dt = 2u du) to keep it polynomial.
  std::array<T, 2> a{T(0.0), T(0.0)};
  if (!m.piece.empty()) {  // (1/2) integral p {1, t} dt, piece by piece (cubic: exact)
    for (std::size_t k = 0; k < m.piece.size(); ++k) {
      const auto& c = m.piece[k];
      const double h = m.knot[k + 1] - m.knot[k], t0 = m.knot[k];
      const double i0 = h * (c[0] + h * (c[1] / 2 + h * (c[2] / 3 + h * c[3] / 4)));
      const double i1 = h * h * (c[0] / 2 + h * (c[1] / 3 + h * (c[2] / 4 + h * c[3] / 5)));
      a[0] += T(0.5 * i0);
      a[1] += T(0.5 * (t0 * i0 + i1));
    }
    return a;
  }
  const GaussLegendreRule g = gauss_legendre(static_cast<int>(m.chebyshev.size()) + 3);
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const double x = 0.5 * (1.0 + g.nodes[i]), w = 0.5 * g.weights[i];
    double t = x, jac = 1.0;
    if (m.sqrt_edge) {
      t = 1.0 - x * x;
      jac = 2.0 * x * x;  // sqrt(1 - t) = u, dt = 2 u du
    }
    const T p = chebyshev_sum(m.chebyshev, t) * (w * jac);
    a[0] += 0.5 * p;
    a[1] += 0.5 * p * t;
  }
  return a;
}

// A table's outer integral: broken at knot crossings (every m-th, at most max_breaks per half
// range) and bisected at crossings, with the intervals on the stack; if that runs out with
// constant f, again from every crossing with kCrossingCapacity intervals per crossing on the
// heap (a kink at every knot: noisy data, steps). The evaluations of both attempts count.
template <class T, class F>
AdaptiveResult<T, 3> integrate_table(F& f, const ExactModel<T>& m, double s_max, double mirror,
                                     std::size_t max_breaks, const std::array<double, 3>& tol) {
  const KnotCrossingSplit split{&m.knot, s_max, mirror};
  std::array<TaggedInterval, 2 * kMaxCrossings + 2> breaks;
  const int nb =
      crossing_intervals(m.knot, s_max, std::min(max_breaks, kMaxCrossings), mirror, breaks.data());
  auto r =
      integrate_adaptive_batch<T, 3, kPiecewiseCapacity, kGK15>(f, breaks.data(), nb, tol, split);
  if (r.converged || m.slip_speed) return r;
  const std::size_t inside = knots_inside(m.knot, s_max);
  std::vector<TaggedInterval> all(2 * inside + 2);
  const int na = crossing_intervals(m.knot, s_max, inside, mirror, all.data());
  const int spent = r.evaluations;
  r = integrate_adaptive_batch_heap<T, 3, kGK15>(
      f, all.data(), na, tol, kCrossingCapacity * na + kPiecewiseCapacity, split);
  r.evaluations += spent;
  return r;
}

// Whether an error estimate [N, N, N m] meets a tolerance relative to f N (forces) and f N R
// (torque), scale_F = f N.
inline bool within_tolerance(const ResultantErrors& e, double tol, double scale_F, double R) {
  return e.Fx <= tol * scale_F && e.Fy <= tol * scale_F && e.Mz <= tol * scale_F * R;
}

}  // namespace detail

// Exact Fx, Fy, Mz for a model and kinematics, to the requested tolerance, with an error
// estimate; converged is true only if every component of that estimate meets the tolerance.
// Throws InvalidArgument for non-finite velocities.
template <class T>
ExactResult<T> exact_resultants(const ExactModel<T>& m, const Kinematics<T>& k,
                                const ExactOptions& options = {}) {
  using std::sqrt;
  require_finite("vx", value_of(k.vx));
  require_finite("vy", value_of(k.vy));
  require_finite("omega", value_of(k.omega));
  if (!(options.tolerance > 0.0) || !(options.tolerance < 1.0))
    throw InvalidArgument("tolerance", format_value(options.tolerance), "must lie in (0, 1)");
  const double R = m.radius;
  const double tol = std::max(options.tolerance, 1e-15);
  ExactResult<T> out;
  const double speed = std::hypot(value_of(k.vx), value_of(k.vy));
  const double w_abs = std::abs(value_of(k.omega));
  const double fscale = m.friction_scale;
  const double scale_F = fscale * value_of(m.pressure) * m.load_area;
  const double repr = m.representation_error * value_of(m.pressure) * fscale * std::numbers::pi *
                      R * R;  // bound on the load error of the representation
  out.error = {repr, repr, repr * R};

  if (speed == 0.0 && w_abs == 0.0) {
    out.converged = detail::within_tolerance(out.error, options.tolerance, scale_F, R);
    return out;
  }

  // Pure sliding, or a centre so far that the first order in eps = |omega| R / |v| (below) is
  // within a tenth of the tolerance: its remainder is at most c eps^2 f N with c = kappa_max^2
  // (1 + |k|) (1 + delta^2 for a slip-speed law of exponent delta); 10^3 random kinematics per
  // profile kind, kappa in [1/3, 3], gave at most 0.3 of that. Switching there rather than at
  // eps ~ tol keeps the derivatives smooth: the integrals about a centre 1/eps radii away
  // lose their derivatives in omega to cancellation (5 % at eps = 2e-13, tolerance 1e-10).
  const double kappa_max = std::max(value_of(m.kappa), 1.0 / value_of(m.kappa));
  const double delta = m.slip_speed ? value_of(m.slip_speed->exponent) : 0.0;
  const double remainder = kappa_max * kappa_max *
                           (1.0 + std::hypot(value_of(m.kx), value_of(m.ky))) *
                           (1.0 + delta * delta);  // c above
  if (w_abs == 0.0 || w_abs * R < std::sqrt(0.1 * tol / remainder) * speed) {
    const auto A = detail::representation_moments(m);
    // |v| and e_v = v/|v| from velocities scaled by their largest component, so that no
    // square under- or overflows (|v| = 1e-200 or 1e200 is still pure sliding).
    const double sv = std::max(std::abs(value_of(k.vx)), std::abs(value_of(k.vy)));
    const T sx = k.vx / sv, sy = k.vy / sv;
    const T n = sqrt(sx * sx + sy * sy);  // in [1, sqrt 2]: never 0
    const T v = sv * n, ux = sx / n, uy = sy / n;
    const T mu = m.slip_speed ? friction_at(*m.slip_speed, v) : m.friction;
    const T N = m.pressure * (2.0 * std::numbers::pi * R * R) * A[0];
    const T C3 = m.pressure * (std::numbers::pi * R * R * R) * A[1];  // p* pi R^3 A^3
    // Traction direction t0 (per unit f sigma): D u, or D^2 u / |D u| (associated).
    const bool assoc = m.associated_orthotropy;
    const T hu = assoc ? T(sqrt(ux * ux + m.kappa * m.kappa * uy * uy)) : T(1.0);
    const T tx = ux / hu, ty = (assoc ? m.kappa * m.kappa : m.kappa) * uy / hu;
    out.resultants.Fx = -mu * N * tx;
    out.resultants.Fy = -mu * N * ty;
    out.resultants.Mz = -mu * C3 * (ty * m.kx - tx * m.ky);
    // First order in omega (theory.md section 2, vc/|vc| linearised about e_v; e_p = z x e_v):
    //   vc/|vc| = e_v + (omega/|v|) (r.e_v) e_p,  |vc| = |v| - omega (r.e_p),
    //   integral sigma r dS = C3 k,  integral sigma r r^T dS = C3 R I,
    //   dF/domega  = -(f C3/|v|) (k.e_v) D e_p + f'(|v|) C3 (k.e_p) D e_v,
    //   dMz/domega = -C3 R [(f/|v|) (kappa ux^2 + uy^2) + f'(|v|) (kappa uy^2 + ux^2)],
    // D = diag(1, kappa). Its value is below the tolerance here, but it makes d/domega right
    // (also at omega = 0). The coefficients are taken as plain numbers: their own derivatives
    // (~ 1/|v|^2, which overflow for |v| ~ 1e-200) only enter multiplied by omega R << tol |v|;
    // 1/|v| is capped at 1e300 (below |v| = 1e-300 no derivative in omega is representable).
    const double uxv = value_of(ux), uyv = value_of(uy), kap = value_of(m.kappa);
    const double kv = value_of(m.kx) * uxv + value_of(m.ky) * uyv;
    const double kp = value_of(m.ky) * uxv - value_of(m.kx) * uyv;
    const double c3 = value_of(C3), iv = std::min(1.0 / value_of(v), 1e300);
    const double fv = value_of(mu) * iv;
    const double fp = m.slip_speed ? value_of(detail::friction_slope_at(*m.slip_speed, v)) : 0.0;
    double dFx = c3 * (fv * kv * uyv + fp * kp * uxv);
    double dFy = c3 * kap * (-fv * kv * uxv + fp * kp * uyv);
    double dMz =
        -c3 * R * (fv * (kap * uxv * uxv + uyv * uyv) + fp * (kap * uyv * uyv + uxv * uxv));
    if (assoc) {
      // Associated law (tau = -f sigma D n, n = D vc/|D vc|): with h = |D u|, n = D u / h,
      // P = I - n n^T, J = z x, d tau/d omega = -sigma [f/(|v| h) D P D J r + f' (J r.u) D n]:
      //   dF/domega  = -(f C3/(|v| h)) D P D J k + f' C3 kp D n,
      //   dMz/domega = -C3 R [(f/(|v| h)) tr(D P D) + f' h],  tr(D P D) = 1 + kappa^2 - |D n|^2.
      const double k2 = kap * kap, kxv = value_of(m.kx), kyv = value_of(m.ky);
      const double h = std::sqrt(uxv * uxv + k2 * uyv * uyv);
      const double txv = uxv / h, tyv = k2 * uyv / h;
      const double cr = (k2 * uyv * kxv - uxv * kyv) / h;  // n . D J k
      dFx = -c3 * (fv / h) * (-kyv - txv * cr) + c3 * fp * kp * txv;
      dFy = -c3 * (fv / h) * (k2 * kxv - tyv * cr) + c3 * fp * kp * tyv;
      dMz = -c3 * R * ((fv / h) * (1.0 + k2 - txv * txv - tyv * tyv) + fp * h);
    }
    out.resultants.Fx += k.omega * dFx;
    out.resultants.Fy += k.omega * dFy;
    out.resultants.Mz += k.omega * dMz;
    const double eps = w_abs * R / std::max(speed, 1e-300);
    out.error.Fx += 2.0 * remainder * eps * eps * scale_F;  // twice the remainder's bound
    out.error.Fy = out.error.Fx;
    out.error.Mz += out.error.Fx * R;
    out.converged = detail::within_tolerance(out.error, options.tolerance, scale_F, R);
    return out;
  }

  const double sgn = value_of(k.omega) > 0.0 ? 1.0 : -1.0;
  const T abs_omega = sgn * k.omega;
  // Centre of sliding r_c = (-vy, vx) / omega, at distance d from O in direction g. The
  // interior integral uses rc only polynomially (no d = |r_c|: its derivative is infinite at
  // v = 0 and loses accuracy like 1/|v| near it); gamma0, the direction of r_c, is a plain
  // double that only fixes where the range of integration starts.
  const T rcx = -k.vy / k.omega, rcy = k.vx / k.omega;
  const double rcx_v = value_of(rcx), rcy_v = value_of(rcy);
  const double dv = std::hypot(rcx_v, rcy_v);
  // Tolerances in integrand units (the factor -f p* is applied at the end).
  const double unit = tol * m.load_area * (m.slip_speed ? fscale : 1.0);
  // Inner integrals are summed over at most pi of beta: keep their share small.
  const double share = 1.0 / (20.0 * std::numbers::pi);
  const std::array<double, 3> tol_inner{unit * share, unit * share * R, unit * share * R};

  // Truncate the chord transforms where their tail is far below the tolerance; the dropped
  // tail bounds the chord moments' error by 2 R^2 (1 + |k|) tail, over at most pi of beta.
  std::size_t terms = m.chord_q0.size();
  const double shift = 1.0 + std::hypot(value_of(m.kx), value_of(m.ky));
  const double tail_scale = 2.0 * std::numbers::pi * R * R * shift;
  while (terms > 1 && m.chord_tail[terms - 1] * tail_scale <= 1e-3 * unit) --terms;
  // A slip-speed law f = f_k + (f_s - f_k) g(w) (theory.md section 2): the f_k part is the
  // constant-f closed form, only the falling part (f_s - f_k) g needs an inner rule.
  const T f_const = m.slip_speed ? m.slip_speed->kinetic_coefficient : m.friction;
  const T f_fall = m.slip_speed ? m.slip_speed->static_coefficient - f_const : T(0.0);
  const double fall = std::abs(value_of(f_fall));
  if (m.piece.empty()) {
    const double dropped =
        std::abs(value_of(f_const) * value_of(m.pressure)) * m.chord_tail[terms] * tail_scale;
    out.error.Fx += dropped;
    out.error.Fy += dropped;
    out.error.Mz += dropped * R;
  }
  // The falling part sums the profile series to profile_terms terms: the dropped tail
  // sum_{k >= n} |c_k| bounds |p - p_n|, so its error is at most |f_s - f_k| p* tail (1 + |k|)
  // pi R^2 (times R for Mz).
  std::size_t profile_terms = m.chebyshev.size();
  std::array<double, 3> tol_fall = tol_inner;
  // A table's chords broken at knot crossings only for tol >= 1e-5: below, the pieces between
  // every m-th knot still hold kinks, G7K15 runs out of its 32 intervals and the unconverged inner
  // estimates can keep the outer rule bisecting to capacity; the unbroken panels converge down
  // to ~3e-9 (101-point table), and below that still report a 100x smaller estimate.
  const bool break_at_knots = tol >= detail::kBreakChordsTolerance;
  if (m.slip_speed && fall > 0.0) {
    for (double& t : tol_fall) t /= fall;
    if (m.piece.empty()) {
      const double area = std::numbers::pi * R * R * shift;
      double tail = 0.0;
      while (profile_terms > 1 &&
             (tail + std::abs(value_of(m.chebyshev[profile_terms - 1]))) * fall * area <=
                 1e-3 * unit) {
        tail += std::abs(value_of(m.chebyshev[profile_terms - 1]));
        --profile_terms;
      }
      const double dropped = fall * value_of(m.pressure) * tail * area;
      out.error.Fx += dropped;
      out.error.Fy += dropped;
      out.error.Mz += dropped * R;
    }
  }
  // Floor of the estimate: min(1e-11, tol / 10) of f N (f N R). On 10^4 random kinematics per
  // profile kind the Kronrod heuristic's estimate fell below the achieved error only at
  // rounding level, at most 6.6e-12 of f N (uniform pressure, tolerance 1e-8, a first
  // partition that over-delivers); test_exact checks the bound.
  const double floor = std::min(1e-11, 0.1 * tol) * scale_F;
  // The outer rule gets the share of tol f N (f N R) that the terms above and the floor leave,
  // at least half of it (a representation error beyond half the tolerance cannot converge).
  auto room = [&](double used, double scale) {
    const double budget = tol * scale_F * scale;
    return budget > 0.0 ? std::clamp(1.0 - used / budget, 0.5, 1.0) : 1.0;
  };
  const std::array<double, 3> tol_out{unit * room(out.error.Fx + floor, 1.0),
                                      unit * room(out.error.Fy + floor, 1.0),
                                      unit * R * room(out.error.Mz + floor * R, R)};

  // Outer integrand for a batch of chords with Jacobians jac: u = sign(omega) z x e,
  // traction direction t = D u = (u_x, kappa u_y) (or D^2 u / |D u| for the associated law);
  // F ~ t I0, Mz ~ t_y Ix - t_x Iy.
  auto chords_to_samples = [&](const detail::Chord<T>* ch, const T* jac, int n,
                               detail::Sample<T, 3>* out_samples) {
    std::array<std::array<T, 3>, detail::kKronrodPoints> I;
    std::array<std::array<double, 3>, detail::kKronrodPoints> ie{};
    detail::chord_moments_closed_form(m, terms, ch, n, I.data());
    if (m.slip_speed) {
      for (int i = 0; i < n; ++i) {
        for (T& v : I[i]) v *= f_const;
        if (fall == 0.0) continue;
        const auto g = detail::chord_moments_falling(m, ch[i], abs_omega, profile_terms, ie[i],
                                                     tol_fall, break_at_knots);
        for (int c = 0; c < 3; ++c) {
          I[i][c] += f_fall * g[c];
          ie[i][c] *= fall;
        }
      }
    }
    for (int i = 0; i < n; ++i) {
      T ux = -sgn * ch[i].ey, uy = sgn * ch[i].ex * m.kappa;
      if (m.associated_orthotropy) {
        const T hu = sqrt(ch[i].ey * ch[i].ey + m.kappa * m.kappa * ch[i].ex * ch[i].ex);
        ux /= hu;
        uy *= m.kappa / hu;
      }
      out_samples[i].value = {ux * I[i][0] * jac[i], uy * I[i][0] * jac[i],
                              (uy * I[i][1] - ux * I[i][2]) * jac[i]};
      const double j = std::abs(value_of(jac[i]));
      out_samples[i].inner_error = {ie[i][0] * j, ie[i][1] * j, ie[i][2] * j};
    }
  };

  detail::AdaptiveResult<T, 3> res;
  const bool fine = tol < 1e-8;
  const double pi = std::numbers::pi;
  // Break points of a table's outer integral (knot crossings) at first, per half range.
  const std::size_t max_breaks = tol >= 1e-7 ? 16 : (tol >= 1e-9 ? 64 : 256);
  if (dv < R) {
    // Interior centre: the rays at beta and beta + pi form one chord, so
    // F = integral_0^pi dbeta u(beta) integral_chord sigma (tau - tau_c) dtau. The chord at
    // beta = gamma0 + theta (e = e(beta)) has tau_c = r_c.e = d cos theta, foot r_c - tau_c e,
    // t_foot = (r_c x e)^2 / R^2 and half-length (R^2 - d^2 + tau_c^2)^(1/2): it nearly touches
    // the rim at theta = pi/2 when r_c nears the rim, so a breakpoint there, then bisection.
    const double gamma0 = dv > 0.0 ? std::atan2(rcy_v, rcx_v) : 0.0;
    const T delta2 = R * R - (rcx * rcx + rcy * rcy);
    auto f = [&](const double* theta, int n, int, detail::Sample<T, 3>* out_samples) {
      std::array<detail::Chord<T>, detail::kKronrodPoints> chords;
      std::array<T, detail::kKronrodPoints> jac;
      for (int i = 0; i < n; ++i) {
        const double ex = std::cos(gamma0 + theta[i]), ey = std::sin(gamma0 + theta[i]);
        detail::Chord<T>& ch = chords[i];
        ch.ex = T(ex);
        ch.ey = T(ey);
        ch.tau_c = rcx * ex + rcy * ey;
        ch.fx = rcx - ch.tau_c * ex;
        ch.fy = rcy - ch.tau_c * ey;
        ch.h = sqrt(delta2 + ch.tau_c * ch.tau_c);
        const T cross = rcx * ey - rcy * ex;
        ch.t_foot = cross * cross / (R * R);
        jac[i] = T(1.0);
      }
      chords_to_samples(chords.data(), jac.data(), n, out_samples);
    };
    // G15K31 from quarters (halves for a loose tolerance): at 1e-10 the seed tire converges
    // on this first partition in every regime.
    const detail::TaggedInterval quarters[4] = {{0.0, 0.25 * pi, 0},
                                                {0.25 * pi, 0.5 * pi, 0},
                                                {0.5 * pi, 0.75 * pi, 0},
                                                {0.75 * pi, pi, 0}};
    const detail::TaggedInterval halves[2] = {{0.0, 0.5 * pi, 0}, {0.5 * pi, pi, 0}};
    if (!m.piece.empty()) {
      // A table: a chord's foot crosses knot t_k at sin theta = sqrt(t_k) R / d (t_foot =
      // (d/R)^2 sin^2 theta), where the chord integrals have a (t_k - t_foot)^(5/2) kink:
      // break there (and at pi/2), G7K15 on each piece.
      res = detail::integrate_table(f, m, dv / R, pi, max_breaks, tol_out);
    } else {
      res =
          fine ? detail::integrate_adaptive_batch<T, 3, 160, detail::kGK31>(f, quarters, 4, tol_out)
               : detail::integrate_adaptive_batch<T, 3, 160, detail::kGK31>(f, halves, 2, tol_out);
    }
  } else {
    // Exterior centre: the wedge of chords through r_c, parametrised by the chord angle phi in
    // [-pi/2, pi/2] (sin theta = (R/d) sin phi), which removes the square root of the chord
    // length at the tangent rays; dtheta/dphi = R cos phi / (d cos theta).
    const T d = sqrt(rcx * rcx + rcy * rcy);  // >= R > 0
    const T gx = rcx / d, gy = rcy / d;
    const T eps2 = (d - R) * (d + R);
    auto f = [&](const double* phi, int n, int, detail::Sample<T, 3>* out_samples) {
      std::array<detail::Chord<T>, detail::kKronrodPoints> chords;
      std::array<T, detail::kKronrodPoints> jac;
      for (int i = 0; i < n; ++i) {
        const double cphi = std::cos(phi[i]), sphi = std::sin(phi[i]);
        const T s_off = sqrt(eps2 + (R * cphi) * (R * cphi));  // d cos theta
        const T ct = s_off / d, st = (R / d) * sphi;
        // e = cos theta u0 + sin theta (z x u0), u0 = -g.
        detail::Chord<T>& ch = chords[i];
        ch.ex = -ct * gx + st * gy;
        ch.ey = -ct * gy - st * gx;
        ch.fx = -(R * sphi) * ch.ey;  // foot of the perpendicular: (R sin phi) z x e
        ch.fy = (R * sphi) * ch.ex;
        ch.h = T(R * cphi);
        ch.tau_c = -s_off;
        ch.t_foot = T(sphi * sphi);
        jac[i] = (R * cphi) / s_off;  // dtheta/dphi
      }
      chords_to_samples(chords.data(), jac.data(), n, out_samples);
    };
    const detail::TaggedInterval quarters[4] = {{-0.5 * pi, -0.25 * pi, 0},
                                                {-0.25 * pi, 0.0, 0},
                                                {0.0, 0.25 * pi, 0},
                                                {0.25 * pi, 0.5 * pi, 0}};
    const detail::TaggedInterval halves[2] = {{-0.5 * pi, 0.0, 0}, {0.0, 0.5 * pi, 0}};
    if (!m.piece.empty()) {
      // A table: t_foot = sin^2 phi crosses knot t_k at phi = +-asin(sqrt(t_k)).
      res = detail::integrate_table(f, m, 1.0, 0.0, max_breaks, tol_out);
    } else {
      res =
          fine ? detail::integrate_adaptive_batch<T, 3, 160, detail::kGK31>(f, quarters, 4, tol_out)
               : detail::integrate_adaptive_batch<T, 3, 160, detail::kGK31>(f, halves, 2, tol_out);
    }
  }
  const T factor = -(m.slip_speed ? T(1.0) : m.friction) * m.pressure;
  out.resultants.Fx = factor * res.value[0];
  out.resultants.Fy = factor * res.value[1];
  out.resultants.Mz = factor * res.value[2];
  const double fabs_ = std::abs(value_of(factor));
  out.error.Fx += fabs_ * res.error[0] + floor;
  out.error.Fy += fabs_ * res.error[1] + floor;
  out.error.Mz += fabs_ * res.error[2] + floor * R;
  out.evaluations = res.evaluations;
  // Converged: the rule met its tolerance and the whole estimate meets the requested one.
  out.converged =
      res.converged && detail::within_tolerance(out.error, options.tolerance, scale_F, R);
  return out;
}

// Convenience overload: builds the model (allocates) and evaluates it.
ExactResult<double> exact_resultants(const ContactPatch& patch, const Kinematics<double>& k,
                                     const ExactOptions& options = {});

}  // namespace contensou
