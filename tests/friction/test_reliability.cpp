// Finite in, finite out or an error; files whole or not at all (file_output.hpp). Each test
// names the hostile case it guards.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/file_output.hpp"
#include "contensou/friction/fractional_law.hpp"

using namespace contensou;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A fresh folder per test, removed afterwards.
struct Folder {
  fs::path path;
  Folder() {
    std::string t = (fs::temp_directory_path() / "contensou-test-XXXXXX").string();
    path = ::mkdtemp(t.data());
  }
  ~Folder() { fs::remove_all(path); }
};

int entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(FileOutput, ReplacesWholeAndLeavesNoTemporaryFile) {
  Folder d;
  const fs::path p = d.path / "a.json";
  write_file_atomically(p.string(), "old");
  write_file_atomically(p.string(), "new");
  EXPECT_EQ(read(p), "new");
  EXPECT_EQ(entries(d.path), 1);
}

TEST(FileOutput, FollowsASymlinkAndKeepsIt) {
  Folder d;
  write_file_atomically((d.path / "real.json").string(), "old");
  fs::create_symlink("real.json", d.path / "link.json");
  write_file_atomically((d.path / "link.json").string(), "new");
  EXPECT_TRUE(fs::is_symlink(d.path / "link.json"));
  EXPECT_EQ(read(d.path / "real.json"), "new");
  EXPECT_EQ(entries(d.path), 2);
}

TEST(FileOutput, WritesThroughADeviceWithoutReplacingIt) {
  write_file_atomically("/dev/null", "anything");
  struct stat st {};
  ASSERT_EQ(::stat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
}

TEST(FileOutput, RefusesAFifoWithoutReaderAndAFolder) {
  Folder d;
  const fs::path fifo = d.path / "f";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  try {
    write_file_atomically(fifo.string(), "x");  // must not wait for a reader
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a FIFO that nobody reads"), std::string::npos);
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  try {
    write_file_atomically(d.path.string(), "x");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a regular file, a folder"), std::string::npos);
  }
}

TEST(FileOutput, AFailedWriteKeepsThePreviousFile) {
  Folder d;
  const fs::path p = d.path / "big.csv";
  write_file_atomically(p.string(), "old");
  // Past the file-size limit: EFBIG (SIGXFSZ ignored, as the apps do), an error naming it.
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  rlimit small = old;
  small.rlim_cur = 1024;
  const auto previous = std::signal(SIGXFSZ, SIG_IGN);
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string error;
  try {
    write_file_atomically(p.string(), std::string(100000, 'x'));
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, previous);
  EXPECT_NE(error.find("File too large"), std::string::npos) << error;
  EXPECT_EQ(read(p), "old");
  EXPECT_EQ(entries(d.path), 1);
}

TEST(FileOutput, AMissingFolderIsAnErrorNamingThePath) {
  Folder d;
  const std::string p = (d.path / "no" / "such.json").string();
  try {
    write_file_atomically(p, "x");
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(p), std::string::npos);
  }
}

TEST(CsvReliability, NulInsideANumberAndAFolderAreRefused) {
  const std::string text("vx_mps,vy_mps\n1\0002,3\n", 20);
  try {
    parse_csv(text, "nul.csv");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find("nul.csv:2:2"), std::string::npos) << e.what();
  }
  Folder d;
  EXPECT_THROW(read_csv(d.path.string()), ParseError);
}

TEST(Scales, SubnormalPositiveValuesAreRefused) {
  EXPECT_THROW(require_positive("N", 1e-310), InvalidArgument);
  EXPECT_NO_THROW(require_positive("N", 1e-300));
}

TEST(Scales, APatchBeyondTheDoublesIsRefusedNamingRadiusAndPressure) {
  ContactPatch p = seed_tire_patch();
  p.radius_m = 1e308;
  try {
    validate(p);
    FAIL() << "no error";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("radius_m, reference_pressure_pa"), std::string::npos);
  }
  p = seed_tire_patch();
  p.reference_pressure_pa = 1e-300;
  EXPECT_THROW(validate(p), InvalidArgument);
  p = seed_tire_patch();
  p.radius_m = 1e90;  // N ~ 1e185, f N R ~ 1e275: large but representable, accepted and finite
  p.reference_pressure_pa = 1.0;
  const ExactModel<double> m = make_exact_model(p);
  const auto r = exact_resultants(m, Kinematics<double>{1e90, 0.0, 1.0}, {1e-8}).resultants;
  EXPECT_TRUE(r.vector().allFinite());
}

// A load in range with a friction that puts f N R out of it: the friction is named, not the load.
TEST(Scales, AFrictionBeyondTheDoublesIsBlamedOnTheFriction) {
  for (const double f : {1e300, 1e-303}) {
    ContactPatch p = seed_tire_patch();
    p.friction = f;
    try {
      validate(p);
      FAIL() << "no error for f = " << f;
    } catch (const InvalidArgument& e) {
      const std::string what = e.what();
      EXPECT_EQ(what.rfind("friction = ", 0), 0u) << what;
      EXPECT_NE(what.find("gives a torque scale f N R of 1e"), std::string::npos) << what;
    }
  }
  ContactPatch p = seed_tire_patch();
  p.friction = 1e250;  // f N R ~ 1e252: representable, accepted
  EXPECT_NO_THROW(validate(p));
}

// Finite in, finite out or an error: the fractional law over parameters and kinematics from
// 1e-300 to 1e300 (log-uniform, random signs) either throws InvalidArgument or returns finite
// resultants and Jacobian. F0 = M0 = 1e308 is refused (it used to give NaN).
TEST(Scales, FractionalLawIsFiniteOrRefusedOverTheDoubles) {
  FractionalLaw<double> law;
  law.F0 = law.M0 = 1e308;
  law.radius = 0.1;
  EXPECT_THROW(fractional_resultants(law, Kinematics<double>{1.0, 0.0, 1.0}), InvalidArgument);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0), sign(-1.0, 1.0);
  auto wide = [&] { return std::copysign(std::pow(10.0, exponent(rng)), sign(rng)); };
  int refused = 0, evaluated = 0;
  for (int i = 0; i < 20000; ++i) {
    FractionalLaw<double> p;
    p.F0 = std::abs(wide());
    p.M0 = std::abs(wide());
    p.radius = std::pow(10.0, exponent(rng) / 10.0);
    p.kx = 0.5 * sign(rng);
    p.ky = 0.5 * sign(rng);
    const Kinematics<double> k{wide(), wide(), wide()};
    try {
      const Resultants<double> r = fractional_resultants(p, k);
      const FractionalWithJacobian j = fractional_resultants_with_jacobian(p, k);
      ASSERT_TRUE(r.vector().allFinite()) << "F0 " << p.F0 << " M0 " << p.M0 << " R " << p.radius;
      ASSERT_TRUE(j.resultants.vector().allFinite() && j.jacobian.allFinite())
          << "F0 " << p.F0 << " M0 " << p.M0 << " R " << p.radius << " v " << k.vx;
      ++evaluated;
    } catch (const InvalidArgument&) {
      ++refused;
    }
  }
  EXPECT_GT(evaluated, 1000);
  EXPECT_GT(refused, 300);  // both branches exercised (729 of 20000 refused with seed 7)
}
