/// \file
/// The estimated absolute errors of the exact resultants (exact_resultants.hpp): one per
/// component, not one number.
#pragma once

#include <algorithm>

namespace contensou {

/// max() is the largest of the three, for the common question "is it small?"; it compares N
/// with N m as plain numbers (the torque's error scales with R), so to weigh them use the
/// components, or ExactResult::converged (each against its own scale, f N or f N R).
struct ResultantErrors {
  double Fx = 0.0;  ///< [N]
  double Fy = 0.0;  ///< [N]
  double Mz = 0.0;  ///< [N m]

  /// The largest of the three, N and N m compared as plain numbers.
  double max() const { return std::max({Fx, Fy, Mz}); }
};

}  // namespace contensou
