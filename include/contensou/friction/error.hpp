/// \file
/// Errors raised for bad input: each names the parameter and the offending value.
#pragma once

#include <charconv>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace contensou {

/// Thrown for an input outside its domain; what() names the parameter and the value.
class InvalidArgument : public std::invalid_argument {
 public:
  /// what() = "parameter = value: rule".
  InvalidArgument(const std::string& parameter, const std::string& value, const std::string& rule)
      : std::invalid_argument(parameter + " = " + value + ": " + rule), parameter_(parameter) {}
  /// The name of the bad parameter.
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

/// Thrown for a malformed input file; what() names the file, the line and, when known, the
/// column (a character position, or a numbered and named cell: "f.csv:11: column 'Mz_Nm' (6):").
class ParseError : public std::runtime_error {
 public:
  /// An error at `line` (1-based; 0: the whole file) and `column` (1-based; 0: unknown).
  ParseError(const std::string& file, int line, int column, const std::string& message)
      : std::runtime_error(location(file, line, column) + message), line_(line), column_(column) {}
  /// An error in cell number `column` (1-based) of a table, named by its header.
  static ParseError in_cell(const std::string& file, int line, int column,
                            const std::string& column_name, const std::string& message) {
    ParseError e(location(file, line, 0) + "column '" + column_name + "' (" +
                     std::to_string(column) + "): " + message,
                 line, column);
    return e;
  }
  /// The line of the error (1-based; 0: the whole file).
  int line() const noexcept { return line_; }
  /// The column of the error (1-based; 0: unknown).
  int column() const noexcept { return column_; }

 private:
  ParseError(const std::string& what, int line, int column)
      : std::runtime_error(what), line_(line), column_(column) {}
  static std::string location(const std::string& file, int line, int column) {
    if (line <= 0) return file + ": ";
    return file + ":" + std::to_string(line) + ":" +
           (column > 0 ? std::to_string(column) + ":" : "") + " ";
  }
  int line_;
  int column_;
};

/// Thrown by a long operation that stopped because its caller asked it to (its StopRequest
/// returned true: Ctrl-C in Python, say). Nothing of the operation's result is kept.
class Interrupted : public std::runtime_error {
 public:
  Interrupted() : std::runtime_error("interrupted: the caller asked the operation to stop") {}
};

/// A caller's request to stop a long operation (a fit, the closed loop, a stability map, a
/// landing, an exact law's build): polled between the operation's units of work (a solver
/// iteration, an integrator step, a sample, a cell), possibly from several threads at once, so
/// it must be thread-safe and cheap (an atomic flag); once it has returned true it should keep
/// doing so. The operation then throws Interrupted. Unset: the operation runs to its end.
using StopRequest = std::function<bool()>;

/// Throws Interrupted if `stop` is set and returns true.
inline void throw_if_stopped(const StopRequest& stop) {
  if (stop && stop()) throw Interrupted();
}

// Validation helpers shared by every module: each throws InvalidArgument naming the value.

/// Shortest text that reads back as the same double ("-0.1", "nan", "inf").
inline std::string format_value(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

/// Throws InvalidArgument naming `name` unless v is finite.
inline void require_finite(const char* name, double v) {
  if (!std::isfinite(v)) throw InvalidArgument(name, format_value(v), "must be finite");
}

/// Positive, finite and a normal double (a subnormal, below 2.2e-308, loses its precision and
/// turns into inf when divided into).
inline void require_positive(const char* name, double v) {
  if (!std::isfinite(v) || !(v > 0.0))
    throw InvalidArgument(name, format_value(v), "must be positive and finite");
  if (v < std::numeric_limits<double>::min())
    throw InvalidArgument(name, format_value(v),
                          "is below 2.2e-308, the smallest normal double: use other units");
}

/// Throws InvalidArgument naming `name` unless v is finite and >= 0.
inline void require_non_negative(const char* name, double v) {
  if (!std::isfinite(v) || !(v >= 0.0))
    throw InvalidArgument(name, format_value(v), "must be non-negative and finite");
}

}  // namespace contensou
