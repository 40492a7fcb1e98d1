// The torsional oscillation at the end of a landing's analysis window, read from its samples:
// amplitude, its trend, the torque-link load, and a verdict that reconciles the simulation with
// the eigenvalues of the linearisation.
#pragma once

#include <string>

#include "contensou/gear/landing_simulation.hpp"

namespace contensou::app {

struct LimitCycle {
  bool measured = false;               // the window holds at least six periods
  double amplitude_rad = 0.0;          // half the psi swing over the window's last 3 periods
  double earlier_amplitude_rad = 0.0;  // over the 3 periods before
  double trend_per_s = 0.0;            // ln(amplitude / earlier) / (3 periods)
  double torque_link_nm = 0.0;         // half the swing of k_psi psi + c_psi psi' over the last 3
  std::string verdict;                 // in words; reconciles simulation and eigenvalues
};

// `eigen_growth_per_s` and `frequency_hz` are the linearisation's (its dominant oscillatory
// mode); the amplitude threshold is the criterion's. A trend within +-0.5 1/s above the
// threshold is a limit cycle.
LimitCycle assess_limit_cycle(const LandingRun& run, const GearStructure& structure,
                              double eigen_growth_per_s, double frequency_hz,
                              const ShimmyCriterion& criterion);

}  // namespace contensou::app
