// Predictions both ways (prediction.hpp), the model's file (model_file.hpp) and held-out rows:
// the motion of a wrench inverts the force of a motion (and agrees with the limit surface's own
// gauge, a second method), a model read back from its file predicts what it did, the held-out
// split keeps groups whole, and the error on a fit's own rows is the fit's.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <set>

#include "contensou/friction/limit_surface.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/model_file.hpp"
#include "contensou/identification/prediction.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

constexpr double kR = 0.05;

// The exact model of a Hertz patch with a lateral shift, as an identification spec.
ModelSpec hertz_spec(double ky) {
  IdentificationOptions o;
  o.radius_m = kR;
  o.normal_load_n = 10.0;
  o.profile = hertz_profile();
  MeasuredData one;
  one.points.resize(1);
  ModelSpec s = base_spec_for(one, o);
  s.exact_only = true;
  s.value[kF0] = 3.0;
  s.value[kKy] = ky;
  return s;
}

// Rows at random twist directions (vx, vy, omega R) of speed 0.02 m/s, the model's wrench as
// the measured one.
MeasuredData rows_of(const ModelSpec& s, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0.0, 1.0);
  MeasuredData d;
  d.source = "test";
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d t(N(rng), N(rng), N(rng));
    t = 0.02 * t.normalized();
    MeasuredPoint p;
    p.line = i + 1;
    p.kinematics = {t[0], t[1], t[2] / kR};
    const Resultants<double> r = evaluate_model(s, s.value.data(), p.kinematics);
    p.force = {r.Fx, r.Fy, r.Mz};
    d.points.push_back(p);
  }
  return d;
}

double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

}  // namespace

// Oracle: the truth (the motion that made each wrench), and the gauge of the patch's limit
// surface (limit_surface.hpp: a Newton solve on the dissipation), whose normal at the friction
// wrench is minus the twist.
TEST(Prediction, TheMotionOfAWrenchInvertsTheForceOfAMotion) {
  const ModelSpec s = hertz_spec(0.3);
  const MeasuredData d = rows_of(s, 60, 4);
  const std::vector<RowPrediction> p = predict_rows(s, d);
  ContactPatch patch = ContactPatch::from_normal_load(kR, 10.0, hertz_profile(), 0.3);
  patch.profile.ky = 0.3;
  const LimitSurface surface = make_limit_surface(patch, 1e-10);
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    const Kinematics<double>& k = d.points[i].kinematics;
    const Eigen::Vector3d truth(k.vx, k.vy, k.omega * kR);
    EXPECT_LT(angle(p[i].twist, truth), 2e-3) << "row " << i;
    EXPECT_LT(p[i].wrench_misfit_rad, 1e-5) << "row " << i;
    const Gauge g =
        gauge(surface, {*d.points[i].force[0], *d.points[i].force[1], *d.points[i].force[2]});
    const Eigen::Vector3d n(g.normal[0], g.normal[1], g.normal[2] * kR);
    EXPECT_LT(angle(p[i].twist, -n), 2e-3) << "row " << i;
    EXPECT_NEAR(p[i].wrench.Fx, *d.points[i].force[0], 1e-12);
  }
  const PredictionScores sc = score_predictions(d, p, kR);
  EXPECT_EQ(sc.rows, 60);
  EXPECT_LT(sc.median_motion_angle_deg, 0.1);
  EXPECT_NEAR(sc.median_force_error, 0.0, 1e-12);
}

// Oracle: the model before writing. Read back from its file, a law with effects, a parametric
// quartic profile and a given table predict the same wrenches (to the exact laws' tolerance).
TEST(Prediction, AModelReadFromItsFilePredictsAsBefore) {
  std::vector<ModelSpec> specs;
  specs.push_back(base_model_spec(kR, 10.0));
  specs.back().value = {};
  for (int i = 0; i < kModelParameters; ++i) specs.back().value[i] = parameter_info(i).null_value;
  specs.back().value[kF0] = 3.0;
  specs.back().value[kM0] = 0.09;
  specs.back().value[kKx] = 0.1;
  specs.back().value[kOffsetMz] = 0.002;
  specs.back().value[kXFyFx] = 0.05;
  ModelSpec quartic = specs.back();
  quartic.exact_only = true;
  quartic.profile_degree = 4;
  quartic.value[kProfileW2] = 0.5;
  quartic.value[kProfileW4] = 3.0;
  specs.push_back(quartic);
  ModelSpec table = hertz_spec(0.1);
  table.profile = tabulated_profile({0.0, 0.5, 0.8, 1.0}, {1.0, 1.2, 2.0, 0.3});
  table.profile_model =
      make_exact_model(ContactPatch::from_normal_load(kR, 1.0, *table.profile, 1.0), 1e-6);
  table.exact_laws = std::make_shared<ExactLawCache>(kR, table.profile_model, 1e-6);
  specs.push_back(table);
  for (const ModelSpec& s : specs) {
    const ModelSpec back = model_from_json(model_to_json(s), "round trip");
    const MeasuredData d = rows_of(s, 20, 7);
    for (const MeasuredPoint& p : d.points) {
      const Resultants<double> r = evaluate_model(back, back.value.data(), p.kinematics);
      EXPECT_NEAR(r.Fx, *p.force[0], 1e-9);
      EXPECT_NEAR(r.Fy, *p.force[1], 1e-9);
      EXPECT_NEAR(r.Mz, *p.force[2], 1e-9 * kR);
    }
  }
}

// Bad files are refused by name: not JSON, another format, a member missing or of a wrong type.
TEST(Prediction, BadModelFilesAreRefusedByName) {
  EXPECT_THROW(model_from_json("{", "m.json"), ParseError);
  const std::string good = model_to_json(base_model_spec(kR, 10.0));
  auto broken = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  try {
    model_from_json(broken("\"contensou-model 1\"", "\"other 2\""), "m.json");
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("m.json: format"), std::string::npos) << e.what();
  }
  EXPECT_THROW(model_from_json(broken("\"radius_m\"", "\"radius\""), "m.json"), InvalidArgument);
  EXPECT_THROW(model_from_json(broken("\"exact_only\":false", "\"exact_only\":3"), "m"),
               InvalidArgument);
  EXPECT_THROW(model_from_json(broken("\"profile_degree\":2", "\"profile_degree\":1e300"), "m"),
               InvalidArgument);
  EXPECT_THROW(model_from_json(broken("\"radius_m\":0.05", "\"radius_m\":-1"), "m"),
               InvalidArgument);
  // A whole report holding the model under "model" is read too.
  EXPECT_NO_THROW(model_from_json("{\"input\": {}, \"model\": " + good + "}", "report.json"));
}

// The split holds out whole groups, about the fraction asked, the same for the same seed.
TEST(Prediction, HoldoutKeepsGroupsWholeAndIsReproducible) {
  DiagramSpec spec;
  spec.radius_m = kR;
  spec.points = 30;
  FractionalLaw<double> law;
  law.F0 = 3.0;
  law.M0 = 0.09;
  law.radius = kR;
  MeasuredData d;
  for (double dir : {0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5}) {
    spec.direction_rad = dir;
    for (const MeasuredPoint& p : simulate_diagrams(law, spec).points) d.points.push_back(p);
  }
  for (std::size_t i = 0; i < d.points.size(); ++i) d.points[i].line = static_cast<int>(i + 1);
  const HoldoutSplit a = holdout_split(d, kR, 0.2, "", 3), b = holdout_split(d, kR, 0.2, "", 3);
  EXPECT_EQ(a.groups, 10);
  EXPECT_EQ(a.held_groups, 2);
  EXPECT_EQ(a.held_out.points.size(), 60u);
  EXPECT_EQ(a.fit.points.size() + a.held_out.points.size(), d.points.size());
  std::set<int> held;
  for (const MeasuredPoint& p : a.held_out.points) held.insert(p.line);
  for (const MeasuredPoint& p : a.fit.points) EXPECT_EQ(held.count(p.line), 0u);
  for (std::size_t i = 0; i < a.held_out.points.size(); ++i)
    EXPECT_EQ(a.held_out.points[i].line, b.held_out.points[i].line);
  EXPECT_THROW(holdout_split(d, kR, 0.0), InvalidArgument);
  EXPECT_THROW(holdout_split(d, kR, 0.95), InvalidArgument);
  EXPECT_THROW(holdout_split(d, kR, 0.2, "no such column"), InvalidArgument);
}

// Oracle: FitReport::error. The fit's own model predicts its own rows with the fit's error.
TEST(Prediction, TheErrorOnAFitsOwnRowsIsTheFits) {
  FractionalLaw<double> law;
  law.F0 = 3.0;
  law.M0 = 0.09;
  law.kx = 0.1;
  law.radius = kR;
  DiagramSpec spec;
  spec.radius_m = kR;
  spec.points = 80;
  spec.spin_speed_mps = 0.02;
  const MeasuredData d = simulate_diagrams(law, spec);
  IdentificationOptions o;
  o.radius_m = kR;
  const FitReport fit = fit_fractional_law(d, o);
  ASSERT_TRUE(fit.model);
  const std::vector<RowPrediction> p = predict_rows(*fit.model, d);
  EXPECT_NEAR(prediction_error(d, wrenches_of(p), kR), fit.error, 1e-9 * fit.error);
  // A channel measured as zero (Fy of a longitudinal sweep) is scaled by the floor, 1e-3 of the
  // force scale, as in the fit: a prediction of 1e-3 F there adds an error of 1/sqrt(3).
  MeasuredData zero = d;
  std::vector<Resultants<double>> exact;
  double force = 0.0;
  for (MeasuredPoint& q : zero.points) {
    force = std::max({force, std::abs(*q.force[0]), std::abs(*q.force[2]) / kR});
    q.force[1] = 0.0;
  }
  for (const MeasuredPoint& q : zero.points)
    exact.push_back({*q.force[0], 1e-3 * force, *q.force[2]});
  EXPECT_NEAR(prediction_error(zero, exact, kR), 1.0 / std::sqrt(3.0), 1e-12);
  EXPECT_THROW(predict_rows(*fit.model, d, {5, 1e-7}), InvalidArgument);
  EXPECT_THROW(score_predictions(d, {}, kR), InvalidArgument);
  const std::string csv = predictions_csv(d, p);
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "source,line,vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm,pred_Fx_N,pred_Fy_N,"
            "pred_Mz_Nm,pred_twist_vx,pred_twist_vy,pred_twist_omegaR,wrench_misfit_deg");
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')),
            d.points.size() + 1);
}
