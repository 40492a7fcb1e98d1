// The closed loop's candidates: the catalogue's effects that can extend a model, their score
// (Lagrange multiplier) tests and what measurement tells two of them apart. See
// loop_candidates.hpp.
#include "loop_candidates.hpp"

#include "contensou/identification/data_checks.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace contensou {
using namespace detail;  // NOLINT: this file implements loop_candidates.hpp

namespace {

constexpr int K = kModelParameters;

// The first slot no variable uses, or -1.
int free_slot(const ModelSpec& s) {
  for (int j = 0; j < kDependenceSlots; ++j)
    if (!s.dependence[j]) return j;
  return -1;
}

bool slot_holds(const ModelSpec& s, const Covariate& c) {
  for (const std::optional<Covariate>& d : s.dependence)
    if (d && d->kind == c.kind && d->recorded == c.recorded) return true;
  return false;
}

// Rows that read the rig's kinematics and channels alone: at rest (v = omega = 0) with the
// channel measured, pure sliding (omega = 0, v != 0), pure spin (v = 0) in each sense.
struct RigEvidence {
  std::array<int, kChannels> rest{};
  int pure_sliding = 0, spin_positive = 0, spin_negative = 0;
};

RigEvidence rig_evidence(const MeasuredData& data) {
  RigEvidence e;
  for (const MeasuredPoint& p : data.points) {
    const Kinematics<double>& k = p.kinematics;
    const bool still = k.vx == 0.0 && k.vy == 0.0;
    if (still && k.omega == 0.0)
      for (int c = 0; c < kChannels; ++c) e.rest[c] += p.force[c].has_value();
    e.pure_sliding += k.omega == 0.0 && !still;
    e.spin_positive += still && k.omega > 0.0;
    e.spin_negative += still && k.omega < 0.0;
  }
  return e;
}

constexpr int kEvidenceRows = 3;

// The rig's kinematics, the patch's growth and friction that follows a recorded variable. A
// slip-angle offset is a candidate only when the force is turned from -v where sliding
// dominates (data_checks.hpp: the median angle's interval excludes 0), a spin offset only with
// pure-sliding rows or pure-spin rows in both senses: without them neither has its evidence.
void conditions_catalogue(const MeasuredData& data, const ModelSpec& s,
                          const std::vector<Covariate>& covariates, std::vector<Candidate>& out) {
  bool longitudinal = false;
  for (const MeasuredPoint& p : data.points) longitudinal = longitudinal || p.kinematics.vx != 0.0;
  if (!s.free[kSlipAngleOffset] && longitudinal && data.count(1) > 0 &&
      check_data(data, s.radius_m).angle_offset_shown())
    out.push_back({Effect::slip_angle_offset, "", {kSlipAngleOffset}, kSlipAngleOffset});
  const RigEvidence e = rig_evidence(data);
  if (!s.free[kSpinOffset] &&
      (e.pure_sliding >= kEvidenceRows || (e.spin_positive > 0 && e.spin_negative > 0)))
    out.push_back({Effect::spin_offset, "", {kSpinOffset}, kSpinOffset});
  const bool load_varies =
      std::any_of(covariates.begin(), covariates.end(),
                  [](const Covariate& c) { return c.kind == Covariate::Kind::load; });
  if (!s.free[kPatchGrowth] && s.reference_load_n && load_varies)
    out.push_back({Effect::patch_growth, "", {kPatchGrowth}, kPatchGrowth});
  const int slot = free_slot(s);
  for (const Covariate& c : covariates)
    if (slot >= 0 && !slot_holds(s, c))
      out.push_back({Effect::friction_dependence,
                     c.name,
                     {dependence_parameter(slot, false)},
                     -1,
                     false,
                     slot,
                     c});
  for (int j = 0; j < kDependenceSlots; ++j)
    if (s.dependence[j] && !s.free[dependence_parameter(j, true)])
      out.push_back({Effect::friction_dependence_curve,
                     s.dependence[j]->name,
                     {dependence_parameter(j, true)},
                     -1,
                     false,
                     j,
                     s.dependence[j]});
}

// The contact's own geometry, the physical alternatives to the rig's torque effects: its centre
// off the body's (with a torque channel) and a contact smaller than the body (with spin too).
void contact_catalogue(const MeasuredData& data, const ModelSpec& s, std::vector<Candidate>& out) {
  if (data.count(2) == 0) return;
  if (!s.free[kCentreX]) out.push_back({Effect::centre_offset, "x", {kCentreX}, kCentreX});
  if (!s.free[kCentreY]) out.push_back({Effect::centre_offset, "y", {kCentreY}, kCentreY});
  const bool spin = std::any_of(data.points.begin(), data.points.end(),
                                [](const MeasuredPoint& p) { return p.kinematics.omega != 0.0; });
  if (spin && !s.free[kContactRatio])
    out.push_back({Effect::contact_radius, "", {kContactRatio}, kContactRatio});
}

}  // namespace

namespace detail {

std::vector<Candidate> catalogue(const MeasuredData& data, const ModelSpec& s,
                                 const std::vector<Covariate>& covariates) {
  std::vector<Candidate> out;
  if (!s.uses_exact()) {
    Candidate shape{Effect::shape,
                    s.profile_model ? "exact integrals over the profile"
                                    : "exact integrals, profile identified",
                    {kShapeBlend},
                    kShapeBlend};
    if (!s.profile_model) shape.parameters = {kShapeBlend, kProfileW1, kProfileW2};
    out.push_back(shape);
  }
  if (!s.free[kKappa]) out.push_back({Effect::anisotropy, "", {kKappa}, kKappa});
  if (!s.free[kKy]) out.push_back({Effect::pressure_shift_y, "", {kKy}, kKy});
  if (!s.free[kSpeedDrop])
    out.push_back({Effect::speed_dependence, "", {kSpeedDrop, kSpeedRef}, kSpeedDrop, true});
  for (int c = 0; c < kChannels; ++c) {
    if (data.count(c) == 0) continue;
    if (!s.free[offset_parameter(c)])
      out.push_back(
          {Effect::channel_offset, kChannelColumns[c], {offset_parameter(c)}, offset_parameter(c)});
    for (int d = 0; d < kChannels; ++d) {
      if (d == c || s.free[crosstalk_parameter(c, d)]) continue;
      out.push_back({Effect::channel_crosstalk,
                     std::string(kChannelColumns[c]) + " <- " + kChannelColumns[d],
                     {crosstalk_parameter(c, d)},
                     crosstalk_parameter(c, d)});
    }
  }
  contact_catalogue(data, s, out);
  conditions_catalogue(data, s, covariates, out);
  return out;
}

// The columns of a full Jacobian (all kModelParameters) that belong to the free parameters.
Eigen::MatrixXd free_columns(const Eigen::MatrixXd& J, const ModelSpec& s) {
  std::vector<int> cols;
  for (int i = 0; i < K; ++i)
    if (s.free[i]) cols.push_back(i);
  Eigen::MatrixXd A(J.rows(), static_cast<Eigen::Index>(cols.size()));
  for (std::size_t k = 0; k < cols.size(); ++k)
    A.col(static_cast<Eigen::Index>(k)) = J.col(cols[k]);
  return A;
}

// The direction in which a candidate moves the weighted residual, its Jacobian column with the
// free columns A projected out, (I - P_A) z: two candidates with nearly parallel directions
// explain the same residual.
Eigen::VectorXd score_direction(const Eigen::MatrixXd& J, const ModelSpec& s,
                                const Eigen::VectorXd& z) {
  const Eigen::MatrixXd A = free_columns(J, s);
  return z - A * A.colPivHouseholderQr().solve(z);
}

// Score (LM) statistic of a column z with direction zp = (I - P_A) z, A the free columns of
// the current fit: (z' r)^2 / (zp' zp) / s^2, chi-square with 1 dof under the null.
double score_statistic(const Eigen::VectorXd& r, const Eigen::VectorXd& z,
                       const Eigen::VectorXd& zp, const ModelSpec& s) {
  const double denom = zp.squaredNorm();
  if (!(denom > 1e-20 * std::max(z.squaredNorm(), 1e-300))) return 0.0;
  int free = 0;
  for (int i = 0; i < K; ++i) free += s.free[i];
  const double s2 = r.squaredNorm() / std::max<double>(1.0, static_cast<double>(r.size()) -
                                                                static_cast<double>(free));
  const double num = z.dot(r);
  return num * num / denom / s2;
}

double lm_statistic(const Eigen::VectorXd& r, const Eigen::MatrixXd& J, const ModelSpec& s, int j) {
  return score_statistic(r, J.col(j), score_direction(J, s, J.col(j)), s);
}

// The Jacobian column of a friction_dependence(_curve) candidate at its null, from the column of
// the friction scale s (the friction part of each row): z_i (linear) or T2(z_i) / (1 + b1 z_i)
// (the curve of a slot whose linear term is b1) times it, z_i the row's scaled variable.
Eigen::VectorXd dependence_column(const MeasuredData& data, const Eigen::MatrixXd& J,
                                  const std::vector<int>& row_point,
                                  const std::array<double, K>& theta, const Candidate& c) {
  Eigen::VectorXd z(J.rows());
  const double b1 = theta[dependence_parameter(c.slot, false)];
  for (Eigen::Index row = 0; row < J.rows(); ++row) {
    const double x = c.covariate->scaled(data.points[row_point[static_cast<std::size_t>(row)]]);
    const double factor =
        c.effect == Effect::friction_dependence_curve ? (2.0 * x * x - 1.0) / (1.0 + b1 * x) : x;
    z(row) = factor * J(row, kFrictionScale);
  }
  return z;
}

double direction_correlation(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  if (a.size() == 0 || b.size() != a.size()) return 0.0;
  const double n = a.norm() * b.norm();
  return n > 0.0 ? std::abs(a.dot(b)) / n : 0.0;
}

std::string label(const Candidate& c) {
  const std::string name = describe(c.effect).name;
  return c.detail.empty() ? name : name + " (" + c.detail + ")";
}

// What data would tell two candidate effects apart, from what each depends on: an offset does
// not follow the motion, a slip-speed law follows the spin speed, anisotropy, a lateral shift
// and crosstalk into or from Fy show in lateral sliding, a crosstalk follows its source
// channel, the shape shows across psi, two recorded variables that rise together are told apart
// by rows where one changes alone; else the catalogue's own words for the first of the two.
std::string separating_measurement(const Candidate& a, const Candidate& b,
                                   const MeasuredData& data) {
  auto either = [&](Effect e) { return a.effect == e || b.effect == e; };
  auto involves_fy = [](const Candidate& c) {
    return c.effect == Effect::anisotropy || c.effect == Effect::pressure_shift_y ||
           (c.effect == Effect::channel_crosstalk && c.detail.find("Fy_N") != std::string::npos);
  };
  auto variable = [](const Candidate& c) {
    return c.effect == Effect::friction_dependence ? c.detail
           : c.effect == Effect::speed_dependence  ? std::string("the slip speed")
                                                   : std::string();
  };
  bool lateral = false;
  for (const MeasuredPoint& p : data.points)
    lateral = lateral || std::abs(p.kinematics.vy) > 0.2 * std::abs(p.kinematics.vx);
  if (!variable(a).empty() && !variable(b).empty())
    return variable(a) + " and " + variable(b) +
           " change together in these data: rows where one changes while the other is held (a "
           "sweep repeated at another value of one of them) separate them";
  if (either(Effect::channel_offset))
    return "rows at rest (v = omega = 0) and sweeps with both signs of v and omega separate them: "
           "an offset does not change sign with the motion";
  if (either(Effect::centre_offset))
    return "pure spin (v = 0) in both senses, or a static load at a known point, separates them: "
           "a patch off the centre slides under pure spin and pushes back, a rig's effect does "
           "not";
  if (either(Effect::speed_dependence))
    return "a second sweep at another spin speed u = |omega| R separates them: the slip speed "
           "changes, the ratio psi does not";
  if (either(Effect::slip_angle_offset))
    return std::string(describe(Effect::slip_angle_offset).separate) + " separate them";
  if ((involves_fy(a) || involves_fy(b)) && !lateral)
    return "a lateral sweep (sliding along y) separates them";
  if (either(Effect::pressure_shift_y))
    return "pure-spin rows in both spin directions separate them: Fx from ky changes sign with "
           "omega";
  if (either(Effect::channel_crosstalk))
    return "sweeps in other sliding directions separate them: a crosstalk follows its source "
           "channel, friction follows the motion";
  if (either(Effect::shape))
    return "more points with psi between 0.1 and 10, where the law's own error is largest, "
           "separate them";
  const Candidate& first = a.effect == Effect::friction_dependence ? b : a;
  return effect_in_words(first.effect, first.detail) + ": " + describe(first.effect).separate +
         " would show it";
}

std::string unconfirmed_slip_angle(double delta_rad, const MeasuredData& data, double radius_m) {
  const DataChecks checks = check_data(data, radius_m);
  const double delta = delta_rad * 180.0 / 3.14159265358979323846;
  const double half = 0.5 * (checks.median_angle_high_deg - checks.median_angle_low_deg);
  if (checks.sliding_rows > 0 &&
      std::abs(delta - checks.median_angle_deg) <= std::max(1.0, 3 * half))
    return "";
  char b[400];
  std::snprintf(b, sizeof b,
                "what the offset of %.2f deg stands in for: where sliding dominates the force is "
                "turned by a median %.2f deg only (anisotropy, or the pressure's shape); pure "
                "sliding in several directions would decide",
                delta, checks.median_angle_deg);
  return b;
}

std::string unconfirmed_instrument(const Candidate& c, const MeasuredData& data) {
  const RigEvidence e = rig_evidence(data);
  const auto channel = [&](const std::string& name) {
    for (int k = 0; k < kChannels; ++k)
      if (name == kChannelColumns[k]) return k;
    return 0;
  };
  if (c.effect == Effect::channel_offset) {
    if (e.rest[channel(c.detail)] >= kEvidenceRows) return "";
    return c.detail == "Mz_Nm"
               ? "a torque through an arm (the force applied, or the torque taken, about a point "
                 "off the assumed centre: it follows the force, which keeps nearly one direction "
                 "in these rows); rows at rest (v = omega = 0) would read a zero drift alone"
               : "a force from outside the contact that keeps its direction in the body's frame "
                 "(a pusher, a cable, a slope); rows at rest (v = omega = 0) would read a zero "
                 "drift alone";
  }
  if (c.effect != Effect::channel_crosstalk) return "";
  const bool into_torque = c.detail.rfind("Mz_Nm", 0) == 0;
  const bool from_torque = c.detail.find("<- Mz_Nm") != std::string::npos;
  if (into_torque || from_torque) {
    if (e.rest[channel(c.detail.substr(0, c.detail.find(' ')))] >= kEvidenceRows) return "";
    return "the centre of pressure (or the point the torque is taken about) off the patch's "
           "centre, whose arm turns force into torque the same way; a static load at a known "
           "point with no motion (the load cell's calibration) would decide";
  }
  if (e.pure_sliding >= kEvidenceRows) return "";
  return "friction that differs with direction (anisotropy) or a patch turned on the body; pure "
         "sliding along x and along y without spin would decide (a crosstalk turns the force "
         "there, anisotropy does not)";
}

}  // namespace detail
}  // namespace contensou
