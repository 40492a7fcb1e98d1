// The rigid patch that predicts the motion from the force (rigid_patch.hpp).
#include "contensou/identification/rigid_patch.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>
#include <thread>
#include <tuple>

#include "contensou/friction/error.hpp"
#include "run_blocks.hpp"

namespace contensou {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The rows the search scores: all three channels, some motion and some force.
struct PairRows {
  std::vector<Eigen::Vector3d> twist;   // (vx, vy, omega) [SI]
  std::vector<Eigen::Vector3d> wrench;  // (Fx, Fy, Mz) [N, N, N m]
};

PairRows pair_rows(const MeasuredData& data, double radius_m) {
  PairRows out;
  for (const MeasuredPoint& p : data.points) {
    if (!p.force[0] || !p.force[1] || !p.force[2]) continue;
    const Eigen::Vector3d t(p.kinematics.vx, p.kinematics.vy, p.kinematics.omega);
    const Eigen::Vector3d w(*p.force[0], *p.force[1], *p.force[2]);
    const Eigen::Vector3d ts(t.x(), t.y(), t.z() * radius_m), ws(w.x(), w.y(), w.z() / radius_m);
    if (!(ts.norm() > 0.0) || !(ws.norm() > 0.0) || !ts.allFinite() || !ws.allFinite()) continue;
    out.twist.push_back(t);
    out.wrench.push_back(w);
  }
  return out;
}

// At most `n` of the rows, spread evenly.
PairRows spread(const PairRows& rows, int n) {
  const std::size_t all = rows.twist.size();
  if (all <= static_cast<std::size_t>(n)) return rows;
  PairRows out;
  for (int k = 0; k < n; ++k) {
    const std::size_t i = static_cast<std::size_t>(k) * all / static_cast<std::size_t>(n);
    out.twist.push_back(rows.twist[i]);
    out.wrench.push_back(rows.wrench[i]);
  }
  return out;
}

double angle_rad(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

Eigen::Vector3d scaled_unit(const Eigen::Vector3d& twist, double radius_m) {
  return Eigen::Vector3d(twist.x(), twist.y(), twist.z() * radius_m).normalized();
}

// The surface of the patch's shape on a disk of radius c R, unchecked (c > 1 allowed: the wider
// contacts of WiderContact), at force scale f N.
LimitSurface shape_surface(const RigidPatch& p, double tolerance) {
  PressureProfile profile = power_profile(p.exponent);
  profile.kx = p.kx;
  profile.ky = p.ky;
  const ContactPatch patch = ContactPatch::from_normal_load(p.contact_radius_ratio * p.radius_m,
                                                            p.force_scale_n, profile, 1.0);
  return make_limit_surface(patch, tolerance);
}

// The median angle [rad] between the motion the surface gives each row's wrench and its motion
// (a row the surface cannot place counts as pi).
// The rows on up to 8 threads (one a core), each its own rows i = w, w + T, ...: each row's
// angle is the same whatever the threads (the surface is only read).
double median_angle(const LimitSurface& surface, double radius_m, const PairRows& rows) {
  std::vector<double> angles(rows.twist.size());
  const auto angle_of = [&](std::size_t i) {
    const Eigen::Vector3d m = rigid_patch_motion(surface, radius_m, rows.wrench[i]);
    const double a = angle_rad(m, scaled_unit(rows.twist[i], radius_m));
    angles[i] = std::isfinite(a) ? a : std::numbers::pi;
  };
  const std::size_t threads = std::min<std::size_t>(
      {std::max(1u, std::thread::hardware_concurrency()), 8, angles.size() / 32 + 1});
  detail::run_blocks(threads, [&](std::size_t w) {
    for (std::size_t i = w; i < angles.size(); i += threads) angle_of(i);
  });
  const std::size_t mid = angles.size() / 2;
  std::nth_element(angles.begin(), angles.begin() + static_cast<std::ptrdiff_t>(mid), angles.end());
  double median = angles[mid];
  if (angles.size() % 2 == 0)
    median = 0.5 * (median + *std::max_element(angles.begin(),
                                               angles.begin() + static_cast<std::ptrdiff_t>(mid)));
  return median;
}

double median_angle(const RigidPatch& patch, const PairRows& rows, double tolerance) {
  return median_angle(limit_surface_of(patch, tolerance), patch.radius_m, rows);
}

void check_options(const RigidPatchOptions& o) {
  if (o.exponents.empty() || o.shifts.empty() || o.radius_ratios.empty())
    throw InvalidArgument("RigidPatchOptions", "an empty grid",
                          "exponents, shifts and radius_ratios need a value each");
  if (o.passes < 1) throw InvalidArgument("passes", std::to_string(o.passes), "must be >= 1");
  if (o.max_rows < 3) throw InvalidArgument("max_rows", std::to_string(o.max_rows), "must be >= 3");
  if (!(o.tolerance >= 1e-14 && o.tolerance <= 1e-6))
    throw InvalidArgument("tolerance", format_value(o.tolerance), "must be in [1e-14, 1e-6]");
  RigidPatch probe;
  probe.radius_m = 1.0;
  for (int n : o.exponents) {
    probe.exponent = n;
    validate(probe);
  }
  probe.exponent = 0;
  for (double c : o.radius_ratios) {
    probe.contact_radius_ratio = c;
    validate(probe);
  }
  for (double k : o.shifts)
    if (!(std::abs(k) <= 1.0))
      throw InvalidArgument("shifts", format_value(k), "must be in [-1, 1]");
  for (double c : o.wider_radius_ratios)
    if (!(c > 1.0 && c <= 10.0))
      throw InvalidArgument("wider_radius_ratios", format_value(c), "must be in (1, 10]");
  if (!(o.wider_margin >= 0.0 && o.wider_margin < 1.0))
    throw InvalidArgument("wider_margin", format_value(o.wider_margin), "must be in [0, 1)");
}

// The best contact wider than the body (WiderContact) when the search ended on c = 1 and one
// places the motions better by more than the margin; none otherwise.
std::optional<WiderContact> wider_contact(const RigidPatch& best, double best_angle,
                                          const PairRows& rows, const RigidPatchOptions& o) {
  if (best.contact_radius_ratio != 1.0) return std::nullopt;
  WiderContact w;
  double least = best_angle;
  for (int n : o.exponents)
    for (double c : o.wider_radius_ratios) {
      RigidPatch p = best;
      p.exponent = n;
      p.contact_radius_ratio = c;
      const double a = median_angle(shape_surface(p, o.tolerance), p.radius_m, rows);
      if (a < least) {
        least = a;
        w = {c, n, a * 180.0 / std::numbers::pi};
      }
    }
  if (!(least < (1.0 - o.wider_margin) * best_angle)) return std::nullopt;
  return w;
}

// The coordinate search (header comment of rigid_patch.hpp): the grid value with the least
// median angle, one coordinate after the other, each combination scored once.
class Search {
 public:
  Search(const PairRows& rows, double radius_m, const RigidPatchOptions& o) : rows_(rows), o_(o) {
    best_.radius_m = radius_m;
    best_angle_ = score(best_);
  }
  void pass() {
    // n and c together: both move load towards or away from the rim, and trade off.
    for (int n : o_.exponents)
      for (double c : o_.radius_ratios)
        consider([&](RigidPatch& p) {
          p.exponent = n;
          p.contact_radius_ratio = c;
        });
    for (double kx : o_.shifts)
      for (double ky : o_.shifts)
        if (kx * kx + ky * ky <= 1.0)
          consider([&](RigidPatch& p) {
            p.kx = kx;
            p.ky = ky;
          });
  }
  const RigidPatch& best() const { return best_; }
  double best_angle() const { return best_angle_; }

 private:
  template <class Change>
  void consider(Change change) {
    RigidPatch p = best_;
    change(p);
    const double a = score(p);
    if (a < best_angle_) {
      best_ = p;
      best_angle_ = a;
    }
  }
  double score(const RigidPatch& p) {
    const auto key = std::make_tuple(p.exponent, p.kx, p.ky, p.contact_radius_ratio);
    const auto it = seen_.find(key);
    if (it != seen_.end()) return it->second;
    return seen_[key] = median_angle(p, rows_, o_.tolerance);
  }
  const PairRows& rows_;
  const RigidPatchOptions& o_;
  RigidPatch best_;
  double best_angle_ = 0.0;
  std::map<std::tuple<int, double, double, double>, double> seen_;
};

// f N by least squares of the measured scaled wrenches on the patch's at unit force scale.
double force_scale(RigidPatch patch, const PairRows& rows) {
  patch.force_scale_n = 1.0;
  const LimitSurface surface = limit_surface_of(patch, 1e-8);
  const double R = patch.radius_m;
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < rows.twist.size(); ++i) {
    const Eigen::Vector3d m = rigid_patch_wrench(surface, rows.twist[i]);
    const Eigen::Vector3d ms(m.x(), m.y(), m.z() / R);
    const Eigen::Vector3d ws(rows.wrench[i].x(), rows.wrench[i].y(), rows.wrench[i].z() / R);
    num += ws.dot(ms);
    den += ms.squaredNorm();
  }
  if (!(num > 0.0 && den > 0.0) || !std::isfinite(num / den))
    throw InvalidArgument(
        "data", "forces that do not oppose the motion",
        "the rigid patch needs rows whose friction opposes the motion on the whole");
  return num / den;
}

}  // namespace

void validate(const RigidPatch& p) {
  if (!(p.radius_m > 0.0) || !std::isfinite(p.radius_m))
    throw InvalidArgument("radius_m", format_value(p.radius_m), "must be positive and finite");
  if (!(p.contact_radius_ratio > 0.0 && p.contact_radius_ratio <= 1.0))
    throw InvalidArgument("contact_radius_ratio", format_value(p.contact_radius_ratio),
                          "must be in (0, 1]: the contact lies inside the body");
  if (p.exponent < 0 || p.exponent > kMaxPowerProfileExponent || p.exponent % 2 != 0)
    throw InvalidArgument("exponent", std::to_string(p.exponent),
                          "must be even, in [0, " + std::to_string(kMaxPowerProfileExponent) + "]");
  if (!(p.kx * p.kx + p.ky * p.ky <= 1.0))
    throw InvalidArgument("kx, ky", format_value(p.kx) + ", " + format_value(p.ky),
                          "kx^2 + ky^2 must be <= 1 (else the pressure is negative at the rim)");
  if (!(p.force_scale_n > 0.0) || !std::isfinite(p.force_scale_n))
    throw InvalidArgument("force_scale_N", format_value(p.force_scale_n),
                          "must be positive and finite");
}

Eigen::Vector2d centre_of_pressure_m(const RigidPatch& p) {
  validate(p);
  // x_c = kx a A^3 / (2 A^1), A^j = 1 / (n + j + 1) for p = rho^n.
  const double a = p.contact_radius_ratio * p.radius_m;
  const double arm = a * (p.exponent + 2.0) / (2.0 * (p.exponent + 4.0));
  return {p.kx * arm, p.ky * arm};
}

LimitSurface limit_surface_of(const RigidPatch& p, double tolerance) {
  validate(p);
  return shape_surface(p, tolerance);
}

Eigen::Vector3d rigid_patch_wrench(const LimitSurface& surface, const Eigen::Vector3d& twist) {
  if (!(twist.norm() > 0.0)) return Eigen::Vector3d::Zero();
  return -dissipation_with_derivatives(surface, twist).gradient;  // grad D = -wrench
}

Eigen::Vector3d rigid_patch_motion(const LimitSurface& surface, double body_radius_m,
                                   const Eigen::Vector3d& wrench) {
  if (!wrench.allFinite() || !(wrench.norm() > 0.0)) return Eigen::Vector3d::Constant(kNaN);
  // The boundary point w / g has outward normal n = grad D^-1: the patch sliding with -n has
  // friction w / g (limit_surface.hpp).
  const Eigen::Vector3d n = -gauge(surface, wrench).normal;
  return scaled_unit(n, body_radius_m);
}

RigidPatch fit_rigid_patch(const MeasuredData& data, double radius_m,
                           const RigidPatchOptions& options) {
  require_positive("radius_m", radius_m);
  check_options(options);
  const PairRows all = pair_rows(data, radius_m);
  if (all.twist.size() < 3)
    throw InvalidArgument("data", std::to_string(all.twist.size()) + " rows with Fx, Fy, Mz",
                          "the rigid patch needs at least 3 rows with all three channels, some "
                          "motion and some force");
  const PairRows rows = spread(all, options.max_rows);
  Search search(rows, radius_m, options);
  for (int k = 0; k < options.passes; ++k) search.pass();
  RigidPatch out = search.best();
  out.median_angle_deg = search.best_angle() * 180.0 / std::numbers::pi;
  out.rows = static_cast<int>(rows.twist.size());
  out.wider_contact = wider_contact(out, search.best_angle(), rows, options);
  out.force_scale_n = force_scale(out, all);
  return out;
}

std::string rigid_patch_text(const RigidPatch& p) {
  const Eigen::Vector2d cop = centre_of_pressure_m(p);
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "p ~ (r/a)^%d (1 %+.2g x/a %+.2g y/a) on a = %.2g R = %.4g mm; centre of pressure "
                "(%+.3g, %+.3g) mm; f N = %.4g N; motion from the force: median angle %.3g deg "
                "over the %d rows it was chosen on",
                p.exponent, p.kx, p.ky, p.contact_radius_ratio,
                1e3 * p.contact_radius_ratio * p.radius_m, 1e3 * cop.x(), 1e3 * cop.y(),
                p.force_scale_n, p.median_angle_deg, p.rows);
  std::string out = buf;
  if (p.wider_contact) {
    const WiderContact& w = *p.wider_contact;
    std::snprintf(buf, sizeof buf,
                  "; the search ends on its bound a = R (no contact is wider than the body): a "
                  "contact of %.2g R with n = %d, wider than the body, would place the motions "
                  "with a median angle of %.3g deg",
                  w.radius_ratio, w.exponent, w.median_angle_deg);
    out += std::string(buf) +
           ": the data carry more torque for their spin than any pressure under the body "
           "gives (the torque or the spin as measured, or a torque from outside the contact "
           "such as a pusher's friction); the motion predicted stays this patch's";
  }
  return out;
}

}  // namespace contensou
