// Shared by the fuzz targets: the readers take a path, so each input is written to a file.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace contensou::fuzz {

// Writes the input to a file unique to this process (removed at exit) and returns its path.
// The file lives in memory (/dev/shm) where possible: a disk file costs ten times the reading.
inline const std::string& write_input(const std::uint8_t* data, std::size_t size,
                                      const char* extension) {
  static const std::string path = [&] {
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    std::string p =
        std::string(dir) + "/contensou_fuzz_" + std::to_string(getpid()) + "." + extension;
    static std::string remove_at_exit = p;
    std::atexit([] { std::remove(remove_at_exit.c_str()); });
    return p;
  }();
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path;
}

// A broken promise of a reader: print it and abort, so that libFuzzer saves the input.
[[noreturn]] inline void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

inline void require(bool ok, const std::string& what) {
  if (!ok) finding(what);
}

}  // namespace contensou::fuzz
