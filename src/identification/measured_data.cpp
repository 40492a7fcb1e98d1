#include "contensou/identification/measured_data.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/file_output.hpp"

namespace contensou {

int MeasuredData::count(int channel) const {
  int n = 0;
  for (const MeasuredPoint& p : points) n += p.force[channel].has_value();
  return n;
}

namespace {

// A cell of a column in SI (nullopt when empty or the column is absent).
std::optional<double> si_value(const CsvTable& t, const CsvRow& row, const LabColumn& c) {
  if (!c.present()) return std::nullopt;
  const std::optional<double> v = t.number(row, c.index);
  if (!v) return v;
  const double si = *v * c.to_si;
  if (!std::isfinite(si))
    throw t.cell_error(row.line, c.index, format_value(*v) + " " + c.unit + " overflows in SI");
  return si;
}

}  // namespace

MeasuredData measured_data_from_table(const CsvTable& t, const ColumnRenames& renames,
                                      KeyStyle style) {
  // Every check of the header (names, units, renames, required and misspelt columns) is
  // lab_columns'; the table is read here only for its cells' numbers.
  const std::vector<std::string> first_row =
      t.rows.empty() ? std::vector<std::string>{} : t.rows.front().cells.strings();
  const LabHeader header{t.header,      t.rows.empty() ? nullptr : &first_row,    t.file,
                         t.header_line, t.rows.empty() ? 0 : t.rows.front().line, style};
  const LabColumns cols = resolve_measured_columns(header, renames);
  MeasuredData data;
  data.source = t.file;
  data.column_notes = cols.notes();
  const LabColumn& fz = cols[MeasuredQuantity::Fz];
  for (std::size_t r = cols.units_row ? 1 : 0; r < t.rows.size(); ++r) {
    const CsvRow& row = t.rows[r];
    MeasuredPoint p;
    p.line = row.line;
    double k[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
      const LabColumn& c = cols.column[i];
      const std::optional<double> v = si_value(t, row, c);
      if (!v) throw t.cell_error(row.line, c.index, "empty (the kinematics must be given)");
      k[i] = *v;
    }
    p.kinematics = {k[0], k[1], k[2]};
    for (int c = 0; c < kChannels; ++c) p.force[c] = si_value(t, row, cols.column[3 + c]);
    p.normal_load = si_value(t, row, fz);
    if (p.normal_load && !(*p.normal_load > 0.0))
      throw t.cell_error(row.line, fz.index, format_value(*p.normal_load) + " must be positive");
    p.time = si_value(t, row, cols[MeasuredQuantity::t]);
    data.points.push_back(p);
  }
  if (data.points.empty())
    throw ParseError(t.file, t.header_line, 0,
                     cols.units_row ? "no data rows after the header and its units row"
                                    : "no data rows after the header");
  return data;
}

MeasuredData read_measured_csv(const std::string& path, const ColumnRenames& renames,
                               KeyStyle style) {
  return measured_data_from_table(read_csv(path), renames, style);
}

std::optional<LoadFromData> normal_load_from_data(const MeasuredData& data) {
  LoadFromData load;
  double sum = 0.0;
  for (const MeasuredPoint& p : data.points)
    if (p.normal_load) {
      sum += *p.normal_load;
      ++load.rows;
    }
  if (load.rows == 0) return std::nullopt;
  load.mean_n = sum / load.rows;
  for (const MeasuredPoint& p : data.points)
    if (p.normal_load)
      load.spread = std::max(load.spread, std::abs(*p.normal_load - load.mean_n) / load.mean_n);
  return load;
}

std::string LoadFromData::description() const {
  char buf[128];
  std::snprintf(buf, sizeof buf, "mean of the Fz column over %d rows, within +-%.2g %%", rows,
                100.0 * spread);
  return buf;
}

void write_measured_csv(const std::string& path, const MeasuredData& data,
                        const std::string& comment) {
  std::ostringstream out;
  if (!comment.empty()) {
    std::string line;
    for (char c : comment + "\n") {
      if (c == '\n') {
        out << "# " << line << "\n";
        line.clear();
      } else {
        line += c;
      }
    }
  }
  bool has_t = false, has_fz = false;
  for (const MeasuredPoint& p : data.points) {
    has_t = has_t || p.time.has_value();
    has_fz = has_fz || p.normal_load.has_value();
  }
  out << "vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm" << (has_fz ? ",Fz_N" : "")
      << (has_t ? ",t_s" : "") << "\n";
  char buf[64];
  auto cell = [&](const std::optional<double>& v) {
    if (!v) return std::string();
    std::snprintf(buf, sizeof buf, "%.10g", *v);
    return std::string(buf);
  };
  for (const MeasuredPoint& p : data.points) {
    out << cell(p.kinematics.vx) << "," << cell(p.kinematics.vy) << "," << cell(p.kinematics.omega);
    for (int c = 0; c < kChannels; ++c) out << "," << cell(p.force[c]);
    if (has_fz) out << "," << cell(p.normal_load);
    if (has_t) out << "," << cell(p.time);
    out << "\n";
  }
  write_file_atomically(path, out.str());  // whole or not at all
}

}  // namespace contensou
