// Rows grouped into sweeps (sweeps.hpp): a rig file's programme of loads and directions comes
// back as the sweeps it was made of, whatever the row order and the load cell's jitter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <set>

#include "contensou/friction/error.hpp"
#include "contensou/identification/sweeps.hpp"

using namespace contensou;

namespace {

// Sweeps of 10 rows at each load and direction, psi from 0.01 to 100 at u = 1 m/s, the load
// read with +-1 % jitter; optionally two pure-spin rows a load, shuffled.
MeasuredData programme(const std::vector<double>& loads, const std::vector<double>& directions,
                       bool pure_spin, bool shuffle) {
  const double R = 0.1;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);
  MeasuredData d;
  int line = 2;
  for (double N : loads) {
    for (double dir : directions)
      for (int i = 0; i < 10; ++i) {
        MeasuredPoint p;
        const double v = 0.01 * std::pow(1e4, i / 9.0);
        p.kinematics = {v * std::cos(dir), v * std::sin(dir), 1.0 / R};
        p.normal_load = N * (1.0 + jitter(rng));
        p.force[0] = 1.0;
        p.line = line++;
        d.points.push_back(p);
      }
    for (int k = 0; pure_spin && k < 2; ++k) {
      MeasuredPoint p;
      p.kinematics = {0.0, 0.0, 1.0 / R};
      p.normal_load = N;
      p.force[2] = 1.0;
      p.line = line++;
      d.points.push_back(p);
    }
  }
  if (shuffle) std::shuffle(d.points.begin(), d.points.end(), rng);
  return d;
}

}  // namespace

TEST(Sweeps, AProgrammeOfLoadsAndDirectionsComesBackAsItsSweeps) {
  for (bool shuffle : {false, true}) {
    const MeasuredData d =
        programme({3000.0, 4500.0, 6000.0}, {0.0, 0.5 * std::numbers::pi}, false, shuffle);
    const std::vector<Sweep> s = sweeps_of(d, 0.1);
    ASSERT_EQ(s.size(), 6u);
    std::set<std::size_t> seen;
    std::set<std::string> labels;
    for (const Sweep& w : s) {
      EXPECT_EQ(w.points.size(), 10u);
      labels.insert(w.label);
      ASSERT_TRUE(w.load_n && w.direction_rad);
      EXPECT_NEAR(w.spin_speed_mps, 1.0, 1e-12);
      for (std::size_t k = 0; k < w.points.size(); ++k) {
        const MeasuredPoint& p = d.points[w.points[k]];
        EXPECT_TRUE(seen.insert(w.points[k]).second) << "a row in two sweeps";
        EXPECT_NEAR(*p.normal_load, *w.load_n, 0.021 * *w.load_n);
        EXPECT_NEAR(std::atan2(p.kinematics.vy, p.kinematics.vx), *w.direction_rad, 1e-12);
        if (k > 0) {  // in increasing psi
          const MeasuredPoint& q = d.points[w.points[k - 1]];
          EXPECT_LT(std::hypot(q.kinematics.vx, q.kinematics.vy),
                    std::hypot(p.kinematics.vx, p.kinematics.vy));
        }
      }
    }
    EXPECT_EQ(seen.size(), d.points.size());
    EXPECT_EQ(labels.size(), 6u);  // each names its load and its direction, nothing else
    for (const Sweep& w : s) {
      char want[64];
      std::snprintf(want, sizeof want, "Fz %.3g kN, %.0f deg", *w.load_n / 1e3,
                    *w.direction_rad * 180.0 / std::numbers::pi);
      EXPECT_EQ(w.label, want);
    }
  }
}

TEST(Sweeps, PureSpinRowsAreASweepOfTheirOwnAndOneSweepIsAllRows) {
  const std::vector<Sweep> s = sweeps_of(programme({4500.0}, {0.0, 1.0}, true, false), 0.1);
  ASSERT_EQ(s.size(), 3u);
  int pure = 0;
  for (const Sweep& w : s) pure += w.label == "pure spin" && !w.direction_rad;
  EXPECT_EQ(pure, 1);
  const std::vector<Sweep> one = sweeps_of(programme({4500.0}, {0.0}, false, false), 0.1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one.front().label, "all rows");
}

TEST(Sweeps, ARadiusThatIsNotPositiveIsAnError) {
  const MeasuredData d = programme({4500.0}, {0.0}, false, false);
  for (double r : {0.0, -1.0, std::nan("")}) EXPECT_THROW(sweeps_of(d, r), InvalidArgument);
}
