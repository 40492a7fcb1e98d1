/// \file
/// Frequency, growth rate and amplitude of an oscillation sampled on a time grid
/// (docs/shimmy.md, section 4: the simulated landings and the standard perturbation).
#pragma once

#include <span>

namespace contensou {

/// What analyse_oscillation() reads off the samples; all zeros when it is not valid().
struct OscillationEstimate {
  int half_cycles = 0;             ///< zero crossings of the rate, less one
  double frequency_hz = 0.0;       ///< half_cycles / (2 (t_last - t_first)) over crossings [Hz]
  double growth_rate_per_s = 0.0;  ///< slope of ln|rate peak| against time, least squares [1/s]
  double first_amplitude = 0.0;    ///< half the first peak-to-peak swing of the position
  double last_amplitude = 0.0;     ///< half the last one (the position's unit: [rad] for psi)
  /// At least 4 half cycles, so that the numbers above were measured.
  bool valid() const { return half_cycles >= 4; }
};

/// `rate` is the derivative of `position`. Extremes of the position lie at the rate's zero
/// crossings, so half-swings between successive crossings measure the amplitude free of any
/// slow drift; the rate's peak in each half cycle measures the growth (0 with fewer than two
/// peaks). Fewer than 4 half cycles give an invalid estimate (zeros). Throws InvalidArgument if
/// the spans differ in length.
OscillationEstimate analyse_oscillation(std::span<const double> t, std::span<const double> rate,
                                        std::span<const double> position);

}  // namespace contensou
