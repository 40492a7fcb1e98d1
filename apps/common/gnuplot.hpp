// Drawing with gnuplot, found at run time: scripts are always written, pictures when gnuplot is
// on the PATH.
#pragma once

#include <string>

#include "contensou/friction/file_output.hpp"
#include "output_folder.hpp"

namespace contensou::app {

// True if `gnuplot` can be run.
bool gnuplot_available();

// Writes `script` to dir/name.gp and runs gnuplot on it in `dir`; each picture the script sets
// as output is drawn under a temporary name and renamed into place when whole. Returns false
// (after a note on stderr) if gnuplot is missing or fails; the script and data stay in place.
// Throws std::runtime_error naming the picture when gnuplot left it incomplete (a file-size
// limit, a full disk): a failed write is an error.
bool run_gnuplot(const OutputDir& dir, const std::string& name, const std::string& script);

}  // namespace contensou::app
