// The report a test engineer reads: warnings in words when the data are too few, failed loop
// steps flagged as such (never shown as a rejection), verdicts that agree with the decision,
// and the same facts in the text and the JSON.
#include <gtest/gtest.h>

#include "seed_tire_law.hpp"

#include <nlohmann/json.hpp>
#include <string>

#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

FractionalLaw<double> truth() {
  return test::seed_tire_law();
}

// The seed tire's diagrams fitted with a radius (the data's own, 0.087 m, by default).
FitReport fit_of(int points, double fit_radius_m = 0.087) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = points;
  s.noise = SimulatedNoise::additive_gaussian;
  s.noise_level = 0.01;
  s.seed = 11;
  IdentificationOptions o;
  o.radius_m = fit_radius_m;
  return fit_fractional_law(simulate_diagrams(truth(), s), o);
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST(ReportText, TooLittleDataIsSaidInWordsAndInTheJson) {
  // Three points: 9 values, 5 parameters and 3 noise scales leave one degree of freedom.
  const FitReport few = fit_of(3);
  ASSERT_EQ(few.degrees_of_freedom, 1);
  const std::vector<std::string> w = fit_warnings(few);
  ASSERT_FALSE(w.empty());
  EXPECT_TRUE(contains(w.front(),
                       "too little data: 9 measured values for 5 parameters and 3 "
                       "noise scales leave 1 degrees of freedom"))
      << w.front();
  const ReportInput in{};
  EXPECT_TRUE(contains(fit_report_text(in, few), "WARNING: too little data"));
  const nlohmann::json j = nlohmann::json::parse(fit_report_json(in, few));
  EXPECT_EQ(j["warnings"].size(), w.size());
  EXPECT_EQ(j["base"]["warnings"][0], w.front());
  // 40 points (120 values, 112 degrees of freedom, 37 per scale): nothing to warn about.
  const FitReport enough = fit_of(40);
  EXPECT_TRUE(fit_warnings(enough).empty());
  EXPECT_FALSE(contains(fit_report_text(in, enough), "WARNING"));
}

TEST(ReportText, AFailedStepIsFlaggedNotRejected) {
  ClosedLoopReport loop;
  loop.base = fit_of(40);
  loop.final_fit = loop.base;
  LoopStep worse;
  worse.effect = "shape";
  worse.error_before = 0.0159;
  worse.error_after = 0.1642;  // ten times worse than the model it nests
  worse.verdict =
      "LR not significant, BIC does not improve, cross-validated error does not improve";
  LoopStep rejected = worse;
  rejected.effect = "channel_offset";
  rejected.error_after = 0.0158;
  loop.steps = {worse, rejected};
  EXPECT_TRUE(step_fit_failed(worse));
  EXPECT_FALSE(step_fit_failed(rejected));
  const std::string text = loop_report_text(ReportInput{}, loop);
  EXPECT_TRUE(contains(text, "0.0159 -> 0.1642  FAILED FIT")) << text;
  EXPECT_TRUE(contains(text, "0.0159 -> 0.0158  rejected")) << text;
  EXPECT_TRUE(contains(text, "legend: LR p-value"));
  EXPECT_TRUE(contains(text, "Not decided (the fit failed): shape")) << text;
  EXPECT_TRUE(contains(text, "Tried and not needed: channel_offset")) << text;
  const nlohmann::json j = nlohmann::json::parse(loop_report_json(ReportInput{}, loop));
  EXPECT_TRUE(j["steps"][0]["fit_failed"].get<bool>());
  EXPECT_TRUE(contains(j["steps"][0]["verdict"].get<std::string>(), "failed fit"));
  EXPECT_FALSE(j["steps"][1]["fit_failed"].get<bool>());
  EXPECT_EQ(j["summary"].get<std::string>(), loop_summary(loop));
  // Retried from other starts: said in the text and counted in the JSON, whether the step
  // still failed or a start recovered it.
  loop.steps[0].retries = 4;
  loop.steps[1].retries = 1;
  const std::string retried = loop_report_text(ReportInput{}, loop);
  EXPECT_TRUE(contains(retried, "ended worse than the model it extends, also from 4 other starts"))
      << retried;
  EXPECT_TRUE(contains(retried, "this row is its fit from another start (1 tried)")) << retried;
  const nlohmann::json k = nlohmann::json::parse(loop_report_json(ReportInput{}, loop));
  EXPECT_EQ(k["steps"][0]["retries"].get<int>(), 4);
  EXPECT_EQ(k["steps"][1]["retries"].get<int>(), 1);
}

// A candidate tried twice is said once, by its last trial: rejected, then failed against the
// extended model, it is "not decided"; failed, then rejected, it is "not needed".
TEST(ReportText, ACandidateTriedTwiceIsSaidByItsLastTrial) {
  ClosedLoopReport loop;
  loop.base = fit_of(40);
  loop.final_fit = loop.base;
  LoopStep rejected;
  rejected.effect = "shape";
  rejected.error_before = 0.0366;
  rejected.error_after = 0.0291;
  rejected.verdict = "LR significant, BIC improves, cross-validated error improves";
  LoopStep failed = rejected;
  failed.error_before = 0.0220;
  failed.error_after = 0.2270;  // ten times worse than the model it extends
  ASSERT_FALSE(step_fit_failed(rejected));
  ASSERT_TRUE(step_fit_failed(failed));
  loop.steps = {rejected, failed};
  const std::string late_failure = loop_summary(loop);
  EXPECT_TRUE(contains(late_failure, "Not decided (the fit failed): shape")) << late_failure;
  EXPECT_FALSE(contains(late_failure, "Tried and not needed")) << late_failure;
  loop.steps = {failed, rejected};
  const std::string late_rejection = loop_summary(loop);
  EXPECT_TRUE(contains(late_rejection, "Tried and not needed: shape")) << late_rejection;
  EXPECT_FALSE(contains(late_rejection, "Not decided")) << late_rejection;
}

// A radius that does not fit the data's torque (a radius in mm, or a torque column in N mm
// read as N m) is warned about: M0 / (F0 R) = A^2 / A^1 lies in (0, 1] for any patch.
TEST(ReportText, ARadiusTheTorqueCannotHaveIsWarnedAbout) {
  const auto warned = [](const FitReport& f, const std::string& part) {
    for (const std::string& w : fit_warnings(f))
      if (contains(w, part)) return true;
    return false;
  };
  const FitReport right = fit_of(40);  // the seed tire: M0 / (F0 R) about 0.6
  EXPECT_FALSE(warned(right, "radius"));
  // The same data refitted as if R were 10 times smaller or 100 times larger.
  for (const auto& [factor, part] :
       {std::pair{0.1, "too small for the torque"}, std::pair{100.0, "too large for the torque"}}) {
    const FitReport wrong = fit_of(40, 0.087 * factor);
    EXPECT_TRUE(warned(wrong, part)) << factor;
    EXPECT_TRUE(contains(fit_report_text(ReportInput{}, wrong), "is R in metres")) << factor;
  }
}
