// The closed loop's backward pass and its noise step: see loop_state.hpp.
#include <algorithm>
#include <limits>
#include <tuple>

#include "contensou/identification/effect_catalogue.hpp"
#include "contensou/identification/statistics.hpp"
#include "loop_state.hpp"

namespace contensou::detail {

namespace {

// An accepted step the backward pass may take out: not the shape nor the profile's degree (the
// model's form, not an effect with a null), and not taken out already. A profile correction is
// (tested right after the shape, it can stand in for effects found later).
bool prunable(const LoopStep& acc) {
  return acc.accepted && !acc.removed && acc.kind != Effect::shape &&
         acc.kind != Effect::profile_detail;
}

}  // namespace

// Backward pass: an effect accepted early may stand in for ones found later. Refit without
// each accepted effect (shape excepted) and remove it if it is no longer significant at
// alpha / (number accepted) or BIC prefers the model without it; repeat until none goes.
void prune(const MeasuredData& data, const NoiseSettings& noise, const ClosedLoopOptions& loop,
           LoopState& st, ClosedLoopReport& report) {
  bool removed = true;
  while (removed && report.accepted_effects.size() > 1) {
    removed = false;
    const double threshold = loop.alpha / static_cast<double>(report.accepted_effects.size());
    for (std::size_t k = 0; k < report.steps.size() && !removed; ++k) {
      LoopStep& acc = report.steps[k];
      if (!prunable(acc)) continue;
      ModelSpec without = st.spec;
      for (const ParameterEstimate& e : acc.parameters) {
        const int i = parameter_index_by_name(e.name);
        if (i < 0) continue;
        without.free[i] = false;
        without.value[i] = parameter_info(i).null_value;
      }
      if (acc.kind == Effect::friction_dependence)  // the slot, and a curve on it, go with it
        for (int j = 0; j < kDependenceSlots; ++j)
          if (without.dependence[j] && without.dependence[j]->name == acc.detail) {
            for (bool curve : {false, true}) {
              without.free[dependence_parameter(j, curve)] = false;
              without.value[dependence_parameter(j, curve)] = 0.0;
            }
            without.dependence[j].reset();
          }
      if (acc.kind == Effect::profile_correction) without.profile_corrected = false;
      set_speed_inside(without, loop);
      say(loop, "backward: refitting without " + acc.effect);
      const LoopState wo = fit_state(data, without, noise);
      const double lr = std::max(0.0, wo.fit.m2ll - st.fit.m2ll);
      const double p = chi2_survival(lr, static_cast<double>(acc.parameters.size()));
      if (p >= threshold || wo.fit.bic < st.fit.bic) {
        acc.removed = true;
        acc.verdict += "; removed in the backward pass (without it: LR p = " + std::to_string(p) +
                       ", BIC " + std::to_string(wo.fit.bic) + " vs " + std::to_string(st.fit.bic) +
                       ")";
        st = wo;
        const auto it =
            std::find(report.accepted_effects.begin(), report.accepted_effects.end(), acc.effect);
        if (it != report.accepted_effects.end()) report.accepted_effects.erase(it);
        for (LoopStep& curve : report.steps)  // a curve on the variable goes with it
          if (acc.kind == Effect::friction_dependence && curve.accepted && !curve.removed &&
              curve.kind == Effect::friction_dependence_curve && curve.detail == acc.detail) {
            curve.removed = true;
            curve.verdict += "; removed with " + acc.effect + " (" + acc.detail + ")";
            const auto c = std::find(report.accepted_effects.begin(), report.accepted_effects.end(),
                                     curve.effect);
            if (c != report.accepted_effects.end()) report.accepted_effects.erase(c);
          }
        say(loop, "backward: " + acc.effect + " removed");
        removed = true;
      }
    }
  }
}

namespace {

// The noise scales of a fit as the noise step's parameters: a_c and b_c of each channel.
std::vector<ParameterEstimate> noise_parameters(const FitReport& fit) {
  std::vector<ParameterEstimate> out;
  for (const ChannelDiagnostics& ch : fit.channels) {
    const std::string unit = ch.channel == "Mz_Nm" ? "N m" : "N";
    for (const auto& [name, value, u] :
         {std::tuple{"noise_a_", ch.noise_scale, unit},
          std::tuple{"noise_b_", ch.noise_slope, std::string("1")}}) {
      ParameterEstimate e;
      e.name = name + ch.channel;
      e.unit = u;
      e.value = value;
      e.determined = false;  // no interval
      out.push_back(e);
    }
  }
  return out;
}

}  // namespace

// The noise step (ClosedLoopOptions::choose_noise_model), after the effects: the model refitted
// with a noise scale that grows with the value, sigma_ic = a_c + b_c |yhat_ic| (NoiseModel::affine,
// fit.hpp), against one constant scale per channel, tested like an effect: the likelihood-ratio
// test with one degree of freedom per measured channel (its slope b_c; the constant model is
// b_c = 0, on the boundary of b_c >= 0, so chi-square with that many degrees of freedom is
// conservative) at alpha, and BIC (two noise parameters per channel against one). Cross-
// validation does not apply: the two models weight the residuals differently. Accepted, the
// affine fit is the final one.
void test_noise_growth(const MeasuredData& data, const NoiseSettings& noise,
                       const ClosedLoopOptions& loop, LoopState& st, ClosedLoopReport& report) {
  NoiseSettings affine = noise;
  affine.model = NoiseModel::affine;
  say(loop, "noise: refitting with a scale that grows with the value (a + b |y|)");
  const LoopState grown = fit_state(data, st.spec, affine);
  LoopStep step;
  step.kind = Effect::noise_growth;
  step.effect = describe(Effect::noise_growth).name;
  step.detail = "a + b |y|";
  step.lr_dof = static_cast<int>(st.fit.channels.size());
  step.lr = std::max(0.0, st.fit.m2ll - grown.fit.m2ll);
  step.lr_p_value = chi2_survival(step.lr, static_cast<double>(step.lr_dof));
  step.threshold = loop.alpha;
  step.bic_before = st.fit.bic;
  step.bic_after = grown.fit.bic;
  step.cv_before = step.cv_after = std::numeric_limits<double>::quiet_NaN();
  step.error_before = st.fit.error;
  step.error_after = grown.fit.error;
  step.channels_before = st.fit.channels;
  step.channels_after = grown.fit.channels;
  step.fit_before = st.fit;
  step.fit_after = grown.fit;
  step.parameters = noise_parameters(grown.fit);
  const bool lr_ok = step.lr_p_value < step.threshold;
  const bool bic_ok = step.bic_after < step.bic_before;
  // A load cell's noise grows by a few tenths of a percent of the value: a share b above
  // kPlausibleNoiseGrowth is a misfit that grows with the value (a missing effect, gross errors
  // left in), not noise, and is not taken for it.
  std::string implausible;
  for (const ChannelDiagnostics& ch : grown.fit.channels)
    if (ch.noise_slope > kPlausibleNoiseGrowth)
      implausible +=
          (implausible.empty() ? "" : ", ") + ch.channel + " b = " + std::to_string(ch.noise_slope);
  step.accepted = lr_ok && bic_ok && implausible.empty();
  step.verdict =
      std::string(lr_ok ? "LR significant" : "LR not significant") +
      (bic_ok ? ", BIC improves" : ", BIC does not improve") +
      (implausible.empty() ? ""
                           : "; implausible as noise (" + implausible + " of |y|, above " +
                                 std::to_string(kPlausibleNoiseGrowth) +
                                 "): the misfit grows with the value, the model lacks something") +
      (step.accepted ? "; the noise grows with the value: the final fit weights each "
                       "value by 1 / (a + b |y|)"
                     : "; one constant noise scale per channel is kept");
  say(loop, std::string("noise: a scale growing with the value ") +
                (step.accepted ? "accepted" : "rejected") + " (" + step.verdict + ")");
  report.steps.push_back(step);
  if (step.accepted) st = grown;
}

}  // namespace contensou::detail
