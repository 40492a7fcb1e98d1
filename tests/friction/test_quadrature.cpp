#include <gtest/gtest.h>

#include <cmath>

#include "contensou/friction/adaptive_integration.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/quadrature.hpp"

using namespace contensou;

// Oracle: integral_{-1}^{1} x^k dx = 2/(k+1) for even k, 0 for odd k.
double monomial_integral(int k) {
  return k % 2 ? 0.0 : 2.0 / (k + 1);
}

TEST(GaussLegendre, ExactForDegree2nMinus1) {
  for (int n : {1, 2, 5, 10, 26, 64}) {
    const GaussLegendreRule g = gauss_legendre(n);
    for (int k = 0; k <= 2 * n - 1; ++k) {
      double s = 0.0;
      for (int i = 0; i < n; ++i) s += g.weights[i] * std::pow(g.nodes[i], k);
      EXPECT_NEAR(s, monomial_integral(k), 2e-14) << "n = " << n << ", k = " << k;
    }
  }
}

TEST(GaussLegendre, RejectsBadOrder) {
  EXPECT_THROW(gauss_legendre(0), InvalidArgument);
  EXPECT_THROW(gauss_legendre(-3), InvalidArgument);
}

// A Kronrod table (symmetric half) integrates x^k exactly up to kronrod_degree, and its
// embedded Gauss weights up to gauss_degree.
template <std::size_t Half>
void expect_exact(const detail::KronrodNode (&table)[Half], int kronrod_degree, int gauss_degree) {
  for (int k = 0; k <= kronrod_degree; ++k) {
    double kr = 0.0, ga = 0.0;
    for (const auto& node : table) {
      const int signs = node.x == 0.0 ? 1 : 2;
      for (int s = 0; s < signs; ++s) {
        const double x = s == 0 ? node.x : -node.x;
        kr += node.kronrod * std::pow(x, k);
        ga += node.gauss * std::pow(x, k);
      }
    }
    EXPECT_NEAR(kr, monomial_integral(k), 2e-15) << "Kronrod, k = " << k;
    if (k <= gauss_degree) {
      EXPECT_NEAR(ga, monomial_integral(k), 2e-15) << "Gauss, k = " << k;
    }
  }
}

TEST(GaussKronrod, K21TableExactToItsDegree) {
  expect_exact(detail::kGK15, 22, 13);
  expect_exact(detail::kGK21, 31, 19);
}

TEST(GaussKronrod, K31TableExactToItsDegree) {
  expect_exact(detail::kGK31, 46, 29);
}

TEST(AdaptiveIntegration, ReachesToleranceOnPeakedIntegrand) {
  // integral_0^1 1/(x^2 + e^2) dx = atan(1/e)/e: a near-singularity at 0 needs bisection.
  const double e = 1e-4;
  auto f = [&](double x, int) {
    detail::Sample<double, 1> s;
    s.value[0] = 1.0 / (x * x + e * e);
    return s;
  };
  const detail::TaggedInterval whole{0.0, 1.0, 0};
  const double exact = std::atan(1.0 / e) / e;
  const auto r = detail::integrate_adaptive<double, 1>(f, &whole, 1, {1e-9 * exact});
  EXPECT_TRUE(r.converged);
  EXPECT_GT(r.intervals, 1);
  EXPECT_NEAR(r.value[0], exact, 1e-9 * exact);
  EXPECT_LE(std::abs(r.value[0] - exact), r.error[0]);  // estimate is an upper bound here
}
