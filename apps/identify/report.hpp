// The identification's pictures (the text and JSON reports are the library's: report_text.hpp,
// report.hpp).
#pragma once

#include <string>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/report.hpp"
#include "output_folder.hpp"

namespace contensou::app {

// What the report says about its input (the library's ReportInput; the JSON report itself is
// written by the library, contensou/identification/report.hpp).
using RunInfo = ReportInput;

// The pictures read the fit's results (its psi, predictions and residuals per point, fit.hpp)
// and the measured values of the data it was fitted to; they compute nothing the fit owns.

// For each fitted step, a PNG of the residuals before and after it (loop_step_K.png).
bool write_loop_plots(const OutputDir& dir, const MeasuredData& data, const ClosedLoopReport& loop);

// Writes dir/fit.csv (psi, upsilon, and measured_, fit_, residual_ per channel, by name) and one
// PNG per measured channel (measured and fitted against psi or
// 1/psi on a log axis, residuals below). Returns false if the pictures could not be drawn.
bool write_plots(const OutputDir& dir, const MeasuredData& data, const FitReport& fit);

}  // namespace contensou::app
