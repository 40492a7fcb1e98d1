#include "gnuplot.hpp"

#include <unistd.h>

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
// temporary name instead (.NAME.tmp-PID); the pairs (temporary, final) are returned in `outputs`.
std::string with_temporary_outputs(const std::string& script,
                                   std::vector<std::pair<std::string, std::string>>& outputs) {
  const std::string suffix = ".tmp-" + std::to_string(::getpid()), key = "set output ";
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
        const std::size_t slash = final_name.rfind('/') + 1;  // 0 without a folder
        const std::string tmp =
            final_name.substr(0, slash) + "." + final_name.substr(slash) + suffix;  // hidden
        outputs.emplace_back(tmp, final_name);
        line.replace(open + 1, close - open - 1, tmp);
      }
    }
    out += line;
    pos = end;
  }
  return out;
}

void remove_quietly(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
}

}  // namespace

bool run_gnuplot(const std::string& dir, const std::string& name, const std::string& script) {
  const std::string gp = dir + "/" + name + ".gp";
  write_file_atomically(gp, script);
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
  const std::string cmd = "cd '" + dir + "' && gnuplot 2> '" + log + "'";
  FILE* pipe = ::popen(cmd.c_str(), "w");
  bool ok = pipe != nullptr &&
            std::fwrite(run_script.data(), 1, run_script.size(), pipe) == run_script.size();
  if (pipe != nullptr) ok = ::pclose(pipe) == 0 && ok;
  for (const auto& [tmp, final_name] : outputs) {
    std::error_code ec;
    if (ok) std::filesystem::rename(dir + "/" + tmp, dir + "/" + final_name, ec);
    if (!ok || ec) {
      remove_quietly(dir + "/" + tmp);
      ok = false;
    }
  }
  if (!ok) {
    std::fprintf(stderr, "note: gnuplot failed on %s (see %s/%s)\n", gp.c_str(), dir.c_str(),
                 log.c_str());
    return false;
  }
  remove_quietly(dir + "/" + log);
  return true;
}

}  // namespace contensou::app
