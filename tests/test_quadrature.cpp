#include <gtest/gtest.h>

#include <cmath>

#include "contensou/adaptive_integration.hpp"
#include "contensou/error.hpp"
#include "contensou/quadrature.hpp"

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

TEST(GaussKronrod, TablesExactToTheirDegree) {
  // Kronrod 21 points: exact to degree 31; embedded Gauss 10 points: degree 19.
  for (int k = 0; k <= 31; ++k) {
    double kr = 0.0, ga = 0.0;
    for (const auto& node : detail::kGK21) {
      const int signs = node.x == 0.0 ? 1 : 2;
      for (int s = 0; s < signs; ++s) {
        const double x = s == 0 ? node.x : -node.x;
        kr += node.kronrod * std::pow(x, k);
        ga += node.gauss * std::pow(x, k);
      }
    }
    EXPECT_NEAR(kr, monomial_integral(k), 1e-15) << "Kronrod, k = " << k;
    if (k <= 19) {
      EXPECT_NEAR(ga, monomial_integral(k), 1e-15) << "Gauss, k = " << k;
    }
  }
}

TEST(GaussKronrod, K31TableExactToItsDegree) {
  // Kronrod 31 points: exact to degree 46; embedded Gauss 15 points: degree 29.
  for (int k = 0; k <= 46; ++k) {
    double kr = 0.0, ga = 0.0;
    for (const auto& node : detail::kGK31) {
      const int signs = node.x == 0.0 ? 1 : 2;
      for (int s = 0; s < signs; ++s) {
        const double x = s == 0 ? node.x : -node.x;
        kr += node.kronrod * std::pow(x, k);
        ga += node.gauss * std::pow(x, k);
      }
    }
    EXPECT_NEAR(kr, monomial_integral(k), 2e-15) << "Kronrod, k = " << k;
    if (k <= 29) {
      EXPECT_NEAR(ga, monomial_integral(k), 2e-15) << "Gauss, k = " << k;
    }
  }
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
