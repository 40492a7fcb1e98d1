// The rigid patch of the motion (rigid_patch.hpp): rows made by a patch's exact integrals
// (exact_resultants on a ContactPatch, not the limit surface the fit uses) give that patch back
// with its motions; the motion of a patch's wrench is the motion that made it; the centre of
// pressure agrees with a brute-force quadrature; bad patches, options and files are refused by
// name; the model's file carries the patch and predict_rows uses it.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/model_file.hpp"
#include "contensou/identification/prediction.hpp"
#include "contensou/identification/rigid_patch.hpp"

using namespace contensou;

namespace {

constexpr double kR = 0.0525;

// A patch of the search's grid, off the start of the search in every coordinate.
RigidPatch grid_patch() {
  RigidPatch p;
  p.radius_m = kR;
  p.exponent = 8;
  p.kx = 0.2;
  p.ky = -0.2;
  p.contact_radius_ratio = 0.8;
  p.force_scale_n = 3.0;
  return p;
}

// Rows at random twists, their wrench the exact integrals of the patch (a ContactPatch built
// here from the patch's definition).
MeasuredData rows_of(const RigidPatch& r, int n, unsigned seed) {
  PressureProfile profile = power_profile(r.exponent);
  profile.kx = r.kx;
  profile.ky = r.ky;
  const ContactPatch patch = ContactPatch::from_normal_load(r.contact_radius_ratio * r.radius_m,
                                                            r.force_scale_n, profile, 1.0);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  MeasuredData d;
  d.source = "test";
  for (int i = 0; i < n; ++i) {
    MeasuredPoint p;
    p.kinematics = {0.01 * N(rng), 0.01 * N(rng), 0.01 * N(rng) / kR};
    const Resultants<double> w = exact_resultants(patch, p.kinematics).resultants;
    p.force = {w.Fx, w.Fy, w.Mz};
    p.line = i + 2;
    d.points.push_back(p);
  }
  return d;
}

Eigen::Vector3d scaled_unit(const Kinematics<double>& k) {
  return Eigen::Vector3d(k.vx, k.vy, k.omega * kR).normalized();
}

}  // namespace

TEST(RigidPatch, RowsOfAPatchGiveThePatchBack) {
  const RigidPatch truth = grid_patch();
  const RigidPatch fit = fit_rigid_patch(rows_of(truth, 120, 3), kR);
  EXPECT_EQ(fit.exponent, truth.exponent);
  EXPECT_DOUBLE_EQ(fit.kx, truth.kx);
  EXPECT_DOUBLE_EQ(fit.ky, truth.ky);
  EXPECT_DOUBLE_EQ(fit.contact_radius_ratio, truth.contact_radius_ratio);
  EXPECT_NEAR(fit.force_scale_n, truth.force_scale_n, 1e-6 * truth.force_scale_n);
  EXPECT_LT(fit.median_angle_deg, 1e-3);
  EXPECT_EQ(fit.rows, 120);
}

// Rows of a ring wider than the body (1.3 R, no pressure under the body gives them) end the
// search on its bound a = R, and the wider contact it reports is the ring's; rows of a patch on
// the body report none, and the text says what the bound means only when it holds.
TEST(RigidPatch, RowsOfAContactWiderThanTheBodyAreNamedAsSuch) {
  RigidPatch ring = grid_patch();
  ring.exponent = 32;
  ring.kx = ring.ky = 0.0;
  ring.contact_radius_ratio = 1.3;
  const RigidPatch fit = fit_rigid_patch(rows_of(ring, 80, 7), kR);
  EXPECT_DOUBLE_EQ(fit.contact_radius_ratio, 1.0);
  ASSERT_TRUE(fit.wider_contact.has_value());
  EXPECT_DOUBLE_EQ(fit.wider_contact->radius_ratio, 1.3);
  EXPECT_EQ(fit.wider_contact->exponent, 32);
  EXPECT_LT(fit.wider_contact->median_angle_deg, 1e-3);
  EXPECT_GT(fit.median_angle_deg, 0.5);
  EXPECT_NE(rigid_patch_text(fit).find("wider than the body"), std::string::npos);

  const RigidPatch on_body = fit_rigid_patch(rows_of(grid_patch(), 80, 7), kR);
  EXPECT_FALSE(on_body.wider_contact.has_value());
  EXPECT_EQ(rigid_patch_text(on_body).find("wider than the body"), std::string::npos);

  RigidPatchOptions none;
  none.wider_radius_ratios.clear();
  EXPECT_FALSE(fit_rigid_patch(rows_of(ring, 40, 7), kR, none).wider_contact.has_value());
}

TEST(RigidPatch, TheMotionOfAWrenchIsTheMotionThatMadeIt) {
  const RigidPatch truth = grid_patch();
  const LimitSurface s = limit_surface_of(truth, 1e-10);
  const MeasuredData d = rows_of(truth, 40, 5);
  for (const MeasuredPoint& p : d.points) {
    const Eigen::Vector3d w(*p.force[0], *p.force[1], *p.force[2]);
    const Eigen::Vector3d m = rigid_patch_motion(s, kR, w);
    EXPECT_LT(
        std::atan2(m.cross(scaled_unit(p.kinematics)).norm(), m.dot(scaled_unit(p.kinematics))),
        1e-6)
        << p.line;
    const Eigen::Vector3d back = rigid_patch_wrench(
        s, Eigen::Vector3d(p.kinematics.vx, p.kinematics.vy, p.kinematics.omega));
    EXPECT_LT((back - w).norm(), 1e-8 * w.norm()) << p.line;
  }
  EXPECT_FALSE(rigid_patch_motion(s, kR, Eigen::Vector3d::Zero()).allFinite());
  EXPECT_TRUE(rigid_patch_wrench(s, Eigen::Vector3d::Zero()).isZero());
}

TEST(RigidPatch, CentreOfPressureAgreesWithAQuadrature) {
  const RigidPatch p = grid_patch();
  const double a = p.contact_radius_ratio * kR;
  // Midpoint rule in (rho, theta) of sigma x and sigma over the disk.
  double load = 0.0, mx = 0.0, my = 0.0;
  const int nr = 400, nt = 256;
  for (int i = 0; i < nr; ++i) {
    const double rho = (i + 0.5) / nr;
    for (int j = 0; j < nt; ++j) {
      const double th = 2.0 * std::numbers::pi * (j + 0.5) / nt;
      const double x = a * rho * std::cos(th), y = a * rho * std::sin(th);
      const double sigma = std::pow(rho, p.exponent) * (1.0 + p.kx * x / a + p.ky * y / a) * rho;
      load += sigma;
      mx += sigma * x;
      my += sigma * y;
    }
  }
  const Eigen::Vector2d cop = centre_of_pressure_m(p);
  EXPECT_NEAR(cop.x(), mx / load, 1e-5 * a);
  EXPECT_NEAR(cop.y(), my / load, 1e-5 * a);
}

TEST(RigidPatch, BadPatchesOptionsAndDataAreRefusedByName) {
  auto refused = [](auto change, const std::string& name) {
    RigidPatch p = grid_patch();
    change(p);
    try {
      validate(p);
      ADD_FAILURE() << name << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  };
  refused([](RigidPatch& p) { p.radius_m = -1.0; }, "radius_m");
  refused([](RigidPatch& p) { p.contact_radius_ratio = 1.5; }, "contact_radius_ratio");
  refused([](RigidPatch& p) { p.exponent = 3; }, "exponent");
  refused([](RigidPatch& p) { p.kx = 0.9, p.ky = 0.9; }, "kx, ky");
  refused([](RigidPatch& p) { p.force_scale_n = std::nan(""); }, "force_scale_N");

  const MeasuredData d = rows_of(grid_patch(), 10, 1);
  MeasuredData two = d;
  two.points.resize(2);
  EXPECT_THROW(fit_rigid_patch(two, kR), InvalidArgument);
  RigidPatchOptions bad;
  bad.exponents = {5};
  EXPECT_THROW(fit_rigid_patch(d, kR, bad), InvalidArgument);
  bad = {};
  bad.shifts = {2.0};
  EXPECT_THROW(fit_rigid_patch(d, kR, bad), InvalidArgument);
  bad = {};
  bad.wider_radius_ratios = {1.0};
  EXPECT_THROW(fit_rigid_patch(d, kR, bad), InvalidArgument);
  bad = {};
  bad.wider_margin = 1.0;
  EXPECT_THROW(fit_rigid_patch(d, kR, bad), InvalidArgument);
  EXPECT_THROW(fit_rigid_patch(d, 0.0), InvalidArgument);
  // Friction that drives the motion: no patch gives it.
  MeasuredData driving = d;
  for (MeasuredPoint& p : driving.points)
    for (auto& f : p.force) f = -*f;
  EXPECT_THROW(fit_rigid_patch(driving, kR), InvalidArgument);
}

TEST(RigidPatch, TheModelFileCarriesThePatchAndPredictUsesIt) {
  const RigidPatch truth = grid_patch();
  ModelSpec s = base_model_spec(kR, 3.0);
  s.value[kF0] = 3.0;
  s.motion_patch = truth;
  s.motion_patch->wider_contact = WiderContact{1.2, 16, 4.5};
  const ModelSpec back = model_from_json(model_to_json(s), "m.json");
  ASSERT_TRUE(back.motion_patch);
  ASSERT_TRUE(back.motion_patch->wider_contact);
  EXPECT_DOUBLE_EQ(back.motion_patch->wider_contact->radius_ratio, 1.2);
  EXPECT_EQ(back.motion_patch->wider_contact->exponent, 16);
  EXPECT_DOUBLE_EQ(back.motion_patch->wider_contact->median_angle_deg, 4.5);
  // A wider contact the file cannot mean is refused by name (an exponent beyond an int, a
  // contact inside the body, an angle past 180 deg).
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"\"exponent\":16", "\"exponent\":1e300"},
           {"\"exponent\":16", "\"exponent\":3"},
           {"\"radius_ratio\":1.2", "\"radius_ratio\":0.8"},
           {"\"median_angle_deg\":4.5", "\"median_angle_deg\":400"}}) {
    std::string bad = model_to_json(s, -1);
    const std::size_t at = bad.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    bad.replace(at, from.size(), to);
    try {
      model_from_json(bad, "m.json");
      ADD_FAILURE() << to << " accepted";
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find("motion_patch.wider_contact."), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(back.motion_patch->exponent, 8);
  EXPECT_DOUBLE_EQ(back.motion_patch->kx, 0.2);
  EXPECT_DOUBLE_EQ(back.motion_patch->contact_radius_ratio, 0.8);

  const MeasuredData d = rows_of(truth, 30, 9);
  const std::vector<RowPrediction> pred = predict_rows(back, d);
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    const Eigen::Vector3d t = scaled_unit(d.points[i].kinematics);
    EXPECT_LT(std::atan2(pred[i].twist.cross(t).norm(), pred[i].twist.dot(t)), 1e-5) << i;
    EXPECT_LT(pred[i].wrench_misfit_rad, 1e-5) << i;
  }

  std::string text = model_to_json(s);
  const std::string from = "\"kx\":0.2";
  ASSERT_NE(text.find(from), std::string::npos) << text;
  text.replace(text.find(from), from.size(), "\"kx\":0.99");
  try {
    model_from_json(text, "m.json");
    ADD_FAILURE() << "a patch with a negative pressure read";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("m.json: motion_patch"), std::string::npos) << e.what();
  }
}
