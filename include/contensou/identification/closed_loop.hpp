/// \file
/// The closed loop: find structure in the residual, trace it to a missing effect from a
/// catalogue, add it, refit, and report the error before and after.
///
/// The catalogue (effect_catalogue.hpp) holds nested extensions, each a parameter whose null
/// value removes it, among them:
/// ~~~
///   shape               the law's own approximation error: the exact integrals over the profile
///                       replace the law (the blend lambda fitted at its end point 1, tested
///                       against its null 0); without a profile, a quadratic profile in rho^2 is
///                       identified too (then, accepted, a quartic: profile_detail)
///   anisotropy          kappa != 1 (null 1)
///   pressure_shift_y    ky (null 0)
///   speed_dependence    f(w) = f (1 - beta (1 - exp(-w / w_s))) (null beta = 0; w_s is scanned)
///   channel_offset      a constant added to one measured channel (null 0)
///   channel_crosstalk   one channel picks up g times another (null 0)
/// ~~~
/// and the rig's kinematics, the patch's growth and friction that follows a recorded variable.
/// Selection at each step: a score (Lagrange-multiplier) test of every candidate at its null
/// from the current fit; candidates are fitted in order of significance (the most significant
/// always, up to four while their score is significant); a candidate passes when (1) the
/// likelihood-ratio test is significant at alpha / (number of candidates scored), (2) BIC
/// improves and (3) the k-fold cross-validated error improves (one-step approximate refits),
/// and of those that pass the one with the lowest BIC is accepted. Others that pass within a
/// BIC difference of 2, or whose score direction (Jacobian column with the fitted columns
/// projected out) correlates above 0.9 with the accepted one's and whose LR is significant
/// with a BIC within 10, are reported as ambiguous alternatives with the measurement that would
/// separate them. Repeats until no candidate passes (or max_steps); then a backward pass
/// removes accepted effects that later ones made redundant. steps lists every fitted candidate.
/// Then, when asked (ClosedLoopOptions::choose_noise_model), the noise: a scale that grows with
/// the value, sigma = a + b |y| per channel (NoiseModel::affine), against one constant scale per
/// channel, by the likelihood-ratio test at alpha and BIC, refused when a share b exceeds
/// kPlausibleNoiseGrowth; reported as a step (effect kNoiseGrowthEffect) and, accepted, the
/// final fit weights the values by it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contensou/identification/effect_catalogue.hpp"
#include "contensou/identification/fit.hpp"

namespace contensou {

/// The largest share b of |y| in sigma = a + b |y| the noise step takes for noise (a load cell's
/// is a few tenths of a percent); above it the growth is a misfit's, and the step is refused.
inline constexpr double kPlausibleNoiseGrowth = 0.1;

/// The effect name of the noise step (describe(Effect::noise_growth).name).
inline constexpr const char* kNoiseGrowthEffect = "noise_growth";

/// The score test of one candidate effect at its null.
struct CandidateScore {
  std::string effect;      ///< catalogue name
  std::string detail;      ///< channel or pair, if any
  double statistic = 0.0;  ///< score (LM) statistic, chi-square with 1 dof (scan: the largest)
  /// chi-square p value, for speed_dependence times the scan's number of w_s (Bonferroni; at
  /// most 1): the correction for a scanned nuisance parameter.
  double p_value = 1.0;
};

/// One fitted candidate of the loop (or the noise step): its tests and its fits.
struct LoopStep {
  std::vector<CandidateScore> scores;         ///< every candidate tried, most significant first
  Effect kind = Effect::shape;                ///< the one fitted (effect_catalogue.hpp)
  std::string effect,                         ///< its name (describe(kind).name)
      detail;                                 ///< its detail (channel, pair, variable), if any
  bool accepted = false;                      ///< accepted into the model
  bool removed = false;                       ///< accepted, then removed by the backward pass
  std::string verdict;                        ///< why it was accepted or not
  std::vector<ParameterEstimate> parameters;  ///< the effect's parameters, fitted
  double lr = 0.0,       ///< likelihood ratio: -2 log L before minus after (at least 0)
      lr_p_value = 1.0,  ///< its chi-square p value with lr_dof degrees of freedom
      threshold = 0.0;   ///< the level lr_p_value is tested at
  /// Degrees of freedom of the LR test: the effect's parameters (the noise step: one a measured
  /// channel).
  int lr_dof = 1;
  double bic_before = 0.0,    ///< BIC of the model it extends
      bic_after = 0.0;        ///< BIC of the extended model
  double cv_before = 0.0,     ///< cross-validated error of the model it extends (NaN: noise step)
      cv_after = 0.0;         ///< cross-validated error of the extended model (NaN: noise step)
  double error_before = 0.0,  ///< FitReport::error of the model it extends
      error_after = 0.0;      ///< FitReport::error of the extended model
  std::vector<ChannelDiagnostics> channels_before,  ///< residual diagnostics before
      channels_after;                               ///< residual diagnostics after
  /// Alternatives the data do not rule out ("effect (detail)"; each passes within a BIC
  /// difference of 2, or has a score direction correlated above 0.9, a significant LR and a BIC
  /// within 10).
  std::vector<std::string> ambiguous_with;
  /// Fits from other starts after the first ended worse than the model it extends (0: none
  /// needed); the step reports the best of them.
  int retries = 0;
  /// For each alternative in ambiguous_with, why it is one and which measurement would separate
  /// it from this one.
  std::vector<std::string> separation;
  /// An instrument effect accepted without the measurement that separates it from a physical
  /// one: that physical alternative and the measurement that would decide, in words ("": the
  /// data hold the measurement, or the effect is physical). The report then names both.
  std::string unconfirmed;
  FitReport fit_after;   ///< the extended fit (kept for pictures)
  FitReport fit_before;  ///< the fit of the model it extends
};

/// How the closed loop chooses.
struct ClosedLoopOptions {
  double alpha = 1e-3;  ///< family-wise level of the likelihood-ratio test per step
  /// k of the cross-validation: the mean squared weighted residual of held-out rows, each fold
  /// refitted by one Gauss-Newton step from the estimate on all rows.
  int folds = 5;
  int max_steps = 6;  ///< forward steps at most
  /// speed_dependence with the exact integrals: f(w) at the local slip speed inside the
  /// integrals (default: the exact law's table of the falling part, exact_law.hpp), or at the
  /// effective speed w = (v^2 + (2u/3)^2)^(1/2) outside them.
  bool speed_inside_integrals = true;
  /// After the effects, test a noise scale that grows with the value against the constant one
  /// (when the noise model is additive and its scales are estimated). The app's and Python's
  /// default (noise_model "auto").
  bool choose_noise_model = false;
  std::function<void(const std::string&)> progress;  ///< called with a line per stage
  /// Effects never proposed, by name ("channel_offset") or with their detail
  /// ("channel_offset (Mz_Nm)"): those identify() found unstable under resampling.
  std::vector<std::string> excluded;

 private:
  detail::TestSeams seams_;
  friend struct testing::Seams;
};

/// How an accepted effect fared when the loop was run again on subsamples of the rows
/// (identify(): IdentifyOptions::resamples).
struct EffectStability {
  std::string effect;   ///< "effect" or "effect (detail)", as the steps name it
  int accepted_in = 0;  ///< the subsamples whose loop accepted it too
  int resamples = 0;    ///< the subsamples
  /// Accepted in at least kStableShare of the subsamples; an unstable effect is left out of the
  /// final model (the loop run again without it) and reported as unstable.
  bool stable = true;
};

/// The share of subsamples that must accept an effect for it to stay in the model.
inline constexpr double kStableShare = 0.8;

/// What the closed loop found.
struct ClosedLoopReport {
  FitReport base;        ///< the base law's fit
  FitReport final_fit;   ///< the fit of the model the loop ends with
  ModelSpec final_spec;  ///< that model, at its estimates
  /// Every fitted candidate, the profile_detail and noise steps included, in order.
  std::vector<LoopStep> steps;
  /// The names of the effects accepted and not removed, in order (the noise step not among them).
  std::vector<std::string> accepted_effects;
  /// The noise model of the final fit (affine: the noise step was accepted).
  NoiseModel noise_model = NoiseModel::additive;
  /// The final residual is still not white, or still follows a variable (ResidualTrace).
  bool structure_remains = false;
  /// The rows the steps were decided on, in a model selection on a sample
  /// (close_the_loop_on_sample; 0 when every row was used). base and final_fit are then fitted
  /// on every row; the steps' statistics are the sample's.
  std::size_t selection_rows = 0,
              rows = 0;  ///< the rows of the data (0 when every row was used)
  /// Each effect of a first loop's final model under resampling (empty when not resampled);
  /// the unstable ones are not in this report's model.
  std::vector<EffectStability> stability;
};

/// A loop step whose extended fit ends worse than the model it extends (which it nests): its
/// optimiser failed, so the step says nothing about the effect (the loop retries such a step
/// from other starts; the reports flag it). Never true of the noise step.
bool step_fit_failed(const LoopStep& step);

/// The closed loop (this file's description) on every row of `data`, from the base fit of
/// `options`. Throws what base_spec_for and fit_model throw, and Interrupted when options.stop
/// asks (polled between the stages and inside every fit).
ClosedLoopReport close_the_loop(const MeasuredData& data, const IdentificationOptions& options,
                                const ClosedLoopOptions& loop = {});

/// The base law and the chosen model of `report` refitted on every row of `data`, each from the
/// report's estimates and noise scales, their residuals traced, structure_remains updated: what
/// close_the_loop_on_sample does after its steps. Throws as fit_model.
void refit_on_every_row(const MeasuredData& data, const IdentificationOptions& options,
                        const ClosedLoopOptions& loop, ClosedLoopReport& report);

/// The chosen model (report.final_spec, at its estimates) at every row of `data` [N, N, N m].
std::vector<Resultants<double>> predict_final_model(const ClosedLoopReport& report,
                                                    const MeasuredData& data);

/// The loop's model selection on the rows `sample` marks (one entry a row of data; rows past its
/// end count as marked), then the base law and the selected model fitted on every row (from the
/// sample's estimates), their residual traced over every row. For large files: the steps' tests
/// need far fewer rows than a day of rig data holds, and each costs a fit per candidate. Throws
/// as close_the_loop.
ClosedLoopReport close_the_loop_on_sample(const MeasuredData& data, const std::vector<char>& sample,
                                          const IdentificationOptions& options,
                                          const ClosedLoopOptions& loop = {});

}  // namespace contensou
