// The identification report as JSON (moved from the app so that the Python package writes the
// same report).
#include "contensou/identification/report.hpp"

#include "contensou/identification/model_file.hpp"
#include "contensou/identification/report_text.hpp"

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <variant>

#include "contensou/friction/error.hpp"

namespace contensou {
namespace {

nlohmann::json scores_json(const PredictionScores& p) {
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {{"rows", p.rows},
          {"median_motion_angle_deg", num(p.median_motion_angle_deg)},
          {"mean_motion_angle_deg", num(p.mean_motion_angle_deg)},
          {"median_force_relative_error", num(p.median_force_error)},
          {"mean_force_relative_error", num(p.mean_force_error)},
          {"median_force_angle_deg", num(p.median_force_angle_deg)}};
}

nlohmann::json checks_json(const DataChecks& c) {
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {
      {"rows", c.rows},
      {"coupling_rows", c.coupling_rows},
      {"torque_ratio_rows", c.ratio_rows},
      {"above_centred_patch_torque", c.above_axisymmetric},
      {"above_any_patch_torque", c.above_any_patch},
      {"torque_sign_rows", c.sign_rows},
      {"torque_drives_spin", c.drives_spin},
      {"force_angle_rows", c.angle_rows},
      {"force_angle_outside", c.angle_outside},
      {"sliding_rows", c.sliding_rows},
      {"median_force_angle_deg", num(c.median_angle_deg)},
      {"median_force_angle_ci95_deg", {num(c.median_angle_low_deg), num(c.median_angle_high_deg)}},
      {"margin", kCheckMargin},
      {"findings", c.findings}};
}

nlohmann::json held_out_json(const std::vector<HeldOutResult>& results) {
  nlohmann::json out = nlohmann::json::array();
  for (const HeldOutResult& h : results) {
    nlohmann::json steps = nlohmann::json::array();
    for (const HeldOutStep& st : h.steps)
      steps.push_back({{"effect", st.effect},
                       {"detail", st.detail},
                       {"accepted", st.accepted},
                       {"error_before", st.error_before},
                       {"error_after", st.error_after}});
    out.push_back({{"name", h.name},
                   {"rows", h.rows},
                   {"base_error", h.base_error},
                   {"final_error", h.final_error},
                   {"base", scores_json(h.base_scores)},
                   {"final", scores_json(h.final_scores)},
                   {"steps", steps}});
  }
  return out;
}

nlohmann::json model_json(const std::string& name, const std::vector<std::string>& effects,
                          const FitReport& fit) {
  nlohmann::json m;
  m["name"] = name;
  m["effects"] = effects;
  nlohmann::json params = nlohmann::json::object();
  for (const ParameterEstimate& p : fit.parameters) {
    nlohmann::json e;
    e["value"] = p.value;
    e["ci95"] = p.ci95 ? nlohmann::json::array({(*p.ci95)[0], (*p.ci95)[1]}) : nlohmann::json();
    e["unit"] = p.unit;
    e["fixed"] = p.fixed;
    e["derived_from_profile"] = p.derived;
    e["determined"] = p.determined || p.fixed;
    e["std_error"] = std::isfinite(p.std_error) ? nlohmann::json(p.std_error) : nlohmann::json();
    if (!p.note.empty()) e["note"] = p.note;
    e["on_bound"] = p.on_bound.empty() ? nlohmann::json() : nlohmann::json(p.on_bound);
    if (!p.on_bound.empty()) e["bound_meaning"] = p.bound_meaning;
    params[p.name] = e;
  }
  m["params"] = params;
  nlohmann::json rms = nlohmann::json::object(), noise = nlohmann::json::object();
  nlohmann::json diag = nlohmann::json::array();
  for (const ChannelDiagnostics& c : fit.channels) {
    rms[c.channel] = c.rms;
    noise[c.channel] = c.noise_scale;
    diag.push_back({{"channel", c.channel},
                    {"points", c.points},
                    {"runs_p_value", c.runs_p_value},
                    {"lag1_autocorrelation", c.lag1},
                    {"durbin_watson", c.durbin_watson},
                    {"neighbour_scale", c.neighbour_scale},
                    {"white", c.white}});
  }
  m["rms"] = rms;
  m["noise_model"] = noise_model_name(fit.noise_model);
  m["noise_scale"] = noise;
  if (fit.noise_model == NoiseModel::affine) {
    nlohmann::json slope = nlohmann::json::object();
    for (const ChannelDiagnostics& c : fit.channels) slope[c.channel] = c.noise_slope;
    m["noise_slope"] = slope;  // sigma = noise_scale + noise_slope |y|
  }
  m["diagnostics"] = diag;
  m["residual_white"] = fit.residual_white;
  m["within_noise"] = fit.within_noise();
  nlohmann::json followed = nlohmann::json::array();
  for (const TracedVariable& t : fit.trace.followed)
    followed.push_back({{"channel", t.channel},
                        {"variable", t.variable},
                        {"kinematic", t.kinematic},
                        {"test", t.test},
                        {"statistic", t.statistic},
                        {"p_value", t.p_value},
                        {"p_adjusted", t.p_adjusted},
                        {"size", t.size},
                        {"spread_sigma", t.spread_sigma}});
  m["trace"] = {{"tests", fit.trace.tests}, {"alpha", fit.trace.alpha}, {"followed", followed}};
  m["aic"] = fit.aic;
  m["bic"] = fit.bic;
  m["chi2"] = fit.chi2;
  m["degrees_of_freedom"] = fit.degrees_of_freedom;
  m["error"] = fit.error;
  m["converged"] = fit.converged;
  m["warnings"] = fit_warnings(fit);
  m["cautions"] = shape_cautions(fit);
  nlohmann::json corr = nlohmann::json::object();
  corr["names"] = fit.correlation_names;
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < fit.correlation.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < fit.correlation.cols(); ++j) row.push_back(fit.correlation(i, j));
    rows.push_back(row);
  }
  corr["matrix"] = rows;
  m["correlation"] = corr;
  return m;
}

nlohmann::json fit_report(const ReportInput& info, const FitReport& base) {
  nlohmann::json r;
  r["input"] = {{"file", info.file},
                {"points", info.points},
                {"values", info.values},
                {"radius_m", info.radius_m},
                {"normal_load_N",
                 info.normal_load_n ? nlohmann::json(*info.normal_load_n) : nlohmann::json()}};
  if (!info.normal_load_source.empty()) r["input"]["normal_load_source"] = info.normal_load_source;
  if (!info.column_notes.empty()) r["input"]["columns_converted"] = info.column_notes;
  nlohmann::json recorded = nlohmann::json::array();
  for (const RecordedSummary& c : info.recorded)
    recorded.push_back({{"name", c.variable.name},
                        {"header", c.variable.header},
                        {"column", c.variable.column},
                        {"unit", c.variable.unit},
                        {"si_unit", c.variable.si_unit},
                        {"kind", c.variable.kind},
                        {"min", c.min},
                        {"max", c.max},
                        {"values", c.values}});
  r["input"]["recorded_columns"] = recorded;
  r["input"]["columns_not_read"] = info.columns_not_read;
  r["input"]["missing_values"] = info.missing_values;
  const auto outlier_list = [](const std::vector<Outlier>& list) {
    nlohmann::json out = nlohmann::json::array();
    for (const Outlier& o : list)
      out.push_back({{"line", o.line > 0 ? nlohmann::json(o.line) : nlohmann::json()},
                     {"point", o.point},
                     {"channel", kChannelColumns[o.channel]},
                     {"value", o.value},
                     {"residual_sigma", o.residual_sigma},
                     {"where", o.where},
                     {"value_in_file_unit", o.file_value}});
    return out;
  };
  r["input"]["outliers"] = outlier_list(info.outliers);
  // Taken for gross errors by the robust judge, fitted by the final model within
  // kPutBackSigma (residual_sigma against it): back in the fit.
  r["input"]["outliers_put_back"] = outlier_list(info.put_back);
  r["input"]["outlier_rule"] =
      "residual of a robust fit minus the median of its four neighbours in kinematic order (load, "
      "spin sense, sliding direction, v/omega), beyond 8 local robust sigma (1.4826 median|d| / "
      "1.14), the row's own residual carrying at least half of it: left out of the fit";
  if (!info.sources.empty()) r["input"]["files"] = info.sources;
  if (!info.profile.empty()) {
    r["input"]["profile"] = info.profile;
    if (info.profile_rms_residual_pa) {
      r["input"]["profile_fit_rms_residual_Pa"] = *info.profile_rms_residual_pa;
      r["input"]["profile_fit_max_residual_Pa"] = *info.profile_max_residual_pa;
    }
  }
  r["base"] = model_json("fractional", {}, base);
  r["steps"] = nlohmann::json::array();
  r["accepted_effects"] = nlohmann::json::array();
  r["final"] = r["base"];
  r["error_before"] = base.error;
  r["error_after"] = base.error;
  r["error_definition"] =
      "root mean square over measured channels of (channel rms / channel's largest |value|)";
  r["warnings"] = fit_warnings(base);
  r["held_out"] = held_out_json(info.held_out);
  r["data_checks"] = checks_json(info.checks);
  if (base.model) r["model"] = nlohmann::json::parse(model_to_json(*base.model));
  return r;
}

nlohmann::json loop_report(const ReportInput& info, const ClosedLoopReport& loop) {
  nlohmann::json r = fit_report(info, loop.base);
  std::vector<std::string> effects;
  nlohmann::json steps = nlohmann::json::array();
  int k = 0;
  for (const LoopStep& st : loop.steps) {
    nlohmann::json scores = nlohmann::json::array();
    for (const CandidateScore& c : st.scores)
      scores.push_back({{"effect", c.effect},
                        {"detail", c.detail},
                        {"score", c.statistic},
                        {"p_value", c.p_value}});
    nlohmann::json params = nlohmann::json::object();
    for (const ParameterEstimate& p : st.parameters)
      params[p.name] = {
          {"value", p.value},
          {"ci95", p.ci95 ? nlohmann::json::array({(*p.ci95)[0], (*p.ci95)[1]}) : nlohmann::json()},
          {"unit", p.unit}};
    nlohmann::json rms_b = nlohmann::json::object(), rms_a = nlohmann::json::object();
    for (const ChannelDiagnostics& c : st.channels_before) rms_b[c.channel] = c.rms;
    for (const ChannelDiagnostics& c : st.channels_after) rms_a[c.channel] = c.rms;
    steps.push_back(
        {{"step", ++k},
         {"candidate_scores", scores},
         {"chosen", st.effect},
         {"detail", st.detail},
         {"accepted", st.accepted && !st.removed},
         {"removed_in_backward_pass", st.removed},
         {"verdict", step_fit_failed(st) ? "failed fit: the extended fit ended worse than the "
                                           "model it extends, so it says nothing about " +
                                               st.effect + " (" + st.verdict + ")"
                                         : st.verdict},
         {"fit_failed", step_fit_failed(st)},
         {"retries", st.retries},
         {"ambiguous_with", st.ambiguous_with},
         {"separation", st.separation},
         {"instrument_unconfirmed",
          st.unconfirmed.empty() ? nlohmann::json() : nlohmann::json(st.unconfirmed)},
         {"parameters", params},
         {"lr", st.lr},
         {"lr_dof", st.lr_dof},
         {"lr_p_value", st.lr_p_value},
         {"threshold", st.threshold},
         {"bic_before", st.bic_before},
         {"bic_after", st.bic_after},
         {"cv_before", st.cv_before},
         {"cv_after", st.cv_after},
         {"rms_before", rms_b},
         {"rms_after", rms_a},
         {"error_before", st.error_before},
         {"error_after", st.error_after}});
  }
  r["steps"] = steps;
  r["accepted_effects"] = loop.accepted_effects;
  // The rows the steps chose the model on: a stratified sample of a large file (the base and
  // final fits use every row), else every row.
  r["selection_rows"] = loop.selection_rows > 0 ? loop.selection_rows : loop.final_fit.psi.size();
  nlohmann::json ambiguities = nlohmann::json::array();
  for (const LoopStep& st : loop.steps)
    if (st.accepted && !st.removed)
      for (const std::string& sep : st.separation) ambiguities.push_back(sep);
  r["ambiguities"] = ambiguities;
  r["final"] = model_json(loop.final_spec.uses_exact() ? "exact" : "fractional",
                          loop.accepted_effects, loop.final_fit);
  r["error_after"] = loop.final_fit.error;
  r["noise_model"] = noise_model_name(loop.noise_model);
  r["structure_remains"] = loop.structure_remains;
  r["summary"] = loop_summary(loop);
  nlohmann::json stability = nlohmann::json::array();
  for (const EffectStability& e : loop.stability)
    stability.push_back({{"effect", e.effect},
                         {"accepted_in", e.accepted_in},
                         {"resamples", e.resamples},
                         {"stable", e.stable}});
  r["stability"] = stability;
  r["warnings"] = fit_warnings(loop.final_fit);
  if (loop.final_fit.model)
    r["model"] = nlohmann::json::parse(model_to_json(*loop.final_fit.model));
  return r;
}

}  // namespace

std::string fit_report_json(const ReportInput& input, const FitReport& base, int indent) {
  return fit_report(input, base).dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string loop_report_json(const ReportInput& input, const ClosedLoopReport& loop, int indent) {
  return loop_report(input, loop)
      .dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string RecordedSummary::describe() const {
  const RecordedVariable& v = variable;
  const auto own = [&](double si) { return (si - v.offset_si) / v.to_si; };
  char range[160];
  std::string s = "'" + v.header + "' (column " + std::to_string(v.column) + "): ";
  std::snprintf(range, sizeof range, "%.6g to %.6g", own(min), own(max));
  s += range;
  if (!v.unit.empty()) s += " " + v.unit;
  if (!v.kind.empty() && (v.to_si != 1.0 || v.offset_si != 0.0)) {
    std::snprintf(range, sizeof range, " (%.6g to %.6g %s)", min, max, v.si_unit.c_str());
    s += range;
  }
  return s + ", " + std::to_string(values) + " values";
}

ReportInput describe_run(const std::string& file, const MeasuredData& data, double radius_m,
                         std::optional<double> normal_load_n, const ProfileChoice& profile) {
  ReportInput in;
  in.file = file;
  in.points = static_cast<int>(data.points.size());
  in.values = data.count(0) + data.count(1) + data.count(2);
  in.radius_m = radius_m;
  in.normal_load_n = normal_load_n;
  in.column_notes = data.column_notes;
  if (data.sources.size() > 1) in.sources = data.sources;
  in.columns_not_read = data.columns_not_read;
  in.missing_values = data.missing_values;
  for (std::size_t k = 0; k < data.recorded.size(); ++k) {
    RecordedSummary c{data.recorded[k], 0.0, 0.0, 0};
    for (const MeasuredPoint& p : data.points) {
      const double v = p.recorded[k];
      if (std::isnan(v)) continue;
      c.min = c.values == 0 ? v : std::min(c.min, v);
      c.max = c.values == 0 ? v : std::max(c.max, v);
      ++c.values;
    }
    in.recorded.push_back(c);
  }
  in.profile = profile.description;
  in.profile_rms_residual_pa = profile.rms_residual_pa;
  in.profile_max_residual_pa = profile.max_residual_pa;
  if (radius_m > 0.0 && std::isfinite(radius_m)) in.checks = check_data(data, radius_m);
  return in;
}

}  // namespace contensou
