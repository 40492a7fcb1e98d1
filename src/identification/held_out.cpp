// An identification judged on rows its fits never saw (held_out.hpp).
#include "contensou/identification/held_out.hpp"

#include <cstdio>
#include <stdexcept>

#include "contensou/identification/model_file.hpp"

namespace contensou {

namespace {

// The model of a fit bound to the rows (a recorded variable found by its name).
std::vector<Resultants<double>> wrenches_on(const FitReport& fit, const MeasuredData& rows) {
  if (!fit.model) return {};
  const ModelSpec m = bind_to_data(*fit.model, rows);
  std::vector<Resultants<double>> out;
  for (const MeasuredPoint& p : rows.points)
    out.push_back(evaluate_model(m, m.value.data(), p.kinematics, conditions_of(m, p)));
  return out;
}

PredictionScores scores_on(const FitReport& fit, const MeasuredData& rows) {
  const ModelSpec m = bind_to_data(*fit.model, rows);
  return score_predictions(rows, predict_rows(m, rows), m.radius_m);
}

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

HeldOutResult judge_on_rows(const FitReport& base, const ClosedLoopReport* loop,
                            const MeasuredData& rows, const std::string& name) {
  if (!base.model || (loop && !loop->final_fit.model))
    throw std::invalid_argument("judge_on_rows: a fit without its model (fit_model sets it)");
  const double R = base.model->radius_m;
  HeldOutResult r;
  r.name = name;
  r.rows = static_cast<int>(rows.points.size());
  const FitReport& final_fit = loop ? loop->final_fit : base;
  r.base_error = prediction_error(rows, wrenches_on(base, rows), R);
  r.final_error = prediction_error(rows, wrenches_on(final_fit, rows), R);
  r.base_scores = scores_on(base, rows);
  r.final_scores = loop ? scores_on(final_fit, rows) : r.base_scores;
  if (!loop) return r;
  for (const LoopStep& st : loop->steps) {
    if (!st.fit_before.model || !st.fit_after.model) continue;
    r.steps.push_back({st.effect, st.detail, st.accepted && !st.removed,
                       prediction_error(rows, wrenches_on(st.fit_before, rows), R),
                       prediction_error(rows, wrenches_on(st.fit_after, rows), R)});
  }
  return r;
}

std::string held_out_text(const HeldOutResult& r) {
  std::string s = "\n" + r.name + ": " + std::to_string(r.rows) + " rows no fit used\n  error " +
                  fmt("%.4f", r.base_error) + " (base law) -> " + fmt("%.4f", r.final_error) +
                  " (final model)\n";
  const auto scores = [](const PredictionScores& p) {
    if (p.rows == 0) return std::string("no row with all three channels and motion");
    return "motion from force: median angle " + fmt("%.3g", p.median_motion_angle_deg) +
           " deg; force from motion: median relative error " + fmt("%.3g", p.median_force_error) +
           " (" + std::to_string(p.rows) + " rows)";
  };
  s += "  base law:    " + scores(r.base_scores) + "\n";
  s += "  final model: " + scores(r.final_scores) + "\n";
  if (!r.steps.empty()) s += "  each step's error on these rows, before -> after:\n";
  for (const HeldOutStep& st : r.steps)
    s += "    " + st.effect + (st.detail.empty() ? "" : " (" + st.detail + ")") + ": " +
         fmt("%.4f", st.error_before) + " -> " + fmt("%.4f", st.error_after) +
         (st.accepted ? (st.error_after > st.error_before ? "  accepted, but worse on these rows"
                                                          : "  accepted")
                      : "  not accepted") +
         "\n";
  return s;
}

}  // namespace contensou
