// Checks on ceres::Jet results shared by the tests of every module.
#pragma once

#include <ceres/jet.h>

#include <cmath>

#include "contensou/friction/kinematics.hpp"

namespace contensou::test_support {

// Whether the values and all N derivatives of Fx, Fy, Mz are finite.
template <int N>
bool all_finite(const Resultants<ceres::Jet<double, N>>& r) {
  for (const auto* x : {&r.Fx, &r.Fy, &r.Mz}) {
    if (!std::isfinite(x->a)) return false;
    for (int i = 0; i < N; ++i)
      if (!std::isfinite(x->v[i])) return false;
  }
  return true;
}

}  // namespace contensou::test_support
