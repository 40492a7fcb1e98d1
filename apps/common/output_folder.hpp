// An app's output folder (contensou-identify --plots, contensou-shimmy --out): locked for one run,
// written file by file with each name recorded as it is written, and tidied only of what
// contensou itself wrote there.
//
// The folder's rules (docs/reliability.md):
//  - It must be new, empty, or hold only what contensou runs wrote there (the files its manifest
//    lists, another output folder of contensou's inside, stale temporary files of a killed run).
//    A folder that holds anything else (a root, a home, a folder of your data) is refused with the
//    first such files named: nothing of it is ever removed.
//  - One run at a time: DIR/.contensou.lock (flock) is held from the constructor on; a second run
//    into the same folder is refused at once.
//  - Each file (and sub-folder) the run writes is appended to DIR/.contensou-journal as soon as it
//    is in place, so a run killed half-way leaves a record of what it wrote; before a file is
//    renamed into place its name is journalled as pending, and the next run records a pending
//    file that is there (a kill between the rename and the record leaves no foreign file).
//  - commit(), once the run has written everything, removes the files and folders an earlier run
//    recorded (its manifest, or the journal of a killed run) that this run did not write again,
//    each only if unchanged since (same size and modification time) and folders only if empty;
//    then the journal becomes the manifest, DIR/.contensou-manifest. A failed run commits
//    nothing and removes nothing.
//  - Temporary files of a killed run (".NAME.contensou-tmp-*", file_output.hpp) are removed when
//    the next run takes the lock.
#pragma once

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace contensou::app {

class OutputFolder {
 public:
  // Creates `dir` (and its parents) if needed, checks its contents, takes the lock, removes stale
  // temporary files. Throws std::runtime_error naming the folder and the reason.
  explicit OutputFolder(const std::string& dir);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& dir() const { return dir_; }

  // Writes DIR/relative whole (write_file_atomically) and records it.
  void write(const std::string& relative, std::string_view text);
  // Records DIR/relative, put in place by other means (a picture renamed after gnuplot): call
  // intend(relative) before the rename, so that a kill between the two leaves it recorded.
  void record(const std::string& relative);
  // Journals that DIR/relative is about to be renamed into place ("pending PATH"): the next run
  // recovers such a file if this one is killed before record().
  void intend(const std::string& relative);
  // Removes DIR/relative, a file this run wrote (a log it no longer needs), from the folder and
  // from the record.
  void remove(const std::string& relative);
  // Creates the folder DIR/relative (and its parents inside DIR), recording those it creates.
  void make_folder(const std::string& relative);
  // The path `path` relative to DIR if it lies inside DIR (a --json report among the pictures),
  // else "".
  std::string inside(const std::string& path) const;

  // Removes what an earlier run wrote and this one did not; writes the manifest. Returns the
  // number of files removed.
  int commit();

  struct Entry {
    long long size = -1;  // -1: a folder
    long long mtime_ns = 0;
  };

 private:
  void append_to_journal(const std::string& relative, const Entry& e);

  std::string dir_;
  int lock_fd_ = -1;
  int journal_fd_ = -1;
  std::map<std::string, Entry> earlier_;  // what earlier runs wrote (manifest, killed journals)
  std::map<std::string, Entry> written_;  // what this run wrote
};

// A folder inside an output folder, to pass to the functions that write pictures and tables:
// dir.write("fit.csv", text), dir.sub("touchdown").
class OutputDir {
 public:
  explicit OutputDir(OutputFolder& folder, std::string relative = "")
      : folder_(&folder), relative_(std::move(relative)) {}

  // The folder's path (DIR or DIR/relative), for messages and for gnuplot's working folder.
  std::string path() const;
  // The name of `name` relative to the output folder.
  std::string relative(const std::string& name) const;
  void write(const std::string& name, std::string_view text) const;
  void record(const std::string& name) const;
  void intend(const std::string& name) const;
  void remove(const std::string& name) const;
  // The sub-folder `name`, created and recorded.
  OutputDir sub(const std::string& name) const;

 private:
  OutputFolder* folder_;
  std::string relative_;
};

// Writes `path` whole: recorded by `folder` when it lies inside it, else write_file_atomically.
void write_output_file(OutputFolder* folder, const std::string& path, std::string_view text);

}  // namespace contensou::app
