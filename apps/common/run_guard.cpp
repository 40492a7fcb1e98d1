#include "run_guard.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace contensou::app {

void prepare_output() {
  std::signal(SIGXFSZ, SIG_IGN);
}

int finish_output(int status) {
  std::cout.flush();
  const bool failed = !std::cout || std::fflush(stdout) != 0 || std::ferror(stdout);
  if (!failed) return status;
  std::fprintf(stderr, "error: writing to standard output failed (%s)\n", std::strerror(errno));
  return 1;
}

}  // namespace contensou::app
