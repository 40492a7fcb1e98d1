// The main job until the apps exist: the seed tire's parameters and the table of the
// fractional law's error against the exact integrals (theory.md section 5).
#include <contensou/contensou.hpp>

#include <cstdio>
#include <exception>

int main() try {
  using namespace contensou;
  const ContactPatch patch = seed_tire_patch();  // seed section 4, Tables 1-3
  std::printf("contensou %s: the seed tire (Kireenkov & Zhavoronok 2020, Table 1)\n", kVersion);
  std::printf("profile: %s, R = %.3f m, p* = %.0f kPa, f = %.2f\n", describe(patch.profile).c_str(),
              patch.radius_m, patch.reference_pressure_pa / 1e3, patch.friction);
  for (const auto& [lo, hi] : negative_intervals(patch.profile))
    std::printf("warning: the profile is negative for rho in (%.4f, %.4f] (p(1) = %.4f)\n", lo, hi,
                shape_value(patch.profile, 1.0));
  std::printf("moments: A0 = %.6f  A1 = %.6f  A2 = %.6f  A3 = %.6f\n", moment(patch.profile, 0),
              moment(patch.profile, 1), moment(patch.profile, 2), moment(patch.profile, 3));
  const FractionalLaw<double> law = fractional_law_from_patch(patch);
  std::printf("N = %.1f N  F0 = %.1f N  M0 = %.2f N m  a = %.4f  m = %.4f\n", normal_load(patch),
              law.F0, law.M0, law.a, law.m);
  std::printf("(the seed's m = 1.72 is (2 A3/A2)^2 = %.4f, the reciprocal formula)\n\n",
              std::pow(2.0 * moment(patch.profile, 3) / moment(patch.profile, 2), 2));
  std::fputs(format_report(model_error_report(patch)).c_str(), stdout);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "error: %s\n", e.what());
  return 1;
}
