/// \file
/// Measured friction diagrams: the CSV format of theory.md section 6.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/identification/lab_columns.hpp"

namespace contensou {

/// The number of measured channels, in the order used everywhere: Fx [N], Fy [N], Mz [N m].
inline constexpr int kChannels = 3;
/// The channels' column names in SI, in channel order.
inline constexpr const char* kChannelColumns[kChannels] = {"Fx_N", "Fy_N", "Mz_Nm"};

/// One row of a measured diagram, in SI.
struct MeasuredPoint {
  Kinematics<double> kinematics;  ///< vx, vy [m/s] and omega [rad/s]
  /// Fx [N], Fy [N], Mz [N m]; nullopt = not measured.
  std::array<std::optional<double>, kChannels> force;
  std::optional<double> normal_load;  ///< Fz [N] (positive), if the row has one
  std::optional<double> time;         ///< t [s], if the row has one
  /// Line in the file (for a table in memory with rows_numbered, the row number; 0 if
  /// synthetic).
  int line = 0;
  int source = 0;  ///< the file it came from: index into MeasuredData::sources (0 for one file)
  /// The recorded columns' values (MeasuredData::recorded, in order), in their SI unit; NaN
  /// where the cell is empty.
  std::vector<double> recorded;
};

/// A numeric column of the file that the law does not read (a temperature, an inflation
/// pressure, a camber, Mx), kept for the residual analysis and listed in the report.
struct RecordedVariable {
  std::string name;     ///< as in the header, without the unit ("T")
  std::string header;   ///< the header cell ("T [degC]")
  int column = 0;       ///< 1-based
  std::string unit;     ///< as written ("degC"; "" if none)
  std::string si_unit;  ///< of the values ("K"; the unit as written when unknown)
  std::string kind;     ///< "temperature", ... ("" if the unit is unknown or absent)
  /// The factor of the map to si_unit: value in si_unit = to_si * value + offset_si.
  double to_si = 1.0, offset_si = 0.0;  ///< the offset of that map (273.15 for degC)
};

/// A measured diagram: its points in SI, where they came from and how its columns were read.
struct MeasuredData {
  std::string source;  ///< file name or description (of all the files, when several)
  /// The files the points came from when several are fitted together (combine_measured):
  /// point.source indexes it. Empty for a single file or data made in memory; source then names
  /// the data.
  std::vector<std::string> sources;
  std::vector<MeasuredPoint> points;  ///< the rows, in the order of the file (files, in turn)
  /// How columns under other names or units were read ("omega_radps from 'omega [rpm]' ...,
  /// x 0.1047 to rad/s"), for the report; empty for a file in the SI names.
  std::vector<std::string> column_notes;
  /// The file's numeric columns the law does not read; each point's values in its `recorded`.
  std::vector<RecordedVariable> recorded;
  /// The columns not read at all, with the reason ("'comment' (column 9): text").
  std::vector<std::string> columns_not_read;
  /// The missing cells of each column read, counted with how the file spells them (an empty
  /// cell, "n/a", "NA", "-", "nan", "null", "#N/A"; case ignored): "'Fx_N' (column 4): 3 of 514
  /// rows (n/a 2, NA 1)". A force or a recorded value missing is not measured in that row; the
  /// kinematics must be given in every row.
  std::vector<std::string> missing_values;
  /// The unit a channel's column is in: value in SI = to_si * value in the file.
  struct ChannelUnit {
    std::string unit = "";  ///< as the file writes it ("kN"; "" for SI)
    double to_si = 1.0;     ///< value in SI = to_si * value in the file
  };
  /// The unit each channel's column is in, per file (sources' order; one entry for a single
  /// file or table; empty for data built in code, such as simulated diagrams).
  std::vector<std::array<ChannelUnit, kChannels>> channel_units;
  /// A channel's value `value_si` at `point` (an index into points), as its file writes it:
  /// "1.84278 kN" ("" when the file's unit is SI, or when channel_units has no entry for the
  /// point's file).
  std::string in_file_unit(std::size_t point, int channel, double value_si) const;

  /// Number of measured values of a channel (0 Fx, 1 Fy, 2 Mz).
  int count(int channel) const;
};

/// Reads the CSV: header row, columns in any order (vx_mps, vy_mps, omega_radps required;
/// Fx_N, Fy_N, Mz_Nm, Fz_N, t_s optional; every other numeric column kept as a recorded
/// variable, text columns listed as not read), '#' comments, an empty cell or another spelling
/// of a missing value (MeasuredData::missing_values) = not measured. Columns may
/// carry other units, in the name (omega_rpm, "Fx [kN]") or in a units row under the header, and
/// other names through `renames` (lab_columns.hpp); values are converted to SI. Throws ParseError
/// naming file, line and column for a missing or unreadable file (read_csv), a malformed or
/// non-finite cell, a missing required column or an empty kinematic cell, an Fz value that is
/// not positive, a unit this reader does not convert, text in a numeric recorded column, a
/// second column of a quantity whose values differ from the read one's (LabColumns::Twin), a file
/// without data rows and a file without any channel (unless `channels_optional`: rows to predict,
/// whose forces are not needed).
MeasuredData read_measured_csv(const std::string& path, const ColumnRenames& renames = {},
                               KeyStyle style = KeyStyle::command_line,
                               bool channels_optional = false);

/// The same from a table already in memory (read_csv's, or a DataFrame's columns written as
/// cells, with `rows_numbered` set): the same columns, units, renames and refusals.
MeasuredData measured_data_from_table(const CsvTable& table, const ColumnRenames& renames = {},
                                      KeyStyle style = KeyStyle::command_line,
                                      bool channels_optional = false);

/// Several files fitted together (a test programme split over files, runs at several loads): the
/// points of each in turn, each keeping its file (MeasuredPoint::source, into `sources`) and line;
/// the recorded columns matched by their header (a column one file lacks is NaN in its rows); the
/// column notes prefixed by their file. `loads` is empty, one load for every file, or one a
/// file: a row without its own Fz value takes its file's load (each row is then fitted at its own
/// load). A single file keeps its source and columns as they are (its rows take the one load
/// given, if any). Throws InvalidArgument for a loads list of another length or a load that is not
/// positive and finite.
MeasuredData combine_measured(std::vector<MeasuredData> files, const std::vector<double>& loads);

/// Where a point came from, "file:line" ("point N" when it has no line).
std::string point_location(const MeasuredData& data, std::size_t point);

/// The normal load the data carry in their Fz column: the mean over the rows that have it, the
/// largest relative deviation from it and the number of rows (normal_load_from_data).
struct LoadFromData {
  double mean_n = 0.0;  ///< mean Fz over the rows that have one [N]
  double spread = 0.0;  ///< max |Fz - mean| / mean over those rows
  double min_n = 0.0;   ///< the smallest Fz [N]
  double max_n = 0.0;   ///< the largest Fz [N]
  int rows = 0;         ///< the number of rows with an Fz value
  /// "mean of the Fz column over 112 rows, within +-0.8 %" (one load) or "mean of the Fz column
  /// over 1089 rows, 2000 to 6000 N, each row at its own load" (a spread above 5 %), for the
  /// report.
  std::string description() const;
};
/// The load of the data's Fz column (LoadFromData); nullopt if no row has one.
std::optional<LoadFromData> normal_load_from_data(const MeasuredData& data);

/// Writes the same format: `comment` as '#' lines, then vx_mps, vy_mps, omega_radps, Fx_N, Fy_N,
/// Mz_Nm, and Fz_N and t_s when a row has them, values to 10 significant digits, empty cells for
/// channels not measured (recorded columns are not written). Written whole or not at all
/// (write_file_atomically); throws std::runtime_error if it cannot.
void write_measured_csv(const std::string& path, const MeasuredData& data,
                        const std::string& comment = "");

}  // namespace contensou
