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

const std::vector<std::string> kKnownColumns = {"vx_mps", "vy_mps", "omega_radps", "Fx_N",
                                                "Fy_N",   "Mz_Nm",  "Fz_N",        "t_s"};

// " (did you mean 'x'?)" for the header's column closest to name, or "".
std::string did_you_mean(const CsvTable& t, const std::string& name) {
  const std::string close = t.closest_column(name, kKnownColumns);
  return close.empty() ? "" : " (did you mean '" + close + "'?)";
}

bool header_looks_like_data(const CsvTable& t) {
  return std::all_of(t.header.begin(), t.header.end(), [](const std::string& h) {
    char* end = nullptr;
    std::strtod(h.c_str(), &end);
    return !h.empty() && *end == '\0';
  });
}

// A column of the file that is not read but looks like a misspelt known column (or the same
// quantity in another unit) while that column is absent: the data would be silently lost.
void refuse_near_misses(const CsvTable& t, const LabColumns& cols, KeyStyle style) {
  std::vector<std::string> read = kKnownColumns;  // not suggested: the columns read anyway
  for (const LabColumn& c : cols.column)
    if (c.present()) read.push_back(t.header[static_cast<std::size_t>(c.index)]);
  for (int q = 0; q < kMeasuredQuantities; ++q) {
    if (cols.column[q].present()) continue;
    const std::string k = si_column_name(static_cast<MeasuredQuantity>(q));
    const std::string close = t.closest_column(k, read);
    if (close.empty()) continue;
    const int col = t.column(close);
    throw ParseError(
        t.file, t.header_line, 0,
        "column '" + close + "' (" + std::to_string(col + 1) +
            ") is not a column this reader knows: did you mean '" + k +
            "'? (columns: vx_mps, vy_mps, omega_radps, Fx_N, Fy_N, Mz_Nm, Fz_N, t_s, "
            "or the same with a unit: 'vx [km/h]', omega_rpm; or map it: " +
            rename_option(quantity_name(static_cast<MeasuredQuantity>(q)), "NAME", style) + ")");
  }
}

}  // namespace

namespace {

// A missing required column, a near miss, no channel: refused naming the header line.
void require_columns(const CsvTable& t, const LabColumns& cols, KeyStyle style) {
  for (MeasuredQuantity q : {MeasuredQuantity::vx, MeasuredQuantity::vy, MeasuredQuantity::omega})
    if (!cols[q].present())
      throw ParseError(t.file, t.header_line, 0,
                       std::string("missing required column '") + si_column_name(q) + "'" +
                           did_you_mean(t, si_column_name(q)) + " (or give its name: " +
                           rename_option(quantity_name(q), "NAME", style) + ")");
  refuse_near_misses(t, cols, style);
  if (!cols[MeasuredQuantity::Fx].present() && !cols[MeasuredQuantity::Fy].present() &&
      !cols[MeasuredQuantity::Mz].present())
    throw ParseError(t.file, t.header_line, 0, "no measured channel (need Fx_N, Fy_N or Mz_Nm)");
}

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
  if (header_looks_like_data(t))
    throw ParseError(t.file, t.header_line, 0,
                     "the first row holds numbers, not column names: the file needs a header row "
                     "(vx_mps,vy_mps,omega_radps and at least one of Fx_N,Fy_N,Mz_Nm)");
  const LabHeader header{t.header,      t.rows.empty() ? nullptr : &t.rows.front().cells, t.file,
                         t.header_line, t.rows.empty() ? 0 : t.rows.front().line,         style};
  const LabColumns cols = resolve_lab_columns(header, renames);
  require_columns(t, cols, style);
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
