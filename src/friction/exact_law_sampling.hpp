// Samplers of the exact law's tables (exact_law.hpp): the six functions of t for constant
// friction from the adaptive integrator, and for the falling part of a slip-speed law from the
// slip-speed quadrature (slip_speed_measure.hpp). Internal to the friction module.
#pragma once

#include <array>
#include <map>
#include <vector>

#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/slip_speed_measure.hpp"

namespace contensou::detail {

// integral_0^1 p(rho) h(rho) d rho over the model's representation (Gauss-Legendre panels in
// rho, broken at a table's knots, graded towards rho = 0 from `layer` on; a Hertz edge through
// rho = sin(theta)).
double profile_integral(const ExactModel<double>& m, const std::function<double(double)>& h,
                        double layer = 1.0);

// The unit model of a model: R = 1, p* = 1, f = 1, no shift, kappa = 1, constant friction.
ExactModel<double> unit_model(const ExactModel<double>& model);

// The six table functions from the six raw integrals (slip_speed_measure.hpp) at sigma > 0.
void law_functions_from_moments(const SlipMoments& raw, double sigma, double load, double* g);

// Chebyshev moments of a table's weight rho p(rho^2) on a binary tree of its pieces in rho,
//   mu_m = integral_a^b rho p(rho^2) T_m(u) d rho,  u = (2 rho - a - b) / (b - a),  m < 24,
// built once a law in O(n) (exact_law_sampling.cpp): a sample's ring integrals (theory.md
// section 2, the exact model in rings about O) then take O(log n) nodes of 8 to 24 ring
// evaluations, instead of 6 to 16 on every piece (docs/speed.md, "Dense tables").
constexpr int kRingTerms = 24;
struct RingNode {
  double a = 0.0, b = 0.0;              // its range of rho
  std::array<double, kRingTerms> mu{};  // integral_a^b rho p(rho^2) T_m(u) d rho
};
struct RingTree {
  std::vector<std::vector<RingNode>> level;  // level 0: the pieces; level s: runs of 2^s
  std::vector<std::vector<double>> cosines;  // [n]: cos(pi m (j + 1/2) / n), m, j < n <= 24
};
RingTree ring_tree(const ExactModel<double>& unit);

// A table's six raw integrals (slip_speed_measure.hpp) for constant friction with the centre of
// sliding at (0, e), e > 0: rings about O in closed form (elliptic integrals), integrated over
// rho: on the tree's nodes far from the centre's ring by the moments, on the pieces near it
// piece by piece (exact_law_sampling.cpp).
SlipMoments table_ring_moments(const RingTree& tree, const ExactModel<double>& unit, double e);

// Constant friction: the six functions at t from five adaptive integrals (exact_law.cpp).
class ConstantSampler {
 public:
  ConstantSampler(const ExactModel<double>& model, double tolerance);
  void operator()(double t, double* g) const;
  double load() const { return unit_.load_area; }

 private:
  Resultants<double> probe(double kappa, double kx, double ky, const Kinematics<double>& k) const;
  ExactModel<double> unit_;
  RingTree rings_;  // a table's (empty otherwise)
  double tol_, slide_limit_ = 0.0, shift_limit_ = 0.0;
};

// The falling part g(w) = exp(-(w / w_s)^delta) of a slip-speed law: the six functions at t for
// every z in zs (out[k * 6 + i]), z = q^delta, q = (|v| + |omega| R) / w_s, from the slip-speed
// quadrature at t, and at t = -1 from the first-order turn of the slip direction (exact_law.hpp).
// `unit` is unit_model(model).
void falling_functions(const ExactModel<double>& unit, double delta,
                       const SlipSpeedMeasureOptions& options, double t,
                       const std::vector<double>& zs, double* out);

}  // namespace contensou::detail
