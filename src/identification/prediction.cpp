// An identified model's predictions both ways and their scores (prediction.hpp).
#include "contensou/identification/prediction.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>

#include "contensou/friction/error.hpp"
#include "contensou/identification/sweeps.hpp"

namespace contensou {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;

// Directions spread evenly on the unit sphere (the Fibonacci lattice).
std::vector<Eigen::Vector3d> fibonacci_sphere(int n) {
  std::vector<Eigen::Vector3d> out;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(1.0 - z * z);
    out.emplace_back(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
  }
  return out;
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The model's scaled wrench (Fx, Fy, Mz / R) at the scaled twist s d (d a unit direction).
struct WrenchMap {
  const ModelSpec& spec;
  PointConditions conditions;
  double speed;
  Eigen::Vector3d operator()(const Eigen::Vector3d& d) const {
    const double R = spec.radius_m;
    const Kinematics<double> k{speed * d[0], speed * d[1], speed * d[2] / R};
    const Resultants<double> r = evaluate_model(spec, spec.value.data(), k, conditions);
    return {r.Fx, r.Fy, r.Mz / R};
  }
};

// Pattern search on the sphere from d: the tangent steps +-h e1, +-h e2, halved when none
// improves the angle to the target, until h < tolerance.
Eigen::Vector3d refine_direction(const WrenchMap& w, const Eigen::Vector3d& target,
                                 Eigen::Vector3d d, double tolerance, double* misfit) {
  double best = angle_between(w(d), target);
  for (double h = 0.05; h >= tolerance;) {
    Eigen::Vector3d e1 = d.unitOrthogonal(), e2 = d.cross(e1);
    bool moved = false;
    for (const Eigen::Vector3d& step : {e1, Eigen::Vector3d(-e1), e2, Eigen::Vector3d(-e2)}) {
      const Eigen::Vector3d trial = (d + h * step).normalized();
      const double a = angle_between(w(trial), target);
      if (a < best) {
        best = a;
        d = trial;
        moved = true;
        break;
      }
    }
    if (!moved) h *= 0.5;
  }
  *misfit = best;
  return d;
}

// The direction whose model wrench is most nearly parallel to `target`.
Eigen::Vector3d motion_of(const WrenchMap& w, const Eigen::Vector3d& target,
                          const std::vector<Eigen::Vector3d>& grid, double tolerance,
                          double* misfit) {
  Eigen::Vector3d best = grid.front();
  double best_angle = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& d : grid) {
    const double a = angle_between(w(d), target);
    if (a < best_angle) {
      best_angle = a;
      best = d;
    }
  }
  return refine_direction(w, target, best, tolerance, misfit);
}

// The measured scaled wrench of a row, if it has all three channels and some force.
std::optional<Eigen::Vector3d> measured_wrench(const MeasuredPoint& p, double R) {
  if (!p.force[0] || !p.force[1] || !p.force[2]) return std::nullopt;
  const Eigen::Vector3d w(*p.force[0], *p.force[1], *p.force[2] / R);
  if (!(w.norm() > 0.0) || !w.allFinite()) return std::nullopt;
  return w;
}

Eigen::Vector3d scaled_twist(const MeasuredPoint& p, double R) {
  return {p.kinematics.vx, p.kinematics.vy, p.kinematics.omega * R};
}

// The speed the model is evaluated at for a row at rest: the median of the rows' speeds.
double typical_speed(const MeasuredData& data, double R) {
  std::vector<double> s;
  for (const MeasuredPoint& p : data.points)
    if (const double n = scaled_twist(p, R).norm(); n > 0.0) s.push_back(n);
  if (s.empty()) return 1.0;
  std::nth_element(s.begin(), s.begin() + static_cast<long>(s.size() / 2), s.end());
  return s[s.size() / 2];
}

double median(std::vector<double> v) {
  if (v.empty()) return kNaN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// The model at row i, or an error naming the row and its kinematics (speeds far beyond any rig,
// or kinematic columns in the wrong unit, make it overflow).
Resultants<double> wrench_at(const ModelSpec& spec, const MeasuredData& data, std::size_t i,
                             const PointConditions& c) {
  const Kinematics<double>& k = data.points[i].kinematics;
  std::string why;
  try {
    const Resultants<double> r = evaluate_model(spec, spec.value.data(), k, c);
    if (r.vector().allFinite()) return r;
    why = "the model is not finite there";
  } catch (const std::invalid_argument& e) {
    why = std::string("the model cannot be evaluated there (") + e.what() + ")";
  }
  throw InvalidArgument(point_location(data, i),
                        "vx = " + format_value(k.vx) + " m/s, vy = " + format_value(k.vy) +
                            " m/s, omega = " + format_value(k.omega) + " rad/s",
                        why + ": check the units of the kinematic columns");
}

// The motion a measured scaled wrench ws causes on the rigid patch's surface, and the angle
// left between the patch's wrench there and the measured one.
RowPrediction patch_motion(const LimitSurface& surface, double R, const Eigen::Vector3d& ws,
                           const Resultants<double>& model_wrench) {
  RowPrediction out;
  out.wrench = model_wrench;
  const Eigen::Vector3d w(ws.x(), ws.y(), ws.z() * R);
  out.twist = rigid_patch_motion(surface, R, w);
  if (!out.twist.allFinite()) return out;
  const Eigen::Vector3d back =
      rigid_patch_wrench(surface, Eigen::Vector3d(out.twist.x(), out.twist.y(), out.twist.z() / R));
  const Eigen::Vector3d bs(back.x(), back.y(), back.z() / R);
  out.wrench_misfit_rad = std::atan2(bs.cross(ws).norm(), bs.dot(ws));
  return out;
}

}  // namespace

std::vector<RowPrediction> predict_rows(const ModelSpec& spec, const MeasuredData& data,
                                        const PredictionOptions& options) {
  if (options.grid_directions < 20 || options.grid_directions > 100000)
    throw InvalidArgument("grid_directions", std::to_string(options.grid_directions),
                          "must lie in [20, 100000]");
  if (!(options.angle_tolerance > 0.0 && options.angle_tolerance < 0.1))
    throw InvalidArgument("angle_tolerance", format_value(options.angle_tolerance),
                          "must lie in (0, 0.1) rad");
  const double R = spec.radius_m;
  const std::vector<Eigen::Vector3d> grid = fibonacci_sphere(options.grid_directions);
  // The motion from the force: the rigid patch's limit surface when the model carries one.
  const std::optional<LimitSurface> patch =
      spec.motion_patch ? std::optional<LimitSurface>(limit_surface_of(*spec.motion_patch))
                        : std::nullopt;
  const double fallback_speed = typical_speed(data, R);
  std::vector<RowPrediction> out(data.points.size());
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const MeasuredPoint& p = data.points[i];
    const PointConditions c = conditions_of(spec, p);
    out[i].wrench = wrench_at(spec, data, i, c);
    const std::optional<Eigen::Vector3d> wm = measured_wrench(p, R);
    if (!wm) continue;
    if (patch) {
      out[i] = patch_motion(*patch, R, *wm, out[i].wrench);
      continue;
    }
    const double speed = scaled_twist(p, R).norm();
    const WrenchMap w{spec, c, speed > 0.0 ? speed : fallback_speed};
    try {
      out[i].twist = motion_of(w, *wm, grid, options.angle_tolerance, &out[i].wrench_misfit_rad);
    } catch (const std::invalid_argument& e) {
      throw InvalidArgument(point_location(data, i), "speed " + format_value(w.speed) + " m/s",
                            std::string("the model cannot be evaluated at this row's speed in "
                                        "every direction (") +
                                e.what() + "): check the units of the kinematic columns");
    }
  }
  return out;
}

PredictionScores score_predictions(const MeasuredData& data,
                                   const std::vector<RowPrediction>& predictions, double radius_m) {
  if (predictions.size() != data.points.size())
    throw InvalidArgument(
        "predictions", std::to_string(predictions.size()),
        "must be one a row of the data (" + std::to_string(data.points.size()) + ")");
  std::vector<double> motion, error, force_angle;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const MeasuredPoint& p = data.points[i];
    const std::optional<Eigen::Vector3d> wm = measured_wrench(p, radius_m);
    const Eigen::Vector3d t = scaled_twist(p, radius_m);
    const RowPrediction& q = predictions[i];
    if (!wm || !(t.norm() > 0.0) || !q.twist.allFinite()) continue;
    const Eigen::Vector3d wp(q.wrench.Fx, q.wrench.Fy, q.wrench.Mz / radius_m);
    motion.push_back(kDeg * angle_between(q.twist, t));
    error.push_back((wp - *wm).norm() / wm->norm());
    force_angle.push_back(kDeg * angle_between(wp, *wm));
  }
  PredictionScores s;
  s.rows = static_cast<int>(motion.size());
  s.median_motion_angle_deg = median(motion);
  s.mean_motion_angle_deg = mean(motion);
  s.median_force_error = median(error);
  s.mean_force_error = mean(error);
  s.median_force_angle_deg = median(force_angle);
  return s;
}

double prediction_error(const MeasuredData& data, const std::vector<Resultants<double>>& model,
                        double radius_m) {
  if (model.size() != data.points.size())
    throw InvalidArgument(
        "predictions", std::to_string(model.size()),
        "must be one a row of the data (" + std::to_string(data.points.size()) + ")");
  require_positive("radius", radius_m);
  std::array<double, kChannels> ss{}, peak{};
  std::array<int, kChannels> n{};
  for (std::size_t i = 0; i < model.size(); ++i)
    for (int c = 0; c < kChannels; ++c)
      if (const std::optional<double>& y = data.points[i].force[c]) {
        ss[c] += std::pow(*y - model[i].vector()(c), 2);
        peak[c] = std::max(peak[c], std::abs(*y));
        ++n[c];
      }
  const double force = std::max({peak[0], peak[1], peak[2] / radius_m});
  double err2 = 0.0;
  int channels = 0;
  for (int c = 0; c < kChannels; ++c) {
    const double magnitude = std::max(peak[c], 1e-3 * force * (c == 2 ? radius_m : 1.0));
    if (n[c] == 0 || !(magnitude > 0.0)) continue;
    err2 += ss[c] / n[c] / (magnitude * magnitude);
    ++channels;
  }
  return channels > 0 ? std::sqrt(err2 / channels) : kNaN;
}

std::vector<Resultants<double>> wrenches_of(const std::vector<RowPrediction>& predictions) {
  std::vector<Resultants<double>> out;
  out.reserve(predictions.size());
  for (const RowPrediction& p : predictions) out.push_back(p.wrench);
  return out;
}

namespace {

// The group of each row: its sweep, or its value of a recorded column.
std::vector<std::vector<std::size_t>> row_groups(const MeasuredData& data, double radius_m,
                                                 const std::string& column) {
  std::vector<std::vector<std::size_t>> groups;
  if (column.empty()) {
    for (const Sweep& s : sweeps_of(data, radius_m)) groups.push_back(s.points);
    return groups;
  }
  int k = -1;
  for (std::size_t j = 0; j < data.recorded.size(); ++j)
    if (data.recorded[j].name == column || data.recorded[j].header == column)
      k = static_cast<int>(j);
  if (k < 0)
    throw InvalidArgument("group column", column, "is not a recorded column of " + data.source);
  std::map<double, std::vector<std::size_t>> by_value;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const double v = data.points[i].recorded[static_cast<std::size_t>(k)];
    by_value[std::isfinite(v) ? v : -std::numeric_limits<double>::infinity()].push_back(i);
  }
  for (auto& [value, rows] : by_value) groups.push_back(std::move(rows));
  return groups;
}

MeasuredData rows_of(const MeasuredData& data, const std::vector<char>& take) {
  MeasuredData out = data;
  out.points.clear();
  for (std::size_t i = 0; i < data.points.size(); ++i)
    if (take[i]) out.points.push_back(data.points[i]);
  return out;
}

}  // namespace

HoldoutSplit holdout_split(const MeasuredData& data, double radius_m, double fraction,
                           const std::string& group_column, unsigned seed) {
  if (!(fraction > 0.0 && fraction <= 0.9))
    throw InvalidArgument("holdout fraction", format_value(fraction), "must lie in (0, 0.9]");
  std::vector<std::vector<std::size_t>> groups = row_groups(data, radius_m, group_column);
  // Fisher-Yates on std::mt19937_64's raw draws: the same split with every standard library.
  std::mt19937_64 rng(seed);
  for (std::size_t i = groups.size(); i > 1; --i) std::swap(groups[i - 1], groups[rng() % i]);
  const double target = fraction * static_cast<double>(data.points.size());
  std::vector<char> held(data.points.size(), 0);
  HoldoutSplit split;
  split.groups = static_cast<int>(groups.size());
  split.grouped_by = group_column.empty() ? "sweeps" : group_column;
  // A group that would take the held-out part past 1.25 times the target is passed over, so
  // that one large sweep does not swallow the fit's rows; the smallest group if none fits.
  std::size_t taken = 0;
  const auto take = [&](const std::vector<std::size_t>& g) {
    for (std::size_t i : g) held[i] = 1;
    taken += g.size();
    ++split.held_groups;
  };
  for (const std::vector<std::size_t>& g : groups) {
    if (static_cast<double>(taken) >= target) break;
    if (static_cast<double>(taken + g.size()) <= 1.25 * target) take(g);
  }
  if (taken == 0 && !groups.empty())
    take(*std::min_element(groups.begin(), groups.end(),
                           [](const auto& a, const auto& b) { return a.size() < b.size(); }));
  if (taken == 0 || taken == data.points.size())
    throw InvalidArgument("holdout fraction", format_value(fraction),
                          "leaves no rows on one side: the data have " +
                              std::to_string(groups.size()) + " groups (" + split.grouped_by +
                              ") of " + std::to_string(data.points.size()) + " rows");
  std::vector<char> fit(held.size());
  for (std::size_t i = 0; i < held.size(); ++i) fit[i] = !held[i];
  split.fit = rows_of(data, fit);
  split.held_out = rows_of(data, held);
  return split;
}

namespace {

std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

std::string cell(const std::optional<double>& v) {
  return v ? cell(*v) : std::string();
}

}  // namespace

std::string predictions_csv(const MeasuredData& data, const std::vector<RowPrediction>& pred) {
  if (pred.size() != data.points.size())
    throw InvalidArgument(
        "predictions", std::to_string(pred.size()),
        "must be one a row of the data (" + std::to_string(data.points.size()) + ")");
  std::string s =
      "source,line,vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm,pred_Fx_N,pred_Fy_N,pred_Mz_Nm,"
      "pred_twist_vx,pred_twist_vy,pred_twist_omegaR,wrench_misfit_deg\n";
  for (std::size_t i = 0; i < pred.size(); ++i) {
    const MeasuredPoint& p = data.points[i];
    const RowPrediction& q = pred[i];
    std::string file = static_cast<std::size_t>(p.source) < data.sources.size()
                           ? data.sources[static_cast<std::size_t>(p.source)]
                           : data.source;
    for (char& c : file)
      if (c == ',' || c == '"' || c == '\n' || c == '\r') c = '_';  // one cell, always
    s += file + "," + std::to_string(p.line) + "," + cell(p.kinematics.vx) + "," +
         cell(p.kinematics.vy) + "," + cell(p.kinematics.omega) + "," + cell(p.force[0]) + "," +
         cell(p.force[1]) + "," + cell(p.force[2]) + "," + cell(q.wrench.Fx) + "," +
         cell(q.wrench.Fy) + "," + cell(q.wrench.Mz) + "," + cell(q.twist[0]) + "," +
         cell(q.twist[1]) + "," + cell(q.twist[2]) + "," + cell(kDeg * q.wrench_misfit_rad) + "\n";
  }
  return s;
}

std::string prediction_scores_text(const PredictionScores& s) {
  if (s.rows == 0)
    return "no row has all three channels and some motion: nothing to score the predictions on\n";
  char b[400];
  std::snprintf(b, sizeof b,
                "motion from the force: median angle %.3g deg (mean %.3g deg) between predicted "
                "and measured (vx, vy, omega R), over %d rows\n"
                "force from the motion: median relative error %.3g (mean %.3g) of (Fx, Fy, Mz/R), "
                "median angle %.3g deg\n",
                s.median_motion_angle_deg, s.mean_motion_angle_deg, s.rows, s.median_force_error,
                s.mean_force_error, s.median_force_angle_deg);
  return b;
}

}  // namespace contensou
