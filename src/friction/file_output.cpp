// Atomic file output (file_output.hpp), POSIX.
#include "contensou/friction/file_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <vector>

namespace contensou {

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what, int error) {
  throw std::runtime_error(path + ": cannot write (" + what + ": " + std::strerror(error) + ")");
}

// Writes all of `text` to fd; false with errno set on failure (EINTR retried).
bool write_all(int fd, std::string_view text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

// A device or a FIFO: written through, never replaced.
void write_through(const std::string& path, std::string_view text, bool fifo) {
  // O_NONBLOCK: opening a FIFO without a reader fails (ENXIO) instead of waiting forever.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC | (fifo ? O_NONBLOCK : 0));
  if (fd < 0 && fifo && errno == ENXIO)
    throw std::runtime_error(path + ": cannot write (a FIFO that nobody reads)");
  if (fd < 0) fail(path, "open", errno);
  if (fifo) ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  const bool ok = write_all(fd, text);
  const int error = errno;
  if (::close(fd) != 0 && ok) fail(path, "close", errno);
  if (!ok) fail(path, "write", error);
}

constexpr const char* kTemporaryMark = ".contensou-tmp-";
constexpr std::size_t kNameMax = 255;  // NAME_MAX of Linux file systems

// The descriptor of this process that `path` names (/dev/stdout, /dev/fd/3, /proc/self/fd/1).
std::optional<int> own_descriptor(const std::string& path) {
  if (path == "/dev/stdin") return 0;
  if (path == "/dev/stdout") return 1;
  if (path == "/dev/stderr") return 2;
  for (const char* prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    const std::size_t n = std::strlen(prefix);
    if (path.compare(0, n, prefix) != 0 || path.size() == n || path.size() > n + 9) continue;
    int fd = 0;
    for (std::size_t i = n; i < path.size(); ++i) {
      if (path[i] < '0' || path[i] > '9') return std::nullopt;
      fd = fd * 10 + (path[i] - '0');
    }
    return fd;
  }
  return std::nullopt;
}

// Writes to one of this process's descriptors; standard output's buffer goes first.
void write_to_descriptor(const std::string& path, int fd, std::string_view text) {
  std::fflush(stdout);
  std::fflush(stderr);
  if (::fcntl(fd, F_GETFL) == -1) fail(path, "descriptor " + std::to_string(fd), errno);
  if (!write_all(fd, text)) fail(path, "write", errno);
}

// The file a path names, following symlinks (a dangling link: the target it names).
std::string resolved(const std::string& path) {
  std::string p = path;
  for (int hops = 0; hops < 40; ++hops) {
    struct stat st {};
    if (own_descriptor(p) || ::lstat(p.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return p;
    std::vector<char> buf(PATH_MAX + 1);
    const ssize_t n = ::readlink(p.c_str(), buf.data(), PATH_MAX);
    if (n < 0) fail(path, "readlink", errno);
    std::string target(buf.data(), static_cast<std::size_t>(n));
    if (target.front() != '/') {
      const std::size_t slash = p.rfind('/');
      if (slash != std::string::npos) target = p.substr(0, slash + 1) + target;
    }
    p = target;
  }
  fail(path, "symlinks", ELOOP);
}

// The permissions of a new file: those of the file it replaces, else 0666 less the umask.
mode_t new_file_mode(const std::string& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0) return st.st_mode & 07777;
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

}  // namespace

std::string temporary_path_for(const std::string& path, const std::string& tag) {
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::size_t room = kNameMax - 1 - std::strlen(kTemporaryMark) - tag.size();
  if (base.size() > room) {
    std::size_t cut = room;  // not inside a UTF-8 character: back off its continuation bytes
    while (cut > 0 && (static_cast<unsigned char>(base[cut]) & 0xC0) == 0x80) --cut;
    base.resize(cut);
  }
  return dir + "." + base + kTemporaryMark + tag;
}

bool is_temporary_file_name(const std::string& name) {
  const std::size_t mark = name.rfind(kTemporaryMark);
  return name.size() > 1 && name[0] == '.' && mark != std::string::npos && mark > 0 &&
         mark + std::strlen(kTemporaryMark) < name.size();
}

void write_file_atomically(const std::string& path, std::string_view text) {
  if (path.empty()) throw std::runtime_error("cannot write: empty file name");
  const std::string target = resolved(path);
  if (const std::optional<int> fd = own_descriptor(target))
    return write_to_descriptor(path, *fd, text);
  struct stat st {};
  if (::stat(target.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))
      return write_through(target, text, S_ISFIFO(st.st_mode));
    throw std::runtime_error(path + ": cannot write (not a regular file" +
                             std::string(S_ISDIR(st.st_mode) ? ", a folder" : "") + ")");
  }
  const std::size_t slash = target.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : target.substr(0, slash + 1);
  std::string tmp = temporary_path_for(target, "XXXXXX");
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0) fail(path, "temporary file in " + dir, errno);
  const bool ok =
      ::fchmod(fd, new_file_mode(target)) == 0 && write_all(fd, text) && ::fsync(fd) == 0;
  const int error = errno;
  if ((::close(fd) != 0 || !ok)) {
    const int e = ok ? errno : error;
    ::unlink(tmp.c_str());
    fail(path, "write", e);
  }
  if (::rename(tmp.c_str(), target.c_str()) != 0) {
    const int e = errno;
    ::unlink(tmp.c_str());
    fail(path, "rename", e);
  }
  // The rename itself made durable: fsync the folder (best effort: some file systems refuse).
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace contensou
