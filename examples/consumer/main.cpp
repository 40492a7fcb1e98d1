// Quick start: exact resultants and the fractional law for the seed tire.
#include <contensou/contensou.hpp>
#include <contensou/gear/landing_simulation.hpp>

#include <cstdio>

int main() {
  using namespace contensou;
  ContactPatch patch = seed_tire_patch();  // SI units: R = 0.087 m, p* = 210 kPa, f = 0.3
  patch.profile.kx = 0.14;

  const ExactModel<double> model = make_exact_model(patch);  // build once
  const Kinematics<double> k{0.5, 0.0, 10.0};                // vx, vy [m/s], omega [rad/s]
  const ExactResult<double> exact = exact_resultants(model, k, {1e-10});
  const FractionalLaw<double> law = fractional_law_from_patch(patch);
  const Resultants<double> approx = fractional_resultants(law, k);

  std::printf("exact      Fx = %9.3f N  Fy = %9.3f N  Mz = %8.4f N m  (+- %.1e N)\n",
              exact.resultants.Fx, exact.resultants.Fy, exact.resultants.Mz, exact.error.Fx);
  std::printf("fractional Fx = %9.3f N  Fy = %9.3f N  Mz = %8.4f N m\n", approx.Fx, approx.Fy,
              approx.Mz);
  // contensou::gear: one landing of the shimmy demo's default gear (SUNDIALS CVODE).
  const LandingRun landing = simulate_landing(make_gear_model(GearConfig{}, ContactModel::coupled));
  std::printf("landing    %ld steps, torsion %.1f Hz, growth %.2f 1/s\n", landing.steps,
              landing.metrics.torsion.frequency_hz, landing.metrics.torsion.growth_rate_per_s);
  const bool sane =
      exact.resultants.Fx < 0 && exact.resultants.Mz < 0 && approx.Fx < 0 && landing.steps > 0;
  return sane ? 0 : 1;
}
