// The rolling tire: the stretched string with combined slip on a friction circle
// (landing_gear.hpp, RollingTire; docs/shimmy.md, "von_schlippe").
#include "contensou/gear/landing_gear.hpp"

#include "gear_internals.hpp"

#include <cmath>
#include <numbers>

#include "contensou/friction/pressure_profile.hpp"

namespace contensou {

namespace detail {

// The stretched string with combined slip on a friction circle (landing_gear.hpp, RollingTire):
// the demanded force D = (-C_x s N, C_Fa alpha N) saturates on the circle, |F| = cap tanh(z),
// z = |D| / cap, cap = f(w) N, and turns from D's direction to the sliding one as the sliding
// share beta = tanh(z)^2 grows: at full slide F = -f(w) N e_s, e_s = (vx, -V alpha) / w the
// tread's sliding velocity (= (vx, vy) in a steady slide), the sliding tires' Coulomb force.
// The pneumatic trail C_Ma / C_Fa shrinks with the adhering share: Mz carries (1 - beta) of it
// (the brush model's trail vanishes at full slide; Pacejka 2012, sec. 3.2).
void rolling_forces(const GearConfig& c, double lambda, ContactState& cs) {
  const RollingTire& rt = c.rolling;
  const double V = c.scenario.forward_speed_mps, N = cs.load_n;
  const double alpha = lambda / rt.relaxation_length_m;
  const double sx = cs.slip.vx, sy = -V * alpha;  // the tread's sliding velocity
  const double w = std::hypot(sx, sy);
  const double mu = friction_at(c.tire.friction, w);
  const double dx = -rt.longitudinal_slip_coefficient * cs.slip_ratio * N;
  const double dy = rt.cornering_coefficient * alpha * N;
  const double demand = std::hypot(dx, dy), cap = mu * N;
  const double z = demand / cap;
  // cap tanh(z) / |D| -> (1 - z^2 / 3) / 1 for small z; beta = tanh(z)^2 -> z^2.
  const double th = z > 1e-4 ? std::tanh(z) : z - z * z * z / 3.0;
  const double beta = th * th;
  double fx = 0.0, fy = 0.0;
  if (demand > 0.0) {
    // The blend of the two unit directions (same quadrant: -e_s and D both oppose the slip).
    const double ex = (1.0 - beta) * dx / demand - (w > 0.0 ? beta * sx / w : 0.0);
    const double ey = (1.0 - beta) * dy / demand - (w > 0.0 ? beta * sy / w : 0.0);
    const double norm = std::hypot(ex, ey);
    const double size = z > 1e-4 ? cap * th : demand * (1.0 - z * z / 3.0);
    if (norm > 0.0) {
      fx = size * ex / norm;
      fy = size * ey / norm;
    }
  }
  cs.friction = mu;
  cs.force.Fx = fx;
  cs.force.Fy = fy;
  cs.force.Mz = -rt.aligning_coefficient_m / rt.cornering_coefficient * (1.0 - beta) * fy -
                rt.tread_moment_nm2_per_rad * (N / c.scenario.static_load_n) * cs.slip.omega / V;
}

// The friction on the tire from the patch kinematics cs.slip (and slip_ratio), the string's
}  // namespace detail

using namespace detail;

double string_deflection_for_force(const GearModel& model, double t, const GearState& x,
                                   double lateral_force_n) {
  const GearMode rolling{true, true, false};
  GearState probe = x;
  const auto force = [&](double lambda) {
    probe[kLambda] = lambda;
    return contact_state(model, rolling, t, probe).force.Fy;
  };
  if (contact_state(model, rolling, t, x).load_n <= 0.0) return 0.0;
  // Fy(lambda) rises from 0 to its peak within a slip angle of a few mu / C_Fa; search up to
  // alpha = 1 rad, and stop at the bracket's end if the force is out of reach.
  const double sigma = model.config.rolling.relaxation_length_m;
  double lo = 0.0, hi = std::copysign(sigma, lateral_force_n);
  if (std::abs(force(hi)) < std::abs(lateral_force_n)) return hi;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::abs(force(mid)) < std::abs(lateral_force_n) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

GearConfig carcass_from_string_tire(GearConfig c) {
  // Stretched string (Pacejka 2012, sec. 5.4; Besselink 2000, ch. 3): string stiffness per
  // length c_c, free length sigma on each side of a contact line of half-length a. Cornering
  // stiffness C_Fa = 2 c_c (sigma + a)^2; rim translated by e with the contact line held:
  // foundation force 2 c_c a e (contact) + 2 c_c sigma e (free parts); rim turned by e_psi:
  // moment c_c e_psi (2 a^3 / 3 + 2 a sigma (sigma + a)) (contact part and the free parts'
  // deflection a e_psi decaying over sigma, at mean lever a + sigma).
  const double N = c.scenario.static_load_n;
  const double a = std::sqrt(N / (2.0 * std::numbers::pi * c.tire.inflation_pressure_pa *
                                  moment(unit_patch(c.tire).profile, 1)));
  const double sigma = c.rolling.relaxation_length_m;
  const double cc = c.rolling.cornering_coefficient * N / (2.0 * (sigma + a) * (sigma + a));
  c.structure.carcass_lateral_stiffness_n_per_m = 2.0 * cc * (sigma + a);
  c.structure.carcass_torsional_stiffness_nm_per_rad =
      cc * (2.0 / 3.0 * a * a * a + 2.0 * a * sigma * (sigma + a));
  return c;
}

}  // namespace contensou
