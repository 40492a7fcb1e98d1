// One identification as contensou-identify and Python's contensou.identify() run it: gross
// errors found and left out (outliers.hpp), then the fit of the fractional law alone or the
// closed loop on the clean rows.
#pragma once

#include <optional>
#include <vector>

#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/measured_data.hpp"
#include "contensou/identification/outliers.hpp"

namespace contensou {

struct IdentifyOptions {
  IdentificationOptions fit;
  std::optional<ClosedLoopOptions> loop;  // nullopt: the fit of the fractional law only
  bool leave_out_outliers = true;         // find gross errors and fit without them
  // Above this many rows, the robust fit that judges gross errors and the loop's model selection
  // use a stratified sample of about this many (sweeps.hpp: stratified_sample); the gross errors
  // are judged, and the reported fits made, on every row. 0: every row always.
  std::size_t selection_rows = 4000;
};

struct Identification {
  std::vector<Outlier> outliers;  // left out of the fit (indices into the data given)
  MeasuredData fitted;            // the data the reported fit used
  std::vector<int> origin;        // for each point of `fitted`, its index in the data given
  FitReport fit;                  // the fractional law (loop off) or the loop's base fit
  std::optional<ClosedLoopReport> loop;
  const FitReport& final_fit() const { return loop ? loop->final_fit : fit; }
};

// Throws as fit_fractional_law and close_the_loop do.
Identification identify(const MeasuredData& data, const IdentifyOptions& options);

}  // namespace contensou
