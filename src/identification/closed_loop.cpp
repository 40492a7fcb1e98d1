#include "contensou/identification/closed_loop.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <tuple>

#include "contensou/identification/effect_catalogue.hpp"
#include "contensou/identification/residual_trace.hpp"
#include "contensou/identification/statistics.hpp"
#include "fit_problem.hpp"
#include "loop_candidates.hpp"
#include "loop_state.hpp"
#include "test_seams.hpp"

namespace contensou {
using namespace detail;  // NOLINT: the loop's candidates (loop_candidates.hpp)

namespace {

constexpr int K = kModelParameters;
constexpr std::size_t kMaxFitted = 4;  // candidates fitted per step at most

// The scan of w_s for speed_dependence: log-spaced over the data's effective slip speeds.
std::vector<double> speed_grid(const MeasuredData& d, double R) {
  std::vector<double> w;
  for (const MeasuredPoint& p : d.points) {
    const double u = std::abs(p.kinematics.omega) * R;
    w.push_back(std::sqrt(p.kinematics.vx * p.kinematics.vx + p.kinematics.vy * p.kinematics.vy +
                          4.0 * u * u / 9.0));
  }
  std::sort(w.begin(), w.end());
  const double lo = std::max(w[w.size() / 10], 1e-3), hi = std::max(w[w.size() * 9 / 10], 2 * lo);
  std::vector<double> grid;
  for (int i = 0; i < 5; ++i) grid.push_back(lo * std::pow(hi / lo, i / 4.0));
  return grid;
}

// Cross-validated error: mean squared weighted prediction error of held-out points, k folds
// (point i in fold i mod k). Each fold's estimate is one Gauss-Newton step from the full-data
// estimate on the training rows, delta = -(J_T' J_T)^-1 J_T' r_T, and the held-out residual is
// r_H + J_H delta (the one-step approximation of refitting, accurate near the optimum).
double cv_error(const MeasuredData& data, const ModelSpec& spec, const std::array<double, K>& theta,
                const NoiseScales& noise, int folds) {
  Eigen::VectorXd r;
  Eigen::MatrixXd Jall;
  std::vector<int> row_point;
  weighted_jacobian(data, spec, theta, noise, &r, &Jall, {}, &row_point);
  const Eigen::MatrixXd J = free_columns(Jall, spec);
  double sum = 0.0;
  int n = 0;
  for (int f = 0; f < folds; ++f) {
    std::vector<Eigen::Index> train, held;
    for (Eigen::Index row = 0; row < J.rows(); ++row)
      (row_point[static_cast<std::size_t>(row)] % folds == f ? held : train).push_back(row);
    if (held.empty() || static_cast<Eigen::Index>(train.size()) <= J.cols()) continue;
    Eigen::MatrixXd JT(static_cast<Eigen::Index>(train.size()), J.cols());
    Eigen::VectorXd rT(static_cast<Eigen::Index>(train.size()));
    for (std::size_t k = 0; k < train.size(); ++k) {
      JT.row(static_cast<Eigen::Index>(k)) = J.row(train[k]);
      rT(static_cast<Eigen::Index>(k)) = r(train[k]);
    }
    const Eigen::VectorXd delta = -JT.colPivHouseholderQr().solve(rT);
    for (Eigen::Index row : held) {
      const double e = r(row) + J.row(row).dot(delta);
      sum += e * e;
      ++n;
    }
  }
  return sum / std::max(n, 1);
}

// Score step: the score statistic of every candidate at its null, from one Jacobian of the
// current fit (with the shape blend's column evaluated at lambda = 0). speed_dependence is
// scored at each w_s of a scan (Bonferroni over the scan); *best_speed_ref gets the best w_s.
std::vector<CandidateScore> score_candidates(const MeasuredData& data, const LoopState& st,
                                             const std::vector<Candidate>& cands,
                                             const NoiseSettings& noise,
                                             const ClosedLoopOptions& loop, double* best_speed_ref,
                                             std::vector<Eigen::VectorXd>* directions) {
  ModelSpec scoring = st.spec;
  if (!st.spec.uses_exact()) scoring.free[kShapeBlend] = true;
  scoring.differentiate_kinematics = true;  // the rig's kinematics scored at their nulls
  const NoiseScales scales = st.fit.noise_scales();
  build_laws(scoring, noise.stop);
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  std::vector<int> row_point;
  weighted_jacobian(data, scoring, st.theta, scales, &r, &J, {}, &row_point);
  const std::vector<double> grid = speed_grid(data, st.spec.radius_m);
  *best_speed_ref = grid[grid.size() / 2];
  std::vector<CandidateScore> scores;
  for (const Candidate& c : cands) {
    CandidateScore sc{describe(c.effect).name, c.detail, 0.0, 1.0};
    if (c.scan_speed) {
      ModelSpec sp = st.spec;
      sp.speed_in_exact = loop.speed_inside_integrals && st.spec.uses_exact();
      double best = 0.0;
      for (double w : grid) {
        build_laws(sp, noise.stop);
        std::array<double, K> th = st.theta;
        th[kSpeedRef] = w;
        Eigen::VectorXd rs;
        Eigen::MatrixXd Js;
        weighted_jacobian(data, sp, th, scales, &rs, &Js);
        const double lm = lm_statistic(rs, Js, st.spec, kSpeedDrop);
        if (lm > best) {
          best = lm;
          *best_speed_ref = w;
        }
      }
      sc.statistic = best;
      sc.p_value = std::min(1.0, chi2_survival(best, 1.0) * static_cast<double>(grid.size()));
      directions->emplace_back();  // scanned: no single direction
    } else {
      const Eigen::VectorXd z = c.scored >= 0 ? Eigen::VectorXd(J.col(c.scored))
                                              : dependence_column(data, J, row_point, st.theta, c);
      directions->push_back(score_direction(J, st.spec, z));
      sc.statistic = score_statistic(r, z, directions->back(), st.spec);
      sc.p_value = chi2_survival(sc.statistic, 1.0);
    }
    scores.push_back(sc);
  }
  return scores;
}

// The current model extended by a candidate effect. For shape, the blend's end point
// lambda = 1: the exact integrals alone (the law's a, M0, m drop out). LR(exact vs law) is a
// lower bound of LR(blend vs law), so testing it with the blend's degrees of freedom is
// conservative, and the fit avoids the blend's degeneracy near lambda = 1.
ModelSpec extend(const ModelSpec& spec, const Candidate& c, double speed_ref,
                 const ClosedLoopOptions& loop) {
  ModelSpec ext = spec;
  for (int p : c.parameters) ext.free[p] = true;
  if (c.effect == Effect::friction_dependence) ext.dependence[c.slot] = c.covariate;
  if (c.effect == Effect::shape) {
    ext.exact_only = true;
    for (int p : {kA, kM0, kMShape, kShapeBlend}) ext.free[p] = false;
    ext.value[kShapeBlend] = 1.0;
  }
  if (c.scan_speed) {
    ext.value[kSpeedRef] = speed_ref;
    ext.value[kSpeedDrop] = 0.05;
  }
  set_speed_inside(ext, loop);
  return ext;
}

// Test step: the extension against the current model by (1) the likelihood-ratio test at
// `threshold`, (2) BIC and (3) the cross-validated error; accepted when all three agree.
LoopStep test_extension(const MeasuredData& data, const LoopState& cur, const LoopState& ext,
                        const Candidate& c, double threshold, const ClosedLoopOptions& loop) {
  LoopStep trial;
  trial.kind = c.effect;
  trial.effect = describe(c.effect).name;
  trial.detail = c.detail;
  const int q = static_cast<int>(c.parameters.size());
  trial.lr = std::max(0.0, cur.fit.m2ll - ext.fit.m2ll);
  trial.lr_dof = q;
  trial.lr_p_value = chi2_survival(trial.lr, q);
  trial.threshold = threshold;
  trial.bic_before = cur.fit.bic;
  trial.bic_after = ext.fit.bic;
  const NoiseScales scales = cur.fit.noise_scales();
  trial.cv_before = cv_error(data, cur.spec, cur.theta, scales, loop.folds);
  trial.cv_after = cv_error(data, ext.spec, ext.theta, scales, loop.folds);
  const bool lr_ok = trial.lr_p_value < trial.threshold;
  const bool bic_ok = trial.bic_after < trial.bic_before;
  const bool cv_ok = trial.cv_after < trial.cv_before;
  trial.accepted = lr_ok && bic_ok && cv_ok;
  trial.verdict =
      std::string(lr_ok ? "LR significant" : "LR not significant") +
      (bic_ok ? ", BIC improves" : ", BIC does not improve") +
      (cv_ok ? ", cross-validated error improves" : ", cross-validated error does not improve");
  if (c.effect == Effect::shape && trial.accepted)
    trial.verdict += "; the exact integrals replace the law";
  trial.error_before = cur.fit.error;
  trial.channels_before = cur.fit.channels;
  trial.fit_before = cur.fit;
  for (const ParameterEstimate& e : ext.fit.parameters)
    for (int p : c.parameters)
      if (e.name == parameter_info(p).name) trial.parameters.push_back(e);
  if (c.effect == Effect::shape) {  // the blend at its end point: the exact integrals alone
    ParameterEstimate blend;
    blend.name = parameter_info(kShapeBlend).name;
    blend.unit = parameter_info(kShapeBlend).unit;
    blend.value = 1.0;
    blend.fixed = true;
    blend.determined = false;
    trial.parameters.insert(trial.parameters.begin(), blend);
  }
  trial.error_after = ext.fit.error;
  trial.channels_after = ext.fit.channels;
  trial.fit_after = ext.fit;
  return trial;
}

std::string step_label(int step) {
  return "step " + std::to_string(step) + ": ";
}

}  // namespace

bool step_fit_failed(const LoopStep& st) {
  // The noise step reweights the values: its unweighted error may rise.
  if (st.effect == kNoiseGrowthEffect) return false;
  // The extended model contains the one before it, so at its optimum the error cannot be
  // larger; a relative 1e-6 allows for the solvers' tolerances.
  return st.error_after > st.error_before * (1.0 + 1e-6) + 1e-12;
}

// The loop of the header: base fit; then per step score, rank, fit and test the candidates
// (of those that pass, the lowest BIC is accepted; close alternatives are named); then prune.
// Other starts for a step whose fit ended worse than the model it extends (which it contains:
// the optimiser stopped short, e.g. at a start where the new parameters' gradient vanishes):
// each new free parameter with a closed range moved a quarter of the way to its upper, then
// its lower bound.
std::vector<ModelSpec> other_starts(const ModelSpec& ext, const Candidate& c) {
  std::vector<ModelSpec> out;
  for (int p : c.parameters) {
    const ParameterBounds b = parameter_bounds(p);
    if (!ext.free[p] || !b.closed()) continue;
    for (double bound : {b.upper, b.lower}) {
      ModelSpec s = ext;
      s.value[p] = ext.value[p] + 0.25 * (bound - ext.value[p]);
      if (s.value[p] != ext.value[p]) out.push_back(s);
    }
  }
  return out;
}

// The extension fitted and tested; refitted from other_starts (the best kept) while its fit
// ends worse than the model it extends.
struct StepFit {
  LoopState ext;
  LoopStep step;
};
StepFit fit_step(const MeasuredData& data, const LoopState& cur, const ModelSpec& ext_spec,
                 const Candidate& c, double threshold, const NoiseSettings& noise,
                 const ClosedLoopOptions& loop) {
  NoiseSettings first = noise;
  if (const int n = testing::Seams::of(loop).first_fit_iterations; n >= 0)
    first.solver_iterations = n;
  StepFit best{fit_state(data, ext_spec, first), {}};
  throw_if_stopped(noise.stop);
  best.step = test_extension(data, cur, best.ext, c, threshold, loop);
  int retries = 0;
  for (const ModelSpec& start : other_starts(ext_spec, c)) {
    if (!step_fit_failed(best.step)) break;
    say(loop, label(c) +
                  ": the fit ended worse than the model it extends; refitting from "
                  "another start");
    ++retries;
    try {
      StepFit again{fit_state(data, start, noise), {}};
      again.step = test_extension(data, cur, again.ext, c, threshold, loop);
      if (again.step.error_after < best.step.error_after) best = std::move(again);
    } catch (const Interrupted&) {
      throw;
    } catch (const std::runtime_error&) {
      // This start failed too (the solver found no usable point): try the next one.
    }
  }
  best.step.retries = retries;
  return best;
}

// A candidate fitted and tested in a step.
struct Trial {
  std::size_t candidate;
  LoopState ext;
  LoopStep step;
};

// The catalogue's candidates for the model, less those the caller excluded (by name, or with
// their detail).
std::vector<Candidate> candidates_for(const MeasuredData& data, const ModelSpec& spec,
                                      const std::vector<Covariate>& covariates,
                                      const ClosedLoopOptions& loop) {
  std::vector<Candidate> cands = catalogue(data, spec, covariates);
  std::erase_if(cands, [&](const Candidate& c) {
    const auto& x = loop.excluded;
    return std::find(x.begin(), x.end(), label(c)) != x.end() ||
           std::find(x.begin(), x.end(), describe(c.effect).name) != x.end();
  });
  return cands;
}

// Of the trials that pass the tests, the one with the lowest BIC (nullptr if none); any other
// that passes within a BIC difference of 2, or whose score direction correlates above 0.9 with
// the accepted one's and whose LR is significant, is named as an alternative the data do not
// rule out, with the measurement that would separate the two.
Trial* choose_among(std::vector<Trial>& trials, const std::vector<Candidate>& cands,
                    const std::vector<Eigen::VectorXd>& directions, const MeasuredData& data,
                    const ClosedLoopOptions& loop, int step) {
  Trial* best = nullptr;
  for (Trial& t : trials)
    if (t.step.accepted && (!best || t.step.bic_after < best->step.bic_after)) best = &t;
  for (Trial& t : trials) {
    const Candidate& c = cands[t.candidate];
    if (best && &t != best) {
      const Candidate& b = cands[best->candidate];
      const double dbic = t.step.bic_after - best->step.bic_after;
      const double corr =
          direction_correlation(directions[t.candidate], directions[best->candidate]);
      const bool significant = t.step.lr_p_value < t.step.threshold;
      if (t.step.accepted)
        t.step.verdict += "; passes too, but " + label(b) + " has the lower BIC (by " +
                          std::to_string(dbic) + ")";
      // Parallel score directions with BIC within 10 of each other (beyond, the data prefer one
      // very strongly: Kass and Raftery's scale) leave the two apart only by their form.
      if ((t.step.accepted && dbic < 2.0) || (significant && corr > 0.9 && dbic < 10.0)) {
        LoopStep& chosen = best->step;
        t.step.verdict += "; ambiguous with the accepted " + label(b);
        chosen.ambiguous_with.push_back(label(c));
        chosen.separation.push_back(label(b) + " and " + label(c) +
                                    " explain the residual about "
                                    "equally (BIC difference " +
                                    std::to_string(dbic) + ", score correlation " +
                                    std::to_string(corr) +
                                    "): " + separating_measurement(b, c, data));
      }
      t.step.accepted = false;
    }
    if (&t == best) {
      t.step.unconfirmed =
          c.effect == Effect::slip_angle_offset
              ? unconfirmed_slip_angle(t.ext.theta[kSlipAngleOffset], data, t.ext.spec.radius_m)
              : unconfirmed_instrument(c, data);
      if (!t.step.unconfirmed.empty()) {
        t.step.ambiguous_with.push_back("a physical effect");
        t.step.separation.push_back(label(c) +
                                    " is an instrument's effect, but the data lack the "
                                    "measurement that tells it from " +
                                    t.step.unconfirmed);
      }
    }
    say(loop, step_label(step) + label(c) + (t.step.accepted ? " accepted" : " rejected") + " (" +
                  t.step.verdict + ")");
  }
  return best;
}

// The quadratic's Bernstein weights (1, w1, w2) raised to degree 4 (the same polynomial): two
// elevations n -> n + 1, w'_k = (k / (n + 1)) w_(k-1) + (1 - k / (n + 1)) w_k.
std::array<double, 5> raised_to_quartic(double w1, double w2) {
  std::array<double, 5> w{1.0, w1, w2, 0.0, 0.0};
  for (int n = 2; n < 4; ++n) {
    std::array<double, 5> e{};
    for (int k = 0; k <= n + 1; ++k) {
      const double t = static_cast<double>(k) / (n + 1);
      e[k] = (k > 0 ? t * w[k - 1] : 0.0) + (k <= n ? (1.0 - t) * w[k] : 0.0);
    }
    w = e;
  }
  return w;
}

// The model's form tested right after the shape (profile_detail, profile_correction): `ext`
// fitted from the current state and tested by the loop's rules at `threshold`; `detail`, if set,
// names the step from its fit. True when accepted (st is then its state).
struct ShapeStep {
  const MeasuredData& data;
  const NoiseSettings& noise;
  const ClosedLoopOptions& loop;
  int step;
  double threshold;
};
bool test_shape_step(const ShapeStep& at, const ModelSpec& ext, const Candidate& c,
                     const std::function<std::string(const LoopState&)>& detail, LoopState& st,
                     ClosedLoopReport& report) {
  const int values = at.data.count(0) + at.data.count(1) + at.data.count(2);
  if (values < measured_values_needed(at.data, ext, at.noise)) return false;
  say(at.loop, step_label(at.step) + "fitting " + label(c));
  StepFit fitted = fit_step(at.data, st, ext, c, at.threshold, at.noise, at.loop);
  if (detail) fitted.step.detail = detail(fitted.ext);
  say(at.loop, step_label(at.step) + label(c) + (fitted.step.accepted ? " accepted" : " rejected") +
                   " (" + fitted.step.verdict + ")");
  report.steps.push_back(fitted.step);
  if (!fitted.step.accepted) return false;
  report.accepted_effects.push_back(describe(c.effect).name);
  st = std::move(fitted.ext);
  return true;
}

// Right after the shape is accepted with the identified profile: the quartic profile, started
// at the quadratic raised to degree 4 (the same profile: the fit starts at the quadratic's
// optimum and can only improve), tested against it by the loop's rules (LR on 2 degrees of
// freedom at alpha over the step's candidates, BIC, CV). A rig file of a tire whose profile is
// not quadratic in rho^2 otherwise leaves a misfit that later steps fill with stand-ins.
bool test_profile_detail(const ShapeStep& at, LoopState& st, ClosedLoopReport& report) {
  if (st.spec.profile_model || !st.spec.uses_exact() || st.spec.profile_degree != 2) return false;
  ModelSpec quartic = st.spec;
  quartic.profile_degree = 4;
  const std::array<double, 5> w = raised_to_quartic(st.theta[kProfileW1], st.theta[kProfileW2]);
  const int slots[4] = {kProfileW1, kProfileW2, kProfileW3, kProfileW4};
  for (int k = 0; k < 4; ++k) {
    quartic.value[slots[k]] = w[static_cast<std::size_t>(k + 1)];
    quartic.free[slots[k]] = true;
  }
  const Candidate c{Effect::profile_detail, "quartic", {kProfileW3, kProfileW4}, -1};
  return test_shape_step(at, quartic, c, {}, st, report);
}

// Right after the shape is accepted with a given profile: that profile times a quadratic factor
// in rho^2 (w1 = w2 = 1 at the start: the profile as given), tested by the loop's rules (LR on
// 2 degrees of freedom, BIC, CV). A profile that is not the tire's otherwise leaves a misfit
// that later steps fill with stand-ins (a speed law, offsets).
bool test_profile_correction(const ShapeStep& at, LoopState& st, ClosedLoopReport& report) {
  if (!st.spec.profile_model || !st.spec.uses_exact() || st.spec.profile_corrected) return false;
  ModelSpec corrected = st.spec;
  corrected.profile_corrected = true;
  for (int p : {kProfileW1, kProfileW2}) {
    corrected.value[p] = 1.0;
    corrected.free[p] = true;
  }
  const Candidate c{Effect::profile_correction, "", {kProfileW1, kProfileW2}, -1};
  // The factor at rho = 0.71 and at the rim, short for the step table (the summary's words
  // take the final model's: profile_correction_detail).
  const auto detail = [](const LoopState& fitted) {
    char buf[64];
    const double w1 = fitted.theta[kProfileW1], w2 = fitted.theta[kProfileW2];
    std::snprintf(buf, sizeof buf, "x%.3g mid, x%.3g rim", 0.25 + 0.5 * w1 + 0.25 * w2, w2);
    return std::string(buf);
  };
  return test_shape_step(at, corrected, c, detail, st, report);
}

ClosedLoopReport close_the_loop(const MeasuredData& data, const IdentificationOptions& options,
                                const ClosedLoopOptions& loop) {
  ClosedLoopReport report;
  const NoiseSettings noise = noise_settings_for(options);
  say(loop, "fitting the base law");
  const std::vector<Covariate> covariates = covariates_of(data);
  LoopState st = fit_state(data, base_spec_for(data, options), noise);
  st.fit.trace = trace_residual(data, st.fit, st.spec.radius_m, covariates);
  report.base = st.fit;
  say(loop, "base law fitted: BIC " + std::to_string(st.fit.bic));
  for (int step = 1; step <= loop.max_steps; ++step) {
    const std::vector<Candidate> cands = candidates_for(data, st.spec, covariates, loop);
    if (cands.empty()) break;
    say(loop, step_label(step) + "scoring " + std::to_string(cands.size()) + " candidate effects");
    double speed_ref = 0.0;
    std::vector<Eigen::VectorXd> directions;
    const std::vector<CandidateScore> scores =
        score_candidates(data, st, cands, noise, loop, &speed_ref, &directions);
    std::vector<std::size_t> order(cands.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return scores[a].p_value < scores[b].p_value;
    });
    std::vector<CandidateScore> sorted;
    for (std::size_t i : order) sorted.push_back(scores[i]);
    const double threshold = loop.alpha / static_cast<double>(cands.size());
    // Candidates in order of significance: the most significant is always fitted, the next
    // ones while their score is significant (at most kMaxFitted). Of those that pass the tests,
    // the one with the lowest BIC is accepted; any other that passes within a BIC difference of
    // 2, or whose score direction correlates above 0.9 with the accepted one's and whose LR is
    // significant, is named as an alternative the data do not rule out.
    std::vector<Trial> trials;
    for (std::size_t rank = 0; rank < order.size() && trials.size() < kMaxFitted; ++rank) {
      if (rank > 0 && sorted[rank].p_value >= threshold) break;
      const Candidate& c = cands[order[rank]];
      const ModelSpec ext_spec = extend(st.spec, c, speed_ref, loop);
      const int values = data.count(0) + data.count(1) + data.count(2);
      if (values < measured_values_needed(data, ext_spec, noise)) {
        say(loop, step_label(step) + label(c) + " not fitted: too little data for its parameters");
        continue;
      }
      say(loop, step_label(step) + "fitting " + label(c));
      StepFit fitted = fit_step(data, st, ext_spec, c, threshold, noise, loop);
      LoopState& ext = fitted.ext;
      LoopStep& trial = fitted.step;
      say(loop, step_label(step) + label(c) + " fitted: BIC " + std::to_string(trial.bic_before) +
                    " -> " + std::to_string(trial.bic_after));
      trial.scores = sorted;
      trials.push_back({order[rank], std::move(ext), std::move(trial)});
    }
    Trial* best = choose_among(trials, cands, directions, data, loop, step);
    for (Trial& t : trials) report.steps.push_back(t.step);
    const bool accepted_any = best != nullptr;
    if (best) {
      report.accepted_effects.push_back(describe(cands[best->candidate].effect).name);
      st = best->ext;
      st.fit.trace = trace_residual(data, st.fit, st.spec.radius_m, covariates);
      report
          .steps[report.steps.size() - trials.size() +
                 static_cast<std::size_t>(best - trials.data())]
          .fit_after.trace = st.fit.trace;
      const ShapeStep at{data, noise, loop, step, threshold};
      if (cands[best->candidate].effect == Effect::shape &&
          (test_profile_detail(at, st, report) || test_profile_correction(at, st, report))) {
        st.fit.trace = trace_residual(data, st.fit, st.spec.radius_m, covariates);
        report.steps.back().fit_after.trace = st.fit.trace;
      }
    }
    if (!accepted_any) break;
  }
  prune(data, noise, loop, st, report);
  if (loop.choose_noise_model && noise.model == NoiseModel::additive && !noise.given)
    test_noise_growth(data, noise, loop, st, report);
  report.noise_model = st.fit.noise_model;
  st.fit.trace = trace_residual(data, st.fit, st.spec.radius_m, covariates);
  report.final_fit = st.fit;
  report.final_spec = st.spec;
  report.structure_remains = !st.fit.residual_white || !st.fit.trace.followed.empty();
  return report;
}

void refit_on_every_row(const MeasuredData& data, const IdentificationOptions& options,
                        const ClosedLoopOptions& loop, ClosedLoopReport& report) {
  NoiseSettings noise = noise_settings_for(options);
  const std::vector<Covariate> covariates = covariates_of(data);
  say(loop, "fitting the base law on all " + std::to_string(data.points.size()) + " rows");
  // Each fit on every row starts from the sample's: its parameters and its noise scales.
  ModelSpec base = base_spec_for(data, options);
  for (const ParameterEstimate& e : report.base.parameters) {
    const int i = parameter_index_by_name(e.name);
    if (i >= 0 && base.free[i]) base.value[i] = e.value;
  }
  noise.start = report.base.noise_scales();
  LoopState st = fit_state(data, base, noise);
  st.fit.trace = trace_residual(data, st.fit, st.spec.radius_m, covariates);
  report.base = st.fit;
  say(loop, "fitting the chosen model on all " + std::to_string(data.points.size()) + " rows");
  noise.model = report.noise_model;
  noise.start = report.final_fit.noise_scales();
  st = fit_state(data, report.final_spec, noise);
  st.fit.trace = trace_residual(data, st.fit, st.spec.radius_m, covariates);
  report.final_fit = st.fit;
  report.final_spec = st.spec;
  report.structure_remains = !st.fit.residual_white || !st.fit.trace.followed.empty();
}

std::vector<Resultants<double>> predict_final_model(const ClosedLoopReport& report,
                                                    const MeasuredData& data) {
  ModelSpec spec = report.final_spec;
  build_laws(spec, {});
  return detail::evaluate_all(spec, spec.value.data(), data);
}

ClosedLoopReport close_the_loop_on_sample(const MeasuredData& data, const std::vector<char>& sample,
                                          const IdentificationOptions& options,
                                          const ClosedLoopOptions& loop) {
  MeasuredData part = data;
  part.points.clear();
  for (std::size_t i = 0; i < data.points.size(); ++i)
    if (i >= sample.size() || sample[i]) part.points.push_back(data.points[i]);
  if (part.points.size() == data.points.size()) return close_the_loop(data, options, loop);
  say(loop, "choosing the model on " + std::to_string(part.points.size()) + " of " +
                std::to_string(data.points.size()) + " rows (every sweep, every variable's range)");
  ClosedLoopReport report = close_the_loop(part, options, loop);
  report.selection_rows = part.points.size();
  report.rows = data.points.size();
  refit_on_every_row(data, options, loop, report);
  return report;
}

}  // namespace contensou
