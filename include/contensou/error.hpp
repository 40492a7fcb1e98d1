// Errors raised for bad input: each names the parameter and the offending value.
#pragma once

#include <cmath>
#include <sstream>
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
      : std::runtime_error(file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " +
                           message),
        line_(line),
        column_(column) {}
  int line() const noexcept { return line_; }
  int column() const noexcept { return column_; }

 private:
  int line_;
  int column_;
};

namespace detail {

inline std::string format_value(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
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

}  // namespace detail
}  // namespace contensou
