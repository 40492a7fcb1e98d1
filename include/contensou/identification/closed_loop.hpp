// The closed loop: find structure in the residual, trace it to a missing effect from a
// catalogue, add it, refit, and report the error before and after.
//
// Catalogue (each a nested extension: a parameter whose null value removes it):
//   shape               the law's own approximation error: blend toward the exact integrals
//                       over the profile (lambda, null 0), then switch to them if BIC prefers;
//                       without a profile, a quadratic profile in rho^2 is identified too
//   anisotropy          kappa != 1 (null 1)
//   pressure_shift_y    ky (null 0)
//   speed_dependence    f(w) = f (1 - beta (1 - exp(-w / w_s))) (null beta = 0; w_s is scanned)
//   channel_offset      a constant added to one measured channel (null 0)
//   channel_crosstalk   one channel picks up g times another (null 0)
// Selection at each step: a score (Lagrange-multiplier) test of every candidate at its null
// from the current fit; candidates are fitted in order of significance (the most significant
// always, up to four while their score is significant); a candidate passes when (1) the
// likelihood-ratio test is significant at alpha / (number of candidates scored), (2) BIC
// improves and (3) the k-fold cross-validated error improves (one-step approximate refits),
// and of those that pass the one with the lowest BIC is accepted. Others that pass within a
// BIC difference of 2, or whose score direction (Jacobian column with the fitted columns
// projected out) correlates above 0.9 with the accepted one's and whose LR is significant, are
// reported as ambiguous alternatives with the measurement that would separate them. Repeats until
// no candidate passes; then a backward pass removes accepted effects that later ones made
// redundant. steps lists every fitted candidate.
// Then, when asked (ClosedLoopOptions::choose_noise_model), the noise: a scale that grows with
// the value, sigma = a + b |y| per channel (NoiseModel::affine), against one constant scale per
// channel, by the likelihood-ratio test at alpha and BIC; reported as a step (effect
// kNoiseGrowthEffect) and, accepted, the final fit weights the values by it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "contensou/identification/effect_catalogue.hpp"
#include "contensou/identification/fit.hpp"

namespace contensou {

// The largest share b of |y| in sigma = a + b |y| the noise step takes for noise (a load cell's
// is a few tenths of a percent); above it the growth is a misfit's, and the step is refused.
inline constexpr double kPlausibleNoiseGrowth = 0.1;

// The effect name of the noise step (describe(Effect::noise_growth).name).
inline constexpr const char* kNoiseGrowthEffect = "noise_growth";

struct CandidateScore {
  std::string effect;      // catalogue name
  std::string detail;      // channel or pair, if any
  double statistic = 0.0;  // score (LM) statistic, chi-square with 1 dof
  double p_value = 1.0;    // after the correction for a scanned nuisance parameter
};

struct LoopStep {
  std::vector<CandidateScore> scores;  // every candidate tried, most significant first
  Effect kind = Effect::shape;         // the one fitted (effect_catalogue.hpp)
  std::string effect, detail;          // its name (describe(kind).name) and detail
  bool accepted = false;
  bool removed = false;                       // accepted, then removed by the backward pass
  std::string verdict;                        // why it was accepted or not
  std::vector<ParameterEstimate> parameters;  // the effect's parameters, fitted
  double lr = 0.0, lr_p_value = 1.0, threshold = 0.0;
  int lr_dof = 1;
  double bic_before = 0.0, bic_after = 0.0;
  double cv_before = 0.0, cv_after = 0.0;
  double error_before = 0.0, error_after = 0.0;
  std::vector<ChannelDiagnostics> channels_before, channels_after;
  // Alternatives the data do not rule out (each passes within a BIC difference of 2, or has a
  // score direction correlated above 0.9 and a significant LR), and for each, why and which
  // measurement would separate it from this one.
  std::vector<std::string> ambiguous_with;
  // Fits from other starts after the first ended worse than the model it extends (0: none
  // needed); the step reports the best of them.
  int retries = 0;
  std::vector<std::string> separation;
  FitReport fit_after;  // the extended fit (kept for pictures)
  FitReport fit_before;
};

struct ClosedLoopOptions {
  double alpha = 1e-3;  // family-wise level of the likelihood-ratio test per step
  int folds = 5;        // k of the cross-validation
  int max_steps = 6;
  // speed_dependence with the exact integrals: f(w) at the local slip speed inside the
  // integrals (default: the exact law's table of the falling part, exact_law.hpp), or at the
  // effective speed w = (v^2 + (2u/3)^2)^(1/2) outside them.
  bool speed_inside_integrals = true;
  // After the effects, test a noise scale that grows with the value against the constant one
  // (when the noise model is additive and its scales are estimated). The app's and Python's
  // default (noise_model "auto").
  bool choose_noise_model = false;
  // Testing only: Ceres' iterations in each candidate's first fit (-1: as every fit), so that a
  // first fit stops at its start and the retry from other starts (LoopStep::retries) runs.
  int test_first_fit_iterations = -1;
  std::function<void(const std::string&)> progress;  // called with a line per stage
};

struct ClosedLoopReport {
  FitReport base;
  FitReport final_fit;
  ModelSpec final_spec;
  std::vector<LoopStep> steps;
  std::vector<std::string> accepted_effects;
  NoiseModel noise_model = NoiseModel::additive;  // of the final fit (affine: noise step accepted)
  bool structure_remains = false;                 // the final residual is still not white
  // Model selection on a sample (close_the_loop_on_sample): the rows the steps were decided on
  // and the rows of the data (both 0 when every row was used). base and final_fit are then
  // fitted on every row; the steps' statistics are the sample's.
  std::size_t selection_rows = 0, rows = 0;
};

// A loop step whose extended fit ends worse than the model it extends (which it nests): its
// optimiser failed, so the step says nothing about the effect (the loop retries such a step
// from other starts; the reports flag it).
bool step_fit_failed(const LoopStep& step);

// Throws what fit_model throws, and Interrupted when options.stop asks (polled between the
// stages and inside every fit).
ClosedLoopReport close_the_loop(const MeasuredData& data, const IdentificationOptions& options,
                                const ClosedLoopOptions& loop = {});

// The loop's model selection on the rows `sample` marks (one entry a row of data), then the
// base law and the selected model fitted on every row (from the sample's estimates), their
// residual traced over every row. For large files: the steps' tests need far fewer rows than
// a day of rig data holds, and each costs a fit per candidate. Throws as close_the_loop.
ClosedLoopReport close_the_loop_on_sample(const MeasuredData& data, const std::vector<char>& sample,
                                          const IdentificationOptions& options,
                                          const ClosedLoopOptions& loop = {});

}  // namespace contensou
