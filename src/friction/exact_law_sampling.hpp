// Samplers of the exact law's tables (exact_law.hpp): the six functions of t for constant
// friction from the adaptive integrator, and for the falling part of a slip-speed law from the
// slip-speed quadrature (slip_speed_measure.hpp). Internal to the friction module.
#pragma once

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

// Constant friction: five adaptive integrals a sample (exact_law.cpp).
class ConstantSampler {
 public:
  ConstantSampler(const ExactModel<double>& model, double tolerance);
  void operator()(double t, double* g);
  double load() const { return load_; }

 private:
  Resultants<double> probe(double kappa, double kx, double ky, const Kinematics<double>& k);
  ExactModel<double> unit_;
  double tol_, load_ = 1.0, slide_limit_ = 0.0, shift_limit_ = 0.0;
};

// The falling part g(w) = exp(-(w / w_s)^delta) of a slip-speed law: the six functions at
// (t, z), z = q^delta, q = (|v| + |omega| R) / w_s, from the slip-speed quadrature at t (cached
// per t), and at t = -1 from the first-order turn of the slip direction (exact_law.hpp).
class FallingSampler {
 public:
  FallingSampler(const ExactModel<double>& model, double delta, double largest_q);
  // The six functions at t for every z in zs (out[k * 6 + i]).
  void operator()(double t, const std::vector<double>& zs, double* out);
  double load() const { return load_; }

 private:
  struct Rule {
    std::vector<double> mu;           // nu^delta, increasing
    std::vector<SlipMoments> weight;  // in the same order
  };
  const Rule& rule_at(double t);
  void spin_limits(double z, double* g) const;
  ExactModel<double> unit_;
  double delta_, load_ = 1.0;
  SlipSpeedMeasureOptions options_;
  std::map<double, Rule> cache_;
};

}  // namespace contensou::detail
