#include "sensitivity.hpp"

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include "contensou/gear/linear_stability.hpp"

namespace contensou::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kSpeeds[] = {45.0, 58.0, 70.0};  // m/s: the braked slide's boundary is lowest
                                                  // near 55-60 m/s on the default gear

double braked_growth(GearModel m, double offset, double speed) {
  m.config.structure.offset_m = offset;
  m.config.scenario.forward_speed_mps = speed;
  return linear_growth_rate(m, StabilityPhase::braked_slide);
}

// The lowest offset in [0, 1] m where the braked slide is unstable at `speed`: a scan in steps
// of 0.05 m, then bisection to 1e-4 m; NaN if stable throughout.
double lowest_unstable_offset(const GearModel& m, double speed) {
  double lo = 0.0;
  if (braked_growth(m, lo, speed) > 0.0) return 0.0;
  for (int k = 1; k <= 20; ++k) {
    const double hi = 0.05 * k;
    if (braked_growth(m, hi, speed) > 0.0) {
      double a = lo, b = hi;
      while (b - a > 1e-4) {
        const double mid = 0.5 * (a + b);
        (braked_growth(m, mid, speed) > 0.0 ? b : a) = mid;
      }
      return 0.5 * (a + b);
    }
    lo = hi;
  }
  return kNaN;
}

SensitivityRow assess(const GearModel& m, const std::string& change) {
  SensitivityRow r;
  r.model = to_string(m.contact);
  r.change = change;
  r.critical_damping_nms_per_rad =
      m.contact == ContactModel::von_schlippe ? classical_critical_damping(m) : kNaN;
  r.braked_growth_per_s = linear_growth_rate(m, StabilityPhase::braked_slide);
  r.boundary_offset_m = kNaN;
  for (const double v : kSpeeds) {
    const double l = lowest_unstable_offset(m, v);
    if (std::isfinite(l) && !(l >= r.boundary_offset_m)) {
      r.boundary_offset_m = l;
      r.boundary_speed_mps = v;
    }
  }
  return r;
}

}  // namespace

std::vector<SensitivityRow> classical_sensitivity(const ShimmyConfig& config,
                                                  const TireInput* tire) {
  const GearModel base = gear_model(config, ContactModel::von_schlippe, tire);
  const RollingTire& rt = base.config.rolling;
  // The half contact length a = R at the static load (theory.md section 4: N = 2 pi R^2 p* A^1).
  const double R =
      std::sqrt(config.gear.scenario.static_load_n /
                (2.0 * std::numbers::pi * config.gear.tire.inflation_pressure_pa * base.moment_1));
  char buf[96];
  std::vector<std::pair<std::string, std::function<void(GearConfig&)>>> variants;
  variants.emplace_back("as configured", [](GearConfig&) {});
  std::snprintf(buf, sizeof buf, "sigma = %.3g m (= R)", R);
  variants.emplace_back(buf, [R](GearConfig& c) { c.rolling.relaxation_length_m = R; });
  std::snprintf(buf, sizeof buf, "sigma = %.3g m (x2)", 2 * rt.relaxation_length_m);
  variants.emplace_back(buf, [](GearConfig& c) { c.rolling.relaxation_length_m *= 2.0; });
  std::snprintf(buf, sizeof buf, "C_x = %.3g (= C_Fa)", rt.cornering_coefficient);
  variants.emplace_back(buf, [](GearConfig& c) {
    c.rolling.longitudinal_slip_coefficient = c.rolling.cornering_coefficient;
  });
  std::snprintf(buf, sizeof buf, "C_x = %.3g (x2)", 2 * rt.longitudinal_slip_coefficient);
  variants.emplace_back(buf, [](GearConfig& c) { c.rolling.longitudinal_slip_coefficient *= 2.0; });
  variants.emplace_back("C_Ma = 0 (no pneumatic trail)",
                        [](GearConfig& c) { c.rolling.aligning_coefficient_m = 0.0; });
  std::snprintf(buf, sizeof buf, "C_Ma = %.3g m/rad (x2)", 2 * rt.aligning_coefficient_m);
  variants.emplace_back(buf, [](GearConfig& c) { c.rolling.aligning_coefficient_m *= 2.0; });
  std::snprintf(buf, sizeof buf, "C_Fa = %.3g /rad (x0.5, same trail)",
                0.5 * rt.cornering_coefficient);
  variants.emplace_back(buf, [](GearConfig& c) {
    c.rolling.cornering_coefficient *= 0.5;
    c.rolling.aligning_coefficient_m *= 0.5;
  });
  std::snprintf(buf, sizeof buf, "C_Fa = %.3g /rad (x2, same trail)", 2 * rt.cornering_coefficient);
  variants.emplace_back(buf, [](GearConfig& c) {
    c.rolling.cornering_coefficient *= 2.0;
    c.rolling.aligning_coefficient_m *= 2.0;
  });
  variants.emplace_back("kappa_t = 0 (no tread moment)",
                        [](GearConfig& c) { c.rolling.tread_moment_nm2_per_rad = 0.0; });
  // The longitudinal relaxation (every model's; landing_gear.hpp, SlidingTire).
  const double sigma_x = base.config.tire.longitudinal_relaxation_length_m;
  variants.emplace_back("sigma_x = 0 (no longitudinal relaxation)",
                        [](GearConfig& c) { c.tire.longitudinal_relaxation_length_m = 0.0; });
  if (sigma_x > 0.0) {
    std::snprintf(buf, sizeof buf, "sigma_x = %.3g m (x2)", 2 * sigma_x);
    variants.emplace_back(buf,
                          [](GearConfig& c) { c.tire.longitudinal_relaxation_length_m *= 2.0; });
  }
  std::vector<SensitivityRow> rows;
  for (const auto& [change, apply] : variants) {
    GearModel m = base;
    apply(m.config);
    rows.push_back(assess(m, change));
  }
  rows.push_back(
      assess(gear_model(config, ContactModel::coupled, tire), "reference, as configured"));
  return rows;
}

void report_sensitivity(const std::vector<SensitivityRow>& rows, nlohmann::json& summary) {
  std::printf(
      "\nthe classical verdict against the classical tire's assumed numbers (eigenvalues; one "
      "change at a time):\n%-13s %-36s %16s %14s %22s\n",
      "model", "change", "crit. damp. td", "braked [1/s]", "lowest unstable l [m]");
  nlohmann::json out = nlohmann::json::array();
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  for (const SensitivityRow& r : rows) {
    char crit[32] = "-", bound[48] = "none up to 1 m";
    if (std::isfinite(r.critical_damping_nms_per_rad))
      std::snprintf(crit, sizeof crit, "%.1f", r.critical_damping_nms_per_rad);
    if (std::isfinite(r.boundary_offset_m))
      std::snprintf(bound, sizeof bound, "%.3f (at %.0f m/s)", r.boundary_offset_m,
                    r.boundary_speed_mps);
    std::printf("%-13s %-36s %16s %14.3f %22s\n", r.model.c_str(), r.change.c_str(), crit,
                r.braked_growth_per_s, bound);
    out.push_back({{"model", r.model},
                   {"change", r.change},
                   {"touchdown_critical_damping_nms_per_rad", num(r.critical_damping_nms_per_rad)},
                   {"braked_slide_growth_rate_per_s", num(r.braked_growth_per_s)},
                   {"lowest_unstable_offset_m", num(r.boundary_offset_m)},
                   {"at_forward_speed_mps", std::isfinite(r.boundary_offset_m)
                                                ? nlohmann::json(r.boundary_speed_mps)
                                                : nlohmann::json()}});
  }
  std::printf("(speeds tried for the offset boundary: 45, 58 and 70 m/s)\n");
  summary["classical_sensitivity"] = out;
}

}  // namespace contensou::app
