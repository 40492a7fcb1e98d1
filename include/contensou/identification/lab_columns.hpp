// The columns of measured diagrams as labs name them (theory.md section 6): a quantity (vx, vy,
// omega, Fx, Fy, Mz, Fz, t) with its unit after an underscore (vx_mps, omega_rpm, Fx_kN), in
// brackets (vx [m/s], Mz (N m)), in a units row under the header, or under another name mapped
// to the quantity (--columns vx=Speed). Values in another unit are converted to SI, never taken
// as they are (units.hpp).
//
// Every other column is accounted for: a column the law does not read but the file records (a
// temperature, an inflation pressure, a camber, Mx) is kept as a recorded column, converted to
// SI where its unit is known; a column that looks like a misspelt channel (Fxx, Fx [kN]x) or
// holds a force that no channel reads (Force X [kN]) is an error, because its data would be lost
// without a word; the rest (an unnamed index, a column declared ignore=) is listed as not read.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contensou/identification/key_style.hpp"

namespace contensou {

enum class MeasuredQuantity { vx, vy, omega, Fx, Fy, Mz, Fz, t };
inline constexpr int kMeasuredQuantities = 8;

// The quantity's short name ("vx", "omega", "Fx", ...) and its column name in SI ("vx_mps",
// "omega_radps", "Fx_N", "Mz_Nm", "Fz_N", "t_s").
const char* quantity_name(MeasuredQuantity q);
const char* si_column_name(MeasuredQuantity q);

// The units a quantity's column may be in, as text for messages ("m/s, km/h, mm/s").
std::string accepted_units(MeasuredQuantity q);

struct LabColumn {
  int index = -1;             // column in the table (0-based); -1 = absent
  std::string header;         // the header cell as written
  std::string unit;           // the unit as written ("" if none given)
  std::string si_unit;        // the SI unit it is converted to ("m/s", "rad/s", "N", "N m", "s")
  double to_si = 1.0;         // value in SI = to_si * value in the file
  bool unit_assumed = false;  // no unit given anywhere: taken as SI
  bool renamed = false;       // found through a rename (--columns)

  bool present() const { return index >= 0; }
  // "'omega [rpm]' (column 4) in rpm, x 0.1047 to rad/s", for reports.
  std::string description() const;
};

// A column of the file that none of the law's quantities reads: a recorded variable (a
// temperature, a pressure, a camber angle, a channel the law does not use), read as numbers
// when every cell is one (measured_data.hpp).
struct RecordedColumn {
  int index = -1;       // column in the table (0-based)
  std::string header;   // the header cell as written
  std::string name;     // its name without the unit ("T" of "T [degC]")
  std::string unit;     // the unit as written ("" if none)
  std::string si_unit;  // the unit the values are in after conversion ("K"; the unit as
                        // written when this reader does not know it; "" if none)
  std::string kind;     // "temperature", "pressure", ... ("" when the unit is unknown or absent)
  double to_si = 1.0;   // value in si_unit = to_si * value + offset_si
  double offset_si = 0.0;
  bool declared = false;  // named by --columns extra=NAME
};

struct LabColumns {
  std::array<LabColumn, kMeasuredQuantities> column;
  bool units_row = false;                // the first row under the header holds units: not data
  std::vector<RecordedColumn> recorded;  // the file's other columns, kept
  std::vector<std::string> not_read;     // why each remaining column is not read, for reports

  const LabColumn& operator[](MeasuredQuantity q) const { return column[static_cast<int>(q)]; }
  // One line per column read under another name or unit than its SI name ("" if none):
  // what a report prints so that a conversion is never silent.
  std::vector<std::string> notes() const;
};

// Column renames: quantity short name ("vx", "omega", "Fx", ...) -> the header cell to read; or
// "extra" -> a column kept as a recorded variable whatever its name, "ignore" -> a column left
// out (listed as not read).
using ColumnRenames = std::vector<std::pair<std::string, std::string>>;

// Parses "vx=Speed,omega=Wheel rate [rpm],extra=Fx_raw" into renames; throws
// std::invalid_argument naming a part without '=' or an unknown quantity (with the list).
ColumnRenames parse_column_renames(const std::string& text,
                                   KeyStyle style = KeyStyle::command_line);

// Appends the rename quantity -> column (a header cell, any characters), or throws
// std::invalid_argument naming an unknown quantity.
void add_column_rename(ColumnRenames& renames, const std::string& quantity,
                       const std::string& column, KeyStyle style = KeyStyle::command_line);

struct LabHeader {
  const std::vector<std::string>& header;     // the header row's cells
  const std::vector<std::string>* first_row;  // the first row under it (nullptr: none)
  std::string file;                           // for messages
  int header_line = 0;                        // 1-based
  int first_row_line = 0;                     // 1-based
  KeyStyle style = KeyStyle::command_line;    // how messages name a rename
};

// Resolves the columns. Throws ParseError naming file, line and column for: a unit this reader
// does not convert (with the units it accepts), a unit of the wrong kind (Mz [N]), two columns
// for one quantity (the same name twice included), a units row that disagrees with the header,
// a rename naming no column, and a column no quantity reads that looks like a misspelt one or
// holds a force or a moment (Mx and My excepted: known channels the law does not use).
LabColumns resolve_lab_columns(const LabHeader& in, const ColumnRenames& renames = {});

// The columns of measured diagrams (measured_data.hpp), every check of the header in one place:
// resolve_lab_columns, and before it a header of numbers (no header row), after it a missing
// required column (vx, vy, omega; with "did you mean" the closest header cell), a column that
// looks like a misspelt known one while that one is absent (its data would be lost silently),
// and no measured channel (Fx, Fy, Mz). Throws ParseError naming the file and the header line.
LabColumns resolve_measured_columns(const LabHeader& in, const ColumnRenames& renames = {});

}  // namespace contensou
