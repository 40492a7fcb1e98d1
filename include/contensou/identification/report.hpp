// The identification report as JSON: the schema written by contensou-identify --json, shared
// by the app and the Python package (contensou.identify(...).to_json()), and the choice of a
// pressure profile by name or CSV path that both offer.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/pressure_profile.hpp"
#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/key_style.hpp"
#include "contensou/identification/outliers.hpp"

namespace contensou {

// What the report says about its input (the "input" object).
struct ReportInput {
  std::string file;
  int points = 0;
  int values = 0;
  double radius_m = 0.0;
  std::optional<double> normal_load_n;
  std::string normal_load_source;                 // where N came from ("" if given directly)
  std::vector<std::string> column_notes;          // columns read under other names or units
  std::vector<Outlier> outliers;                  // gross errors left out of the fit
  std::string profile;                            // how the pressure profile was given ("" if none)
  std::optional<double> profile_rms_residual_pa;  // a smoothing fit's residual
  std::optional<double> profile_max_residual_pa;
};

// The report of a fit alone: input, base, steps (empty), accepted_effects, final (= base),
// error_before, error_after. `indent` as nlohmann::json::dump (2 in the app's files).
std::string fit_report_json(const ReportInput& input, const FitReport& base, int indent = 2);

// The report of a closed loop: the above with the steps, accepted effects, ambiguities, final
// model and errors before and after.
std::string loop_report_json(const ReportInput& input, const ClosedLoopReport& loop,
                             int indent = 2);

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

// The report's description of a run: the file (or source), the data's point and value counts,
// the radius, the load and the profile as chosen.
ReportInput describe_run(const std::string& file, const MeasuredData& data, double radius_m,
                         std::optional<double> normal_load_n, const ProfileChoice& profile);

}  // namespace contensou
