#include "run_guard.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>

namespace contensou::app {

void prepare_output() {
  std::signal(SIGXFSZ, SIG_IGN);
}

OutputFolderLock::OutputFolderLock(const std::string& dir) {
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
