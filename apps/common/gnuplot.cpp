#include "gnuplot.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace contensou::app {

bool gnuplot_available() {
  return std::system("gnuplot --version > /dev/null 2>&1") == 0;
}

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
  const std::string cmd = "cd '" + dir + "' && gnuplot '" + name + ".gp' 2> '" + name + ".log'";
  if (std::system(cmd.c_str()) != 0) {
    std::fprintf(stderr, "note: gnuplot failed on %s (see %s/%s.log)\n", gp.c_str(), dir.c_str(),
                 name.c_str());
    return false;
  }
  std::filesystem::remove(dir + "/" + name + ".log");
  return true;
}

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) {
      std::filesystem::remove(tmp);
      throw std::runtime_error(path + ": cannot write");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp);
    throw std::runtime_error(path + ": cannot write (" + ec.message() + ")");
  }
}

}  // namespace contensou::app
