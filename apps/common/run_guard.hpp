// What every app does around its run so that nothing is lost: write errors reported (also on
// standard output), and file-size limits turned into errors instead of a kill.
#pragma once

#include <string>

namespace contensou::app {

// Call first in main: a write past the file-size limit (ulimit -f) then fails with EFBIG, which
// the writers report, instead of killing the process with SIGXFSZ.
void prepare_output();

// The output folder itself (lock, record of what a run writes, tidying): output_folder.hpp.

// The exit status after flushing standard output: `status` if every write to it succeeded,
// else 1 after a message on stderr (a full disk or a closed pipe behind stdout).
int finish_output(int status);

}  // namespace contensou::app
