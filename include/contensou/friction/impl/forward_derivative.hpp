// A minimal forward-mode derivative type for the friction module's own Jacobians (the module
// depends on Eigen only; callers may use ceres::Jet for the same templates). It provides what
// the closed-form laws use: arithmetic with itself and doubles, sqrt and pow. Members a (value)
// and v (derivatives) as in ceres::Jet, so value_of() and has_derivative() apply.
#pragma once

#include <array>
#include <cmath>

namespace contensou::detail {

template <int N>
struct ForwardDerivative {
  double a = 0.0;
  std::array<double, N> v{};

  ForwardDerivative() = default;
  explicit ForwardDerivative(double value) : a(value) {}
  ForwardDerivative(double value, int i) : a(value) { v[i] = 1.0; }  ///< the i-th variable

  ForwardDerivative& operator+=(const ForwardDerivative& y) {
    a += y.a;
    for (int i = 0; i < N; ++i) v[i] += y.v[i];
    return *this;
  }
  ForwardDerivative& operator-=(const ForwardDerivative& y) {
    a -= y.a;
    for (int i = 0; i < N; ++i) v[i] -= y.v[i];
    return *this;
  }
  ForwardDerivative& operator*=(const ForwardDerivative& y) {
    for (int i = 0; i < N; ++i) v[i] = v[i] * y.a + y.v[i] * a;
    a *= y.a;
    return *this;
  }
  ForwardDerivative& operator/=(const ForwardDerivative& y) {
    const double q = a / y.a, r = 1.0 / y.a;
    for (int i = 0; i < N; ++i) v[i] = (v[i] - y.v[i] * q) * r;
    a = q;
    return *this;
  }
  ForwardDerivative& operator*=(double y) {
    a *= y;
    for (int i = 0; i < N; ++i) v[i] *= y;
    return *this;
  }
};

template <int N>
ForwardDerivative<N> operator+(ForwardDerivative<N> x, const ForwardDerivative<N>& y) {
  return x += y;
}
template <int N>
ForwardDerivative<N> operator-(ForwardDerivative<N> x, const ForwardDerivative<N>& y) {
  return x -= y;
}
template <int N>
ForwardDerivative<N> operator*(ForwardDerivative<N> x, const ForwardDerivative<N>& y) {
  return x *= y;
}
template <int N>
ForwardDerivative<N> operator/(ForwardDerivative<N> x, const ForwardDerivative<N>& y) {
  return x /= y;
}
template <int N>
ForwardDerivative<N> operator+(ForwardDerivative<N> x, double y) {
  x.a += y;
  return x;
}
template <int N>
ForwardDerivative<N> operator+(double x, ForwardDerivative<N> y) {
  y.a += x;
  return y;
}
template <int N>
ForwardDerivative<N> operator-(ForwardDerivative<N> x, double y) {
  x.a -= y;
  return x;
}
template <int N>
ForwardDerivative<N> operator-(double x, ForwardDerivative<N> y) {
  y.a = x - y.a;
  for (int i = 0; i < N; ++i) y.v[i] = -y.v[i];
  return y;
}
template <int N>
ForwardDerivative<N> operator*(ForwardDerivative<N> x, double y) {
  return x *= y;
}
template <int N>
ForwardDerivative<N> operator*(double x, ForwardDerivative<N> y) {
  return y *= x;
}
template <int N>
ForwardDerivative<N> operator/(ForwardDerivative<N> x, double y) {
  return x *= 1.0 / y;
}
template <int N>
ForwardDerivative<N> operator/(double x, const ForwardDerivative<N>& y) {
  ForwardDerivative<N> out(x / y.a);
  const double d = -out.a / y.a;
  for (int i = 0; i < N; ++i) out.v[i] = d * y.v[i];
  return out;
}

template <int N>
ForwardDerivative<N> operator-(ForwardDerivative<N> x) {
  x.a = -x.a;
  for (int i = 0; i < N; ++i) x.v[i] = -x.v[i];
  return x;
}

template <int N>
ForwardDerivative<N> sqrt(const ForwardDerivative<N>& x) {
  ForwardDerivative<N> out(std::sqrt(x.a));
  const double d = 0.5 / out.a;
  for (int i = 0; i < N; ++i) out.v[i] = d * x.v[i];
  return out;
}

template <int N>
ForwardDerivative<N> pow(const ForwardDerivative<N>& x, double e) {
  ForwardDerivative<N> out(std::pow(x.a, e));
  const double d = x.a == 0.0 ? 0.0 : e * out.a / x.a;
  for (int i = 0; i < N; ++i) out.v[i] = d * x.v[i];
  return out;
}

}  // namespace contensou::detail
