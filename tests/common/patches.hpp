// Contact patches shared by the tests of every module.
#pragma once

#include <cmath>
#include <vector>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/pressure_profile.hpp"

namespace contensou::test_support {

// A uniform disk with round numbers: R = 0.1 m, p* = 100 kPa, f = 0.5 (N = 3141.6 N).
inline ContactPatch uniform_patch() {
  ContactPatch p;
  p.radius_m = 0.1;
  p.reference_pressure_pa = 1.0e5;
  p.friction = 0.5;
  p.profile = uniform_profile();
  return p;
}

// A tabulated profile with a kink near the rim, n points rho_i = i / (n - 1) (a finite-element
// profile): p = 1 + 0.4 rho^2 - 0.9 rho^4 below 0.9, 0.7439 - 4 (rho - 0.9) from there (a step
// of 0.01 at 0.9 as well: the monotone interpolant has a bump one interval wide).
inline PressureProfile kinked_table_profile(int n, std::vector<double>* rho_out = nullptr) {
  std::vector<double> rho, p;
  for (int i = 0; i < n; ++i) {
    const double r = static_cast<double>(i) / (n - 1);
    rho.push_back(r);
    p.push_back(r < 0.9 ? 1.0 + 0.4 * r * r - 0.9 * std::pow(r, 4) : 0.7439 - 4.0 * (r - 0.9));
  }
  if (rho_out) *rho_out = rho;
  return tabulated_profile(rho, p);
}

}  // namespace contensou::test_support
