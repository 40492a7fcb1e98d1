/// \file
/// The rigid patch that predicts the motion a force causes: a Coulomb patch whose limit surface
/// exists by construction (a non-negative pressure, the exact integrals of theory.md section 2),
/// identified from measured (force, motion) pairs by the directions alone, for the planar
/// pushing field's question: which motion does a measured friction wrench belong to?
///
/// The pressure is the radial power law with a linear shift on a centred disk of radius
/// a = c R inside the body's radius R (power_profile):
/// ~~~
///   sigma(x, y) = p* (r / a)^n (1 + kx x / a + ky y / a),   n even,  kx^2 + ky^2 <= 1,
/// ~~~
/// which covers the physical alternatives to a rig's offsets (issue of evidence,
/// docs/real-data.md): a centre of pressure off the body's centre, at
///   (x_c, y_c) = (kx, ky) a A^3 / (2 A^1) = (kx, ky) a (n + 2) / (2 (n + 4)),
/// a contact smaller than the body (c < 1) and a pressure concentrated towards the rim (n > 0:
/// a machined plate that touches near its edge). Its friction wrench at a twist s is
/// -grad D(s), D the dissipation (limit_surface.hpp), and the motion of a measured wrench w is
/// the normal of the surface at w's radial projection, -(gauge normal) (maximum dissipation).
///
/// Identified by a coarse search: coordinate passes over (n, c) together, then (kx, ky), each the
/// grid value with the least median angle between the motion the patch gives each row's
/// measured wrench and the row's measured motion, in the scaled twist (vx, vy, omega R); the
/// force scale f N then by least squares of the measured wrenches on the patch's wrenches at
/// the measured motions. The directions alone choose the shape, as the field's models are judged.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/limit_surface.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// A contact wider than the body (a = c R, c > 1) that places the measured motions better than
/// every patch on the body: evidence that the bound c <= 1 holds the search, i.e. that the data
/// carry more torque per spin than any pressure under the body gives (the torque or the spin
/// measured, or a torque from outside the contact). Reported, never used to predict.
struct WiderContact {
  double radius_ratio = 1.0;      ///< c > 1 of the best wider contact
  int exponent = 0;               ///< its n (the patch's kx, ky kept)
  double median_angle_deg = 0.0;  ///< on the rows the patch was chosen on [deg]
};

/// The identified patch (header comment): shape, shift, size and force scale.
struct RigidPatch {
  double radius_m = 0.0;              ///< R: the body's radius [m] (of the scaled twist)
  double contact_radius_ratio = 1.0;  ///< c = a / R in (0, 1]
  int exponent = 0;                   ///< n of (r / a)^n: even, in [0, kMaxPowerProfileExponent]
  double kx = 0.0;                    ///< pressure shift along x, relative to a
  double ky = 0.0;                    ///< pressure shift along y, relative to a
  double force_scale_n = 1.0;         ///< f N [N]: the sliding force
  double median_angle_deg = 0.0;      ///< on the rows it was chosen on [deg]
  int rows = 0;                       ///< the rows it was chosen on
  /// Set when the search ends on c = 1 and a wider contact's median angle is smaller by more
  /// than RigidPatchOptions::wider_margin (relative): the bound, not the data, holds c.
  std::optional<WiderContact> wider_contact;
};

/// Throws InvalidArgument naming the first bad field: R not positive and finite, c outside
/// (0, 1], n odd or outside [0, kMaxPowerProfileExponent], kx^2 + ky^2 > 1 (a negative pressure
/// on the rim) or f N not positive and finite.
void validate(const RigidPatch& patch);

/// The centre of pressure (x_c, y_c) [m] (header comment).
Eigen::Vector2d centre_of_pressure_m(const RigidPatch& patch);

/// The patch's limit surface (validates the patch first). tolerance as make_limit_surface.
LimitSurface limit_surface_of(const RigidPatch& patch, double tolerance = 1e-8);

/// The friction wrench (Fx, Fy, Mz) [N, N, N m] of the patch at a twist (vx, vy, omega)
/// [m/s, m/s, rad/s]: -grad D (zero at rest).
Eigen::Vector3d rigid_patch_wrench(const LimitSurface& surface, const Eigen::Vector3d& twist);

/// The motion a measured friction wrench (Fx, Fy, Mz) causes: the unit scaled twist
/// (vx, vy, omega R) with R = body_radius_m, the normal of the surface at the wrench's radial
/// projection (NaN for a zero or non-finite wrench).
Eigen::Vector3d rigid_patch_motion(const LimitSurface& surface, double body_radius_m,
                                   const Eigen::Vector3d& wrench);

/// The search's grids and effort.
struct RigidPatchOptions {
  std::vector<int> exponents{0, 2, 4, 8, 16, 32, 64, 128};  ///< n (even)
  std::vector<double> shifts{-0.4, -0.2, 0.0, 0.2, 0.4};    ///< kx and ky (kx^2 + ky^2 <= 1)
  std::vector<double> radius_ratios{0.5, 0.6, 0.7, 0.8, 0.9, 1.0};  ///< c
  /// c > 1 tried (with every exponent) when the search ends on c = 1 (WiderContact); empty: none
  std::vector<double> wider_radius_ratios{1.1, 1.2, 1.3, 1.4, 1.5};
  double wider_margin = 0.05;  ///< relative gain in the median angle that counts, in [0, 1)
  int passes = 2;              ///< coordinate passes, at least 1
  int max_rows = 1000;         ///< rows the search uses (spread evenly over the data), at least 3
  double tolerance = 1e-6;     ///< of the exact integrals in the search (relative to f N)
};

/// The patch of `data` (rows with all three channels and some motion and force) for a body of
/// radius `radius_m` [m]. Throws InvalidArgument for bad options or a radius that is not
/// positive, and for data with fewer than 3 such rows (naming how many there are).
RigidPatch fit_rigid_patch(const MeasuredData& data, double radius_m,
                           const RigidPatchOptions& options = {});

/// The patch in words: "p ~ (r/a)^8 (1 + 0.2 x/a - 0.2 y/a) on a = 0.9 R = 47.3 mm; centre of
/// pressure (+2.8, -2.8) mm; f N = 2.61 N; motion from the force: median angle 9.6 deg over
/// 300 rows".
std::string rigid_patch_text(const RigidPatch& patch);

}  // namespace contensou
