#include "contensou/friction/coulomb_envelope.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "contensou/friction/error.hpp"

namespace contensou {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Throws InvalidArgument unless eps is >= 0 (+inf allowed).
void require_ratio(const char* name, double eps) {
  if (!(eps >= 0.0)) throw InvalidArgument(name, format_value(eps), "must be >= 0 (+inf allowed)");
}

// J(k) = int_0^{pi/2} cos^2 t / sqrt(1 - k^2 sin^2 t) dt = (E - (1 - k^2) K) / k^2, 0 <= k <= 1.
// Below k = 0.5 the difference cancels (E - (1 - k^2) K = O(k^2)): the series
// J = (pi/2) sum_n c_n^2 k^{2n} / (2n + 2), c_n = (2n)! / (4^n n!^2), converges as 4^-n there.
double j_integral(double k) {
  if (k >= 1.0) return 1.0;
  if (k >= 0.5) return (std::comp_ellint_2(k) - (1.0 - k * k) * std::comp_ellint_1(k)) / (k * k);
  const double k2 = k * k;
  double c = 1.0, power = 1.0, sum = 0.0;
  for (int n = 0; n < 60; ++n) {
    if (n > 0) c *= (2.0 * n - 1.0) / (2.0 * n);
    const double term = c * c * power / (2.0 * n + 2.0);
    sum += term;
    if (term < 1e-18 * sum) break;
    power *= k2;
  }
  return 0.5 * kPi * sum;
}

// E(k) of modulus k, with E(1) = 1.
double e_integral(double k) {
  return k >= 1.0 ? 1.0 : std::comp_ellint_2(k);
}

// Throws InvalidArgument naming a channel that is infinite (NaN: not measured, allowed).
void require_channel(const char* name, double value) {
  if (std::isinf(value))
    throw InvalidArgument(name, format_value(value),
                          "must be finite, or NaN for a channel not measured");
}

void validate_options(const EnvelopeCheckOptions& o) {
  require_non_negative("angle_margin_rad", o.angle_margin_rad);
  require_non_negative("ratio_margin", o.ratio_margin);
  require_non_negative("min_spin_fraction", o.min_spin_fraction);
}

// theta from v to -F, counter-clockwise positive.
double force_angle(const Kinematics<double>& k, double Fx, double Fy) {
  return std::atan2(-(k.vx * Fy - k.vy * Fx), -(k.vx * Fx + k.vy * Fy));
}

// The force and torque checks of a row with its bounds already set (header, points 1-3).
void check_channels(const Kinematics<double>& k, double Fx, double Fy, double Mz, double radius_m,
                    const EnvelopeCheckOptions& o, RowEnvelopeCheck& c) {
  const bool have_force = !std::isnan(Fx) && !std::isnan(Fy);
  const double force = have_force ? std::hypot(Fx, Fy) : 0.0;
  const double speed = std::hypot(k.vx, k.vy);
  if (have_force && force > 0.0 && speed > 0.0) {
    c.angle_checked = true;
    c.force_angle_rad = force_angle(k, Fx, Fy);
    if (std::abs(c.force_angle_rad) > c.force_angle_bound_rad + o.angle_margin_rad)
      c.outside_any_patch = true;
  }
  if (have_force && force > 0.0 && !std::isnan(Mz)) {
    c.torque_ratio_checked = true;
    c.torque_ratio = std::abs(Mz) / force / radius_m;  // two steps: no overflow of force R
    if (c.torque_ratio > c.any_patch_torque_bound * (1.0 + o.ratio_margin))
      c.outside_any_patch = true;
    c.above_axisymmetric_torque =
        c.torque_ratio > c.axisymmetric_torque_bound * (1.0 + o.ratio_margin);
  }
  if (!std::isnan(Mz) && k.omega != 0.0 &&
      std::abs(k.omega) * radius_m >= o.min_spin_fraction * speed) {
    c.torque_sign_checked = true;
    c.torque_drives_spin = (Mz > 0.0 && k.omega > 0.0) || (Mz < 0.0 && k.omega < 0.0);
  }
}

}  // namespace

double sliding_spin_ratio(const Kinematics<double>& k, double radius_m) {
  require_finite("vx", k.vx);
  require_finite("vy", k.vy);
  require_finite("omega", k.omega);
  require_positive("radius_m", radius_m);
  if (k.omega == 0.0) return kInf;
  return std::hypot(k.vx, k.vy) / std::abs(k.omega) / radius_m;
}

double force_angle_bound(double eps) {
  require_ratio("eps", eps);
  return eps > 1.0 ? std::asin(1.0 / eps) : kPi;
}

double any_patch_torque_ratio_bound(double eps) {
  require_ratio("eps", eps);
  return eps >= 1.0 ? 1.0 : kInf;
}

RingResultants ring_resultants(double s) {
  require_ratio("s", s);
  constexpr double c = 2.0 / kPi;
  if (s <= 1.0) return {c * s * j_integral(s), c * e_integral(s)};
  const double q = 1.0 / s;  // 0 at s = +inf: P = 1, Q = 0
  return {c * e_integral(q), c * q * j_integral(q)};
}

double ring_torque_ratio(double eps, double rho) {
  require_ratio("eps", eps);
  if (!(rho > 0.0) || !(rho <= 1.0))
    throw InvalidArgument("rho", format_value(rho), "must lie in (0, 1]");
  if (eps == 0.0) return kInf;
  if (std::isinf(eps)) return 0.0;
  // rho Q(s) / P(s), s = eps / rho, with the common factor 2/pi cancelled (header, point 2).
  if (rho >= eps) {
    const double s = eps / rho;
    return rho * e_integral(s) / (s * j_integral(s));
  }
  const double q = rho / eps;  // 1 / s
  return rho * q * j_integral(q) / e_integral(q);
}

double axisymmetric_torque_ratio_envelope(double eps) {
  require_ratio("eps", eps);
  if (eps == 0.0) return kInf;
  if (std::isinf(eps)) return 0.0;
  if (eps <= 1.0) return e_integral(eps) / (eps * j_integral(eps));
  const double q = 1.0 / eps;
  return j_integral(q) / (eps * e_integral(q));
}

RowEnvelopeCheck check_row_against_patches(const Kinematics<double>& k, double Fx, double Fy,
                                           double Mz, double radius_m,
                                           const EnvelopeCheckOptions& options) {
  RowEnvelopeCheck c;
  c.eps = sliding_spin_ratio(k, radius_m);  // validates the kinematics and R
  require_channel("Fx", Fx);
  require_channel("Fy", Fy);
  require_channel("Mz", Mz);
  validate_options(options);
  c.force_angle_bound_rad = force_angle_bound(c.eps);
  c.any_patch_torque_bound = any_patch_torque_ratio_bound(c.eps);
  c.axisymmetric_torque_bound = axisymmetric_torque_ratio_envelope(c.eps);
  c.at_rest = k.vx == 0.0 && k.vy == 0.0 && k.omega == 0.0;
  if (c.at_rest) return c;
  check_channels(k, Fx, Fy, Mz, radius_m, options, c);
  return c;
}

}  // namespace contensou
