// Stability by eigenvalues (docs/shimmy.md, "Stability criterion"): the classical critical
// damping against Routh-Hurwitz, the default gear's classical margin over 30-90 m/s, the
// kinematic-shimmy wavelength 12a of the stretched string with sigma = 3a (Pacejka), the
// quasi-steady braked state against the anti-skid's closed form, the standard perturbation's
// growth against the eigenvalue, and the energy balance per cycle against the growth rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "contensou/gear/stability_map.hpp"

using namespace contensou;

namespace {

constexpr double kPi = std::numbers::pi;

double patch_radius(const GearModel& m) {
  return contact_state(m, {true, true, false}, 10.0, GearState::Zero()).patch_radius_m;
}

// The Routh-Hurwitz bound of the torsion + stretched-string system (test_landing_gear.cpp has
// its derivation): I psi'' = -k psi - d psi' - q lambda, lambda' = V psi + (e - a) psi' -
// (V/sigma) lambda, q = N (e C_Fa + C_Ma) / sigma, d = c_psi + kappa_t / V.
double routh_hurwitz_critical_damping(const GearConfig& c, double a) {
  const double I = c.structure.torsional_inertia_kgm2,
               k = c.structure.torsional_stiffness_nm_per_rad;
  const double V = c.scenario.forward_speed_mps, N = c.scenario.static_load_n;
  const double sigma = c.rolling.relaxation_length_m, e = c.structure.trail_m;
  const double q =
      N * (e * c.rolling.cornering_coefficient + c.rolling.aligning_coefficient_m) / sigma;
  const double K1 = (q * (e - a) + k) / I, a0 = V * (k / sigma + q) / I;
  const double A = V / (I * I * sigma), B = K1 / I + V * V / (I * sigma * sigma),
               C = V / sigma * K1 - a0;
  return (-B + std::sqrt(B * B - 4 * A * C)) / (2 * A) - c.rolling.tread_moment_nm2_per_rad / V;
}

}  // namespace

TEST(LinearStability, ClassicalCriticalDampingOfARigidStrutMatchesRouthHurwitz) {
  for (double V : {30.0, 70.0}) {
    GearConfig c;
    c.scenario.forward_speed_mps = V;
    c.scenario.drift_speed_mps = 0.0;  // Routh-Hurwitz is straight rolling's (the state is kept)
    c.structure.offset_m = 0.0;
    c.structure.lateral_stiffness_n_per_m = 1e11;  // no lateral bending
    c.structure.lateral_damping_ns_per_m = 1e6;
    const GearModel m = make_gear_model(c, ContactModel::von_schlippe);
    const double expected = routh_hurwitz_critical_damping(c, patch_radius(m));
    EXPECT_NEAR(classical_critical_damping(m), expected, 2e-3 * expected) << "V = " << V;
  }
}

TEST(LinearStability, DefaultGearIsClassicallyStableWithAMarginOf1p3To1p5Over30To90) {
  // The onset boundary by eigenvalues at 2.5 m/s steps; the default damping over its maximum.
  double worst = 0.0, worst_speed = 0.0;
  for (double V = 30.0; V <= 90.0 + 1e-9; V += 2.5) {
    GearConfig c;
    c.scenario.forward_speed_mps = V;
    const GearModel m = make_gear_model(c, ContactModel::von_schlippe);
    const double crit = classical_critical_damping(m);
    if (crit > worst) {
      worst = crit;
      worst_speed = V;
    }
    EXPECT_LT(linear_growth_rate(m, StabilityPhase::touchdown), 0.0) << "V = " << V;
  }
  const double margin = GearConfig{}.structure.torsional_damping_nms_per_rad / worst;
  EXPECT_GE(margin, 1.3) << "worst at " << worst_speed << " m/s";
  EXPECT_LE(margin, 1.5) << "worst at " << worst_speed << " m/s";
  // The legacy gear is the classically unstable one.
  EXPECT_GT(linear_growth_rate(make_gear_model(legacy_gear_config(), ContactModel::von_schlippe),
                               StabilityPhase::touchdown),
            0.0);
}

TEST(LinearStability, NonlinearResponseChangesSignAtTheEigenvalueBoundary) {
  GearConfig c;
  const double crit = classical_critical_damping(make_gear_model(c, ContactModel::von_schlippe));
  for (double factor : {0.8, 1.2}) {
    c.structure.torsional_damping_nms_per_rad = factor * crit;
    const StabilityReport r =
        assess_stability(make_gear_model(c, ContactModel::von_schlippe), StabilityPhase::touchdown);
    ASSERT_TRUE(std::isfinite(r.perturbation_growth_rate_per_s));
    EXPECT_EQ(r.perturbation_growth_rate_per_s > 0, factor < 1) << factor;
    EXPECT_NEAR(r.perturbation_growth_rate_per_s, r.torsion_growth_rate_per_s, 0.05) << factor;
  }
}

// Pacejka (Tyre and Vehicle Dynamics, ch. 5): for the string with sigma = 3a the yaw moment's
// response to a yaw oscillation of the wheel (centre moving straight, swivel axis through the
// centre) has its dip, the kinematic-shimmy wavelength, at about 12a. The leading point's
// deflection is the model's lambda: its equation is read off gear_rhs by central differences;
// the contact line is the chord from the leading point to the trailing point, which lies on the
// leading point's path 2a behind (von Schlippe-Dietrich), so the moment of the string is
// proportional to v1 - v2 (v1 = lambda, v2 the trailing point's deflection).
TEST(LinearStability, KinematicShimmyWavelengthIsTwelveHalfContactLengths) {
  GearConfig c;
  c.structure.trail_m = 0.0;
  c.structure.offset_m = 0.0;
  c.scenario.drift_speed_mps = 0.0;
  GearModel m = make_gear_model(c, ContactModel::von_schlippe);
  const double a = patch_radius(m);
  m.config.rolling.relaxation_length_m = 3.0 * a;
  const double V = c.scenario.forward_speed_mps;
  const GearMode rolling{true, true, false};
  GearState x0 = GearState::Zero();
  x0[kSpin] = V / c.structure.wheel_radius_m;
  const auto slope = [&](int i) {
    GearState xp = x0, xm = x0;
    const double h = 1e-7;
    xp[i] += h;
    xm[i] -= h;
    return (gear_rhs(m, rolling, 10.0, xp)[kLambda] - gear_rhs(m, rolling, 10.0, xm)[kLambda]) /
           (2 * h);
  };
  const double c_psi = slope(kPsi), c_rate = slope(kPsiDot), c_lambda = slope(kLambda);
  // lambda' = c_psi psi + c_rate psi' + c_lambda lambda; psi = e^{i kappa X}, X = V t.
  const auto moment = [&](double kappa) {
    const std::complex<double> iw(0.0, kappa * V);
    const std::complex<double> v1 = (c_psi + iw * c_rate) / (iw - c_lambda);
    const std::complex<double> path = a + v1;  // leading point's lateral position (psi = 1)
    const std::complex<double> v2 = path * std::exp(std::complex<double>(0, -2 * kappa * a)) + a;
    return std::abs(v1 - v2);
  };
  double best = 1e300, best_wavelength = 0.0;
  for (double wavelength = 4 * a; wavelength <= 40 * a; wavelength += 1e-3 * a) {
    const double mz = moment(2 * kPi / wavelength);
    if (mz < best) {
      best = mz;
      best_wavelength = wavelength;
    }
  }
  // Pacejka's "about 12a"; the chord model's own minimum lies at 11.66a.
  EXPECT_NEAR(best_wavelength / a, 12.0, 0.5);
  EXPECT_LT(best, 0.1 * moment(2 * kPi / (40 * a)));  // a real dip
}

TEST(LinearStability, BrakedQuasiSteadyStateBalancesTheAntiSkid) {
  for (ContactModel cm :
       {ContactModel::coupled, ContactModel::decoupled, ContactModel::von_schlippe}) {
    const GearModel m = make_gear_model(GearConfig{}, cm);
    const QuasiSteadyState q = quasi_steady_state(m, StabilityPhase::braked_slide);
    ASSERT_TRUE(q.converged) << to_string(cm);
    const LandingScenario& s = m.config.scenario;
    const ContactState cs = contact_state(m, q.mode, q.t, q.x);
    // I_w Omega' = 0: T = -r Fx / tanh(Omega), and the anti-skid law inverted for the slip.
    const double r = m.config.structure.wheel_radius_m;
    const double T = -r * cs.force.Fx / std::tanh(q.x[kSpin]);
    const double slip =
        s.brake_target_slip + s.brake_slip_band * std::log(s.brake_max_torque_nm / T - 1.0);
    EXPECT_NEAR(1.0 - q.x[kSpin] * r / s.forward_speed_mps, slip, 1e-9) << to_string(cm);
    // Torsion: k psi = Mz - e Fy - l Fx.
    const GearStructure& g = m.config.structure;
    EXPECT_NEAR(g.torsional_stiffness_nm_per_rad * q.x[kPsi],
                cs.force.Mz - g.trail_m * cs.force.Fy - g.offset_m * cs.force.Fx,
                1e-6 * g.offset_m * std::abs(cs.force.Fx))
        << to_string(cm);
    // Every model brakes at the same friction level f(s* V) (within the anti-skid's band).
    EXPECT_NEAR(cs.friction, friction_at(m.config.tire.friction, slip * s.forward_speed_mps), 0.01)
        << to_string(cm);
  }
}

TEST(LinearStability, PerturbationGrowthMatchesTheTorsionalEigenvalue) {
  for (ContactModel cm : {ContactModel::coupled, ContactModel::von_schlippe}) {
    const StabilityReport r =
        assess_stability(make_gear_model(legacy_gear_config(), cm), StabilityPhase::braked_slide);
    ASSERT_TRUE(std::isfinite(r.perturbation_growth_rate_per_s)) << to_string(cm);
    EXPECT_NEAR(r.perturbation_growth_rate_per_s, r.torsion_growth_rate_per_s, 0.05)
        << to_string(cm);
    EXPECT_NEAR(r.perturbation_frequency_hz, r.torsion_frequency_hz, 0.02 * r.torsion_frequency_hz)
        << to_string(cm);
  }
}

// A mode growing at sigma gains 2 sigma E per unit time, E its mean mechanical energy; over one
// period the work of all non-conservative terms is 2 sigma E (2 pi / w). At a resonance the mean
// energy is twice the mean kinetic energy, (I |psi'^|^2 + m |y'^|^2) / 2 for amplitudes ^.
TEST(LinearStability, EnergyPerCycleMatchesTheGrowthRate) {
  for (ContactModel cm : {ContactModel::coupled, ContactModel::von_schlippe}) {
    const GearModel m = make_gear_model(legacy_gear_config(), cm);
    StabilityOptions o;
    o.simulate_perturbation = false;
    const StabilityReport r = assess_stability(m, StabilityPhase::braked_slide, o);
    ASSERT_GT(r.torsion_share, 0.5) << to_string(cm);
    // Torsion amplitude 1 mrad; the lateral motion is small in this mode (share > 0.5).
    const double w = 2 * kPi * r.frequency_hz;
    const double E = 0.5 * m.config.structure.torsional_inertia_kgm2 * std::pow(1e-3 * w, 2);
    const double expected = 2 * r.growth_rate_per_s * E * 2 * kPi / w;
    EXPECT_NEAR(r.energy.total(), expected, 0.15 * std::abs(expected) + 1e-4) << to_string(cm);
    EXPECT_EQ(r.energy.total() > 0, r.growth_rate_per_s > 0) << to_string(cm);
  }
}

// A lateral mode is scaled to 1 mm of lateral deflection (its torsion is smaller than 1 mrad x
// 1 m), so its energy per cycle is bounded by 2 |growth| E T with E <= (m + I / 1 m^2) (1e-3 w)^2
// / 2; scaled to 1 mrad of its tiny torsion it read -3.7e4 J on the default touchdown.
TEST(LinearStability, EnergyOfALateralModeIsScaledByItsLateralDeflection) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  StabilityOptions o;
  o.simulate_perturbation = false;
  const StabilityReport r = assess_stability(m, StabilityPhase::touchdown, o);
  ASSERT_EQ(r.mode_kind, "lateral");
  const double w = 2 * kPi * r.frequency_hz;
  const GearStructure& g = m.config.structure;
  const double E = 0.5 * (g.lateral_mass_kg + g.torsional_inertia_kgm2) * std::pow(1e-3 * w, 2);
  const double bound = 2 * std::abs(r.growth_rate_per_s) * E * 2 * kPi / w;
  EXPECT_LE(std::abs(r.energy.total()), 1.15 * bound) << r.energy.total();
  EXPECT_GT(std::abs(r.energy.total()), 1e-3 * bound) << r.energy.total();
  EXPECT_EQ(r.energy.total() > 0, r.growth_rate_per_s > 0);
}

TEST(LinearStability, EigenvalueMapCellsMatchSingleAssessments) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  const MapAxis x{"scenario.forward_speed_mps", 40.0, 80.0, 3};
  const MapAxis y{"structure.offset_m", 0.1, 0.4, 2};
  const StabilityMap map = linear_stability_map(m, x, y, StabilityPhase::braked_slide, 2);
  ASSERT_EQ(map.cells.size(), 6u);
  GearModel single = m;
  single.config.scenario.forward_speed_mps = 80.0;
  single.config.structure.offset_m = 0.4;
  const MapCell& cell = map.cells[1 * 3 + 2];
  EXPECT_TRUE(cell.valid);
  EXPECT_DOUBLE_EQ(cell.growth_rate_per_s,
                   linear_growth_rate(single, StabilityPhase::braked_slide));
  EXPECT_EQ(cell.shimmy, cell.growth_rate_per_s > 0);
}

TEST(LinearStability, BadNamesAndSlipsAreRejected) {
  EXPECT_THROW(gear_config_by_name("boeing"), InvalidArgument);
  EXPECT_THROW(quasi_steady_state(make_gear_model(GearConfig{}, ContactModel::coupled),
                                  StabilityPhase::touchdown, 1.5),
               InvalidArgument);
}

// Somieski's own parameter table (Aerospace Sci. Technol. 1997; read in a secondary
// reproduction, docs/gear-sources.md section 6.1): F_z = 9 kN, I_z = 1 kg m^2,
// c = 1e5 N m/rad, e = a = 0.1 m, sigma = 0.3 m, c_Fa = 20 /rad, c_Ma = -2 m/rad (2 in this
// project's sign), kappa = 270 N m^2/rad. docs/gear-sources.md section 6.3 solved his equations'
// Routh-Hurwitz boundary with an independent script: without damping the gear loses stability at
// V = 15.3 m/s, and at 70 m/s it needs k = 46.67 N m s/rad. Not a published figure (his chart
// could not be read), but his parameters in this project's model, by its eigenvalues.
TEST(LinearStability, SomieskiParameterTableGivesTheDerivedBoundary) {
  GearConfig c;
  c.scenario.static_load_n = 9000.0;
  c.scenario.drift_speed_mps = 0.0;
  c.scenario.braking = false;
  c.structure.torsional_inertia_kgm2 = 1.0;
  c.structure.torsional_stiffness_nm_per_rad = 1e5;
  c.structure.trail_m = 0.1;
  c.structure.offset_m = 0.0;
  c.structure.lateral_stiffness_n_per_m = 1e11;  // his model has no lateral bending
  c.structure.lateral_damping_ns_per_m = 1e6;
  c.rolling.relaxation_length_m = 0.3;
  c.rolling.cornering_coefficient = 20.0;
  c.rolling.aligning_coefficient_m = 2.0;
  c.rolling.tread_moment_nm2_per_rad = 270.0;
  // Half contact length a = 0.1 m: the patch radius R = sqrt(N / (2 pi p* A^1)) sets p*.
  GearModel probe = make_gear_model(c, ContactModel::von_schlippe);
  c.tire.inflation_pressure_pa = 9000.0 / (2 * kPi * 0.01 * probe.moment_1);
  probe = make_gear_model(c, ContactModel::von_schlippe);
  ASSERT_NEAR(patch_radius(probe), 0.1, 1e-12);
  const auto critical = [&](double V) {
    GearConfig v = c;
    v.scenario.forward_speed_mps = V;
    return classical_critical_damping(make_gear_model(v, ContactModel::von_schlippe));
  };
  EXPECT_NEAR(critical(70.0), 46.67, 0.05);
  EXPECT_NEAR(critical(30.0), 22.81, 0.05);
  // Onset without damping: bisection on the speed where the critical damping leaves zero.
  double lo = 10.0, hi = 20.0;
  for (int i = 0; i < 40; ++i) {
    const double mid = 0.5 * (lo + hi);
    (critical(mid) > 0.0 ? hi : lo) = mid;
  }
  EXPECT_NEAR(0.5 * (lo + hi), 15.3, 0.05);
}

// Torque-link freeplay of half-width delta: the braked slide's static twist under the drag at the
// offset moves by delta (k_psi (psi - delta) = the same torque, to the dead zone's smoothing
// s^2 / (psi - delta) ~ 1e-6 rad, s = delta / 20), and inside the band the spring is left with
// the smoothing's residual slope 1 - delta / sqrt(delta^2 + s^2) ~ 1/800 of k_psi.
TEST(LinearStability, FreeplayShiftsTheStaticTwistByItsHalfWidth) {
  GearConfig c;
  const GearModel plain = make_gear_model(c, ContactModel::coupled);
  c.structure.freeplay_rad = 2e-3;
  const GearModel loose = make_gear_model(c, ContactModel::coupled);
  const QuasiSteadyState a = quasi_steady_state(plain, StabilityPhase::braked_slide);
  const QuasiSteadyState b = quasi_steady_state(loose, StabilityPhase::braked_slide);
  ASSERT_TRUE(a.converged && b.converged);
  ASSERT_GT(a.x[kPsi], 5e-3);  // the drag twists the strut well beyond the band
  // The torque on the strut depends on the twist through the contact only weakly; compare the
  // spring torques, which must balance the same contact moment.
  const ContactState ca = contact_state(plain, a.mode, a.t, a.x);
  const ContactState cb = contact_state(loose, b.mode, b.t, b.x);
  const GearStructure& g = c.structure;
  const auto moment = [&](const ContactState& cs) {
    return cs.force.Mz - g.trail_m * cs.force.Fy - g.offset_m * cs.force.Fx;
  };
  EXPECT_NEAR(g.torsional_stiffness_nm_per_rad * a.x[kPsi], moment(ca),
              1e-6 * std::abs(moment(ca)));
  EXPECT_NEAR(
      g.torsional_stiffness_nm_per_rad * (b.x[kPsi] - 2e-3), moment(cb),
      1e-6 * std::abs(moment(cb)) + g.torsional_stiffness_nm_per_rad * 1e-8 / (b.x[kPsi] - 2e-3));
  EXPECT_NEAR(b.x[kPsi] - a.x[kPsi], 2e-3, 2e-4);
  // Inside the band (straight rolling, psi = 0) the spring does not act: the classical
  // linearisation loses the torsional stiffness, d(dpsi'/dt)/dpsi ~ 0.
  GearConfig r = c;
  const GearModel rolling = make_gear_model(r, ContactModel::von_schlippe);
  GearState x0 = GearState::Zero();
  x0[kSpin] = r.scenario.forward_speed_mps / r.structure.wheel_radius_m;
  const GearJacobian J = gear_jacobian(rolling, GearMode{false, true, false}, 0.0, x0);
  EXPECT_NEAR(-J(kPsiDot, kPsi) * r.structure.torsional_inertia_kgm2 /
                  r.structure.torsional_stiffness_nm_per_rad,
              1.0 - 20.0 / std::sqrt(401.0), 1e-9);
}

// Fore-aft bending (m_x x'' = -k_x x - c_x x' + Fx cos psi - Fy sin psi): airborne, its
// eigenvalues are those of a damped oscillator, -c/2m +- i sqrt(k/m - (c/2m)^2); braked, the
// drag bends the strut back by (Fx cos psi - Fy sin psi) / k_x.
TEST(LinearStability, ForeAftBendingIsAnOscillatorLoadedByTheDrag) {
  GearConfig c;
  c.structure.fore_aft_stiffness_n_per_m = 2e6;
  const GearStructure& g = c.structure;
  const GearModel m = make_gear_model(c, ContactModel::coupled);
  const GearJacobian J = gear_jacobian(m, GearMode{false, false, false}, 0.0, GearState::Zero());
  Eigen::Matrix2d A;
  A << J(kX, kX), J(kX, kXDot), J(kXDot, kX), J(kXDot, kXDot);
  // lambda^2 - tr lambda + det = 0: a complex pair when (tr/2)^2 < det.
  const double half_trace = A.trace() / 2, det = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0);
  const double disc = half_trace * half_trace - det;
  ASSERT_LT(disc, 0.0);
  const std::complex<double> ev[2] = {{half_trace, std::sqrt(-disc)},
                                      {half_trace, -std::sqrt(-disc)}};
  const double decay = g.fore_aft_damping_ns_per_m / (2 * g.fore_aft_mass_kg);
  const double w = std::sqrt(g.fore_aft_stiffness_n_per_m / g.fore_aft_mass_kg - decay * decay);
  EXPECT_NEAR(ev[0].real(), -decay, 1e-9 * w);
  EXPECT_NEAR(std::abs(ev[0].imag()), w, 1e-9 * w);
  const QuasiSteadyState q = quasi_steady_state(m, StabilityPhase::braked_slide);
  ASSERT_TRUE(q.converged);
  const ContactState cs = contact_state(m, q.mode, q.t, q.x);
  const double along_x = cs.force.Fx * std::cos(q.x[kPsi]) - cs.force.Fy * std::sin(q.x[kPsi]);
  EXPECT_LT(along_x, -1e4);  // the brake's drag
  EXPECT_NEAR(q.x[kX], along_x / g.fore_aft_stiffness_n_per_m, 1e-9);
  // With the strut rigid fore-aft the state x stays inert and out of the linearisation.
  const QuasiSteadyState rigid = quasi_steady_state(
      make_gear_model(GearConfig{}, ContactModel::coupled), StabilityPhase::braked_slide);
  EXPECT_EQ(std::count(rigid.states.begin(), rigid.states.end(), kX), 0);
  EXPECT_EQ(q.states.size(), rigid.states.size() + 2);
}

// A twin gear: the drag difference of the two wheels acts on the torsion through half the wheel
// spacing. Rolling straight without brakes and without trail, the torsional damping from the
// longitudinal slip, sum_i l_i^2 C_x N_i / V, of a twin at l = 0 with spacing 2L equals that of
// one wheel at the offset L (2 L^2 C_x (N/2) / V = L^2 C_x N / V); every other term of
// d(psi'')/d(psi') is independent of the offset. Each wheel's spin feels its own drag.
TEST(LinearStability, TwinGearsOffsetLeverIsHalfTheWheelSpacing) {
  const double L = 0.3;
  GearConfig single;
  single.structure.trail_m = 0.0;
  single.structure.offset_m = L;
  GearConfig twin = single;
  twin.structure.offset_m = 0.0;
  twin.structure.wheel_spacing_m = 2 * L;
  const GearModel ms = make_gear_model(single, ContactModel::von_schlippe);
  const GearModel mt = make_gear_model(twin, ContactModel::von_schlippe);
  GearState x = GearState::Zero();
  x[kSpin] = x[kSpin2] = single.scenario.forward_speed_mps / single.structure.wheel_radius_m;
  const GearMode rolling{true, true, false};
  const GearJacobian Js = gear_jacobian(ms, rolling, 10.0, x);
  const GearJacobian Jt = gear_jacobian(mt, rolling, 10.0, x);
  const double I = single.structure.torsional_inertia_kgm2, V = single.scenario.forward_speed_mps;
  const double slip_damping =
      L * L * single.rolling.longitudinal_slip_coefficient * single.scenario.static_load_n / V;
  ASSERT_GT(slip_damping, 1e3);  // the lever matters here
  EXPECT_NEAR(Jt(kPsiDot, kPsiDot), Js(kPsiDot, kPsiDot), 1e-5 * slip_damping / I);
  // The two wheels' drags respond to psi' with opposite signs, each half the single wheel's.
  EXPECT_NEAR(Jt(kSpin, kPsiDot), 0.5 * Js(kSpin, kPsiDot), 1e-5 * std::abs(Js(kSpin, kPsiDot)));
  EXPECT_NEAR(Jt(kSpin2, kPsiDot), -0.5 * Js(kSpin, kPsiDot), 1e-5 * std::abs(Js(kSpin, kPsiDot)));
  // The twin's second spin is a state of its quasi-steady problems; a single wheel's is not.
  const QuasiSteadyState qt = quasi_steady_state(make_gear_model(twin, ContactModel::coupled),
                                                 StabilityPhase::braked_slide);
  EXPECT_TRUE(qt.converged);
  EXPECT_EQ(std::count(qt.states.begin(), qt.states.end(), kSpin2), 1);
  EXPECT_NEAR(qt.x[kSpin2], qt.x[kSpin], 1e-6 * qt.x[kSpin]);  // symmetric at l = 0
}

// The fall of friction with slip speed, split off the friction terms: zero when f is constant;
// with the wheel far beside the strut axis (0.45 m, braked at 58 m/s) it is what feeds the
// torsion: the friction terms without it would drain energy.
TEST(LinearStability, FallOfFrictionIsWhatFeedsTheLargeOffset) {
  GearConfig c;
  c.structure.offset_m = 0.45;
  c.scenario.forward_speed_mps = 58.0;
  StabilityOptions o;
  o.simulate_perturbation = false;
  const StabilityReport r =
      assess_stability(make_gear_model(c, ContactModel::coupled), StabilityPhase::braked_slide, o);
  ASSERT_GT(r.growth_rate_per_s, 0.0);
  const EnergyPerCycle& e = r.energy;
  const double friction =
      e.spin_torque + e.trail_lateral_force + e.offset_drag + e.lateral_friction;
  EXPECT_GT(e.fall_of_friction, 0.0);
  EXPECT_LT(friction - e.fall_of_friction, 0.0) << friction << " " << e.fall_of_friction;
  GearConfig flat = c;
  flat.tire.friction.kinetic_coefficient = flat.tire.friction.static_coefficient;
  const StabilityReport q = assess_stability(make_gear_model(flat, ContactModel::coupled),
                                             StabilityPhase::braked_slide, o);
  EXPECT_NEAR(q.energy.fall_of_friction, 0.0, 1e-9);
  EXPECT_LT(q.growth_rate_per_s, 0.0);  // constant f: sliding friction damps
}

// The drag slope -dFx/dvx at the braked state: read through the tire's longitudinal deflection
// (relaxation on, the default) it equals the one read through the wheel speed (relaxation off),
// and for the decoupled model it is the closed form of Fx = -N f(w) vx / w:
// -dFx/dvx = N (f'(w) vx^2 / w^2 + f(w) vy^2 / w^3), negative where f falls.
TEST(LinearStability, DragSlopeIsTheSameThroughTheDeflectionAndTheWheelSpeed) {
  StabilityOptions o;
  o.simulate_perturbation = false;
  for (ContactModel cm : {ContactModel::coupled, ContactModel::decoupled}) {
    GearConfig relaxed;
    GearConfig rigid = relaxed;
    rigid.tire.longitudinal_relaxation_length_m = 0.0;
    ASSERT_GT(relaxed.tire.longitudinal_relaxation_length_m, 0.0);
    const GearModel m = make_gear_model(relaxed, cm);
    const StabilityReport a = assess_stability(m, StabilityPhase::braked_slide, o);
    const StabilityReport b =
        assess_stability(make_gear_model(rigid, cm), StabilityPhase::braked_slide, o);
    ASSERT_TRUE(a.state.converged && b.state.converged) << to_string(cm);
    EXPECT_LT(a.drag_slope_ns_per_m, 0.0) << to_string(cm);
    EXPECT_NEAR(a.drag_slope_ns_per_m, b.drag_slope_ns_per_m,
                1e-3 * std::abs(b.drag_slope_ns_per_m))
        << to_string(cm);
    if (cm != ContactModel::decoupled) continue;
    const ContactState cs = contact_state(m, a.state.mode, a.state.t, a.state.x);
    const double vx = cs.slip.vx, vy = cs.slip.vy, w = std::hypot(vx, vy), h = 1e-5 * w;
    const auto& fc = m.config.tire.friction;
    const double df = (friction_at(fc, w + h) - friction_at(fc, w - h)) / (2 * h);
    const double expected =
        cs.load_n * (df * vx * vx / (w * w) + friction_at(fc, w) * vy * vy / (w * w * w));
    EXPECT_NEAR(a.drag_slope_ns_per_m, expected, 0.02 * std::abs(expected));
  }
}
