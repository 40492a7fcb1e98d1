#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <numbers>
#include <set>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"
#include "test_seams.hpp"

using namespace contensou;

namespace {

// The seed tire (Table 1 profile, R = 0.087 m, p* = 210 kPa, f = 0.3, kx = 0.14) and a test
// of two sweeps, longitudinal then lateral sliding (20 points each, psi = 0.01 ... 100,
// omega R = 1 m/s, 0.5 s apart), with 1 % white noise: lateral sliding is what makes the
// lateral friction (anisotropy) observable.
struct Case {
  ContactPatch patch;
  RigEffects rig;
};

Case seed_case() {
  Case c;
  c.patch = seed_tire_patch();
  c.patch.profile.kx = 0.14;
  return c;
}

struct Data {
  MeasuredData measured;
  std::array<double, kChannels> noise{};  // true noise scale of each channel
};

template <class Model>
Data two_sweeps(const Model& model, const RigEffects& rig, std::uint64_t seed) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = 20;
  s.noise_level = 0.01;
  s.time_step_s = 0.5;
  s.rig = rig;
  Data d;
  for (int sweep = 0; sweep < 2; ++sweep) {
    s.direction_rad = sweep * 0.5 * std::numbers::pi;
    s.seed = seed + 1000 * sweep;
    for (MeasuredPoint p : simulate_diagrams(model, s).points) {
      *p.time += 20.0 * sweep;
      d.measured.points.push_back(p);
    }
  }
  // The additive noise is 1 % of each channel's peak in its sweep; take the clean peak.
  DiagramSpec clean = s;
  clean.noise = SimulatedNoise::none;
  for (int sweep = 0; sweep < 2; ++sweep) {
    clean.direction_rad = sweep * 0.5 * std::numbers::pi;
    for (const MeasuredPoint& p : simulate_diagrams(model, clean).points)
      for (int c = 0; c < kChannels; ++c)
        d.noise[c] = std::max(d.noise[c], 0.01 * std::abs(*p.force[c]));
  }
  return d;
}

IdentificationOptions options() {
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.profile = seed_tire_profile();
  o.normal_load_n = 4535;
  return o;
}

std::set<std::string> as_set(const std::vector<std::string>& v) {
  return {v.begin(), v.end()};
}

ClosedLoopReport expect_found(const Case& c, const std::set<std::string>& expected,
                              std::uint64_t seed = 7) {
  const Data d = two_sweeps(make_exact_model(c.patch), c.rig, seed);
  ClosedLoopReport r = close_the_loop(d.measured, options());
  EXPECT_EQ(as_set(r.accepted_effects), expected);
  for (const ChannelDiagnostics& ch : r.final_fit.channels) {
    // d.noise is the larger of the two sweeps' noise scales of the channel: the final rms
    // must come within 25 % of it (the fit reaches the noise, no structure left).
    const int ci = ch.channel == "Fx_N" ? 0 : ch.channel == "Fy_N" ? 1 : 2;
    EXPECT_LT(ch.rms, 1.25 * d.noise[ci]) << ch.channel;
  }
  EXPECT_LT(r.final_fit.error, r.base.error);
  EXPECT_FALSE(r.structure_remains);
  return r;
}

}  // namespace

TEST(ClosedLoop, ExactDataNeedsOnlyTheShape) {
  expect_found(seed_case(), {"shape"});
}

TEST(ClosedLoop, FindsAnisotropy) {
  Case c = seed_case();
  c.patch.kappa = 0.8;
  expect_found(c, {"shape", "anisotropy"});
}

TEST(ClosedLoop, FindsLateralPressureShift) {
  Case c = seed_case();
  c.patch.profile.ky = 0.1;
  expect_found(c, {"shape", "pressure_shift_y"});
}

TEST(ClosedLoop, FindsSpeedDependence) {
  Case c = seed_case();
  c.patch.slip_speed_friction = SlipSpeedFriction<double>{0.3, 0.21, 5.0, 1.0};
  const ClosedLoopReport r = expect_found(c, {"shape", "speed_dependence"});
  // f is friction at rest; its note gives f (1 - beta), the friction of fast sliding (0.21).
  const ParameterEstimate* f = r.final_fit.parameter("f");
  const ParameterEstimate* beta = r.final_fit.parameter("speed_drop");
  ASSERT_TRUE(f && beta);
  EXPECT_NEAR(f->value, 0.3, 0.01);
  char fast[32];
  std::snprintf(fast, sizeof fast, "%.4g at large w", f->value * (1.0 - beta->value));
  EXPECT_NE(f->note.find("f at rest (w = 0)"), std::string::npos) << f->note;
  EXPECT_NE(f->note.find(fast), std::string::npos) << f->note;
  EXPECT_NEAR(f->value * (1.0 - beta->value), 0.21, 0.01);
}

// Another tire, as a user would bring it: Hertz pressure with a rolling shift, friction falling
// with the local slip speed inside the integrals (0.6 to 0.42, w_s = 3 m/s), the profile given.
// The loop names exactly the two true effects, and its estimate of the law is the injected one.
TEST(ClosedLoop, FindsSlipSpeedFrictionInsideTheIntegralsOnAnotherTire) {
  Case c;
  c.patch = seed_tire_patch();
  c.patch.profile = hertz_profile();
  c.patch.profile.kx = 0.1;
  c.patch.slip_speed_friction = SlipSpeedFriction<double>{0.6, 0.42, 3.0, 1.0};
  const Data d = two_sweeps(make_exact_model(c.patch), c.rig, 5);
  IdentificationOptions o = options();
  o.profile = hertz_profile();
  o.normal_load_n.reset();
  const ClosedLoopReport r = close_the_loop(d.measured, o);
  EXPECT_EQ(as_set(r.accepted_effects), (std::set<std::string>{"shape", "speed_dependence"}));
  for (const ChannelDiagnostics& ch : r.final_fit.channels) {
    const int ci = ch.channel == "Fx_N" ? 0 : ch.channel == "Fy_N" ? 1 : 2;
    EXPECT_LT(ch.rms, 1.25 * d.noise[ci]) << ch.channel;
  }
  for (const ParameterEstimate& e : r.final_fit.parameters) {
    if (e.name == "speed_drop") {
      EXPECT_NEAR(e.value, 0.3, 0.02);
    }
    if (e.name == "speed_ref_mps") {
      EXPECT_NEAR(e.value, 3.0, 0.3);
    }
  }
}

TEST(ClosedLoop, FindsChannelOffset) {
  Case c = seed_case();
  c.rig.offset = {0.0, 15.0, 0.0};
  expect_found(c, {"shape", "channel_offset"});
}

TEST(ClosedLoop, FindsChannelCrosstalk) {
  Case c = seed_case();
  c.rig.crosstalk[2][0] = 0.002;  // Mz picks up 2 mm times Fx
  expect_found(c, {"shape", "channel_crosstalk"});
}

TEST(ClosedLoop, FindsTwoEffectsAtOnce) {
  Case c = seed_case();
  c.patch.kappa = 0.8;
  c.rig.offset = {0.0, 15.0, 0.0};
  expect_found(c, {"shape", "anisotropy", "channel_offset"});
}

TEST(ClosedLoop, SaysStructureRemainsForAnEffectOutsideTheCatalogue) {
  Case c = seed_case();
  c.rig.periodic_amplitude_n = 50.0;  // rig vibration in Fy, periodic in time
  const Data d = two_sweeps(make_exact_model(c.patch), c.rig, 7);
  const ClosedLoopReport r = close_the_loop(d.measured, options());
  EXPECT_TRUE(r.structure_remains);
  EXPECT_FALSE(r.final_fit.residual_white);
}

TEST(ClosedLoop, NoEffectOnFractionalLawData) {
  // Data drawn from the fractional law (its own shape constants) plus white noise: the loop
  // must accept nothing; false positives at most 5 % of the replicas.
  // The law with the cross-shift constants that the identification assumes without a
  // profile (uniform pressure); a, m, F0, M0, kx those of the seed tire.
  FractionalLaw<double> law = fractional_law_from_patch(seed_case().patch);
  law.c = 4.0;
  law.a_k = 1.0;
  law.Mk = 0.375 * law.M0;
  IdentificationOptions o = options();
  const int replicas = 100;
  int false_positives = 0;
  for (int seed = 1; seed <= replicas; ++seed) {
    const Data d = two_sweeps(law, RigEffects{}, static_cast<std::uint64_t>(seed));
    o.profile = std::nullopt;  // shape constants of uniform pressure, as in `law`
    ClosedLoopOptions lo;
    lo.max_steps = 3;
    const ClosedLoopReport r = close_the_loop(d.measured, o, lo);
    false_positives += !r.accepted_effects.empty();
  }
  EXPECT_LE(false_positives, replicas / 20);
}

// Longitudinal sliding only, with anisotropy injected: anisotropy and a crosstalk Mz <- Fy
// move the residual in the same direction. The loop must accept anisotropy or name it as the
// alternative of what it accepted, with a lateral sweep as the separating measurement.
TEST(ClosedLoop, NamesTheAlternativeWhenTwoEffectsExplainTheResidualEqually) {
  Case c = seed_case();
  c.patch.kappa = 0.8;
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = 60;
  s.noise_level = 0.01;
  s.seed = 3;
  const MeasuredData d = simulate_diagrams(make_exact_model(c.patch), s);
  const ClosedLoopReport r = close_the_loop(d, options());
  const std::set<std::string> accepted = as_set(r.accepted_effects);
  bool named = accepted.count("anisotropy") > 0;
  for (const LoopStep& st : r.steps) {
    if (!st.accepted || st.removed || st.ambiguous_with.empty()) continue;
    ASSERT_EQ(st.separation.size(), st.ambiguous_with.size());
    for (std::size_t i = 0; i < st.ambiguous_with.size(); ++i) {
      if (st.ambiguous_with[i] != "anisotropy") continue;
      named = true;
      EXPECT_NE(st.separation[i].find("a lateral sweep"), std::string::npos) << st.separation[i];
    }
  }
  EXPECT_TRUE(named) << "anisotropy neither accepted nor named as an alternative";
  EXPECT_FALSE(r.structure_remains);
}

// The loop's retry from other starts: every candidate's first fit stops at its start (a testing
// hook gives it no solver iterations). Without a profile the shape step fits the exact integrals
// with an identified profile, and its start (uniform pressure at the law's F0 and kx) fits worse
// than the law it replaces: the loop refits it from other starts (the profile coefficients moved
// towards their bounds), keeps the best, says so, and decides as without the hook.
TEST(ClosedLoop, AFirstFitThatStopsAtItsStartIsRetried) {
  const Data d = two_sweeps(make_exact_model(seed_case().patch), RigEffects{}, 7);
  IdentificationOptions o = options();
  o.profile.reset();
  ClosedLoopOptions lo;
  lo.max_steps = 1;
  const ClosedLoopReport plain = close_the_loop(d.measured, o, lo);
  contensou::testing::Seams::of(lo).first_fit_iterations = 0;
  const ClosedLoopReport stalled = close_the_loop(d.measured, o, lo);
  const auto shape_step = [](const ClosedLoopReport& r) -> const LoopStep* {
    for (const LoopStep& st : r.steps)
      if (st.effect == "shape") return &st;
    return nullptr;
  };
  const LoopStep* retried = shape_step(stalled);
  const LoopStep* first = shape_step(plain);
  ASSERT_NE(retried, nullptr);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->retries, 0);
  EXPECT_GT(retried->retries, 0);
  EXPECT_FALSE(step_fit_failed(*retried));  // a start recovered it
  EXPECT_EQ(retried->accepted, first->accepted);
  EXPECT_EQ(as_set(stalled.accepted_effects), as_set(plain.accepted_effects));
  EXPECT_NEAR(retried->error_after, first->error_after, 1e-3 * first->error_after);
  std::printf("shape: error %.4f -> %.4f after %d retries (%.4f without the hook)\n",
              retried->error_before, retried->error_after, retried->retries, first->error_after);
  const std::string text = loop_report_text(ReportInput{}, stalled);
  EXPECT_NE(text.find("the first fit with shape ended worse than the model it extends; this row "
                      "is its fit from another start"),
            std::string::npos)
      << text;
}
