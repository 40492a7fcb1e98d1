#include "contensou/identification/identify.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "contensou/friction/error.hpp"
#include "contensou/identification/prediction.hpp"
#include "contensou/identification/rigid_patch.hpp"
#include "contensou/identification/sweeps.hpp"
#include "shared_laws.hpp"

namespace contensou {

namespace {

// The data without the outlying values (a row left with no channel dropped), and for each of
// its points the index of the point in the data given.
MeasuredData clean_rows(const MeasuredData& data, const std::vector<Outlier>& outliers,
                        std::vector<int>& origin) {
  std::vector<std::array<bool, kChannels>> out(data.points.size());
  for (const Outlier& o : outliers) out[static_cast<std::size_t>(o.point)][o.channel] = true;
  MeasuredData clean;  // the data's description, and its points but for the outlying values
  clean.source = data.source;
  clean.sources = data.sources;
  clean.column_notes = data.column_notes;
  clean.recorded = data.recorded;
  clean.columns_not_read = data.columns_not_read;
  clean.missing_values = data.missing_values;
  origin.clear();
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    MeasuredPoint p = data.points[i];
    for (int c = 0; c < kChannels; ++c)
      if (out[i][c]) p.force[c].reset();
    if (!p.force[0] && !p.force[1] && !p.force[2]) continue;
    clean.points.push_back(std::move(p));
    origin.push_back(static_cast<int>(i));
  }
  return clean;
}

// The fit the gross errors are judged against: robust (Cauchy loss at 3 noise scales, the
// scales from the residuals' median, fit.hpp), so that the glitches do not pull the model
// towards them; the user's own robust loss when one is chosen.
IdentificationOptions robust(const IdentificationOptions& o) {
  IdentificationOptions r = o;
  if (r.loss == RobustLoss::none) {
    r.loss = RobustLoss::cauchy;
    r.loss_scale = 3.0;
  }
  return r;
}

// The robust fit on `data`: the exact integrals over the profile (the given one, else the
// quadratic profile identified with them, as the loop's shape step), since the law's own
// misfit, several noise scales at a sweep's knee, would otherwise show between neighbouring
// rows; the fractional law if that fit fails.
FitReport judge_fit(const MeasuredData& data, const IdentificationOptions& judge,
                    const std::vector<char>& use) {
  const ModelSpec base = base_spec_for(data, judge);
  ModelSpec spec = base;
  spec.exact_only = true;
  for (int p : {kA, kM0, kMShape, kShapeBlend}) spec.free[p] = false;
  spec.value[kShapeBlend] = 1.0;
  if (!spec.profile_model) spec.free[kProfileW1] = spec.free[kProfileW2] = true;
  try {
    return fit_model(data, spec, noise_settings_for(judge), nullptr, use);
  } catch (const Interrupted&) {
    throw;
  } catch (const std::exception&) {
    return fit_model(data, base, noise_settings_for(judge), nullptr, use);
  }
}

// The outliers the loop's final model fits within kPutBackSigma of its noise scale go to
// r.put_back (with that residual in sigma); the rest stay out. Returns whether any went back.
bool put_back_fitting_values(const MeasuredData& data, Identification& r) {
  const FitReport& fit = r.loop->final_fit;
  const std::vector<Resultants<double>> model = predict_final_model(*r.loop, data);
  std::vector<Outlier> kept;
  for (Outlier o : r.outliers) {
    const double yhat = model[static_cast<std::size_t>(o.point)].vector()(o.channel);
    const double sigma =
        fit.noise_model == NoiseModel::relative
            ? fit.noise_scale[o.channel] * std::abs(yhat)
            : fit.noise_scale[o.channel] + fit.noise_slope[o.channel] * std::abs(yhat);
    const double z = (o.value - yhat) / sigma;
    if (sigma > 0.0 && std::isfinite(z) && std::abs(z) <= kPutBackSigma) {
      o.residual_sigma = z;
      r.put_back.push_back(o);
    } else {
      kept.push_back(o);
    }
  }
  r.outliers = std::move(kept);
  return !r.put_back.empty();
}

// The name of an accepted step as the stability and the exclusions use it.
std::string step_label(const LoopStep& st) {
  return st.detail.empty() || st.kind == Effect::shape || st.kind == Effect::profile_correction
             ? st.effect
             : st.effect + " (" + st.detail + ")";
}

std::vector<std::string> kept_effects(const ClosedLoopReport& loop) {
  std::vector<std::string> out;
  for (const LoopStep& st : loop.steps)
    if (st.accepted && !st.removed && st.kind != Effect::noise_growth)
      out.push_back(step_label(st));
  return out;
}

// About 80 % of the rows: whole sweeps drawn at random when there are at least five and they
// leave 70 % or more of the rows, else rows drawn one by one.
MeasuredData subsample(const MeasuredData& rows, double radius_m, unsigned seed) {
  if (sweeps_of(rows, radius_m).size() >= 5) {
    MeasuredData part = holdout_split(rows, radius_m, 0.2, "", seed).fit;
    if (static_cast<double>(part.points.size()) >= 0.7 * static_cast<double>(rows.points.size()))
      return part;
  }
  std::mt19937_64 rng(seed);
  MeasuredData part = rows;
  part.points.clear();
  for (const MeasuredPoint& p : rows.points)
    if (rng() % 5 != 0) part.points.push_back(p);
  return part;
}

// The loop again on `resamples` subsamples (holdout_split's fit part at 20 %, seeds 1..k): how
// often each effect of `loop` is accepted there.
std::vector<EffectStability> stability_of(const MeasuredData& rows, const ClosedLoopReport& loop,
                                          const IdentifyOptions& o) {
  std::vector<EffectStability> out;
  for (const std::string& e : kept_effects(loop)) out.push_back({e, 0, 0, true});
  if (out.empty()) return out;
  ClosedLoopOptions quiet = *o.loop;
  quiet.progress = nullptr;
  for (int k = 1; k <= o.resamples; ++k) {
    if (o.loop->progress)
      o.loop->progress("resample " + std::to_string(k) + " of " + std::to_string(o.resamples));
    std::vector<std::string> kept;
    try {
      const MeasuredData part = subsample(rows, o.fit.radius_m, static_cast<unsigned>(k));
      kept = kept_effects(close_the_loop_on_sample(
          part, stratified_sample(part, o.fit.radius_m, o.selection_rows), o.fit, quiet));
    } catch (const Interrupted&) {
      throw;
    } catch (const std::exception&) {
      continue;  // a subsample the loop cannot fit says nothing either way: not counted
    }
    for (EffectStability& s : out) {
      ++s.resamples;
      s.accepted_in += std::find(kept.begin(), kept.end(), s.effect) != kept.end();
    }
  }
  for (EffectStability& s : out) s.stable = s.accepted_in >= kStableShare * s.resamples - 1e-9;
  return out;
}

// The loop's effects under resampling; the unstable ones left out by running the loop again
// without them (the stability kept in the report).
void resample_the_loop(const IdentifyOptions& o, Identification& r) {
  // On a large file, the subsamples are drawn from the rows the steps chose the model on.
  const std::vector<char> chosen = stratified_sample(r.fitted, o.fit.radius_m, o.selection_rows);
  MeasuredData rows = r.fitted;
  rows.points.clear();
  for (std::size_t i = 0; i < r.fitted.points.size(); ++i)
    if (i >= chosen.size() || chosen[i]) rows.points.push_back(r.fitted.points[i]);
  // Rounds: the effects not yet checked, the unstable ones left out and the loop run again
  // without them (its new effects checked in the next round; three rounds at most).
  IdentifyOptions current = o;
  std::vector<EffectStability> stability;
  for (int round = 0; round < 3; ++round) {
    std::vector<std::string> unstable;
    for (const EffectStability& s : stability_of(rows, *r.loop, current)) {
      const bool seen = std::any_of(stability.begin(), stability.end(),
                                    [&](const EffectStability& e) { return e.effect == s.effect; });
      if (seen) continue;
      stability.push_back(s);
      if (!s.stable) unstable.push_back(s.effect);
    }
    if (unstable.empty()) break;
    std::vector<std::string>& x = current.loop->excluded;
    x.insert(x.end(), unstable.begin(), unstable.end());
    r.loop = close_the_loop_on_sample(r.fitted,
                                      stratified_sample(r.fitted, o.fit.radius_m, o.selection_rows),
                                      o.fit, *current.loop);
  }
  r.loop->stability = std::move(stability);
}

// The rigid patch of the motion on the fitted rows, attached to the model reported (none on
// data without three rows that carry all three channels, motion and force).
void attach_motion_patch(const IdentifyOptions& o, Identification& r) {
  FitReport& final_fit = r.loop ? r.loop->final_fit : r.fit;
  if (!final_fit.model) return;
  int pairs = 0;
  for (const MeasuredPoint& p : r.fitted.points)
    pairs += p.force[0] && p.force[1] && p.force[2] &&
             (p.kinematics.vx != 0.0 || p.kinematics.vy != 0.0 || p.kinematics.omega != 0.0);
  if (pairs < 3) return;
  try {
    auto model = std::make_shared<ModelSpec>(*final_fit.model);
    model->motion_patch = fit_rigid_patch(r.fitted, o.fit.radius_m);
    final_fit.model = std::move(model);
  } catch (const InvalidArgument&) {
    // Forces that do not oppose the motion on the whole: no patch gives them, none is attached
    // (the law's own inversion remains).
  }
}

}  // namespace

Identification identify(const MeasuredData& data, const IdentifyOptions& given) {
  // Every fit below (the loop, its refits, its resamples) shares the profile's laws.
  IdentifyOptions options = given;
  detail::LawSharing::share(options.fit);
  Identification r;
  r.fitted = data;
  r.origin.resize(data.points.size());
  for (std::size_t i = 0; i < r.origin.size(); ++i) r.origin[i] = static_cast<int>(i);
  if (options.leave_out_outliers) {
    // Rounds of: the robust fit, every gross error it shows (outliers.hpp), the rows without
    // them; a glitch hidden by glitched neighbours shows once they are out.
    const IdentificationOptions judge = robust(options.fit);
    const double R = options.fit.radius_m;
    FitReport current = judge_fit(data, judge, stratified_sample(data, R, options.selection_rows));
    for (int round = 0; round < 10; ++round) {
      const std::vector<Outlier> found = find_outliers(r.fitted, current.prediction);
      if (found.empty()) break;
      for (Outlier o : found) {
        o.point = r.origin[static_cast<std::size_t>(o.point)];
        r.outliers.push_back(o);
      }
      r.fitted = clean_rows(data, r.outliers, r.origin);
      current = judge_fit(r.fitted, judge, stratified_sample(r.fitted, R, options.selection_rows));
    }
    std::sort(r.outliers.begin(), r.outliers.end(), [](const Outlier& a, const Outlier& b) {
      return std::abs(a.residual_sigma) > std::abs(b.residual_sigma);
    });
  }
  if (options.loop) {
    r.loop = close_the_loop_on_sample(
        r.fitted, stratified_sample(r.fitted, options.fit.radius_m, options.selection_rows),
        options.fit, *options.loop);
    if (!r.outliers.empty() && put_back_fitting_values(data, r)) {
      r.fitted = clean_rows(data, r.outliers, r.origin);
      refit_on_every_row(r.fitted, options.fit, *options.loop, *r.loop);
    }
    if (options.resamples > 0 && r.fitted.points.size() >= 10) resample_the_loop(options, r);
    r.fit = r.loop->base;
  } else {
    r.fit = fit_fractional_law(r.fitted, options.fit);
    r.fit.trace = trace_residual(r.fitted, r.fit, options.fit.radius_m, covariates_of(r.fitted));
  }
  if (options.motion_patch) attach_motion_patch(options, r);
  return r;
}

}  // namespace contensou
