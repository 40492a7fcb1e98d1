// Tire carcass compliance in series with the sliding patch (docs/shimmy.md, "Carcass
// compliance"; issue 12, item 3): a very stiff carcass converges to the rigid model, a rim held
// in a steady slide deflects the carcass by friction / stiffness, and the eigenvalue criterion
// works with the two new states.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/linear_stability.hpp"

using namespace contensou;

namespace {

GearConfig stiffened(GearConfig c, double factor) {
  c.structure.carcass_lateral_stiffness_n_per_m *= factor;
  c.structure.carcass_torsional_stiffness_nm_per_rad *= factor;
  return c;
}

StabilityReport eigen_report(const GearConfig& c, ContactModel m, StabilityPhase phase) {
  StabilityOptions o;
  o.simulate_perturbation = false;
  const GearModel model = make_gear_model(c, m);
  return phase == StabilityPhase::touchdown ? assess_touchdown(model, o)
                                            : assess_stability(model, phase, o);
}

}  // namespace

TEST(Carcass, EstimateFromTheStretchedStringAndOffByDefault) {
  const GearConfig rigid;
  EXPECT_FALSE(rigid.structure.carcass_compliance());
  const GearConfig c = carcass_from_string_tire(rigid);
  ASSERT_TRUE(c.structure.carcass_compliance());
  // String: C_Fa = 2 c_c (sigma + a)^2, k_cy = 2 c_c (sigma + a) = C_Fa / (sigma + a).
  const double a = contact_state(make_gear_model(rigid, ContactModel::coupled),
                                 {true, false, false}, 10.0, GearState::Zero())
                       .patch_radius_m;
  const double sigma = rigid.rolling.relaxation_length_m;
  const double CFa = rigid.rolling.cornering_coefficient * rigid.scenario.static_load_n;
  EXPECT_NEAR(c.structure.carcass_lateral_stiffness_n_per_m, CFa / (sigma + a), 1e-9 * CFa);
  EXPECT_GT(c.structure.carcass_torsional_stiffness_nm_per_rad, 5e4);
  EXPECT_LT(c.structure.carcass_torsional_stiffness_nm_per_rad, 1e5);
}

TEST(Carcass, ValidationNamesTheKey) {
  GearConfig c = carcass_from_string_tire(GearConfig{});
  c.structure.carcass_torsional_stiffness_nm_per_rad = 0.0;
  try {
    make_gear_model(c, ContactModel::coupled);
    FAIL() << "expected InvalidArgument";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("structure.carcass_torsional_stiffness_nm_per_rad"),
              std::string::npos)
        << e.what();
  }
  c = carcass_from_string_tire(GearConfig{});
  c.structure.carcass_lateral_damping_ns_per_m = 0.0;
  EXPECT_THROW(make_gear_model(c, ContactModel::coupled), InvalidArgument);
  c = carcass_from_string_tire(GearConfig{});
  c.structure.wheel_spacing_m = 0.8;
  EXPECT_THROW(make_gear_model(c, ContactModel::coupled), InvalidArgument);
}

// Oracle: the rim held in a steady slide (wheel locked, lateral drift, a constant yaw rate). The
// patch comes to rest relative to the rim, so its motion is the rim's and the carcass carries
// the rigid model's friction: e_y = Fy / k_cy, e_psi = Mz / k_cpsi.
TEST(Carcass, SteadySlideDeflectsTheCarcassByFrictionOverStiffness) {
  for (ContactModel m : {ContactModel::coupled, ContactModel::decoupled}) {
    GearConfig rigid;
    rigid.scenario.drift_speed_mps = 1.0;
    // The carcass's own balance: no longitudinal relaxation, the law sees the rim's vx.
    rigid.tire.longitudinal_relaxation_length_m = 0.0;
    const GearConfig c = carcass_from_string_tire(rigid);
    const GearModel model = make_gear_model(c, m);
    const GearMode mode{true, false, false};
    const double t = 10.0;  // full load
    GearState x = GearState::Zero();
    x[kPsiDot] = 0.2;  // spin of the rim, so that the torque is not zero
    // Integrate e_y, e_psi alone (RK4, the rest of the state held) to steady state: about 20
    // time constants (c + |dF/dv|) / k, long for the decoupled model's regularised spin torque
    // (its slope M0 R / eps ~ 1.3e4 N m s/rad against k_cpsi ~ 7.8e4 N m/rad: 0.17 s).
    const bool coupled = m == ContactModel::coupled;
    const double dt = coupled ? 2e-4 : 1e-3;
    for (int step = 0; step < (coupled ? 1000 : 4000); ++step) {
      const auto rate = [&](const GearState& s) {
        const GearState d = gear_rhs(model, mode, t, s);
        return Eigen::Vector2d(d[kCarcassY], d[kCarcassPsi]);
      };
      GearState s = x;
      const Eigen::Vector2d k1 = rate(s);
      s[kCarcassY] = x[kCarcassY] + 0.5 * dt * k1[0];
      s[kCarcassPsi] = x[kCarcassPsi] + 0.5 * dt * k1[1];
      const Eigen::Vector2d k2 = rate(s);
      s[kCarcassY] = x[kCarcassY] + 0.5 * dt * k2[0];
      s[kCarcassPsi] = x[kCarcassPsi] + 0.5 * dt * k2[1];
      const Eigen::Vector2d k3 = rate(s);
      s[kCarcassY] = x[kCarcassY] + dt * k3[0];
      s[kCarcassPsi] = x[kCarcassPsi] + dt * k3[1];
      const Eigen::Vector2d k4 = rate(s);
      x[kCarcassY] += dt / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
      x[kCarcassPsi] += dt / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
    }
    const ContactState patch = contact_state(model, mode, t, x);
    EXPECT_LT(std::abs(patch.carcass_rate[0]), 1e-9) << to_string(m);
    EXPECT_LT(std::abs(patch.carcass_rate[1]), 1e-9) << to_string(m);
    // The rigid model at the same rim motion; the patch centre sits e_y further out on the yaw
    // lever, so its vx differs by e_y psi' (below 1e-4 m/s here): the oracle gets that too.
    GearConfig rigid_here = rigid;
    const GearModel rigid_model = make_gear_model(rigid_here, m);
    GearState xr = GearState::Zero();
    xr[kPsiDot] = x[kPsiDot];
    const ContactState r = contact_state(rigid_model, mode, t, xr);
    const double ky = c.structure.carcass_lateral_stiffness_n_per_m;
    const double kp = c.structure.carcass_torsional_stiffness_nm_per_rad;
    EXPECT_NEAR(x[kCarcassY], r.force.Fy / ky, 1e-5 * std::abs(r.force.Fy / ky)) << to_string(m);
    EXPECT_NEAR(x[kCarcassPsi], r.force.Mz / kp, 1e-4 * std::abs(r.force.Mz / kp) + 1e-12)
        << to_string(m);
    // The law saw the patch's motion: equal to the rim's at steady state.
    EXPECT_NEAR(patch.slip.vy, r.slip.vy, 1e-9);
    EXPECT_NEAR(patch.slip.omega, r.slip.omega, 1e-9);
    EXPECT_GT(std::abs(x[kCarcassY]), 4e-4);  // a real deflection: |Fy| ~ f N |vy| / |v|
  }
}

// A very stiff carcass (1000 x the string's estimate) gives the rigid model's eigenvalues: the
// dominant oscillatory mode within 0.02 1/s and 0.1 % in frequency, and for the coupled model
// every eigenvalue within 0.02 1/s + 0.2 %. (The decoupled model's overdamped torsion converges
// only as c_spin / k: its regularised spin damper c_spin ~ 1.3e4 N m s/rad in series with the
// carcass spring moves those real eigenvalues by ~10 % even at 1000 x.)
TEST(Carcass, VeryStiffCarcassConvergesToTheRigidModel) {
  const GearConfig rigid;
  const GearConfig stiff = stiffened(carcass_from_string_tire(rigid), 1000.0);
  for (ContactModel m : {ContactModel::coupled, ContactModel::decoupled}) {
    for (StabilityPhase phase : {StabilityPhase::braked_slide, StabilityPhase::touchdown}) {
      const StabilityReport a = eigen_report(rigid, m, phase);
      const StabilityReport b = eigen_report(stiff, m, phase);
      ASSERT_TRUE(a.state.converged && b.state.converged);
      EXPECT_NEAR(b.growth_rate_per_s, a.growth_rate_per_s, 0.02)
          << to_string(m) << " " << to_string(phase);
      EXPECT_NEAR(b.frequency_hz, a.frequency_hz, 1e-3 * a.frequency_hz)
          << to_string(m) << " " << to_string(phase);
      // The rigid model's eigenvalues are all there (the two extra ones are the carcass's own,
      // fast and real).
      if (m != ContactModel::coupled) continue;
      for (const std::complex<double>& ev : a.eigenvalues) {
        double nearest = 1e300;
        for (const std::complex<double>& evb : b.eigenvalues)
          nearest = std::min(nearest, std::abs(evb - ev));
        EXPECT_LT(nearest, 0.02 + 2e-3 * std::abs(ev))
            << to_string(m) << " " << to_string(phase) << " " << ev;
      }
    }
  }
}

// The eigenvalue criterion with the carcass states: finite eigenvalues, one per state, the
// coupled braked slide and touchdown stable at the default, and the rolling (classical) model's
// eigenvalues unchanged (the stretched string is its carcass; e_y, e_psi only relax, adding the
// real eigenvalues -k_cy / c_cy and -k_cpsi / c_cpsi).
TEST(Carcass, EigenvalueCriterionWithCarcassStates) {
  const GearConfig rigid;
  const GearConfig c = carcass_from_string_tire(rigid);
  for (ContactModel m :
       {ContactModel::coupled, ContactModel::decoupled, ContactModel::von_schlippe}) {
    for (StabilityPhase phase : {StabilityPhase::braked_slide, StabilityPhase::touchdown}) {
      const StabilityReport r = eigen_report(c, m, phase);
      ASSERT_TRUE(r.state.converged) << to_string(m) << " " << to_string(phase);
      EXPECT_EQ(std::count(r.state.states.begin(), r.state.states.end(), kCarcassY), 1);
      EXPECT_EQ(std::count(r.state.states.begin(), r.state.states.end(), kCarcassPsi), 1);
      EXPECT_EQ(r.eigenvalues.size(), r.state.states.size());
      for (const std::complex<double>& ev : r.eigenvalues)
        EXPECT_TRUE(std::isfinite(ev.real()) && std::isfinite(ev.imag()));
      EXPECT_TRUE(r.stable()) << to_string(m) << " " << to_string(phase) << " " << r.max_real_part;
    }
  }
  // Classical: the torsional eigenvalue is the rigid model's to 1e-6 (relative).
  for (StabilityPhase phase : {StabilityPhase::braked_slide, StabilityPhase::touchdown}) {
    const StabilityReport a = eigen_report(rigid, ContactModel::von_schlippe, phase);
    const StabilityReport b = eigen_report(c, ContactModel::von_schlippe, phase);
    const std::complex<double> ta(a.torsion_growth_rate_per_s, a.torsion_frequency_hz);
    const std::complex<double> tb(b.torsion_growth_rate_per_s, b.torsion_frequency_hz);
    EXPECT_LT(std::abs(ta - tb), 1e-6 * std::abs(ta)) << to_string(phase);
    bool lateral = false, torsional = false;
    for (const std::complex<double>& ev : b.eigenvalues) {
      lateral |= std::abs(ev.real() + c.structure.carcass_lateral_stiffness_n_per_m /
                                          c.structure.carcass_lateral_damping_ns_per_m) < 1e-3 &&
                 ev.imag() == 0.0;
      torsional |=
          std::abs(ev.real() + c.structure.carcass_torsional_stiffness_nm_per_rad /
                                   c.structure.carcass_torsional_damping_nms_per_rad) < 1e-3 &&
          ev.imag() == 0.0;
    }
    EXPECT_TRUE(lateral && torsional) << to_string(phase);
  }
  // The compliant carcass changes the coupled braked slide measurably (the torsional mode loses
  // part of its damping: -3.38 -> -2.55 1/s at the string's estimate).
  const StabilityReport a =
      eigen_report(rigid, ContactModel::coupled, StabilityPhase::braked_slide);
  const StabilityReport b = eigen_report(c, ContactModel::coupled, StabilityPhase::braked_slide);
  EXPECT_GT(b.torsion_growth_rate_per_s - a.torsion_growth_rate_per_s, 0.3);
}

// The structured Jacobian with the carcass on is the difference quotient of the right-hand side:
// it agrees with central differences.
TEST(Carcass, JacobianAgreesWithCentralDifferences) {
  GearConfig c = carcass_from_string_tire(GearConfig{});
  c.scenario.drift_speed_mps = 0.3;
  const GearModel model = make_gear_model(c, ContactModel::coupled);
  const GearMode mode{true, false, true};
  GearState x = GearState::Zero();
  x[kY] = 1e-3;
  x[kYDot] = 0.05;
  x[kPsi] = 2e-3;
  x[kPsiDot] = 0.3;
  x[kSpin] = 100.0;
  x[kCarcassY] = 2e-3;
  x[kCarcassPsi] = 1e-4;
  // The longitudinal deflection at its steady value sigma_x vx / V (vx = V - Omega r - l psi').
  x[kSlipX] = c.tire.longitudinal_relaxation_length_m *
              (1.0 - (100.0 * c.structure.wheel_radius_m + 0.3 * c.structure.offset_m) /
                         c.scenario.forward_speed_mps);
  const double t = 0.5;
  const GearJacobian J = gear_jacobian(model, mode, t, x);
  for (int j : {static_cast<int>(kPsiDot), static_cast<int>(kSpin), static_cast<int>(kCarcassY),
                static_cast<int>(kCarcassPsi), static_cast<int>(kSlipX)}) {
    const double h = 1e-6 * std::max(std::abs(x[j]), 1e-3);
    GearState xp = x, xm = x;
    xp[j] += h;
    xm[j] -= h;
    const GearState d = (gear_rhs(model, mode, t, xp) - gear_rhs(model, mode, t, xm)) / (2 * h);
    for (int i = 0; i < kStateSize; ++i)
      EXPECT_NEAR(J(i, j), d[i], 1e-3 * (std::abs(d[i]) + 1.0)) << i << "," << j;
  }
}

// A simulated landing with the carcass on: it completes, spins up as the rigid model does (the
// carcass does not change the drag), deflects the carcass by Fy / k_cy during the braked slide
// (the patch's rate is small there), and after spin-up (rolling, before the brake) the carcass
// has relaxed to zero.
TEST(Carcass, SimulatedLandingWithCarcass) {
  const GearConfig rigid;
  const GearConfig c = carcass_from_string_tire(rigid);
  SolverOptions o;
  o.relative_tolerance = 1e-6;
  const LandingRun a = simulate_landing(make_gear_model(rigid, ContactModel::coupled), o);
  const LandingRun b = simulate_landing(make_gear_model(c, ContactModel::coupled), o);
  ASSERT_TRUE(a.spin_up_s && b.spin_up_s);
  EXPECT_NEAR(*b.spin_up_s, *a.spin_up_s, 0.02 * *a.spin_up_s);
  bool relaxed = false, deflected = false;
  const double ky = c.structure.carcass_lateral_stiffness_n_per_m;
  for (const LandingSample& s : b.samples) {
    ASSERT_TRUE(s.x.allFinite()) << s.t;
    if (s.rolling && s.t > c.scenario.touchdown_time_s + *b.spin_up_s + 0.05 &&
        s.t < c.scenario.brake_on_s)
      relaxed |= std::abs(s.x[kCarcassY]) < 1e-8 && std::abs(s.x[kCarcassPsi]) < 1e-8;
    if (!s.rolling && s.t > c.scenario.brake_on_s + 0.2 && s.t < c.scenario.brake_off_s &&
        std::abs(s.contact.force.Fy) > 100.0) {
      // k e_y + c e_y' = Fy: the balance holds at every sample.
      EXPECT_NEAR(ky * s.x[kCarcassY] +
                      c.structure.carcass_lateral_damping_ns_per_m * s.contact.carcass_rate[0],
                  s.contact.force.Fy, 1e-6 * std::abs(s.contact.force.Fy) + 1e-6);
      deflected = true;
    }
  }
  EXPECT_TRUE(relaxed);
  EXPECT_TRUE(deflected);
}

// The energy per cycle (linear_stability.hpp) with the carcass on, the carcass lever term
// included, matches the growth rate as in the rigid test (test_linear_stability.cpp): the legacy
// gear's torsional mode, 1 mrad, work = 2 sigma E 2 pi / w.
TEST(Carcass, EnergyPerCycleMatchesTheGrowthRate) {
  const GearConfig c = carcass_from_string_tire(legacy_gear_config());
  StabilityOptions o;
  o.simulate_perturbation = false;
  const StabilityReport r =
      assess_stability(make_gear_model(c, ContactModel::coupled), StabilityPhase::braked_slide, o);
  ASSERT_GT(r.torsion_share, 0.5);
  const double w = 2 * std::numbers::pi * r.frequency_hz;
  const double E = 0.5 * c.structure.torsional_inertia_kgm2 * std::pow(1e-3 * w, 2);
  const double expected = 2 * r.growth_rate_per_s * E * 2 * std::numbers::pi / w;
  EXPECT_NEAR(r.energy.total(), expected, 0.15 * std::abs(expected) + 1e-4)
      << "carcass lever " << r.energy.carcass_lever << " growth " << r.growth_rate_per_s;
  EXPECT_EQ(r.energy.total() > 0, r.growth_rate_per_s > 0);
}
