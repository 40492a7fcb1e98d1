// The command-line conventions every app keeps: --help and --version (the CMake project's
// version), and the exit status, documented in each --help:
//   0  success (also after --help and --version)
//   1  failure: bad input data (a value out of its range included: --radius -1, --points 1e9,
//      a NaN), a missing or unreadable input file, a run that failed, a write that failed
//   2  usage error: an unknown option (named, with the nearest valid option: "--los" gives
//      "did you mean --loss?"), a missing option or value, a malformed value (not a number),
//      a word not among the allowed ones (named with them: "--loss hubber"), an option given
//      twice for one thing (CLI11's parse errors, whose own codes, 105, 106, ..., are mapped
//      to 2; an app's own checks of the same kind throw UsageError)
#pragma once

#include <CLI/CLI.hpp>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "contensou/friction/csv.hpp"
#include "contensou/version.hpp"

namespace contensou::app {

inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;

inline constexpr const char* kExitStatusHelp =
    "Exit status: 0 success, 1 failure (bad data or a value out of its range, a missing or "
    "unreadable input file, a failed run or write), 2 usage error (an unknown option, a missing "
    "or malformed value, a value not among the allowed ones).";

// A usage error found by an app's own checks after parsing (exit status 2).
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// --version ("NAME X.Y.Z") and the exit statuses in the --help epilog (CLI11 adds --help).
inline void add_conventions(CLI::App& app, const char* name) {
  app.name(name);
  app.set_version_flag("--version", std::string(name) + " " + kVersion,
                       "print the name and version, and exit");
  app.footer(kExitStatusHelp);
}

inline std::string join_words(const std::vector<std::string>& words, const char* separator) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "" : separator) + w;
  return out;
}

// A check that the value is one of `words`: else "'hubber' is not one of none, huber, cauchy
// (did you mean 'huber'?)", a usage error.
inline CLI::Validator one_of(const std::vector<std::string>& words) {
  return CLI::Validator(
      [words](std::string& value) -> std::string {
        for (const std::string& w : words)
          if (value == w) return {};
        const std::string close = closest_name(words, value);
        return "'" + value + "' is not one of " + join_words(words, ", ") +
               (close.empty() ? "" : " (did you mean '" + close + "'?)");
      },
      "{" + join_words(words, "|") + "}");
}

namespace detail {

// The options of `app` ("--loss", "-h"), with the subcommand they belong to ("" for the app's).
inline void option_names(const CLI::App& app, const std::string& sub,
                         std::vector<std::pair<std::string, std::string>>& out) {
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) out.emplace_back("--" + n, sub);
    for (const std::string& n : o->get_snames()) out.emplace_back("-" + n, sub);
  }
  for (const CLI::App* s : app.get_subcommands({})) option_names(*s, s->get_name(), out);
}

// "unknown option --los (did you mean --loss?)" for the first argument that looks like an
// option and was not taken, or "" if there is none.
inline std::string unknown_option(const CLI::App& app) {
  std::vector<std::pair<std::string, std::string>> options;
  option_names(app, "", options);
  std::vector<std::string> names;
  for (const auto& o : options) names.push_back(o.first);
  for (const std::string& arg : app.remaining(true)) {
    if (arg.size() < 2 || arg[0] != '-' || (arg[1] >= '0' && arg[1] <= '9') || arg[1] == '.')
      continue;  // a value, a negative number
    const std::string name = arg.substr(0, arg.find('='));
    for (const auto& [option, sub] : options)
      if (option == name && !sub.empty())
        return name + " is an option of '" + sub + "' (" + app.get_name() + " " + sub + " " + name +
               " ...)";
    const std::string close = closest_name(names, name);
    return "unknown option " + name + (close.empty() ? "" : " (did you mean " + close + "?)");
  }
  return {};
}

}  // namespace detail

// Parses the command line. Returns nothing to go on with the run, or the exit status to end
// with: 0 after --help or --version (printed), 2 after a usage error (printed on stderr; an
// unknown option is named first, with the nearest valid one, before any other error), 1 when
// an input file an option names does not exist (CLI11's ExistingFile check).
inline std::optional<int> parse(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = e.get_exit_code();
    if (code == static_cast<int>(CLI::ExitCodes::Success)) {
      app.exit(e);  // prints help or version
      return kExitSuccess;
    }
    std::string message = detail::unknown_option(app);
    int status = kExitUsage;
    if (message.empty()) {
      message = e.what();
      if (message.find("does not exist") != std::string::npos) status = kExitFailure;
    }
    std::fprintf(stderr, "%s: error: %s\nRun with --help for more information.\n",
                 app.get_name().c_str(), message.c_str());
    return status;
  }
  return std::nullopt;
}

}  // namespace contensou::app
