#include "contensou/friction/quadrature.hpp"

#include "contensou/friction/error.hpp"

namespace contensou {

GaussLegendreRule gauss_legendre(int n) {
  if (n < 1 || n > 1000) throw InvalidArgument("n", std::to_string(n), "must be in [1, 1000]");
  GaussLegendreRule rule;
  rule.nodes.resize(n);
  rule.weights.resize(n);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    // Tricomi's initial guess, then Newton on P_n.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    bool close = false;  // one more step after |dx| < 1e-13: quadratic convergence does the rest
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      const double pn = (n == 1) ? x : p1;
      const double pnm1 = (n == 1) ? 1.0 : p0;
      dp = n * (x * pn - pnm1) / (x * x - 1.0);
      const double dx = pn / dp;
      x -= dx;
      if (close || std::abs(dx) < 1e-17) break;
      close = std::abs(dx) < 1e-13;
    }
    const double w = 2.0 / ((1.0 - x * x) * dp * dp);
    rule.nodes[i] = -x;
    rule.weights[i] = w;
    rule.nodes[n - 1 - i] = x;
    rule.weights[n - 1 - i] = w;
  }
  if (n % 2 == 1) rule.nodes[n / 2] = 0.0;
  return rule;
}

}  // namespace contensou
