/// \file
/// The contact patch: geometry, pressure and friction of the exact model (theory.md section 2).
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "contensou/friction/pressure_profile.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou {

/// Friction coefficient falling with the local slip speed w [m/s] (Stribeck-type):
///   f(w) = f_k + (f_s - f_k) exp(-(w / w_s)^delta).
template <class T = double>
struct SlipSpeedFriction {
  T static_coefficient{0.3};   ///< f_s, at w = 0
  T kinetic_coefficient{0.3};  ///< f_k, for w >> w_s
  T reference_speed{1.0};      ///< w_s [m/s]
  T exponent{1.0};             ///< delta
};

/// The falling part of the law, g(w) = exp(-(w / w_s)^delta) (1 at w = 0), so that
/// f(w) = f_k + (f_s - f_k) g(w).
template <class T>
T slip_speed_decay(const SlipSpeedFriction<T>& law, const T& w) {
  using std::exp;
  using std::pow;
  if (!(w > T(0))) return T(1.0);
  const T z = w / law.reference_speed;
  // The exponential (Stribeck) form, exponent 1, is the common case: no pow.
  return value_of(law.exponent) == 1.0 && !has_derivative(law.exponent)
             ? exp(-z)
             : exp(-pow(z, law.exponent));
}

/// f(w) = f_k + (f_s - f_k) g(w), and f_s at w <= 0.
template <class T>
T friction_at(const SlipSpeedFriction<T>& law, const T& w) {
  if (!(w > T(0))) return law.static_coefficient;
  return law.kinetic_coefficient +
         (law.static_coefficient - law.kinetic_coefficient) * slip_speed_decay(law, w);
}

/// Everything the exact model needs: sigma = p* p(rho) (1 + kx x/R + ky y/R) on a disk of radius
/// R, orthotropic Coulomb friction diag(f, kappa f) (seed eq. 1), f optionally f(w).
///
/// A patch is made from what a multibody model knows, the normal load N:
///   ContactPatch::from_normal_load(R, N, profile, f)   p* = N / (2 pi R^2 A^1) derived,
/// or from the reference pressure p* by setting the fields. R, p* and f start unset (NaN): a
/// default-constructed patch is refused by validate() (and so by everything that uses it) until
/// they are set. ContactPatch::seed_tire() is the tire of the seed.
struct ContactPatch {
  /// The value of a field not yet set (NaN): validate() refuses it.
  static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

  double radius_m = kUnset;               ///< R [m]
  double reference_pressure_pa = kUnset;  ///< p* [Pa]; from_normal_load derives it from N
  double friction = kUnset;               ///< f (longitudinal)
  double kappa = 1.0;                     ///< lateral / longitudinal friction ratio
  PressureProfile profile;                ///< shape p(rho) and shift kx, ky (uniform by default)
  std::optional<SlipSpeedFriction<double>> slip_speed_friction;  ///< replaces `friction` if set

  /// The patch of radius R [m] carrying the normal load N [N] with the pressure shape
  /// `profile`: p* = N / (2 pi R^2 A^1) (theory.md section 4; the shift kx, ky carries no load).
  /// Validated: throws InvalidArgument naming the bad argument, or the profile if A^1 <= 0.
  static ContactPatch from_normal_load(double radius_m, double normal_load_n,
                                       PressureProfile profile, double friction,
                                       double kappa = 1.0);

  /// The tire of the seed (seed_tire_patch below).
  static ContactPatch seed_tire();

  /// N = 2 pi R^2 p* A^1 [N] (theory.md section 4); validates the patch first.
  double normal_load() const;
};

/// The tire of the seed (Kireenkov & Zhavoronok 2020): R = 0.087 m (section 4), the Table 1
/// profile, f = 0.3 (Table 3), p* = 210 kPa (so that N = 4535 N, near Table 2's 4.48 kN), no
/// shift (set profile.kx = 0.14 for the rolling tire of seed eq. 10).
ContactPatch seed_tire_patch();

/// Normal load N = 2 pi R^2 p* A^1 [N] (theory.md section 4); validates the patch first.
double normal_load(const ContactPatch& patch);

/// Throws InvalidArgument naming the first bad field (an unset R, p* or f first, then radius,
/// pressure, friction, kappa, shift, slip-speed law), or the scales when they leave the doubles
/// (require_representable_scales).
void validate(const ContactPatch& patch);

/// Throws InvalidArgument unless the load N = 2 pi R^2 p* A^1 and the torque scale f N R lie
/// within 1e-300 ... 1e300, so that finite input gives finite resultants (R = 1e308 is refused
/// here, naming R and p*, instead of returning inf or NaN).
void require_representable_scales(const ContactPatch& patch);

}  // namespace contensou
