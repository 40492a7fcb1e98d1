// Contact patches shared by the tests of every module.
#pragma once

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

}  // namespace contensou::test_support
