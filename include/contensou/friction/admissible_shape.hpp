/// \file
/// Which fractional laws a patch can produce: the shapes a, m and the torque ratio M0 / (F0 R)
/// that some non-negative pressure on the patch gives (theory.md section 4).
///
/// With the radial moments A^n = integral_0^1 p(rho) rho^n d rho of a pressure p >= 0 (the moments
/// mu_n of the measure p(rho) d rho on [0, 1]), the law's constants are
/// ~~~
///   t = A^1 / A^0 = sqrt(a) / 2,   q = A^2 / A^1 = M0 / (F0 R),   r = A^3 / A^2 = 2 / sqrt(m).
/// ~~~
/// Four numbers mu_0..mu_3 are the moments of a non-negative measure on [0, 1] exactly when the
/// Hankel matrices of x d mu and of (1 - x) d mu are positive semidefinite (the truncated
/// Hausdorff moment problem of odd order, Krein & Nudelman 1977, ch. III):
/// ~~~
///   [mu1 mu2; mu2 mu3] >= 0                         <=>  q <= r
///   [mu0-mu1 mu1-mu2; mu1-mu2 mu2-mu3] >= 0         <=>  t <= 1, r <= 1,
///                                                        (1 - t) q (1 - r) >= t (1 - q)^2
/// ~~~
/// (with mu0 = 1, mu1 = t, mu2 = t q, mu3 = t q r). On their own, a <= 4 (t <= 1) and m >= 4
/// (r <= 1); a and m together need t <= r, i.e. a m <= 16 (a two-point measure at 0 and r
/// reaches every t <= r); the torque ratio then lies in [q_min, r], q_min the smaller root of
/// t q^2 - (2 t + (1 - t)(1 - r)) q + t = 0. A ring of pressure at radius rho0 R gives
/// t = q = r = rho0 (on the boundary); uniform pressure t = 1/2, q = 2/3, r = 3/4.
#pragma once

#include <optional>
#include <string>

namespace contensou {

/// Where a law's shape stands against what non-negative pressures give.
struct ShapeAdmissibility {
  bool admissible = true;  ///< some p >= 0 on the patch gives these a, m (and torque ratio)
  double t = 0.0;          ///< sqrt(a) / 2 = A^1 / A^0
  double r = 0.0;          ///< 2 / sqrt(m) = A^3 / A^2
  /// The torque ratio q = M0 / (F0 R) if given; its admissible range [q_min, q_max] for these
  /// a, m (empty when a, m are themselves inadmissible).
  std::optional<double> q;
  double q_min = 0.0;  ///< the least M0 / (F0 R) that fits a and m
  double q_max = 0.0;  ///< the most M0 / (F0 R) that fits a and m (= r)
  /// Why not, in words with the numbers ("m = 0.25 < 4: ..."); "" when admissible.
  std::string reason;
  /// For an admissible shape on the edge of the set (within the tolerance) by a joint condition:
  /// which, in words ("a m = 16: ..."); "" inside, or when only a = 4 or m = 4 holds it.
  std::string edge;
};

/// Checks a and m (and, when given, the torque ratio M0 / (F0 R), R the patch radius) against
/// the moment conditions above, to a relative tolerance of 1e-6 (a fit held on the edge by a
/// stiff penalty ends within about 1e-8 of it). a, m and the ratio must be
/// finite and positive (InvalidArgument otherwise).
ShapeAdmissibility shape_admissibility(double a, double m,
                                       std::optional<double> torque_ratio = std::nullopt);

}  // namespace contensou
