// The law FMU's resource file (src/fmu/law_resource.hpp): the tables read back give the same
// law bit for bit, and a damaged or foreign file is refused with its line, never evaluated.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "contensou/fmu/fmu_export.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/exact_model.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "law_resource.hpp"

namespace contensou::fmu {
namespace {

// (A looser table than the default for the slip-speed law, whose build is the slow part here:
// the file's round trip does not depend on the tolerance.)
LawResource exact_resource(const ContactPatch& patch, double tolerance = 1e-8) {
  ExactLawOptions options;
  options.tolerance = tolerance;
  LawResource r;
  r.guid = "{test}";
  r.description = "a patch";
  r.normal_load_n = normal_load(patch);
  r.radius_m = patch.radius_m;
  r.exact = make_exact_law(make_exact_model(patch), options);
  return r;
}

ContactPatch rolling_seed_tire() {
  ContactPatch p = seed_tire_patch();
  p.profile.kx = 0.14;
  p.profile.ky = -0.03;
  p.kappa = 0.8;
  return p;
}

// The same resultants and Jacobians at kinematics over every regime.
void expect_same_law(const ExactLaw& a, const ExactLaw& b) {
  for (int i = 0; i < 300; ++i) {
    const double u = 2.0 * (static_cast<double>(i % 17) / 16.0) - 1.0;
    const Kinematics<double> k{0.01 * i * u, 0.3 * u * (i % 3), 20.0 * (i % 5 - 2) * u};
    const ExactLawWithJacobian ja = exact_law_resultants_with_jacobian(a, k),
                               jb = exact_law_resultants_with_jacobian(b, k);
    EXPECT_EQ(ja.resultants.Fx, jb.resultants.Fx) << i;
    EXPECT_EQ(ja.resultants.Fy, jb.resultants.Fy) << i;
    EXPECT_EQ(ja.resultants.Mz, jb.resultants.Mz) << i;
    EXPECT_TRUE(ja.jacobian == jb.jacobian) << i;
  }
}

TEST(FmuResource, ExactLawReadBackBitForBit) {
  const LawResource r = exact_resource(rolling_seed_tire());
  const LawResource back = read_law_resource(write_law_resource(r), "law.txt");
  ASSERT_TRUE(back.exact.has_value());
  EXPECT_EQ(back.guid, r.guid);
  EXPECT_EQ(back.normal_load_n, r.normal_load_n);
  EXPECT_EQ(back.exact->table.breaks, r.exact->table.breaks);
  EXPECT_EQ(back.exact->table.coefficients, r.exact->table.coefficients);
  EXPECT_EQ(back.exact->achieved, r.exact->achieved);
  expect_same_law(*r.exact, *back.exact);
}

TEST(FmuResource, SlipSpeedLawReadBackBitForBit) {
  ContactPatch p = rolling_seed_tire();
  p.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 10.0, 2.0};
  const LawResource r = exact_resource(p, 1e-5);
  ASSERT_TRUE(r.exact->falling.has_value());
  const LawResource back = read_law_resource(write_law_resource(r), "law.txt");
  ASSERT_TRUE(back.exact->falling.has_value());
  EXPECT_EQ(back.exact->falling->block, r.exact->falling->block);
  expect_same_law(*r.exact, *back.exact);
}

TEST(FmuResource, FractionalLawReadBack) {
  LawResource r;
  r.guid = "{f}";
  r.normal_load_n = 4535.0;
  r.fractional = fractional_law_from_patch(rolling_seed_tire());
  const LawResource back = read_law_resource(write_law_resource(r), "law.txt");
  ASSERT_TRUE(back.fractional.has_value());
  const Kinematics<double> k{0.3, -0.1, 7.0};
  const Resultants<double> a = fractional_resultants(*r.fractional, k),
                           b = fractional_resultants(*back.fractional, k);
  EXPECT_EQ(a.Fx, b.Fx);
  EXPECT_EQ(a.Fy, b.Fy);
  EXPECT_EQ(a.Mz, b.Mz);
}

// The text with the first line starting with `name` replaced by `line`.
std::string replaced(std::string text, const std::string& name, const std::string& line) {
  const std::size_t at = text.find("\n" + name + " ");
  EXPECT_NE(at, std::string::npos) << name;
  const std::size_t end = text.find('\n', at + 1);
  return text.replace(at + 1, end - at - 1, line);
}

void expect_refused(const std::string& text, const std::string& fragment) {
  try {
    read_law_resource(text, "law.txt");
    ADD_FAILURE() << "accepted; expected an error with '" << fragment << "'";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("law.txt:", 0), 0u) << e.what();
  }
}

TEST(FmuResource, DamagedFilesAreRefusedWithTheirLine) {
  const std::string good = write_law_resource(exact_resource(rolling_seed_tire()));
  expect_refused("", "empty file");
  expect_refused("PK\3\4 a zip\n", "not a law FMU resource");
  expect_refused(good.substr(0, good.size() / 2), "law.txt:");
  expect_refused(replaced(good, "exact", "exact 6 0x1p+0 0x1p+0 nan 0 1 5"), "not finite");
  expect_refused(replaced(good, "exact", "exact 5 0x1p+0 0x1p+0 0 0 1"), "expected 6");
  expect_refused(replaced(good, "exact", "exact 6 0x1p+0 0x1p+0 0 0 1 5 7"), "more values");
  expect_refused(replaced(good, "exact", "exact 99999999999 1"), "the count must be");
  expect_refused(replaced(good, "exact", "exact 6 -1 0x1p+0 0 0 1 5"), "must be positive");
  expect_refused(replaced(good, "table_shape", "table_shape 2 6 40"), "table degree");
  expect_refused(replaced(good, "table_breaks", "table_breaks 3 -1 0.5 0.25"), "");
  expect_refused(replaced(good, "table_breaks", "table_breaks 3 -1 0.5 1"), "table_coefficients");
  expect_refused(good + "mystery 1 0\n", "unknown record 'mystery'");
  expect_refused(good + "exact 6 1 1 0 0 1 5\n", "a second record 'exact'");
  expect_refused(replaced(good, "text law", "text law lookup"), "exact or fractional expected");
}

TEST(FmuResource, DamagedFallingTableIsRefused) {
  ContactPatch p = rolling_seed_tire();
  p.slip_speed_friction = SlipSpeedFriction<double>{0.8, 0.45, 10.0, 2.0};
  const std::string good = write_law_resource(exact_resource(p, 1e-5));
  const std::size_t at = good.find("\nfalling_block ");
  const std::size_t end = good.find('\n', at + 1);
  std::string line = good.substr(at + 1, end - at - 1);
  line = line.substr(0, line.rfind(' ')) + " 0x1p+40";  // the last offset far beyond the data
  expect_refused(replaced(good, "falling_block", line), "is not a block of falling_coefficients");
  std::string without = good;
  without.erase(good.find("exact_slip_speed"),
                good.find('\n', good.find("exact_slip_speed")) - good.find("exact_slip_speed") + 1);
  expect_refused(without, "needs both");
}

}  // namespace
}  // namespace contensou::fmu

namespace contensou::fmu {

// A name no XML reader accepts is refused by name before anything is written.
TEST(FmuExport, NamesXmlCannotCarryAreRefusedAndNothingIsWritten) {
  const std::string path = ::testing::TempDir() + "contensou_unprintable.fmu";
  std::remove(path.c_str());
  for (const std::string& name : {std::string("a\x01"
                                              "b\x1b"
                                              "c"),
                                  std::string("tire\abell"), std::string("cut \xc3")}) {
    LawFmuOptions o;
    o.law = FmuLaw::fractional;
    o.model_name = name;
    try {
      export_law_fmu(seed_tire_patch(), path, o);
      ADD_FAILURE() << "exported";
    } catch (const InvalidArgument& e) {
      EXPECT_EQ(e.parameter(), "model_name") << e.what();
    }
    o.model_name = "contensou_law";
    o.profile_text = name;
    EXPECT_THROW(export_law_fmu(seed_tire_patch(), path, o), InvalidArgument);
    std::FILE* written = std::fopen(path.c_str(), "rb");
    EXPECT_EQ(written, nullptr);
    if (written) std::fclose(written);
  }
}

}  // namespace contensou::fmu
