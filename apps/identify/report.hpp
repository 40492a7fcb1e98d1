// The identification's pictures (the text and JSON reports are the library's: report_text.hpp,
// report.hpp).
#pragma once

#include <string>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/outliers.hpp"
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

// What the fit pictures show: every row of the data as read (gross errors included, marked),
// where each row went in the fit (Identification::origin) and the radius for psi.
struct PlotInput {
  const MeasuredData& data;
  const std::vector<Outlier>& outliers;
  const std::vector<int>& origin;
  double radius_m;
};

// Writes dir/fit.csv (every row, by sweep and psi: file, line, sweep, Fz_N, psi, upsilon, and
// per channel measured_, fit_, residual_, outlier_, with measured_X_in_file and its unit where
// a file is not in SI), dir/sweeps.csv (each sweep's label, file, load, direction, spin speed)
// and one PNG per measured channel: measured and fitted against psi or 1/psi on a log axis, one
// colour a sweep, gross errors marked; residuals below. Returns false if the pictures could not
// be drawn.
bool write_plots(const OutputDir& dir, const PlotInput& in, const FitReport& fit);

}  // namespace contensou::app
