/// \file
/// Fractional (Pade-type) laws of coupled dry friction (seed eqs. 5-7, 13; theory.md section 4),
/// in vector form for any sliding direction, with analytic Jacobians.
///
/// With u = omega R, v = |v|, eps the regularisation speed and k = (kx, ky):
///   F  = -F0 (vx, kappa vy) / S_a                                   S_a = sqrt(v^2 + a u^2 +
///   eps^2)
///        -(M0 / 2R) [ g2 (z x k) + (g1 - g2) (k.v)(z x v) / v^2 ]
///   Mz = -M0 (1 + kappa)/2 u / S_m + Mk (vx ky - kappa vy kx) v^2 / S_k^3
///   g1 = u / sqrt(s0 + m v^2 / 4),  g2 = u s0 / (s0 + c v^2)^(3/2),  s0 = u^2 + eps^2,
///   S_m = sqrt(u^2 + m v^2 + eps^2),  S_k = sqrt(v^2 + a_k u^2 + eps^2).
/// g1 = g2 at v = 0, so (g1 - g2)/v^2 is smooth there: it is evaluated without cancellation as
///   (g1 - g2)/v^2 = u P / (S1 S2^3 (S2^3 + s0 S1)),  P = s0^2 (3c - m/4) + 3 s0 c^2 v^2 + c^3 v^4
/// (S1, S2 the two roots above), and the law is smooth through v = 0 for every direction of v.
/// For sliding along x with the shift along x this is the seed's law (5) exactly:
///   F_par = F0 v / sqrt(v^2 + a u^2),  Fy = -kx M0 u / (2R sqrt(u^2 + m v^2/4)),
///   Mz = -M0 u / sqrt(u^2 + m v^2).
/// The shift across the sliding direction (k_perp = k . (z x v)/v) adds two terms the seed does
/// not have: a force along v that is sign(omega) (M0/2R) k_perp at pure spin and decays like
/// (u/v)^3 (shape c), and the pure-sliding torque Mk k_perp, Mk = pi f R^3 p* A^3, which the
/// exact integrals show to vanish like (v/u)^3 at small sliding (shape a_k; 1 for uniform
/// pressure). Every term is bounded, and the law is smooth for eps > 0: no NaN or Inf for finite
/// input. Evaluation checks the law's fields and the velocities (InvalidArgument naming the first
/// bad one): a NaN velocity, kappa < 0 (friction that generates energy), a <= 0 or eps = 0 never
/// give a silent NaN.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou {

/// The parameters of the fractional law (seed eqs. 5-7; theory.md §4), usually from a patch
/// (fractional_law_from_patch). T = double, or ceres::Jet for fits.
template <class T = double>
struct FractionalLaw {
  T F0{0};              ///< sliding force scale f N [N]
  T M0{0};              ///< spin torque scale 2 pi f R^3 p* A^2 [N m]
  T a{1};               ///< sliding shape (2 A^1/A^0)^2
  T m{64.0 / 9.0};      ///< spin shape (2 A^2/A^3)^2
  T kx{0};              ///< pressure shift along x (seed eq. 9)
  T ky{0};              ///< pressure shift along y (seed eq. 9)
  T kappa{1};           ///< lateral / longitudinal friction ratio
  T c{4};               ///< shape of the cross-shift force, (4 A^2/A^5)^(2/3)
  T Mk{0};              ///< cross-shift sliding torque pi f R^3 p* A^3 [N m]
  T a_k{1};             ///< shape of the cross-shift torque (exact small-sliding asymptote)
  double radius = 0.1;  ///< R [m]
  double regularization_speed = 1e-4;  ///< eps [m/s]
};

/// Asymptote-matched coefficients from a patch (theory.md section 4): a, m, c from the
/// moments A^n; a_k from the exact integrals' small-sliding asymptote.
FractionalLaw<double> fractional_law_from_patch(const ContactPatch& patch);

/// a and m (and c, a_k when the patch has a shift) fitted by least squares to the exact
/// integrals over psi = v/u in [psi_min, psi_max] (log-spaced, n points), sliding along x.
FractionalLaw<double> fractional_law_fitted(const ContactPatch& patch, double psi_min = 1e-2,
                                            double psi_max = 1e2, int n = 41);

/// Throws InvalidArgument naming the first bad parameter; also a pressure shift |(kx, ky)| >= 1,
/// under which the pressure would be negative on part of the patch (evaluation itself, used
/// inside fits, checks the rest only).
void validate(const FractionalLaw<double>& law);

namespace detail {
/// The checks of validate(), on the values of any scalar (double or ceres::Jet).
template <class T>
void check_law(const FractionalLaw<T>& p) {
  require_non_negative("F0", value_of(p.F0));
  require_non_negative("M0", value_of(p.M0));
  require_positive("a", value_of(p.a));
  require_positive("m", value_of(p.m));
  require_positive("c", value_of(p.c));
  require_positive("a_k", value_of(p.a_k));
  require_positive("kappa", value_of(p.kappa));
  require_finite("kx", value_of(p.kx));
  require_finite("ky", value_of(p.ky));
  require_non_negative("Mk", value_of(p.Mk));
  require_positive("radius", p.radius);
  require_positive("regularization_speed", p.regularization_speed);
  // Finite in, finite out: the largest force and torque the law returns (the shift terms'
  // factors are bounded, by 4 here with room to spare) and its Jacobian, at most these over the
  // regularisation speed (times R for omega), must be doubles; refused with the range otherwise.
  const double kappa = value_of(p.kappa),
               shift = std::abs(value_of(p.kx)) + std::abs(value_of(p.ky));
  const double force =
      value_of(p.F0) * std::max(1.0, kappa) + value_of(p.M0) / (2.0 * p.radius) * 4.0 * shift;
  const double torque =
      value_of(p.M0) * 0.5 * (1.0 + kappa) + value_of(p.Mk) * 4.0 * shift * std::max(1.0, kappa);
  const double slope =
      16.0 * std::max(force, torque) * std::max(1.0, p.radius) / p.regularization_speed;
  if (!(slope < std::numeric_limits<double>::max()))
    throw InvalidArgument("F0, M0, radius",
                          format_value(value_of(p.F0)) + " N, " + format_value(value_of(p.M0)) +
                              " N m, " + format_value(p.radius) + " m",
                          "too large: the forces, torques or derivatives (up to 16 max(F0, M0) "
                          "max(1, R) / regularization_speed) would overflow a double; check the "
                          "radius, or use larger units (kN, kN m)");
}

/// The kinematics finite, and the rim speed omega R a double (omega = 1e300 on R = 1e10 is
/// refused, not NaN).
inline void check_kinematics(double vx, double vy, double omega, double radius) {
  require_finite("vx", vx);
  require_finite("vy", vy);
  require_finite("omega", omega);
  if (!(std::abs(omega) * radius <= std::numeric_limits<double>::max()))
    throw InvalidArgument("omega", format_value(omega),
                          "times the radius " + format_value(radius) +
                              " m overflows a double (the rim speed omega R)");
}
}  // namespace detail

/// Every term is homogeneous of degree 0 in (v, u, eps): the law is evaluated on velocities
/// divided by s = max(|vx|, |vy|, |u|, eps), which keeps squares finite for any finite input.
template <class T>
Resultants<T> fractional_resultants(const FractionalLaw<T>& p, const Kinematics<T>& k0) {
  using std::sqrt;
  detail::check_law(p);
  detail::check_kinematics(value_of(k0.vx), value_of(k0.vy), value_of(k0.omega), p.radius);
  const double R = p.radius;
  const double s = std::max({std::abs(value_of(k0.vx)), std::abs(value_of(k0.vy)),
                             std::abs(value_of(k0.omega)) * R, p.regularization_speed});
  const Kinematics<T> k{k0.vx / s, k0.vy / s, k0.omega / s};
  const double e2 = (p.regularization_speed / s) * (p.regularization_speed / s);
  const T u = k.omega * R;
  const T U = u * u;
  const T q = k.vx * k.vx + k.vy * k.vy;
  const T s0 = U + e2;
  const T Sa = sqrt(q + p.a * U + e2);
  const T Sm = sqrt(U + p.m * q + e2);
  const T S1 = sqrt(s0 + 0.25 * p.m * q);
  const T S2sq = s0 + p.c * q;
  const T S23 = S2sq * sqrt(S2sq);
  const T g2 = u * s0 / S23;
  // (g1 - g2) / q without cancellation (header comment).
  const T P =
      s0 * s0 * (3.0 * p.c - 0.25 * p.m) + 3.0 * s0 * p.c * p.c * q + p.c * p.c * p.c * q * q;
  const T Gq = u * P / (S1 * S23 * (S23 + s0 * S1));
  const T h = Gq * (p.kx * k.vx + p.ky * k.vy);
  const T half_m0_r = p.M0 / (2.0 * R);
  Resultants<T> r;
  r.Fx = -p.F0 * k.vx / Sa + half_m0_r * (g2 * p.ky + h * k.vy);
  r.Fy = -p.F0 * p.kappa * k.vy / Sa - half_m0_r * (g2 * p.kx + h * k.vx);
  const T Sk2 = q + p.a_k * U + e2;
  r.Mz = -p.M0 * 0.5 * (1.0 + p.kappa) * u / Sm +
         p.Mk * (k.vx * p.ky - p.kappa * k.vy * p.kx) * q / (Sk2 * sqrt(Sk2));
  return r;
}

/// The law and its Jacobian d(Fx, Fy, Mz)/d(vx, vy, omega), analytic.
struct FractionalWithJacobian {
  Resultants<double> resultants;  ///< Fx, Fy, Mz [N, N, N m]
  Eigen::Matrix3d jacobian;       ///< rows Fx, Fy, Mz; columns vx, vy, omega
};
/// The fractional law and its analytic Jacobian at k (fractional_resultants' contract).
FractionalWithJacobian fractional_resultants_with_jacobian(const FractionalLaw<double>& p,
                                                           const Kinematics<double>& k);

}  // namespace contensou
