#include <gtest/gtest.h>

#include "contensou/friction/model_error.hpp"

using namespace contensou;

TEST(ModelError, SeedTireFiguresOfTheory) {
  const ContactPatch p = seed_tire_patch();
  const ModelErrorReport r = model_error_report(p, 1e-3, 1e3, 61);
  ASSERT_EQ(r.laws.size(), 2u);
  const auto& asym = r.laws[0];
  const auto& fit = r.laws[1];
  ASSERT_EQ(asym.channels.size(), 2u);  // no shift: F_par and Mz
  // theory.md section 5: about 19 % (F_par) and 24 % (Mz) asymptote-matched, ~9 % fitted.
  EXPECT_NEAR(asym.channels[0].max_error, 0.19, 0.01);
  EXPECT_NEAR(asym.channels[1].max_error, 0.24, 0.01);
  for (int c = 0; c < 2; ++c) {
    EXPECT_LT(fit.channels[c].max_error, 0.11);
    EXPECT_LT(fit.channels[c].rms_error, asym.channels[c].rms_error);
  }
  EXPECT_NE(format_report(r).find("asymptote-matched"), std::string::npos);
}

TEST(ModelError, LateralChannelWithShiftAndBadRange) {
  ContactPatch p = ContactPatch::from_normal_load(0.087, 5000.0, uniform_profile(), 0.3);
  p.profile.kx = 0.1;
  const ModelErrorReport r = model_error_report(p, 1e-2, 1e2, 11);
  EXPECT_EQ(r.laws[0].channels.size(), 3u);
  EXPECT_EQ(r.laws[0].channels[1].channel, "F_lat");
  EXPECT_THROW(model_error_report(p, -1.0, 1.0, 5), InvalidArgument);
  EXPECT_THROW(model_error_report(p, 1.0, 10.0, 1), InvalidArgument);
}
