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

// A table's six raw integrals (slip_speed_measure.hpp) for constant friction with the centre of
// sliding at (0, e), e > 0: rings about O in closed form (elliptic integrals), integrated over
// rho piece by piece (exact_law_sampling.cpp).
SlipMoments table_ring_moments(const ExactModel<double>& unit, double e);

// Constant friction: the six functions at t from five adaptive integrals (exact_law.cpp).
class ConstantSampler {
 public:
  ConstantSampler(const ExactModel<double>& model, double tolerance);
  void operator()(double t, double* g) const;
  double load() const { return unit_.load_area; }

 private:
  Resultants<double> probe(double kappa, double kx, double ky, const Kinematics<double>& k) const;
  ExactModel<double> unit_;
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
