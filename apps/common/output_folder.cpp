#include "output_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include "contensou/friction/file_output.hpp"

namespace contensou::app {

namespace {

namespace fs = std::filesystem;
using Entry = OutputFolder::Entry;

constexpr const char* kLockName = ".contensou.lock";
constexpr const char* kManifestName = ".contensou-manifest";
constexpr const char* kJournalName = ".contensou-journal";
constexpr int kForeignNamed = 3;  // how many foreign files a refusal names

long long nanoseconds(const struct timespec& t) {
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

// The size and modification time of a regular file (a symlink not followed), if it is one.
std::optional<Entry> stamp_of(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return Entry{static_cast<long long>(st.st_size), nanoseconds(st.st_mtim)};
}

bool escapes(const std::string& relative) {
  const fs::path p(relative);
  bool out = relative.empty() || p.is_absolute();
  for (const fs::path& part : p) out = out || part == "..";
  return out;
}

// A manifest's or journal's entries: "SIZE MTIME_NS PATH" for a file, "folder PATH" for a
// folder, "pending PATH" for a file about to be renamed into place (a journal's: the run may have
// been killed after the rename, before the file's own line), after comment lines; entries that
// would leave the folder are ignored. A pending file that is there and has no line of its own is
// recovered: recorded with its stamp now (the lock says no run is writing it).
void read_entries(const std::string& dir, const std::string& name,
                  std::map<std::string, Entry>& entries) {
  std::ifstream in(dir + "/" + name);
  std::set<std::string> pending;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    Entry e;
    std::string relative;
    if (line.rfind("pending ", 0) == 0) {
      if (!escapes(line.substr(8))) pending.insert(line.substr(8));
      continue;
    }
    if (line.rfind("folder ", 0) == 0) {
      relative = line.substr(7);
    } else if (fields >> e.size >> e.mtime_ns) {
      std::getline(fields >> std::ws, relative);
    } else {
      continue;
    }
    if (!escapes(relative)) {
      entries[relative] = e;
      pending.erase(relative);
    }
  }
  for (const std::string& relative : pending)
    if (const std::optional<Entry> now = stamp_of(dir + "/" + relative)) entries[relative] = *now;
}

std::string entry_line(const std::string& relative, const Entry& e) {
  if (e.size < 0) return "folder " + relative + "\n";
  return std::to_string(e.size) + " " + std::to_string(e.mtime_ns) + " " + relative + "\n";
}

bool is_bookkeeping(const std::string& name) {
  return name == kLockName || name == kManifestName || name == kJournalName;
}

// A folder of another run's output folder (it has a lock or a manifest of its own).
bool is_output_folder(const fs::path& p) {
  std::error_code ec;
  return fs::exists(p / kLockName, ec) || fs::exists(p / kManifestName, ec);
}

// Walks `dir`: removes stale temporary files, and returns up to kForeignNamed paths of files
// that no contensou run recorded (folders of other output folders are not entered).
std::vector<std::string> foreign_files(const std::string& dir,
                                       const std::map<std::string, Entry>& known) {
  std::vector<std::string> foreign;
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec);
  if (ec) throw std::runtime_error(dir + ": cannot read the output folder (" + ec.message() + ")");
  for (; it != fs::recursive_directory_iterator(); it.increment(ec)) {
    if (ec)
      throw std::runtime_error(dir + ": cannot read the output folder (" + ec.message() + ")");
    const fs::path& p = it->path();
    const std::string name = p.filename().string();
    const std::string relative = p.lexically_relative(dir).string();
    const bool is_dir = it->is_directory(ec) && !it->is_symlink(ec);
    if (is_dir) {
      if (is_output_folder(p)) it.disable_recursion_pending();
      continue;  // a folder holds files, or nothing: its files decide
    }
    if ((it.depth() == 0 && is_bookkeeping(name)) || known.count(relative) != 0) continue;
    if (is_temporary_file_name(name) && !it->is_symlink(ec)) {
      fs::remove(p, ec);  // a killed run's: the lock says no run is writing it now
      continue;
    }
    foreign.push_back(relative);
    if (static_cast<int>(foreign.size()) == kForeignNamed) break;
  }
  return foreign;
}

[[noreturn]] void refuse_foreign(const std::string& dir, const std::vector<std::string>& files) {
  std::string names;
  for (const std::string& f : files) names += (names.empty() ? "'" : ", '") + f + "'";
  throw std::runtime_error(
      dir + ": not an output folder of contensou: it holds files no contensou run wrote (" + names +
      (files.size() == static_cast<std::size_t>(kForeignNamed) ? ", ..." : "") +
      "), and a run tidies its output folder; choose a new or empty folder (a sub-folder, "
      "say), or one that contensou runs wrote");
}

// The root and the home folder are never output folders, whatever they hold.
void refuse_special(const std::string& dir) {
  std::error_code ec;
  const fs::path p = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  const char* home = std::getenv("HOME");
  std::error_code ec2;
  if (p == p.root_path() ||
      (home != nullptr && *home != '\0' && fs::equivalent(p, fs::path(home), ec2)))
    throw std::runtime_error(dir +
                             ": the root or the home folder is not an output folder (a run "
                             "tidies its output folder); choose a sub-folder of its own");
}

int open_locked(const std::string& dir) {
  const std::string lock = dir + "/" + kLockName;
  const int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error(dir + ": cannot write into the output folder (" +
                             std::strerror(errno) + ")");
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd);
    if (error == EWOULDBLOCK)
      throw std::runtime_error(dir +
                               ": another run is writing into this output folder; wait for it to "
                               "finish or choose another folder");
    throw std::runtime_error(dir + ": cannot lock the output folder (" + std::strerror(error) +
                             ")");
  }
  return fd;
}

// Removes `relative` under `dir` if it is still the file `e` recorded.
bool remove_if_unchanged(const std::string& dir, const std::string& relative, const Entry& e) {
  const std::string path = dir + "/" + relative;
  const std::optional<Entry> now = stamp_of(path);
  return now && now->size == e.size && now->mtime_ns == e.mtime_ns && ::unlink(path.c_str()) == 0;
}

}  // namespace

OutputFolder::OutputFolder(const std::string& dir) : dir_(dir) {
  if (dir.empty()) throw std::runtime_error("empty output folder name");
  refuse_special(dir);
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw std::runtime_error(dir + ": not a folder (an output folder is needed here)");
  fs::create_directories(dir, ec);
  if (ec)
    throw std::runtime_error(dir + ": cannot create the output folder (" + ec.message() + ")");
  // Under the lock: read what earlier runs recorded, check the folder holds nothing else.
  lock_fd_ = open_locked(dir);
  read_entries(dir, kManifestName, earlier_);
  read_entries(dir, kJournalName, earlier_);  // a killed run's journal
  const std::vector<std::string> foreign = foreign_files(dir, earlier_);
  if (!foreign.empty()) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    refuse_foreign(dir, foreign);
  }
  // The killed run's journal joins the manifest, so that it is not lost if this run is killed.
  std::string manifest = "# contensou: what earlier runs wrote here\n";
  for (const auto& [relative, e] : earlier_) manifest += entry_line(relative, e);
  write_file_atomically(dir + "/" + kManifestName, manifest);
  const std::string journal = dir + "/" + kJournalName;
  journal_fd_ = ::open(journal.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0644);
  if (journal_fd_ < 0)
    throw std::runtime_error(journal + ": cannot write (" + std::string(std::strerror(errno)) +
                             ")");
}

OutputFolder::~OutputFolder() {
  if (journal_fd_ >= 0) ::close(journal_fd_);
  if (lock_fd_ >= 0) ::close(lock_fd_);  // releases the lock
}

void OutputFolder::append_to_journal(const std::string& relative, const Entry& e) {
  written_[relative] = e;
  const std::string line = entry_line(relative, e);
  if (::write(journal_fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size()))
    throw std::runtime_error(dir_ + "/" + kJournalName + ": cannot write (" +
                             std::string(std::strerror(errno)) + ")");
}

void OutputFolder::write(const std::string& relative, std::string_view text) {
  intend(relative);
  write_file_atomically(dir_ + "/" + relative, text);
  record(relative);
}

void OutputFolder::intend(const std::string& relative) {
  if (escapes(relative)) throw std::logic_error("output outside its folder: " + relative);
  const std::string line = "pending " + relative + "\n";
  if (::write(journal_fd_, line.data(), line.size()) != static_cast<ssize_t>(line.size()))
    throw std::runtime_error(dir_ + "/" + kJournalName + ": cannot write (" +
                             std::string(std::strerror(errno)) + ")");
}

void OutputFolder::record(const std::string& relative) {
  if (escapes(relative)) throw std::logic_error("output outside its folder: " + relative);
  const std::optional<Entry> e = stamp_of(dir_ + "/" + relative);
  if (e) append_to_journal(relative, *e);
}

void OutputFolder::remove(const std::string& relative) {
  if (written_.count(relative) == 0) throw std::logic_error("not written by this run: " + relative);
  ::unlink((dir_ + "/" + relative).c_str());
  written_.erase(relative);  // the journal keeps the line: a name that is gone matches nothing
}

void OutputFolder::make_folder(const std::string& relative) {
  if (escapes(relative)) throw std::logic_error("output outside its folder: " + relative);
  fs::path sofar;
  for (const fs::path& part : fs::path(relative)) {
    sofar /= part;
    const std::string path = dir_ + "/" + sofar.string();
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      if (earlier_.count(sofar.string()) != 0 && written_.count(sofar.string()) == 0)
        append_to_journal(sofar.string(), Entry{});  // an earlier run's folder, still ours
      continue;
    }
    if (!fs::create_directory(path, ec) || ec)
      throw std::runtime_error(path + ": cannot create the folder (" + ec.message() + ")");
    append_to_journal(sofar.string(), Entry{});
  }
}

std::string OutputFolder::inside(const std::string& path) const {
  std::error_code ec;
  const fs::path root = fs::weakly_canonical(fs::absolute(dir_), ec);
  const fs::path file = fs::weakly_canonical(fs::absolute(path), ec);
  if (ec) return "";
  const fs::path relative = file.lexically_relative(root);
  const std::string r = relative.string();
  return r.empty() || r == "." || escapes(r) ? "" : r;
}

int OutputFolder::commit() {
  int removed = 0;
  // Files first, then folders deepest first (the map's reverse order puts "a/b" before "a").
  for (const auto& [relative, e] : earlier_)
    if (e.size >= 0 && written_.count(relative) == 0 && remove_if_unchanged(dir_, relative, e))
      ++removed;
  for (auto it = earlier_.rbegin(); it != earlier_.rend(); ++it)
    if (it->second.size < 0 && written_.count(it->first) == 0)
      ::rmdir((dir_ + "/" + it->first).c_str());  // only if empty
  std::string manifest =
      "# contensou: the files the last run wrote here (size in bytes, modification time in ns, "
      "path; 'folder PATH' for a folder it made); the next run removes those it does not "
      "rewrite, if unchanged\n";
  for (const auto& [relative, e] : written_) manifest += entry_line(relative, e);
  write_file_atomically(dir_ + "/" + kManifestName, manifest);
  ::close(journal_fd_);
  journal_fd_ = -1;
  ::unlink((dir_ + "/" + kJournalName).c_str());
  return removed;
}

std::string OutputDir::path() const {
  return relative_.empty() ? folder_->dir() : folder_->dir() + "/" + relative_;
}

std::string OutputDir::relative(const std::string& name) const {
  return relative_.empty() ? name : relative_ + "/" + name;
}

void OutputDir::write(const std::string& name, std::string_view text) const {
  folder_->write(relative(name), text);
}

void OutputDir::record(const std::string& name) const {
  folder_->record(relative(name));
}

void OutputDir::intend(const std::string& name) const {
  folder_->intend(relative(name));
}

void OutputDir::remove(const std::string& name) const {
  folder_->remove(relative(name));
}

OutputDir OutputDir::sub(const std::string& name) const {
  folder_->make_folder(relative(name));
  return OutputDir(*folder_, relative(name));
}

void write_output_file(OutputFolder* folder, const std::string& path, std::string_view text) {
  const std::string relative = folder != nullptr ? folder->inside(path) : "";
  if (relative.empty()) return write_file_atomically(path, text);
  folder->write(relative, text);
}

}  // namespace contensou::app
