/// \file
/// What the data can determine, before any fit: each row checked against every rigid Coulomb
/// patch of the given radius (coulomb_envelope.hpp), the shares of rows outside, and what
/// follows in plain words.
///
/// Three checks a row (theory.md sections 1-4; eps = |v| / (|omega| R)):
///  - the force's angle to -v: 0 for any pressure centred on the patch and axisymmetric, at most
///    asin(1/eps) for any pressure on the patch (eps > 1); its median over the sliding rows
///    (eps > 3) with a distribution-free 95 % interval is what a slip-angle offset would move;
///  - the torque ratio |Mz| / (|F| R) against the rim ring's Lambda(eps), the most any centred
///    axisymmetric pressure gives, and against 1, the most any pressure gives (eps >= 1), over
///    the rows where the coupling shows, 1 < eps < 10;
///  - the torque's sign against the spin's: a centred patch never drives the spin.
/// A row is counted outside a bound only when it is beyond it by the margin (kCheckMargin), so
/// that noise at the bound is not counted.
#pragma once

#include <string>
#include <vector>

#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// A row counts as outside a torque bound beyond bound * (1 + kCheckMargin), outside the angle
/// bound beyond bound + kCheckMargin rad (about 3 degrees).
inline constexpr double kCheckMargin = 0.05;
/// A share of rows at or above this is reported as a finding ("the data say ...").
inline constexpr double kFindingShare = 0.05;

/// The checks over the data.
struct DataChecks {
  int rows = 0;           ///< rows with motion
  int coupling_rows = 0;  ///< rows with 0.1 <= psi = |v| / (|omega| R) <= 10
  /// Force angle (Fx and Fy measured, |v| > 0): the rows with eps > 1 checked.
  int angle_rows = 0;
  /// Of those, the rows whose force is turned beyond asin(1/eps) (no isotropic patch of radius
  /// R gives them).
  int angle_outside = 0;
  /// The median force angle over the rows with eps > 3 [deg] (NaN when none).
  double median_angle_deg = 0.0;
  double median_angle_low_deg = 0.0;   ///< its distribution-free 95 % interval's low end [deg]
  double median_angle_high_deg = 0.0;  ///< and its high end [deg]
  int sliding_rows = 0;                ///< the rows with eps > 3 the median is taken over
  /// Torque ratio: the rows with 1 < eps < 10 and all channels, checked.
  int ratio_rows = 0;
  /// Of those, the rows above the rim ring's ratio (no centred axisymmetric pressure gives them).
  int above_axisymmetric = 0;
  /// Of those, the rows above 1 (no pressure on the patch gives them).
  int above_any_patch = 0;
  /// Torque sign: the rows checked (Mz and omega measured, |omega| R >= 0.1 |v|).
  int sign_rows = 0;
  int drives_spin = 0;  ///< of those, the rows whose torque drives the spin
  /// What follows, in plain words, one sentence a finding (empty: nothing the checks object to).
  std::vector<std::string> findings;
  /// Whether the median force angle is distinguishable from zero (its interval excludes 0): the
  /// evidence a slip-angle offset or a crosstalk between the forces would need.
  bool angle_offset_shown() const;
};

/// The checks of every row of `data` on a patch of radius `radius_m` [m]. Throws InvalidArgument
/// for a radius that is not positive and finite.
DataChecks check_data(const MeasuredData& data, double radius_m);

/// The checks as the report's lines: the shares, then the findings.
std::string data_checks_text(const DataChecks& checks);

}  // namespace contensou
