/// \file
/// An identified model at rows it may never have seen, both ways (the planar-pushing field's two
/// questions): the friction wrench from the motion, and the motion a measured wrench would
/// cause, i.e. the normal of the model's limit surface at that wrench.
///
/// In the scaled twist t = (vx, vy, omega R) and scaled wrench w = (Fx, Fy, Mz / R) [N] (R the
/// patch radius; theory.md section 1 for the signs: the wrench is the friction on the body), a
/// rate-independent friction law maps each twist direction d (|d| = 1) to a wrench w(d), the
/// limit surface's point whose outward normal is -d (limit_surface.hpp). The motion of a
/// measured wrench w_m is the direction d whose w(d) is parallel to w_m (the radial projection of
/// w_m onto the surface, then its normal): found by maximising cos angle(w(d), w_m) over the
/// unit sphere, from the best of a Fibonacci grid of directions, then a pattern search in the
/// tangent plane (the model is evaluated at the row's own speed |t|, which matters only to a
/// speed law f(w)).
#pragma once

#include <Eigen/Core>
#include <limits>
#include <string>
#include <vector>

#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// How predict_rows searches the motion of a wrench.
struct PredictionOptions {
  int grid_directions = 400;      ///< Fibonacci directions on the unit sphere (at least 20)
  double angle_tolerance = 1e-7;  ///< the pattern search's last step [rad]
};

/// One row's predictions.
struct RowPrediction {
  /// The model's friction at the row's motion: Fx, Fy [N], Mz [N m].
  Resultants<double> wrench;
  /// The direction of motion the row's measured wrench would cause: unit (vx, vy, omega R), NaN
  /// when the row lacks a channel or its wrench is zero.
  Eigen::Vector3d twist = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  /// The angle left between the model's wrench at `twist` and the measured one [rad]: 0 when
  /// the measured wrench's direction is one the model's limit surface has; large when no motion
  /// gives it (a torque above what the patch can carry, say). NaN with `twist`.
  double wrench_misfit_rad = std::numeric_limits<double>::quiet_NaN();
};

/// Both predictions at every row of `data` (rows without forces get the wrench only). The spec
/// is evaluated at its values (ModelSpec::value) and each row's conditions (conditions_of: bind
/// a model read from a file to the data first, model_file.hpp). Throws InvalidArgument for bad
/// options, and what evaluate_model throws.
std::vector<RowPrediction> predict_rows(const ModelSpec& model, const MeasuredData& data,
                                        const PredictionOptions& options = {});

/// The field's scores of predictions against the measured rows (those with all three channels
/// and some motion), in the scaled twist and wrench above.
struct PredictionScores {
  int rows = 0;                        ///< rows scored
  double median_motion_angle_deg = 0;  ///< median angle, predicted vs measured unit twist [deg]
  double mean_motion_angle_deg = 0;    ///< its mean [deg]
  double median_force_error = 0;       ///< median |w_pred - w| / |w|
  double mean_force_error = 0;         ///< its mean
  double median_force_angle_deg = 0;   ///< median angle between w_pred and w [deg]
};
/// The scores of `predictions` (one a row of `data`); R = radius_m [m]. Rows = 0 (the rest NaN)
/// when no row can be scored.
PredictionScores score_predictions(const MeasuredData& data,
                                   const std::vector<RowPrediction>& predictions, double radius_m);

/// The fit's error measure (FitReport::error) of predictions `model` (one a row) on the rows of
/// `data`: the root mean square over the measured channels of (the channel's rms residual / its
/// magnitude), the magnitude its largest |value| in these rows but at least 1e-3 of the rows'
/// force scale (the largest |Fx|, |Fy|, |Mz| / R; times R for Mz), as the fit's: a channel
/// measured near zero (Fx of a lateral sweep) does not blow the measure up. R = radius_m [m].
/// NaN when no channel is measured.
double prediction_error(const MeasuredData& data, const std::vector<Resultants<double>>& model,
                        double radius_m);

/// The wrenches of predictions (RowPrediction::wrench), one a row.
std::vector<Resultants<double>> wrenches_of(const std::vector<RowPrediction>& predictions);

/// Rows set aside to judge a model on rows its fit never saw (holdout_split).
struct HoldoutSplit {
  MeasuredData fit;        ///< the rows the fit may use (each keeps its file, line, columns)
  MeasuredData held_out;   ///< the rows held out
  int groups = 0;          ///< the groups the rows fall into
  int held_groups = 0;     ///< the groups held out
  std::string grouped_by;  ///< "sweeps" or the group column's header
};
/// Whole groups (the sweeps of sweeps_of, or the values of the recorded column `group_column`
/// when given) drawn at random (seed `seed`) until `fraction` of the rows is held out; the
/// others are the fit's. Throws InvalidArgument for a fraction outside (0, 0.9], a group column
/// the data lack, or data whose groups cannot leave both parts non-empty.
HoldoutSplit holdout_split(const MeasuredData& data, double radius_m, double fraction,
                           const std::string& group_column = "", unsigned seed = 1);

/// The predictions as CSV, one line a row of `data` in its order: the row's file and line, its
/// kinematics and measured channels (empty where not measured), then pred_Fx_N, pred_Fy_N,
/// pred_Mz_Nm, pred_twist_vx, pred_twist_vy, pred_twist_omegaR (the unit twist; empty where no
/// motion was predicted) and wrench_misfit_deg. Values to 10 significant digits.
std::string predictions_csv(const MeasuredData& data,
                            const std::vector<RowPrediction>& predictions);

/// The scores in words, one line each ("motion from the force: median angle 12.3 deg (mean
/// 15.1 deg) over 500 rows").
std::string prediction_scores_text(const PredictionScores& scores);

}  // namespace contensou
