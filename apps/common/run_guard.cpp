#include "run_guard.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "contensou/friction/file_output.hpp"

namespace contensou::app {

namespace {

namespace fs = std::filesystem;

constexpr const char* kLockName = ".contensou.lock";
constexpr const char* kManifestName = ".contensou-manifest";

struct FileStamp {
  long long size = 0;
  long long mtime_ns = 0;
  bool operator==(const FileStamp& o) const { return size == o.size && mtime_ns == o.mtime_ns; }
};

long long nanoseconds(const struct timespec& t) {
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

// The size and modification time of a regular file (not following a symlink), if it is one.
std::optional<FileStamp> stamp_of(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
  return FileStamp{static_cast<long long>(st.st_size), nanoseconds(st.st_mtim)};
}

// The regular files under `dir` modified at or after `since_ns`, by path relative to `dir`;
// another output folder inside (one with its own lock file) is not entered.
std::map<std::string, FileStamp> files_written_since(const std::string& dir, long long since_ns) {
  std::map<std::string, FileStamp> written;
  std::error_code ec;
  fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const fs::path& path = it->path();
    if (it.depth() > 0 && it->is_directory(ec) && !it->is_symlink(ec) &&
        fs::exists(path / kLockName, ec)) {
      it.disable_recursion_pending();
      continue;
    }
    const std::string name = path.filename().string();
    if (it.depth() == 0 && (name == kLockName || name == kManifestName)) continue;
    const std::string relative = path.lexically_relative(dir).string();
    if (relative.find('\n') != std::string::npos) continue;
    const std::optional<FileStamp> stamp = stamp_of(path.string());
    if (stamp && stamp->mtime_ns >= since_ns) written[relative] = *stamp;
  }
  return written;
}

// The manifest's entries: "SIZE MTIME_NS PATH" a line after a comment line; entries that would
// leave the folder (absolute, "..") are ignored.
std::map<std::string, FileStamp> read_manifest(const std::string& path) {
  std::map<std::string, FileStamp> entries;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    FileStamp stamp;
    std::string relative;
    if (line.empty() || line[0] == '#' || !(fields >> stamp.size >> stamp.mtime_ns)) continue;
    std::getline(fields >> std::ws, relative);
    const fs::path p(relative);
    bool escapes = relative.empty() || p.is_absolute();
    for (const fs::path& part : p) escapes = escapes || part == "..";
    if (!escapes) entries[relative] = stamp;
  }
  return entries;
}

// Removes `relative` under `dir` if it still has `stamp`, then its parent folders left empty.
bool remove_if_unchanged(const std::string& dir, const std::string& relative,
                         const FileStamp& stamp) {
  const fs::path path = fs::path(dir) / relative;
  const std::optional<FileStamp> now = stamp_of(path.string());
  if (!now || !(*now == stamp) || ::unlink(path.c_str()) != 0) return false;
  for (fs::path parent = path.parent_path(); parent.lexically_relative(dir) != ".";
       parent = parent.parent_path())
    if (::rmdir(parent.c_str()) != 0) break;  // not empty (or not ours): stop
  return true;
}

}  // namespace

void prepare_output() {
  std::signal(SIGXFSZ, SIG_IGN);
}

OutputFolderLock::OutputFolderLock(const std::string& dir) : dir_(dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw std::runtime_error(dir + ": cannot create the output folder (" + ec.message() + ")");
  const std::string lock = dir + "/.contensou.lock";
  fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error(dir + ": cannot write into the output folder (" +
                             std::strerror(errno) + ")");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw std::runtime_error(dir +
                               ": another run is writing into this output folder; wait for it to "
                               "finish or choose another folder");
    throw std::runtime_error(dir + ": cannot lock the output folder (" + std::strerror(error) +
                             ")");
  }
  // The run's start on the file system's own clock (coarser than the process's): touch the lock.
  struct stat st {};
  if (::futimens(fd_, nullptr) != 0 || ::fstat(fd_, &st) != 0)
    throw std::runtime_error(dir + ": cannot write into the output folder (" +
                             std::strerror(errno) + ")");
  start_ns_ = nanoseconds(st.st_mtim);
}

int OutputFolderLock::commit() {
  const std::map<std::string, FileStamp> written = files_written_since(dir_, start_ns_);
  int removed = 0;
  for (const auto& [relative, stamp] : read_manifest(dir_ + "/" + kManifestName))
    if (written.count(relative) == 0 && remove_if_unchanged(dir_, relative, stamp)) ++removed;
  std::string manifest =
      "# contensou: the files the last run wrote here (size in bytes, modification time in ns, "
      "path); the next run into this folder removes those it does not rewrite\n";
  for (const auto& [relative, stamp] : written)
    manifest +=
        std::to_string(stamp.size) + " " + std::to_string(stamp.mtime_ns) + " " + relative + "\n";
  write_file_atomically(dir_ + "/" + kManifestName, manifest);
  return removed;
}

OutputFolderLock::~OutputFolderLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

int finish_output(int status) {
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed) return status;
  std::fprintf(stderr, "error: writing to standard output failed (%s)\n", std::strerror(errno));
  return 1;
}

}  // namespace contensou::app
