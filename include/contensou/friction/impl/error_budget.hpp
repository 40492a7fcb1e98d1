// The error budget of the exact resultants (theory.md section 2): the requested tolerance tol
// f N (tol f N R for the torque) is shared between the profile's representation error, the
// truncations of the chord transforms and of the falling part's profile series, a floor, and
// what is left for the outer rule (at least half); the inner rules of the falling part get a
// small share of the outer one's.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/slip_speed_integrals.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/resultant_errors.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou::detail {

// The requested tolerance (the estimate is tested against it), the one the rules get (at least
// 1e-15), and the scales of the estimate: f N [N] (f = the model's friction_scale) and R [m].
struct ToleranceScale {
  double requested;
  double tol;
  double scale_F;
  double R;
};

template <class T>
ToleranceScale tolerance_scale(const ExactModel<T>& m, double requested) {
  return {requested, std::max(requested, 1e-15),
          m.friction_scale * value_of(m.pressure) * m.load_area, m.radius};
}

// Whether an error estimate [N, N, N m] meets a tolerance relative to f N (forces) and f N R
// (torque), scale_F = f N.
inline bool within_tolerance(const ResultantErrors& e, double tol, double scale_F, double R) {
  return e.Fx <= tol * scale_F && e.Fy <= tol * scale_F && e.Mz <= tol * scale_F * R;
}

inline bool within_tolerance(const ResultantErrors& e, const ToleranceScale& s) {
  return within_tolerance(e, s.requested, s.scale_F, s.R);
}

// The representation's share: |p - representation| <= e (dimensionless) bounds the load error
// by e p* f pi R^2 [N] (times R for the torque).
template <class T>
ResultantErrors representation_error_bound(const ExactModel<T>& m) {
  const double R = m.radius;
  const double repr =
      m.representation_error() * value_of(m.pressure) * m.friction_scale * std::numbers::pi * R * R;
  return {repr, repr, repr * R};
}

// A dropped tail d [N] in the estimate: d on each force, d R on the torque.
inline void add_dropped(ResultantErrors& e, double d, double R) {
  e.Fx += d;
  e.Fy += d;
  e.Mz += d * R;
}

// The split of a slip-speed law f = f_k + (f_s - f_k) g(w) (theory.md section 2): the constant
// part (f_k, or f without a law) is in closed form, the falling part f_s - f_k needs an inner
// rule.
template <class T>
T constant_coefficient(const ExactModel<T>& m) {
  return m.slip_speed ? m.slip_speed->kinetic_coefficient : m.friction;
}

template <class T>
T falling_coefficient(const ExactModel<T>& m) {
  return m.slip_speed ? m.slip_speed->static_coefficient - constant_coefficient(m) : T(0.0);
}

// The terms of the chord transforms summed: truncated where their tail is far below the
// tolerance (1e-3 unit); the dropped tail bounds the chord moments' error by 2 R^2 (1 + |k|)
// tail, over at most pi of beta (tail_scale = 2 pi R^2 (1 + |k|)).
template <class T>
std::size_t chord_transform_terms(const ExactModel<T>& m, double unit, double tail_scale) {
  std::size_t terms = m.chord_q0().size();
  while (terms > 1 && m.chord_tail()[terms - 1] * tail_scale <= 1e-3 * unit) --terms;
  return terms;
}

// The terms of the profile series the falling part sums: the dropped tail sum_{k >= n} |c_k|
// bounds |p - p_n|, so its error is at most |f_s - f_k| p* tail (1 + |k|) pi R^2 (times R for
// Mz), returned in `dropped`.
template <class T>
std::size_t falling_profile_terms(const ExactModel<T>& m, double fall, double unit,
                                  double& dropped) {
  const double R = m.radius;
  const double area = std::numbers::pi * R * R * (1.0 + std::hypot(value_of(m.kx), value_of(m.ky)));
  std::size_t terms = m.chebyshev().size();
  double tail = 0.0;
  while (terms > 1 &&
         (tail + std::abs(value_of(m.chebyshev()[terms - 1]))) * fall * area <= 1e-3 * unit) {
    tail += std::abs(value_of(m.chebyshev()[terms - 1]));
    --terms;
  }
  dropped = fall * value_of(m.pressure) * tail * area;
  return terms;
}

// The outer rule's tolerances [integrand units]: the share of tol f N (f N R) that the terms
// already in the estimate e and the floor leave, at least half of it (a representation error
// beyond half the tolerance cannot converge).
inline std::array<double, 3> outer_tolerances(const ResultantErrors& e, double floor, double unit,
                                              const ToleranceScale& s) {
  auto room = [&](double used, double scale) {
    const double budget = s.tol * s.scale_F * scale;
    return budget > 0.0 ? std::clamp(1.0 - used / budget, 0.5, 1.0) : 1.0;
  };
  return {unit * room(e.Fx + floor, 1.0), unit * room(e.Fy + floor, 1.0),
          unit * s.R * room(e.Mz + floor * s.R, s.R)};
}

// What the rules of a spinning contact get, and the floor of the estimate.
struct SpinBudget {
  std::size_t terms = 0;             // chord-transform terms summed
  std::size_t profile_terms = 0;     // profile terms the falling part sums
  std::array<double, 3> tol_fall{};  // the falling part's inner rules (per unit |f_s - f_k|)
  std::array<double, 3> tol_out{};   // the outer rule
  double floor = 0.0;                // added to the estimate [N] (times R for Mz)
  bool break_at_knots = false;       // a table's chords broken at knot crossings (f(w) inside)
};

// The budget (the truncations' bounds added to the estimate e). Tolerances in integrand units
// (the factor -f p* is applied at the end); the inner integrals are summed over at most pi of
// beta, so they get 1/(20 pi) of it. Floor of the estimate: min(1e-11, tol / 10) of f N (f N
// R): on 10^4 random kinematics per profile kind the Kronrod heuristic's estimate fell below
// the achieved error only at rounding level, at most 6.6e-12 of f N (uniform pressure,
// tolerance 1e-8, a first partition that over-delivers); test_exact_resultants checks the bound. A
// table's chords are broken at knot crossings only for tol >= kBreakChordsTolerance: below, the
// pieces between every m-th knot still hold kinks, G7K15 runs out of its 32 intervals and the
// unconverged inner estimates can keep the outer rule bisecting to capacity; the unbroken
// panels converge down to ~3e-9 (101-point table), and below that still report a 100x smaller
// estimate.
template <class T>
SpinBudget spin_budget(const ExactModel<T>& m, const ToleranceScale& s, ResultantErrors& e) {
  const double R = m.radius, tol = s.tol;
  const double unit = tol * m.load_area * (m.slip_speed ? m.friction_scale : 1.0);
  const double share = 1.0 / (20.0 * std::numbers::pi);
  SpinBudget b;
  b.tol_fall = {unit * share, unit * share * R, unit * share * R};
  const double shift = 1.0 + std::hypot(value_of(m.kx), value_of(m.ky));
  const double tail_scale = 2.0 * std::numbers::pi * R * R * shift;
  b.terms = chord_transform_terms(m, unit, tail_scale);
  const double fall = std::abs(value_of(falling_coefficient(m)));
  if (!m.table())
    add_dropped(e,
                std::abs(value_of(constant_coefficient(m)) * value_of(m.pressure)) *
                    m.chord_tail()[b.terms] * tail_scale,
                R);
  b.profile_terms = m.chebyshev().size();
  b.break_at_knots = tol >= kBreakChordsTolerance;
  if (m.slip_speed && fall > 0.0) {
    for (double& t : b.tol_fall) t /= fall;
    if (!m.table()) {
      double dropped = 0.0;
      b.profile_terms = falling_profile_terms(m, fall, unit, dropped);
      add_dropped(e, dropped, R);
    }
  }
  b.floor = std::min(1e-11, 0.1 * tol) * s.scale_F;
  b.tol_out = outer_tolerances(e, b.floor, unit, s);
  return b;
}

}  // namespace contensou::detail
