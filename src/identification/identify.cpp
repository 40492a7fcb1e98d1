#include "contensou/identification/identify.hpp"

#include <algorithm>
#include <cmath>

#include "contensou/identification/sweeps.hpp"

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

}  // namespace

Identification identify(const MeasuredData& data, const IdentifyOptions& options) {
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
    r.fit = r.loop->base;
  } else {
    r.fit = fit_fractional_law(r.fitted, options.fit);
    r.fit.trace = trace_residual(r.fitted, r.fit, options.fit.radius_m, covariates_of(r.fitted));
  }
  return r;
}

}  // namespace contensou
