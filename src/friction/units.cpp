#include "contensou/friction/units.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <utility>
#include <vector>

namespace contensou {

namespace {

struct UnitSpec {
  std::vector<const char*> spellings;  // normalised (see normalise)
  Unit unit;
};

constexpr double kDegree = M_PI / 180.0;

const std::vector<UnitSpec>& unit_table() {
  static const std::vector<UnitSpec> units = {
      {{"m/s", "mps", "ms-1", "ms^-1"}, {Dimension::speed, 1.0, 0.0, "m/s"}},
      {{"km/h", "kmh", "kph", "kmph"}, {Dimension::speed, 1.0 / 3.6, 0.0, "km/h"}},
      {{"mm/s", "mmps"}, {Dimension::speed, 1e-3, 0.0, "mm/s"}},
      {{"rad/s", "radps", "rads-1", "rad/sec"}, {Dimension::rate, 1.0, 0.0, "rad/s"}},
      {{"deg/s", "degps", "dps", "deg/sec"}, {Dimension::rate, kDegree, 0.0, "deg/s"}},
      {{"rpm", "1/min", "rev/min", "u/min", "r/min"},
       {Dimension::rate, 2.0 * M_PI / 60.0, 0.0, "rpm"}},
      {{"n"}, {Dimension::force, 1.0, 0.0, "N"}},
      {{"kn"}, {Dimension::force, 1e3, 0.0, "kN"}},
      {{"nm"}, {Dimension::moment, 1.0, 0.0, "N m"}},
      {{"knm"}, {Dimension::moment, 1e3, 0.0, "kN m"}},
      {{"nmm"}, {Dimension::moment, 1e-3, 0.0, "N mm"}},
      {{"s", "sec"}, {Dimension::time, 1.0, 0.0, "s"}},
      {{"ms"}, {Dimension::time, 1e-3, 0.0, "ms"}},
      {{"min"}, {Dimension::time, 60.0, 0.0, "min"}},
      {{"h"}, {Dimension::time, 3600.0, 0.0, "h"}},
      {{"k", "kelvin"}, {Dimension::temperature, 1.0, 0.0, "K"}},
      {{"degc", "celsius"}, {Dimension::temperature, 1.0, 273.15, "degC"}},
      {{"degf", "fahrenheit"}, {Dimension::temperature, 5.0 / 9.0, 273.15 - 160.0 / 9.0, "degF"}},
      {{"pa"}, {Dimension::pressure, 1.0, 0.0, "Pa"}},
      {{"hpa", "mbar"}, {Dimension::pressure, 1e2, 0.0, "hPa"}},
      {{"kpa"}, {Dimension::pressure, 1e3, 0.0, "kPa"}},
      {{"mpa"}, {Dimension::pressure, 1e6, 0.0, "MPa"}},
      {{"bar"}, {Dimension::pressure, 1e5, 0.0, "bar"}},
      {{"psi"}, {Dimension::pressure, 6894.757293168361, 0.0, "psi"}},
      {{"rad"}, {Dimension::angle, 1.0, 0.0, "rad"}},
      {{"mrad"}, {Dimension::angle, 1e-3, 0.0, "mrad"}},
      {{"deg", "degree", "degrees"}, {Dimension::angle, kDegree, 0.0, "deg"}},
      {{"m"}, {Dimension::length, 1.0, 0.0, "m"}},
      {{"mm"}, {Dimension::length, 1e-3, 0.0, "mm"}},
      {{"cm"}, {Dimension::length, 1e-2, 0.0, "cm"}},
      {{"-", "1"}, {Dimension::ratio, 1.0, 0.0, "1"}},
      {{"%"}, {Dimension::ratio, 1e-2, 0.0, "%"}}};
  return units;
}

// Lower case; spaces, '.', '*', U+00B7 middle dot and U+22C5 dot operator dropped; U+00B0, the
// degree sign, read as "deg".
std::string normalise(const std::string& text) {
  std::string u;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == 0xC2 && i + 1 < text.size()) {
      const unsigned char d = static_cast<unsigned char>(text[i + 1]);
      if (d == 0xB7 || d == 0xB0) {
        if (d == 0xB0) u += "deg";
        ++i;
        continue;
      }
    }
    if (c == 0xE2 && i + 2 < text.size() && static_cast<unsigned char>(text[i + 1]) == 0x8B &&
        static_cast<unsigned char>(text[i + 2]) == 0x85) {
      i += 2;
      continue;
    }
    if (c == ' ' || c == '.' || c == '*' || c == '\t') continue;
    u += static_cast<char>(std::tolower(c));
  }
  return u;
}

}  // namespace

const Unit* find_unit(const std::string& text) {
  const std::string u = normalise(text);
  for (const UnitSpec& spec : unit_table())
    for (const char* s : spec.spellings)
      if (u == s) return &spec.unit;
  return nullptr;
}

const char* si_unit_of(Dimension d) {
  static constexpr std::array<const char*, 10> kSi = {"m/s", "rad/s", "N",   "N m", "s",
                                                      "K",   "Pa",    "rad", "m",   "1"};
  return kSi[static_cast<std::size_t>(d)];
}

const char* dimension_name(Dimension d) {
  static constexpr std::array<const char*, 10> kNames = {
      "speed",       "angular rate", "force", "moment", "time",
      "temperature", "pressure",     "angle", "length", "ratio"};
  return kNames[static_cast<std::size_t>(d)];
}

std::string units_of(Dimension d) {
  std::string s;
  for (const UnitSpec& spec : unit_table())
    if (spec.unit.dimension == d) s += (s.empty() ? "" : ", ") + std::string(spec.unit.display);
  return s;
}

NameAndUnit split_name_and_unit(const std::string& header) {
  auto trim = [](const std::string& t) {
    const auto b = t.find_first_not_of(" \t"), e = t.find_last_not_of(" \t");
    return b == std::string::npos ? std::string() : t.substr(b, e - b + 1);
  };
  const std::string h = trim(header);
  for (const auto& [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}}) {
    const auto b = h.rfind(open);
    if (b != std::string::npos && b > 0 && h.back() == close)
      return {trim(h.substr(0, b)), trim(h.substr(b + 1, h.size() - b - 2))};
  }
  const auto u = h.rfind('_');
  if (u != std::string::npos && u > 0 && u + 1 < h.size() && find_unit(h.substr(u + 1)))
    return {h.substr(0, u), h.substr(u + 1)};
  return {h, ""};
}

}  // namespace contensou
