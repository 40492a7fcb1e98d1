// The request shared by contensou-identify and Python's identify(): one table of keys, errors
// naming the key as each front end writes it, and the normal load taken from where it is known.
#include <gtest/gtest.h>

#include "seed_tire_law.hpp"

#include <cmath>
#include <set>
#include <string>
#include <thread>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/identify_request.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

MeasuredData sweep(std::optional<double> fz) {
  DiagramSpec s;
  s.radius_m = 0.087;
  s.points = 40;
  s.noise = SimulatedNoise::additive_gaussian;
  s.noise_level = 0.01;
  s.seed = 7;
  MeasuredData d = simulate_diagrams(test::seed_tire_law(), s);
  d.source = "sweep";
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    d.points[i].line = static_cast<int>(i) + 2;
    // A load cell that reads N within +-1 %: the mean is what f = F0/N must use.
    if (fz) d.points[i].normal_load = *fz * (1.0 + 0.01 * std::sin(static_cast<double>(i)));
  }
  return d;
}

std::string message_of(const IdentifyRequest& r) {
  ProfileChoice profile;
  try {
    identify_options(r, profile);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(IdentifyRequest, KeysAreNamedAsEachFrontEndWritesThem) {
  EXPECT_EQ(key_name("normal_load", KeyStyle::command_line), "--normal-load");
  EXPECT_EQ(key_name("normal_load", KeyStyle::python), "normal_load");
  std::set<std::string> seen;
  for (const RequestKey& k : identify_request_keys()) {
    EXPECT_TRUE(seen.insert(k.key).second) << "key listed twice: " << k.key;
    EXPECT_GT(std::string(k.help).size(), 10u) << k.key;
    EXPECT_STREQ(key_help(k.key), k.help);
  }
  EXPECT_THROW(key_help("radius_m"), std::logic_error);
}

TEST(IdentifyRequest, BadValuesAreRefusedNamingTheKeyAndTheRange) {
  IdentifyRequest r;
  r.radius_m = 0.087;
  EXPECT_EQ(message_of(r), "");
  struct Case {
    std::function<void(IdentifyRequest&)> set;
    std::string python, command_line;
  };
  const std::vector<Case> cases = {
      {[](IdentifyRequest& q) { q.radius_m = 0.0; }, "radius = 0: must be positive",
       "--radius = 0: must be positive"},
      {[](IdentifyRequest& q) { q.loss = "l1"; }, "loss = l1: must be one of none, huber, cauchy",
       "--loss = l1"},
      {[](IdentifyRequest& q) { q.alpha = 0.7; }, "alpha = 0.7: must lie in [1e-12, 0.5]",
       "--alpha = 0.7"},
      {[](IdentifyRequest& q) {
         q.noise_scale = {1.0, 2.0};
       },
       "noise_scale needs three values", "--noise-scale needs three values"},
      {[](IdentifyRequest& q) {
         q.noise_scale = {1.0, -2.0, 1.0};
       },
       "noise_scale = -2", "--noise-scale = -2"},
      {[](IdentifyRequest& q) { q.noise_model = "white"; }, "noise_model = white",
       "--noise-model = white"},
      {[](IdentifyRequest& q) {
         q.noise_model = "affine";
         q.noise_scale = {1.0, 1.0, 1.0};
       },
       "noise_scale gives constant scales: use noise_model additive or relative",
       "--noise-scale gives constant scales: use --noise-model additive or relative"},
      {[](IdentifyRequest& q) { q.pressure_pa = 2e5; }, "pressure 2e+05 is the reference",
       "--pressure 2e+05 is the reference"},
      {[](IdentifyRequest& q) {
         q.normal_load_n = 4000.0;
         q.profile = "hertz";
         q.pressure_pa = 2e5;
       },
       "give normal_load or pressure, not both", "give --normal-load or --pressure, not both"},
      {[](IdentifyRequest& q) { q.profile_smoothing = 4; }, "profile_smoothing needs profile",
       "--profile-smoothing needs --profile"},
      {[](IdentifyRequest& q) { q.fix["a"] = std::nan(""); }, "fix a = nan: must be finite",
       "--fix a = nan"},
      {[](IdentifyRequest& q) { q.profile = "/nowhere/profile.csv"; }, "/nowhere/profile.csv",
       "/nowhere/profile.csv"},
      // A fixed parameter within the fit's bounds: kx = 1.5 would make the pressure negative.
      {[](IdentifyRequest& q) { q.fix["kx"] = 1.5; },
       "fix kx = 1.5: must lie in [-0.95, 0.95] (|kx| >= 1 makes the pressure negative)",
       "--fix kx = 1.5: must lie in [-0.95, 0.95]"},
      {[](IdentifyRequest& q) { q.fix["a"] = -1.0; },
       "fix a = -1: must lie in [1e-12, 4] (a <= 4 for any non-negative pressure)", "--fix a = -1"},
      {[](IdentifyRequest& q) { q.fix["b1"] = 0.1; }, "unknown parameter (use F0_N",
       "--fix = b1=0.1: unknown parameter"},
      // Noise scales that would make chi^2 overflow (1e-300 N) or that no force reaches.
      {[](IdentifyRequest& q) {
         q.noise_scale = {1e-300, 1.0, 1.0};
       },
       "noise_scale = 1e-300: must lie in [1e-12, 1e12]", "--noise-scale = 1e-300"},
      {[](IdentifyRequest& q) {
         q.noise_scale = {1.0, 1.0, 1e300};
       },
       "noise_scale = 1e+300: must lie in [1e-12, 1e12]", "--noise-scale = 1e+300"},
      {[](IdentifyRequest& q) { q.profile_smoothing = -1; },
       "profile_smoothing = -1: must lie in [0, 64]", "--profile-smoothing = -1"},
      {[](IdentifyRequest& q) { q.profile_smoothing = 65; },
       "profile_smoothing = 65: must lie in [0, 64]", "--profile-smoothing = 65"},
  };
  for (const Case& c : cases) {
    IdentifyRequest q = r;
    c.set(q);
    q.style = KeyStyle::python;
    EXPECT_NE(message_of(q).find(c.python), std::string::npos) << message_of(q);
    q.style = KeyStyle::command_line;
    EXPECT_NE(message_of(q).find(c.command_line), std::string::npos) << message_of(q);
  }
}

TEST(IdentifyRequest, NormalLoadComesFromTheFzColumnOrElseFromTheProfile) {
  IdentifyRequest r;
  r.radius_m = 0.087;
  r.loop = false;
  // From the data's Fz column: its mean, and the report says where it came from.
  const IdentifyRun from_fz = identify(sweep(4500.0), r);
  ASSERT_TRUE(from_fz.input.normal_load_n);
  EXPECT_NEAR(*from_fz.input.normal_load_n, 4500.0, 0.01 * 4500.0);
  EXPECT_NE(from_fz.input.normal_load_source.find("mean of the Fz column over 40 rows"),
            std::string::npos)
      << from_fz.input.normal_load_source;
  // Given: used as is, no source line.
  r.normal_load_n = 4000.0;
  const IdentifyRun given = identify(sweep(4500.0), r);
  EXPECT_EQ(*given.input.normal_load_n, 4000.0);
  EXPECT_TRUE(given.input.normal_load_source.empty());
  // Given with a built-in profile: the profile gives the shape, the load is the one given.
  r.profile = "hertz";
  const IdentifyRun given_with_profile = identify(sweep(std::nullopt), r);
  EXPECT_EQ(*given_with_profile.input.normal_load_n, 4000.0);
  r.profile.clear();
  // From a built-in profile and its pressure: N = 2 pi R^2 p* A1 (theory.md section 1), the
  // same as the contact patch computes.
  r.normal_load_n.reset();
  r.profile = "seed-tire";
  r.pressure_pa = 2.1e5;
  const IdentifyRun from_profile = identify(sweep(std::nullopt), r);
  ContactPatch patch;
  patch.radius_m = 0.087;
  patch.reference_pressure_pa = 2.1e5;
  patch.friction = 0.3;
  patch.profile = seed_tire_profile();
  EXPECT_NEAR(*from_profile.input.normal_load_n, normal_load(patch), 1e-9 * normal_load(patch));
  // The profile's pressure and rows with their own Fz: the rows win (each row at its load, f at
  // their mean), and the report says that the profile gives only its shape.
  const IdentifyRun both = identify(sweep(3000.0), r);
  EXPECT_NEAR(*both.input.normal_load_n, 3000.0, 0.01 * 3000.0);
  EXPECT_NE(both.input.normal_load_source.find("the profile's pressure, " +
                                               std::to_string(std::lround(normal_load(patch))) +
                                               " N over the patch, gives only its shape"),
            std::string::npos)
      << both.input.normal_load_source;
  // No load anywhere: none reported, and f is not either.
  r.profile.clear();
  r.pressure_pa.reset();
  EXPECT_FALSE(identify(sweep(std::nullopt), r).input.normal_load_n);
}

// The same input gives the same bits, whatever else the machine does: four identical
// identifications on four threads at once and one alone give byte-identical reports (with
// several evaluation threads, Ceres' sums of the cost and gradient change order from run to
// run and the last digits move).
TEST(IdentifyRequest, TheSameInputGivesTheSameReportBitForBit) {
  IdentifyRequest r;
  r.radius_m = 0.087;
  r.loop = false;
  r.profile = "seed-tire";
  const MeasuredData d = sweep(std::nullopt);
  const auto report = [&] {
    const IdentifyRun run = identify(d, r);
    return fit_report_json(run.input, run.result.fit);
  };
  const std::string alone = report();
  std::vector<std::string> together(4);
  std::vector<std::thread> threads;
  for (std::string& out : together) threads.emplace_back([&out, &report] { out = report(); });
  for (std::thread& t : threads) t.join();
  for (const std::string& out : together) EXPECT_EQ(out, alone);
}

// noise_model: auto (the default) asks the closed loop to choose between one constant scale
// per channel and a + b|y|; the other words fix the model (and no test is made).
TEST(IdentifyRequest, TheNoiseModelKeyChoosesTheModelOrLetsTheLoopChoose) {
  IdentifyRequest r;
  r.radius_m = 0.087;
  EXPECT_EQ(r.noise_model, "auto");
  const auto options = [](const IdentifyRequest& q) {
    ProfileChoice profile;
    return identify_options(q, profile);
  };
  IdentifyOptions o = options(r);
  EXPECT_EQ(o.fit.noise_model, NoiseModel::additive);
  ASSERT_TRUE(o.loop);
  EXPECT_TRUE(o.loop->choose_noise_model);
  r.noise_scale = {1.0, 1.0, 1.0};  // given constant scales: nothing to choose
  EXPECT_FALSE(options(r).loop->choose_noise_model);
  r.noise_scale.clear();
  for (const auto& [word, model] :
       {std::pair{"additive", NoiseModel::additive}, std::pair{"relative", NoiseModel::relative},
        std::pair{"affine", NoiseModel::affine}}) {
    r.noise_model = word;
    o = options(r);
    EXPECT_EQ(o.fit.noise_model, model) << word;
    EXPECT_FALSE(o.loop->choose_noise_model) << word;
  }
}

// One rule for both front ends: 0 (the default) interpolates, so it is accepted with or without
// a profile; validate() alone (no file read) gives the same verdicts as identify_options.
TEST(IdentifyRequest, ProfileSmoothingZeroInterpolatesAndValidateAloneChecksTheRanges) {
  IdentifyRequest r;
  r.radius_m = 0.087;
  r.profile_smoothing = 0;
  EXPECT_NO_THROW(validate(r));
  r.profile = "hertz";
  EXPECT_NO_THROW(validate(r));
  r.profile_smoothing = 3;  // a series needs a table to fit
  EXPECT_THROW(validate(r), std::invalid_argument);
  r = IdentifyRequest{};
  r.radius_m = 0.087;
  r.fix["kx"] = 0.95;  // the bound itself is in range
  EXPECT_NO_THROW(validate(r));
  r.fix["kx"] = -0.9500001;
  EXPECT_THROW(validate(r), std::invalid_argument);
}

TEST(IdentifyRequest, KeysThatNameAChoiceListTheirWords) {
  EXPECT_EQ(key_choices("loss"), (std::vector<std::string>{"none", "huber", "cauchy"}));
  EXPECT_EQ(key_choices("noise_model"),
            (std::vector<std::string>{"auto", "additive", "relative", "affine"}));
  EXPECT_TRUE(key_choices("radius").empty());
  for (const std::string& w : key_choices("loss")) {
    IdentifyRequest r;
    r.radius_m = 0.087;
    r.loss = w;
    EXPECT_NO_THROW(validate(r)) << w;
  }
}

// The library itself, without the request: a fixed kx outside the fit's bounds is refused too.
TEST(IdentifyRequest, TheFitRefusesAFixedParameterOutsideItsBounds) {
  IdentificationOptions o;
  o.radius_m = 0.087;
  o.fixed["kx"] = 1.5;
  try {
    base_spec_for(sweep(std::nullopt), o);
    FAIL() << "kx = 1.5 accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("fix kx = 1.5: must lie in [-0.95, 0.95]"),
              std::string::npos)
        << e.what();
  }
}
