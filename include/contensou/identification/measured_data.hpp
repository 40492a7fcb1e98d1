// Measured friction diagrams: the CSV format of theory.md section 6.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/identification/lab_columns.hpp"

namespace contensou {

// The measured channels, in the order used everywhere: Fx [N], Fy [N], Mz [N m].
inline constexpr int kChannels = 3;
inline constexpr const char* kChannelColumns[kChannels] = {"Fx_N", "Fy_N", "Mz_Nm"};

struct MeasuredPoint {
  Kinematics<double> kinematics;
  std::array<std::optional<double>, kChannels> force;  // Fx, Fy, Mz; nullopt = not measured
  std::optional<double> normal_load;                   // Fz_N
  std::optional<double> time;                          // t_s
  int line = 0;                                        // line in the file (0 if synthetic)
  int source = 0;  // the file it came from: index into MeasuredData::sources
  // The recorded columns' values (MeasuredData::recorded, in order), in their SI unit; NaN
  // where the cell is empty.
  std::vector<double> recorded;
};

// A numeric column of the file that the law does not read (a temperature, an inflation
// pressure, a camber, Mx), kept for the residual analysis and listed in the report.
struct RecordedVariable {
  std::string name;                     // as in the header, without the unit ("T")
  std::string header;                   // the header cell ("T [degC]")
  int column = 0;                       // 1-based
  std::string unit;                     // as written ("degC"; "" if none)
  std::string si_unit;                  // of the values ("K"; the unit as written when unknown)
  std::string kind;                     // "temperature", ... ("" if the unit is unknown or absent)
  double to_si = 1.0, offset_si = 0.0;  // value in si_unit = to_si * value + offset_si
};

struct MeasuredData {
  std::string source;  // file name or description (of all the files, when several)
  // The files the points came from (one, or several fitted together): point.source indexes it.
  // Empty for data made in memory; source then names them.
  std::vector<std::string> sources;
  std::vector<MeasuredPoint> points;
  // How columns under other names or units were read ("omega_radps from 'omega [rpm]' ...,
  // x 0.1047 to rad/s"), for the report; empty for a file in the SI names.
  std::vector<std::string> column_notes;
  // The file's numeric columns the law does not read; each point's values in its `recorded`.
  std::vector<RecordedVariable> recorded;
  // The columns not read at all, with the reason ("'comment' (column 9): text").
  std::vector<std::string> columns_not_read;
  // The unit each channel's column is in, per file (sources' order; one entry for a single file;
  // empty for data made in memory): value in SI = to_si * value in the file.
  struct ChannelUnit {
    std::string unit = "";  // as the report writes it ("kN"; "" for SI)
    double to_si = 1.0;
  };
  std::vector<std::array<ChannelUnit, kChannels>> channel_units;
  // A channel's value as its file writes it, "1.84278 kN" ("" when the file's unit is SI).
  std::string in_file_unit(std::size_t point, int channel, double value_si) const;

  // Number of measured values of a channel.
  int count(int channel) const;
};

// Reads the CSV: header row, columns in any order (vx_mps, vy_mps, omega_radps required;
// Fx_N, Fy_N, Mz_Nm, Fz_N, t_s optional; every other numeric column kept as a recorded
// variable, text columns listed as not read), '#' comments, empty cell = not measured. Columns may
// carry other units, in the name (omega_rpm, "Fx [kN]") or in a units row under the header, and
// other names through `renames` (lab_columns.hpp); values are converted to SI. Throws ParseError
// naming file, line and column for a malformed or non-finite cell, a missing required column or an
// empty kinematic cell, a unit this reader does not convert, and a file without any channel.
MeasuredData read_measured_csv(const std::string& path, const ColumnRenames& renames = {},
                               KeyStyle style = KeyStyle::command_line);

// The same from a table already in memory (read_csv's, or a DataFrame's columns written as
// cells, with `rows_numbered` set): the same columns, units, renames and refusals.
MeasuredData measured_data_from_table(const CsvTable& table, const ColumnRenames& renames = {},
                                      KeyStyle style = KeyStyle::command_line);

// Several files fitted together (a test programme split over files, runs at several loads): the
// points of each in turn, each keeping its file (MeasuredPoint::source, into `sources`) and line;
// the recorded columns matched by their header (a column one file lacks is NaN in its rows); the
// column notes prefixed by their file. `loads` is empty, one load for every file, or one a
// file: a row without its own Fz value takes its file's load (each row is then fitted at its own
// load). Throws InvalidArgument for a loads list of another length or a load that is not
// positive.
MeasuredData combine_measured(std::vector<MeasuredData> files, const std::vector<double>& loads);

// Where a point came from, "file:line" ("point N" when it has no line).
std::string point_location(const MeasuredData& data, std::size_t point);

// The normal load the data carry in their Fz column: the mean over the rows that have it, the
// largest relative deviation from it and the number of rows; nullopt if no row has one.
struct LoadFromData {
  double mean_n = 0.0;
  double spread = 0.0;  // max |Fz - mean| / mean
  int rows = 0;
  std::string description() const;  // "mean of the Fz column over 112 rows, within +-0.8 %"
};
std::optional<LoadFromData> normal_load_from_data(const MeasuredData& data);

// Writes the same format (with a comment header); throws std::runtime_error if it cannot.
void write_measured_csv(const std::string& path, const MeasuredData& data,
                        const std::string& comment = "");

}  // namespace contensou
