// The exact laws of an identification model's profile (exact_law_cache.hpp): a given profile
// times the basis shapes phi1 = 1 + T1(2t - 1) = 2t and phi2 = 1 + T2(2t - 1) = 2(2t - 1)^2
// (the profile_correction effect) against closed forms of their load and spin torque, and a
// table's product against the same product as a series; options' shared laws are one cache that
// builds the laws a fit builds alone.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contensou/identification.hpp"
#include "shared_laws.hpp"  // src/identification (internal)

using namespace contensou;

namespace {

constexpr double kPi = std::numbers::pi;

ExactModel<double> unit_model(const PressureProfile& profile, double radius) {
  ContactPatch patch;
  patch.radius_m = radius;
  patch.reference_pressure_pa = 1.0;
  patch.friction = 1.0;
  patch.profile = profile;
  return make_exact_model(patch, 1e-6);
}

ExactLawParameters<double> unit_pressure() {
  ExactLawParameters<double> p;
  p.pressure = 1.0;
  p.friction = 1.0;
  return p;
}

}  // namespace

// Hertz, p = sqrt(1 - t): L = 2 pi A^1 with A^1 = (1/2) integral p phi dt, and the pure-spin
// torque |Mz| = p* R^3 2 pi A^2, A^2 = integral_0^1 p phi rho^2 d rho (rho = sin theta):
//   phi0: A^1 = 1/3, A^2 = pi/16; phi1 = 2 rho^2: A^1 = 4/15, A^2 = 2 pi/32;
//   phi2 = 2 (2 rho^2 - 1)^2: A^1 = 22/105, A^2 = 2 (4 5pi/256 - 4 pi/32 + pi/16) = pi/32.
TEST(ExactLawCache, AHertzProfileTimesTheBasisShapesHasTheClosedFormLoadAndSpinTorque) {
  const double R = 0.1;
  const ExactLawCache cache(R, unit_model(hertz_profile(), R), 1e-9);
  ASSERT_EQ(cache.laws(false, {}, 0).size(), 1u);
  const std::vector<ExactLaw>& laws = cache.laws(false, {}, 2);
  ASSERT_EQ(laws.size(), 3u);
  const double a1[3] = {1.0 / 3.0, 4.0 / 15.0, 22.0 / 105.0};
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(laws[k].load_area, 2.0 * kPi * a1[k], 1e-9) << k;
  // Pure spin: the torque is the sum of f sigma r over the patch.
  const double a2[3] = {kPi / 16.0, kPi / 16.0, kPi / 32.0};
  for (int k = 0; k < 3; ++k) {
    const Resultants<double> r = exact_law_resultants(
        laws[static_cast<std::size_t>(k)], unit_pressure(), Kinematics<double>{0.0, 0.0, 3.0});
    EXPECT_NEAR(std::abs(r.Mz), R * R * R * 2.0 * kPi * a2[k], 1e-9 * R * R * R) << k;
    EXPECT_NEAR(r.Fx, 0.0, 1e-9 * R * R);
  }
  // Pure sliding: |F| = f N = p* R^2 L for any shape.
  for (const ExactLaw& law : laws) {
    const Resultants<double> r =
        exact_law_resultants(law, unit_pressure(), Kinematics<double>{0.7, 0.0, 0.0});
    EXPECT_NEAR(-r.Fx, R * R * law.load_area, 1e-9 * R * R);
  }
}

// A uniform table (p = 1, slope 0 at every knot) times phi_k is a quadratic in t, which the cubic
// Hermite pieces of the product hold exactly: its laws are those of the series 1 + T_k.
TEST(ExactLawCache, AUniformTableTimesTheBasisShapesIsTheSeries) {
  const double R = 0.087;
  const ExactLawCache table(R, unit_model(tabulated_profile({0.0, 0.4, 0.8, 1.0}, {1, 1, 1, 1}), R),
                            1e-9);
  const std::vector<ExactLaw>& laws = table.laws(false, {}, 2);
  ASSERT_EQ(laws.size(), 3u);
  for (int k = 1; k <= 2; ++k) {
    std::vector<double> c(static_cast<std::size_t>(k) + 1, 0.0);
    c[0] = c[static_cast<std::size_t>(k)] = 1.0;
    PressureProfile series;
    series.shape = ChebyshevShape{c};
    const ExactLaw direct = make_exact_law(unit_model(series, R), ExactLawOptions{1e-9});
    const ExactLaw& product = laws[static_cast<std::size_t>(k)];
    EXPECT_NEAR(product.load_area, direct.load_area, 1e-12) << k;
    for (const Kinematics<double>& kin :
         {Kinematics<double>{0.3, 0.1, 2.0}, Kinematics<double>{0.0, 0.0, -5.0},
          Kinematics<double>{-0.02, 0.05, 9.0}}) {
      const Resultants<double> a = exact_law_resultants(product, unit_pressure(), kin);
      const Resultants<double> b = exact_law_resultants(direct, unit_pressure(), kin);
      const double N = R * R * direct.load_area;
      EXPECT_NEAR(a.Fx, b.Fx, 1e-8 * N) << k;
      EXPECT_NEAR(a.Fy, b.Fy, 1e-8 * N) << k;
      EXPECT_NEAR(a.Mz, b.Mz, 1e-8 * N * R) << k;
    }
  }
}

// The parametric profile's degrees keep their meaning (three laws, then five).
TEST(ExactLawCache, TheParametricProfileHasThreeThenFiveBasisLaws) {
  const ExactLawCache cache(0.087, std::nullopt, 1e-6);
  EXPECT_EQ(cache.laws(false, {}, 2).size(), 3u);
  EXPECT_EQ(cache.laws(false, {}, 4).size(), 5u);
}

// Options given shared laws (identify() gives its resamples the laws of its first loop) hand
// every base spec one cache and the profile model a spec builds alone: the laws are built once,
// and they are the laws each fit would build (the same resultants to the last bit).
TEST(ExactLawCache, SharedLawsAreOneCacheForEveryFitOfTheOptions) {
  MeasuredData d;
  MeasuredPoint p;
  p.kinematics = {0.3, 0.1, 2.0};
  p.force = {-100.0, -30.0, -2.0};
  d.points.push_back(p);
  for (const bool given : {true, false}) {
    IdentificationOptions o;
    o.radius_m = 0.087;
    if (given) o.profile = hertz_profile();
    const ModelSpec alone = base_spec_for(d, o), again = base_spec_for(d, o);
    EXPECT_NE(alone.exact_laws, again.exact_laws) << given;
    detail::LawSharing::share(o);
    const ModelSpec first = base_spec_for(d, o), second = base_spec_for(d, o);
    ASSERT_TRUE(first.exact_laws);
    EXPECT_EQ(first.exact_laws, second.exact_laws) << given;
    EXPECT_EQ(first.profile_model.has_value(), given);
    const Kinematics<double> k{0.3, 0.1, 2.0};
    if (given) {
      const Resultants<double> a = exact_resultants(*first.profile_model, k).resultants;
      const Resultants<double> b = exact_resultants(*alone.profile_model, k).resultants;
      EXPECT_EQ(a.vector(), b.vector());
    }
    const std::vector<ExactLaw>& shared = first.exact_laws->laws(false, {}, 2);
    const std::vector<ExactLaw>& own = alone.exact_laws->laws(false, {}, 2);
    ASSERT_EQ(shared.size(), own.size());
    for (std::size_t i = 0; i < own.size(); ++i)
      EXPECT_EQ(exact_law_resultants(shared[i], k).vector(),
                exact_law_resultants(own[i], k).vector())
          << given << " " << i;
  }
  IdentificationOptions bad;
  EXPECT_THROW(detail::LawSharing::share(bad), InvalidArgument);
}
