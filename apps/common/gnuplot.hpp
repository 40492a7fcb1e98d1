// Drawing with gnuplot, found at run time: scripts are always written, pictures when gnuplot is
// on the PATH.
#pragma once

#include <string>

#include "contensou/friction/file_output.hpp"

namespace contensou::app {

// True if `gnuplot` can be run.
bool gnuplot_available();

// Writes `script` to dir/name.gp and runs gnuplot on it in `dir`. Returns false (after a
// note on stderr) if gnuplot is missing or fails; the script and data stay in place.
bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script);

}  // namespace contensou::app
