// Internal: the closed loop's candidate effects and their score tests, shared by
// closed_loop.cpp and loop_candidates.cpp. Not installed.
#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/effect_catalogue.hpp"

namespace contensou::detail {

struct Candidate {
  Candidate(Effect e, std::string d, std::vector<int> p, int s, bool scan = false, int sl = -1,
            std::optional<Covariate> c = std::nullopt)
      : effect(e),
        detail(std::move(d)),
        parameters(std::move(p)),
        scored(s),
        scan_speed(scan),
        slot(sl),
        covariate(std::move(c)) {}
  Effect effect;
  std::string detail;
  std::vector<int> parameters;  // made free when the effect is fitted
  int scored = -1;              // the parameter whose score ranks the candidate (-1: derived)
  bool scan_speed = false;      // speed_dependence: scan w_s
  int slot = -1;                // friction_dependence(_curve): its slot
  std::optional<Covariate> covariate;  // friction_dependence: the variable
};

// The catalogue's candidates that can extend the model s on these data (the recorded
// variables as covariates): the shape, kinematic and channel effects not yet in s.
std::vector<Candidate> catalogue(const MeasuredData& data, const ModelSpec& s,
                                 const std::vector<Covariate>& covariates);

// The columns of a full Jacobian (all kModelParameters) that belong to s's free parameters.
Eigen::MatrixXd free_columns(const Eigen::MatrixXd& J, const ModelSpec& s);

// The direction (I - P_A) z in which a candidate's column z moves the weighted residual.
Eigen::VectorXd score_direction(const Eigen::MatrixXd& J, const ModelSpec& s,
                                const Eigen::VectorXd& z);

// The score (LM) statistic (z' r)^2 / (zp' zp) / s^2, chi-square with 1 dof under the null.
double score_statistic(const Eigen::VectorXd& r, const Eigen::VectorXd& z,
                       const Eigen::VectorXd& zp, const ModelSpec& s);

// The score statistic of the full Jacobian's column j.
double lm_statistic(const Eigen::VectorXd& r, const Eigen::MatrixXd& J, const ModelSpec& s, int j);

// The Jacobian column of a friction_dependence(_curve) candidate at its null.
Eigen::VectorXd dependence_column(const MeasuredData& data, const Eigen::MatrixXd& J,
                                  const std::vector<int>& row_point,
                                  const std::array<double, kModelParameters>& theta,
                                  const Candidate& c);

// |cos| of the angle between two directions (0 for empty or mismatched ones).
double direction_correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

// "effect (detail)".
std::string label(const Candidate& c);

// An instrument effect (a channel's offset or crosstalk) whose separating measurement the data
// lack: the physical effect it cannot be told from, in words with the measurement that would
// decide ("" when the data hold that measurement, or for a physical effect).
std::string unconfirmed_instrument(const Candidate& c, const MeasuredData& data);

// A slip-angle offset delta [rad] fitted where the force's own turn (data_checks.hpp: the
// median angle to -v where sliding dominates) does not match it: what it stands in for, in
// words ("" when they agree within max(1 deg, 3 half-widths of the median's interval)).
std::string unconfirmed_slip_angle(double delta_rad, const MeasuredData& data, double radius_m);

// What data would tell two candidate effects apart, in a sentence.
std::string separating_measurement(const Candidate& a, const Candidate& b,
                                   const MeasuredData& data);

}  // namespace contensou::detail
