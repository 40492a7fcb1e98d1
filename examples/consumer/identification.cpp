// Identification consumer: simulate noisy diagrams of the seed tire and fit the fractional law
// back with 95 % intervals (contensou::identification, Ceres).
#include <contensou/identification.hpp>

#include <cstdio>

int main() {
  using namespace contensou;
  ContactPatch patch = seed_tire_patch();
  patch.profile.kx = 0.14;  // pressure centre shifted forward by 0.14 R
  const FractionalLaw<double> truth = fractional_law_from_patch(patch);
  DiagramSpec spec;  // 40 points, psi in [0.01, 100], 1 % additive noise
  const MeasuredData data = simulate_diagrams(truth, spec);

  IdentificationOptions options;
  options.radius_m = patch.radius_m;
  const FitReport fit = fit_fractional_law(data, options);
  const ParameterEstimate* F0 = fit.parameter("F0_N");
  if (!fit.converged || !F0->ci95) return 1;
  std::printf("F0 = %.2f N, 95 %% interval [%.2f, %.2f] N (simulated with %.2f N)\n", F0->value,
              (*F0->ci95)[0], (*F0->ci95)[1], truth.F0);
  return 0;
}
