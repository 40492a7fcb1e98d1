/// \file
/// What ANY rigid Coulomb patch of radius R can produce, for checking measured rows
/// (vx, vy, omega; Fx, Fy, Mz) before a fit (theory.md sections 1-4, 6).
///
/// Setting (theory.md sections 1-2). A disk of radius R [m]; twist v = (vx, vy) [m/s], omega
/// [rad/s]; slip velocity vc(r) = v + omega z x r; isotropic Coulomb friction (kappa = 1) with
/// any weight w(r) = f(r) sigma(r) >= 0 [Pa] (pressure and coefficient enter only as their
/// product). Friction on the body: F = -int w e dS [N], Mz = int w (r x (-e))_z dS [N m],
/// e = vc/|vc|. eps = |v| / (|omega| R) (+inf at omega = 0). kappa != 1 is out of scope.
///
/// Centre of sliding r_c = (z x v)/omega, |r_c| = eps R. With n(r) = (r - r_c)/|r - r_c|,
/// e = sign(omega) z x n, so |F| = |int w n dS| and (r x (z x n))_z = r.n gives
///   Mz = -sign(omega) int w (r . n) dS.                                               (*)
///
/// 1. Force angle theta [rad], from v to -F, positive counter-clockwise (about +z):
///    theta = atan2((v x (-F))_z, v . (-F)), in (-pi, pi].
///    Any patch: |omega z x r| <= |omega| R, so for eps > 1 every -e lies within asin(1/eps) of
///    -v, and so does their positive combination F: |theta| <= asin(1/eps) (reached by a point
///    contact where r - r_c is tangent to the rim). For eps <= 1, r_c lies in the disk, the
///    -e take every direction: no bound (pi).
///    Axisymmetric centred pressure, w = w(|r|): theta = 0. Proof (v along +x): the reflection
///    x -> -x keeps w and |vc| = |(|v| - omega y, omega x)| and flips vc_y, so Fy = 0; and every
///    ring pushes along -v (P(s) > 0 below), so -F is along +v.
///
/// 2. Torque ratio lambda = |Mz| / (|F| R).
///    Any patch, eps >= 1: lambda <= 1. Proof: with cos b = n . (-r_c/|r_c|) > 0, the chord of
///    the disk along n from r_c gives |r . n| <= R sqrt(1 - eps^2 sin^2 b) <= R cos b; by (*),
///    |Mz| <= R int w cos b dS = R (int w n dS) . (-r_c/|r_c|) <= R |F|. Equality: a point
///    contact at r = +-R r_c/|r_c| (on the rim, F = -e, |r x e| = R). For eps < 1 there is no
///    bound: a ring about r_c inside the disk gives F = 0 and Mz != 0 (for pure spin the
///    uniform patch gives F = 0, |Mz| = (2/3) f N R, theory.md section 3).
///    Axisymmetric centred pressure: a ring of radius a = rho R (0 < rho <= 1) carrying the
///    load W [N] gives F = -W P(s) v/|v|, Mz = -sign(omega) W a Q(s), s = |v|/(|omega| a) =
///    eps/rho, with K(k), E(k) the complete elliptic integrals of MODULUS k and
///    J(k) = int_0^{pi/2} cos^2 t / sqrt(1 - k^2 sin^2 t) dt = (E - (1 - k^2) K) / k^2
///    (J(0) = pi/4, J(1) = 1):
///      s <= 1:  P = (2/pi) s J(s),     Q = (2/pi) E(s);
///      s >= 1:  P = (2/pi) E(1/s),     Q = (2/pi) J(1/s) / s        (so P(1/s) = Q(s)).
///    Derivation (v along +x, omega > 0, ring angle t, D = sqrt(1 + s^2 - 2 s sin t)):
///    P = mean((s - sin t)/D), Q = mean((1 - s sin t)/D), the means over t; both are combinations
///    of mean(D) = (2/pi)(1 + s) E(k1) and mean(1/D) = (2/pi) K(k1)/(1 + s), k1 = 2 sqrt(s)/(1 +
///    s), and the Landen transformation takes them to modulus s (or 1/s). Checked in the tests
///    against a 1-D adaptive quadrature over t, and in the limits P -> s/2, Q -> 1 (s -> 0),
///    P -> 1, Q -> 1/(2 s) (s -> infinity).
///    The ring's ratio rho Q/P = eps E(s)/(s^2 J(s)) (rho >= eps) or eps q^2 J(q)/E(q),
///    q = rho/eps (rho <= eps), increases with rho: h(k) = (1 - k^2) K/E decreases in k (its
///    log-derivative times k (1 - k^2) is E/K + (1 - k^2) K/E - 2 < 0, as (1 - k^2) <= E/K <= 1).
///    So the best ring is the rim ring, rho = 1 (also checked numerically by a rho grid and a
///    local refinement in the tests), and the envelope is
///      Lambda(eps) = E(eps) / (eps J(eps))          for eps <= 1,
///      Lambda(eps) = J(1/eps) / (eps E(1/eps))      for eps >= 1,
///    with Lambda(1) = 1, Lambda(1/eps) = 1/Lambda(eps), Lambda -> 2/eps (eps -> 0) and
///    Lambda -> 1/(2 eps) (eps -> infinity). Any axisymmetric pressure p(rho) >= 0 is a
///    positive mixture of rings whose forces are all along -v and torques all of one sign; the
///    resultants are linear in the pressure, and a ratio of sums of positive terms is at most the
///    largest ratio of the terms: lambda <= Lambda(eps). Note Lambda > 1 for eps < 1 (the
///    uniform patch itself has lambda > 1 there; theory.md section 3).
///
/// 3. Torque sign. Q(s) > 0 for every s (E - (1 - k^2) K > 0), so an axisymmetric centred
///    pressure never drives the spin: Mz omega <= 0. A shifted pressure can: with
///    sigma = p* p(rho)(1 + ky y/R) (theory.md section 2), v along +x and omega -> 0,
///    Mz -> int w y dS = pi ky f p* R^3 A^3 > 0 for ky > 0 (theory.md section 4), while omega > 0.
///
/// Units: SI throughout. The bounds are dimensionless (angles in radians); the check takes the
/// row's own units for (Fx, Fy) [N] and Mz [N m], and R [m].
#pragma once

#include <limits>
#include <numbers>

#include "contensou/friction/kinematics.hpp"

namespace contensou {

/// eps = |v| / (|omega| R), the ratio of the sliding speed to the spin speed at the rim
/// (dimensionless, >= 0; +inf at omega = 0, including the rest). Throws InvalidArgument for a
/// non-finite vx, vy, omega, or a radius_m [m] that is not positive and finite.
double sliding_spin_ratio(const Kinematics<double>& k, double radius_m);

/// Any patch: the largest |theta| [rad] of the force's angle to -v (header, point 1):
/// asin(1/eps) for eps > 1 (0 at eps = +inf), pi (no bound) for eps <= 1. Throws
/// InvalidArgument for eps negative or NaN (+inf is allowed).
double force_angle_bound(double eps);

/// Any patch: the largest torque ratio |Mz| / (|F| R) (header, point 2): 1 for eps >= 1,
/// +inf (no bound) for eps < 1. Throws InvalidArgument for eps negative or NaN.
double any_patch_torque_ratio_bound(double eps);

/// The resultants of a ring of radius a carrying the load W, per unit W f (header, point 2).
struct RingResultants {
  double force = 0.0;   ///< P(s) = |F| / (f W), F along -v (dimensionless, in [0, 1])
  double torque = 0.0;  ///< Q(s) = |Mz| / (f W a), Mz of sign -sign(omega) (dimensionless)
};

/// P(s) and Q(s) of a ring, s = |v| / (|omega| a) >= 0 (closed forms, header point 2; s = 0
/// pure spin: P = 0, Q = 1; s = +inf pure sliding: P = 1, Q = 0). Relative accuracy about
/// 1e-13. Throws InvalidArgument for s negative or NaN.
RingResultants ring_resultants(double s);

/// The torque ratio |Mz| / (|F| R) of a ring of radius rho R, 0 < rho <= 1, on a patch of
/// radius R at eps = |v| / (|omega| R) >= 0: rho Q(eps/rho) / P(eps/rho) (header, point 2;
/// +inf at eps = 0, 0 at eps = +inf). It increases with rho. Throws InvalidArgument for eps
/// negative or NaN, or rho outside (0, 1].
double ring_torque_ratio(double eps, double rho);

/// Lambda(eps): the largest |Mz| / (|F| R) of any axisymmetric, centred pressure p(rho) >= 0
/// with isotropic Coulomb friction, at eps = |v| / (|omega| R) (header, point 2): the rim
/// ring's ratio, in closed form (relative accuracy about 1e-13; no table needed: two elliptic
/// integrals). Values: Lambda(0.5) = 3.6118, Lambda(1) = 1, Lambda(2) = 0.27687,
/// Lambda(10) = 0.050188; +inf at eps = 0, 0 at eps = +inf. Throws InvalidArgument for eps
/// negative or NaN.
double axisymmetric_torque_ratio_envelope(double eps);

/// Tolerances of check_row_against_patches for measured (noisy) rows; the defaults check the
/// bounds as they are.
struct EnvelopeCheckOptions {
  /// A force angle is flagged only beyond bound + this [rad] (>= 0).
  double angle_margin_rad = 0.0;
  /// A torque ratio is flagged only beyond bound * (1 + this) (>= 0, dimensionless).
  double ratio_margin = 0.0;
  /// The torque sign is checked only where |omega| R >= this * |v| (>= 0; 0: wherever
  /// omega != 0). Near omega = 0 a tiny shift of the pressure, or noise, sets the sign of Mz.
  double min_spin_fraction = 1e-6;
};

/// The verdict on one row (check_row_against_patches). Every number is finite or +-inf, never
/// NaN; a value whose check was not made is 0.
struct RowEnvelopeCheck {
  double eps = 0.0;      ///< |v| / (|omega| R), +inf at omega = 0 (dimensionless)
  bool at_rest = false;  ///< v = 0 and omega = 0: nothing is checked

  bool angle_checked = false;    ///< Fx, Fy measured, |v| > 0 and |F| > 0
  double force_angle_rad = 0.0;  ///< theta, from v to -F, counter-clockwise positive [rad]
  double force_angle_bound_rad = std::numbers::pi;  ///< force_angle_bound(eps) [rad]

  bool torque_ratio_checked = false;  ///< Fx, Fy, Mz measured, |F| > 0, not at rest
  double torque_ratio = 0.0;          ///< |Mz| / (|F| R) (dimensionless)
  /// any_patch_torque_ratio_bound(eps): 1, or +inf for eps < 1.
  double any_patch_torque_bound = std::numeric_limits<double>::infinity();
  /// axisymmetric_torque_ratio_envelope(eps) (+inf at eps = 0).
  double axisymmetric_torque_bound = std::numeric_limits<double>::infinity();

  /// Mz measured, omega != 0 and |omega| R >= min_spin_fraction |v|.
  bool torque_sign_checked = false;

  /// No rigid isotropic Coulomb patch of radius R gives this row: the angle beyond its bound
  /// (eps > 1), or the torque ratio above 1 (eps >= 1).
  bool outside_any_patch = false;
  /// The torque ratio is above Lambda(eps): no axisymmetric centred pressure gives it.
  bool above_axisymmetric_torque = false;
  /// Mz omega > 0: the friction torque drives the spin, which no axisymmetric centred
  /// pressure does (a shifted one can).
  bool torque_drives_spin = false;
};

/// Checks one measured row against what rigid Coulomb patches of radius R can produce
/// (header, points 1-3). Fx, Fy [N] and Mz [N m] act on the body (theory.md section 1); NaN
/// marks a channel not measured (theory.md section 6), and the checks that need it are skipped
/// (their *_checked flag false). Throws InvalidArgument naming the argument for a non-finite vx,
/// vy or omega, an infinite Fx, Fy or Mz, a radius_m [m] not positive and finite, or a negative
/// or non-finite option.
RowEnvelopeCheck check_row_against_patches(const Kinematics<double>& k, double Fx, double Fy,
                                           double Mz, double radius_m,
                                           const EnvelopeCheckOptions& options = {});

}  // namespace contensou
