#include "gnuplot.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <utility>
#include <vector>

namespace contensou::app {

bool gnuplot_available() {
  return std::system("gnuplot --version > /dev/null 2>&1") == 0;
}

namespace {

// The script gnuplot runs: each `set output 'NAME'` (or "NAME") of `script` writes to a hidden
// temporary name instead (temporary_path_for); the pairs (temporary, final) are returned in
// `outputs`.
std::string with_temporary_outputs(const std::string& script,
                                   std::vector<std::pair<std::string, std::string>>& outputs) {
  const std::string tag = std::to_string(::getpid()), key = "set output ";
  std::string out;
  std::size_t pos = 0;
  while (pos < script.size()) {
    std::size_t end = script.find('\n', pos);
    end = end == std::string::npos ? script.size() : end + 1;
    std::string line = script.substr(pos, end - pos);
    const std::size_t at = line.find_first_not_of(" \t");
    if (at != std::string::npos && line.compare(at, key.size(), key) == 0) {
      const std::size_t open = line.find_first_of("'\"", at + key.size());
      const std::size_t close = open == std::string::npos ? open : line.find(line[open], open + 1);
      if (close != std::string::npos) {
        const std::string final_name = line.substr(open + 1, close - open - 1);
        const std::string tmp = temporary_path_for(final_name, tag);
        outputs.emplace_back(tmp, final_name);
        line.replace(open + 1, close - open - 1, tmp);
      }
    }
    out += line;
    pos = end;
  }
  return out;
}

// Runs gnuplot in `dir` on `script` (its stdin), stderr appended to `log`; true if it exits 0.
// gnuplot dies with this process (PR_SET_PDEATHSIG): a killed run leaves no gnuplot writing on.
bool run_gnuplot_process(const std::string& dir, const std::string& log,
                         const std::string& script) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) return false;
  const pid_t parent = ::getpid();
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  if (child == 0) {  // async-signal-safe calls only, until exec
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int err = ::open(log.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (::chdir(dir.c_str()) != 0 || ::dup2(fds[0], 0) < 0 || err < 0 || ::dup2(err, 2) < 0)
      ::_exit(127);
    ::execlp("gnuplot", "gnuplot", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  ::close(fds[0]);
  // A gnuplot that stops reading must not kill this process with SIGPIPE: block it while writing.
  sigset_t pipe_signal, old;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  ::pthread_sigmask(SIG_BLOCK, &pipe_signal, &old);
  bool ok = true;
  for (std::size_t done = 0; ok && done < script.size();) {
    const ssize_t n = ::write(fds[1], script.data() + done, script.size() - done);
    if (n < 0 && errno == EINTR) continue;
    ok = n > 0;
    if (ok) done += static_cast<std::size_t>(n);
  }
  ::close(fds[1]);
  const struct timespec now {};
  while (::sigtimedwait(&pipe_signal, nullptr, &now) == SIGPIPE) {
  }
  ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  return ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

void remove_quietly(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

// A whole picture: a PNG ends with its IEND chunk (length 0, "IEND", CRC AE 42 60 82); any
// other file is not empty.
bool picture_is_whole(const std::string& path, const std::string& final_name) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamoff size = in.tellg();
  const std::size_t n = final_name.size();
  const bool png = n > 4 && final_name.compare(n - 4, 4, ".png") == 0;
  if (!png) return size > 0;
  static const char kIend[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', '\xAE', '\x42', '\x60', '\x82'};
  if (size < 12 + 8) return false;
  char tail[12];
  in.seekg(size - 12);
  return static_cast<bool>(in.read(tail, 12)) && std::equal(tail, tail + 12, kIend);
}

}  // namespace

bool run_gnuplot(const OutputDir& out, const std::string& name, const std::string& script) {
  const std::string dir = out.path(), gp = dir + "/" + name + ".gp";
  out.write(name + ".gp", script);
  if (!gnuplot_available()) {
    std::fprintf(stderr,
                 "note: gnuplot not found; wrote %s and its data, but no picture "
                 "(install gnuplot and run: cd %s && gnuplot %s.gp)\n",
                 gp.c_str(), dir.c_str(), name.c_str());
    return false;
  }
  // The pictures are drawn under temporary names and renamed when gnuplot has finished, so a
  // kill leaves the previous picture or the new one, never a truncated PNG.
  std::vector<std::pair<std::string, std::string>> outputs;
  const std::string run_script = with_temporary_outputs(script, outputs);
  const std::string log = name + ".log";
  out.write(log, "");  // recorded before gnuplot writes into it
  bool ok = run_gnuplot_process(dir, dir + "/" + log, run_script);
  std::string incomplete;
  for (const auto& [tmp, final_name] : outputs) {
    std::error_code ec;
    const bool whole = ok && picture_is_whole(dir + "/" + tmp, final_name);
    if (ok && !whole && incomplete.empty()) incomplete = dir + "/" + final_name;
    if (whole) out.intend(final_name);  // journalled before the rename: a kill leaves it ours
    if (whole) std::filesystem::rename(dir + "/" + tmp, dir + "/" + final_name, ec);
    if (whole && !ec) out.record(final_name);
    if (!whole || ec) {
      remove_quietly(dir + "/" + tmp);
      ok = false;
    }
  }
  if (!incomplete.empty()) {
    out.remove(log);
    throw std::runtime_error(incomplete +
                             ": cannot write (gnuplot left the picture incomplete: a file-size "
                             "limit or a full disk?); the previous picture is kept");
  }
  if (!ok) {
    out.record(log);
    std::fprintf(stderr, "note: gnuplot failed on %s (see %s/%s)\n", gp.c_str(), dir.c_str(),
                 log.c_str());
    return false;
  }
  out.remove(log);
  return true;
}

}  // namespace contensou::app
