// The command-line conventions every app keeps: --help and --version (the CMake project's
// version), and the exit status, documented in each --help:
//   0  success (also after --help and --version)
//   1  failure: bad input data, a run that failed, a write that failed
//   2  usage error: an unknown option, a missing or malformed value (CLI11's parse errors,
//      whose own codes, 105, 106, ..., are mapped to 2)
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "contensou/version.hpp"

namespace contensou::app {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

// --version ("NAME X.Y.Z") and the exit statuses in the --help epilog (CLI11 adds --help).
inline void add_conventions(CLI::App& app, const char* name) {
  app.set_version_flag("--version", std::string(name) + " " + kVersion,
                       "print the name and version, and exit");
  app.footer(
      "Exit status: 0 success, 1 failure (bad data, a failed run or write), 2 usage error "
      "(an unknown option, a missing or malformed value).");
}

// Parses the command line. Returns nothing to go on with the run, or the exit status to end
// with: 0 after --help or --version (printed), 2 after a usage error (printed on stderr).
inline std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, version or the error
    return code == static_cast<int>(CLI::ExitCodes::Success) ? kExitSuccess : kExitUsage;
  }
  return std::nullopt;
}

}  // namespace contensou::app
