// Synthetic friction diagrams (the seed's "simulated test diagrams", section 5), for planning
// tests and for checking identification.
#pragma once

#include <cstdint>
#include <string>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

enum class SimulatedNoise {
  none,
  relative_uniform,   // y (1 + level U(-1, 1)): the seed's "random distribution with amplitude"
  relative_gaussian,  // y (1 + level N(0, 1))
  additive_gaussian,  // y + level max|y_c| N(0, 1), per channel c
  // A load cell's: y + (level max|y_c| + growth |y|) N(0, 1), per channel c (DiagramSpec's
  // noise_growth), the noise NoiseModel::affine fits.
  load_cell,
};

// Effects of the test rig applied to the simulated channels (for testing the closed loop):
//   y_c <- y_c + offset_c + sum_d crosstalk[c][d] y_d,   Mz <- Mz - viscous_torque * omega.
// The viscous spin torque is deliberately outside the closed loop's catalogue.
struct RigEffects {
  std::array<double, kChannels> offset{};
  std::array<std::array<double, kChannels>, kChannels> crosstalk{};
  double viscous_torque = 0.0;  // [N m s]
  // A periodic disturbance of Fy in time (rig vibration), also outside the catalogue:
  // Fy <- Fy + amplitude sin(2 pi t / period) (needs time stamps).
  double periodic_amplitude_n = 0.0;
  double periodic_period_s = 5.0;
};

// Points at log-spaced psi = v/u in [psi_min, psi_max], u = |omega| R = spin_speed_mps, sliding
// in the direction direction_rad; the time stamp t_s is the point's index times time_step_s.
struct DiagramSpec {
  double radius_m = 0.087;
  double psi_min = 1e-2;
  double psi_max = 1e2;
  int points = 40;
  double spin_speed_mps = 1.0;
  double direction_rad = 0.0;
  SimulatedNoise noise = SimulatedNoise::additive_gaussian;
  double noise_level = 0.01;
  double noise_growth = 0.0;  // load_cell: the share b of |y| in sigma = a + b |y|
  std::uint64_t seed = 1;
  double time_step_s = 0.0;  // 0: no t_s column
  RigEffects rig;
};

// Clean kinematics of the spec (forces unset).
MeasuredData diagram_kinematics(const DiagramSpec& spec);

// Diagrams from the fractional law or from the exact integrals (tolerance 1e-10), with noise.
MeasuredData simulate_diagrams(const FractionalLaw<double>& law, const DiagramSpec& spec);
MeasuredData simulate_diagrams(const ExactModel<double>& model, const DiagramSpec& spec);

// Adds the spec's noise to every measured value, in place (deterministic for a seed, and the
// same with every standard library: std::mt19937_64 and contensou/friction/random.hpp).
void add_noise(MeasuredData& data, const DiagramSpec& spec);

SimulatedNoise parse_noise(const std::string& name);  // throws InvalidArgument
std::string noise_name(SimulatedNoise noise);

}  // namespace contensou
