// Contensou's closed forms for a uniform disk (theory.md section 3), the oracles shared by the
// tests of every module, and the sliding-spinning disk's limit ratio they imply.
#pragma once

#include <cmath>
#include <numbers>
#include <utility>

namespace contensou::test_support {

// F_par / (f N) and |Mz| / (f N R) of uniform pressure at eps = |v| / (|omega| R) >= 0
// (theory.md section 3; std::comp_ellint_1/2 take the modulus k). eps = 1 is the common limit
// of both branches (E(1) = 1, (1 - eps^2) K -> 0).
inline std::pair<double, double> uniform_closed_form(double eps) {
  constexpr double pi = std::numbers::pi;
  if (eps == 0.0) return {0.0, 2.0 / 3.0};
  if (eps == 1.0) return {8 / (3 * pi), 8 / (9 * pi)};
  if (eps < 1.0) {
    const double K = std::comp_ellint_1(eps), E = std::comp_ellint_2(eps);
    return {4 / (3 * pi) * ((1 + eps * eps) * E - (1 - eps * eps) * K) / eps,
            4 / (9 * pi) * ((4 - 2 * eps * eps) * E - (1 - eps * eps) * K)};
  }
  const double k = 1 / eps, K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  return {4 / (3 * pi) * ((1 + eps * eps) * E - (eps * eps - 1) * K),
          4 / (9 * pi) *
              (2 * eps * (2 - eps * eps) * E + (2 * eps * eps - 3) * (eps * eps - 1) * K / eps)};
}

// The limit of v / (omega R) of a uniform disk sliding and spinning to rest (I = M R^2 / 2):
// equal relative decay of v and omega R, F_par(eps) = 2 eps |Mz|(eps) / R, by bisection on
// [0.3, 0.95]: 0.6530 (Farkas, Bartels, Unger & Wolf, PRL 90, 248302, 2003).
inline double sliding_disk_fixed_point() {
  auto g = [](double e) {
    const auto [f, m] = uniform_closed_form(e);
    return f - 2 * e * m;
  };
  double lo = 0.3, hi = 0.95;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(lo) * g(mid) <= 0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace contensou::test_support
