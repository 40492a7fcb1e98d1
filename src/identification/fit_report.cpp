// The fit's report: parameters with intervals, residual diagnostics, likelihood, AIC and BIC.
// See fit.hpp and fit_problem.hpp.
#include "fit_problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <numeric>

#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/outliers.hpp"
#include "contensou/identification/statistics.hpp"

namespace contensou {
using namespace detail;  // NOLINT: this file implements part of fit_problem.hpp

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int K = kModelParameters;

// Whether a parameter belongs in the report of a model.
bool reported(const ModelSpec& s, int i) {
  if (s.exact_only && (i == kA || i == kM0 || i == kMShape || i == kShapeBlend)) return false;
  const bool parametric = !s.profile_model && s.uses_exact();
  if ((i == kProfileW1 || i == kProfileW2) && !parametric && !s.profile_corrected) return false;
  if (i == kProfileW3 || i == kProfileW4) return parametric && s.profile_degree == 4;
  if (i == kSpeedRef) return s.free[kSpeedDrop] || s.value[kSpeedDrop] != 0.0;
  return s.free[i] || i <= kKx || s.value[i] != parameter_info(i).null_value;
}

// A friction_dependence parameter in the variable's units, at the middle of the range (z = 0,
// f = f_ref (1 - b2)): (1/f) df/dX = b1 / (h (1 - b2)) and (1/f) d2f/dX2 = 4 b2 / (h^2 (1 - b2)),
// h the half range (the note of each parameter shows its own term, the other at 0).
std::string dependence_note(const ModelSpec& spec, int i, const ParameterEstimate& e) {
  if (i < kDependence1 || i > kDependence3Curve) return "";
  const int slot = (i - kDependence1) / 2;
  const bool curve = (i - kDependence1) % 2 == 1;
  if (!spec.dependence[slot]) return "";
  const Covariate& c = *spec.dependence[slot];
  const std::string unit = c.unit.empty() ? "row" : c.unit;
  char buf[320];
  const double per = curve ? 4.0 * e.value / (c.half_range * c.half_range * (1.0 - e.value))
                           : e.value / c.half_range;
  std::snprintf(
      buf, sizeof buf,
      "%s of f (1 + b1 z + b2 (2 z^2 - 1)), z = %s over %.6g to %.6g %s: %s = %.4g 1/%s%s",
      curve ? "b2" : "b1", c.name.c_str(), c.mid - c.half_range, c.mid + c.half_range, unit.c_str(),
      curve ? "(1/f) d2f/dX2" : "(1/f) df/dX", per, unit.c_str(), curve ? "^2" : "");
  return buf;
}

// With friction falling with the slip speed, f is its value at rest: the note says what it is at
// w = w_s and fast, f (1 - beta (1 - e^-1)) and f (1 - beta) (a large beta extrapolates f(0)
// far above the friction the rows show).
std::string speed_note(const ModelSpec& spec, const std::array<double, K>& theta, double f) {
  if (!spec.free[kSpeedDrop] && spec.value[kSpeedDrop] == 0.0) return "";
  const double beta = theta[kSpeedDrop], ws = theta[kSpeedRef];
  char buf[240];
  std::snprintf(buf, sizeof buf,
                "f at rest (w = 0); f(w) = f (1 - beta (1 - e^(-w/w_s))) is %.4g at w = w_s = "
                "%.3g m/s and falls to f (1 - beta) = %.4g at large w",
                f * (1.0 - beta * (1.0 - std::exp(-1.0))), ws, f * (1.0 - beta));
  return buf;
}

// A free estimate on a bound of the fit is named with what the bound means, and no interval
// reaches past the bounds: on a bound it is one-sided, from the bound.
void mark_bound(const ModelSpec& spec, int i, ParameterEstimate& e) {
  const ParameterBounds b = parameter_bounds(spec, i);
  if (e.ci95) {
    (*e.ci95)[0] = std::max((*e.ci95)[0], b.lower);
    (*e.ci95)[1] = std::min((*e.ci95)[1], b.upper);
  }
  if (!spec.free[i]) return;
  const double tol = 1e-9 * std::max(1.0, std::abs(e.value));
  const bool lower = std::isfinite(b.lower) && e.value <= b.lower + tol;
  const bool upper = std::isfinite(b.upper) && e.value >= b.upper - tol;
  if (!lower && !upper) return;
  e.on_bound = lower ? "lower" : "upper";
  e.bound_meaning = bound_meaning(i, upper);
}

ParameterEstimate estimate_of(int i, double value) {
  ParameterEstimate e;
  e.name = parameter_info(i).name;
  e.unit = parameter_info(i).unit;
  e.value = value;
  return e;
}

}  // namespace

namespace detail {

// Values, standard errors and Student-t 95 % intervals (n - p degrees of freedom) of the
// reported parameters; the profile's derived a, M0, m for the exact model; f = F0 / N when the
// load is known; the correlation matrix of the determined parameters.
void report_parameters(const ModelSpec& spec, const std::array<double, K>& theta,
                       const std::array<bool, K>& undetermined, const std::vector<int>& est,
                       const std::optional<Eigen::MatrixXd>& cov, FitReport& report) {
  const double tq =
      report.degrees_of_freedom > 0 ? student_t_quantile(0.975, report.degrees_of_freedom) : kNaN;
  for (int i = 0; i < K; ++i) {
    if (!reported(spec, i)) continue;
    ParameterEstimate e = estimate_of(i, theta[i]);
    e.fixed = !spec.free[i];
    e.determined = spec.free[i] && !undetermined[i];
    if (e.determined && cov && (*cov)(i, i) >= 0.0) {
      e.std_error = std::sqrt((*cov)(i, i));
      e.ci95 = std::array<double, 2>{e.value - tq * e.std_error, e.value + tq * e.std_error};
    } else {
      e.determined = false;
    }
    mark_bound(spec, i, e);
    e.note = dependence_note(spec, i, e);
    report.parameters.push_back(e);
  }
  if (spec.exact_only && spec.profile_model && !spec.profile_corrected) {
    // The exact model has no a, m, M0 of its own: report the profile's asymptote-matched
    // values (fixed, no interval), so that a report always carries the law's parameters.
    const double derived[3] = {spec.profile_a, theta[kF0] * spec.radius_m * spec.profile_m0_ratio,
                               spec.profile_m};
    const int index[3] = {kA, kM0, kMShape};
    for (int j = 0; j < 3; ++j) {
      ParameterEstimate e = estimate_of(index[j], derived[j]);
      e.fixed = true;
      e.determined = false;
      e.derived = true;
      report.parameters.insert(report.parameters.begin() + 1 + j, e);
    }
  }
  if (spec.normal_load_n) {
    const ParameterEstimate& F0 = report.parameters[0];
    const double N = *spec.normal_load_n;
    ParameterEstimate f;
    f.name = "f";
    f.unit = "1";
    f.value = F0.value / N;
    f.fixed = F0.fixed;
    f.determined = F0.determined;
    f.std_error = F0.std_error / N;
    if (F0.ci95) f.ci95 = std::array<double, 2>{(*F0.ci95)[0] / N, (*F0.ci95)[1] / N};
    f.note = speed_note(spec, theta, f.value);
    report.parameters.push_back(f);
  }
  report.correlation = Eigen::MatrixXd::Identity(est.size(), est.size());
  for (std::size_t a = 0; a < est.size(); ++a) {
    report.correlation_names.push_back(parameter_info(est[a]).name);
    if (!cov) continue;
    for (std::size_t b = 0; b < est.size(); ++b)
      if ((*cov)(est[a], est[a]) > 0 && (*cov)(est[b], est[b]) > 0)
        report.correlation(a, b) =
            (*cov)(est[a], est[b]) / std::sqrt((*cov)(est[a], est[a]) * (*cov)(est[b], est[b]));
  }
}

// Diagnostics on the used points: residual whiteness per channel, the dimensionless error,
// the Gaussian -2 log L with the noise scales, AIC and BIC.
void report_quality(const FitSetup& s, const Solution& sol, FitReport& report) {
  MeasuredData subset;
  std::vector<Resultants<double>> sub_pred;
  for (std::size_t i = 0; i < s.data.points.size(); ++i)
    if (s.used(i)) {
      subset.points.push_back(s.data.points[i]);
      sub_pred.push_back(sol.prediction[i]);
    }
  report.prediction = sol.prediction;
  report.psi = sliding_spin_ratio(s.data, s.spec.radius_m);
  report.residual.resize(s.data.points.size());
  for (std::size_t i = 0; i < s.data.points.size(); ++i)
    for (int c = 0; c < kChannels; ++c)
      if (const std::optional<double>& y = s.data.points[i].force[c])
        report.residual[i][c] = *y - sol.prediction[i].vector()(c);
  report.noise_model = s.noise.model;
  report.noise_scale = sol.scale;
  report.noise_slope = sol.slope;
  report.channels = residual_diagnostics(subset, sub_pred, s.spec.radius_m, sol.scale);
  const NoiseScales scales = report.noise_scales();
  const std::array<double, kChannels> scatter =
      neighbour_scatter(subset, sub_pred, [&](int c, std::size_t i) {
        return value_scale(scales, c, sub_pred[i].vector()(c), s.floor_rel[c]);
      });
  for (ChannelDiagnostics& d : report.channels)
    for (int c = 0; c < kChannels; ++c)
      if (d.channel == kChannelColumns[c]) {
        d.noise_slope = sol.slope[c];
        d.neighbour_scale = scatter[c];
      }
  report.residual_white = std::all_of(report.channels.begin(), report.channels.end(),
                                      [](const ChannelDiagnostics& d) { return d.white; });
  double log_det = 0.0, err2 = 0.0;
  for (std::size_t i = 0; i < s.data.points.size(); ++i) {
    if (!s.used(i)) continue;
    for (int c = 0; c < kChannels; ++c) {
      if (!s.data.points[i].force[c]) continue;
      const double sc =
          value_scale(report.noise_scales(), c, sol.prediction[i].vector()(c), s.floor_rel[c]);
      log_det += std::log(2.0 * std::numbers::pi * sc * sc);
    }
  }
  const int measured = static_cast<int>(report.channels.size());
  for (int c = 0, k = 0; c < kChannels; ++c) {
    if (s.counts[c] == 0) continue;
    const double rel = report.channels[k++].rms / s.peak[c];
    err2 += rel * rel;
  }
  report.error = std::sqrt(err2 / std::max(measured, 1));
  const int k_params = report.free_parameters + measured * noise_parameters(s.noise);
  report.m2ll = log_det + report.chi2;
  report.aic = report.m2ll + 2.0 * k_params;
  report.bic = report.m2ll + k_params * std::log(static_cast<double>(report.residuals));
}

}  // namespace detail

bool FitReport::within_noise() const {
  return std::all_of(channels.begin(), channels.end(), [](const ChannelDiagnostics& c) {
    return c.neighbour_scale <= 0.0 || c.rms <= 1.5 * c.neighbour_scale;
  });
}

const ParameterEstimate* FitReport::parameter(const std::string& name) const {
  for (const ParameterEstimate& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<Resultants<double>> predict(const FractionalLaw<double>& law,
                                        const MeasuredData& data) {
  std::vector<Resultants<double>> out;
  out.reserve(data.points.size());
  for (const MeasuredPoint& p : data.points)
    out.push_back(fractional_resultants(law, p.kinematics));
  return out;
}

// The sliding-spin ratio psi = |v| / u with v = (vx, vy) and u = |omega| R (seed eqs. 12-13;
// theory.md sections 1 and 4); infinity for pure sliding (u = 0).
std::vector<double> sliding_spin_ratio(const MeasuredData& data, double radius_m) {
  std::vector<double> psi;
  psi.reserve(data.points.size());
  for (const MeasuredPoint& p : data.points) {
    const double v = std::hypot(p.kinematics.vx, p.kinematics.vy);
    const double u = std::abs(p.kinematics.omega) * radius_m;
    psi.push_back(u > 0.0 ? v / u : std::numeric_limits<double>::infinity());
  }
  return psi;
}

std::vector<ChannelDiagnostics> residual_diagnostics(const MeasuredData& data,
                                                     const std::vector<Resultants<double>>& model,
                                                     double radius_m,
                                                     const std::array<double, kChannels>& scale) {
  // Order along time if every point has one, else along psi.
  std::vector<std::size_t> order(data.points.size());
  std::iota(order.begin(), order.end(), 0);
  const bool timed = std::all_of(data.points.begin(), data.points.end(),
                                 [](const MeasuredPoint& p) { return p.time.has_value(); });
  const std::vector<double> psi = sliding_spin_ratio(data, radius_m);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return timed ? *data.points[a].time < *data.points[b].time : psi[a] < psi[b];
  });
  std::vector<ChannelDiagnostics> out;
  int measured = 0;
  for (int c = 0; c < kChannels; ++c) measured += data.count(c) > 0;
  const double alpha = 0.01 / std::max(1, 2 * measured);  // Bonferroni: channels x two tests
  for (int c = 0; c < kChannels; ++c) {
    if (data.count(c) == 0) continue;
    ChannelDiagnostics d;
    d.channel = kChannelColumns[c];
    std::vector<double> r;
    double ss = 0.0;
    for (std::size_t i : order) {
      const auto& y = data.points[i].force[c];
      if (!y) continue;
      const double e = *y - model[i].vector()(c);
      r.push_back(e);
      ss += e * e;
    }
    d.points = static_cast<int>(r.size());
    d.rms = std::sqrt(ss / static_cast<double>(std::max<std::size_t>(1, r.size())));
    d.noise_scale = scale[c];
    const RunsTest rt = runs_test(r);
    d.runs_p_value = rt.p_value;
    d.lag1 = lag1_autocorrelation(r);
    d.durbin_watson = durbin_watson(r);
    const double lag_p =
        2.0 * normal_cdf(-std::abs(d.lag1) * std::sqrt(static_cast<double>(r.size())));
    d.white = d.runs_p_value >= alpha && lag_p >= alpha;
    out.push_back(d);
  }
  return out;
}

}  // namespace contensou
