/// \file
/// The choice of a pressure profile by name or CSV path that contensou-identify and the Python
/// package offer: a step of reading the request, before the fit (the report describes it).
#pragma once

#include <optional>
#include <string>

#include "contensou/friction/pressure_profile.hpp"
#include "contensou/identification/key_style.hpp"

namespace contensou {

/// A pressure profile chosen by choose_profile, with what the report says of it.
struct ProfileChoice {
  PressureProfile profile;                   ///< the chosen profile
  std::optional<double> reference_pressure;  ///< p* [Pa] of a CSV profile (unset for a name)
  std::string description;                   ///< for the report: "Hertz", "f.csv, ..."
  std::optional<double> rms_residual_pa,     ///< rms residual of a smoothing fit [Pa]
      max_residual_pa;                       ///< largest residual of a smoothing fit [Pa]
};

/// The profile of `spec`: a built-in name (uniform, hertz, seed-tire) or a CSV path
/// (rho,pressure_Pa; read_profile_csv). With `smoothing` > 0 a CSV is fitted by a Chebyshev
/// series in rho^2 of that many terms (smoothed_profile) instead of interpolated: the shape is
/// divided by the fit's mean pressure, which becomes the reference pressure, and a fit that dips
/// below zero is clipped at 0 (`clip` is not needed). Without smoothing, a CSV that dips below
/// zero is refused unless `clip` (then clipped at 0). Throws std::runtime_error naming the
/// option as `style` writes it (`--profile`, `--profile-smoothing` on the command line) and the
/// file, for a path that does not exist, a negative table or a failed smoothing fit; a
/// malformed file's ParseError or InvalidArgument (read_profile_csv) passes through.
ProfileChoice choose_profile(const std::string& spec, int smoothing = 0, bool clip = false,
                             KeyStyle style = KeyStyle::command_line);

}  // namespace contensou
