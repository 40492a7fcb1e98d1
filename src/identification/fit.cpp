#include "contensou/identification/fit.hpp"

#include <algorithm>
#include <cmath>

#include "contensou/friction/error.hpp"
#include "contensou/identification/effect_model.hpp"
#include "fit_problem.hpp"
#include "shared_laws.hpp"

namespace contensou {

namespace {
// Why a and m have the bounds they have, for an error on a fixed value.
std::string shape_bound_reason(int i) {
  if (i == kA) return " (a = (2 A^1 / A^0)^2 <= 4 for any non-negative pressure)";
  if (i == kMShape) return " (m = (2 A^2 / A^3)^2 >= 4 for any non-negative pressure)";
  return "";
}
}  // namespace
using namespace detail;  // NOLINT: this file implements part of fit_problem.hpp

namespace {

constexpr int K = kModelParameters;

// The given profile's shape on the patch (only the shape matters: a unit load and unit
// friction, no shift).
ContactPatch profile_patch(const IdentificationOptions& o) {
  PressureProfile shape = *o.profile;
  shape.kx = shape.ky = 0.0;
  return ContactPatch::from_normal_load(o.radius_m, 1.0, shape, 1.0);
}

// 1e-6 of the profile is far below any measurement noise and keeps a tabulated profile's
// series short (its PCHIP is only C1).
ExactModel<double> profile_exact_model(const ContactPatch& patch) {
  return make_exact_model(patch, 1e-6);
}

}  // namespace

void detail::LawSharing::share(IdentificationOptions& o) {
  require_positive("radius", o.radius_m);
  auto shared = std::make_shared<SharedLaws>();
  if (o.profile) shared->profile_model = profile_exact_model(profile_patch(o));
  shared->laws = std::make_shared<ExactLawCache>(o.radius_m, shared->profile_model,
                                                 ModelSpec{}.exact_tolerance);
  o.shared_laws_ = std::move(shared);
}

ModelSpec base_spec_for(const MeasuredData& data, const IdentificationOptions& o) {
  require_positive("radius", o.radius_m);
  if (o.normal_load_n) require_positive("normal load", *o.normal_load_n);
  ModelSpec s = base_model_spec(o.radius_m, o.normal_load_n);
  s.regularization_speed = o.regularization_speed;
  s.admissible_shape = o.admissible_shape;
  s.joint_admissibility = o.joint_admissibility && o.admissible_shape;
  // Rows with their own load (an Fz column): each at rho = N_i / N_ref, N_ref the load given (or
  // the rows' mean), at which F0 and M0 are reported.
  if (const std::optional<LoadFromData> rows = normal_load_from_data(data)) {
    s.reference_load_n = o.normal_load_n.value_or(rows->mean_n);
    s.normal_load_n = s.reference_load_n;
  }
  const detail::SharedLaws* shared = detail::LawSharing::of(o);
  if (shared) s.exact_laws = shared->laws;
  if (o.profile) {
    const ContactPatch patch = profile_patch(o);
    const FractionalLaw<double> law = fractional_law_from_patch(patch);
    s.c = law.c;
    s.a_k = law.a_k;
    s.mk_ratio = law.Mk / law.M0;
    s.value[kA] = law.a;
    s.value[kMShape] = law.m;
    s.profile_a = law.a;
    s.profile_m = law.m;
    s.profile_m0_ratio = law.M0 / (law.F0 * o.radius_m);
    s.profile = patch.profile;
    if (shared) {
      s.profile_model = shared->profile_model;
    } else {
      s.profile_model = profile_exact_model(patch);
      s.exact_laws =
          std::make_shared<ExactLawCache>(o.radius_m, s.profile_model, s.exact_tolerance);
    }
  }
  double f0 = 0.0, m0 = 0.0;
  for (const MeasuredPoint& p : data.points) {
    f0 = std::max(f0, std::hypot(p.force[0].value_or(0.0), p.force[1].value_or(0.0)));
    m0 = std::max(m0, std::abs(p.force[2].value_or(0.0)));
  }
  s.value[kF0] = f0 > 0.0 ? f0 : 1.0;
  s.value[kM0] = m0 > 0.0 ? m0 : 0.3 * s.value[kF0] * o.radius_m;
  for (const auto& [name, value] : o.fixed) {
    const int i = parameter_index_by_name(name);
    if (i < 0 || i > kKx)
      throw InvalidArgument("fix", name, "unknown parameter (use F0_N, a, M0_Nm, m or kx)");
    require_finite(name.c_str(), value);
    const ParameterBounds b = parameter_bounds(s, i);
    if (!(value >= b.lower && value <= b.upper))
      throw InvalidArgument("fix " + name, format_value(value),
                            "must lie in [" + format_value(b.lower) + ", " + format_value(b.upper) +
                                "], the fit's bounds for it" + shape_bound_reason(i));
    s.free[i] = false;
    s.value[i] = value;
  }
  return s;
}

int measured_values_needed(const MeasuredData& data, const ModelSpec& spec,
                           const NoiseSettings& noise) {
  int needed = static_cast<int>(std::count(spec.free.begin(), spec.free.end(), true)) + 1;
  for (int c = 0; c < kChannels; ++c) needed += data.count(c) > 0 ? noise_parameters(noise) : 0;
  return needed;
}

FitReport fit_model(const MeasuredData& data, const ModelSpec& spec, const NoiseSettings& noise,
                    std::array<double, K>* estimate, const std::vector<char>& use) {
  const FitSetup setup = prepare_fit(data, spec, noise, use);
  Solution sol = solve(setup);
  FitReport report;
  report.converged = sol.summary.IsSolutionUsable();
  report.solver_summary = sol.summary.BriefReport();
  const Eigen::MatrixXd J = jacobian_at_optimum(*sol.problem, spec, &report);
  const std::array<bool, K> undetermined = undetermined_parameters(J, setup.active);
  std::vector<int> est;  // free and determined
  for (int i : setup.active)
    if (!undetermined[i]) est.push_back(i);
  report.free_parameters = static_cast<int>(est.size());
  int estimated_scales = 0;  // each estimated noise parameter uses up a degree of freedom too
  for (int c = 0; c < kChannels; ++c)
    estimated_scales += setup.counts[c] > 0 ? noise_parameters(noise) : 0;
  report.degrees_of_freedom = report.residuals - report.free_parameters - estimated_scales;
  const std::optional<Eigen::MatrixXd> cov = parameter_covariance(J, setup.active, est, report);
  report_parameters(spec, sol.theta, undetermined, est, cov, report);
  if (!spec.exact_only) report.law = fractional_law_of(spec, sol.theta.data());
  report_quality(setup, sol, report);
  auto model = std::make_shared<ModelSpec>(spec);
  model->value = sol.theta;
  report.model = std::move(model);
  if (estimate) *estimate = sol.theta;
  return report;
}

void weighted_jacobian(const MeasuredData& data, const ModelSpec& spec,
                       const std::array<double, K>& theta_in, const NoiseScales& noise,
                       Eigen::VectorXd* r, Eigen::MatrixXd* J, const std::vector<char>& use,
                       std::vector<int>* row_point) {
  std::array<double, K> theta = theta_in;
  const std::array<double, kChannels> peak = channel_magnitudes(data, spec.radius_m);
  std::array<double, kChannels> floor_rel{};
  for (int c = 0; c < kChannels; ++c) floor_rel[c] = 0.05 * peak[c];
  const std::vector<Resultants<double>> pred = evaluate_all(spec, theta.data(), data);
  // Columns for the parameters that are free or scored (non-null or listed as free); the
  // others get zero columns.
  std::vector<int> active;
  for (int i = 0; i < K; ++i)
    if (spec.free[i] || spec.value[i] != parameter_info(i).null_value || i <= kKx ||
        (i >= kKy && i <= kXMzFy) || i == kShapeBlend ||
        (i >= kSlipAngleOffset && i <= kFrictionScale) || i >= kCentreX)
      active.push_back(i);
  std::vector<double> packed(active.size());
  for (std::size_t j = 0; j < active.size(); ++j) packed[j] = theta[active[j]];
  ceres::Problem problem;
  const Weighting wt{noise, floor_rel, &pred, RobustLoss::none, 1.0, -1};
  add_points(problem, data, spec, active, theta, packed.data(), wt, use);
  if (row_point) {
    row_point->clear();
    for (std::size_t i = 0; i < data.points.size(); ++i) {
      if (!use.empty() && !use[i]) continue;
      for (int c = 0; c < kChannels; ++c)
        if (data.points[i].force[c]) row_point->push_back(static_cast<int>(i));
    }
  }
  ceres::CRSMatrix crs;
  std::vector<double> res;
  double cost = 0.0;
  problem.Evaluate(evaluate_options(), &cost, &res, nullptr, &crs);
  *r = Eigen::Map<Eigen::VectorXd>(res.data(), static_cast<Eigen::Index>(res.size()));
  *J = Eigen::MatrixXd::Zero(crs.num_rows, K);
  for (int row = 0; row < crs.num_rows; ++row)
    for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k)
      (*J)(row, active[crs.cols[k]]) = crs.values[k];
}

FitReport fit_fractional_law(const MeasuredData& data, const IdentificationOptions& o) {
  return fit_model(data, base_spec_for(data, o), noise_settings_for(o));
}

}  // namespace contensou
