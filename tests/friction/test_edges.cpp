// The rows a rig produces (pure spin, pure sliding, v = omega = 0,
// negative omega, any sliding direction) give finite values and finite, correct derivatives
// through the exact integrals and the fractional law, for double and ceres::Jet (the fitted
// model's paths: tests/identification/test_fit_edges.cpp). Derivatives are checked against central
// differences and against the first-order closed forms at the edges (theory.md sections 2, 4).
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "jet_checks.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"

using namespace contensou;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSpin = 11.49425287;  // u = omega R = 1 m/s on the seed tire

// The seed tire with a shift and anisotropy, so that every term of the exact model is on.
ContactPatch shifted_seed(double kx = 0.14, double ky = -0.05, double kappa = 0.9) {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = kx;
  p.profile.ky = ky;
  p.kappa = kappa;
  return p;
}

using contensou::test_support::all_finite;

using J3 = ceres::Jet<double, 3>;

// Jets of the exact resultants in (vx, vy, omega).
Resultants<J3> exact_jets(const ExactModel<double>& m, const Kinematics<double>& k, double tol) {
  return exact_resultants(promote<J3>(m), Kinematics<J3>{J3(k.vx, 0), J3(k.vy, 1), J3(k.omega, 2)},
                          {tol})
      .resultants;
}

// Central differences of the exact resultants in (vx, vy, omega), steps h.
std::array<Eigen::Vector3d, 3> exact_differences(const ExactModel<double>& m,
                                                 const Kinematics<double>& k,
                                                 const std::array<double, 3>& h, double tol) {
  std::array<Eigen::Vector3d, 3> d;
  for (int j = 0; j < 3; ++j) {
    double xp[3] = {k.vx, k.vy, k.omega}, xm[3] = {k.vx, k.vy, k.omega};
    xp[j] += h[j];
    xm[j] -= h[j];
    const auto rp = exact_resultants(m, Kinematics<double>{xp[0], xp[1], xp[2]}, {tol});
    const auto rm = exact_resultants(m, Kinematics<double>{xm[0], xm[1], xm[2]}, {tol});
    d[j] = (rp.resultants.vector() - rm.resultants.vector()) / (2 * h[j]);
  }
  return d;
}

void expect_jets_match(const Resultants<J3>& r, const std::array<Eigen::Vector3d, 3>& fd,
                       const std::array<double, 3>& row_scale, double rel,
                       const std::string& what) {
  const J3 rows[3] = {r.Fx, r.Fy, r.Mz};
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(rows[c].v[j], fd[j](c), rel * row_scale[c])
          << what << " row " << c << " col " << j;
}

}  // namespace

// --- Exact integrals --------------------------------------------------------------------

// Root cause: d = sqrt(rcx^2 + rcy^2) differentiated at r_c = 0 (Jet sqrt: 0 * inf = NaN), and
// g = r_c / d, whose derivative ~ 1/d made the result lose accuracy like 1/|v| near v = 0.
TEST(ExactEdges, JetsAtPureSpinAreFiniteAndMatchCentralDifferences) {
  const double R = 0.087;
  ContactPatch speed = shifted_seed();
  speed.slip_speed_friction = SlipSpeedFriction<double>{0.4, 0.3, 0.5, 1.0};
  ContactPatch uniform = shifted_seed();
  uniform.profile = uniform_profile();
  uniform.profile.kx = 0.2;
  const ContactPatch patches[3] = {shifted_seed(), uniform, speed};
  for (int i = 0; i < 3; ++i) {
    const ExactModel<double> m = make_exact_model(patches[i]);
    const double fn = normal_load(patches[i]) * 0.4;
    for (double w : {kSpin, -kSpin, 0.3 * kSpin}) {
      const Kinematics<double> k{0.0, 0.0, w};
      const auto rj = exact_jets(m, k, 1e-12);
      ASSERT_TRUE(all_finite(rj)) << i << " " << w;
      const double hv = 1e-6 * std::abs(w) * R;
      const auto fd = exact_differences(m, k, {hv, hv, 1e-6 * std::abs(w)}, 1e-13);
      // Scale of a row: its largest entry (the linear response -K v at rest is ~ fN/(omega R)).
      const std::array<double, 3> scale = {fn / (std::abs(w) * R), fn / (std::abs(w) * R),
                                           fn / std::abs(w)};
      expect_jets_match(rj, fd, scale, i == 2 ? 1e-5 : 1e-6,
                        "patch " + std::to_string(i) + " omega " + std::to_string(w));
      // Continuity: the derivatives at |v| down to 1e-300 are those at v = 0.
      for (double v : {1e-6, 1e-100, 1e-160, 1e-300}) {
        for (double phi : {0.0, 1.0, -2.5}) {
          const Kinematics<double> kv{v * std::cos(phi), v * std::sin(phi), w};
          const auto rv = exact_jets(m, kv, 1e-12);
          ASSERT_TRUE(all_finite(rv)) << i << " " << v;
          const J3 a[3] = {rj.Fx, rj.Fy, rj.Mz}, b[3] = {rv.Fx, rv.Fy, rv.Mz};
          for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(b[c].a, a[c].a, scale[c] * (1e-9 * std::abs(w) * R + 2 * v))
                << v << " " << c;
            for (int j = 0; j < 3; ++j)
              EXPECT_NEAR(b[c].v[j], a[c].v[j], 1e-5 * scale[c]) << v << " " << c << j;
          }
        }
      }
    }
  }
}

// Root cause: the pure-sliding branch returned F(v) only, whose d/domega is 0; the truth at
// omega = 0 is the first order of the local slip direction (theory.md section 2).
TEST(ExactEdges, OmegaDerivativeAtPureSlideIsTheFirstOrder) {
  const double R = 0.087;
  ContactPatch speed = shifted_seed(0.1, 0.06, 0.8);
  speed.slip_speed_friction = SlipSpeedFriction<double>{0.4, 0.3, 0.5, 1.0};
  const ContactPatch patches[3] = {shifted_seed(0.14, 0.0, 1.0), shifted_seed(0.1, 0.06, 0.8),
                                   speed};
  for (int i = 0; i < 3; ++i) {
    const ExactModel<double> m = make_exact_model(patches[i]);
    const double fn = normal_load(patches[i]) * 0.4;
    for (double phi : {0.0, 0.7, -2.0}) {
      const Kinematics<double> k{0.5 * std::cos(phi), 0.5 * std::sin(phi), 0.0};
      const auto rj = exact_jets(m, k, 1e-12);
      ASSERT_TRUE(all_finite(rj));
      const auto fd = exact_differences(m, k, {1e-6, 1e-6, 1e-4}, 1e-13);
      const std::array<double, 3> scale = {fn, fn, fn * R};
      expect_jets_match(rj, fd, scale, 1e-6, "patch " + std::to_string(i));
      EXPECT_GT(std::abs(rj.Mz.v[2]), 0.1 * fn * R * R / 0.5);  // not the old 0
    }
  }
  // Closed form, seed tire sliding along x with kx = 0.14 (p* = 210 kPa, f = 0.3):
  //   dMz/domega = -f p* pi R^4 A^3 / |v|,  dFy/domega = (kx / R) dMz/domega.
  const ContactPatch p = shifted_seed(0.14, 0.0, 1.0);
  const auto rj = exact_jets(make_exact_model(p), {0.5, 0.0, 0.0}, 1e-12);
  const double dmz = -0.3 * 2.1e5 * kPi * std::pow(R, 4) * moment(p.profile, 3) / 0.5;
  EXPECT_NEAR(rj.Mz.v[2], dmz, 1e-9 * std::abs(dmz));  // -4.0993 N m s
  EXPECT_NEAR(rj.Fy.v[2], 0.14 / R * dmz, 1e-9 * std::abs(dmz) / R);
}

// The first-order pure-slide form takes over where the first order is within a tenth of the
// tolerance (the integrals about a centre 1/eps radii away would lose their omega-derivatives
// to cancellation, 5 % off at eps = 2e-13, tolerance 1e-10): the
// Jacobian is continuous through it (the change over eps <= 1e-5 is O(eps) relative) and the
// value stays within its error estimate on both sides; for the default and the associated
// orthotropic law and a slip-speed law.
TEST(ExactEdges, JacobianIsContinuousThroughTheSwitchToThePureSlideForm) {
  ContactPatch speed = shifted_seed(0.1, 0.06, 0.8);
  speed.slip_speed_friction = SlipSpeedFriction<double>{0.4, 0.3, 0.5, 2.0};
  for (int i = 0; i < 3; ++i) {
    ExactModel<double> m = make_exact_model(i == 2 ? speed : shifted_seed(0.1, 0.06, 0.8));
    m.associated_orthotropy = i == 1;
    const double R = m.radius, fn = normal_load(seed_tire_patch()) * 0.4, v = 0.5;
    const Kinematics<double> slide{v * std::cos(0.7), v * std::sin(0.7), 0.0};
    for (double tol : {1e-6, 1e-10}) {
      const Resultants<J3> j0 = exact_jets(m, slide, tol);
      const J3 rows0[3] = {j0.Fx, j0.Fy, j0.Mz};
      for (double eps : {1e-14, 1e-12, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5}) {
        Kinematics<double> k = slide;
        k.omega = eps * v / R;
        const Resultants<J3> j = exact_jets(m, k, tol);
        const J3 rows[3] = {j.Fx, j.Fy, j.Mz};
        const std::string what = "model " + std::to_string(i) + " tol " + std::to_string(tol) +
                                 " eps " + std::to_string(eps);
        for (int c = 0; c < 3; ++c) {
          const double row = c == 2 ? fn * R : fn;
          for (int d = 0; d < 3; ++d)  // d/dv ~ f N / |v|, d/domega ~ f N R / |v|
            EXPECT_NEAR(rows[c].v[d], rows0[c].v[d], 1e-4 * row * (d == 2 ? R : 1.0) / v)
                << what << " row " << c << " col " << d;
        }
        const auto r = exact_resultants(m, k, {tol});
        const auto ref = exact_resultants(m, k, {1e-14}).resultants;
        EXPECT_LE(std::abs(r.resultants.Fx - ref.Fx), r.error.Fx) << what;
        EXPECT_LE(std::abs(r.resultants.Fy - ref.Fy), r.error.Fy) << what;
        EXPECT_LE(std::abs(r.resultants.Mz - ref.Mz), r.error.Mz) << what;
      }
    }
  }
}

// Root cause: |v| = sqrt(vx^2 + vy^2) under- or overflowed (vx = 1e-200 gave NaN, 1e200 zero).
TEST(ExactEdges, PureSlideAtExtremeSpeeds) {
  const ContactPatch p = shifted_seed();
  const ExactModel<double> m = make_exact_model(p);
  const double fn = 0.3 * normal_load(p);
  for (double s : {1e-310, 1e-200, 1e-20, 1.0, 1e20, 1e200, 1e300}) {
    for (double phi : {0.0, 0.5 * kPi, 2.2}) {
      const Kinematics<double> k{s * std::cos(phi), s * std::sin(phi), 0.0};
      const double ux = phi == 0.5 * kPi ? 0.0 : std::cos(phi), uy = std::sin(phi);
      const auto r = exact_resultants(m, k).resultants;
      EXPECT_NEAR(r.Fx, -fn * ux, 1e-12 * fn) << s << " " << phi;
      EXPECT_NEAR(r.Fy, -fn * 0.9 * uy, 1e-12 * fn) << s << " " << phi;
      if (s < 1e-300) continue;  // a Jet divides through 1/x, which overflows for subnormal x
      const auto rj = exact_jets(m, k, 1e-10);
      EXPECT_TRUE(all_finite(rj)) << s << " " << phi;
      EXPECT_NEAR(rj.Fx.a, r.Fx, 1e-12 * fn);
    }
  }
}

// Convention (exact_resultants.hpp): at v = omega = 0 zero resultants with zero derivatives.
TEST(ExactEdges, RestGivesZeroWithFiniteDerivatives) {
  const ExactModel<double> m = make_exact_model(shifted_seed());
  const auto rj = exact_jets(m, {0.0, 0.0, 0.0}, 1e-10);
  ASSERT_TRUE(all_finite(rj));
  EXPECT_EQ(rj.Fx.a, 0.0);
  EXPECT_EQ(rj.Mz.a, 0.0);
  EXPECT_EQ(rj.Fy.v.cwiseAbs().maxCoeff(), 0.0);
}

// Root cause: validate(ContactPatch) did not look into a tabulated shape; pchip_value read
// front() of empty vectors (segfault).
TEST(ExactEdges, HandFilledTabulatedShapeIsRefused) {
  ContactPatch p = shifted_seed();
  p.profile.shape = TabulatedShape{};
  EXPECT_THROW(make_exact_model(p), InvalidArgument);
  EXPECT_THROW(normal_load(p), InvalidArgument);
  p.profile.shape = TabulatedShape{{0.0, 1.0}, {1.0, 0.5}, {}};  // slopes missing
  EXPECT_THROW(make_exact_model(p), InvalidArgument);
  p.profile.shape = TabulatedShape{{0.0, 0.7, 0.6, 1.0}, {1, 1, 1, 1}, {0, 0, 0, 0}};
  EXPECT_THROW(make_exact_model(p), InvalidArgument);
  p.profile.shape = CosineSeriesShape{0.8, {}};
  EXPECT_THROW(make_exact_model(p), InvalidArgument);
  p.profile = tabulated_profile({0.0, 0.5, 1.0}, {1.0, 0.9, 0.2});  // the factory's output is fine
  EXPECT_NO_THROW(make_exact_model(p));
}

// A profile with a negative part: refused unless the caller clips it or keeps it. Clipped, the
// friction dissipates at every velocity (F.v + Mz omega < 0); the seed tire keeps its published
// series explicitly (negative on (0.9936, 1], 1.8e-4 of its load).
TEST(ExactEdges, NegativePressureIsRefusedUnlessClippedOrKept) {
  ContactPatch p = seed_tire_patch();
  p.profile = tabulated_profile({0.0, 0.5, 0.8, 1.0}, {1.0, 0.8, -0.3, -0.5});
  EXPECT_GT(negative_load_share(p.profile), 0.1);
  try {
    make_exact_model(p);
    FAIL() << "a negative profile was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("negative on rho in (0."), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("clip_negative"), std::string::npos) << e.what();
  }
  p.profile.clip_negative = true;
  const ExactModel<double> clipped = make_exact_model(p);
  for (const Kinematics<double>& k : {Kinematics<double>{0.5, 0.0, 0.0},
                                      {0.0, 0.0, 11.5},
                                      {0.3, -0.2, 7.0},
                                      {0.01, 0.02, -20.0}}) {
    const Resultants<double> r = exact_resultants(clipped, k, {1e-10}).resultants;
    EXPECT_LT(r.Fx * k.vx + r.Fy * k.vy + r.Mz * k.omega, 0.0);
  }
  p.profile.clip_negative = false;
  p.profile.keep_negative = true;
  EXPECT_NO_THROW(make_exact_model(p));
  EXPECT_TRUE(seed_tire_profile().keep_negative);
  EXPECT_NEAR(negative_load_share(seed_tire_profile()), 1.8e-4, 0.1e-4);
  EXPECT_NO_THROW(make_exact_model(seed_tire_patch()));
  EXPECT_EQ(negative_load_share(hertz_profile()), 0.0);
}

// --- Fractional law ---------------------------------------------------------------------

TEST(FractionalEdges, EvaluationRejectsNaNVelocitiesAndBadFields) {
  const FractionalLaw<double> good = fractional_law_from_patch(shifted_seed());
  auto parameter = [](const auto& f) -> std::string {
    try {
      f();
    } catch (const InvalidArgument& e) {
      return e.parameter();
    }
    return "no exception";
  };
  EXPECT_EQ(parameter([&] {
              fractional_resultants(good, Kinematics<double>{NAN, 0.0, 1.0});
            }),
            "vx");
  EXPECT_EQ(parameter([&] {
              fractional_resultants_with_jacobian(good, Kinematics<double>{0.0, 0.0, NAN});
            }),
            "omega");
  FractionalLaw<double> bad = good;
  bad.kappa = -1.0;  // would generate energy
  EXPECT_EQ(parameter([&] {
              fractional_resultants(bad, Kinematics<double>{0.1, 0.1, 1.0});
            }),
            "kappa");
  bad = good;
  bad.a = -1.0;
  EXPECT_EQ(parameter([&] { fractional_resultants(bad, Kinematics<double>{0.0, 0.0, 0.0}); }), "a");
  bad = good;
  bad.regularization_speed = 0.0;
  EXPECT_EQ(parameter([&] {
              fractional_resultants_with_jacobian(bad, Kinematics<double>{0.0, 0.0, 0.0});
            }),
            "regularization_speed");
  FractionalLaw<J3> lj{J3(good.F0), J3(good.M0),  J3(-1.0),       J3(good.m),
                       J3(good.kx), J3(good.ky),  J3(good.kappa), J3(good.c),
                       J3(good.Mk), J3(good.a_k), good.radius,    good.regularization_speed};
  EXPECT_EQ(parameter([&] {
              fractional_resultants(lj, Kinematics<J3>{J3(0.1), J3(0.0), J3(1.0)});
            }),
            "a");
}

// Root cause: with a shift, (g1 - g2)(k.v)(z x v)/v^2 had g1 - g2 = u eps^2/S^3 != 0 at v = 0:
// a direction-dependent term, so the Jacobian grew like 1/|v| near rest.
TEST(FractionalEdges, ShiftJacobianIsContinuousThroughRest) {
  for (double eps : {1e-4, 1e-6}) {
    FractionalLaw<double> law = fractional_law_from_patch(shifted_seed(0.14, 0.05, 0.9));
    law.regularization_speed = eps;
    for (double w : {kSpin, -kSpin, 1e-3 * eps / law.radius}) {
      const auto at0 = fractional_resultants_with_jacobian(law, Kinematics<double>{0.0, 0.0, w});
      ASSERT_TRUE(at0.jacobian.allFinite());
      const double scale = at0.jacobian.cwiseAbs().maxCoeff();
      for (double v : {1e-15 * eps, 1e-11 * eps, 1e-9 * eps, 1e-15, 1e-12}) {
        for (double phi : {0.3, 2.0, -1.2}) {
          const Kinematics<double> k{v * std::cos(phi), v * std::sin(phi), w};
          const auto fj = fractional_resultants_with_jacobian(law, k);
          const double dv = v / std::max({std::abs(w) * law.radius, eps});
          EXPECT_LE((fj.jacobian - at0.jacobian).cwiseAbs().maxCoeff(), (1e-9 + 10 * dv) * scale)
              << eps << " " << w << " " << v << " " << phi;
          // Jets through the templated law agree with the analytic Jacobian.
          FractionalLaw<J3> lj{J3(law.F0), J3(law.M0),  J3(law.a),     J3(law.m),
                               J3(law.kx), J3(law.ky),  J3(law.kappa), J3(law.c),
                               J3(law.Mk), J3(law.a_k), law.radius,    law.regularization_speed};
          const auto rj =
              fractional_resultants(lj, Kinematics<J3>{J3(k.vx, 0), J3(k.vy, 1), J3(k.omega, 2)});
          ASSERT_TRUE(all_finite(rj));
          const J3 rows[3] = {rj.Fx, rj.Fy, rj.Mz};
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
              EXPECT_NEAR(rows[r].v[c], fj.jacobian(r, c), 1e-9 * scale) << r << c;
        }
      }
    }
  }
}

// Scales of the law and the patch's friction are 0 or normal doubles, as loads and radii are: a
// subnormal F0, M0, Mk or friction (below 2.2e-308) is refused naming it, where it was accepted
// and lost its precision; 0 and the smallest normal double are accepted.
TEST(Edges, SubnormalScalesOfTheLawAreRefusedNamingThem) {
  const FractionalLaw<double> good = fractional_law_from_patch(shifted_seed(0.14, 0.05, 0.9));
  for (const char* name : {"F0", "M0", "Mk"}) {
    for (double v : {1e-310, 0.0, 2.3e-308}) {
      FractionalLaw<double> law = good;
      (name[0] == 'F' ? law.F0 : name[1] == '0' ? law.M0 : law.Mk) = v;
      if (v > 0.0 && v < 2.2e-308) {
        try {
          validate(law);
          ADD_FAILURE() << name << " = " << v << " accepted";
        } catch (const InvalidArgument& e) {
          EXPECT_EQ(e.parameter(), name);
          EXPECT_NE(std::string(e.what()).find("smallest normal double"), std::string::npos);
        }
      } else {
        EXPECT_NO_THROW(validate(law)) << name << " " << v;
      }
    }
  }
  ContactPatch patch = seed_tire_patch();
  patch.friction = 1e-310;
  EXPECT_THROW(validate(patch), InvalidArgument);
}
