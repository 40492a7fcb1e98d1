#include "contensou/identification.hpp"

#include <ceres/ceres.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>

#include "contensou/error.hpp"
#include "contensou/statistics.hpp"

namespace contensou {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Constants of the law that the diagrams do not identify: shapes of the cross-shift terms.
struct ShapeConstants {
  double c = 4.0, a_k = 1.0, mk_ratio = 0.375;  // uniform pressure: (4 A2/A5)^(2/3), 1, A3/(2A2)
  double a = 1.0, m = 64.0 / 9.0;               // start values
};

ShapeConstants shape_constants(const IdentificationOptions& o) {
  ShapeConstants s;
  if (!o.profile) return s;
  ContactPatch patch;
  patch.radius_m = o.radius_m;
  patch.profile = *o.profile;
  patch.profile.kx = patch.profile.ky = 0.0;
  const FractionalLaw<double> law = fractional_law_from_patch(patch);
  s.c = law.c;
  s.a_k = law.a_k;
  s.mk_ratio = law.Mk / law.M0;
  s.a = law.a;
  s.m = law.m;
  return s;
}

template <class T>
FractionalLaw<T> law_from(const T* theta, const ShapeConstants& s, double R, double eps) {
  FractionalLaw<T> law;
  law.F0 = theta[0];
  law.a = theta[1];
  law.M0 = theta[2];
  law.m = theta[3];
  law.kx = theta[4];
  law.ky = T(0.0);
  law.kappa = T(1.0);
  law.c = T(s.c);
  law.a_k = T(s.a_k);
  law.Mk = theta[2] * s.mk_ratio;
  law.radius = R;
  law.regularization_speed = eps;
  return law;
}

// Weighted residuals of one point: w_c (y_c - yhat_c) for each measured channel c.
struct PointResidual {
  Kinematics<double> k;
  std::array<double, kChannels> y{};
  std::array<double, kChannels> w{};  // 0 = not measured
  std::array<int, kChannels> slot{};  // residual index of each measured channel
  ShapeConstants shape;
  double R, eps;

  template <class T>
  bool operator()(const T* theta, T* r) const {
    const FractionalLaw<T> law = law_from(theta, shape, R, eps);
    const Resultants<T> f = fractional_resultants(law, Kinematics<T>{T(k.vx), T(k.vy), T(k.omega)});
    const T model[kChannels] = {f.Fx, f.Fy, f.Mz};
    for (int c = 0; c < kChannels; ++c)
      if (w[c] != 0.0) r[slot[c]] = w[c] * (y[c] - model[c]);
    return true;
  }
};

double channel_peak(const MeasuredData& d, int c) {
  double m = 0.0;
  for (const MeasuredPoint& p : d.points)
    if (p.force[c]) m = std::max(m, std::abs(*p.force[c]));
  return m;
}

int parameter_index(const std::string& name) {
  for (int i = 0; i < kLawParameters; ++i)
    if (name == kLawParameterNames[i]) return i;
  return -1;
}

}  // namespace

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

std::vector<double> sliding_spin_ratio(const MeasuredData& data, double radius_m) {
  std::vector<double> psi;
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

FitReport fit_fractional_law(const MeasuredData& data, const IdentificationOptions& o) {
  detail::require_positive("radius", o.radius_m);
  if (o.normal_load_n) detail::require_positive("normal load", *o.normal_load_n);
  std::array<bool, kLawParameters> is_fixed{};
  double theta[kLawParameters];
  for (const auto& [name, value] : o.fixed) {
    const int i = parameter_index(name);
    if (i < 0)
      throw InvalidArgument("fix", name, "unknown parameter (use F0_N, a, M0_Nm, m or kx)");
    detail::require_finite(name.c_str(), value);
    is_fixed[i] = true;
    theta[i] = value;
  }
  const ShapeConstants shape = shape_constants(o);
  std::array<int, kChannels> counts{};
  int n = 0;
  for (int c = 0; c < kChannels; ++c) n += counts[c] = data.count(c);
  const int p_free =
      kLawParameters - static_cast<int>(std::count(is_fixed.begin(), is_fixed.end(), true));
  if (n <= p_free)
    throw InvalidArgument(
        "data", std::to_string(n) + " measured values",
        "need more measured values than free parameters (" + std::to_string(p_free) + ")");
  std::array<double, kChannels> peak{};
  for (int c = 0; c < kChannels; ++c) peak[c] = channel_peak(data, c);

  // Start values.
  if (!is_fixed[0]) {
    double f0 = 0.0;
    for (const MeasuredPoint& p : data.points)
      f0 = std::max(f0, std::hypot(p.force[0].value_or(0.0), p.force[1].value_or(0.0)));
    theta[0] = f0 > 0.0 ? f0 : 1.0;
  }
  if (!is_fixed[1]) theta[1] = shape.a;
  if (!is_fixed[2]) theta[2] = peak[2] > 0.0 ? peak[2] : 0.3 * theta[0] * o.radius_m;
  if (!is_fixed[3]) theta[3] = shape.m;
  if (!is_fixed[4]) theta[4] = 0.0;

  // Noise scales: given, or estimated (start at 5 % of each channel's peak).
  std::array<double, kChannels> scale{};
  for (int c = 0; c < kChannels; ++c)
    scale[c] =
        o.noise_scale
            ? (*o.noise_scale)[c]
            : (o.noise_model == NoiseModel::relative ? 0.05 : 0.05 * std::max(peak[c], 1e-12));
  if (o.noise_scale)
    for (int c = 0; c < kChannels; ++c)
      if (counts[c] > 0) detail::require_positive("noise scale", scale[c]);
  std::array<double, kChannels> floor_rel{};
  for (int c = 0; c < kChannels; ++c) floor_rel[c] = 0.05 * std::max(peak[c], 1e-12);

  std::vector<Resultants<double>> prev;
  FitReport report;
  ceres::Solver::Summary summary;
  const int rounds =
      o.noise_scale && o.noise_model == NoiseModel::additive ? 1 : std::max(1, o.noise_iterations);
  std::unique_ptr<ceres::Problem> problem;
  for (int round = 0; round < rounds; ++round) {
    problem = std::make_unique<ceres::Problem>();
    problem->AddParameterBlock(theta, kLawParameters);
    for (std::size_t i = 0; i < data.points.size(); ++i) {
      const MeasuredPoint& pt = data.points[i];
      auto* f =
          new PointResidual{pt.kinematics, {}, {}, {}, shape, o.radius_m, o.regularization_speed};
      int m = 0;
      for (int c = 0; c < kChannels; ++c) {
        if (!pt.force[c]) continue;
        f->y[c] = *pt.force[c];
        double s = scale[c];
        if (o.noise_model == NoiseModel::relative) {
          const double yh = prev.empty() ? *pt.force[c] : prev[i].vector()(c);
          s *= std::max(std::abs(yh), floor_rel[c]);
        }
        f->w[c] = 1.0 / s;
        f->slot[c] = m++;
      }
      if (m == 0) {
        delete f;
        continue;
      }
      ceres::LossFunction* loss = nullptr;
      if (o.loss == RobustLoss::huber) loss = new ceres::HuberLoss(o.loss_scale);
      if (o.loss == RobustLoss::cauchy) loss = new ceres::CauchyLoss(o.loss_scale);
      problem->AddResidualBlock(
          new ceres::AutoDiffCostFunction<PointResidual, ceres::DYNAMIC, kLawParameters>(f, m),
          loss, theta);
    }
    for (int i : {0, 1, 2, 3}) problem->SetParameterLowerBound(theta, i, 1e-12);
    std::vector<int> constant;
    for (int i = 0; i < kLawParameters; ++i)
      if (is_fixed[i]) constant.push_back(i);
    if (!constant.empty())
      problem->SetManifold(theta, new ceres::SubsetManifold(kLawParameters, constant));
    ceres::Solver::Options opt;
    opt.linear_solver_type = ceres::DENSE_QR;
    opt.max_num_iterations = 200;
    opt.function_tolerance = 1e-14;
    opt.gradient_tolerance = 1e-14;
    opt.parameter_tolerance = 1e-12;
    opt.logging_type = ceres::SILENT;
    ceres::Solve(opt, problem.get(), &summary);

    report.law = law_from(theta, shape, o.radius_m, o.regularization_speed);
    prev = predict(report.law, data);
    if (o.noise_scale && o.noise_model == NoiseModel::additive) break;
    // Re-estimate each channel's scatter with its share of the degrees of freedom.
    double change = 0.0;
    for (int c = 0; c < kChannels; ++c) {
      if (counts[c] == 0 || o.noise_scale) continue;
      double ss = 0.0;
      for (std::size_t i = 0; i < data.points.size(); ++i) {
        const auto& y = data.points[i].force[c];
        if (!y) continue;
        double e = *y - prev[i].vector()(c);
        if (o.noise_model == NoiseModel::relative)
          e /= std::max(std::abs(prev[i].vector()(c)), floor_rel[c]);
        ss += e * e;
      }
      const double dof_c = counts[c] * (1.0 - double(p_free) / n);
      const double s_new = std::sqrt(ss / std::max(dof_c, 1.0));
      if (s_new > 0.0) {
        change = std::max(change, std::abs(s_new - scale[c]) / scale[c]);
        scale[c] = s_new;
      }
    }
    if (round > 0 && change < 1e-3) break;
  }
  report.converged = summary.IsSolutionUsable();
  report.solver_summary = summary.BriefReport();

  // Weighted Jacobian at the optimum (tangent space: free parameters only).
  ceres::CRSMatrix crs;
  std::vector<double> residuals;
  double cost = 0.0;
  problem->Evaluate(ceres::Problem::EvaluateOptions(), &cost, &residuals, nullptr, &crs);
  std::vector<int> free_index;
  for (int i = 0; i < kLawParameters; ++i)
    if (!is_fixed[i]) free_index.push_back(i);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[r]; k < crs.rows[r + 1]; ++k) J(r, crs.cols[k]) = crs.values[k];
  report.residuals = static_cast<int>(residuals.size());
  report.chi2 = 0.0;
  for (double r : residuals) report.chi2 += r * r;

  // Parameters the data cannot determine: zero columns or the null space of J.
  std::array<bool, kLawParameters> undetermined{};
  if (J.cols() > 0) {
    Eigen::VectorXd norms = J.colwise().norm();
    Eigen::MatrixXd Jn = J;
    for (int j = 0; j < J.cols(); ++j)
      if (norms(j) > 0.0) Jn.col(j) /= norms(j);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
    const Eigen::VectorXd sv = svd.singularValues();
    for (int j = 0; j < J.cols(); ++j)
      if (!(norms(j) > 1e-12 * norms.maxCoeff())) undetermined[free_index[j]] = true;
    for (int s = 0; s < sv.size(); ++s) {
      if (sv(s) > 1e-7 * sv(0)) continue;
      for (int j = 0; j < J.cols(); ++j)
        if (std::abs(svd.matrixV()(j, s)) > 0.3) undetermined[free_index[j]] = true;
    }
  }
  std::vector<int> est;  // free and determined
  for (int i : free_index)
    if (!undetermined[i]) est.push_back(i);
  report.free_parameters = static_cast<int>(est.size());
  // Each estimated noise scale uses up a degree of freedom too.
  int estimated_scales = 0;
  for (int c = 0; c < kChannels; ++c) estimated_scales += counts[c] > 0 && !o.noise_scale;
  report.degrees_of_freedom = report.residuals - report.free_parameters - estimated_scales;

  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(kLawParameters, kLawParameters);
  bool have_cov = false;
  if (!est.empty() && report.degrees_of_freedom > 0) {
    std::vector<int> constant;
    for (int i = 0; i < kLawParameters; ++i)
      if (std::find(est.begin(), est.end(), i) == est.end()) constant.push_back(i);
    if (!constant.empty())
      problem->SetManifold(theta, new ceres::SubsetManifold(kLawParameters, constant));
    ceres::Covariance::Options copt;
    copt.algorithm_type = ceres::DENSE_SVD;
    copt.null_space_rank = -1;
    ceres::Covariance covariance(copt);
    std::vector<std::pair<const double*, const double*>> blocks{{theta, theta}};
    if (covariance.Compute(blocks, problem.get())) {
      std::vector<double> c(est.size() * est.size());
      covariance.GetCovarianceBlockInTangentSpace(theta, theta, c.data());
      const double s2 = report.chi2 / (report.residuals - report.free_parameters);
      for (std::size_t a = 0; a < est.size(); ++a)
        for (std::size_t b = 0; b < est.size(); ++b)
          cov(est[a], est[b]) = s2 * c[a * est.size() + b];
      have_cov = true;
    }
  }
  const double tq =
      report.degrees_of_freedom > 0 ? student_t_quantile(0.975, report.degrees_of_freedom) : kNaN;
  for (int i = 0; i < kLawParameters; ++i) {
    ParameterEstimate e;
    e.name = kLawParameterNames[i];
    e.unit = kLawParameterUnits[i];
    e.value = theta[i];
    e.fixed = is_fixed[i];
    e.determined = !undetermined[i] && !is_fixed[i];
    if (e.determined && have_cov && cov(i, i) >= 0.0) {
      e.std_error = std::sqrt(cov(i, i));
      e.ci95 = std::array<double, 2>{e.value - tq * e.std_error, e.value + tq * e.std_error};
    } else if (!is_fixed[i]) {
      e.determined = false;
    }
    report.parameters.push_back(e);
  }
  if (o.normal_load_n) {
    const ParameterEstimate& F0 = report.parameters[0];
    ParameterEstimate f{"f",         "1",           F0.value / *o.normal_load_n,
                        F0.fixed,    F0.determined, F0.std_error / *o.normal_load_n,
                        std::nullopt};
    if (F0.ci95)
      f.ci95 =
          std::array<double, 2>{(*F0.ci95)[0] / *o.normal_load_n, (*F0.ci95)[1] / *o.normal_load_n};
    report.parameters.push_back(f);
  }
  report.correlation = Eigen::MatrixXd::Identity(est.size(), est.size());
  for (std::size_t a = 0; a < est.size(); ++a) {
    report.correlation_names.push_back(kLawParameterNames[est[a]]);
    for (std::size_t b = 0; b < est.size(); ++b)
      if (have_cov && cov(est[a], est[a]) > 0 && cov(est[b], est[b]) > 0)
        report.correlation(a, b) =
            cov(est[a], est[b]) / std::sqrt(cov(est[a], est[a]) * cov(est[b], est[b]));
  }

  // Quality: per-channel diagnostics, AIC/BIC of the Gaussian likelihood with the noise scales.
  report.channels = residual_diagnostics(data, prev, o.radius_m, scale);
  report.residual_white = std::all_of(report.channels.begin(), report.channels.end(),
                                      [](const ChannelDiagnostics& d) { return d.white; });
  double log_det = 0.0, err2 = 0.0;
  for (std::size_t i = 0; i < data.points.size(); ++i)
    for (int c = 0; c < kChannels; ++c) {
      if (!data.points[i].force[c]) continue;
      double s = scale[c];
      if (o.noise_model == NoiseModel::relative)
        s *= std::max(std::abs(prev[i].vector()(c)), floor_rel[c]);
      log_det += std::log(2.0 * std::numbers::pi * s * s);
    }
  const int measured = static_cast<int>(report.channels.size());
  for (int c = 0, k = 0; c < kChannels; ++c) {
    if (counts[c] == 0) continue;
    const double rel = report.channels[k++].rms / std::max(peak[c], 1e-300);
    err2 += rel * rel;
  }
  report.error = std::sqrt(err2 / std::max(measured, 1));
  const int k_params = report.free_parameters + (o.noise_scale ? 0 : measured);
  const double m2ll = log_det + report.chi2;
  report.aic = m2ll + 2.0 * k_params;
  report.bic = m2ll + k_params * std::log(static_cast<double>(report.residuals));
  return report;
}

}  // namespace contensou
