// Oracles of the exact resultants shared by their tests (test_exact_resultants,
// test_exact_model, test_table_pieces): a brute-force grid straight from the definition
// (theory.md §2), the check against it, and the ratios of the closed forms (theory.md §3).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <numbers>
#include <vector>

#include "closed_forms.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "patches.hpp"

namespace contensou::test_support {

inline constexpr double kPi = std::numbers::pi;

inline ContactPatch seed_patch() {
  return seed_tire_patch();
}

// Brute-force oracle: midpoint rule on an (r, theta) grid about O, straight from the
// definition tau = -sigma f(|vc|) diag(1, kappa) vc/|vc| (theory.md section 2).
inline Resultants<double> brute_force(const ContactPatch& p, const Kinematics<double>& k,
                                      int nr = 700, int nt = 1400) {
  Resultants<double> out;
  const double R = p.radius_m;
  for (int i = 0; i < nr; ++i) {
    const double r = R * (i + 0.5) / nr;
    for (int j = 0; j < nt; ++j) {
      const double th = 2 * kPi * (j + 0.5) / nt;
      const double x = r * std::cos(th), y = r * std::sin(th);
      const double sigma = p.reference_pressure_pa * shape_value(p.profile, r / R) *
                           (1 + p.profile.kx * x / R + p.profile.ky * y / R);
      const double cx = k.vx - k.omega * y, cy = k.vy + k.omega * x;
      const double w = std::hypot(cx, cy);
      if (w == 0.0) continue;
      const double f = p.slip_speed_friction ? friction_at(*p.slip_speed_friction, w) : p.friction;
      const double dA = r * (R / nr) * (2 * kPi / nt);
      const double tx = -sigma * f * cx / w, ty = -sigma * f * p.kappa * cy / w;
      out.Fx += tx * dA;
      out.Fy += ty * dA;
      out.Mz += (x * ty - y * tx) * dA;
    }
  }
  return out;
}

// The exact resultants of a model agree with the brute-force grid within 2e-4 of f N at the
// ratios |v| / (|omega| R) given (sliding at -53 degrees, omega R = 8 m/s); friction dissipates.
inline void expect_matches_brute_force(const ContactPatch& p, const ExactModel<double>& m,
                                       std::initializer_list<double> ratios, double tol = 1e-10) {
  const double fN = m.friction_scale * normal_load(p), R = p.radius_m;
  for (double ratio : ratios) {
    const Kinematics<double> k{0.6 * ratio * 8.0, -0.8 * ratio * 8.0, 8.0 / R};
    const auto e = exact_resultants(m, k, {tol});
    EXPECT_TRUE(e.converged);
    const auto b = brute_force(p, k);
    EXPECT_NEAR(e.resultants.Fx, b.Fx, 2e-4 * fN) << describe(p.profile) << " " << ratio;
    EXPECT_NEAR(e.resultants.Fy, b.Fy, 2e-4 * fN) << describe(p.profile) << " " << ratio;
    EXPECT_NEAR(e.resultants.Mz, b.Mz, 2e-4 * fN * R) << describe(p.profile) << " " << ratio;
    if (ratio > 0.0) {
      EXPECT_LT(e.resultants.Fx * k.vx + e.resultants.Fy * k.vy + e.resultants.Mz * k.omega, 0.0);
    }
  }
}

inline std::vector<double> closed_form_ratios() {
  std::vector<double> eps;
  for (int i = 0; i < 32; ++i) eps.push_back(0.02 * std::pow(1000.0, i / 31.0));  // 0.02 .. 20
  for (double e : {0.999, 1.001, 0.9999, 1.0001, 1 - 1e-7, 1 + 1e-7, 1 - 1e-11, 1 + 1e-11})
    eps.push_back(e);
  return eps;
}

}  // namespace contensou::test_support
