/// \file
/// Identification of the fractional law's parameters from measured diagrams, with Ceres
/// (seed section 5, equations 14 and 15), reporting 95 % confidence intervals.
///
/// The law (fractional_law.hpp) is fitted by weighted nonlinear least squares:
/// ~~~
///   min sum_i sum_c rho( ((y_ic - yhat_c(x_i; theta)) / s_ic)^2 ),  theta = (F0, a, M0, m, kx),
/// ~~~
/// s_ic the noise scale of channel c (constant; proportional to |yhat| for relative noise; or
/// a_c + b_c |yhat| for load-cell noise, NoiseModel::affine), estimated from the data (fit,
/// per-channel scatter, refit) unless given. The covariance of the determined parameters is
/// s^2 (J^T J)^-1 at the optimum, s^2 = chi^2 / (n - p), computed from the SVD of the
/// column-normalised Jacobian, and the 95 % intervals use Student's t with n - p degrees of
/// freedom less one per estimated noise parameter. A parameter the data cannot determine (its
/// Jacobian column is zero or in the near null space) is reported at the value the solve left
/// it at, without a standard error or an interval.
#pragma once

#include <Eigen/Core>
#include <array>
#include <limits>
#include <map>
#include <memory>
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

namespace testing {
struct Seams;  // (Internal) src/identification/test_seams.hpp, not installed
}  // namespace testing

namespace detail {
struct SharedLaws;  // (Internal) src/identification/shared_laws.hpp, not installed
struct LawSharing;  // (Internal) the only way to set or read IdentificationOptions' shared laws
/// (Internal) What tests set, through testing::Seams only, to reach failure paths; -1: off.
struct TestSeams {
  int failing_point = -1;         ///< this point's residual fails to evaluate (a failed solve)
  int first_fit_iterations = -1;  ///< Ceres' iterations in a loop candidate's first fit
};
}  // namespace detail

/// How the noise scale s_ic of value i of channel c follows the value.
enum class NoiseModel {
  additive,  ///< s_ic = s_c
  relative,  ///< s_ic = s_c max(|yhat_ic|, 5 % of the channel's largest |y|)
  /// s_ic = a_c + b_c |yhat_ic| (a load cell: a floor plus a share of the load), a_c = s_c and
  /// b_c estimated together by maximum likelihood of the residuals (affine_noise in
  /// noise_estimation.cpp); b_c = 0 is the additive model, a_c near 0 nearly the relative one.
  affine,
};
/// The name of a noise model: "additive", "relative" or "affine".
const char* noise_model_name(NoiseModel model);

/// The robust loss of the fit (Ceres' HuberLoss or CauchyLoss at loss_scale), or none.
enum class RobustLoss {
  none,   ///< plain least squares
  huber,  ///< Huber loss
  cauchy  ///< Cauchy loss
};

/// The number of the fractional law's fitted parameters (F0, a, M0, m, kx).
inline constexpr int kLawParameters = 5;
/// Names (as used by `--fix` and the JSON report) of the fitted parameters.
inline constexpr const char* kLawParameterNames[kLawParameters] = {"F0_N", "a", "M0_Nm", "m", "kx"};
/// Units of the fitted parameters, in the order of kLawParameterNames.
inline constexpr const char* kLawParameterUnits[kLawParameters] = {"N", "1", "N m", "1", "1"};

/// What fit_fractional_law (and the closed loop's base fit) is asked for.
struct IdentificationOptions {
  double radius_m = 0.0;                ///< patch radius R [m] (required: positive)
  std::optional<double> normal_load_n;  ///< N [N]: f = F0 / N is reported when known
  /// Shape constants c, a_k, Mk/M0 and the start a, m (its shift is ignored); also the profile
  /// of the exact integrals. Unset: the law's defaults and the parametric profile.
  std::optional<PressureProfile> profile;
  /// Parameter name (F0_N, a, M0_Nm, m or kx) to the value it is held at, within its bounds.
  std::map<std::string, double> fixed;
  NoiseModel noise_model = NoiseModel::additive;  ///< how the noise scale follows the value
  /// Given s_c [N, N, N m] (else estimated), each in [1e-12, 1e12]; not with affine noise.
  std::optional<std::array<double, kChannels>> noise_scale;
  RobustLoss loss = RobustLoss::none;  ///< robust loss of the residuals
  double loss_scale = 2.0;             ///< robust loss threshold, in noise scales
  int noise_iterations = 6;            ///< fit / scatter / refit rounds when s_c is estimated
  double regularization_speed = 1e-6;  ///< eps of the law [m/s]
  /// The law's a and m within what a non-negative pressure gives, a <= 4 and m >= 4 (theory.md
  /// section 4; ModelSpec::admissible_shape). false reproduces fits such as the seed's Table 3,
  /// whose m = 1.72 no patch gives.
  bool admissible_shape = true;
  /// Hold a, m and M0 / (F0 R) to what a non-negative pressure gives together, not only a and
  /// m on their own (ModelSpec::joint_admissibility): the law is then one some patch produces.
  /// Off by default; contensou-identify --admissible-law.
  bool joint_admissibility = false;
  /// Polled between the solver's iterations and the closed loop's stages (and by the exact laws'
  /// builds): the fit or the loop throws Interrupted once it returns true (error.hpp).
  StopRequest stop{};

 private:
  detail::TestSeams seams_;
  // The profile's exact model and laws, shared by the fits of one identify() (its resamples),
  // so that each builds them once; unset: each fit builds its own (shared_laws.hpp).
  std::shared_ptr<const detail::SharedLaws> shared_laws_;
  friend struct testing::Seams;
  friend struct detail::LawSharing;
};

/// One parameter of a fit's report.
struct ParameterEstimate {
  std::string name;        ///< as in `--fix` and the JSON report ("F0_N", "kappa", "f")
  std::string unit;        ///< "N", "N m", "1", ...
  double value = 0.0;      ///< the estimate (or the fixed or derived value)
  bool fixed = false;      ///< held at its given or start value, not estimated
  bool determined = true;  ///< estimated and determined by the data (false: no interval)
  bool derived = false;    ///< computed from the profile, not estimated
  /// Standard error (NaN when not determined).
  double std_error = std::numeric_limits<double>::quiet_NaN();
  /// The 95 % interval (none when not determined), clipped to the parameter's bounds.
  std::optional<std::array<double, 2>> ci95;
  /// "lower" or "upper" when the estimate ends on that bound of the fit (parameter_bounds),
  /// else "": its interval is then one-sided, from the bound.
  std::string on_bound;
  /// What the bound means (bound_meaning), when on_bound is set.
  std::string bound_meaning;
  /// What a parameter of a friction_dependence slot follows, and the dependence in the variable's
  /// units ("f (1 + b1 z), z = T [degC] over 293.15 to 313.15 K: (1/f) df/dX = -0.0042 1/K");
  /// "" for the others.
  std::string note;
};

/// Residual diagnostics of one channel, its residuals in time order when every row has a time,
/// else along psi = |v| / |omega R|.
struct ChannelDiagnostics {
  std::string channel;         ///< "Fx_N", "Fy_N" or "Mz_Nm"
  int points = 0;              ///< measured values of the channel
  double rms = 0.0;            ///< rms residual, unweighted [N or N m]
  double noise_scale = 0.0;    ///< s_c (a_c of affine noise)
  double noise_slope = 0.0;    ///< b_c of affine noise (0 otherwise)
  double runs_p_value = 1.0;   ///< p value of the runs test on the residual's signs (runs_test)
  double lag1 = 0.0;           ///< lag-1 autocorrelation of the residual
  double durbin_watson = 2.0;  ///< Durbin-Watson statistic of the residual
  /// Neither the runs test nor the lag-1 autocorrelation is significant at 0.01, Bonferroni
  /// corrected over the two tests of every measured channel.
  bool white = true;
  /// The residual's scatter between neighbouring rows (outliers.hpp, neighbour_scatter): the
  /// noise as the data show it, whatever the model misses (0: too few rows to tell).
  double neighbour_scale = 0.0;
};

/// The noise scales of a fit: its model and the per-channel constants.
struct NoiseScales {
  NoiseModel model = NoiseModel::additive;  ///< how the scale follows the value
  std::array<double, kChannels> scale{};    ///< s_c (a_c of affine noise)
  std::array<double, kChannels> slope{};    ///< b_c of affine noise
};

/// The result of a fit (fit_model, fit_fractional_law): estimates, diagnostics and the model at
/// every data point.
struct FitReport {
  /// The reported parameters in index order (F0_N, a, M0_Nm, m, kx, then any other that is free
  /// or away from its null), then f = F0 / N if N is known.
  std::vector<ParameterEstimate> parameters;
  std::vector<std::string> correlation_names;  ///< free, determined parameters
  Eigen::MatrixXd correlation;  ///< their correlation matrix (identity without a covariance)
  std::vector<ChannelDiagnostics> channels;  ///< measured channels only
  /// The fitted law (base model); default-constructed when the exact integrals replace the law
  /// (ModelSpec::exact_only).
  FractionalLaw<double> law;
  /// The model fitted, at its estimates (ModelSpec::value): what predicts new rows
  /// (prediction.hpp) and what the report's "model" records (model_file.hpp).
  std::shared_ptr<const ModelSpec> model;
  // At each data point (all points of the data, also those a subset fit did not use):
  std::vector<Resultants<double>> prediction;  ///< the model at each data point
  std::vector<double> psi;  ///< psi = |v| / (|omega| R) at each point (sliding_spin_ratio)
  /// y - yhat per channel (Fx, Fy, Mz; nullopt where the channel was not measured), at each point.
  std::vector<std::array<std::optional<double>, kChannels>> residual;
  NoiseModel noise_model = NoiseModel::additive;  ///< the fit's noise model
  std::array<double, kChannels> noise_scale{};    ///< s_c (a_c of affine noise)
  std::array<double, kChannels> noise_slope{};    ///< b_c of affine noise (0 otherwise)
  double m2ll = 0.0;        ///< -2 log likelihood (Gaussian, with the noise scales)
  int residuals = 0;        ///< measured values fitted (weighted residuals)
  int free_parameters = 0;  ///< free parameters the data determine
  /// residuals - free_parameters - estimated noise parameters (the intervals' Student t).
  int degrees_of_freedom = 0;
  double chi2 = 0.0;  ///< weighted sum of squares
  double aic = 0.0;   ///< m2ll + 2 k, k = free_parameters + estimated noise parameters
  double bic = 0.0;   ///< m2ll + k log(residuals)
  /// Dimensionless error: rms over channels of (channel rms / channel's largest |y|).
  double error = 0.0;
  bool residual_white = true;  ///< every channel's residual white (ChannelDiagnostics::white)
  bool converged = false;      ///< Ceres' solution usable (a failed solve throws instead)
  std::string solver_summary;  ///< Ceres' brief report of the last solve
  /// What the residual follows (residual_trace.hpp); filled by identify() and the closed loop
  /// for the fits they report (empty otherwise).
  ResidualTrace trace;
  /// Every channel's rms within 1.5 times its scatter between neighbouring rows (a channel whose
  /// scatter is unknown counts as within): the misfit is no larger than the noise the data show.
  bool within_noise() const;

  /// The parameter named `name` ("F0_N"), or nullptr if the report has none.
  const ParameterEstimate* parameter(const std::string& name) const;
  /// The fit's noise model and scales.
  NoiseScales noise_scales() const { return {noise_model, noise_scale, noise_slope}; }
};

/// Fits the fractional law to the data (base_spec_for, noise_settings_for, fit_model). Throws
/// InvalidArgument for a non-positive radius or load, an unknown `--fix` name or a fixed value
/// outside its bounds, every parameter fixed, rows all at rest, fewer measured values than
/// measured_values_needed, forces outside [1e-6, 1e8] N and bad given noise scales;
/// std::runtime_error naming the fit if the solve fails; Interrupted when options.stop asks.
FitReport fit_fractional_law(const MeasuredData& data, const IdentificationOptions& options);

/// How a fit treats the noise (shared by the base fit and the closed loop).
struct NoiseSettings {
  NoiseModel model = NoiseModel::additive;  ///< how the noise scale follows the value
  /// Fixed scales (else estimated), each in [1e-12, 1e12]; not with affine noise.
  std::optional<std::array<double, kChannels>> given;
  /// Where the estimated scales start (a fit of a sample of the same rows, say), when its model
  /// is this one; else 5 % of each channel's peak. The rounds then settle sooner.
  std::optional<NoiseScales> start;
  RobustLoss loss = RobustLoss::none;  ///< robust loss of the residuals
  double loss_scale = 2.0;             ///< robust loss threshold, in noise scales
  /// Fit / scatter / refit rounds at most (one when given additive scales); they stop once the
  /// scales change by less than 1e-3.
  int iterations = 6;
  int solver_iterations = 200;  ///< Ceres' iterations per round (the loop's retry test lowers it)
  /// Polled after every solver iteration and between the rounds: Interrupted once it returns
  /// true (IdentificationOptions::stop).
  StopRequest stop{};

 private:
  detail::TestSeams seams_;
  friend struct testing::Seams;
};

/// Fits a general model (effect_model.hpp): its free parameters, from spec.value as start.
/// `use` selects the points (empty: all); `estimate`, if given, receives every parameter's value
/// at the optimum. Used by fit_fractional_law and the closed loop. Throws
/// InvalidArgument for data a fit cannot be made on (as fit_fractional_law) and for a start or
/// fixed value outside the model's domain, and std::runtime_error naming the fit if the solve
/// fails or its Jacobian is not finite (no covariance or report is computed from a failed
/// solve); Interrupted when noise.stop asks.
FitReport fit_model(const MeasuredData& data, const ModelSpec& spec, const NoiseSettings& noise,
                    std::array<double, kModelParameters>* estimate = nullptr,
                    const std::vector<char>& use = {});

/// Measured values a fit of `spec` needs at least: free parameters + estimated noise parameters
/// (one per channel, two for affine noise) + 1 (one degree of freedom left for the intervals).
/// fit_model refuses fewer.
int measured_values_needed(const MeasuredData& data, const ModelSpec& spec,
                           const NoiseSettings& noise);

/// The noise scales of a fit (FitReport::noise_scales()).
NoiseScales noise_scales_of(const FitReport& fit);

/// Weighted residuals r and their Jacobian J with respect to all kModelParameters parameters
/// at theta (weights 1/s_ic, NoiseModel, with yhat the model at theta; no robust loss): a row
/// per measured value of the points `use` selects (empty: all). Columns of parameters neither
/// free nor scored by the closed loop are zero. `row_point`, if given, receives each row's point
/// index.
void weighted_jacobian(const MeasuredData& data, const ModelSpec& spec,
                       const std::array<double, kModelParameters>& theta, const NoiseScales& noise,
                       Eigen::VectorXd* r, Eigen::MatrixXd* J, const std::vector<char>& use = {},
                       std::vector<int>* row_point = nullptr);

/// The spec of the base fit for the options (law, start values, fixed parameters; the
/// reference load when rows have their own Fz). Throws InvalidArgument for a non-positive radius
/// or load, an unknown fixed name or a fixed value that is not finite or outside its bounds.
ModelSpec base_spec_for(const MeasuredData& data, const IdentificationOptions& options);
/// The noise settings of the options (model, given scales, loss, rounds, stop).
NoiseSettings noise_settings_for(const IdentificationOptions& options);

/// Predictions of a law at the data's kinematics.
std::vector<Resultants<double>> predict(const FractionalLaw<double>& law, const MeasuredData& data);

/// psi = |v| / (|omega| R) of each point (infinity for pure sliding), R = `radius_m` [m]. A fit
/// carries it for its data (FitReport::psi): a report reads it there.
std::vector<double> sliding_spin_ratio(const MeasuredData& data, double radius_m);

/// Residual diagnostics of each measured channel for given predictions `model` (one a point),
/// with noise scales `scale` reported as ChannelDiagnostics::noise_scale (noise_slope and
/// neighbour_scale are left 0).
std::vector<ChannelDiagnostics> residual_diagnostics(const MeasuredData& data,
                                                     const std::vector<Resultants<double>>& model,
                                                     double radius_m,
                                                     const std::array<double, kChannels>& scale);

}  // namespace contensou
