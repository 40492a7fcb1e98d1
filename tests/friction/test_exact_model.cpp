// The exact model (exact_model.hpp, exact_model.cpp): the representation of the profile, a
// clipped table's pieces, and what make_exact_model refuses.
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

TEST(ExactResultants, RepresentationToleranceTradesTermsForAReportedError) {
  // A smooth profile with many terms (a wide cosine series): a loose representation is
  // shorter, its error enters the estimate, and the result stays within that estimate of the
  // fine one.
  ContactPatch patch = uniform_patch();
  patch.profile = cosine_series_profile(2.3, {1.0, 0.2, -0.15, 0.05, 0.02});
  patch.profile.keep_negative = true;
  const ExactModel<double> fine = make_exact_model(patch), loose = make_exact_model(patch, 1e-4);
  EXPECT_LT(loose.chebyshev().size(), fine.chebyshev().size());
  EXPECT_GT(loose.representation_error(), fine.representation_error());
  const Kinematics<double> k{0.03, 0.02, 0.5 / patch.radius_m};
  const auto a = exact_resultants(fine, k, {1e-8}), b = exact_resultants(loose, k, {1e-8});
  EXPECT_LE(std::abs(a.resultants.Fx - b.resultants.Fx), a.error.Fx + b.error.Fx);
  EXPECT_LE(std::abs(a.resultants.Mz - b.resultants.Mz), a.error.Mz + b.error.Mz);
  EXPECT_THROW(make_exact_model(patch, 0.0), InvalidArgument);
}

// A dense table (4001 knots of a profile with a kink at rho = 0.6, as a finite-element model
// writes it) is thinned for the integrals to the knots its cubics need at the tolerance asked:
// far fewer, the kink kept, the deviation in the representation error, and the resultants within
// that error of the whole table's (the default tolerance keeps every knot).
TEST(ExactResultants, ADenseTableIsThinnedToItsToleranceKeepingItsKink) {
  std::vector<double> rho, pressure;
  for (int i = 0; i <= 4000; ++i) {
    const double r = i / 4000.0;
    rho.push_back(r);
    pressure.push_back(r < 0.6 ? 1.0 + 0.5 * r * r
                               : 1.18 - 2.0 * (r - 0.6) * (r - 0.6) - 0.4 * (r - 0.6));
  }
  ContactPatch patch = uniform_patch();
  patch.profile = tabulated_profile(rho, pressure);
  patch.profile.kx = 0.1;
  const ExactModel<double> whole = make_exact_model(patch), thin = make_exact_model(patch, 1e-6);
  ASSERT_TRUE(whole.table() && thin.table());
  EXPECT_EQ(whole.table()->knot.size(), 4001u);
  EXPECT_LT(thin.table()->knot.size(), 400u);
  EXPECT_GT(thin.representation_error(), 0.0);
  EXPECT_LT(thin.representation_error(), 2e-6);
  const auto near_kink = std::find_if(thin.table()->knot.begin(), thin.table()->knot.end(),
                                      [](double t) { return std::abs(t - 0.36) < 1e-3; });
  EXPECT_NE(near_kink, thin.table()->knot.end());  // t = rho^2 = 0.36 at the kink
  for (const Kinematics<double> k :
       {Kinematics<double>{0.03, 0.01, 0.5 / patch.radius_m}, Kinematics<double>{0.0, 0.0, 1.0}}) {
    const auto a = exact_resultants(whole, k, {1e-9}), b = exact_resultants(thin, k, {1e-9});
    const double scale = whole.pressure * whole.load_area * whole.friction;  // f N
    EXPECT_LE(std::abs(a.resultants.Fx - b.resultants.Fx), 2e-6 * scale);
    EXPECT_LE(std::abs(a.resultants.Fy - b.resultants.Fy), 2e-6 * scale);
    EXPECT_LE(std::abs(a.resultants.Mz - b.resultants.Mz), 2e-6 * scale * patch.radius_m);
  }
}

// A table with a negative part, clipped: the pieces are split at their zero crossings and the
// negative parts become zero pieces, so the integrals stay exact for max(p, 0).
TEST(ExactResultants, ClippedTableIsSplitAtItsZeros) {
  ContactPatch p = uniform_patch();
  p.profile = tabulated_profile({0.0, 0.3, 0.6, 0.8, 1.0}, {1.0, 0.9, 0.3, -0.2, -0.4});
  p.profile.clip_negative = true;
  p.profile.kx = 0.1;
  const ExactModel<double> m = make_exact_model(p);
  ASSERT_TRUE(m.table().has_value());
  EXPECT_LT(m.representation_error(), 1e-11);
  int zero_pieces = 0;
  for (const auto& c : m.table()->piece) zero_pieces += c[0] == 0.0 && c[1] == 0.0 && c[3] == 0.0;
  EXPECT_GE(zero_pieces, 1);
  expect_matches_brute_force(p, m, {0.2, 0.9, 2.5});
}
