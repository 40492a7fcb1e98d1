/// \file
/// Synthetic friction diagrams (the seed's "simulated test diagrams", section 5), for planning
/// tests and for checking identification.
#pragma once

#include <cstdint>
#include <string>

#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// The noise add_noise puts on each measured value y of channel c (U, N: uniform and standard
/// normal draws, one a value; max|y_c|: the largest |y| of channel c over the data).
enum class SimulatedNoise {
  none,               ///< no noise
  relative_uniform,   ///< y (1 + level U(-1, 1)): the seed's "random distribution with amplitude"
  relative_gaussian,  ///< y (1 + level N(0, 1))
  additive_gaussian,  ///< y + level max|y_c| N(0, 1), per channel c
  /// A load cell's: y + (level max|y_c| + growth |y|) N(0, 1), per channel c (DiagramSpec's
  /// noise_growth), the noise NoiseModel::affine fits.
  load_cell,
};

/// Effects of the test rig applied to the simulated channels (for testing the closed loop),
/// before the noise: first Mz becomes Mz - viscous_torque omega and Fy gets the periodic
/// disturbance; then each channel y_c becomes y_c + offset_c + the sum over the other
/// channels d of `crosstalk[c][d] y_d` (the diagonal is not used).
/// The viscous spin torque is deliberately outside the closed loop's catalogue.
struct RigEffects {
  std::array<double, kChannels> offset{};  ///< added to Fx, Fy, Mz [N, N, N m]
  /// `crosstalk[c][d]`: the share of channel d added to channel c (c != d): [1] between the
  /// forces, [m] from a force into Mz, [1/m] from Mz into a force.
  std::array<std::array<double, kChannels>, kChannels> crosstalk{};
  double viscous_torque = 0.0;  ///< [N m s]
  /// A periodic disturbance of Fy in time (rig vibration), also outside the catalogue:
  /// Fy becomes Fy + amplitude sin(2 pi t / period), amplitude [N] (needs time stamps: without
  /// them t = 0 and the term vanishes).
  double periodic_amplitude_n = 0.0;
  double periodic_period_s = 5.0;  ///< its period [s] (positive)
};

/// Points at log-spaced psi = v/u in [psi_min, psi_max], u = |omega| R = spin_speed_mps, sliding
/// in the direction direction_rad; the time stamp t_s is the point's index times time_step_s.
struct DiagramSpec {
  double radius_m = 0.087;      ///< patch radius R [m]
  double psi_min = 1e-2;        ///< the smallest sliding-spin ratio (positive)
  double psi_max = 1e2;         ///< the largest (at least psi_min)
  int points = 40;              ///< number of points (at least 1; one point: psi_min)
  double spin_speed_mps = 1.0;  ///< u = |omega| R [m/s] (positive; omega = u / R is positive)
  double direction_rad = 0.0;   ///< sliding direction, from x [rad]
  SimulatedNoise noise = SimulatedNoise::additive_gaussian;  ///< the kind of noise
  double noise_level = 0.01;  ///< its level (non-negative; relative, or a share of max|y_c|)
  double noise_growth = 0.0;  ///< load_cell: the share b of |y| in sigma = a + b |y|
  std::uint64_t seed = 1;     ///< of the noise's random numbers
  double time_step_s = 0.0;   ///< [s]; 0: no t_s column
  RigEffects rig;             ///< effects of the test rig (none by default)
};

/// Clean kinematics of the spec (forces unset; source "simulated"). Throws InvalidArgument for
/// a radius, psi_min or spin speed that is not positive and finite, psi_max below psi_min, or
/// fewer than one point.
MeasuredData diagram_kinematics(const DiagramSpec& spec);

/// Diagrams from the fractional law (checked by validate, InvalidArgument), with the rig's
/// effects and the noise. Throws as diagram_kinematics and add_noise do.
MeasuredData simulate_diagrams(const FractionalLaw<double>& law, const DiagramSpec& spec);
/// Diagrams from the exact integrals (tolerance 1e-10), with the rig's effects and the noise.
/// Throws as diagram_kinematics and add_noise do.
MeasuredData simulate_diagrams(const ExactModel<double>& model, const DiagramSpec& spec);

/// Adds the spec's noise to every measured value, in place (deterministic for a seed, and the
/// same with every standard library: std::mt19937_64 and contensou/friction/random.hpp).
/// Throws InvalidArgument for a negative or non-finite noise level or growth.
void add_noise(MeasuredData& data, const DiagramSpec& spec);

/// The noise of a name: none, relative-uniform, relative-gaussian, additive-gaussian or
/// load-cell; throws InvalidArgument for another.
SimulatedNoise parse_noise(const std::string& name);
/// The name of a noise, as parse_noise reads it.
std::string noise_name(SimulatedNoise noise);

}  // namespace contensou
