// Errors raised for bad input: each names the parameter and the offending value.
#pragma once

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace contensou {

// Thrown for an input outside its domain; what() names the parameter and the value.
class InvalidArgument : public std::invalid_argument {
 public:
  InvalidArgument(const std::string& parameter, const std::string& value, const std::string& rule)
      : std::invalid_argument(parameter + " = " + value + ": " + rule), parameter_(parameter) {}
  const std::string& parameter() const noexcept { return parameter_; }

 private:
  std::string parameter_;
};

// Thrown for a malformed input file; what() names the file, line and column.
class ParseError : public std::runtime_error {
 public:
  ParseError(const std::string& file, int line, int column, const std::string& message)
      : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ":" +
                                          std::to_string(column) + ": " + message
                                    : file + ": " + message),
        line_(line),
        column_(column) {}
  int line() const noexcept { return line_; }
  int column() const noexcept { return column_; }

 private:
  int line_;
  int column_;
};

// Validation helpers shared by every module: each throws InvalidArgument naming the value.

// Shortest text that reads back as the same double ("-0.1", "nan", "inf").
inline std::string format_value(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

inline void require_finite(const char* name, double v) {
  if (!std::isfinite(v)) throw InvalidArgument(name, format_value(v), "must be finite");
}

inline void require_positive(const char* name, double v) {
  if (!std::isfinite(v) || !(v > 0.0))
    throw InvalidArgument(name, format_value(v), "must be positive and finite");
}

inline void require_non_negative(const char* name, double v) {
  if (!std::isfinite(v) || !(v >= 0.0))
    throw InvalidArgument(name, format_value(v), "must be non-negative and finite");
}

}  // namespace contensou
