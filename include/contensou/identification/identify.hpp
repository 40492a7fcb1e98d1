/// \file
/// One identification as contensou-identify and Python's contensou.identify() run it: gross
/// errors found and left out (outliers.hpp), then the fit of the fractional law alone or the
/// closed loop on the clean rows.
#pragma once

#include <optional>
#include <vector>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/measured_data.hpp"
#include "contensou/identification/outliers.hpp"

namespace contensou {

/// What identify() does: the fit's options, the closed loop's (or none) and the gross errors'
/// treatment.
struct IdentifyOptions {
  IdentificationOptions fit;              ///< the fit's options (radius, load, profile, noise, ...)
  std::optional<ClosedLoopOptions> loop;  ///< nullopt: the fit of the fractional law only
  bool leave_out_outliers = true;         ///< find gross errors and fit without them
  /// Above this many rows, the robust fit that judges gross errors and the loop's model selection
  /// use a stratified sample of about this many (sweeps.hpp: stratified_sample); the gross errors
  /// are judged, and the reported fits made, on every row. 0: every row always.
  std::size_t selection_rows = 4000;
  /// With the loop: how many subsamples (about 80 % of the rows each, whole sweeps drawn at
  /// random) the loop is run again on; an effect accepted in fewer than kStableShare of them is
  /// unstable, reported as such and left out (the loop run once more without it). 0: none.
  int resamples = 0;
  /// Identify the rigid patch that gives the motion from the force (rigid_patch.hpp) on the
  /// fitted rows with all three channels, and attach it to the final model (its
  /// ModelSpec::motion_patch). Skipped, without a word, on data with fewer than 3 such rows.
  bool motion_patch = true;
};

/// The result of identify(): the gross errors left out, the data fitted and the fits.
struct Identification {
  std::vector<Outlier> outliers;  ///< left out of the fit (indices into the data given)
  /// Values the robust judge named as gross errors that the loop's final model fits within
  /// kPutBackSigma of its noise scale: put back and refitted (residual_sigma: against the
  /// final model, before the refit).
  std::vector<Outlier> put_back;
  MeasuredData fitted;      ///< the data the reported fit used
  std::vector<int> origin;  ///< for each point of `fitted`, its index in the data given
  /// The fractional law (loop off; its residual traced) or the loop's base fit.
  FitReport fit;
  std::optional<ClosedLoopReport> loop;  ///< the closed loop's report (nullopt: loop off)
  /// The fit to report: the loop's final fit, or `fit` when the loop was off.
  const FitReport& final_fit() const { return loop ? loop->final_fit : fit; }
};

/// A value left out as a gross error is put back when the loop's final model fits it within
/// this many of its noise scales (a + b |yhat|): the robust judge fit lacks the effects the loop
/// finds (friction that follows the load or a temperature), and at the end of a sweep its misfit
/// can pass for a glitch.
inline constexpr double kPutBackSigma = 4.0;

/// Finds the gross errors (options.leave_out_outliers: up to ten rounds of a robust fit, the
/// values find_outliers names and a refit without them; outliers sorted most extreme first),
/// then fits the fractional law to the clean rows, or closes the loop on them
/// (close_the_loop_on_sample); with the loop, the values its final model fits within
/// kPutBackSigma are put back and the base and final models refitted (refit_on_every_row). Throws
/// as fit_fractional_law, fit_model and close_the_loop do (Interrupted when options.fit.stop asks).
Identification identify(const MeasuredData& data, const IdentifyOptions& options);

}  // namespace contensou
