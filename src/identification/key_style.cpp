#include "contensou/identification/key_style.hpp"

#include <algorithm>
#include <cctype>

namespace contensou {

std::string key_name(std::string_view key, KeyStyle style) {
  std::string name(key);
  if (style == KeyStyle::python) return name;
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

std::string rename_option(const std::string& quantity, const std::string& column, KeyStyle style) {
  if (style == KeyStyle::python) return "columns={'" + quantity + "': '" + column + "'}";
  // A column name with spaces or shell characters in single quotes, as a shell would need it.
  const bool plain = std::all_of(column.begin(), column.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
  if (plain || column == "NAME") return "--columns " + quantity + "=" + column;
  std::string quoted = "'";
  for (char c : column) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return "--columns " + quantity + "=" + quoted + "'";
}

}  // namespace contensou
