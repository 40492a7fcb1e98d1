// The fit's Jacobian at the optimum, the parameters the data cannot determine and the
// covariance of the others. See fit_problem.hpp.
#include "fit_problem.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contensou {
using namespace detail;  // NOLINT: this file implements part of fit_problem.hpp

namespace {

constexpr int K = kModelParameters;

}  // namespace

namespace detail {

// The weighted Jacobian at the optimum (free parameters only); sets the report's residual
// count and chi^2. Throws, naming the fit, if residuals or Jacobian are not finite: no
// covariance is ever computed from them.
Eigen::MatrixXd jacobian_at_optimum(ceres::Problem& problem, const ModelSpec& spec,
                                    FitReport* report) {
  ceres::CRSMatrix crs;
  std::vector<double> residuals;
  double cost = 0.0;
  const bool evaluated = problem.Evaluate(evaluate_options(), &cost, &residuals, nullptr, &crs);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[r]; k < crs.rows[r + 1]; ++k) J(r, crs.cols[k]) = crs.values[k];
  const bool finite =
      std::all_of(residuals.begin(), residuals.end(), [](double r) { return std::isfinite(r); });
  if (!evaluated || !finite || !J.allFinite())
    throw std::runtime_error("fit of the " + fit_name(spec) +
                             " failed: non-finite residuals or Jacobian at the optimum");
  report->residuals = static_cast<int>(residuals.size());
  report->chi2 = 0.0;
  for (double r : residuals) report->chi2 += r * r;
  return J;
}

// Parameters the data cannot determine: zero columns of J, or a large share in a singular
// vector of the column-normalised J (singular value below 1e-7 of the largest).
std::array<bool, K> undetermined_parameters(const Eigen::MatrixXd& J,
                                            const std::vector<int>& active) {
  std::array<bool, K> undetermined{};
  if (J.cols() == 0) return undetermined;
  const Eigen::VectorXd norms = J.colwise().norm();
  Eigen::MatrixXd Jn = J;
  for (int j = 0; j < J.cols(); ++j)
    if (norms(j) > 0.0) Jn.col(j) /= norms(j);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  for (int j = 0; j < J.cols(); ++j)
    if (!(norms(j) > 1e-12 * norms.maxCoeff())) undetermined[active[j]] = true;
  for (int sidx = 0; sidx < sv.size(); ++sidx) {
    if (sv(sidx) > 1e-7 * sv(0)) continue;
    for (int j = 0; j < J.cols(); ++j)
      if (std::abs(svd.matrixV()(j, sidx)) > 0.3) undetermined[active[j]] = true;
  }
  return undetermined;
}

// Covariance of the determined parameters, s^2 (J_e^T J_e)^-1 with s^2 = chi^2 / (n - p) and
// J_e the Jacobian's columns of those parameters, from the SVD of the column-normalised J_e:
// (J_e^T J_e)^-1 = D^-1 V S^-2 V^T D^-1, D = diag(column norms). Normalising first keeps the
// result accurate when the columns differ by many orders of magnitude (a channel measured as
// zero, say). A K x K matrix, or nothing when it cannot be had.
std::optional<Eigen::MatrixXd> parameter_covariance(const Eigen::MatrixXd& J,
                                                    const std::vector<int>& active,
                                                    const std::vector<int>& est,
                                                    const FitReport& report) {
  if (est.empty() || report.degrees_of_freedom <= 0 || !J.allFinite()) return std::nullopt;
  const auto p = static_cast<Eigen::Index>(est.size());
  Eigen::MatrixXd Je(J.rows(), p);
  for (Eigen::Index a = 0; a < p; ++a) {
    const auto col = std::find(active.begin(), active.end(), est[static_cast<std::size_t>(a)]);
    Je.col(a) = J.col(static_cast<Eigen::Index>(col - active.begin()));
  }
  const Eigen::VectorXd norms = Je.colwise().norm();
  if (!(norms.minCoeff() > 0.0)) return std::nullopt;
  const Eigen::MatrixXd Jn = Je * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  if (!(sv(p - 1) > 1e-12 * sv(0))) return std::nullopt;
  const Eigen::MatrixXd Vs = svd.matrixV() * sv.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd inv =
      norms.cwiseInverse().asDiagonal() * (Vs * Vs.transpose()) * norms.cwiseInverse().asDiagonal();
  const double s2 = report.chi2 / (report.residuals - report.free_parameters);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(K, K);
  for (Eigen::Index a = 0; a < p; ++a)
    for (Eigen::Index b = 0; b < p; ++b)
      cov(est[static_cast<std::size_t>(a)], est[static_cast<std::size_t>(b)]) = s2 * inv(a, b);
  return cov;
}

}  // namespace detail

}  // namespace contensou
