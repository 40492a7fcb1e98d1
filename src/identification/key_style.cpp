#include "contensou/identification/key_style.hpp"

#include <algorithm>

namespace contensou {

std::string key_name(std::string_view key, KeyStyle style) {
  std::string name(key);
  if (style == KeyStyle::python) return name;
  std::replace(name.begin(), name.end(), '_', '-');
  return "--" + name;
}

std::string rename_option(const std::string& quantity, const std::string& column, KeyStyle style) {
  if (style == KeyStyle::python) return "columns={'" + quantity + "': '" + column + "'}";
  return "--columns " + quantity + "=" + column;
}

}  // namespace contensou
