// Identification of the fractional law's parameters from measured diagrams, with Ceres
// (seed section 5, eqs. 14-15), reporting 95 % confidence intervals.
//
// The law (fractional_law.hpp) is fitted by weighted nonlinear least squares:
//   min sum_i sum_c rho( ((y_ic - yhat_c(x_i; theta)) / s_ic)^2 ),  theta = (F0, a, M0, m, kx),
// s_ic the noise scale of channel c (constant; proportional to |yhat| for relative noise; or
// a_c + b_c |yhat| for load-cell noise, NoiseModel::affine), estimated from the data (fit,
// per-channel scatter, refit) unless given. The covariance of
// theta is s^2 (J^T J)^-1 at the optimum (Ceres Covariance), s^2 = chi^2 / (n - p), and the 95 %
// intervals use Student's t with n - p degrees of freedom. A parameter the data cannot
// determine (its Jacobian column is zero or in the null space) is held at its start value
// and reported without an interval.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/measured_data.hpp"
#include "contensou/identification/residual_trace.hpp"

namespace contensou {

enum class NoiseModel {
  additive,  // s_ic = s_c
  relative,  // s_ic = s_c max(|yhat_ic|, 5 % of the channel's largest |y|)
  // s_ic = a_c + b_c |yhat_ic| (a load cell: a floor plus a share of the load), a_c = s_c and
  // b_c estimated together by maximum likelihood of the residuals (fit.cpp, affine_noise);
  // b_c = 0 is the additive model, a_c -> 0 nearly the relative one.
  affine,
};
const char* noise_model_name(NoiseModel model);  // "additive", "relative", "affine"

enum class RobustLoss { none, huber, cauchy };

// Names (as used by --fix and the JSON report) and units of the fitted parameters.
inline constexpr int kLawParameters = 5;
inline constexpr const char* kLawParameterNames[kLawParameters] = {"F0_N", "a", "M0_Nm", "m", "kx"};
inline constexpr const char* kLawParameterUnits[kLawParameters] = {"N", "1", "N m", "1", "1"};

struct IdentificationOptions {
  double radius_m = 0.0;                   // patch radius R [m] (required)
  std::optional<double> normal_load_n;     // N [N]: f = F0 / N is reported when known
  std::optional<PressureProfile> profile;  // shape constants c, a_k, Mk/M0 and the start a, m
  std::map<std::string, double> fixed;     // parameter name -> value held fixed
  NoiseModel noise_model = NoiseModel::additive;
  std::optional<std::array<double, kChannels>> noise_scale;  // given s_c (else estimated)
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 2.0;             // robust loss threshold, in noise scales
  int noise_iterations = 6;            // fit / scatter / refit rounds when s_c is estimated
  double regularization_speed = 1e-6;  // eps of the law [m/s]
  int failing_point = -1;              // testing only: see NoiseSettings::failing_point
  // Polled between the solver's iterations and the closed loop's stages (and by the exact laws'
  // builds): the fit or the loop throws Interrupted once it returns true (error.hpp).
  StopRequest stop{};
};

struct ParameterEstimate {
  std::string name;
  std::string unit;
  double value = 0.0;
  bool fixed = false;
  bool determined = true;  // false: not determined by the data (no interval)
  bool derived = false;    // computed from the profile, not estimated
  double std_error = std::numeric_limits<double>::quiet_NaN();
  std::optional<std::array<double, 2>> ci95;
  // What a parameter of a friction_dependence slot follows, and the dependence in the variable's
  // units ("f (1 + b1 z), z = T [degC] over 293.15 to 313.15 K: (1/f) df/dX = -0.0042 1/K");
  // "" for the others.
  std::string note;
};

// Residual diagnostics of one channel, points ordered along psi = |v| / |omega R| (or time).
struct ChannelDiagnostics {
  std::string channel;
  int points = 0;
  double rms = 0.0;          // unweighted [N or N m]
  double noise_scale = 0.0;  // s_c (a_c of affine noise)
  double noise_slope = 0.0;  // b_c of affine noise (0 otherwise)
  double runs_p_value = 1.0;
  double lag1 = 0.0;
  double durbin_watson = 2.0;
  bool white = true;
  // The residual's scatter between neighbouring rows (outliers.hpp, neighbour_scatter): the
  // noise as the data show it, whatever the model misses (0: too few rows to tell).
  double neighbour_scale = 0.0;
};

// The noise scales of a fit: its model and the per-channel constants.
struct NoiseScales {
  NoiseModel model = NoiseModel::additive;
  std::array<double, kChannels> scale{};  // s_c (a_c of affine noise)
  std::array<double, kChannels> slope{};  // b_c of affine noise
};

struct FitReport {
  std::vector<ParameterEstimate> parameters;   // F0_N, a, M0_Nm, m, kx, then f if N is known
  std::vector<std::string> correlation_names;  // free, determined parameters
  Eigen::MatrixXd correlation;
  std::vector<ChannelDiagnostics> channels;  // measured channels only
  FractionalLaw<double> law;                 // the fitted law (base model)
  // At each data point (all points of the data, also those a subset fit did not use):
  std::vector<Resultants<double>> prediction;  // the model
  std::vector<double> psi;                     // psi = |v| / (|omega| R) (sliding_spin_ratio)
  // y - yhat per channel (Fx, Fy, Mz; nullopt where the channel was not measured).
  std::vector<std::array<std::optional<double>, kChannels>> residual;
  NoiseModel noise_model = NoiseModel::additive;
  std::array<double, kChannels> noise_scale{};  // s_c (a_c of affine noise)
  std::array<double, kChannels> noise_slope{};  // b_c of affine noise (0 otherwise)
  double m2ll = 0.0;  // -2 log likelihood (Gaussian, with the noise scales)
  int residuals = 0;
  int free_parameters = 0;
  int degrees_of_freedom = 0;
  double chi2 = 0.0;  // weighted sum of squares
  double aic = 0.0;
  double bic = 0.0;
  // Dimensionless error: rms over channels of (channel rms / channel's largest |y|).
  double error = 0.0;
  bool residual_white = true;
  bool converged = false;
  std::string solver_summary;
  // What the residual follows (residual_trace.hpp); filled by identify() and the closed loop
  // for the fits they report (empty otherwise).
  ResidualTrace trace;
  // Every channel's rms within 1.5 times its scatter between neighbouring rows: the misfit is no
  // larger than the noise the data show.
  bool within_noise() const;

  const ParameterEstimate* parameter(const std::string& name) const;
  NoiseScales noise_scales() const { return {noise_model, noise_scale, noise_slope}; }
};

// Fits the fractional law to the data. Throws InvalidArgument for a non-positive radius or
// load, an unknown --fix name, and for fewer measured values than free parameters; Interrupted
// when options.stop asks.
FitReport fit_fractional_law(const MeasuredData& data, const IdentificationOptions& options);

// How a fit treats the noise (shared by the base fit and the closed loop).
struct NoiseSettings {
  NoiseModel model = NoiseModel::additive;
  std::optional<std::array<double, kChannels>> given;  // fixed scales (else estimated)
  // Where the estimated scales start (a fit of a sample of the same rows, say), when its model
  // is this one; else 5 % of each channel's peak. The rounds then settle sooner.
  std::optional<NoiseScales> start;
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 2.0;
  int iterations = 6;
  int solver_iterations = 200;  // Ceres' iterations per round (the loop's retry test lowers it)
  // Testing only: the residual of this point (index into the data) fails to evaluate, so that
  // the failed-solve path (an error naming the fit, no report) can be exercised. -1: none.
  int failing_point = -1;
  // Polled after every solver iteration and between the rounds: Interrupted once it returns
  // true (IdentificationOptions::stop).
  StopRequest stop{};
};

// Fits a general model (effect_model.hpp): its free parameters, from spec.value as start.
// `use` selects the points (empty: all). Used by fit_fractional_law and the closed loop.
// Throws InvalidArgument for a start or fixed value outside the model's domain, and
// std::runtime_error naming the fit if the solve fails or its Jacobian is not finite (no
// covariance or report is computed from a failed solve).
FitReport fit_model(const MeasuredData& data, const ModelSpec& spec, const NoiseSettings& noise,
                    std::array<double, kModelParameters>* estimate = nullptr,
                    const std::vector<char>& use = {});

// Measured values a fit of `spec` needs at least: free parameters + estimated noise parameters
// (one per channel, two for affine noise) + 1 (one degree of freedom left for the intervals).
// fit_model refuses fewer.
int measured_values_needed(const MeasuredData& data, const ModelSpec& spec,
                           const NoiseSettings& noise);

// The noise scales of a fit (FitReport::noise_scales()).
NoiseScales noise_scales_of(const FitReport& fit);

// Weighted residuals r and their Jacobian J with respect to all kModelParameters parameters
// at theta (weights 1/s_ic, NoiseModel, with yhat the model at theta).
void weighted_jacobian(const MeasuredData& data, const ModelSpec& spec,
                       const std::array<double, kModelParameters>& theta, const NoiseScales& noise,
                       Eigen::VectorXd* r, Eigen::MatrixXd* J, const std::vector<char>& use = {},
                       std::vector<int>* row_point = nullptr);

// The spec of the base fit for the options (law, start values, fixed parameters).
ModelSpec base_spec_for(const MeasuredData& data, const IdentificationOptions& options);
NoiseSettings noise_settings_for(const IdentificationOptions& options);

// Predictions of a law at the data's kinematics.
std::vector<Resultants<double>> predict(const FractionalLaw<double>& law, const MeasuredData& data);

// psi = |v| / (|omega| R) of each point (infinity for pure sliding). A fit carries it for its
// data (FitReport::psi): a report reads it there.
std::vector<double> sliding_spin_ratio(const MeasuredData& data, double radius_m);

// Residual diagnostics of each measured channel for given predictions.
std::vector<ChannelDiagnostics> residual_diagnostics(const MeasuredData& data,
                                                     const std::vector<Resultants<double>>& model,
                                                     double radius_m,
                                                     const std::array<double, kChannels>& scale);

}  // namespace contensou
