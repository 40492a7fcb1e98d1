// Presentation of an identification: the table on stdout, the JSON report, the pictures.
#pragma once

#include <string>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/report.hpp"

namespace contensou::app {

// What the report says about its input (the library's ReportInput; the JSON report itself is
// written by the library, contensou/identification/report.hpp).
using RunInfo = ReportInput;

// The steps of the loop as a table.
std::string format_loop(const ClosedLoopReport& loop);

// For each fitted step, a PNG of the residuals before and after it (loop_step_K.png).
bool write_loop_plots(const std::string& dir, const MeasuredData& data,
                      const ClosedLoopReport& loop, double radius_m);

// A readable table of parameters and fit quality.
std::string format_table(const RunInfo& info, const FitReport& fit);

// Writes dir/fit.csv (psi, upsilon, and measured_, fit_, residual_ per channel, by name) and one
// PNG per measured channel (measured and fitted against psi or
// 1/psi on a log axis, residuals below). Returns false if the pictures could not be drawn.
bool write_plots(const std::string& dir, const MeasuredData& data, const FitReport& fit,
                 double radius_m);

}  // namespace contensou::app
