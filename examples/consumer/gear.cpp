// Gear consumer: one landing of the shimmy demo's default gear (contensou::gear, SUNDIALS).
#include <contensou/gear.hpp>

#include <cstdio>

int main() {
  using namespace contensou;
  const LandingRun landing = simulate_landing(make_gear_model(GearConfig{}, ContactModel::coupled));
  std::printf("landing    %ld steps, torsion %.1f Hz, growth %.2f 1/s\n", landing.steps,
              landing.metrics.torsion.frequency_hz, landing.metrics.torsion.growth_rate_per_s);
  return landing.steps > 0 && landing.metrics.torsion.frequency_hz > 0 ? 0 : 1;
}
