// Presentation of an identification: the table on stdout, the JSON report, the pictures.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"

namespace contensou::app {

struct RunInfo {
  std::string file;
  int points = 0;
  int values = 0;
  double radius_m = 0.0;
  std::optional<double> normal_load_n;
  std::string profile;                            // how the pressure profile was given ("" if none)
  std::optional<double> profile_rms_residual_pa;  // a smoothing fit's residual
  std::optional<double> profile_max_residual_pa;
};

// The fitted model as a JSON object (the MODEL of the report schema).
nlohmann::json model_json(const std::string& name, const std::vector<std::string>& effects,
                          const FitReport& fit);

// The whole report: input, base, steps, accepted_effects, final, error_before, error_after.
nlohmann::json report_json(const RunInfo& info, const FitReport& base);

// The report of a closed loop: steps, accepted effects, final model, errors before and after.
nlohmann::json loop_report_json(const RunInfo& info, const ClosedLoopReport& loop);

// The steps of the loop as a table.
std::string format_loop(const ClosedLoopReport& loop);

// For each fitted step, a PNG of the residuals before and after it (loop_step_K.png).
bool write_loop_plots(const std::string& dir, const MeasuredData& data,
                      const ClosedLoopReport& loop, double radius_m);

// A readable table of parameters and fit quality.
std::string format_table(const RunInfo& info, const FitReport& fit);

// Writes dir/fit.dat and one PNG per measured channel (measured and fitted against psi or
// 1/psi on a log axis, residuals below). Returns false if the pictures could not be drawn.
bool write_plots(const std::string& dir, const MeasuredData& data, const FitReport& fit,
                 double radius_m);

}  // namespace contensou::app
