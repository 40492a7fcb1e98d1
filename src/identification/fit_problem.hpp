// Internal: the pieces of a fit shared by fit.cpp, fit_problem.cpp (the Ceres problem and its
// solve), noise_estimation.cpp, fit_covariance.cpp and fit_report.cpp. Not installed.
#pragma once

#include <ceres/ceres.h>

#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "contensou/identification/fit.hpp"

namespace contensou::detail {

// Ceres' evaluation of a whole problem, on one thread (see fit_problem.cpp).
ceres::Problem::EvaluateOptions evaluate_options();

// The magnitude of each channel: its largest |y|, but at least 1e-3 of the data's force scale.
std::array<double, kChannels> channel_magnitudes(const MeasuredData& d, double radius);

// Noise parameters estimated per measured channel: 0 when given, 2 for affine noise, else 1.
int noise_parameters(const NoiseSettings& noise);

// The noise scale of one value of channel c with prediction (or datum) yh.
double value_scale(const NoiseScales& n, int c, double yh, double floor_rel);

// How add_points weights the residuals: the noise scales, the relative noise's floor per
// channel, the predictions the scales are taken at (empty: the data), the robust loss.
struct Weighting {
  NoiseScales noise;
  std::array<double, kChannels> floor_rel{};
  const std::vector<Resultants<double>>* prediction = nullptr;
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 1.0;
  int failing_point = -1;  // NoiseSettings::failing_point
};

// Adds one residual block per used row with measured values (weights 1 / s_ic); returns the
// number of residuals. The cost functions point into `active` and `theta_const`.
int add_points(ceres::Problem& problem, const MeasuredData& data, const ModelSpec& spec,
               const std::vector<int>& active,
               const std::array<double, kModelParameters>& theta_const, double* packed,
               const Weighting& wt, const std::vector<char>& use);

// The model at every row of d with parameters theta.
std::vector<Resultants<double>> evaluate_all(const ModelSpec& spec, const double* theta,
                                             const MeasuredData& d);

// The fit named by its model and free parameters, for the error of a failed solve.
std::string fit_name(const ModelSpec& s);

// What a fit works on: the used points, the measured values per channel, the active (free)
// parameters and the start values the inactive ones are held at. Ceres' cost functions point
// into it, so it outlives the problem.
struct FitSetup {
  FitSetup(const MeasuredData& d, const ModelSpec& sp, const NoiseSettings& ns,
           const std::vector<char>& u)
      : data(d), spec(sp), noise(ns), use(u) {}
  const MeasuredData& data;
  const ModelSpec& spec;
  const NoiseSettings& noise;
  const std::vector<char>& use;
  std::array<int, kChannels> counts{};  // measured values per channel
  int n = 0;                            // measured values in all
  int p_free = 0;
  std::array<double, kChannels> peak{};                // magnitude per channel (channel_magnitudes)
  std::array<double, kChannels> floor_rel{};           // 5 % of the peak: floor of relative noise
  std::vector<int> active;                             // free parameters, in index order
  std::array<double, kModelParameters> theta_const{};  // values of the others

  bool used(std::size_t i) const { return use.empty() || use[i]; }
};

// The fit's setup; throws InvalidArgument for data a fit cannot be made on (at rest, nothing
// free, too few values, forces outside [1e-6, 1e8] N, bad given noise scales).
FitSetup prepare_fit(const MeasuredData& data, const ModelSpec& spec, const NoiseSettings& noise,
                     const std::vector<char>& use);

// A solved problem: the estimate, the noise scales and the predictions at the optimum.
struct Solution {
  std::unique_ptr<ceres::Problem> problem;
  std::vector<double> packed;  // the active parameters (Ceres' parameter block)
  std::array<double, kModelParameters> theta{};
  std::array<double, kChannels> scale{};
  std::array<double, kChannels> slope{};  // b_c of affine noise
  std::vector<Resultants<double>> prediction;
  ceres::Solver::Summary summary;
  // The admissibility penalty of the law's shape (add_shape_penalty; nullptr: none), removed
  // before the covariance.
  ceres::ResidualBlockId shape_penalty = nullptr;
};

// Builds the problem, solves, estimates the noise scales; repeated (warm-started) until the
// scales settle. Throws std::runtime_error naming the fit when a solve fails.
Solution solve(const FitSetup& s);

// Start noise scales: the given ones, or 5 % (of the channel's peak for additive and affine).
std::array<double, kChannels> initial_noise_scales(const FitSetup& s);

// Noise scales from the residual scatter of each channel (noise_estimation.cpp); returns the
// largest relative change.
double estimate_noise_scales(const FitSetup& s, const std::vector<Resultants<double>>& prediction,
                             std::array<double, kChannels>& scale,
                             std::array<double, kChannels>& slope);

// The weighted Jacobian at the optimum; sets report->residuals and chi2. Throws if not finite.
Eigen::MatrixXd jacobian_at_optimum(ceres::Problem& problem, const ModelSpec& spec,
                                    FitReport* report);

// Parameters the data cannot determine (zero or near-dependent columns of J).
std::array<bool, kModelParameters> undetermined_parameters(const Eigen::MatrixXd& J,
                                                           const std::vector<int>& active);

// Covariance s^2 (J_e^T J_e)^-1 of the determined parameters `est`, K x K, or nothing.
std::optional<Eigen::MatrixXd> parameter_covariance(const Eigen::MatrixXd& J,
                                                    const std::vector<int>& active,
                                                    const std::vector<int>& est,
                                                    const FitReport& report);

// The report's parameters: values, standard errors, Student-t 95 % intervals, correlations.
void report_parameters(const ModelSpec& spec, const std::array<double, kModelParameters>& theta,
                       const std::array<bool, kModelParameters>& undetermined,
                       const std::vector<int>& est, const std::optional<Eigen::MatrixXd>& cov,
                       FitReport& report);

// The report's diagnostics on the used rows: whiteness, error, -2 log L, AIC, BIC.
void report_quality(const FitSetup& s, const Solution& sol, FitReport& report);

}  // namespace contensou::detail
