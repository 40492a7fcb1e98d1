// Friction-only consumer: exact resultants and the fractional law for the seed tire. Links
// contensou::friction alone, so it builds where only Eigen is installed.
#include <contensou/contensou.hpp>

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
  // Friction opposes sliding and spin: both exact and fractional Fx, Mz are negative here.
  const bool sane = exact.resultants.Fx < 0 && exact.resultants.Mz < 0 && approx.Fx < 0;
  return sane ? 0 : 1;
}
