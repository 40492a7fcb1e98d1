// Coefficients for other engines' spin friction from a contact patch, each matched
// at one point and measured against the exact resultants over psi = v / (omega R) in
// [1e-3, 1e3]. Errors are relative to F0 = f N (forces) and M0 = f N R A^2/A^1 (torque), the
// exact pure-spin torque (theory.md section 4: M0 = 2 pi f R^3 p* A^2, N = 2 pi R^2 p* A^1).
// The same table as contensou.engines in the Python package.
//
// - MuJoCo, condim 4, elliptic cone (friction="f mu_t 0", mu_t a length): read as maximum
//   dissipation on the ellipse (F / f N)^2 + (M / mu_t N)^2 <= 1, which gives
//   F / F0 = psi / sqrt(psi^2 + c^2), M = mu_t N c / sqrt(psi^2 + c^2), c = mu_t / (f R).
//   Pure spin: mu_t = M0 / N ((2/3) R f for uniform pressure, theory.md section 3); least
//   squares: c minimising the squared errors of F/F0 and M/M0 at the psi grid.
// - Chrono's spinning friction and Bullet's spinningFriction (lengths): torque bound mu_s N,
//   independent of sliding (F = F0 whenever it slides). Pure spin: mu_s = M0 / N.
// - Gazebo/ODE torsional friction: torque (3 pi/16) mu a N (a Hertz patch of radius a:
//   3 pi/16 = A^2/A^1 of sqrt(1 - rho^2)), independent of sliding; with mu = f, the pure-spin
//   patch radius is a = (M0 / N) / (3 pi f / 16).
#pragma once

#include <string>
#include <vector>

#include "contensou/friction/contact_patch.hpp"

namespace contensou::engines {

struct EngineCoefficient {
  std::string engine, parameter, unit, definition;
  double value = 0.0;
  double worst_force_error = 0.0;   // max over psi of |F - F_exact| / F0
  double worst_torque_error = 0.0;  // max over psi of |M - M_exact| / M0
  std::string snippet;              // MJCF, URDF, SDF or C++
};

struct Grid {
  double psi_min = 1e-3, psi_max = 1e3;
  int points = 121;
};

// The patch for a named profile ("uniform", "hertz", "seed-tire"), radius [m] and f, with unit
// normal load. Throws InvalidArgument naming the option and value for bad input.
ContactPatch named_patch(const std::string& profile, double radius, double friction);

// M0 / N = f R A^2 / A^1 [m]: the exact pure-spin torque per unit normal force.
double spin_torque_per_load(const ContactPatch& patch);

std::vector<EngineCoefficient> engine_coefficients(const ContactPatch& patch, Grid grid = {});

}  // namespace contensou::engines
