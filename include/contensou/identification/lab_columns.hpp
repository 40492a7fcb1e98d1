/// \file
/// The columns of measured diagrams as labs name them (theory.md section 6): a quantity (vx, vy,
/// omega, Fx, Fy, Mz, Fz, t) with its unit after an underscore (vx_mps, omega_rpm, Fx_kN), in
/// brackets (vx [m/s], Mz (N m)), in a units row under the header, or under another name mapped
/// to the quantity (--columns vx=Speed). Values in another unit are converted to SI, never taken
/// as they are (units.hpp).
///
/// Every other column is accounted for: a column the law does not read but the file records (a
/// temperature, an inflation pressure, a camber, Mx) is kept as a recorded column, converted to
/// SI where its unit is known; a column that looks like a misspelt channel (Fxx, Fx [kN]x) or
/// holds a force that no channel reads (Force X [kN]) is an error, because its data would be lost
/// without a word; the rest (an unnamed index, a column declared ignore=) is listed as not read.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "contensou/identification/key_style.hpp"

namespace contensou {

/// A quantity a measured diagram's column may hold; its value indexes LabColumns::column.
enum class MeasuredQuantity {
  vx,     ///< sliding velocity along x [m/s] (required)
  vy,     ///< sliding velocity along y [m/s] (required)
  omega,  ///< spin about z [rad/s] (required)
  Fx,     ///< measured force along x [N]
  Fy,     ///< measured force along y [N]
  Mz,     ///< measured torque about z [N m]
  Fz,     ///< normal load [N]
  t       ///< time stamp [s]
};
/// The number of MeasuredQuantity values.
inline constexpr int kMeasuredQuantities = 8;

/// The quantity's short name, as renames write it: "vx", "vy", "omega", "Fx", "Fy", "Mz", "Fz",
/// "t".
const char* quantity_name(MeasuredQuantity q);
/// The quantity's column name in SI: "vx_mps", "vy_mps", "omega_radps", "Fx_N", "Fy_N", "Mz_Nm",
/// "Fz_N", "t_s".
const char* si_column_name(MeasuredQuantity q);

/// The units a quantity's column may be in, as text for messages ("m/s, km/h, mm/s").
std::string accepted_units(MeasuredQuantity q);

/// The column of the table a quantity is read from, with its unit and its conversion to SI.
struct LabColumn {
  int index = -1;             ///< column in the table (0-based); -1 = absent
  std::string header;         ///< the header cell as written (trimmed)
  std::string unit;           ///< the unit as written ("" if none given)
  std::string si_unit;        ///< the SI unit it is converted to ("m/s", "rad/s", "N", "N m", "s")
  double to_si = 1.0;         ///< value in SI = to_si * value in the file
  bool unit_assumed = false;  ///< no unit given anywhere: taken as SI
  bool renamed = false;       ///< found through a rename (--columns)

  /// Whether the table has the column (index >= 0).
  bool present() const { return index >= 0; }
  /// "'omega [rpm]' (column 4) in rpm, x 0.1047 to rad/s", for reports ("... in rad/s" when no
  /// conversion is needed, "..., no unit given: read as rad/s" when the unit was assumed).
  std::string description() const;
};

/// A column of the file that none of the law's quantities reads: a recorded variable (a
/// temperature, a pressure, a camber angle, a channel the law does not use), read as numbers by
/// measured_data.hpp (a column whose first non-empty cell is text is listed as not read).
struct RecordedColumn {
  int index = -1;      ///< column in the table (0-based)
  std::string header;  ///< the header cell as written (trimmed)
  std::string name;    ///< its name without the unit ("T" of "T [degC]")
  std::string unit;    ///< the unit as written, in the header or the units row ("" if none)
  /// The unit the values are in after conversion ("K"; the unit as written when this reader
  /// does not know it; "" if none).
  std::string si_unit;
  std::string kind;    ///< "temperature", "pressure", ... ("" when the unit is unknown or absent)
  double to_si = 1.0;  ///< value in si_unit = to_si * value + offset_si
  double offset_si = 0.0;  ///< the offset of that map (273.15 for degC, 0 for most units)
  bool declared = false;   ///< declared by an extra= rename (--columns extra=NAME)
};

/// The columns of a table resolved to the quantities (resolve_lab_columns), and what became of
/// the others.
struct LabColumns {
  std::array<LabColumn, kMeasuredQuantities> column;  ///< one a quantity, in MeasuredQuantity order
  bool units_row = false;                ///< the first row under the header holds units: not data
  std::vector<RecordedColumn> recorded;  ///< the file's other columns, kept
  std::vector<std::string> not_read;     ///< why each remaining column is not read, for reports
  /// A second column of a quantity beside the one read under its SI name, in a unit of that
  /// quantity ("omega [rpm]" beside omega_radps, "Fx [kN]" beside Fx_N): not read, but every
  /// row's value must equal the read column's to the digits written (measured_data.hpp checks
  /// them), else the file is refused: the column holds another channel.
  struct Twin {
    int quantity = 0;    ///< MeasuredQuantity, as an index of column
    int index = -1;      ///< the twin's column in the table (0-based)
    std::string header;  ///< as written (trimmed)
    std::string unit;    ///< as written ("" for SI)
    double to_si = 1.0;  ///< value in SI = to_si * value in the file
    std::string remedy;  ///< how to say what it is ("map it (--columns Fx='Fx [N]'); else ...")
  };
  std::vector<Twin> twins;  ///< every such column, checked row by row when the rows are read

  /// The column of quantity `q`.
  const LabColumn& operator[](MeasuredQuantity q) const { return column[static_cast<int>(q)]; }
  /// One line per column read under another name or unit than its SI name ("omega_radps from
  /// 'omega [rpm]' (column 4) in rpm, x 0.1047 to rad/s"; empty if none): what a report prints
  /// so that a conversion is never silent.
  std::vector<std::string> notes() const;
};

/// Column renames: quantity short name ("vx", "omega", "Fx", ...) mapped to the header cell to
/// read; or "extra" mapped to a column kept as a recorded variable whatever its name, "ignore"
/// to a column left out (listed as not read).
using ColumnRenames = std::vector<std::pair<std::string, std::string>>;

/// Parses "vx=Speed,omega=Wheel rate [rpm],extra=Fx_raw" into renames (empty parts skipped,
/// names trimmed); throws std::invalid_argument naming a part without '=' or an unknown
/// quantity (with the list).
ColumnRenames parse_column_renames(const std::string& text,
                                   KeyStyle style = KeyStyle::command_line);

/// Appends the rename quantity to column (a header cell, any characters; both trimmed; the
/// quantity's case ignored), or throws std::invalid_argument naming an unknown quantity.
void add_column_rename(ColumnRenames& renames, const std::string& quantity,
                       const std::string& column, KeyStyle style = KeyStyle::command_line);

/// The header of a table as resolve_lab_columns reads it, with what its messages name.
struct LabHeader {
  const std::vector<std::string>& header;     ///< the header row's cells
  const std::vector<std::string>* first_row;  ///< the first row under it (nullptr: none)
  std::string file;                           ///< for messages
  int header_line = 0;                        ///< 1-based
  int first_row_line = 0;                     ///< 1-based
  KeyStyle style = KeyStyle::command_line;    ///< how messages name a rename
  bool channels_optional = false;  ///< a table without Fx, Fy, Mz is read (rows to predict)
};

/// Resolves the columns. Throws ParseError naming file, line and column for: a unit this reader
/// does not convert (with the units it accepts), a unit of the wrong kind (Mz [N]), two columns
/// for one quantity (the same name twice included; but when exactly one of two has the SI name,
/// that one is read and the other, in a unit of the quantity, is a Twin whose values the rows
/// must confirm; one in a unit this reader does not know, Fx_raw, is refused until --columns
/// says what it is), a units row that disagrees with the
/// header, a rename naming no column, and a column no quantity reads that looks like a misspelt
/// one or holds a force or a moment (Mx and My excepted: known channels the law does not use).
LabColumns resolve_lab_columns(const LabHeader& in, const ColumnRenames& renames = {});

/// The columns of measured diagrams (measured_data.hpp), every check of the header in one place:
/// resolve_lab_columns, and before it a header of numbers (no header row), after it a missing
/// required column (vx, vy, omega; with "did you mean" the closest header cell), a column that
/// looks like a misspelt known one while that one is absent (its data would be lost silently),
/// and no measured channel (Fx, Fy, Mz). Throws ParseError naming the file and the header line.
LabColumns resolve_measured_columns(const LabHeader& in, const ColumnRenames& renames = {});

}  // namespace contensou
