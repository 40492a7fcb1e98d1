// Frequency, growth rate and amplitude of an oscillation sampled on a time grid
// (docs/shimmy.md, "What counts as shimmy").
#pragma once

#include <span>

namespace contensou {

struct OscillationEstimate {
  int half_cycles = 0;             // zero crossings of the rate, less one
  double frequency_hz = 0.0;       // half_cycles / (2 (t_last - t_first)) over crossings
  double growth_rate_per_s = 0.0;  // slope of ln|rate peak| against time (least squares)
  double first_amplitude = 0.0;    // half the first peak-to-peak swing of the position
  double last_amplitude = 0.0;     // half the last one
  bool valid() const { return half_cycles >= 4; }
};

// `rate` is the derivative of `position`. Extremes of the position lie at the rate's zero
// crossings, so half-swings between successive crossings measure the amplitude free of any
// slow drift; the rate's peak in each half cycle measures the growth. Fewer than 4 half cycles
// give an invalid estimate (zeros). Throws InvalidArgument if the spans differ in length.
OscillationEstimate analyse_oscillation(std::span<const double> t, std::span<const double> rate,
                                        std::span<const double> position);

}  // namespace contensou
