/// \file
/// Random numbers that are the same with every standard library.
///
/// std::mt19937_64 is specified to the bit (the C++ standard fixes its 10000th output), but the
/// distributions are not: std::normal_distribution's algorithm is the library's choice
/// (libstdc++ and libc++ use different ones), and std::uniform_real_distribution leaves
/// rounding and edge cases to the library too. Simulated data (simulate_diagrams, draw_tire_laws)
/// take their numbers from here instead, so that a seed gives the same data with GCC's and clang's
/// libraries:
///   uniform_01:      the 53 high bits of one 64-bit output, times 2^-53: a double in [0, 1),
///                    exact (no rounding);
///   StandardNormal:  Marsaglia's polar method (Marsaglia & Bray 1964) on pairs of
///                    u = 2 uniform_01 - 1: a pair (u, v) with 0 < s = u^2 + v^2 < 1 gives two
///                    independent N(0, 1) draws u sqrt(-2 ln s / s) and v sqrt(-2 ln s / s),
///                    returned in that order. sqrt is exact (IEEE 754); ln is std::log, within
///                    an ulp in every libm and correctly rounded in glibc's, so a draw can differ
///                    between C libraries only in its last bit.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

namespace contensou {

/// A double in [0, 1) from the 53 high bits of one output of the engine.
inline double uniform_01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// A double in [-1, 1): 2 uniform_01 - 1 (exact).
inline double uniform_pm1(std::mt19937_64& rng) {
  return 2.0 * uniform_01(rng) - 1.0;
}

/// Standard normal draws N(0, 1) by the polar method (see above). Keeps the second draw of a
/// pair for the next call; copy it with its engine to repeat a stream.
class StandardNormal {
 public:
  /// The next draw, from `rng` (two uniforms a pair of draws).
  double operator()(std::mt19937_64& rng) {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    double u = 0.0, v = 0.0, s = 0.0;
    do {
      u = uniform_pm1(rng);
      v = uniform_pm1(rng);
      s = u * u + v * v;
    } while (!(s > 0.0 && s < 1.0));
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    spare_ = v * factor;
    has_spare_ = true;
    return u * factor;
  }

 private:
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace contensou
