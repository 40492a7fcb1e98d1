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

FitReport fit_of(int points) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = points;
  s.noise = SimulatedNoise::additive_gaussian;
  s.noise_level = 0.01;
  s.seed = 11;
  IdentificationOptions o;
  o.radius_m = 0.087;
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
}
