#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"

using namespace contensou;

namespace {

ContactPatch seed_patch(double kx = 0.0, double ky = 0.0) {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = kx;
  p.profile.ky = ky;
  return p;
}

FractionalLaw<double> random_law(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  FractionalLaw<double> law;
  law.radius = 0.05 + 0.3 * U(rng);
  law.F0 = 100 + 5000 * U(rng);
  law.M0 = law.F0 * law.radius * (0.3 + 0.5 * U(rng));
  law.a = 0.5 + U(rng);
  law.m = 4 + 8 * U(rng);
  law.c = 2 + 5 * U(rng);
  law.a_k = 0.5 + 2 * U(rng);
  law.Mk = 0.5 * law.M0 * U(rng);
  const double k = 0.9 * U(rng), th = 6.283 * U(rng);
  law.kx = k * std::cos(th);
  law.ky = k * std::sin(th);
  law.kappa = 0.3 + 2.7 * U(rng);
  law.regularization_speed = std::pow(10.0, -6 + 4 * U(rng));
  return law;
}

Kinematics<double> random_kinematics(std::mt19937_64& rng, double R) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const double mag = std::pow(10.0, 4 * U(rng));
  const double wmag = std::pow(10.0, 4 * U(rng));
  return {mag * U(rng), mag * U(rng), wmag * U(rng) / R};
}

}  // namespace

TEST(FractionalLaw, ReducesToTheSeedLawForSlidingAlongTheShift) {
  const FractionalLaw<double> law = fractional_law_from_patch(seed_patch(0.14));
  FractionalLaw<double> sharp = law;
  sharp.regularization_speed = 1e-12;
  const double R = law.radius;
  for (double psi : {1e-3, 0.1, 1.0, 7.0, 1e3}) {
    const double u = 2.0, v = psi * u, ups = 1 / psi;
    const auto r = fractional_resultants(sharp, Kinematics<double>{v, 0.0, u / R});
    // Seed eq. 13 (with the 1/R of eq. 5 that eq. 13 omits).
    EXPECT_NEAR(-r.Fx, law.F0 * psi / std::sqrt(psi * psi + law.a), 1e-12 * law.F0);
    EXPECT_NEAR(-r.Fy, law.kx * law.M0 * ups / (R * std::sqrt(4 * ups * ups + law.m)),
                1e-12 * law.F0);
    EXPECT_NEAR(-r.Mz, law.M0 * ups / std::sqrt(ups * ups + law.m), 1e-12 * law.M0);
  }
}

TEST(FractionalLaw, MatchesTheExactAsymptotes) {
  const ContactPatch p = seed_patch(0.14, 0.0);
  const FractionalLaw<double> law = fractional_law_from_patch(p);
  const ExactModel<double> model = make_exact_model(p);
  const double R = p.radius_m;
  auto both = [&](double vx, double vy, double omega) {
    const Kinematics<double> k{vx, vy, omega};
    return std::pair{fractional_resultants(law, k), exact_resultants(model, k, {1e-12}).resultants};
  };
  // Small sliding: F_par -> F0 psi / sqrt(a). Small spin: Mz -> M0 / (sqrt(m) psi), lateral force.
  auto [ls, es] = both(1e-3, 0.0, 1.0 / R);
  EXPECT_NEAR(ls.Fx / es.Fx, 1.0, 1e-4);
  auto [lf, ef] = both(1.0, 0.0, 1e-3 / R);
  EXPECT_NEAR(lf.Mz / ef.Mz, 1.0, 1e-4);
  EXPECT_NEAR(lf.Fy / ef.Fy, 1.0, 1e-4);
  // Pure spin: lateral force sign(omega) (M0/2R)(ky, -kx).
  auto [lp, ep] = both(0.0, 0.0, 3.0);
  EXPECT_NEAR(lp.Fy, ep.Fy, 1e-6 * law.F0);
  EXPECT_NEAR(lp.Mz, ep.Mz, 1e-6 * law.M0);
  // Cross shift (ky with sliding along x): pure-spin force along v, pure-slide torque, and
  // the (u/v)^3 small-spin asymptote of the force.
  const ContactPatch q = seed_patch(0.0, 0.1);
  const FractionalLaw<double> lq = fractional_law_from_patch(q);
  const ExactModel<double> mq = make_exact_model(q);
  const ExactModel<double> m0 = make_exact_model(seed_patch());
  const FractionalLaw<double> l0 = fractional_law_from_patch(seed_patch());
  for (const Kinematics<double>& k :
       {Kinematics<double>{1e-9, 0.0, 3.0}, Kinematics<double>{3.0, 0.0, 0.0},
        Kinematics<double>{1.0, 0.0, 0.05 / R}}) {
    const auto ex = exact_resultants(mq, k, {1e-13}).resultants;
    const auto ex0 = exact_resultants(m0, k, {1e-13}).resultants;
    const auto la = fractional_resultants(lq, k), la0 = fractional_resultants(l0, k);
    const double dF = ex.Fx - ex0.Fx, dFl = la.Fx - la0.Fx;
    const double dM = ex.Mz - ex0.Mz, dMl = la.Mz - la0.Mz;
    EXPECT_NEAR(dFl, dF, 2e-2 * std::abs(dF) + 1e-9 * lq.F0) << k.vx << " " << k.omega;
    EXPECT_NEAR(dMl, dM, 2e-2 * std::abs(dM) + 1e-9 * lq.M0) << k.vx << " " << k.omega;
  }
}

TEST(FractionalLaw, AnalyticJacobianMatchesJetsAndFiniteDifferences) {
  using J3 = ceres::Jet<double, 3>;
  std::mt19937_64 rng(7);
  for (int n = 0; n < 500; ++n) {
    const FractionalLaw<double> law = random_law(rng);
    Kinematics<double> k = random_kinematics(rng, law.radius);
    if (n == 0) k = {0.0, 0.0, 0.0};
    if (n == 1) k = {0.0, 0.0, 3.0};
    if (n == 2) k = {2.0, -1.0, 0.0};
    const FractionalWithJacobian fj = fractional_resultants_with_jacobian(law, k);
    FractionalLaw<J3> lj{J3(law.F0), J3(law.M0),  J3(law.a),     J3(law.m),
                         J3(law.kx), J3(law.ky),  J3(law.kappa), J3(law.c),
                         J3(law.Mk), J3(law.a_k), law.radius,    law.regularization_speed};
    const auto rj =
        fractional_resultants(lj, Kinematics<J3>{J3(k.vx, 0), J3(k.vy, 1), J3(k.omega, 2)});
    const auto plain = fractional_resultants(law, k);
    const double level = 1e-13 * (law.F0 + law.M0 / law.radius);
    EXPECT_NEAR(fj.resultants.Fx, plain.Fx, level);
    EXPECT_NEAR(fj.resultants.Fy, plain.Fy, level);
    EXPECT_NEAR(fj.resultants.Mz, plain.Mz, level * law.radius);
    const J3 rows[3] = {rj.Fx, rj.Fy, rj.Mz};
    // Each entry against the size of its row (entries far below the row suffer cancellation).
    for (int r = 0; r < 3; ++r) {
      EXPECT_NEAR(rows[r].a, fj.resultants.vector()(r), level);
      const double scale = fj.jacobian.row(r).cwiseAbs().maxCoeff() + 1e-12;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(fj.jacobian(r, c), rows[r].v[c], 1e-9 * scale) << n << " " << r << c;
    }
    // Central differences where the law is far from its regularisation scale (there the
    // curvature ~ 1/eps^2 defeats differencing; the Jets above cover it).
    const double floor = 1e3 * law.regularization_speed;
    if (std::abs(k.vx) > floor && std::abs(k.vy) > floor &&
        std::abs(k.omega) * law.radius > floor) {
      const double x[3] = {k.vx, k.vy, k.omega};
      for (int c = 0; c < 3; ++c) {
        const double h = 1e-6 * std::abs(x[c]);
        double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
        xp[c] += h;
        xm[c] -= h;
        const auto rp = fractional_resultants(law, Kinematics<double>{xp[0], xp[1], xp[2]});
        const auto rm = fractional_resultants(law, Kinematics<double>{xm[0], xm[1], xm[2]});
        const Eigen::Vector3d fd = (rp.vector() - rm.vector()) / (2 * h);
        for (int r = 0; r < 3; ++r) {
          // Differencing noise: about 1e-15 |F| / h.
          const double noise = 1e-15 * (std::abs(rp.vector()(r)) + std::abs(rm.vector()(r))) / h;
          const double scale = fj.jacobian.row(r).cwiseAbs().maxCoeff() + 1e-12;
          EXPECT_NEAR(fj.jacobian(r, c), fd(r), 1e-4 * scale + 100 * noise) << n << " " << r << c;
        }
      }
    }
  }
}

TEST(FractionalLaw, FiniteForEveryFiniteInputAndDissipative) {
  std::mt19937_64 rng(99);
  for (int n = 0; n < 10000; ++n) {
    const FractionalLaw<double> law = random_law(rng);
    Kinematics<double> k = random_kinematics(rng, law.radius);
    if (n % 1000 == 1) k = {1e300, -1e300, 1e300};
    if (n % 1000 == 2) k = {1e-300, 0.0, -1e-300};
    if (n % 1000 == 3) k = {0.0, 0.0, 0.0};
    if (n % 1000 == 4) k = {-1e150, 1e-150, 0.0};
    const auto fj = fractional_resultants_with_jacobian(law, k);
    ASSERT_TRUE(fj.resultants.vector().allFinite()) << n;
    ASSERT_TRUE(fj.jacobian.allFinite()) << n;
    // Power in units scaled to avoid overflow: F.v/s + Mz omega/s, s the largest speed.
    const double s =
        std::max({std::abs(k.vx), std::abs(k.vy), std::abs(k.omega) * law.radius, 1e-300});
    const auto& r = fj.resultants;
    const double power = r.Fx * (k.vx / s) + r.Fy * (k.vy / s) + r.Mz * (k.omega / s);
    EXPECT_LE(power, 1e-12 * (law.F0 + law.M0 / law.radius)) << n;
  }
}

TEST(FractionalLaw, RegularisationIsSmoothThroughRest) {
  FractionalLaw<double> law = fractional_law_from_patch(seed_patch(0.1, 0.05));
  const auto zero = fractional_resultants(law, Kinematics<double>{0.0, 0.0, 0.0});
  EXPECT_EQ(zero.Fx, 0.0);
  EXPECT_EQ(zero.Fy, 0.0);
  EXPECT_EQ(zero.Mz, 0.0);
  // Linear (viscous-like) near rest with slope F0/eps.
  const double dv = 1e-3 * law.regularization_speed;
  const auto small = fractional_resultants(law, Kinematics<double>{dv, 0.0, 0.0});
  EXPECT_NEAR(small.Fx, -law.F0 * dv / law.regularization_speed, 1e-5 * law.F0 * 1e-3);
}

TEST(FractionalLaw, FittedCoefficientsReduceTheError) {
  const ContactPatch p = seed_patch();
  const FractionalLaw<double> asym = fractional_law_from_patch(p), fit = fractional_law_fitted(p);
  EXPECT_NE(fit.a, asym.a);
  EXPECT_LT(fit.a, asym.a);
  EXPECT_LT(fit.m, asym.m);
  EXPECT_THROW(fractional_law_fitted(p, 0.0, 10.0), InvalidArgument);
  EXPECT_THROW(fractional_law_fitted(p, 10.0, 1.0), InvalidArgument);
}

TEST(FractionalLaw, ValidateNamesTheBadParameter) {
  FractionalLaw<double> law = fractional_law_from_patch(seed_patch());
  law.m = -1;
  try {
    validate(law);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(e.parameter(), "m");
  }
  law = fractional_law_from_patch(seed_patch());
  law.radius = 0;
  EXPECT_THROW(validate(law), InvalidArgument);
}

// A pressure shift |(kx, ky)| >= 1 makes p* p(rho) (1 + kx x/R + ky y/R) negative on part of the
// patch (theory.md section 2): refused as validate(ContactPatch) refuses it.
TEST(FractionalLaw, ValidateRefusesAShiftThatMakesThePressureNegative) {
  FractionalLaw<double> law = fractional_law_from_patch(seed_patch());
  law.kx = 0.6;
  law.ky = 0.79;  // |k| = 0.992
  EXPECT_NO_THROW(validate(law));
  for (const auto& [kx, ky] : {std::pair{1.5, 0.0}, {0.0, -1.0}, {0.8, 0.61}}) {
    law.kx = kx;
    law.ky = ky;
    try {
      validate(law);
      FAIL() << "kx = " << kx << ", ky = " << ky << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "|(kx, ky)|");
      EXPECT_NE(std::string(e.what()).find("pressure stays positive"), std::string::npos);
    }
  }
}
