// What the data can determine before any fit (data_checks.hpp).
#include "contensou/identification/data_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "contensou/friction/coulomb_envelope.hpp"
#include "contensou/friction/error.hpp"

namespace contensou {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDeg = 180.0 / std::numbers::pi;

double value_or_nan(const std::optional<double>& v) {
  return v ? *v : kNaN;
}

// The median of `x` and its distribution-free 95 % interval: the order statistics at ranks
// n/2 -+ 1.96 sqrt(n)/2 (the binomial's normal approximation).
void median_interval(std::vector<double> x, double* median, double* low, double* high) {
  if (x.empty()) {
    *median = *low = *high = kNaN;
    return;
  }
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  const auto at = [&](double rank) {
    const long i = std::clamp(static_cast<long>(std::lround(rank)), 0L, static_cast<long>(n) - 1);
    return x[static_cast<std::size_t>(i)];
  };
  const std::size_t m = x.size();
  *median = m % 2 ? x[m / 2] : 0.5 * (x[m / 2 - 1] + x[m / 2]);
  *low = at(std::floor(n / 2 - 1.96 * std::sqrt(n) / 2) - 1);
  *high = at(std::ceil(n / 2 + 1.96 * std::sqrt(n) / 2) - 1);
}

std::string percent(int part, int whole) {
  char b[48];
  std::snprintf(b, sizeof b, "%d of %d rows (%.0f %%)", part, whole,
                whole > 0 ? 100.0 * part / whole : 0.0);
  return b;
}

void add_findings(DataChecks& c) {
  const auto share = [](int part, int whole) {
    return whole > 0 && static_cast<double>(part) / whole >= kFindingShare;
  };
  if (share(c.above_any_patch, c.ratio_rows))
    c.findings.push_back(
        percent(c.above_any_patch, c.ratio_rows) +
        " with 1 < |v|/(|omega| R) < 10 carry more torque than any pressure on a patch of this "
        "radius can (|Mz| > |F| R): the radius is too small, or the torque is not only the "
        "patch's friction");
  if (share(c.above_axisymmetric, c.ratio_rows))
    c.findings.push_back(
        percent(c.above_axisymmetric, c.ratio_rows) +
        " with 1 < |v|/(|omega| R) < 10 carry more torque than any pressure centred on the "
        "patch can (a ring at the rim): the torque is set by something besides a centred patch "
        "(the pressure off the centre, or a torque from outside the contact, such as a pusher or "
        "a support), and a law of a centred patch cannot fit these rows; the spin-sliding "
        "coupling cannot be identified from them without a model of that");
  if (share(c.drives_spin, c.sign_rows))
    c.findings.push_back(percent(c.drives_spin, c.sign_rows) +
                         " with spin have a torque that drives the spin, which a centred patch "
                         "never gives: the centre of pressure is off the centre, or the torque "
                         "is not only friction");
  if (share(c.angle_outside, c.angle_rows))
    c.findings.push_back(percent(c.angle_outside, c.angle_rows) +
                         " with |v| > |omega| R have a force turned from -v by more than any "
                         "isotropic patch of this radius allows (asin(|omega| R / |v|)): "
                         "friction differs with direction, or the motion is misread");
  if (c.rows > 0 && c.coupling_rows < std::max(10, c.rows / 10))
    c.findings.push_back(
        percent(c.coupling_rows, c.rows) +
        " lie where sliding and spin are of one size (0.1 <= |v|/(|omega| R) <= 10): the "
        "coupling's shape (a, m, the profile) is hardly determined");
}

}  // namespace

bool DataChecks::angle_offset_shown() const {
  return sliding_rows > 0 && (median_angle_low_deg > 0.0 || median_angle_high_deg < 0.0);
}

DataChecks check_data(const MeasuredData& data, double radius_m) {
  require_positive("radius", radius_m);
  DataChecks c;
  EnvelopeCheckOptions o;
  o.angle_margin_rad = kCheckMargin;
  o.ratio_margin = kCheckMargin;
  o.min_spin_fraction = 0.1;
  std::vector<double> angles;
  for (const MeasuredPoint& p : data.points) {
    const RowEnvelopeCheck r =
        check_row_against_patches(p.kinematics, value_or_nan(p.force[0]), value_or_nan(p.force[1]),
                                  value_or_nan(p.force[2]), radius_m, o);
    if (r.at_rest) continue;
    ++c.rows;
    c.coupling_rows += r.eps >= 0.1 && r.eps <= 10.0;
    if (r.angle_checked && r.eps > 1.0) {
      ++c.angle_rows;
      c.angle_outside += std::abs(r.force_angle_rad) > r.force_angle_bound_rad + kCheckMargin;
    }
    if (r.angle_checked && r.eps > 3.0) angles.push_back(kDeg * r.force_angle_rad);
    if (r.torque_ratio_checked && r.eps > 1.0 && r.eps < 10.0) {
      ++c.ratio_rows;
      c.above_axisymmetric += r.above_axisymmetric_torque;
      c.above_any_patch += r.torque_ratio > r.any_patch_torque_bound * (1.0 + kCheckMargin);
    }
    if (r.torque_sign_checked) {
      ++c.sign_rows;
      c.drives_spin += r.torque_drives_spin;
    }
  }
  c.sliding_rows = static_cast<int>(angles.size());
  median_interval(angles, &c.median_angle_deg, &c.median_angle_low_deg, &c.median_angle_high_deg);
  add_findings(c);
  return c;
}

std::string data_checks_text(const DataChecks& c) {
  char b[900];
  std::snprintf(
      b, sizeof b,
      "what the data can determine (each row against every rigid Coulomb patch of radius R, "
      "before any fit; a row counts as outside a bound beyond it by %.0f %%):\n"
      "  rows where sliding and spin are of one size (0.1 <= |v|/(|omega| R) <= 10): %s\n"
      "  torque above the most a centred patch gives (rim ring), 1 < |v|/(|omega| R) < 10: %s\n"
      "  torque above the most any patch gives (|F| R), same rows: %s\n"
      "  torque that drives the spin: %s\n"
      "  force turned from -v beyond what any patch allows: %s\n",
      100 * kCheckMargin, percent(c.coupling_rows, c.rows).c_str(),
      percent(c.above_axisymmetric, c.ratio_rows).c_str(),
      percent(c.above_any_patch, c.ratio_rows).c_str(), percent(c.drives_spin, c.sign_rows).c_str(),
      percent(c.angle_outside, c.angle_rows).c_str());
  std::string s = b;
  if (c.sliding_rows > 0) {
    std::snprintf(b, sizeof b,
                  "  force angle to -v where sliding dominates (|v| > 3 |omega| R): median %+.2f "
                  "deg, 95 %% interval [%+.2f, %+.2f] over %d rows: %s\n",
                  c.median_angle_deg, c.median_angle_low_deg, c.median_angle_high_deg,
                  c.sliding_rows,
                  c.angle_offset_shown()
                      ? "the force is turned, as a slip-angle offset or anisotropy would turn it"
                      : "no turn a slip-angle offset would show");
    s += b;
  }
  for (const std::string& f : c.findings) s += "  the data say: " + f + "\n";
  return s;
}

}  // namespace contensou
