// The exact resultants (exact_resultants.hpp): closed forms, the tolerance and its estimate,
// asymptotes, brute force, signs, Jets, bad input. The properties every law shares (dissipation,
// isotropy, Jacobian, finiteness, load scaling) are in test_law_properties.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <sstream>
#include <string>

#include "exact_oracles.hpp"

using namespace contensou;
using namespace contensou::test_support;

TEST(ExactResultants, UniformPressureMatchesContensouClosedForms) {
  const ContactPatch p = uniform_patch();
  const ExactModel<double> m = make_exact_model(p);
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  for (double eps : closed_form_ratios()) {
    for (double phi : {0.0, 2.0}) {
      const double u = 0.7, v = eps * u;  // u = |omega| R
      const Kinematics<double> k{v * std::cos(phi), v * std::sin(phi), -u / R};
      const ExactResult<double> r = exact_resultants(m, k, {1e-12});
      ASSERT_TRUE(r.converged) << eps;
      const auto [fpar, mz] = uniform_closed_form(eps);
      const double got_fpar = -(r.resultants.Fx * std::cos(phi) + r.resultants.Fy * std::sin(phi));
      const double got_fperp = -r.resultants.Fx * std::sin(phi) + r.resultants.Fy * std::cos(phi);
      EXPECT_NEAR(got_fpar / fN, fpar, 1e-10 * fpar) << "eps = " << eps << " phi = " << phi;
      EXPECT_NEAR(r.resultants.Mz / (fN * R), mz, 1e-10 * mz) << "eps = " << eps;  // omega < 0
      EXPECT_NEAR(got_fperp / fN, 0.0, 1e-12) << "eps = " << eps;
      EXPECT_LT(r.error.Fx, 1e-11 * fN);
    }
  }
}

TEST(ExactResultants, AchievesTheRequestedToleranceAndReportsIt) {
  const ContactPatch p = uniform_patch();
  const ExactModel<double> m = make_exact_model(p);
  const double fN = p.friction * normal_load(p), R = p.radius_m;
  for (double tol : {1e-4, 1e-6, 1e-8}) {
    for (double eps : closed_form_ratios()) {
      const ExactResult<double> r = exact_resultants(m, {eps, 0.0, 1.0 / R}, {tol});
      const auto [fpar, mz] = uniform_closed_form(eps);
      EXPECT_LE(std::abs(-r.resultants.Fx / fN - fpar), tol) << eps;
      EXPECT_LE(std::abs(-r.resultants.Mz / (fN * R) - mz), tol) << eps;
      EXPECT_LE(r.error.Fx, tol * fN);
      EXPECT_LE(r.error.Mz, tol * fN * R);
      EXPECT_TRUE(r.converged);
    }
  }
}

// The error estimate bounds the achieved error (against the same integrals at 1e-13) on a
// random sample of kinematics for each profile kind: |v| / (|omega| R) log-uniform over
// 1e-3 ... 1e3 and within 0.5 % of the rim for one point in ten, any sliding direction, both
// signs of omega, at three tolerances.
TEST(ExactResultants, ErrorEstimateBoundsTheAchievedErrorOnRandomKinematics) {
  std::vector<std::pair<std::string, ContactPatch>> kinds;
  ContactPatch seed = seed_patch();
  seed.profile.kx = 0.14;
  kinds.push_back({"seed series, kx", seed});
  ContactPatch aniso = seed;
  aniso.profile.ky = -0.08;
  aniso.kappa = 0.8;
  kinds.push_back({"seed series, kx, ky, kappa", aniso});
  ContactPatch clipped = seed;
  clipped.profile.clip_negative = true;
  kinds.push_back({"seed series clipped", clipped});
  kinds.push_back({"uniform", uniform_patch()});
  ContactPatch hertz = uniform_patch();
  hertz.profile = hertz_profile();
  hertz.profile.kx = -0.2;
  kinds.push_back({"Hertz, kx", hertz});
  ContactPatch speed = seed;
  speed.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 5.0, 1.0};
  kinds.push_back({"seed series, f(w)", speed});
  std::vector<double> rho, pv;
  for (int i = 0; i <= 100; ++i) {
    rho.push_back(i / 100.0);
    const double r = rho.back();
    pv.push_back(r < 0.9 ? 1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) : 0.7439 - 4.0 * (r - 0.9));
  }
  ContactPatch table = seed;
  table.profile = tabulated_profile(rho, pv);
  table.profile.kx = 0.14;
  table.kappa = 0.9;
  kinds.push_back({"101-point table with a kink", table});
  for (const auto& [name, p] : kinds) {
    const ExactModel<double> m = make_exact_model(p);
    const double R = p.radius_m;
    const int samples = p.slip_speed_friction || m.table() ? 300 : 3000;
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> U(0.0, 1.0);
    int checked = 0;
    for (int i = 0; i < samples; ++i) {
      double ratio = std::pow(10.0, -3.0 + 6.0 * U(rng));
      if (i % 10 == 0) ratio = 1.0 + (U(rng) - 0.5) * 1e-2;
      const double dir = 2.0 * kPi * U(rng), w = (U(rng) < 0.5 ? -20.0 : 20.0);
      const double v = ratio * std::abs(w) * R;
      const Kinematics<double> k{v * std::cos(dir), v * std::sin(dir), w};
      const auto ref = exact_resultants(m, k, {1e-13}).resultants;
      for (double tol : {1e-6, 1e-8, 1e-10}) {
        const auto r = exact_resultants(m, k, {tol});
        ASSERT_LE(std::abs(r.resultants.Fx - ref.Fx), r.error.Fx)
            << name << " " << ratio << " " << tol;
        ASSERT_LE(std::abs(r.resultants.Fy - ref.Fy), r.error.Fy)
            << name << " " << ratio << " " << tol;
        ASSERT_LE(std::abs(r.resultants.Mz - ref.Mz), r.error.Mz)
            << name << " " << ratio << " " << tol;
        ++checked;
      }
    }
    EXPECT_EQ(checked, 3 * samples);
  }
}

TEST(ExactResultants, AsymptotesGiveTheMomentFormulas) {
  // a from small sliding (F_par -> F0 psi / sqrt(a)), m from small spin (Mz -> M0/(sqrt(m) psi)).
  struct Case {
    ContactPatch patch;
    double a, m;
  };
  ContactPatch hertz = uniform_patch();
  hertz.profile = hertz_profile();
  const std::vector<Case> cases = {{uniform_patch(), 1.0, 64.0 / 9.0},
                                   {hertz, std::pow(8 / (3 * kPi), 2), std::pow(15 * kPi / 16, 2)},
                                   {seed_patch(), 1.0296, 9.2848}};
  for (const Case& c : cases) {
    const ExactModel<double> model = make_exact_model(c.patch);
    const double R = c.patch.radius_m, F0 = c.patch.friction * normal_load(c.patch);
    const double M0 = 2 * kPi * c.patch.friction * std::pow(R, 3) * c.patch.reference_pressure_pa *
                      moment(c.patch.profile, 2);
    const double psi = 1e-4;
    const auto slow = exact_resultants(model, {psi, 0.0, 1.0 / R}, {1e-12}).resultants;
    const auto fast = exact_resultants(model, {1.0 / psi, 0.0, 1.0 / R}, {1e-12}).resultants;
    const double a = std::pow(F0 * psi / -slow.Fx, 2), m = std::pow(M0 * psi / -fast.Mz, 2);
    EXPECT_NEAR(a, c.a, 2e-3 * c.a) << describe(c.patch.profile);
    EXPECT_NEAR(m, c.m, 2e-3 * c.m) << describe(c.patch.profile);
  }
}

TEST(ExactResultants, PureSlideAndPureSpinClosedForms) {
  ContactPatch p = seed_patch();
  p.kappa = 0.7;
  p.profile.kx = 0.14;
  p.profile.ky = -0.05;
  const ExactModel<double> model = make_exact_model(p);
  const double N = normal_load(p), R = p.radius_m, f = p.friction;
  const double A2 = moment(p.profile, 2), A3 = moment(p.profile, 3);
  const double M0 = 2 * kPi * f * R * R * R * p.reference_pressure_pa * A2;
  for (double phi : {0.0, 0.9, -2.5}) {
    const double c = std::cos(phi), s = std::sin(phi);
    const auto r = exact_resultants(model, {3.0 * c, 3.0 * s, 0.0}).resultants;
    EXPECT_NEAR(r.Fx, -f * N * c, 1e-12 * f * N);
    EXPECT_NEAR(r.Fy, -f * N * p.kappa * s, 1e-12 * f * N);
    const double mz = -f * kPi * R * R * R * p.reference_pressure_pa * A3 *
                      (p.kappa * s * p.profile.kx - c * p.profile.ky);
    EXPECT_NEAR(r.Mz, mz, 1e-12 * f * N * R);
    // Continuity: a tiny spin gives nearly the same.
    const auto r2 = exact_resultants(model, {3.0 * c, 3.0 * s, 1e-6}).resultants;
    EXPECT_NEAR(r2.Fx, r.Fx, 1e-6 * f * N);
    EXPECT_NEAR(r2.Mz, r.Mz, 1e-6 * f * N * R);
  }
  for (double omega : {2.0, -5.0}) {
    const auto r = exact_resultants(model, {0.0, 0.0, omega}, {1e-11}).resultants;
    EXPECT_NEAR(r.Mz, -std::copysign(1.0, omega) * M0 * (1 + p.kappa) / 2, 1e-9 * M0);
  }
  // Isotropic: F = sign(omega) (M0 / 2R) (ky, -kx).
  p.kappa = 1.0;
  const ExactModel<double> iso = make_exact_model(p);
  for (double omega : {2.0, -5.0}) {
    const auto r = exact_resultants(iso, {0.0, 0.0, omega}, {1e-11}).resultants;
    const double sg = std::copysign(1.0, omega);
    EXPECT_NEAR(r.Fx, sg * M0 / (2 * R) * p.profile.ky, 1e-9 * f * N);
    EXPECT_NEAR(r.Fy, -sg * M0 / (2 * R) * p.profile.kx, 1e-9 * f * N);
  }
}

TEST(ExactResultants, AgreesWithBruteForceForShiftAnisotropyHertzAndSpeedLaw) {
  std::vector<ContactPatch> patches;
  ContactPatch a = seed_patch();
  a.profile.kx = 0.14;
  a.profile.ky = 0.08;
  a.kappa = 0.8;
  patches.push_back(a);
  ContactPatch h = uniform_patch();
  h.profile = hertz_profile();
  h.profile.kx = -0.2;
  patches.push_back(h);
  ContactPatch s = seed_patch();
  s.profile.clip_negative = true;
  s.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 5.0, 1.0};
  patches.push_back(s);
  for (const ContactPatch& p : patches)
    expect_matches_brute_force(p, make_exact_model(p), {0.3, 0.98, 1.02, 4.0});
}

TEST(ExactResultants, SignConventions) {
  ContactPatch p = seed_patch();
  p.profile.kx = 0.14;
  const ExactModel<double> model = make_exact_model(p);
  const auto slide = exact_resultants(model, {2.0, 0.0, 0.0}).resultants;
  EXPECT_LT(slide.Fx, 0.0);  // sliding along +x resists: Fx < 0
  const auto spin = exact_resultants(model, {0.0, 0.0, 5.0}).resultants;
  EXPECT_LT(spin.Mz, 0.0);  // omega > 0: Mz < 0
  const auto both = exact_resultants(model, {1.0, 0.0, 10.0}).resultants;
  EXPECT_LT(both.Fy, 0.0);  // lateral force has the sign of -kx omega
  const auto neg = exact_resultants(model, {1.0, 0.0, -10.0}).resultants;
  EXPECT_GT(neg.Fy, 0.0);
}

TEST(ExactResultants, JetDerivativesMatchFiniteDifferences) {
  using J = ceres::Jet<double, 8>;
  ContactPatch p = seed_patch();
  p.profile.kx = 0.1;
  p.profile.ky = -0.07;
  p.kappa = 0.9;
  const ExactModel<double> base = make_exact_model(p);
  const double x0[8] = {1.1, -0.4, 9.0, 0.3, 0.9, 0.1, -0.07, 2.1e5};  // vx vy w f kappa kx ky p*
  auto eval = [&](const double* x) {
    ExactModel<double> m = base;
    m.friction = x[3];
    m.kappa = x[4];
    m.kx = x[5];
    m.ky = x[6];
    m.pressure = x[7];
    return exact_resultants(m, Kinematics<double>{x[0], x[1], x[2]}, {1e-12}).resultants;
  };
  for (double ratio : {0.5, 1.0 + 1e-3, 3.0}) {
    double x[8];
    std::copy(x0, x0 + 8, x);
    x[0] *= ratio;
    x[1] *= ratio;
    ExactModel<J> mj = promote<J>(base);
    mj.friction = J(x[3], 3);
    mj.kappa = J(x[4], 4);
    mj.kx = J(x[5], 5);
    mj.ky = J(x[6], 6);
    mj.pressure = J(x[7], 7);
    const Kinematics<J> kj{J(x[0], 0), J(x[1], 1), J(x[2], 2)};
    const auto rj = exact_resultants(mj, kj, {1e-12}).resultants;
    for (int d = 0; d < 8; ++d) {
      double xp[8], xm[8];
      std::copy(x, x + 8, xp);
      std::copy(x, x + 8, xm);
      const double h = 1e-5 * std::max(1.0, std::abs(x[d]));
      xp[d] += h;
      xm[d] -= h;
      const auto rp = eval(xp), rm = eval(xm);
      const double fd[3] = {(rp.Fx - rm.Fx) / (2 * h), (rp.Fy - rm.Fy) / (2 * h),
                            (rp.Mz - rm.Mz) / (2 * h)};
      const double jet[3] = {rj.Fx.v[d], rj.Fy.v[d], rj.Mz.v[d]};
      for (int c = 0; c < 3; ++c) {
        const double scale = std::max({std::abs(fd[c]), std::abs(jet[c]), 1e-3});
        EXPECT_NEAR(jet[c], fd[c], 1e-5 * scale) << "ratio " << ratio << " d " << d << " c " << c;
      }
    }
  }
}

TEST(ExactResultants, BadInputNamesParameterAndValue) {
  auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return e.what();
    }
    return "no exception";
  };
  ContactPatch p = uniform_patch();
  p.radius_m = -0.1;
  EXPECT_NE(message([&] { make_exact_model(p); }).find("radius_m = -0.1"), std::string::npos);
  p.radius_m = 0.0;
  EXPECT_NE(message([&] { make_exact_model(p); }).find("radius_m = 0"), std::string::npos);
  p = uniform_patch();
  p.kappa = 0.0;
  EXPECT_NE(message([&] { make_exact_model(p); }).find("kappa = 0"), std::string::npos);
  p.kappa = -1.0;
  EXPECT_NE(message([&] { make_exact_model(p); }).find("kappa = -1"), std::string::npos);
  p = uniform_patch();
  p.profile.kx = 1.2;
  EXPECT_NE(message([&] { make_exact_model(p); }).find("1.2"), std::string::npos);
  const ExactModel<double> m = make_exact_model(uniform_patch());
  EXPECT_NE(message([&] {
              exact_resultants(m, {NAN, 0.0, 1.0});
            }).find("vx = nan"),
            std::string::npos);
  EXPECT_NE(message([&] {
              exact_resultants(m, {0.0, INFINITY, 1.0});
            }).find("vy = inf"),
            std::string::npos);
  EXPECT_NE(message([&] {
              exact_resultants(m, {0.0, 1.0, -INFINITY});
            }).find("omega = -inf"),
            std::string::npos);
  EXPECT_NE(message([&] {
              exact_resultants(m, {0.0, 1.0, 1.0}, {0.0});
            }).find("tolerance"),
            std::string::npos);
  EXPECT_EQ(exact_resultants(m, {0.0, 0.0, 0.0}).resultants.Fx, 0.0);
}

// ExactResult::error is one estimate per component; max() the largest of the three.
TEST(ExactResult, ErrorIsPerComponentWithAMax) {
  const ContactPatch p = ContactPatch::from_normal_load(0.1, 1000.0, uniform_profile(), 0.5);
  const ExactModel<double> model = make_exact_model(p);
  const ExactResult<double> r = exact_resultants(model, {0.3, 0.1, 5.0}, {1e-10});
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.error.max(), std::max({r.error.Fx, r.error.Fy, r.error.Mz}));
  // Converged: forces within 1e-10 f N, the torque within 1e-10 f N R (R = 0.1 m).
  EXPECT_LE(r.error.max(), 1e-10 * 0.5 * 1000.0);
}
