// The outer rule of the exact resultants (theory.md section 2): in polar coordinates about the
// centre of sliding r_c = (-vy, vx)/omega, vc/|vc| = sign(omega) z x e(beta) depends on beta
// alone and the rays at beta and beta + pi make one chord, so
//   F = -p* sign(omega) integral dbeta D (z x e) integral_chord f sigma/p* (tau - tau_c) dtau
// (and the same with weights x, y for Mz). The chords are parametrised by theta = beta - gamma
// in [0, pi] for a centre inside the disk, by the chord angle phi in [-pi/2, pi/2] for one
// outside; the integral over them is adaptive Gauss-Kronrod from a first partition (G15K31),
// or for a table from its knot crossings (G7K15, impl/table_partition.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/chord_integrals.hpp"
#include "contensou/friction/impl/error_budget.hpp"
#include "contensou/friction/impl/slip_speed_integrals.hpp"
#include "contensou/friction/impl/table_partition.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// The outer integrand for a batch of chords with Jacobians jac: the chord moments I = integral
// f sigma/p* (tau - tau_c) {1, x, y} dtau (f_k I_closed + (f_s - f_k) I_falling with a
// slip-speed law), u = sign(omega) z x e, traction direction t = D u = (u_x, kappa u_y) (or
// D^2 u / |D u| for the associated law); F ~ t I0, Mz ~ t_y Ix - t_x Iy.
template <class T>
struct ChordIntegrand {
  const ExactModel<T>& m;
  std::size_t terms;          // chord-transform terms summed
  std::size_t profile_terms;  // profile terms the falling part sums
  T f_const, f_fall;          // f_k (or f) and f_s - f_k
  double fall;                // |f_s - f_k|
  T abs_omega;                // |omega|
  double sgn;                 // sign(omega)
  std::array<double, 3> tol_fall;
  bool break_at_knots;

  void operator()(const Chord<T>* ch, const T* jac, int n, Sample<T, 3>* out) const {
    std::array<std::array<T, 3>, kKronrodPoints> I;
    std::array<std::array<double, 3>, kKronrodPoints> ie{};
    moments(ch, n, I, ie);
    for (int i = 0; i < n; ++i) out[i] = sample(ch[i], jac[i], I[i], ie[i]);
  }

  // The chord moments with the friction law inside, and the inner rules' error estimates.
  void moments(const Chord<T>* ch, int n, std::array<std::array<T, 3>, kKronrodPoints>& I,
               std::array<std::array<double, 3>, kKronrodPoints>& ie) const {
    chord_moments_closed_form(m, terms, ch, n, I.data());
    if (!m.slip_speed) return;
    for (int i = 0; i < n; ++i) {
      for (T& v : I[i]) v *= f_const;
      if (fall == 0.0) continue;
      const auto g = chord_moments_falling(m, ch[i], abs_omega, profile_terms, ie[i], tol_fall,
                                           break_at_knots);
      for (int c = 0; c < 3; ++c) {
        I[i][c] += f_fall * g[c];
        ie[i][c] *= fall;
      }
    }
  }

  // One chord's contribution {t_x I0, t_y I0, t_y Ix - t_x Iy} dbeta/dparameter.
  Sample<T, 3> sample(const Chord<T>& ch, const T& jac, const std::array<T, 3>& I,
                      const std::array<double, 3>& ie) const {
    using std::sqrt;
    T ux = -sgn * ch.ey, uy = sgn * ch.ex * m.kappa;
    if (m.associated_orthotropy) {
      const T hu = sqrt(ch.ey * ch.ey + m.kappa * m.kappa * ch.ex * ch.ex);
      ux /= hu;
      uy *= m.kappa / hu;
    }
    Sample<T, 3> s;
    s.value = {ux * I[0] * jac, uy * I[0] * jac, (uy * I[1] - ux * I[2]) * jac};
    const double j = std::abs(value_of(jac));
    s.inner_error = {ie[0] * j, ie[1] * j, ie[2] * j};
    return s;
  }
};

// The centre of sliding r_c = (-vy, vx) / omega. The interior integral uses it only
// polynomially (no d = |r_c|: its derivative is infinite at v = 0 and loses accuracy like 1/|v|
// near it); d and the direction of r_c are plain doubles that only choose the parametrisation
// and where its range starts.
template <class T>
struct SlidingCentre {
  T x, y;
  double xv, yv;  // values of x, y
  double d;       // |r_c|
};

template <class T>
SlidingCentre<T> sliding_centre(const Kinematics<T>& k) {
  const T rcx = -k.vy / k.omega, rcy = k.vx / k.omega;
  const double xv = value_of(rcx), yv = value_of(rcy);
  return {rcx, rcy, xv, yv, std::hypot(xv, yv)};
}

// Interior centre (d < R): the chord at beta = gamma0 + theta (e = e(beta)) has tau_c = r_c.e =
// d cos theta, foot r_c - tau_c e, t_foot = (r_c x e)^2 / R^2 and half-length (R^2 - d^2 +
// tau_c^2)^(1/2), dbeta/dtheta = 1.
template <class T>
struct InteriorChords {
  const ChordIntegrand<T>& integrand;
  const SlidingCentre<T>& rc;
  double R;
  double gamma0;  // direction of r_c
  T delta2;       // R^2 - d^2

  void operator()(const double* theta, int n, int, Sample<T, 3>* out) const {
    using std::sqrt;
    std::array<Chord<T>, kKronrodPoints> chords;
    std::array<T, kKronrodPoints> jac;
    for (int i = 0; i < n; ++i) {
      const double ex = std::cos(gamma0 + theta[i]), ey = std::sin(gamma0 + theta[i]);
      Chord<T>& ch = chords[i];
      ch.ex = T(ex);
      ch.ey = T(ey);
      ch.tau_c = rc.x * ex + rc.y * ey;
      ch.fx = rc.x - ch.tau_c * ex;
      ch.fy = rc.y - ch.tau_c * ey;
      ch.h = sqrt(delta2 + ch.tau_c * ch.tau_c);
      const T cross = rc.x * ey - rc.y * ex;
      ch.t_foot = cross * cross / (R * R);
      jac[i] = T(1.0);
    }
    integrand(chords.data(), jac.data(), n, out);
  }
};

// Exterior centre (d >= R): the wedge of chords through r_c, parametrised by the chord angle
// phi in [-pi/2, pi/2] (sin theta = (R/d) sin phi), which removes the square root of the chord
// length at the tangent rays: e = cos theta u0 + sin theta (z x u0), u0 = -g, foot (R sin phi)
// z x e, h = R cos phi, tau_c = -d cos theta, dtheta/dphi = R cos phi / (d cos theta).
template <class T>
struct ExteriorChords {
  const ChordIntegrand<T>& integrand;
  double R;
  T d;       // |r_c| >= R > 0
  T gx, gy;  // r_c / d
  T eps2;    // d^2 - R^2

  void operator()(const double* phi, int n, int, Sample<T, 3>* out) const {
    using std::sqrt;
    std::array<Chord<T>, kKronrodPoints> chords;
    std::array<T, kKronrodPoints> jac;
    for (int i = 0; i < n; ++i) {
      const double cphi = std::cos(phi[i]), sphi = std::sin(phi[i]);
      const T s_off = sqrt(eps2 + (R * cphi) * (R * cphi));  // d cos theta
      const T ct = s_off / d, st = (R / d) * sphi;
      Chord<T>& ch = chords[i];
      ch.ex = -ct * gx + st * gy;
      ch.ey = -ct * gy - st * gx;
      ch.fx = -(R * sphi) * ch.ey;
      ch.fy = (R * sphi) * ch.ex;
      ch.h = T(R * cphi);
      ch.tau_c = -s_off;
      ch.t_foot = T(sphi * sphi);
      jac[i] = (R * cphi) / s_off;  // dtheta/dphi
    }
    integrand(chords.data(), jac.data(), n, out);
  }
};

// The range of a parametrisation, as its first partitions (quarters, halves), and where a
// table's chord feet cross its knots: t_foot = s_max^2 sin^2 x, mirrored about `mirror`
// (crossing_intervals).
struct OuterRange {
  TaggedInterval quarters[4];
  TaggedInterval halves[2];
  double s_max;
  double mirror;
};

// Break points of a table's outer integral (knot crossings) at first, per half range.
inline std::size_t max_table_breaks(double tol) {
  return tol >= 1e-7 ? 16 : (tol >= 1e-9 ? 64 : 256);
}

// The outer integral over a range: G15K31 from quarters (halves for a loose tolerance; at
// 1e-10 the seed tire converges on this first partition in every regime), or for a table from
// its knot crossings (the chord integrals have a (t_k - t_foot)^(5/2) kink there).
template <class T, class F>
AdaptiveResult<T, 3> integrate_chords(F& f, const ExactModel<T>& m, const OuterRange& r, double tol,
                                      const std::array<double, 3>& tol_out) {
  if (m.table()) return integrate_table(f, m, r.s_max, r.mirror, max_table_breaks(tol), tol_out);
  if (tol < 1e-8) return integrate_adaptive_batch<T, 3, 160, kGK31>(f, r.quarters, 4, tol_out);
  return integrate_adaptive_batch<T, 3, 160, kGK31>(f, r.halves, 2, tol_out);
}

// Interior centre: theta in [0, pi], with a breakpoint at pi/2, where the chord nearly touches
// the rim when r_c nears it. A table's foot crosses knot t_k at sin theta = sqrt(t_k) R / d
// (t_foot = (d/R)^2 sin^2 theta).
template <class T>
AdaptiveResult<T, 3> integrate_interior(const ChordIntegrand<T>& integrand, const ExactModel<T>& m,
                                        const SlidingCentre<T>& rc, double tol,
                                        const std::array<double, 3>& tol_out) {
  const double R = m.radius, pi = std::numbers::pi;
  const double gamma0 = rc.d > 0.0 ? std::atan2(rc.yv, rc.xv) : 0.0;
  const InteriorChords<T> f{integrand, rc, R, gamma0, R * R - (rc.x * rc.x + rc.y * rc.y)};
  const OuterRange range{
      {{0.0, 0.25 * pi, 0}, {0.25 * pi, 0.5 * pi, 0}, {0.5 * pi, 0.75 * pi, 0}, {0.75 * pi, pi, 0}},
      {{0.0, 0.5 * pi, 0}, {0.5 * pi, pi, 0}},
      rc.d / R,
      pi};
  return integrate_chords(f, m, range, tol, tol_out);
}

// Exterior centre: phi in [-pi/2, pi/2]; a table's foot, t_foot = sin^2 phi, crosses knot t_k
// at phi = +-asin(sqrt(t_k)).
template <class T>
AdaptiveResult<T, 3> integrate_exterior(const ChordIntegrand<T>& integrand, const ExactModel<T>& m,
                                        const SlidingCentre<T>& rc, double tol,
                                        const std::array<double, 3>& tol_out) {
  using std::sqrt;
  const double R = m.radius, pi = std::numbers::pi;
  const T d = sqrt(rc.x * rc.x + rc.y * rc.y);
  const ExteriorChords<T> f{integrand, R, d, rc.x / d, rc.y / d, (d - R) * (d + R)};
  const OuterRange range{{{-0.5 * pi, -0.25 * pi, 0},
                          {-0.25 * pi, 0.0, 0},
                          {0.0, 0.25 * pi, 0},
                          {0.25 * pi, 0.5 * pi, 0}},
                         {{-0.5 * pi, 0.0, 0}, {0.0, 0.5 * pi, 0}},
                         1.0,
                         0.0};
  return integrate_chords(f, m, range, tol, tol_out);
}

// The outer integral about the centre of sliding (omega != 0), in integrand units (the factor
// -f p* is applied by add_outer_result).
template <class T>
AdaptiveResult<T, 3> integrate_about_centre(const ExactModel<T>& m, const Kinematics<T>& k,
                                            double tol, const SpinBudget& b) {
  const double sgn = value_of(k.omega) > 0.0 ? 1.0 : -1.0;
  const T f_fall = falling_coefficient(m);
  const ChordIntegrand<T> integrand{m,
                                    b.terms,
                                    b.profile_terms,
                                    constant_coefficient(m),
                                    f_fall,
                                    std::abs(value_of(f_fall)),
                                    sgn * k.omega,
                                    sgn,
                                    b.tol_fall,
                                    b.break_at_knots};
  const SlidingCentre<T> rc = sliding_centre(k);
  if (rc.d < m.radius) return integrate_interior(integrand, m, rc, tol, b.tol_out);
  return integrate_exterior(integrand, m, rc, tol, b.tol_out);
}

// The resultants from the outer integral: F = -f p* res (f = 1 with a slip-speed law, which is
// inside the integrals), and its error estimate with the floor added to e.
template <class T>
void add_outer_result(const ExactModel<T>& m, const AdaptiveResult<T, 3>& res, double floor,
                      Resultants<T>& r, ResultantErrors& e) {
  const double R = m.radius;
  const T factor = -(m.slip_speed ? T(1.0) : m.friction) * m.pressure;
  r.Fx = factor * res.value[0];
  r.Fy = factor * res.value[1];
  r.Mz = factor * res.value[2];
  const double scale = std::abs(value_of(factor));
  e.Fx += scale * res.error[0] + floor;
  e.Fy += scale * res.error[1] + floor;
  e.Mz += scale * res.error[2] + floor * R;
}

}  // namespace contensou::detail
