// What every app does around its run so that nothing is lost or mixed: an exclusive lock on its
// output folder, write errors reported (also on standard output), and file-size limits turned
// into errors instead of a kill.
#pragma once

#include <string>

namespace contensou::app {

// Call first in main: a write past the file-size limit (ulimit -f) then fails with EFBIG, which
// the writers report, instead of killing the process with SIGXFSZ.
void prepare_output();

// Creates `dir` (and its parents) and holds an exclusive lock on it (DIR/.contensou.lock, flock)
// until destroyed or the process ends, killed or not. A second run into the same folder is
// refused with an error naming the folder, so two runs never mix their files.
//
// Runs one after another into one folder do not mix either: commit(), called once the run has
// written everything, removes the files the previous run listed in DIR/.contensou-manifest that
// this run did not rewrite (only if unchanged since: same size and time), then lists the files
// this run wrote. A failed or killed run commits nothing, so the previous run's files stay.
class OutputFolderLock {
 public:
  explicit OutputFolderLock(const std::string& dir);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  // Returns the number of stale files removed.
  int commit();

 private:
  std::string dir_;
  int fd_ = -1;
  long long start_ns_ = 0;  // the lock file's time when the run began (the file system's clock)
};

// The exit status after flushing standard output: `status` if every write to it succeeded,
// else 1 after a message on stderr (a full disk or a closed pipe behind stdout).
int finish_output(int status);

}  // namespace contensou::app
