// The contact's own geometry in the general model (effect_model.hpp): a patch whose centre is
// off the body's and a contact smaller than the body, against a brute-force quadrature of
// Coulomb's law over the displaced, shrunk disk (a second method), and the closed loop on rows of
// an off-centre patch: it names the patch's centre, not a rig's torque offset.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/simulation.hpp"

using namespace contensou;

namespace {

constexpr double kR = 0.05;

// The exact integrals over a uniform pressure, f N = 3 N.
ModelSpec uniform_spec() {
  IdentificationOptions o;
  o.radius_m = kR;
  o.normal_load_n = 10.0;
  o.profile = uniform_profile();
  MeasuredData one;
  one.points.resize(1);
  ModelSpec s = base_spec_for(one, o);
  s.exact_only = true;
  s.value[kF0] = 3.0;
  return s;
}

// Coulomb's law summed over a uniform disk of radius a centred at (xc, yc), load share per cell,
// f N = F0: the friction on the body and its torque about the body's centre (midpoint rule in
// polar coordinates about the disk's centre).
Eigen::Vector3d brute_force(double F0, double a, double xc, double yc,
                            const Kinematics<double>& k) {
  const int nr = 600, nt = 720;
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (int i = 0; i < nr; ++i) {
    const double r = a * (i + 0.5) / nr;
    for (int j = 0; j < nt; ++j) {
      const double th = 2.0 * std::numbers::pi * (j + 0.5) / nt;
      const double x = xc + r * std::cos(th), y = yc + r * std::sin(th);
      const double ux = k.vx - k.omega * y, uy = k.vy + k.omega * x;
      const double u = std::hypot(ux, uy), dA = r;
      area += dA;
      if (u == 0.0) continue;
      const double fx = -ux / u * dA, fy = -uy / u * dA;
      w += Eigen::Vector3d(fx, fy, x * fy - y * fx);
    }
  }
  return F0 * w / area;
}

}  // namespace

TEST(ContactGeometry, AnOffCentreSmallerPatchAgreesWithABruteForceQuadrature) {
  ModelSpec s = uniform_spec();
  s.value[kCentreX] = 0.2;
  s.value[kCentreY] = -0.1;
  s.value[kContactRatio] = 0.7;
  for (const Kinematics<double>& k :
       {Kinematics<double>{0.01, 0.0, 0.0}, Kinematics<double>{0.0, 0.0, 0.4},
        Kinematics<double>{0.006, -0.004, 0.3}, Kinematics<double>{-0.002, 0.01, -0.5}}) {
    const Resultants<double> m = evaluate_model(s, s.value.data(), k);
    const Eigen::Vector3d b = brute_force(3.0, 0.7 * kR, 0.2 * kR, -0.1 * kR, k);
    EXPECT_NEAR(m.Fx, b.x(), 2e-4 * 3.0) << k.vx << " " << k.vy << " " << k.omega;
    EXPECT_NEAR(m.Fy, b.y(), 2e-4 * 3.0) << k.vx << " " << k.vy << " " << k.omega;
    EXPECT_NEAR(m.Mz, b.z(), 2e-4 * 3.0 * kR) << k.vx << " " << k.vy << " " << k.omega;
  }
  // At the null values the model is the centred patch of the body's radius.
  const ModelSpec centred = uniform_spec();
  const Kinematics<double> k{0.006, -0.004, 0.3};
  const Resultants<double> m = evaluate_model(centred, centred.value.data(), k);
  const Eigen::Vector3d b = brute_force(3.0, kR, 0.0, 0.0, k);
  EXPECT_NEAR(m.Mz, b.z(), 2e-4 * 3.0 * kR);
}

// Rows of the seed tire whose patch sits 0.1 R ahead of the point the torque is taken about
// (longitudinal and lateral sweeps, 1 % noise): the loop finds the centre, not an offset.
TEST(ContactGeometry, TheLoopNamesTheCentreOfAnOffCentrePatch) {
  ContactPatch patch = seed_tire_patch();
  patch.profile.kx = 0.14;
  const ExactModel<double> model = make_exact_model(patch);
  const double R = 0.087, xc = 0.1 * R;
  DiagramSpec spec;
  spec.radius_m = R;
  spec.points = 20;
  spec.noise = SimulatedNoise::none;
  MeasuredData d;
  std::array<double, kChannels> peak{};
  for (int sweep = 0; sweep < 2; ++sweep) {
    spec.direction_rad = sweep * 0.5 * std::numbers::pi;
    for (MeasuredPoint p : simulate_diagrams(model, spec).points) {
      const Kinematics<double>& k = p.kinematics;
      const Resultants<double> r =
          exact_resultants(model, Kinematics<double>{k.vx, k.vy + k.omega * xc, k.omega})
              .resultants;
      p.force = {r.Fx, r.Fy, r.Mz + xc * r.Fy};
      for (int c = 0; c < kChannels; ++c) peak[c] = std::max(peak[c], std::abs(*p.force[c]));
      d.points.push_back(p);
    }
  }
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0.0, 1.0);
  for (MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c) *p.force[c] += 0.01 * peak[c] * N(rng);
  IdentificationOptions o;
  o.radius_m = R;
  o.profile = seed_tire_profile();
  o.normal_load_n = 4535;
  const ClosedLoopReport r = close_the_loop(d, o);
  const std::set<std::string> accepted(r.accepted_effects.begin(), r.accepted_effects.end());
  std::string steps;
  for (const LoopStep& st : r.steps)
    steps += st.effect + " (" + st.detail + ") " + (st.accepted ? "accepted" : "no") +
             (st.removed ? " removed" : "") + " lr " + std::to_string(st.lr) + "; ";
  EXPECT_EQ(accepted.count("centre_offset"), 1u) << steps;
  EXPECT_EQ(accepted.count("channel_offset"), 0u);
  EXPECT_NEAR(r.final_spec.value[kCentreX], 0.1, 0.02);
}
