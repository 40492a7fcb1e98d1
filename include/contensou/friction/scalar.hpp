/// \file
/// Helpers that let the templated formulas accept double and ceres::Jet alike.
#pragma once

#include <type_traits>

namespace contensou {

/// The plain value of a scalar: the double itself, or the real part of an automatic-
/// differentiation type that exposes a member `a` (ceres::Jet).
template <class T>
double value_of(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return static_cast<double>(x);
  } else {
    return value_of(x.a);
  }
}

/// Whether a scalar carries a non-zero derivative (always false for a plain double).
template <class T>
bool has_derivative(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return false;
  } else {
    for (int i = 0; i < static_cast<int>(x.v.size()); ++i)
      if (x.v[i] != 0.0) return true;
    return has_derivative(x.a);
  }
}

}  // namespace contensou
