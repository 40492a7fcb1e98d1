// (Internal, not installed) The test seams of the identification's options: the only way to set
// or read detail::TestSeams, for the library's own sources, its tests and the app's hidden
// --test-failing-point. A point whose residual fails to evaluate reaches the failed-solve path
// (an error naming the fit, no report); a first fit of zero iterations stops at its start, so
// that the loop's retry from other starts runs.
#pragma once

#include "contensou/identification/fit.hpp"

namespace contensou::testing {

struct Seams {
  /// The seams of any options struct that carries them (IdentificationOptions, NoiseSettings,
  /// ClosedLoopOptions, IdentifyRequest).
  template <class Options>
  static detail::TestSeams& of(Options& o) {
    return o.seams_;
  }
  template <class Options>
  static const detail::TestSeams& of(const Options& o) {
    return o.seams_;
  }
};

}  // namespace contensou::testing
