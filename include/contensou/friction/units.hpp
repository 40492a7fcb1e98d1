/// \file
/// Units as labs write them in column names and units rows ("km/h", "kN", "N m", "°C", "bar"),
/// with their conversion to SI. One table for every reader: measured diagrams, pressure
/// profiles, in files and in DataFrames.
#pragma once

#include <string>

namespace contensou {

/// The physical quantity a column or a unit measures, with its SI unit.
enum class Dimension {
  speed,        ///< m/s
  rate,         ///< rad/s
  force,        ///< N
  moment,       ///< N m
  time,         ///< s
  temperature,  ///< K
  pressure,     ///< Pa
  angle,        ///< rad
  length,       ///< m
  ratio         ///< 1 (a fraction; "%" is 0.01)
};

/// A unit of the table (find_unit): its dimension and its affine map to SI.
struct Unit {
  Dimension dimension;  ///< what it measures
  double to_si;         ///< value in SI = to_si * value + offset_si
  double offset_si;     ///< 273.15 for degrees Celsius, 0 for every unit but temperatures
  const char* display;  ///< the unit as messages write it ("km/h")
};

/// The unit a text names, after normalisation (case, spaces, '.', '*' and middle dots ignored;
/// a degree sign read as "deg"), or nullptr if this table does not know it.
const Unit* find_unit(const std::string& text);

/// The SI unit of a dimension as reports write it ("m/s", "rad/s", "N", "N m", "s", "K", "Pa",
/// "rad", "m", "1"), and the dimension's name ("speed", "temperature", ...).
const char* si_unit_of(Dimension d);
/// The name of a dimension ("speed", "temperature", ...).
const char* dimension_name(Dimension d);

/// The units of a dimension this table knows, for messages ("m/s, km/h, mm/s").
std::string units_of(Dimension d);

/// A column header split into its name and its unit (split_name_and_unit).
struct NameAndUnit {
  std::string name;  ///< the header without its unit, trimmed ("pressure")
  std::string unit;  ///< the unit as written ("kPa"); "" when the header has none
};
/// Splits a column header into its name and its unit: "pressure [kPa]", "Mz (N m)" (bracketed,
/// at the end), or "pressure_kPa" (after the last '_' when that is a unit of this table); the
/// unit "" when there is none. Spaces around either part are trimmed.
NameAndUnit split_name_and_unit(const std::string& header);

}  // namespace contensou
