// Helpers that let the templated formulas accept double and ceres::Jet alike.
#pragma once

#include <type_traits>

namespace contensou {

// The plain value of a scalar: the double itself, or the real part of an automatic-
// differentiation type that exposes a member `a` (ceres::Jet).
template <class T>
double value_of(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) {
    return static_cast<double>(x);
  } else {
    return value_of(x.a);
  }
}

}  // namespace contensou
