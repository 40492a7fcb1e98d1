// The choice of a pressure profile by name or CSV path (moved from the report: the request
// chooses it before the fit, the report only describes it).
#include "contensou/identification/profile_choice.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <variant>

#include "contensou/friction/error.hpp"

namespace contensou {

ProfileChoice choose_profile(const std::string& spec, int smoothing, bool clip, KeyStyle style) {
  // "--profile X" on the command line, "profile = X" in Python: the option as the user wrote it.
  const auto given = [&](const char* key, const std::string& value) {
    return key_name(key, style) + (style == KeyStyle::python ? " = " : " ") + value;
  };
  if (spec == "uniform") return {uniform_profile(), std::nullopt, "uniform", {}, {}};
  if (spec == "hertz") return {hertz_profile(), std::nullopt, "Hertz", {}, {}};
  if (spec == "seed-tire")
    return {seed_tire_profile(), std::nullopt, "the seed tire's series (Table 1)", {}, {}};
  if (!std::filesystem::exists(spec))
    throw std::runtime_error(given("profile", spec) +
                             ": no such file (or use uniform, hertz, seed-tire)");
  if (smoothing <= 0) {
    MeasuredProfile m = read_profile_csv(spec, clip);
    const auto negative = negative_intervals(m.profile);
    if (!negative.empty() && !clip)
      throw std::runtime_error(given("profile", spec) + ": the pressure is negative on rho in (" +
                               format_value(negative.front().first) + ", " +
                               format_value(negative.front().second) +
                               "); a contact pressure cannot be: correct the table, or add " +
                               key_name("profile_clip", style) + " to clip it at zero");
    return {m.profile, m.reference_pressure_pa, spec + ", " + describe(m.profile), {}, {}};
  }
  const ProfileTable t = read_profile_table(spec);
  SmoothedProfile fit;
  try {
    fit = smoothed_profile(t.rho, t.pressure_pa, smoothing);
  } catch (const InvalidArgument& e) {
    throw std::runtime_error(given("profile_smoothing", std::to_string(smoothing)) + " (" + spec +
                             "): " + e.what());
  }
  // Mean pressure of the fit = 2 integral_0^1 p rho d rho [Pa]; the shape is p / mean.
  const double mean = 2.0 * moment(fit.profile, 1);
  if (!(mean > 0.0 && std::isfinite(mean)))
    throw std::runtime_error(given("profile_smoothing", std::to_string(smoothing)) +
                             ": the fit of " + spec + " has no positive mean pressure");
  for (double& c : std::get<ChebyshevShape>(fit.profile.shape).c) c /= mean;
  if (!negative_intervals(fit.profile).empty()) fit.profile.clip_negative = true;
  return {fit.profile, mean,
          spec + ", " + describe(fit.profile) + " fitted to " + std::to_string(t.rho.size()) +
              " points" + (fit.profile.clip_negative ? ", clipped at 0" : ""),
          fit.rms_residual, fit.max_residual};
}

}  // namespace contensou
