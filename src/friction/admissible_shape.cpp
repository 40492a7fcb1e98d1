// The fractional law's shapes that a non-negative pressure gives (admissible_shape.hpp).
#include "contensou/friction/admissible_shape.hpp"

#include <cmath>
#include <cstdio>

#include "contensou/friction/error.hpp"

namespace contensou {

namespace {

constexpr double kTolerance = 1e-6;

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

// a and m on their own and together (t <= 1, r <= 1, t <= r).
std::string shape_reason(double a, double m, double t, double r) {
  if (t > 1.0 + kTolerance)
    return "a = " + number(a) +
           " > 4: the sliding force weakens with spin faster than even a ring of pressure at the "
           "rim makes it (a <= 4 for any non-negative pressure)";
  if (r > 1.0 + kTolerance)
    return "m = " + number(m) +
           " < 4: the torque falls with sliding more slowly than even a ring of pressure at the "
           "rim lets it (m >= 4 for any non-negative pressure)";
  if (t > r * (1.0 + kTolerance))
    return "a m = " + number(a * m) +
           " > 16: the sliding force wants the pressure nearer the rim than the torque does (a "
           "m <= 16 for any non-negative pressure)";
  return "";
}

}  // namespace

ShapeAdmissibility shape_admissibility(double a, double m, std::optional<double> torque_ratio) {
  for (const auto& [name, v] : {std::pair{"a", a}, std::pair{"m", m}})
    if (!(std::isfinite(v) && v > 0.0))
      throw InvalidArgument(name, format_value(v), "must be finite and positive");
  if (torque_ratio && !(std::isfinite(*torque_ratio) && *torque_ratio > 0.0))
    throw InvalidArgument("M0 / (F0 R)", format_value(*torque_ratio),
                          "must be finite and positive");
  ShapeAdmissibility s;
  s.t = std::sqrt(a) / 2.0;
  s.r = 2.0 / std::sqrt(m);
  s.q = torque_ratio;
  s.reason = shape_reason(a, m, s.t, s.r);
  if (!s.reason.empty()) {
    s.admissible = false;
    return s;
  }
  // q_min: the smaller root of t q^2 - (2 t + (1 - t)(1 - r)) q + t = 0 (product of roots 1).
  const double t = std::min(s.t, 1.0), r = std::min(s.r, 1.0);
  const double b = 2.0 * t + (1.0 - t) * (1.0 - r);
  s.q_min = 2.0 * t / (b + std::sqrt(std::max(0.0, b * b - 4.0 * t * t)));
  s.q_max = r;
  if (s.t >= s.r * (1.0 - kTolerance) && s.r < 1.0 - kTolerance)
    s.edge = "a m = " + number(a * m) +
             " = 16: the sliding shape and the spin shape meet (as for a ring of pressure at "
             "rho = " +
             number(s.r) + ")";
  if (!torque_ratio) return s;
  const double q = *torque_ratio;
  if (q > s.q_max * (1.0 + kTolerance)) {
    s.admissible = false;
    s.reason = "M0 / (F0 R) = " + number(q) + " > " + number(s.q_max) +
               ": more spin torque than any non-negative pressure with m = " + number(m) +
               " gives on a patch of radius R";
  } else if (q < s.q_min * (1.0 - kTolerance)) {
    s.admissible = false;
    s.reason = "M0 / (F0 R) = " + number(q) + " < " + number(s.q_min) +
               ": less spin torque than any non-negative pressure with a = " + number(a) +
               " and m = " + number(m) +
               " gives on a patch of radius R (the contact may be smaller than R)";
  } else if (s.edge.empty() && q >= s.q_max * (1.0 - kTolerance)) {
    s.edge =
        "M0 / (F0 R) = " + number(q) + ", the most any pressure with m = " + number(m) + " gives";
  } else if (s.edge.empty() && q <= s.q_min * (1.0 + kTolerance) && s.q_min < s.q_max) {
    s.edge = "M0 / (F0 R) = " + number(q) + ", the least any pressure with a = " + number(a) +
             " and m = " + number(m) + " gives";
  }
  return s;
}

}  // namespace contensou
