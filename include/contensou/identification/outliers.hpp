/// \file
/// Gross errors in measured diagrams (a sign flip, a spike of tens of sigma from a loose
/// connector or a logging slip): found in a fit's residual, named, and left out of the fit that
/// is reported, so that its parameters and intervals are those of the clean rows.
///
/// The rule (documented in docs/identification.md): in each channel, the residual
/// e_i = y_i - model_i of a row is compared with the median of those of its four neighbours in
/// kinematic order (two before, two after, where the channel was measured; rows ordered by load,
/// spin sense, sliding direction, then v / |omega| and |omega|, whatever the order of the file)
/// that are in its regime (same spin sense, sliding direction within 0.2 rad, v/omega within a
/// factor 5; or all at rest), d_i = e_i - median; a row with fewer than two such neighbours is
/// not judged. A smooth misfit of the model (a missing effect) hardly changes from one row to the
/// next and cancels in d; an isolated glitch does not. The row's own residual must carry at least
/// half of d, with its sign: a good row beside glitched ones (a run of sign flips at a sweep's
/// peak) differs from them by their residual, not its own, and is not named. The model is a
/// robust fit (Cauchy loss unless the user chose a robust loss, identify.hpp), which glitches do
/// not pull towards them.
/// The robust noise scale at the value is sigma = 1.4826 median|d| / 1.14 over the 16 values up
/// to it and over the 16 from it on, the larger (local, because noise changes along a file: it
/// grows with the load, sweeps in other directions have other scales; 1.14: d of Gaussian noise
/// has 1.3 times its variance, the median of four adding 0.3). A value with |d| > 8 sigma is a
/// gross error: a scale from 16 values is uncertain by about 20 %, and 8 keeps Gaussian noise
/// below the threshold with room for that (none in 500 clean rows of the tests).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contensou/identification/fit.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// The threshold of the rule, in robust noise scales: a value with |d| above it is a gross error.
inline constexpr double kOutlierThresholdSigma = 8.0;

/// A gross error: one measured value of one row.
struct Outlier {
  int point = 0;                ///< index into the data's points
  int line = 0;                 ///< line in the file (0: not from a file)
  int channel = 0;              ///< 0 Fx, 1 Fy, 2 Mz
  double value = 0.0;           ///< the measured value [N or N m]
  double residual_sigma = 0.0;  ///< d_i / sigma, signed
  std::string where;            ///< "data.csv:17" (point_location; "" when not set)
  std::string file_value;       ///< the value in its file's unit when it is not SI ("1.2 kN")
  /// "data.csv:17 Fy_N +41.2 sigma (1200 N = 1.2 kN)"; when `where` is empty, the place is
  /// `source`:line, or "point N" without a line.
  std::string describe(const std::string& source) const;
};

/// The gross errors in `data` against the model values `prediction` (one per point), most
/// extreme first. A channel with fewer than 8 measured values is not examined; the local
/// noise scale is at least 1e-9 times the channel's largest |y| (exact data have no scatter).
/// Empty when `prediction` does not have one value per point.
std::vector<Outlier> find_outliers(const MeasuredData& data,
                                   const std::vector<Resultants<double>>& prediction,
                                   double threshold_sigma = kOutlierThresholdSigma);

/// The scatter of each channel's residual between neighbouring rows (the rule's d, in kinematic
/// order): the rms of d over its smaller 98 %, / 1.067 (what that is for Gaussian noise of unit
/// scale), a noise scale comparable with the
/// residual's rms that a smooth misfit of the model does not inflate (0 for a channel with fewer
/// than four such differences, and for every channel when `prediction` does not have one value
/// per point). A residual whose rms is several times it is a misfit, not noise. With
/// `row_scale` (the noise scale of channel c at point i, for noise that grows with the value),
/// the 2 % left out are the largest d / scale, not the largest d: the quiet rows' glitches, not
/// the loud rows' noise (which the residual's rms counts too).
std::array<double, kChannels> neighbour_scatter(
    const MeasuredData& data, const std::vector<Resultants<double>>& prediction,
    const std::function<double(int c, std::size_t i)>& row_scale = {});

/// The data with the outlying values marked not measured (a row left with no channel is
/// dropped; an outlier whose point or channel is out of range is ignored).
MeasuredData without_outliers(const MeasuredData& data, const std::vector<Outlier>& outliers);

}  // namespace contensou
