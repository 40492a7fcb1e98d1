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
//
// Layout: this header holds the API; the model is exact_model.hpp, and the steps of the
// formula above are in impl/, one concern a header:
//   impl/profile_representation.hpp  p(t) as a series or a table's pieces, and its moments
//   impl/chord_integrals.hpp         the chords and their moments (closed forms, transforms)
//   impl/table_pieces.hpp            a table's chord integrals: knot terms, far series
//   impl/slip_speed_integrals.hpp    the falling part of f(w) on a chord (inner rule)
//   impl/table_partition.hpp         a table's knot crossings in the outer rule
//   impl/outer_rule.hpp              the chords about r_c (inside / outside) and the outer rule
//   impl/pure_sliding.hpp            omega = 0 in closed form with its first order in omega
//   impl/error_budget.hpp            the tolerance's shares and the error estimate's terms
#pragma once

#include <algorithm>
#include <cmath>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/impl/chord_integrals.hpp"
#include "contensou/friction/impl/error_budget.hpp"
#include "contensou/friction/impl/outer_rule.hpp"
#include "contensou/friction/impl/profile_representation.hpp"
#include "contensou/friction/impl/pure_sliding.hpp"
#include "contensou/friction/impl/slip_speed_integrals.hpp"
#include "contensou/friction/impl/table_partition.hpp"
#include "contensou/friction/impl/table_pieces.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/resultant_errors.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou {

struct ExactOptions {
  // Requested accuracy, relative to f N for the forces and f N R for the torque.
  double tolerance = 1e-10;
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

// Exact Fx, Fy, Mz for a model and kinematics, to the requested tolerance, with an error
// estimate; converged is true only if every component of that estimate meets the tolerance.
// Throws InvalidArgument for non-finite velocities. The steps: at rest zero (0 is in Coulomb's
// set); pure sliding, or a centre of sliding so far that the first order in omega meets the
// tolerance, in closed form (impl/pure_sliding.hpp); else the budget of the tolerance
// (impl/error_budget.hpp) and the outer rule about the centre of sliding (impl/outer_rule.hpp).
template <class T>
ExactResult<T> exact_resultants(const ExactModel<T>& m, const Kinematics<T>& k,
                                const ExactOptions& options = {}) {
  require_finite("vx", value_of(k.vx));
  require_finite("vy", value_of(k.vy));
  require_finite("omega", value_of(k.omega));
  if (!(options.tolerance > 0.0) || !(options.tolerance < 1.0))
    throw InvalidArgument("tolerance", format_value(options.tolerance), "must lie in (0, 1)");
  const detail::ToleranceScale s = detail::tolerance_scale(m, options.tolerance);
  ExactResult<T> out;
  out.error = detail::representation_error_bound(m);
  const double speed = std::hypot(value_of(k.vx), value_of(k.vy));
  const double w_abs = std::abs(value_of(k.omega));
  if (speed == 0.0 && w_abs == 0.0) {
    out.converged = detail::within_tolerance(out.error, s);
    return out;
  }
  const double remainder = detail::first_order_remainder(m);
  if (detail::first_order_suffices(w_abs, m.radius, speed, s.tol, remainder)) {
    out.resultants = detail::sliding_to_first_order(m, k);
    const double eps = w_abs * m.radius / std::max(speed, 1e-300);
    detail::add_first_order_remainder(out.error, remainder, eps, s);
    out.converged = detail::within_tolerance(out.error, s);
    return out;
  }
  const detail::SpinBudget budget = detail::spin_budget(m, s, out.error);
  const detail::AdaptiveResult<T, 3> res = detail::integrate_about_centre(m, k, s.tol, budget);
  detail::add_outer_result(m, res, budget.floor, out.resultants, out.error);
  out.evaluations = res.evaluations;
  // Converged: the rule met its tolerance and the whole estimate meets the requested one.
  out.converged = res.converged && detail::within_tolerance(out.error, s);
  return out;
}

// Convenience overload: builds the model (allocates) and evaluates it.
ExactResult<double> exact_resultants(const ContactPatch& patch, const Kinematics<double>& k,
                                     const ExactOptions& options = {});

}  // namespace contensou
