#include "contensou/identification/report_text.hpp"

#include "contensou/friction/admissible_shape.hpp"
#include "contensou/identification/identify.hpp"

#include <algorithm>
#include <cstdio>
#include <map>

namespace contensou {

namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

std::string input_text(const ReportInput& info) {
  std::string s = "data: " + info.file + ", " + std::to_string(info.points) + " points, " +
                  std::to_string(info.values) +
                  " measured values, R = " + fmt("%g", info.radius_m) + " m";
  if (info.normal_load_n) s += ", N = " + fmt("%g", *info.normal_load_n) + " N";
  if (!info.normal_load_source.empty()) s += " (" + info.normal_load_source + ")";
  for (const std::string& note : info.column_notes) s += "\ncolumn: " + note;
  for (const RecordedSummary& c : info.recorded) s += "\nrecorded, not in the law: " + c.describe();
  for (const std::string& note : info.columns_not_read) s += "\nnot read: " + note;
  for (const std::string& note : info.missing_values)
    s += "\nmissing (not measured in those rows): " + note;
  if (!info.outliers.empty()) {
    s += "\noutliers: " + std::to_string(info.outliers.size()) +
         " values left out of the fit as gross errors (a robust fit's residual more than 8 robust "
         "sigma from its kinematic neighbours'):";
    for (const Outlier& o : info.outliers) s += "\n  " + o.describe(info.file);
  }
  if (!info.put_back.empty()) {
    s += "\nput back: " + std::to_string(info.put_back.size()) +
         " values first taken for gross errors, which the final model fits within " +
         fmt("%g", kPutBackSigma) + " sigma (sigma against the final model):";
    for (const Outlier& o : info.put_back) s += "\n  " + o.describe(info.file);
  }
  if (!info.profile.empty()) {
    s += "\nprofile: " + info.profile;
    if (info.profile_rms_residual_pa)
      s += " (fit residual: rms " + fmt("%.4g", *info.profile_rms_residual_pa) + " Pa, max " +
           fmt("%.4g", *info.profile_max_residual_pa) + " Pa)";
  }
  return s + "\n";
}

std::string parameters_text(const FitReport& fit) {
  std::string s = "\nparameter   value          95 % interval                 unit\n";
  for (const ParameterEstimate& p : fit.parameters) {
    std::string ci;
    if (p.derived)
      ci = "(from the profile)";
    else if (p.fixed)
      ci = "(fixed)";
    else if (!p.determined)
      ci = "not determined by the data";
    else if (p.ci95)
      ci = "[" + fmt("%.6g", (*p.ci95)[0]) + (p.on_bound == "lower" ? " (bound)" : "") + ", " +
           fmt("%.6g", (*p.ci95)[1]) + (p.on_bound == "upper" ? " (bound)" : "") + "]";
    if (!p.on_bound.empty() && !p.ci95) ci = "on its " + p.on_bound + " bound";
    char line[160];
    std::snprintf(line, sizeof line, "%-10s  %-13.6g  %-28s  %s\n", p.name.c_str(), p.value,
                  ci.c_str(), p.unit.c_str());
    s += line;
    if (!p.note.empty()) s += "            " + p.note + "\n";
  }
  return s;
}

std::string channels_text(const FitReport& fit) {
  std::string s =
      "\nchannel  points  rms          noise scale  scatter      runs p   lag-1   white\n";
  for (const ChannelDiagnostics& c : fit.channels) {
    char line[200];
    std::snprintf(line, sizeof line, "%-7s  %6d  %-11.4g  %-11.4g  %-11.4g  %-7.3f  %+6.3f  %s\n",
                  c.channel.c_str(), c.points, c.rms, c.noise_scale, c.neighbour_scale,
                  c.runs_p_value, c.lag1, c.white ? "yes" : "no");
    s += line;
  }
  s += "scatter = the residual's scatter between neighbouring rows (the noise the data show)\n";
  if (fit.noise_model == NoiseModel::affine) {
    s += "noise grows with the value: sigma = a + b |y|, a in the noise scale column, b =";
    for (const ChannelDiagnostics& c : fit.channels)
      s += " " + fmt("%.4g", c.noise_slope) + " (" + c.channel + ")";
    s += "\n";
  }
  return s;
}

const char* verdict_word(const LoopStep& st) {
  if (step_fit_failed(st)) return "FAILED FIT";
  if (st.removed) return "removed (backward pass)";
  return st.accepted ? "accepted" : "rejected";
}

std::string steps_text(const ClosedLoopReport& loop) {
  std::string s = "\nclosed loop (score test, then LR at alpha / candidates, BIC and 5-fold CV):\n";
  if (loop.selection_rows > 0)
    s += "the steps chose the model on " + std::to_string(loop.selection_rows) + " of the " +
         std::to_string(loop.rows) +
         " rows (every k-th row of each sweep, and each variable's extremes); the base law and "
         "the final model below are fitted on all " +
         std::to_string(loop.rows) + "\n";
  s +=
      "step  effect              detail            LR p-value  threshold  BIC before -> after      "
      "error before -> after  verdict\n";
  int k = 0;
  for (const LoopStep& st : loop.steps) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%-4d  %-18s  %-16s  %-10.2e  %-9.1e  %9.1f -> %-9.1f  %.4f -> %.4f  %s\n", ++k,
                  st.effect.c_str(), st.detail.c_str(), st.lr_p_value, st.threshold, st.bic_before,
                  st.bic_after, st.error_before, st.error_after, verdict_word(st));
    s += line;
    if (step_fit_failed(st))
      s += "      the fit with " + st.effect + " ended worse than the model it extends" +
           (st.retries > 0 ? ", also from " + std::to_string(st.retries) + " other starts" : "") +
           ": its optimiser failed, so this step says nothing about " + st.effect + "\n";
    else if (st.retries > 0)
      s += "      the first fit with " + st.effect +
           " ended worse than the model it extends; this row is its fit from another start (" +
           std::to_string(st.retries) + " tried)\n";
    if (st.accepted && !st.removed)
      for (const std::string& alt : st.ambiguous_with)
        s += "      ambiguous with " + alt + " (see its row; the lower BIC picks " + st.effect +
             ")\n";
  }
  return s;
}

std::string legend_text() {
  return "legend: LR p-value  likelihood-ratio test of the step against the model before it "
         "(small: the effect is in the data)\n"
         "        threshold   alpha / the number of candidate effects (Bonferroni)\n"
         "        BIC         Bayesian information criterion: the fit penalised by its number of "
         "parameters (lower is better)\n"
         "        5-fold CV   the error on data left out of each of five fits\n"
         "        accepted    LR p-value below the threshold, and BIC and CV both lower\n"
         "        FAILED FIT  the extended fit ended worse than the model it extends (its "
         "optimiser failed)\n"
         "        noise_growth  a noise scale growing with the value, a + b |y| per channel, "
         "against a constant one: LR (one degree of freedom per channel) at alpha, and BIC\n"
         "        error       rms over the channels of (channel rms / channel's largest "
         "|value|)\n"
         "        white       the runs and lag-1 tests find no structure left in the residual "
         "(level 0.01 over all the tests)\n";
}

std::string accepted_text(const ClosedLoopReport& loop) {
  std::string s = "accepted effects:";
  std::vector<std::string> notes;
  for (const LoopStep& st : loop.steps)
    if (st.accepted && !st.removed) {
      s += " " + st.effect + (st.detail.empty() ? "" : " (" + st.detail + ")");
      if (!st.ambiguous_with.empty()) {
        s += " [or";
        for (std::size_t i = 0; i < st.ambiguous_with.size(); ++i)
          s += (i ? ", " : " ") + st.ambiguous_with[i];
        s += "]";
      }
      notes.insert(notes.end(), st.separation.begin(), st.separation.end());
    }
  if (loop.accepted_effects.empty()) s += " none";
  if (loop.noise_model == NoiseModel::affine)
    s += "\nnoise: grows with the value (a + b |y| per channel); the final fit is weighted by it";
  for (const std::string& n : notes) s += "\nAMBIGUOUS: " + n;
  s += "\nerror before " + fmt("%.4f", loop.base.error) + ", after " +
       fmt("%.4f", loop.final_fit.error) + "\n";
  if (loop.structure_remains || !loop.final_fit.trace.followed.empty()) {
    const std::string where = loop.final_fit.trace.where();
    s += "STRUCTURE REMAINS: " +
         (where.empty() ? std::string("the final residual is still not white, and follows none of "
                                      "the recorded variables")
                        : "the final residual follows " + where) +
         "; the model lacks something its catalogue does not add.\n";
  }
  return s;
}

std::string join(const std::vector<std::string>& parts, const std::string& middle,
                 const std::string& last) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i)
    s += (i == 0 ? "" : i + 1 == parts.size() ? last : middle) + parts[i];
  return s;
}

}  // namespace

// A recorded variable as a report names it: the load, the time and the row order in words.
std::string variable_in_words(const std::string& name) {
  if (name == "Fz_N") return "the load (Fz_N)";
  if (name == "t_s") return "the time (t_s): a drift over the run";
  if (name == "row order") return "the row order: a drift over the run";
  return name;
}

// What limits a fit, in words that hold on the data: the noise only when the residual is white,
// follows none of the recorded variables and is no larger than its scatter between
// neighbouring rows; else where the structure is.
std::string limit_text(const FitReport& fit, bool structure_remains) {
  const std::string where = fit.trace.where();
  std::string worst;
  double ratio = 0.0;
  for (const ChannelDiagnostics& c : fit.channels)
    if (c.neighbour_scale > 0.0 && c.rms / c.neighbour_scale > ratio) {
      ratio = c.rms / c.neighbour_scale;
      worst = c.channel;
    }
  if (!where.empty()) return "structure in the residual that the model lacks: it follows " + where;
  if (structure_remains)
    return "structure in the residual (not white along " +
           std::string(fit.channels.empty() ? "the rows" : "psi or the time") +
           ") that none of the recorded variables explains";
  if (!fit.within_noise())
    return "a misfit larger than the noise: " + worst + "'s rms is " + fmt("%.2g", ratio) +
           " times its scatter between neighbouring rows";
  const std::vector<std::string> warnings = fit_warnings(fit);
  if (!warnings.empty()) return "the data: " + warnings.front();
  return "the measurement noise (the residual is white, follows none of the recorded "
         "variables and is no larger than its scatter between neighbouring rows; error " +
         fmt("%.4f", fit.error) + ")";
}

std::string trace_text(const FitReport& fit) {
  const ResidualTrace& t = fit.trace;
  if (t.tests == 0) return "";
  if (t.followed.empty())
    return "residual traced: follows none of the variables (" + std::to_string(t.tests) +
           " tests, Holm at " + fmt("%g", t.alpha) + ")\n";
  std::string s = "residual traced (" + std::to_string(t.tests) + " tests, Holm at " +
                  fmt("%g", t.alpha) + "), strongest first:\n";
  for (const TracedVariable& v : t.followed) s += "  " + v.describe() + "\n";
  return s;
}

// With the profile identified (no --profile) and a residual that still follows the kinematics,
// the identified profile misses the tire's shape, and what was accepted besides the shape
// may stand in for that misfit (offsets, crosstalk): said, with the measurement that decides.
std::string identified_profile_caveat(const ClosedLoopReport& loop) {
  const bool stand_in = std::any_of(loop.steps.begin(), loop.steps.end(), [](const LoopStep& st) {
    return st.accepted && !st.removed && st.kind != Effect::shape &&
           st.kind != Effect::profile_detail && st.kind != Effect::profile_correction;
  });
  if (loop.final_spec.profile_model || !loop.final_spec.uses_exact() || !stand_in) return "";
  std::string kinematic;
  for (const TracedVariable& t : loop.final_fit.trace.followed)
    if (t.kinematic && kinematic.find(t.variable) == std::string::npos)
      kinematic += (kinematic.empty() ? "" : ", ") + t.variable;
  if (kinematic.empty()) return "";
  return " Caution: the residual still follows the kinematics (" + kinematic + "): the " +
         (loop.final_spec.profile_degree == 4 ? "quartic" : "quadratic") +
         " profile identified without --profile does not capture this "
         "tire's shape, and the effects accepted after the shape may stand in for that misfit; a "
         "measured profile (--profile) decides them.";
}

namespace {

// A profile correction's factor in the final model (the step's own if the final fit does not
// report its weights).
std::string final_correction(const FitReport& fit, const std::string& step_detail) {
  const ParameterEstimate *w1 = nullptr, *w2 = nullptr;
  for (const ParameterEstimate& e : fit.parameters) {
    if (e.name == "profile_w1") w1 = &e;
    if (e.name == "profile_w2") w2 = &e;
  }
  return w1 && w2 ? profile_correction_detail(w1->value, w2->value) : step_detail;
}

}  // namespace

namespace {

// What an instrument effect did to the channels, without naming a cause: "a constant in
// Mz_Nm", "Fy_N picks up a share of Fx_N".
std::string instrument_words(const LoopStep& st) {
  if (st.kind == Effect::channel_offset) return "a constant in " + st.detail;
  if (st.kind == Effect::slip_angle_offset) return "the sliding direction read turned";
  const std::size_t arrow = st.detail.find(" <- ");
  if (arrow == std::string::npos) return st.effect + " (" + st.detail + ")";
  return st.detail.substr(0, arrow) + " picks up a share of " + st.detail.substr(arrow + 4);
}

// An accepted step in words: an instrument's effect without its evidence names its physical
// alternative too.
std::string accepted_in_words(const LoopStep& st) {
  if (!st.unconfirmed.empty())
    return instrument_words(st) + ": an instrument's fault, or " + st.unconfirmed +
           " (these rows cannot tell which)";
  return effect_in_words(st.kind, variable_in_words(st.detail));
}

// ". Unstable under resampling, so not accepted: X (3 of 5), ..." or "".
std::string unstable_in_words(const ClosedLoopReport& loop) {
  std::vector<std::string> unstable;
  for (const EffectStability& e : loop.stability)
    if (!e.stable)
      unstable.push_back(e.effect + " (" + std::to_string(e.accepted_in) + " of " +
                         std::to_string(e.resamples) + ")");
  return unstable.empty()
             ? ""
             : ". Unstable under resampling, so not accepted: " + join(unstable, ", ", ", ");
}

}  // namespace

std::string loop_summary(const ClosedLoopReport& loop) {
  std::vector<std::string> shown, not_needed, failed;
  const auto step_name = [](const LoopStep& st) {
    return st.detail.empty() || st.kind == Effect::shape || st.kind == Effect::noise_growth ||
                   st.kind == Effect::profile_correction
               ? st.effect
               : st.effect + " (" + st.detail + ")";
  };
  // A candidate's last trial decides whether it is "not needed" or "not decided": a rejection
  // after a failed fit, or a failed fit after a rejection, is tested against another model.
  std::map<std::string, bool> last_failed;
  for (const LoopStep& st : loop.steps) last_failed[step_name(st)] = step_fit_failed(st);
  for (const LoopStep& st : loop.steps) {
    const std::string name = step_name(st);
    if (st.accepted && !st.removed && st.kind == Effect::profile_correction)
      shown.push_back(effect_in_words(st.kind, final_correction(loop.final_fit, st.detail)));
    else if (st.accepted && !st.removed)
      shown.push_back(accepted_in_words(st));
    else if (last_failed[name])
      failed.push_back(name);
    else
      not_needed.push_back(name);
  }
  // A candidate tried in several steps is named once, and not at all once it was accepted.
  const auto once = [&](std::vector<std::string>& names) {
    std::vector<std::string> kept;
    for (const std::string& n : names)
      if (std::find(kept.begin(), kept.end(), n) == kept.end()) kept.push_back(n);
    names = kept;
  };
  for (const LoopStep& st : loop.steps)
    if (st.accepted && !st.removed) {
      std::erase(not_needed, step_name(st));
      std::erase(failed, step_name(st));
    }
  once(not_needed);
  once(failed);
  std::string s = shown.empty() ? "the data need nothing beyond the fractional law"
                                : "the data show that " + join(shown, "; ", "; and ");
  if (!not_needed.empty()) s += ". Tried and not needed: " + join(not_needed, ", ", ", ");
  if (!failed.empty()) s += ". Not decided (the fit failed): " + join(failed, ", ", ", ");
  s += unstable_in_words(loop);
  s += ". The fit is limited by " + limit_text(loop.final_fit, loop.structure_remains);
  return s + "." + identified_profile_caveat(loop);
}

// The radius against the data: the pure-spin torque over the sliding force and the radius,
// M0 / (F0 R) = A^2 / A^1 (theory.md section 4), is at most 1 for any patch (every point's
// arm is at most R) and 0.59 to 2/3 for Hertz and uniform pressure. Far outside, the radius
// or the units of a column are wrong, and the fit is not to be believed.
std::string radius_warning(const FractionalLaw<double>& law) {
  if (!(law.F0 > 0.0 && law.M0 > 0.0 && law.radius > 0.0)) return "";
  const double ratio = law.M0 / (law.F0 * law.radius);
  const std::string numbers = "M0 = " + fmt("%.4g", law.M0) +
                              " N m, F0 R = " + fmt("%.4g", law.F0 * law.radius) +
                              " N m with R = " + fmt("%.4g", law.radius) + " m";
  if (ratio > 1.05)
    return "the radius is too small for the torque: " + numbers +
           ", but no patch of radius R "
           "gives more than F0 R (M0 / (F0 R) = " +
           fmt("%.3g", ratio) + " > 1): is R in metres, and the torque in N m?";
  if (ratio < 0.05)
    return "the radius is too large for the torque: " + numbers +
           ", M0 / (F0 R) = " + fmt("%.3g", ratio) +
           " where a tire patch gives 0.3 to 0.7 (2/3 for uniform pressure): is R in metres, "
           "and the torque in N m?";
  return "";
}

std::vector<std::string> fit_warnings(const FitReport& fit) {
  std::vector<std::string> w;
  const int scales = fit.residuals - fit.free_parameters - fit.degrees_of_freedom;
  if (fit.degrees_of_freedom < kFewDegreesOfFreedomPerScale * std::max(1, scales))
    w.push_back("too little data: " + std::to_string(fit.residuals) + " measured values for " +
                std::to_string(fit.free_parameters) + " parameters and " + std::to_string(scales) +
                " noise scales leave " + std::to_string(fit.degrees_of_freedom) +
                " degrees of freedom (fewer than " + std::to_string(kFewDegreesOfFreedomPerScale) +
                " per noise scale): the noise scales are uncertain and the intervals wide "
                "(Student t with " +
                std::to_string(fit.degrees_of_freedom) + " degrees of freedom)");
  for (const ParameterEstimate& p : fit.parameters)
    if (!p.derived && !p.fixed && !p.determined)
      w.push_back(p.name + " is not determined by the data (no row is sensitive to it)");
  if (!fit.converged) w.push_back("the solver did not converge; the values are its last iterate");
  const std::string radius = radius_warning(fit.law);
  if (!radius.empty()) w.push_back(radius);
  return w;
}

std::vector<std::string> shape_cautions(const FitReport& fit) {
  std::vector<std::string> w;
  // A profile's weight at zero (a pressure that vanishes at the rim, say) or the blend at an
  // end is an ordinary shape, marked in the table but no caution.
  const auto ordinary = [](const std::string& name) {
    return name.rfind("profile_w", 0) == 0 || name == "shape_blend";
  };
  for (const ParameterEstimate& p : fit.parameters)
    if (!p.on_bound.empty() && !ordinary(p.name))
      w.push_back(p.name + " = " + fmt("%.6g", p.value) + " ends on its " + p.on_bound +
                  " bound: " + p.bound_meaning +
                  "; its interval is one-sided, from the bound, and the fit is held there by the "
                  "bound rather than by the data");
  const FractionalLaw<double>& law = fit.law;
  if (law.F0 > 0.0 && law.M0 > 0.0 && law.radius > 0.0 && law.a > 0.0 && law.m > 0.0) {
    const ShapeAdmissibility a = shape_admissibility(law.a, law.m, law.M0 / (law.F0 * law.radius));
    if (!a.admissible)
      w.push_back("no non-negative pressure on the patch gives this law: " + a.reason);
    else if (!a.edge.empty())
      w.push_back("the law is held on the edge of the laws a non-negative pressure gives (" +
                  a.edge + "): the data push it further, where no patch goes");
  }
  return w;
}

namespace {

// The cautions of a fit as the report's first lines ("" when there are none).
std::string cautions_text(const std::string& which, const FitReport& fit) {
  std::string s;
  for (const std::string& c : shape_cautions(fit)) s += "CAUTION (" + which + "): " + c + "\n";
  return s;
}

// The rigid patch that gives the motion from the force, when the model carries one.
std::string motion_patch_text(const FitReport& fit) {
  if (!fit.model || !fit.model->motion_patch) return "";
  return "\nthe motion from the force (predict): the normal of the limit surface of a rigid "
         "Coulomb patch chosen by the measured directions (a non-negative pressure, so its "
         "surface exists; the force from the motion stays the law's): " +
         rigid_patch_text(*fit.model->motion_patch) + "\n";
}

}  // namespace

std::string fit_report_text(const ReportInput& input, const FitReport& fit) {
  std::string s = input_text(input) + parameters_text(fit) + channels_text(fit);
  s += "\nfit: chi2 = " + fmt("%.4g", fit.chi2) + " on " + std::to_string(fit.degrees_of_freedom) +
       " degrees of freedom, AIC = " + fmt("%.2f", fit.aic) + ", BIC = " + fmt("%.2f", fit.bic) +
       ", error = " + fmt("%.4f", fit.error) + (fit.converged ? "" : "  (solver NOT converged)") +
       "\n";
  s += fit.residual_white
           ? "residuals: white (no structure found by the runs and lag-1 tests)\n"
           : "residuals: NOT white: the model misses something the data show (see the pictures)\n";
  s += trace_text(fit);
  s += "error = rms over the channels of (channel rms / channel's largest |value|)\n";
  for (const std::string& w : fit_warnings(fit)) s += "WARNING: " + w + "\n";
  return s;
}

std::string fit_report_text_with_cautions(const ReportInput& input, const FitReport& fit) {
  std::string s = cautions_text("the law", fit) + data_checks_text(input.checks) + "\n" +
                  fit_report_text(input, fit) + motion_patch_text(fit);
  for (const HeldOutResult& h : input.held_out) s += held_out_text(h);
  return s;
}

namespace {

std::string stability_text(const ClosedLoopReport& loop) {
  if (loop.stability.empty()) return "";
  std::string s =
      "\nstability (the loop run again on subsamples of about 80 % of the rows; an "
      "effect stays when accepted in at least " +
      fmt("%.0f", 100 * kStableShare) + " % of them):\n";
  for (const EffectStability& e : loop.stability)
    s += "  " + e.effect + ": accepted in " + std::to_string(e.accepted_in) + " of " +
         std::to_string(e.resamples) +
         (e.stable ? "" : ": UNSTABLE, not accepted (the model above is the loop without it)") +
         "\n";
  return s;
}

}  // namespace

std::string loop_report_text(const ReportInput& input, const ClosedLoopReport& loop) {
  std::string s = cautions_text("final model", loop.final_fit);
  if (!loop.accepted_effects.empty()) s += cautions_text("base law", loop.base);
  s += data_checks_text(input.checks) + "\n";
  s += "base model: the fractional law (seed eqs. 5-7)\n" + fit_report_text(input, loop.base) +
       steps_text(loop) + legend_text() + accepted_text(loop);
  if (!loop.accepted_effects.empty())
    s += std::string("\nfinal model (") +
         (loop.final_spec.uses_exact() ? "exact integrals over the profile" : "fractional law") +
         "):\n" + fit_report_text(input, loop.final_fit);
  s += stability_text(loop) + motion_patch_text(loop.final_fit);
  s += "\nin plain words: " + loop_summary(loop) + "\n";
  for (const HeldOutResult& h : input.held_out) s += held_out_text(h);
  return s;
}

}  // namespace contensou
