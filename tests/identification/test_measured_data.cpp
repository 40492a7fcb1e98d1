// Measured diagrams read and combined (measured_data.hpp): several files fitted together keep
// each row's file and line, recorded columns are matched by header across files, and a load
// given for a file reaches exactly its rows that carry no Fz of their own.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/identification/measured_data.hpp"

using namespace contensou;

namespace {

// A CSV file in the test's temporary folder; removed at the end of the test.
struct TempCsv {
  std::string path;
  explicit TempCsv(const std::string& name, const std::string& text)
      : path(testing::TempDir() + name) {
    std::ofstream(path) << text;
  }
  ~TempCsv() { std::remove(path.c_str()); }
};

}  // namespace

TEST(CombineMeasured, EachRowKeepsItsFileAndLineAndRecordedColumnsMatchByHeader) {
  const TempCsv a("combine_a.csv",
                  "vx_mps,vy_mps,omega_radps,Fx_N,T [degC]\n"
                  "0.1,0,10,-100,20\n"
                  "0.2,0,10,-150,25\n");
  const TempCsv b("combine_b.csv",
                  "# a comment line\n"
                  "vx_mps,vy_mps,omega_radps,Fx_N,p_kPa,T [degC]\n"
                  "0.3,0,10,-170,200,30\n");
  const MeasuredData all =
      combine_measured({read_measured_csv(a.path), read_measured_csv(b.path)}, {});
  ASSERT_EQ(all.points.size(), 3u);
  ASSERT_EQ(all.sources.size(), 2u);
  EXPECT_EQ(all.sources[0], a.path);
  EXPECT_EQ(all.sources[1], b.path);
  EXPECT_EQ(all.points[0].source, 0);
  EXPECT_EQ(all.points[2].source, 1);
  EXPECT_EQ(all.points[1].line, 3);
  EXPECT_EQ(all.points[2].line, 3);    // the comment line counts
  ASSERT_EQ(all.recorded.size(), 2u);  // T from both files, p from the second
  std::size_t t = all.recorded[0].header == "T [degC]" ? 0 : 1;
  const std::size_t p = 1 - t;
  EXPECT_EQ(all.recorded[p].header, "p_kPa");
  // Temperatures in kelvin, whichever file they came from; p is NaN in the first file's rows.
  EXPECT_NEAR(all.points[1].recorded[t], 298.15, 1e-9);
  EXPECT_NEAR(all.points[2].recorded[t], 303.15, 1e-9);
  EXPECT_TRUE(std::isnan(all.points[0].recorded[p]));
  EXPECT_NEAR(all.points[2].recorded[p], 2e5, 1e-6);
}

TEST(CombineMeasured, AGivenLoadReachesOnlyTheRowsWithoutTheirOwnFz) {
  const TempCsv a("combine_load.csv",
                  "vx_mps,vy_mps,omega_radps,Fx_N,Fz_N\n"
                  "0.1,0,10,-100,\n"
                  "0.2,0,10,-150,3000\n");
  // One file, one load (as Python's identify(data, normal_load=[N]) passes it).
  MeasuredData one = combine_measured({read_measured_csv(a.path)}, {4000.0});
  ASSERT_EQ(one.points.size(), 2u);
  EXPECT_EQ(one.points[0].normal_load.value_or(0.0), 4000.0);
  EXPECT_EQ(one.points[1].normal_load.value_or(0.0), 3000.0);
  EXPECT_EQ(one.source, a.path);
  // Two files, one load each.
  const TempCsv b("combine_load_b.csv", "vx_mps,vy_mps,omega_radps,Fx_N\n0.3,0,10,-170\n");
  MeasuredData two =
      combine_measured({read_measured_csv(a.path), read_measured_csv(b.path)}, {4000.0, 5000.0});
  ASSERT_EQ(two.points.size(), 3u);
  EXPECT_EQ(two.points[0].normal_load.value_or(0.0), 4000.0);
  EXPECT_EQ(two.points[1].normal_load.value_or(0.0), 3000.0);
  EXPECT_EQ(two.points[2].normal_load.value_or(0.0), 5000.0);
  // No load given: a row without Fz stays without one.
  MeasuredData none = combine_measured({read_measured_csv(a.path)}, {});
  EXPECT_FALSE(none.points[0].normal_load.has_value());
}

TEST(CombineMeasured, RefusesALoadsListOfAnotherLengthAndALoadThatIsNotPositive) {
  const TempCsv a("combine_bad.csv", "vx_mps,vy_mps,omega_radps,Fx_N\n0.1,0,10,-100\n");
  auto files = [&] {
    std::vector<MeasuredData> f;
    for (int k = 0; k < 3; ++k) f.push_back(read_measured_csv(a.path));
    return f;
  };
  EXPECT_THROW(combine_measured(files(), {1000.0, 2000.0}), InvalidArgument);
  EXPECT_THROW(combine_measured(files(), {-1000.0}), InvalidArgument);
  EXPECT_THROW(combine_measured(files(), {0.0, 1.0, 2.0}), InvalidArgument);
  EXPECT_THROW(combine_measured(files(), {std::nan(""), 1.0, 2.0}), InvalidArgument);
  EXPECT_NO_THROW(combine_measured(files(), {1000.0, 2000.0, 3000.0}));
}
