// A realistic fractional law for the seed tire (R = 0.087 m) with the cross-shift constants of
// uniform pressure, which the identification assumes without a profile: the truth the
// identification tests simulate from.
#pragma once

#include "contensou/friction/fractional_law.hpp"

namespace contensou::test {

inline FractionalLaw<double> seed_tire_law() {
  FractionalLaw<double> law;
  law.F0 = 1360;
  law.M0 = 71.8;
  law.a = 1.03;
  law.m = 9.28;
  law.kx = 0.14;
  law.radius = 0.087;
  law.c = 4.0;
  law.Mk = 0.375 * law.M0;
  law.a_k = 1.0;
  return law;
}

}  // namespace contensou::test
