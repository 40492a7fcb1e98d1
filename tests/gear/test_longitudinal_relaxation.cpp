// Longitudinal relaxation of every contact model (landing_gear.hpp,
// SlidingTire::longitudinal_relaxation_length_m; docs/shimmy.md, "Longitudinal relaxation"):
// the step response against the first-order closed form, the energy balance of a slip cycle
// (the tire takes energy from the rim, none is created), the landing with and without it, and
// bad lengths refused by name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/landing_simulation.hpp"

using namespace contensou;

namespace {

// The wheel spin that gives the kinematic slip velocity vx = V - Omega r (psi, y', x' = 0).
double spin_for(const GearConfig& c, double vx) {
  return (c.scenario.forward_speed_mps - vx) / c.structure.wheel_radius_m;
}

// RK4 on u alone, the rest of the state held except the spin, which spin(t) prescribes; calls
// visit(t, x) at every step's start and at the end.
void integrate_u(const GearModel& m, const GearMode& mode, double t0, double t1, int steps,
                 const std::function<double(double)>& spin, GearState& x,
                 const std::function<void(double, const GearState&)>& visit) {
  const double dt = (t1 - t0) / steps;
  const auto rate = [&](double t, double u) {
    GearState s = x;
    s[kSpin] = spin(t);
    s[kSlipX] = u;
    return gear_rhs(m, mode, t, s)[kSlipX];
  };
  for (int k = 0; k < steps; ++k) {
    const double t = t0 + k * dt, u = x[kSlipX];
    x[kSpin] = spin(t);
    visit(t, x);
    const double k1 = rate(t, u), k2 = rate(t + 0.5 * dt, u + 0.5 * dt * k1);
    const double k3 = rate(t + 0.5 * dt, u + 0.5 * dt * k2), k4 = rate(t + dt, u + dt * k3);
    x[kSlipX] = u + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  x[kSpin] = spin(t1);
  visit(t1, x);
}

}  // namespace

// Oracle: the first-order lag u' = vx - (V / sigma_x) u after a step of vx from 0 to v1 at
// u = 0 gives u = sigma_x (v1 / V) (1 - exp(-V t / sigma_x)): 63.2 % after sigma_x of rolling,
// in the slip the law sees and, in the linear range of the rolling tire, in its drag.
TEST(LongitudinalRelaxation, AStepInSlipReaches63PercentAfterSigmaXOfRolling) {
  for (ContactModel model : {ContactModel::von_schlippe, ContactModel::coupled}) {
    GearConfig c;
    c.scenario.drift_speed_mps = 0.0;
    const double V = c.scenario.forward_speed_mps,
                 sigma_x = c.tire.longitudinal_relaxation_length_m;
    const GearModel m = make_gear_model(c, model);
    const GearMode mode{true, model == ContactModel::von_schlippe, false};
    const double t0 = 10.0;  // full load
    // The rolling tire in its linear range (slip 1e-4); the sliding law at a slip velocity
    // of 7 m/s (its force then barely depends on the slip's size, so only the slip is checked).
    const double v1 = model == ContactModel::von_schlippe ? 1e-4 * V : 0.1 * V;
    GearState x = GearState::Zero();
    const auto spin = [&](double) { return spin_for(c, v1); };
    integrate_u(m, mode, t0, t0 + sigma_x / V, 400, spin, x, [](double, const GearState&) {});
    const double expected = sigma_x * v1 / V * (1.0 - std::exp(-1.0));
    EXPECT_NEAR(x[kSlipX], expected, 1e-8 * expected) << to_string(model);
    const ContactState cs = contact_state(m, mode, t0, x);
    EXPECT_NEAR(cs.slip.vx / v1, 1.0 - std::exp(-1.0), 1e-8) << to_string(model);
    if (model == ContactModel::von_schlippe) {
      // The drag against the steady drag at the kinematic slip: 63 % too (linear range).
      GearState steady = x;
      steady[kSlipX] = sigma_x * v1 / V;
      const double ratio = cs.force.Fx / contact_state(m, mode, t0, steady).force.Fx;
      EXPECT_NEAR(ratio, 1.0 - std::exp(-1.0), 1e-6);
    }
    // Off (sigma_x = 0): the law sees the kinematic vx itself.
    GearConfig off = c;
    off.tire.longitudinal_relaxation_length_m = 0.0;
    GearState y = GearState::Zero();
    y[kSpin] = spin_for(c, v1);
    EXPECT_NEAR(contact_state(make_gear_model(off, model), mode, t0, y).slip.vx, v1, 1e-9 * V);
    EXPECT_EQ(gear_rhs(make_gear_model(off, model), mode, t0, y)[kSlipX], 0.0);
  }
}

// Energy: with the kinematic slip velocity vx(t) cycling through zero, the rim does the work
// W_rim = int -Fx vx dt on the tire; the patch dissipates W_patch = int -Fx vx_relaxed dt, which
// is >= 0 at every instant (the law opposes the slip it sees); over whole cycles of the settled
// response the deflection's energy int -Fx du returns, so W_rim = W_patch > 0: no energy is
// created by the lag (a first-order lag with the force a function of u alone is a nonlinear
// spring in series with the sliding patch).
TEST(LongitudinalRelaxation, ASlipCycleCreatesNoEnergy) {
  for (ContactModel model : {ContactModel::von_schlippe, ContactModel::coupled}) {
    GearConfig c;
    c.scenario.drift_speed_mps = 0.0;
    const double V = c.scenario.forward_speed_mps,
                 sigma_x = c.tire.longitudinal_relaxation_length_m;
    const GearModel m = make_gear_model(c, model);
    const GearMode mode{true, model == ContactModel::von_schlippe, false};
    // A slip cycle at the wheel-tire mode's scale: period 4 sigma_x / V, amplitude 0.02 V about
    // 0.005 V (the sign of the slip changes).
    const double period = 4.0 * sigma_x / V, omega = 2.0 * std::numbers::pi / period;
    const auto vx = [&](double t) { return V * (0.005 + 0.02 * std::sin(omega * t)); };
    const auto spin = [&](double t) { return spin_for(c, vx(t)); };
    GearState x = GearState::Zero();
    x[kSlipX] = sigma_x * 0.005;
    // Settle for 20 periods (the lag's time constant is a quarter period), then measure 4.
    const double t0 = 10.0, t1 = t0 + 20.0 * period, t2 = t1 + 4.0 * period;
    integrate_u(m, mode, t0, t1, 8000, spin, x, [](double, const GearState&) {});
    double w_rim = 0.0, w_patch = 0.0, lowest = 0.0, previous_t = t1;
    double previous_rim = 0.0, previous_patch = 0.0;
    bool first = true;
    integrate_u(m, mode, t1, t2, 8000, spin, x, [&](double t, const GearState& s) {
      const ContactState cs = contact_state(m, mode, t, s);
      const double rim = -cs.force.Fx * vx(t), patch = -cs.force.Fx * cs.slip.vx;
      lowest = std::min(lowest, patch);
      if (!first) {  // trapezoidal rule
        w_rim += 0.5 * (t - previous_t) * (rim + previous_rim);
        w_patch += 0.5 * (t - previous_t) * (patch + previous_patch);
      }
      first = false;
      previous_t = t;
      previous_rim = rim;
      previous_patch = patch;
    });
    EXPECT_GE(lowest, 0.0) << to_string(model);
    EXPECT_GT(w_patch, 0.0) << to_string(model);
    EXPECT_NEAR(w_rim, w_patch, 1e-4 * w_patch) << to_string(model);
  }
}

// A landing of every model with and without the relaxation runs, spins up at about the same
// time (the lag, sigma_x / V = 2 ms, is short against the 0.1 s spin-up), and holds u at
// sigma_x times the slip during the braked slide.
TEST(LongitudinalRelaxation, LandingsRunWithAndWithoutIt) {
  for (ContactModel model :
       {ContactModel::coupled, ContactModel::decoupled, ContactModel::von_schlippe}) {
    GearConfig c;
    SolverOptions o;
    o.output_interval_s = 2e-3;
    const LandingRun with = simulate_landing(make_gear_model(c, model), o);
    GearConfig off = c;
    off.tire.longitudinal_relaxation_length_m = 0.0;
    const LandingRun without = simulate_landing(make_gear_model(off, model), o);
    ASSERT_TRUE(with.spin_up_s && without.spin_up_s) << to_string(model);
    EXPECT_NEAR(*with.spin_up_s, *without.spin_up_s, 0.01) << to_string(model);
    // At 0.9 s (braked slide): u = sigma_x vx / V to within the slip's drift over sigma_x / V.
    const auto at = std::find_if(with.samples.begin(), with.samples.end(),
                                 [](const LandingSample& s) { return s.t >= 0.9; });
    ASSERT_NE(at, with.samples.end());
    const double V = c.scenario.forward_speed_mps,
                 sigma_x = c.tire.longitudinal_relaxation_length_m;
    const double kinematic_vx =
        V - at->x[kSpin] * c.structure.wheel_radius_m - c.structure.offset_m * at->x[kPsiDot];
    EXPECT_NEAR(at->x[kSlipX], sigma_x * kinematic_vx / V, 0.05 * sigma_x * kinematic_vx / V)
        << to_string(model);
    for (const LandingSample& s : without.samples) ASSERT_EQ(s.x[kSlipX], 0.0);
  }
}

TEST(LongitudinalRelaxation, BadLengthsAreRefusedByName) {
  for (double bad : {-0.1, 0.001, 10.0, std::nan("")}) {
    GearConfig c;
    c.tire.longitudinal_relaxation_length_m = bad;
    try {
      validate(c);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("tire.longitudinal_relaxation_length_m"),
                std::string::npos)
          << e.what();
    }
  }
}
