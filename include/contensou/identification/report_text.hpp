/// \file
/// The identification report as text, as contensou-identify prints it and as Python's
/// IdentificationResult.text gives it: the input, the parameters with their intervals, the
/// channels' diagnostics, warnings in words, the closed loop's steps with a legend, and a
/// plain-language summary. The JSON report (report.hpp) carries the same facts.
#pragma once

#include <string>
#include <vector>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/report.hpp"

namespace contensou {

/// Fewer residual degrees of freedom than this per estimated noise scale make a warning: a
/// scale estimated from k degrees of freedom has a relative standard error of about
/// 1 / sqrt(2 k), 22 % at 10.
inline constexpr int kFewDegreesOfFreedomPerScale = 10;

/// What a reader must know before trusting the fit, in words (empty if nothing): too little data
/// for the noise scales, parameters the data do not determine, a solver that did not converge,
/// a radius that cannot match the torque (M0 / (F0 R) above 1.05 or below 0.05).
std::vector<std::string> fit_warnings(const FitReport& fit);

/// What makes a fit physically doubtful, for the report's first lines (empty if nothing):
/// each parameter that ends on a bound of the fit (but a profile weight at zero or the blend at
/// an end, ordinary shapes), with what the bound means, and a law whose
/// a, m and M0 / (F0 R) no non-negative pressure on the patch gives (admissible_shape.hpp).
std::vector<std::string> shape_cautions(const FitReport& fit);

/// fit_report_text with the fit's cautions (shape_cautions) as its first lines.
std::string fit_report_text_with_cautions(const ReportInput& input, const FitReport& fit);

/// The loop's outcome in plain words: what the data show, what was tried and not needed, what
/// was not decided because its fit failed, what limits the fit.
std::string loop_summary(const ClosedLoopReport& loop);

/// The fit of the fractional law alone: input, parameters, channels, fit line, residual
/// whiteness and trace, warnings.
std::string fit_report_text(const ReportInput& input, const FitReport& fit);

/// The closed loop: the cautions of the final model (and of the base law when effects were
/// added) first, then the base fit as above, the steps with a legend, the accepted effects, the
/// final model (when an effect was accepted) and a summary in plain words.
std::string loop_report_text(const ReportInput& input, const ClosedLoopReport& loop);

}  // namespace contensou
