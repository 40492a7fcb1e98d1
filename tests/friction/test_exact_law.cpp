// The exact law (exact_law.hpp) against independent oracles: the adaptive integrator on random
// kinematics for every profile kind (constant friction and f(w) inside), Contensou's closed
// forms of the uniform disk (theory.md section 3), the pure-spin and pure-sliding limits, the
// Jacobian against central differences of the law and of the integrator, a Newton solver on an
// implicit Euler step, dissipation, the sliding-spinning disk's stopping ratio 0.6530, and bad
// input.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "closed_forms.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/impl/forward_derivative.hpp"
#include "contensou/friction/slip_speed_measure.hpp"
#include "jet_checks.hpp"
#include "patches.hpp"

using namespace contensou;

namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr int kRandomPoints = 2000;  // the sanitizer build runs the same checks on fewer points
#else
constexpr int kRandomPoints = 100000;
#endif

struct Case {
  const char* name;
  ContactPatch patch;
};

std::vector<Case> profile_kinds() {
  std::vector<Case> out;
  ContactPatch u = test_support::uniform_patch();
  out.push_back({"uniform", u});
  ContactPatch h = test_support::uniform_patch();
  h.profile = hertz_profile();
  h.profile.ky = 0.2;
  out.push_back({"hertz", h});
  ContactPatch s = seed_tire_patch();
  s.profile.kx = 0.14;
  s.profile.ky = -0.05;
  s.kappa = 0.7;
  out.push_back({"seed", s});
  ContactPatch c = seed_tire_patch();
  c.profile.clip_negative = true;
  c.kappa = 1.4;
  out.push_back({"clipped", c});
  ContactPatch t = seed_tire_patch();
  t.profile = test_support::kinked_table_profile(101);
  t.profile.kx = 0.14;
  out.push_back({"table101", t});
  return out;
}

// Random kinematics with |v| / (|omega| R) log-uniform over 6 decades, a tenth within 1 % of the
// rim, and exact zeros (pure spin, pure sliding, rest).
Kinematics<double> random_kinematics(std::mt19937& rng, double R, int i) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double angle = std::numbers::pi * U(rng);
  double eps = std::exp(6.9 * U(rng));
  if (i % 10 == 0) eps = std::exp(0.01 * U(rng));
  const double w = std::exp(4.0 * U(rng)) * (U(rng) > 0 ? 1.0 : -1.0);
  const double v = eps * std::abs(w) * R;
  if (i % 97 == 0) return {0.0, 0.0, w};
  if (i % 89 == 0) return {v * std::cos(angle), v * std::sin(angle), 0.0};
  if (i % 83 == 0) return {0.0, 0.0, 0.0};
  return {v * std::cos(angle), v * std::sin(angle), w};
}

double relative_error(const Resultants<double>& a, const Resultants<double>& b, double fN,
                      double R) {
  return std::max(
      {std::abs(a.Fx - b.Fx) / fN, std::abs(a.Fy - b.Fy) / fN, std::abs(a.Mz - b.Mz) / (fN * R)});
}

}  // namespace

// Item: the error against the adaptive integrator at 1e-13 stays below the certified bound,
// which is below the requested tolerance, on random kinematics for every profile kind.
TEST(ExactLaw, MatchesIntegratorOnRandomKinematicsForEveryProfileKind) {
  for (const Case& c : profile_kinds()) {
    const ExactModel<double> model = make_exact_model(c.patch);
    const ExactLaw law = make_exact_law(model);
    EXPECT_TRUE(law.reached) << c.name;
    EXPECT_LE(law.achieved, 1e-8) << c.name;
    EXPECT_LE(law.bytes(), 1u << 20) << c.name;
    const double fN = model.friction * normal_load(c.patch), R = model.radius;
    std::mt19937 rng(7);
    const int points = std::string(c.name) == "table101" ? kRandomPoints / 50 : kRandomPoints;
    double worst = 0.0;
    for (int i = 0; i < points; ++i) {
      const Kinematics<double> k = random_kinematics(rng, R, i);
      const Resultants<double> e = exact_resultants(model, k, {1e-13}).resultants;
      worst = std::max(worst, relative_error(exact_law_resultants(law, k), e, fN, R));
    }
    EXPECT_LE(worst, law.achieved) << c.name;
    RecordProperty(std::string(c.name) + "_worst", format_value(worst));
  }
}

// Friction falling (or rising) with the local slip speed inside the integrals: the same check on
// smooth profiles, exponents 1, 2 and 0.5, speeds up to 350 m/s against w_s = 5 m/s.
TEST(ExactLaw, MatchesIntegratorWithSlipSpeedFriction) {
  struct SlipCase {
    const char* name;
    PressureProfile profile;
    SlipSpeedFriction<double> law;
  };
  PressureProfile shifted = seed_tire_profile();
  shifted.kx = 0.14;
  PressureProfile hertz = hertz_profile();
  hertz.ky = 0.1;
  const SlipCase cases[] = {{"seed, delta 1", shifted, {0.3, 0.2, 5.0, 1.0}},
                            {"hertz rising, delta 2", hertz, {0.2, 0.35, 5.0, 2.0}},
                            {"uniform, delta 0.5", uniform_profile(), {0.8, 0.45, 5.0, 0.5}}};
  for (const SlipCase& c : cases) {
    ContactPatch p = seed_tire_patch();
    p.profile = c.profile;
    p.kappa = 0.85;
    p.slip_speed_friction = c.law;
    const ExactModel<double> model = make_exact_model(p);
    const ExactLaw law = make_exact_law(model);
    EXPECT_TRUE(law.reached) << c.name;
    EXPECT_LE(law.achieved, 1e-8) << c.name;
    const double fN = model.friction_scale * normal_load(p), R = model.radius;
    std::mt19937 rng(17);
    double worst = 0.0;
    for (int i = 0; i < 400; ++i) {
      Kinematics<double> k = random_kinematics(rng, R, i);
      k.vx *= 40.0;  // |omega| R up to 350 m/s
      k.vy *= 40.0;
      k.omega *= 40.0;
      const Resultants<double> e = exact_resultants(model, k, {1e-11}).resultants;
      worst = std::max(worst, relative_error(exact_law_resultants(law, k), e, fN, R));
    }
    EXPECT_LE(worst, law.achieved) << c.name;
    RecordProperty(std::string(c.name) + " worst", format_value(worst));
  }
}

// The slip-speed quadrature (a second method: ring integrals about the centre of sliding) gives
// the integrator's resultants for constant friction and for f = exp(-q nu) on the unit model.
TEST(SlipSpeedMeasure, AgreesWithIntegrator) {
  for (const Case& c : profile_kinds()) {
    ExactModel<double> unit = make_exact_model(c.patch);
    unit.load_area /= unit.radius * unit.radius;
    unit.radius = unit.pressure = unit.friction = unit.friction_scale = 1.0;
    unit.kx = unit.ky = 0.0;
    unit.kappa = 1.0;
    for (double t : {-0.999, -0.9, -0.5, -0.05, -1e-4, 0.0, 1e-4, 0.05, 0.5, 0.99}) {
      const SlipSpeedMeasure m = slip_speed_measure(unit, t);
      const double sigma = 0.5 * (1.0 + t), eta = 0.5 * (1.0 - t);
      for (double q : {0.0, 3.0}) {
        double A = 0.0, spin = 0.0;
        for (std::size_t k = 0; k < m.nu.size(); ++k) {
          const double g = std::exp(-q * m.nu[k]);
          A += m.weight[k][0] * g;
          spin += (m.weight[k][1] - m.weight[k][2]) * g;  // a - b
        }
        ExactModel<double> mq = unit;
        if (q > 0.0) mq.slip_speed = SlipSpeedFriction<double>{1.0, 0.0, 1.0 / q, 1.0};
        const bool table = unit.table().has_value();
        if (table && q > 0.0) continue;  // the integrator is too slow there at this tolerance
        const Resultants<double> r =
            exact_resultants(mq, Kinematics<double>{sigma, 0.0, eta}, {1e-12}).resultants;
        EXPECT_NEAR(A, -r.Fx, 2e-10 * unit.load_area) << c.name << " t " << t << " q " << q;
        EXPECT_NEAR(spin, -r.Mz, 2e-10 * unit.load_area) << c.name << " t " << t << " q " << q;
      }
    }
  }
}

// A table's slip-speed quadrature (its pieces between knot tangencies get as many nodes as their
// nearest singular points ask for, their rings are integrated eight at a time) against the same
// quadrature refined (16 nodes a panel and a piece, ring pieces to 1e-15), where the integrator
// is too slow: f = exp(-q nu) for q from 0 to 1e4 (the falling table's range at delta = 1), the
// 101-point table and a coarse 11-point one, centre inside, near the rim and outside.
TEST(SlipSpeedMeasure, TableRuleAgreesWithRefinedRule) {
  SlipSpeedMeasureOptions fine;
  fine.nodes = fine.piece_nodes = 16;
  fine.ring_nodes = 8;
  fine.ring_tolerance = 1e-15;
  SlipSpeedMeasureOptions build;  // as the f(w) table's build at the default tolerance
  build.largest_q = fine.largest_q = 1e6;
  build.ring_tolerance = 7e-12;
  build.nodes = 10;
  for (int knots : {101, 11}) {
    ContactPatch p = seed_tire_patch();
    p.profile = test_support::kinked_table_profile(knots);
    ExactModel<double> unit = make_exact_model(p);
    unit.load_area /= unit.radius * unit.radius;
    unit.radius = unit.pressure = unit.friction = unit.friction_scale = 1.0;
    for (double t : {-0.99, -0.9275, -0.43, -0.1, -1e-3, 0.0, 0.02, 0.3, 0.9}) {
      const SlipSpeedMeasure a = slip_speed_measure(unit, t, build);
      const SlipSpeedMeasure b = slip_speed_measure(unit, t, fine);
      for (double q : {0.0, 30.0, 1e3, 1e4}) {
        SlipMoments sa{}, sb{};
        for (std::size_t k = 0; k < a.nu.size(); ++k)
          for (int c = 0; c < 6; ++c) sa[c] += a.weight[k][c] * std::exp(-q * a.nu[k]);
        for (std::size_t k = 0; k < b.nu.size(); ++k)
          for (int c = 0; c < 6; ++c) sb[c] += b.weight[k][c] * std::exp(-q * b.nu[k]);
        for (int c = 0; c < 6; ++c)
          EXPECT_NEAR(sa[c], sb[c], 1e-11 * unit.load_area)
              << knots << " knots, t " << t << " q " << q << " integral " << c;
      }
    }
  }
}

// Contensou's closed forms (theory.md section 3), independent of the integrator: uniform
// pressure, kappa = 1, sliding along 30 degrees at ratios across the rim.
TEST(ExactLaw, UniformDiskMatchesContensouClosedForms) {
  const ContactPatch p = test_support::uniform_patch();
  const ExactLaw law = make_exact_law(make_exact_model(p));
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  for (double eps : {0.0, 1e-3, 0.1, 0.5, 0.9, 0.999, 1.0, 1.001, 1.1, 2.0, 10.0, 1e3}) {
    const double w = 7.0, v = eps * w * R, c = std::cos(0.52), s = std::sin(0.52);
    const Resultants<double> r = exact_law_resultants(law, Kinematics<double>{v * c, v * s, w});
    const auto [f_par, m] = test_support::uniform_closed_form(eps);
    EXPECT_NEAR(-(r.Fx * c + r.Fy * s) / fN, f_par, 1e-8) << eps;
    EXPECT_NEAR(-r.Fx * s + r.Fy * c, 0.0, 1e-8 * fN) << eps;  // no lateral force
    EXPECT_NEAR(-r.Mz / (fN * R), m, 1e-8) << eps;
  }
}

// theory.md section 2: omega = 0 gives F = -f N (cos phi, kappa sin phi) and, with a shift,
// Mz = -f C3 (t_y kx - t_x ky); v = 0 gives Mz = -sign(omega) M0 (1 + kappa)/2 and
// F = sign(omega) (M0 / 2R) D (ky, -kx).
TEST(ExactLaw, PureSpinAndPureSlidingLimits) {
  ContactPatch p = seed_tire_patch();
  p.kappa = 0.8;
  p.profile.kx = 0.1;
  p.profile.ky = -0.07;
  const ExactModel<double> model = make_exact_model(p);
  const ExactLaw law = make_exact_law(model);
  const double R = model.radius, f = p.friction, fN = f * normal_load(p);
  const double A1 = moment(p.profile, 1), A2 = moment(p.profile, 2), A3 = moment(p.profile, 3);
  const double M0 = fN * R * A2 / A1, C3 = std::numbers::pi * R * R * R * A3;
  for (double sgn : {1.0, -1.0}) {
    const Resultants<double> spin = exact_law_resultants(law, Kinematics<double>{0, 0, 9 * sgn});
    EXPECT_NEAR(spin.Mz, -sgn * M0 * (1 + p.kappa) / 2, 1e-8 * fN * R);
    EXPECT_NEAR(spin.Fx, sgn * M0 / (2 * R) * p.profile.ky, 1e-8 * fN);
    EXPECT_NEAR(spin.Fy, -sgn * M0 / (2 * R) * p.kappa * p.profile.kx, 1e-8 * fN);
  }
  const double phi = 2.2, cx = std::cos(phi), sy = std::sin(phi);
  const Resultants<double> slide =
      exact_law_resultants(law, Kinematics<double>{3 * cx, 3 * sy, 0.0});
  EXPECT_NEAR(slide.Fx, -fN * cx, 1e-8 * fN);
  EXPECT_NEAR(slide.Fy, -fN * p.kappa * sy, 1e-8 * fN);
  const double tx = cx, ty = p.kappa * sy;
  EXPECT_NEAR(slide.Mz, -f * p.reference_pressure_pa * C3 * (ty * p.profile.kx - tx * p.profile.ky),
              1e-8 * fN * R);
  const Resultants<double> rest = exact_law_resultants(law, Kinematics<double>{0, 0, 0});
  EXPECT_EQ(rest.Fx, 0.0);
  EXPECT_EQ(rest.Fy, 0.0);
  EXPECT_EQ(rest.Mz, 0.0);
}

// The Jacobian is the exact derivative of the interpolant (central differences of the law
// itself: test_law_properties); it matches those of the adaptive integrator away from
// eps = 1 +- 1e-3 (where the exact function has a log-singular derivative).
TEST(ExactLaw, JacobianMatchesDifferencesOfTheIntegrator) {
  for (const Case& c : profile_kinds()) {
    const ExactModel<double> model = make_exact_model(c.patch);
    const ExactLaw law = make_exact_law(model);
    const double fN = model.friction * normal_load(c.patch), R = model.radius;
    std::mt19937 rng(11);
    const int points = std::string(c.name) == "table101" ? 60 : 300;
    for (int i = 1; i < points; ++i) {
      Kinematics<double> k = random_kinematics(rng, R, i);
      if (k.omega == 0.0 && k.vx == 0.0) continue;
      const double speed = std::hypot(k.vx, k.vy) + std::abs(k.omega) * R;
      const ExactLawWithJacobian J = exact_law_resultants_with_jacobian(law, k);
      const double eps = std::hypot(k.vx, k.vy) / (std::abs(k.omega) * R);
      for (int col = 0; col < 3; ++col) {
        const double h = 1e-6 * speed / (col == 2 ? R : 1.0);
        Kinematics<double> a = k, b = k;
        (col == 0 ? a.vx : col == 1 ? a.vy : a.omega) += h;
        (col == 0 ? b.vx : col == 1 ? b.vy : b.omega) -= h;
        const double scale = fN / speed * (col == 2 ? R : 1.0);
        if (std::abs(eps - 1.0) < 2e-3 || eps < 1e-2 || eps > 1e2) continue;
        const Resultants<double> ea = exact_resultants(model, a, {1e-13}).resultants;
        const Resultants<double> eb = exact_resultants(model, b, {1e-13}).resultants;
        const double fd[3] = {(ea.Fx - eb.Fx) / (2 * h), (ea.Fy - eb.Fy) / (2 * h),
                              (ea.Mz - eb.Mz) / (2 * h)};
        for (int row = 0; row < 3; ++row) {
          const double s = scale * (row == 2 ? R : 1.0);
          EXPECT_NEAR(J.jacobian(row, col), fd[row], 1e-4 * s) << c.name << " eps " << eps;
        }
      }
    }
  }
}

// The hand-derived Jacobian (exact_law_jacobian.cpp) is the template's formula differentiated:
// it equals the template evaluated with forward derivatives, also with f(w), kappa and shifts,
// at the zeros and at subnormal speeds.
TEST(ExactLaw, HandJacobianEqualsForwardDerivatives) {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = 0.12;
  p.profile.ky = -0.04;
  p.kappa = 0.7;
  p.slip_speed_friction = SlipSpeedFriction<double>{0.35, 0.2, 4.0, 1.0};
  const ExactLaw laws[] = {make_exact_law(make_exact_model(p)),
                           make_exact_law(make_exact_model(test_support::uniform_patch()))};
  using D = detail::ForwardDerivative<3>;
  for (const ExactLaw& law : laws) {
    std::mt19937 rng(29);
    for (int i = 0; i < 3000; ++i) {
      Kinematics<double> k = random_kinematics(rng, law.radius, i);
      if (i % 50 == 1) k = {1e-200, -3e-201, 7.0};
      const ExactLawWithJacobian h = exact_law_resultants_with_jacobian(law, k);
      const Resultants<D> f = exact_law_resultants(
          law, law.parameters, Kinematics<D>{D(k.vx, 0), D(k.vy, 1), D(k.omega, 2)});
      const double scale = std::max({std::abs(f.Fx.a), std::abs(f.Fy.a), std::abs(f.Mz.a), 1.0});
      EXPECT_NEAR(h.resultants.Fx, f.Fx.a, 1e-13 * scale);
      EXPECT_NEAR(h.resultants.Mz, f.Mz.a, 1e-13 * scale);
      double jscale = 0.0;
      for (int j = 0; j < 3; ++j)
        jscale = std::max({jscale, std::abs(f.Fx.v[j]), std::abs(f.Fy.v[j]), std::abs(f.Mz.v[j])});
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(h.jacobian(0, j), f.Fx.v[j], 1e-11 * jscale) << i;
        EXPECT_NEAR(h.jacobian(1, j), f.Fy.v[j], 1e-11 * jscale) << i;
        EXPECT_NEAR(h.jacobian(2, j), f.Mz.v[j], 1e-11 * jscale) << i;
      }
    }
  }
}

// Derivatives in the parameters through ceres::Jet (a fit's path) agree with central
// differences, and the Jet evaluation of kinematics gives the same Jacobian as the double path.
TEST(ExactLaw, JetDerivativesInParameters) {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = 0.12;
  p.kappa = 0.9;
  const ExactLaw law = make_exact_law(make_exact_model(p));
  using J5 = ceres::Jet<double, 5>;
  const ExactLawParameters<double>& q = law.parameters;
  const ExactLawParameters<J5> pj{J5(q.pressure, 0), J5(q.friction, 1), J5(q.kappa, 2),
                                  J5(q.kx, 3),       J5(q.ky, 4),       std::nullopt};
  const Kinematics<double> k{0.4, -0.3, 12.0};
  const Resultants<J5> r = exact_law_resultants(law, pj, k);
  EXPECT_TRUE(test_support::all_finite(r));
  for (int j = 0; j < 5; ++j) {
    ExactLawParameters<double> a = q, b = q;
    double* pa[5] = {&a.pressure, &a.friction, &a.kappa, &a.kx, &a.ky};
    double* pb[5] = {&b.pressure, &b.friction, &b.kappa, &b.kx, &b.ky};
    const double h = 1e-6 * std::max(1.0, std::abs(*pa[j]));
    *pa[j] += h;
    *pb[j] -= h;
    const Resultants<double> ra = exact_law_resultants(law, a, k);
    const Resultants<double> rb = exact_law_resultants(law, b, k);
    // The law is linear in p*, f, kx, ky and quadratic in kappa: only rounding in the differences.
    const double scale = std::max(std::abs(*pb[j] + h), 0.01);
    EXPECT_NEAR(r.Fx.v[j], (ra.Fx - rb.Fx) / (2 * h), 1e-6 * std::abs(r.Fx.a) / scale) << j;
    EXPECT_NEAR(r.Fy.v[j], (ra.Fy - rb.Fy) / (2 * h), 1e-6 * std::abs(r.Fx.a) / scale) << j;
    EXPECT_NEAR(r.Mz.v[j], (ra.Mz - rb.Mz) / (2 * h), 1e-6 * std::abs(r.Mz.a) / scale) << j;
  }
}

// A Newton solver of an implicit Euler step converges with the law's Jacobian, also when the
// new state is at the rim (eps = 1) and after the spin has almost stopped: the interpolant is
// continuous and its derivative is its own.
TEST(ExactLaw, NewtonConvergesOnImplicitEulerSteps) {
  const ContactPatch p = seed_tire_patch();
  const ExactLaw law = make_exact_law(make_exact_model(p));
  const double R = p.radius_m, fN = p.friction * normal_load(p);
  const double mass = fN / (p.friction * 9.81), inertia = 0.5 * mass * R * R, h = 0.05;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double eps = trial % 4 == 0 ? 1.0 + 1e-4 * U(rng) : std::exp(2 * U(rng));
    const double w0 = 30.0 * (1.0 + U(rng) * 0.5), v0 = eps * w0 * R, a = 3.0 * U(rng);
    const Eigen::Vector3d x0(v0 * std::cos(a), v0 * std::sin(a), w0);
    Eigen::Vector3d x = x0;
    const Eigen::Vector3d M(mass, mass, inertia);
    bool converged = false;
    for (int it = 0; it < 30 && !converged; ++it) {
      const ExactLawWithJacobian r = exact_law_resultants_with_jacobian(law, {x[0], x[1], x[2]});
      const Eigen::Vector3d G = M.cwiseProduct(x - x0) - h * r.resultants.vector();
      const Eigen::Matrix3d JG = Eigen::Matrix3d(M.asDiagonal()) - h * r.jacobian;
      const Eigen::Vector3d dx = JG.partialPivLu().solve(-G);
      x += dx;
      converged = dx.norm() < 1e-12 * x0.norm();
    }
    EXPECT_TRUE(converged) << "trial " << trial << " eps " << eps;
  }
}

// The sliding-spinning uniform disk stops both motions together at v/(omega R) = 0.6530
// (theory.md section 3; Farkas et al. 2003): RK4 in steps of a hundredth of the remaining speed.
TEST(ExactLaw, SlidingDiskStopsAtFarkasRatio) {
  ContactPatch p = test_support::uniform_patch();
  p.radius_m = 1.0;
  p.reference_pressure_pa = 1.0 / std::numbers::pi;  // N = 1
  p.friction = 1.0;
  const ExactLaw law = make_exact_law(make_exact_model(p));
  auto rate = [&](const Eigen::Vector2d& y) {  // M = 1, I = 1/2, f N = 1
    const Resultants<double> r = exact_law_resultants(
        law, Kinematics<double>{std::max(y[0], 0.0), 0.0, std::max(y[1], 0.0)});
    return Eigen::Vector2d(r.Fx, 2.0 * r.Mz);
  };
  for (auto [v0, w0] : {std::pair{1.0, 1.0}, std::pair{3.0, 0.5}, std::pair{0.2, 2.0}}) {
    Eigen::Vector2d y(v0, w0);
    while (y.sum() > 1e-13 * (v0 + w0)) {
      const double dt = 1e-2 * y.sum();
      const Eigen::Vector2d k1 = rate(y), k2 = rate(y + 0.5 * dt * k1),
                            k3 = rate(y + 0.5 * dt * k2), k4 = rate(y + dt * k3);
      y += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      ASSERT_TRUE(y[0] > 0 && y[1] > 0) << "one motion stopped first: " << y.transpose();
    }
    EXPECT_NEAR(y[0] / y[1], test_support::sliding_disk_fixed_point(), 1e-4) << v0 << " " << w0;
    EXPECT_NEAR(y[0] / y[1], 0.6530, 2e-4);
  }
}

// A tolerance the sampled integrals cannot certify (their rounding is about 1e-13 of the load)
// gives a law that says so (reached false, achieved above the tolerance), quickly, and is still
// as good as it says; a tight one it can reach is reached.
TEST(ExactLaw, SaysWhenItCannotReachTheTolerance) {
  const ContactPatch p = seed_tire_patch();
  const ExactModel<double> model = make_exact_model(p);
  const ExactLaw tight = make_exact_law(model, {1e-12});
  EXPECT_TRUE(tight.reached);
  EXPECT_LE(tight.achieved, 1e-12);
  const ExactLaw beyond = make_exact_law(model, {2e-14});
  EXPECT_FALSE(beyond.reached);
  EXPECT_GT(beyond.achieved, 2e-14);
  EXPECT_LT(beyond.achieved, 1e-11);
  const double fN = p.friction * normal_load(p), R = model.radius;
  std::mt19937 rng(23);
  for (int i = 0; i < 2000; ++i) {
    const Kinematics<double> k = random_kinematics(rng, R, i);
    const Resultants<double> e = exact_resultants(model, k, {1e-14}).resultants;
    EXPECT_LE(relative_error(exact_law_resultants(beyond, k), e, fN, R), beyond.achieved + 2e-15);
    EXPECT_LE(relative_error(exact_law_resultants(tight, k), e, fN, R), tight.achieved + 2e-15);
  }
}

// The tables' builder splits a piece at a singular point (t = 0, where the centre of sliding
// crosses the rim) geometrically down to the width its error asks for: on t^2 log|t| (errors
// shrinking like the width squared) and t log|t| (like the width, where the prediction falls
// short and bisection goes on) it reaches the tolerance, its error between the samples stays
// within what it reports, and it needs fewer samples than plain bisection for as many pieces.
TEST(PiecewiseChebyshev, SplitsTowardsSingularPointsAtOnce) {
  auto g = [](double t, double* v) {
    const double l = t == 0.0 ? 0.0 : std::log(std::abs(t));
    v[0] = t * t * l;
    v[1] = t * l;
  };
  PiecewiseChebyshevOptions o;
  o.degree = 8;
  o.tolerance = 1e-10;
  o.breaks = graded_breaks(3);
  const PiecewiseChebyshevBuild plain = build_piecewise_chebyshev(2, g, o);
  o.singular_points = {0.0};
  const PiecewiseChebyshevBuild graded = build_piecewise_chebyshev(2, g, o);
  EXPECT_TRUE(plain.reached);
  EXPECT_TRUE(graded.reached);
  EXPECT_LT(graded.samples, plain.samples);
  EXPECT_LE(graded.table.pieces(), plain.table.pieces() + 2);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double t = i % 2 ? U(rng) : std::ldexp(U(rng), -20 * (i % 3));
    double want[2], got[2];
    g(t, want);
    evaluate_chebyshev(graded.table, t, got);
    worst = std::max({worst, std::abs(got[0] - want[0]), std::abs(got[1] - want[1])});
  }
  EXPECT_LE(worst, graded.achieved + 1e-15);
  RecordProperty("samples",
                 std::to_string(graded.samples) + " vs " + std::to_string(plain.samples));
  RecordProperty("worst", format_value(worst) + " of " + format_value(graded.achieved));
}

TEST(ExactLaw, RejectsBadInputWithClearErrors) {
  const ExactModel<double> model = make_exact_model(test_support::uniform_patch());
  for (double tol : {0.0, 1e-15, 1e-2, 0.5, -1.0, std::nan("")}) {
    try {
      (void)make_exact_law(model, {tol});
      ADD_FAILURE() << "tolerance " << tol << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "tolerance");
      EXPECT_NE(std::string(e.what()).find("(1e-14, 1e-2)"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW((void)make_exact_law(model, {1e-8, 9}), InvalidArgument);
  ExactModel<double> assoc = model;
  assoc.kappa = 0.5;
  assoc.associated_orthotropy = true;
  EXPECT_THROW((void)make_exact_law(assoc), InvalidArgument);
  const ExactLaw law = make_exact_law(model);
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {std::nan(""), inf, -inf}) {
    EXPECT_THROW((void)exact_law_resultants(law, Kinematics<double>{bad, 0.0, 1.0}),
                 InvalidArgument);
    EXPECT_THROW((void)exact_law_resultants(law, Kinematics<double>{0.0, 1.0, bad}),
                 InvalidArgument);
    EXPECT_THROW((void)exact_law_resultants_with_jacobian(law, {0.0, bad, 1.0}), InvalidArgument);
  }
  // Finite extremes give finite resultants.
  for (double big : {1e300, -1e300, 1e-300, 5e-324}) {
    for (const Kinematics<double>& k :
         {Kinematics<double>{big, 0.0, 1.0}, {1.0, big, big}, {0.0, 0.0, big}, {big, big, 0.0}}) {
      const ExactLawWithJacobian r = exact_law_resultants_with_jacobian(law, k);
      EXPECT_TRUE(std::isfinite(r.resultants.Fx) && std::isfinite(r.resultants.Fy) &&
                  std::isfinite(r.resultants.Mz));
    }
  }
}

// A build stopped by its caller throws Interrupted.
TEST(ExactLaw, AStopRequestStopsTheBuild) {
  ExactLawOptions o;
  o.stop = [] { return true; };
  EXPECT_THROW(make_exact_law(make_exact_model(seed_tire_patch()), o), Interrupted);
}
