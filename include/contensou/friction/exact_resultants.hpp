/// \file
/// Exact resultants of coupled sliding-spinning dry friction over a circular patch
/// (theory.md §2; seed eqs. 1-4), by adaptive cubature with an error estimate:
///
///     F  = integral_S tau dS,   Mz = integral_S (x tau_y - y tau_x) dS,
///     tau = -sigma(r) f(|vc|) diag(1, kappa) vc / |vc|,   vc = v + omega z x r
///
/// (or the associated orthotropic law, ExactModel::associated_orthotropy). Units SI: velocities
/// [m/s], spin [rad/s], forces [N], torque [N m]. The polar cubature about the centre of sliding,
/// the closed-form chord integrals and the error budget: docs/theory.md §7.2. The steps are in
/// impl/ (internal; docs/architecture.md lists them); the model is exact_model.hpp.
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

/// How exact_resultants integrates.
struct ExactOptions {
  /// Requested accuracy, relative to f N for the forces and f N R for the torque.
  double tolerance = 1e-10;
};

/// The exact resultants and their error estimate.
template <class T = double>
struct ExactResult {
  Resultants<T> resultants;  ///< Fx, Fy, Mz [N, N, N m]
  ResultantErrors error;     ///< estimated absolute error of each component [N, N, N m]
  int evaluations = 0;       ///< rays evaluated (outer integrand evaluations)
  /// true only if every component of `error` meets the requested tolerance (tol f N, tol f N R;
  /// representation error and floor included); false if the estimate exceeds it (the interval
  /// budget ran out, or the profile's representation alone is coarser than the tolerance).
  bool converged = true;
};

/// Exact Fx, Fy, Mz for a model and kinematics, to the requested tolerance, with an error
/// estimate; converged is true only if every component of that estimate meets the tolerance.
/// Throws InvalidArgument for non-finite velocities. The steps: at rest zero (0 is in Coulomb's
/// set); pure sliding, or a centre of sliding so far that the first order in omega meets the
/// tolerance, in closed form (impl/pure_sliding.hpp); else the budget of the tolerance
/// (impl/error_budget.hpp) and the outer rule about the centre of sliding (impl/outer_rule.hpp).
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

/// Convenience overload: builds the model (allocates) and evaluates it.
ExactResult<double> exact_resultants(const ContactPatch& patch, const Kinematics<double>& k,
                                     const ExactOptions& options = {});

}  // namespace contensou
