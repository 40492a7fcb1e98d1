// A minimal forward-mode derivative type for the friction module's own Jacobians (the module
// depends on Eigen only; callers may use ceres::Jet for the same templates). It provides what
// the closed-form laws use: arithmetic with itself and doubles, sqrt and pow. Members a (value) and
// v (derivatives) as in ceres::Jet, so value_of() and has_derivative() apply.
#pragma once

#include <Eigen/Core>
#include <cmath>

namespace contensou {

template <int N>
struct ForwardDerivative {
  double a = 0.0;
  Eigen::Matrix<double, N, 1> v = Eigen::Matrix<double, N, 1>::Zero();

  ForwardDerivative() = default;
  explicit ForwardDerivative(double value) : a(value) {}
  ForwardDerivative(double value, int i) : a(value) { v[i] = 1.0; }  // the i-th variable

  ForwardDerivative& operator+=(const ForwardDerivative& y) {
    a += y.a;
    v += y.v;
    return *this;
  }
  ForwardDerivative& operator-=(const ForwardDerivative& y) {
    a -= y.a;
    v -= y.v;
    return *this;
  }
  ForwardDerivative& operator*=(const ForwardDerivative& y) {
    v = v * y.a + y.v * a;
    a *= y.a;
    return *this;
  }
  ForwardDerivative& operator/=(const ForwardDerivative& y) {
    const double q = a / y.a;
    v = (v - y.v * q) / y.a;
    a = q;
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
  y.v = -y.v;
  return y;
}
template <int N>
ForwardDerivative<N> operator*(ForwardDerivative<N> x, double y) {
  x.a *= y;
  x.v *= y;
  return x;
}
template <int N>
ForwardDerivative<N> operator*(double x, ForwardDerivative<N> y) {
  return y * x;
}
template <int N>
ForwardDerivative<N> operator/(ForwardDerivative<N> x, double y) {
  x.a /= y;
  x.v /= y;
  return x;
}
template <int N>
ForwardDerivative<N> operator/(double x, const ForwardDerivative<N>& y) {
  return ForwardDerivative<N>(x) /= y;
}

template <int N>
ForwardDerivative<N> operator-(ForwardDerivative<N> x) {
  x.a = -x.a;
  x.v = -x.v;
  return x;
}

template <int N>
ForwardDerivative<N> sqrt(const ForwardDerivative<N>& x) {
  ForwardDerivative<N> out(std::sqrt(x.a));
  out.v = x.v / (2.0 * out.a);
  return out;
}

template <int N>
ForwardDerivative<N> pow(const ForwardDerivative<N>& x, double e) {
  ForwardDerivative<N> out(std::pow(x.a, e));
  out.v = x.v * (x.a == 0.0 ? 0.0 : e * out.a / x.a);
  return out;
}

}  // namespace contensou
