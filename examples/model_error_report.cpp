// The main job until the apps exist: the seed tire's parameters and the table of the
// fractional law's error against the exact integrals (theory.md section 5).
#include <contensou/contensou.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

namespace {

constexpr const char* kName = "contensou-model-error";

// The apps' conventions (apps/common/cli.hpp) for a program without options: --help, --version,
// anything else a usage error (exit status 2). Returns the status to end with, or -1 to run.
int arguments(int argc, char** argv) {
  if (argc <= 1) return -1;
  const std::string arg = argv[1];
  if (argc == 2 && (arg == "--help" || arg == "-h")) {
    std::printf(
        "The seed tire's parameters and the fractional law's error against the exact "
        "integrals (theory.md section 5).\nUsage: %s [--help] [--version]\n\nExit status: 0 "
        "success, 1 failure (a failed run or write), 2 usage error (an unknown option or "
        "argument).\n",
        kName);
  } else if (argc == 2 && arg == "--version") {
    std::printf("%s %s\n", kName, contensou::kVersion);
  } else {
    int bad = 1;  // the first argument that is not --help or --version, else the second one
    while (bad < argc - 1 &&
           (std::string(argv[bad]) == "--help" || std::string(argv[bad]) == "--version" ||
            std::string(argv[bad]) == "-h"))
      ++bad;
    std::fprintf(stderr,
                 "%s: error: unexpected argument '%s': this program takes none but --help or "
                 "--version\nRun with --help for more information.\n",
                 kName, argv[bad]);
    return 2;
  }
  return std::fflush(stdout) == 0 && !std::ferror(stdout) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) try {
  using namespace contensou;
  if (const int status = arguments(argc, argv); status >= 0) return status;
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
  // A full disk or a closed pipe behind stdout is a failure, as in the apps (finish_output).
  if (std::fflush(stdout) != 0 || std::ferror(stdout)) {
    std::fprintf(stderr, "%s: error: writing to standard output failed (%s)\n", kName,
                 std::strerror(errno));
    return 1;
  }
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
  return 1;
}
