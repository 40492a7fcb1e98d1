// The choice of a pressure profile by name or CSV path that contensou-identify and the Python
// package offer: a step of reading the request, before the fit (the report describes it).
#pragma once

#include <optional>
#include <string>

#include "contensou/friction/pressure_profile.hpp"
#include "contensou/identification/key_style.hpp"

namespace contensou {

// A pressure profile given as a built-in name (uniform, hertz, seed-tire) or a CSV path
// (rho,pressure_Pa). With smoothing > 0 a CSV is fitted by a Chebyshev series in rho^2 of that
// many terms instead of interpolated; a CSV that dips below zero is refused unless clip.
// Throws std::runtime_error naming the option (--profile, --profile-smoothing) and the file.
struct ProfileChoice {
  PressureProfile profile;
  std::optional<double> reference_pressure;  // from a CSV profile
  std::string description;
  std::optional<double> rms_residual_pa, max_residual_pa;  // of a smoothing fit
};
ProfileChoice choose_profile(const std::string& spec, int smoothing = 0, bool clip = false,
                             KeyStyle style = KeyStyle::command_line);

}  // namespace contensou
