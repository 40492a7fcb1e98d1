// The landing-gear model (docs/shimmy.md): free frequencies with friction off, Somieski's
// nose-gear stability boundary against its Routh-Hurwitz form, convergence with the
// tolerance, dissipation, mirror symmetry, the oscillation analysis and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/oscillation.hpp"
#include "contensou/gear/stability_map.hpp"
#include "eigenvalues.hpp"

using namespace contensou;

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// A gear that never lands: free vibration from an initial deflection.
GearConfig airborne(double psi0, double y0) {
  GearConfig c;
  c.scenario.touchdown_time_s = 10.0;
  c.scenario.end_time_s = 0.5;
  c.scenario.braking = false;
  c.scenario.initial_torsion_rad = psi0;
  c.scenario.initial_lateral_m = y0;
  return c;
}

OscillationEstimate analyse(const LandingRun& r, int position, int rate) {
  std::vector<double> t, v, p;
  for (const LandingSample& s : r.samples) {
    t.push_back(s.t);
    p.push_back(s.x[position]);
    v.push_back(s.x[rate]);
  }
  return analyse_oscillation(t, v, p);
}

}  // namespace

TEST(Oscillation, RecoversFrequencyGrowthAndAmplitudeOfADampedSine) {
  for (double sigma : {-3.0, 0.0, 2.0}) {
    const double f = 17.0, w = kTwoPi * f;
    std::vector<double> t, x, v;
    for (int i = 0; i <= 20000; ++i) {
      const double ti = i * 5e-5;
      t.push_back(ti);
      x.push_back(0.01 * std::exp(sigma * ti) * std::sin(w * ti) + 0.3);  // offset is ignored
      v.push_back(0.01 * std::exp(sigma * ti) * (sigma * std::sin(w * ti) + w * std::cos(w * ti)));
    }
    const OscillationEstimate e = analyse_oscillation(t, v, x);
    ASSERT_TRUE(e.valid());
    EXPECT_NEAR(e.frequency_hz, f, 0.01);
    EXPECT_NEAR(e.growth_rate_per_s, sigma, 0.02);
    EXPECT_NEAR(e.last_amplitude, 0.01 * std::exp(sigma * 0.97), 0.01 * std::exp(sigma) * 0.05);
  }
}

TEST(Oscillation, TooFewCrossingsAreInvalidAndLengthsMustMatch) {
  std::vector<double> t{0, 1, 2, 3}, v{1, -1, 1, -1}, x{0, 0, 0, 0};
  EXPECT_FALSE(analyse_oscillation(t, v, x).valid());
  std::vector<double> shorter{0, 1};
  EXPECT_THROW(analyse_oscillation(t, shorter, x), InvalidArgument);
}

TEST(LandingGear, FreeTorsionalAndLateralFrequenciesWithFrictionOff) {
  const GearConfig c = airborne(0.01, 0.002);
  const GearStructure& g = c.structure;
  const LandingRun r = simulate_landing(make_gear_model(c, ContactModel::coupled), {1e-9});
  // Damped oscillators: omega_d = sqrt(k/I - (c/2I)^2), decay c / 2I.
  const double zt = g.torsional_damping_nms_per_rad / (2 * g.torsional_inertia_kgm2);
  const double ft =
      std::sqrt(g.torsional_stiffness_nm_per_rad / g.torsional_inertia_kgm2 - zt * zt) / kTwoPi;
  const double zy = g.lateral_damping_ns_per_m / (2 * g.lateral_mass_kg);
  const double fy = std::sqrt(g.lateral_stiffness_n_per_m / g.lateral_mass_kg - zy * zy) / kTwoPi;
  const OscillationEstimate et = analyse(r, kPsi, kPsiDot), ey = analyse(r, kY, kYDot);
  EXPECT_NEAR(et.frequency_hz, ft, 1e-3 * ft);
  EXPECT_NEAR(et.growth_rate_per_s, -zt, 0.02);
  EXPECT_NEAR(ey.frequency_hz, fy, 1e-3 * fy);
  EXPECT_NEAR(ey.growth_rate_per_s, -zy, 0.02);
  EXPECT_TRUE(r.events.empty());
  EXPECT_EQ(r.metrics.torsion.half_cycles, et.half_cycles);  // window: the whole run
}

namespace {

// Somieski's nose gear: torsion psi with a stretched-string tire (lambda), no lateral bending.
// Linearised numerically (central differences of gear_rhs) about straight rolling.
Eigen::Matrix3d nose_gear_matrix(const GearModel& m) {
  GearMode mode;
  mode.loaded = true;
  mode.rolling = true;
  const double t = m.config.scenario.touchdown_time_s + 2 * m.config.scenario.load_ramp_s;
  GearState x0 = GearState::Zero();
  x0[kSpin] = m.config.scenario.forward_speed_mps / m.config.structure.wheel_radius_m;
  const int idx[3] = {kPsi, kPsiDot, kLambda};
  Eigen::Matrix3d A;
  for (int j = 0; j < 3; ++j) {
    const double h = 1e-7;
    GearState xp = x0, xm = x0;
    xp[idx[j]] += h;
    xm[idx[j]] -= h;
    const GearState d = (gear_rhs(m, mode, t, xp) - gear_rhs(m, mode, t, xm)) / (2 * h);
    for (int i = 0; i < 3; ++i) A(i, j) = d[idx[i]];
  }
  return A;
}

double max_real_eigenvalue(const Eigen::Matrix3d& A) {
  return contensou::testing::eigenvalues(A).real().maxCoeff();
}

GearConfig nose_gear(double V, double trail) {
  GearConfig c;
  c.scenario.forward_speed_mps = V;
  c.scenario.drift_speed_mps = 0.0;
  c.scenario.braking = false;
  c.structure.trail_m = trail;
  c.structure.offset_m = 0.0;
  return c;
}

// Routh-Hurwitz: the characteristic polynomial of
//   I psi'' = -k psi - d psi' - q lambda,  lambda' = V psi + (e - a) psi' - (V / sigma) lambda,
// q = N (e C_Fa + C_Ma) / sigma, d = c_psi + kappa_t / V, is s^3 + a2 s^2 + a1 s + a0 with
//   a2 = d/I + V/sigma, a1 = d V / (I sigma) + (q (e - a) + k) / I, a0 = V (k / sigma + q) / I,
// stable iff a2, a0 > 0 and a2 a1 > a0. The boundary a2 a1 = a0 is a quadratic in d.
double routh_hurwitz_critical_damping(const GearConfig& c, double patch_radius) {
  const double I = c.structure.torsional_inertia_kgm2,
               k = c.structure.torsional_stiffness_nm_per_rad;
  const double V = c.scenario.forward_speed_mps, N = c.scenario.static_load_n;
  const double sigma = c.rolling.relaxation_length_m, e = c.structure.trail_m, a = patch_radius;
  const double q =
      N * (e * c.rolling.cornering_coefficient + c.rolling.aligning_coefficient_m) / sigma;
  const double K1 = (q * (e - a) + k) / I, a0 = V * (k / sigma + q) / I;
  const double A = V / (I * I * sigma), B = K1 / I + V * V / (I * sigma * sigma),
               C = V / sigma * K1 - a0;
  const double d = (-B + std::sqrt(B * B - 4 * A * C)) / (2 * A);
  return d - c.rolling.tread_moment_nm2_per_rad / V;
}

}  // namespace

TEST(LandingGear, SomieskiNoseGearBoundaryMatchesRouthHurwitz) {
  for (const auto& [V, e] : {std::pair{30.0, 0.05}, std::pair{70.0, 0.05}, std::pair{70.0, 0.12},
                             std::pair{100.0, 0.0}}) {
    GearConfig c = nose_gear(V, e);
    const GearModel probe = make_gear_model(c, ContactModel::von_schlippe);
    const double R =
        contact_state(probe, {true, true, false}, 1.0, GearState::Zero()).patch_radius_m;
    const double expected = routh_hurwitz_critical_damping(c, R);
    ASSERT_GT(expected, 1.0) << "choose cases with a positive critical damping";
    // Numerical boundary: bisection on the sign of the largest real part.
    double lo = 0.0, hi = 10.0 * expected;
    for (int i = 0; i < 60; ++i) {
      c.structure.torsional_damping_nms_per_rad = 0.5 * (lo + hi);
      const bool unstable =
          max_real_eigenvalue(nose_gear_matrix(make_gear_model(c, ContactModel::von_schlippe))) > 0;
      (unstable ? lo : hi) = 0.5 * (lo + hi);
    }
    EXPECT_NEAR(0.5 * (lo + hi), expected, 1e-5 * expected) << "V = " << V << ", e = " << e;
  }
}

TEST(LandingGear, SimulatedNoseGearGrowsBelowTheBoundaryAndDecaysAbove) {
  GearConfig c = nose_gear(70.0, 0.05);
  c.structure.lateral_stiffness_n_per_m = 1e10;  // a rigid strut laterally
  c.structure.lateral_damping_ns_per_m = 3.5e6;
  c.scenario.initial_torsion_rad = 1e-3;
  const GearModel probe = make_gear_model(c, ContactModel::von_schlippe);
  const double R = contact_state(probe, {true, true, false}, 1.0, GearState::Zero()).patch_radius_m;
  const double critical = routh_hurwitz_critical_damping(c, R);
  for (double factor : {0.7, 1.3}) {
    c.structure.torsional_damping_nms_per_rad = factor * critical;
    const LandingRun r = simulate_landing(make_gear_model(c, ContactModel::von_schlippe), {1e-8});
    ASSERT_TRUE(r.metrics.torsion.valid());
    if (factor < 1)
      EXPECT_GT(r.metrics.torsion.growth_rate_per_s, 0.1);
    else
      EXPECT_LT(r.metrics.torsion.growth_rate_per_s, -0.1);
  }
}

TEST(LandingGear, ResultsConvergeAsTheToleranceTightens) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  std::vector<double> growth, peak;
  for (double rtol : {1e-5, 1e-7, 1e-9}) {
    const LandingRun r = simulate_landing(m, {rtol, 5e-4, false});
    growth.push_back(r.metrics.torsion.growth_rate_per_s);
    peak.push_back(r.metrics.peak_torsion_rad);
  }
  EXPECT_LT(std::abs(growth[1] - growth[2]), 0.05);
  EXPECT_LT(std::abs(peak[1] - peak[2]), 0.01 * peak[2]);
  EXPECT_LE(std::abs(peak[1] - peak[2]), std::abs(peak[0] - peak[2]) + 1e-12);
}

TEST(LandingGear, SlidingFrictionDissipatesAlongTheWholeLanding) {
  for (ContactModel cm : {ContactModel::coupled, ContactModel::decoupled}) {
    const LandingRun r = simulate_landing(make_gear_model(GearConfig{}, cm));
    int sliding = 0;
    for (const LandingSample& s : r.samples) {
      if (s.rolling || s.contact.load_n <= 0) continue;
      ++sliding;
      EXPECT_LE(friction_power(s.contact.force, s.contact.slip), 1e-9 * s.contact.load_n)
          << to_string(cm) << " at t = " << s.t;
    }
    EXPECT_GT(sliding, 100) << to_string(cm);
  }
}

TEST(LandingGear, MirroredGearGivesMirroredMotion) {
  GearConfig c;
  GearConfig m = c;
  m.structure.offset_m = -c.structure.offset_m;
  m.scenario.drift_speed_mps = -c.scenario.drift_speed_mps;
  for (ContactModel cm : {ContactModel::coupled, ContactModel::von_schlippe}) {
    const LandingRun a = simulate_landing(make_gear_model(c, cm), {1e-9});
    const LandingRun b = simulate_landing(make_gear_model(m, cm), {1e-9});
    ASSERT_EQ(a.samples.size(), b.samples.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < a.samples.size(); ++i)
      worst = std::max(worst, std::abs(a.samples[i].x[kPsi] + b.samples[i].x[kPsi]));
    EXPECT_LT(worst, 1e-3 * a.metrics.peak_torsion_rad) << to_string(cm);
    EXPECT_NEAR(a.samples.back().x[kSpin], b.samples.back().x[kSpin], 1e-6);
  }
}

TEST(LandingGear, EventsComeInTheirOrder) {
  const LandingRun r = simulate_landing(make_gear_model(GearConfig{}, ContactModel::coupled));
  std::vector<std::string> names;
  for (const LandingEvent& e : r.events) names.push_back(e.what);
  ASSERT_GE(names.size(), 5u);
  EXPECT_EQ(names[0], "load onset");
  EXPECT_EQ(names[1], "full load");  // spin-up ends after the 0.1 s ramp with these numbers
  EXPECT_EQ(names[2], "spin-up");
  EXPECT_EQ(names[3], "brake on");
  EXPECT_EQ(names[4], "sliding");  // the anti-skid's target slip 0.15 exceeds sliding_slip
  ASSERT_TRUE(r.spin_up_s.has_value());
  EXPECT_GT(*r.spin_up_s, 0.0);
  // At the end of spin-up the patch's slip ratio is rolling_slip.
  EXPECT_NEAR(r.events[2].t - GearConfig{}.scenario.touchdown_time_s, *r.spin_up_s, 1e-12);
}

TEST(LandingGear, ExactIntegralsRunAndAgreeOnTheTorsionalFrequency) {
  GearConfig c;
  c.scenario.end_time_s = 0.6;
  c.scenario.brake_off_s = 0.55;
  const LandingRun law = simulate_landing(make_gear_model(c, ContactModel::coupled), {1e-6});
  c.tire.exact_integrals = true;
  const LandingRun exact = simulate_landing(make_gear_model(c, ContactModel::coupled), {1e-6});
  ASSERT_TRUE(exact.metrics.torsion.valid());
  EXPECT_NEAR(exact.metrics.torsion.frequency_hz, law.metrics.torsion.frequency_hz,
              0.03 * law.metrics.torsion.frequency_hz);
  EXPECT_TRUE(std::isfinite(exact.metrics.torsion.growth_rate_per_s));
}

TEST(LandingGear, BadInputIsRejectedByName) {
  GearConfig c;
  c.structure.torsional_inertia_kgm2 = -1.0;
  try {
    validate(c);
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "structure.torsional_inertia_kgm2");
  }
  c = GearConfig{};
  c.scenario.brake_off_s = 0.1;  // before brake_on_s
  EXPECT_THROW(validate(c), InvalidArgument);
  c = GearConfig{};
  c.tire.law_coefficients = "magic";
  EXPECT_THROW(make_gear_model(c, ContactModel::coupled), InvalidArgument);
  EXPECT_THROW(contact_model_from_string("rolling"), InvalidArgument);
  EXPECT_EQ(gear_parameter(c, "structure.nope"), nullptr);
  EXPECT_THROW(simulate_landing(make_gear_model(GearConfig{}, ContactModel::coupled), {0.0}),
               InvalidArgument);
  EXPECT_THROW(stability_map(make_gear_model(GearConfig{}, ContactModel::coupled),
                             {"structure.nope", 0, 1, 2}, {"structure.offset_m", 0, 1, 2}, {}, {}),
               InvalidArgument);
}

TEST(StabilityMap, CellsMatchSingleRunsAndCoverTheGrid) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  const MapAxis x{"scenario.forward_speed_mps", 40.0, 70.0, 3};
  const MapAxis y{"structure.torsional_damping_nms_per_rad", 0.0, 300.0, 2};
  int calls = 0;
  const StabilityMap map = stability_map(m, x, y, {}, {}, 2, [&](int, int) { ++calls; });
  ASSERT_EQ(map.cells.size(), 6u);
  EXPECT_GE(calls, 1);
  const MapCell& cell = map.cells[1 * 3 + 2];  // x = 70, y = 300
  EXPECT_DOUBLE_EQ(cell.x, 70.0);
  EXPECT_DOUBLE_EQ(cell.y, 300.0);
  GearModel single = m;
  single.config.scenario.forward_speed_mps = 70.0;
  single.config.structure.torsional_damping_nms_per_rad = 300.0;
  const LandingRun r = simulate_landing(single);
  EXPECT_DOUBLE_EQ(cell.growth_rate_per_s, r.metrics.torsion.growth_rate_per_s);
  EXPECT_EQ(cell.shimmy, r.metrics.shimmy);
  // More torsional damping never makes the coupled gear less stable at the same speed.
  for (int i = 0; i < 3; ++i)
    EXPECT_LT(map.cells[static_cast<std::size_t>(3 + i)].growth_rate_per_s,
              map.cells[static_cast<std::size_t>(i)].growth_rate_per_s);
}

// The structured Jacobian against central differences of the right-hand side (brute force) for
// every contact model, in the sliding, rolling and braked modes, at states off equilibrium.
TEST(LandingGear, StructuredJacobianMatchesDifferencesOfTheRightHandSide) {
  for (bool exact : {false, true}) {
    for (ContactModel cm :
         {ContactModel::coupled, ContactModel::decoupled, ContactModel::von_schlippe}) {
      if (exact && cm != ContactModel::coupled) continue;
      for (double spacing : {0.0, 0.8}) {
        GearConfig c;
        c.structure.wheel_spacing_m = spacing;
        c.tire.exact_integrals = exact;
        c.structure.gyroscopic_length_m = 2.0;
        c.structure.freeplay_rad = 3.9e-3;  // psi = 4e-3 sits in the dead band's smoothed corner
        c.structure.fore_aft_stiffness_n_per_m = 2e6;
        const GearModel m = make_gear_model(c, cm);
        const double V = c.scenario.forward_speed_mps, r = c.structure.wheel_radius_m;
        for (bool brake : {false, true}) {
          for (bool rolling : {false, true}) {
            const GearMode mode{true, rolling, brake};
            GearState x;
            x << 1e-3, 0.02, 4e-3, 0.3, V * (rolling ? 0.97 : 0.6) / r, 2e-3, -4e-3, 0.05,
                V * (rolling ? 0.96 : 0.62) / r, 0.0, 0.0,  // carcass states: inert here
                1.5e-3, -1e-3;  // each wheel's longitudinal tire deflection u, u2
            const double t = c.scenario.touchdown_time_s + 0.6 * c.scenario.load_ramp_s;
            const GearJacobian J = gear_jacobian(m, mode, t, x);
            for (int j = 0; j < kStateSize; ++j) {
              const double h = 1e-6 * std::max(std::abs(x[j]), 1e-2);
              GearState xp = x, xm = x;
              xp[j] += h;
              xm[j] -= h;
              const GearState d = (gear_rhs(m, mode, t, xp) - gear_rhs(m, mode, t, xm)) / (2 * h);
              const double tol = (exact ? 1e-3 : 1e-5) * std::max(d.norm(), 1.0);
              EXPECT_LT((J.col(j) - d).norm(), tol)
                  << to_string(cm) << (exact ? " exact" : "") << " brake " << brake << " rolling "
                  << rolling << " column " << j << "\n"
                  << J.col(j).transpose() << "\n"
                  << d.transpose() << "\nspacing " << spacing;
            }
          }
        }
      }
    }
  }
}

TEST(LandingGear, StructuredAndDifferenceQuotientJacobiansGiveTheSameLanding) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  SolverOptions analytic{1e-9}, dq{1e-9};
  dq.analytic_jacobian = false;
  const LandingRun a = simulate_landing(m, analytic), b = simulate_landing(m, dq);
  EXPECT_NEAR(a.metrics.peak_torsion_rad, b.metrics.peak_torsion_rad,
              1e-5 * b.metrics.peak_torsion_rad);
  EXPECT_NEAR(a.metrics.torsion.growth_rate_per_s, b.metrics.torsion.growth_rate_per_s, 1e-3);
  EXPECT_LT(a.rhs_evaluations, b.rhs_evaluations);  // no difference quotients
}

// Gyroscopic coupling (g = I_w Omega / L): the airborne, undamped gear with the wheel spinning
// has the frequencies of two gyroscopically coupled oscillators,
//   (k_psi - I w^2)(k_y - m w^2) = g^2 w^2   (a quadratic in w^2),
// and no growth or decay (the coupling does no work).
TEST(LandingGear, GyroscopicCouplingGivesTheCoupledOscillatorFrequencies) {
  GearConfig c;
  c.structure.gyroscopic_length_m = 1.5;
  c.structure.torsional_damping_nms_per_rad = 0.0;
  c.structure.lateral_damping_ns_per_m = 0.0;
  const GearModel m = make_gear_model(c, ContactModel::von_schlippe);
  const GearStructure& g = c.structure;
  GearState x = GearState::Zero();
  x[kSpin] = c.scenario.forward_speed_mps / g.wheel_radius_m;
  const GearJacobian J = gear_jacobian(m, GearMode{false, true, false}, 0.0, x);
  const int idx[4] = {kY, kYDot, kPsi, kPsiDot};
  Eigen::Matrix4d A;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) A(i, j) = J(idx[i], idx[j]);
  const Eigen::VectorXcd ev = contensou::testing::eigenvalues(A);
  const double gy = g.wheel_inertia_kgm2 * x[kSpin] / g.gyroscopic_length_m;
  const double I = g.torsional_inertia_kgm2, k1 = g.torsional_stiffness_nm_per_rad;
  const double M = g.lateral_mass_kg, k2 = g.lateral_stiffness_n_per_m;
  // I M W^2 - (I k2 + M k1 + gy^2) W + k1 k2 = 0, W = w^2.
  const double b = I * k2 + M * k1 + gy * gy, disc = std::sqrt(b * b - 4 * I * M * k1 * k2);
  std::vector<double> expected{std::sqrt((b - disc) / (2 * I * M)),
                               std::sqrt((b + disc) / (2 * I * M))};
  std::vector<double> found;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(ev[i].real(), 0.0, 1e-9 * std::abs(ev[i]));
    if (ev[i].imag() > 0) found.push_back(ev[i].imag());
  }
  std::sort(found.begin(), found.end());
  ASSERT_EQ(found.size(), 2u);
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(found[i], expected[i], 1e-9 * expected[i]);
  // The coupling is not negligible: the frequencies move from the uncoupled ones.
  EXPECT_GT(std::abs(found[1] - std::sqrt(k1 / I)), 1e-3 * std::sqrt(k1 / I));
}

// The default Adams-Moulton integrator and BDF agree on the landing to the tolerance's level
// (rtol 1e-7: both within 2e-3 1/s and 1e-5 of the peak of a run at rtol 1e-10), and Adams takes
// fewer steps on the gear's lightly damped modes (docs/shimmy.md, "Numerics").
TEST(LandingGear, AdamsAndBdfGiveTheSameLanding) {
  for (ContactModel cm : {ContactModel::coupled, ContactModel::von_schlippe}) {
    const GearModel m = make_gear_model(GearConfig{}, cm);
    SolverOptions adams, bdf, reference{1e-10};
    adams.record = bdf.record = reference.record = false;
    bdf.method = reference.method = Integrator::bdf;
    const LandingRun a = simulate_landing(m, adams), b = simulate_landing(m, bdf),
                     r = simulate_landing(m, reference);
    for (const LandingRun* run : {&a, &b}) {
      EXPECT_NEAR(run->metrics.torsion.growth_rate_per_s, r.metrics.torsion.growth_rate_per_s, 2e-3)
          << to_string(cm);
      EXPECT_NEAR(run->metrics.peak_torsion_rad, r.metrics.peak_torsion_rad,
                  1e-5 * r.metrics.peak_torsion_rad)
          << to_string(cm);
      EXPECT_EQ(run->metrics.shimmy, r.metrics.shimmy);
      ASSERT_EQ(run->events.size(), r.events.size()) << to_string(cm);
      for (std::size_t i = 0; i < r.events.size(); ++i) {
        EXPECT_EQ(run->events[i].what, r.events[i].what);
        EXPECT_NEAR(run->events[i].t, r.events[i].t, 1e-6);
      }
    }
    EXPECT_LT(a.steps, b.steps) << to_string(cm);
    EXPECT_EQ(a.convergence_failures, 0) << to_string(cm);
  }
}

// Like for like: the string tire touches down with the wheel at rest, as the dry-friction models
// do, and slides on its friction circle until the wheel has spun up. Its drag is then mu N with
// the same f(w), so the spin-up (I Omega' = -Fx r until Omega r = (1 - rolling_slip) V) takes
// the time the coupled model's does, and mid-way the two drags agree.
TEST(LandingGear, StringTireSpinsUpFromRestLikeTheSlidingModels) {
  SolverOptions o;
  o.record = true;
  GearConfig c;
  c.scenario.braking = false;
  const LandingRun string_tire =
      simulate_landing(make_gear_model(c, ContactModel::von_schlippe), o);
  const LandingRun coupled = simulate_landing(make_gear_model(c, ContactModel::coupled), o);
  ASSERT_TRUE(string_tire.spin_up_s && coupled.spin_up_s);
  EXPECT_NEAR(*string_tire.spin_up_s, *coupled.spin_up_s, 0.05 * *coupled.spin_up_s);
  EXPECT_EQ(string_tire.samples.front().x[kSpin], 0.0);
  const double mid = c.scenario.touchdown_time_s + 0.5 * *coupled.spin_up_s;
  const auto at = [&](const LandingRun& r) {
    return *std::min_element(r.samples.begin(), r.samples.end(),
                             [&](const LandingSample& a, const LandingSample& b) {
                               return std::abs(a.t - mid) < std::abs(b.t - mid);
                             });
  };
  const LandingSample s = at(string_tire), k = at(coupled);
  EXPECT_GT(s.contact.slip_ratio, 0.3);  // still sliding half-way
  EXPECT_NEAR(s.contact.force.Fx, k.contact.force.Fx, 0.05 * std::abs(k.contact.force.Fx));
  bool spin_up_event = false;
  for (const LandingEvent& e : string_tire.events) spin_up_event |= e.what == "spin-up";
  EXPECT_TRUE(spin_up_event);
}

// Issue 22 (Bounds): a caller's stop request ends a landing and a map with Interrupted, which a
// map does not file as a cell's error.
TEST(StabilityMap, AStopRequestStopsALandingAndTheMap) {
  const GearModel m = make_gear_model(GearConfig{}, ContactModel::coupled);
  SolverOptions stopped;
  stopped.stop = [] { return true; };
  EXPECT_THROW(simulate_landing(m, stopped), Interrupted);
  const MapAxis x{"scenario.forward_speed_mps", 40.0, 70.0, 3};
  const MapAxis y{"structure.torsional_damping_nms_per_rad", 0.0, 300.0, 2};
  EXPECT_THROW(stability_map(m, x, y, stopped, {}, 2), Interrupted);
  // Fired mid-way through a landing: the integration stops within a step of it.
  std::atomic<long> polls{0};
  SolverOptions midway;
  midway.stop = [&polls] { return ++polls > 200; };
  EXPECT_THROW(simulate_landing(m, midway), Interrupted);
  EXPECT_EQ(polls.load(), 201);
}

// The step budget of a landing: one that needs more steps than solver.max_total_steps ends with
// an error naming the budget and the input that is furthest from a landing gear's (a negative
// torsional damping here), not after minutes; 0 is no bound, a negative budget is refused. (The
// app's run that integrated on for minutes is tests/reliability/cases/shimmy.txt's.)
// A stepped landing (the gear FMU): a tolerance CVODE cannot meet is refused by its range, not
// by CVODE's flag; a communication step far longer than max_steps can cover names the step.
TEST(LandingGear, AStepperNamesItsToleranceRangeAndAStepTooLong) {
  const GearModel model = make_gear_model(GearConfig{}, ContactModel::coupled);
  for (const double rtol : {1e-300, 1e-15, 0.1, 1.0}) {
    SolverOptions o;
    o.relative_tolerance = rtol;
    try {
      LandingStepper stepper(model, o, LandingInputs{});
      ADD_FAILURE() << "relative_tolerance " << rtol << " accepted";
    } catch (const contensou::InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("solver.relative_tolerance = "), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("must lie in [1e-14, 0.1)"), std::string::npos);
    }
  }
  SolverOptions o;
  o.max_steps = 500;
  LandingStepper stepper(model, o, LandingInputs{});
  try {
    stepper.advance_to(1e300);
    ADD_FAILURE() << "a step of 1e300 s ended";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("in a step of 1e+300 s from t = 0 s"), std::string::npos)
        << e.what();
  }
}

TEST(LandingGear, ALandingPastItsStepBudgetEndsNamingIt) {
  GearConfig c;
  c.structure.torsional_damping_nms_per_rad = -100.0;
  SolverOptions o;
  o.record = false;
  o.max_total_steps = 300;  // a landing takes about 1500
  try {
    simulate_landing(make_gear_model(c, ContactModel::coupled), o);
    ADD_FAILURE() << "the landing ended within 300 steps";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("solver.max_total_steps = 300"), std::string::npos) << m;
    EXPECT_NE(m.find("structure.torsional_damping_nms_per_rad = -100 (negative"), std::string::npos)
        << m;
  }
  o.max_total_steps = 0;
  EXPECT_GT(simulate_landing(make_gear_model(c, ContactModel::coupled), o).steps, 300);
  o.max_total_steps = -1;
  EXPECT_THROW(simulate_landing(make_gear_model(GearConfig{}, ContactModel::coupled), o),
               contensou::InvalidArgument);
}

// The inputs named as far from the default gear's: none for the default gear; a negative value
// where the default is positive comes first, then a value 1e3 times the default's with its
// decades; a value 10 times off is not named.
TEST(LandingGear, UnusualInputsAreTheNegativeThenTheDecadesOff) {
  EXPECT_EQ(unusual_gear_inputs(GearConfig{}), "");
  GearConfig c;
  c.structure.torsional_damping_nms_per_rad = -100.0;
  c.structure.offset_m *= 1e3;
  c.structure.torsional_stiffness_nm_per_rad *= 10.0;
  const std::string u = unusual_gear_inputs(c);
  const std::size_t negative = u.find("structure.torsional_damping_nms_per_rad = -100 (negative");
  const std::size_t offset = u.find("structure.offset_m = ");
  ASSERT_NE(negative, std::string::npos) << u;
  ASSERT_NE(offset, std::string::npos) << u;
  EXPECT_LT(negative, offset) << u;
  EXPECT_NE(u.find("(1e3x off the default)"), std::string::npos) << u;
  EXPECT_EQ(u.find("torsional_stiffness"), std::string::npos) << u;
}
