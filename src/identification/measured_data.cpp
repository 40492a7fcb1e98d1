#include "contensou/identification/measured_data.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
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

// A missing value as labs and spreadsheets write it (case ignored): an empty cell, "-", "--",
// "n/a", "na", "nan", "null", "none", "#n/a".
bool is_missing_spelling(const std::string& cell) {
  std::string c;
  for (char ch : cell)
    if (ch != ' ' && ch != '\t')
      c += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  constexpr std::array<const char*, 10> kSpellings = {"",    "-",    "--",   "n/a",  "na",
                                                      "nan", "-nan", "null", "none", "#n/a"};
  return std::any_of(kSpellings.begin(), kSpellings.end(), [&](const char* m) { return c == m; });
}

// The missing cells of each column (its 0-based index): how they were spelt, and how often.
using MissingTally = std::map<int, std::map<std::string, int>>;

// A cell of a column in SI (nullopt when missing, counted in `tally`, or the column is absent).
std::optional<double> si_value(const CsvTable& t, const CsvRow& row, const LabColumn& c,
                               MissingTally& tally) {
  if (!c.present()) return std::nullopt;
  const std::string& text = row.cells[static_cast<std::size_t>(c.index)];
  if (is_missing_spelling(text)) {
    ++tally[c.index][text];
    return std::nullopt;
  }
  const std::optional<double> v = t.number(row, c.index);
  if (!v) return v;
  const double si = *v * c.to_si;
  if (!std::isfinite(si))
    throw t.cell_error(row.line, c.index, format_value(*v) + " " + c.unit + " overflows in SI");
  return si;
}

// "'Fx_N' (column 4): 3 of 514 rows (n/a 2, empty 1)" for each column with missing cells.
std::vector<std::string> missing_notes(const CsvTable& t, const MissingTally& tally, int rows) {
  std::vector<std::string> notes;
  for (const auto& [column, spellings] : tally) {
    int n = 0;
    std::string how;
    for (const auto& [text, count] : spellings) {
      n += count;
      how += (how.empty() ? "" : ", ") + (text.empty() ? std::string("empty") : text) + " " +
             std::to_string(count);
    }
    notes.push_back("'" + t.header[static_cast<std::size_t>(column)] + "' (column " +
                    std::to_string(column + 1) + "): " + std::to_string(n) + " of " +
                    std::to_string(rows) + " rows (" + how + ")");
  }
  return notes;
}

// A recorded column's cell: NaN when missing (counted) or not finite; nullopt when it is text.
std::optional<double> recorded_cell(const CsvTable& t, const CsvRow& row, int column,
                                    std::map<std::string, int>& missing) {
  const std::string& text = row.cells[static_cast<std::size_t>(column)];
  if (is_missing_spelling(text)) {
    ++missing[text];
    return std::nan("");
  }
  try {
    const std::optional<double> v = t.number(row, column);
    return v ? *v : std::nan("");
  } catch (const ParseError&) {
    char* end = nullptr;
    std::strtod(text.c_str(), &end);  // "inf", "-inf": a missing value, not text
    if (end == text.c_str() || *end != '\0') return std::nullopt;
    ++missing[text];
    return std::nan("");
  }
}

// Half a unit in the last digit a number's text writes: "153.20" 0.005, "1.5e3" 50, "12" 0.5.
double half_last_digit(const std::string& text) {
  const std::size_t e = text.find_first_of("eE");
  const std::string mantissa = text.substr(0, e);
  const std::size_t point = mantissa.find_first_of(".,");
  int decimals = 0;
  if (point != std::string::npos)
    for (std::size_t k = point + 1; k < mantissa.size(); ++k)
      decimals += std::isdigit(static_cast<unsigned char>(mantissa[k])) ? 1 : 0;
  const long exponent = e == std::string::npos ? 0 : std::strtol(text.c_str() + e + 1, nullptr, 10);
  return 0.5 * std::pow(10.0, static_cast<double>(std::clamp(exponent, -400L, 400L) - decimals));
}

// Every twin (a second column of a quantity beside its SI column) holds the read column's value
// in each row where both have one, to the digits written; else it is another channel: refused.
void check_twins(const CsvTable& t, const LabColumns& cols, std::size_t first) {
  for (const LabColumns::Twin& twin : cols.twins) {
    const LabColumn& c = cols.column[static_cast<std::size_t>(twin.quantity)];
    const char* name = quantity_name(static_cast<MeasuredQuantity>(twin.quantity));
    for (std::size_t r = first; r < t.rows.size(); ++r) {
      const CsvRow& row = t.rows[r];
      const std::string& a = row.cells[static_cast<std::size_t>(c.index)];
      const std::string& b = row.cells[static_cast<std::size_t>(twin.index)];
      if (is_missing_spelling(a) || is_missing_spelling(b)) continue;
      const double va = *t.number(row, c.index) * c.to_si;
      const double vb = *t.number(row, twin.index) * twin.to_si;
      const double tol = half_last_digit(a) * c.to_si + half_last_digit(b) * twin.to_si +
                         1e-12 * std::max(std::abs(va), std::abs(vb));
      if (std::abs(va - vb) <= tol) continue;
      const auto show = [](double v) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.8g", v);
        return std::string(buf);
      };
      throw t.cell_error(
          row.line, twin.index,
          std::string("is a second ") + name + " beside '" + c.header + "' (column " +
              std::to_string(c.index + 1) + "), but this row differs: " + b +
              (twin.unit.empty() ? "" : " " + twin.unit) + " here = " + show(vb) + " " + c.si_unit +
              ", " + show(va) + " " + c.si_unit + " in '" + c.header +
              "': it holds another channel. If it is " + name + ", " + twin.remedy);
    }
  }
}

// The recorded columns' values in SI, column by column, into the points: a column whose first
// non-empty cell is text is a text column (listed as not read); text further down a numeric
// column is an error at its cell.
void read_recorded(const CsvTable& t, const LabColumns& cols, std::size_t first, MeasuredData& data,
                   MissingTally& tally) {
  for (const RecordedColumn& c : cols.recorded) {
    const std::string where = "'" + c.header + "' (column " + std::to_string(c.index + 1) + ")";
    std::vector<double> values;
    values.reserve(data.points.size());
    bool any = false, text = false;
    std::map<std::string, int> missing;
    for (std::size_t r = first; r < t.rows.size() && !text; ++r) {
      const std::optional<double> v = recorded_cell(t, t.rows[r], c.index, missing);
      if (!v && !any) text = true;
      if (!v && any)
        throw t.cell_error(t.rows[r].line, c.index,
                           "not a number in a column of numbers: '" +
                               t.rows[r].cells[static_cast<std::size_t>(c.index)] + "'");
      if (!v) break;
      any = any || !std::isnan(*v);
      values.push_back(std::isnan(*v) ? *v : c.to_si * *v + c.offset_si);
    }
    if (text || !any) {
      data.columns_not_read.push_back(where + (text ? ": text" : ": empty"));
      continue;
    }
    if (!missing.empty()) tally[c.index] = missing;
    for (std::size_t k = 0; k < data.points.size(); ++k)
      data.points[k].recorded.push_back(values[k]);
    data.recorded.push_back(
        {c.name, c.header, c.index + 1, c.unit, c.si_unit, c.kind, c.to_si, c.offset_si});
  }
}

}  // namespace

MeasuredData measured_data_from_table(const CsvTable& t, const ColumnRenames& renames,
                                      KeyStyle style, bool channels_optional) {
  // Every check of the header (names, units, renames, required and misspelt columns) is
  // lab_columns'; the table is read here only for its cells' numbers.
  const std::vector<std::string> first_row =
      t.rows.empty() ? std::vector<std::string>{} : t.rows.front().cells.strings();
  const LabHeader header{t.header,         t.rows.empty() ? nullptr : &first_row,    t.file,
                         t.header_line,    t.rows.empty() ? 0 : t.rows.front().line, style,
                         channels_optional};
  const LabColumns cols = resolve_measured_columns(header, renames);
  MeasuredData data;
  data.source = t.file;
  data.column_notes = cols.notes();
  const LabColumn& fz = cols[MeasuredQuantity::Fz];
  MissingTally tally;
  for (std::size_t r = cols.units_row ? 1 : 0; r < t.rows.size(); ++r) {
    const CsvRow& row = t.rows[r];
    MeasuredPoint p;
    p.line = row.line;
    double k[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i) {
      const LabColumn& c = cols.column[i];
      const std::optional<double> v = si_value(t, row, c, tally);
      const std::string& text = row.cells[static_cast<std::size_t>(c.index)];
      if (!v)
        throw t.cell_error(
            row.line, c.index,
            (text.empty() ? std::string("empty") : "'" + text + "', a missing value") +
                " (the kinematics vx, vy, omega must be given in every row)");
      k[i] = *v;
    }
    p.kinematics = {k[0], k[1], k[2]};
    for (int c = 0; c < kChannels; ++c) p.force[c] = si_value(t, row, cols.column[3 + c], tally);
    p.normal_load = si_value(t, row, fz, tally);
    if (p.normal_load && !(*p.normal_load > 0.0))
      throw t.cell_error(row.line, fz.index, format_value(*p.normal_load) + " must be positive");
    p.time = si_value(t, row, cols[MeasuredQuantity::t], tally);
    data.points.push_back(p);
  }
  if (data.points.empty())
    throw ParseError(t.file, t.header_line, 0,
                     cols.units_row ? "no data rows after the header and its units row"
                                    : "no data rows after the header");
  data.columns_not_read = cols.not_read;
  std::array<MeasuredData::ChannelUnit, kChannels> units;
  for (int c = 0; c < kChannels; ++c) {
    const LabColumn& col = cols.column[3 + c];
    if (col.present() && col.to_si != 1.0) units[c] = {col.unit, col.to_si};
  }
  data.channel_units.push_back(units);
  check_twins(t, cols, cols.units_row ? 1 : 0);
  read_recorded(t, cols, cols.units_row ? 1 : 0, data, tally);
  data.missing_values = missing_notes(t, tally, static_cast<int>(data.points.size()));
  return data;
}

MeasuredData read_measured_csv(const std::string& path, const ColumnRenames& renames,
                               KeyStyle style, bool channels_optional) {
  return measured_data_from_table(read_csv(path), renames, style, channels_optional);
}

namespace {

// The index of a recorded column with this header in `into`, appended if new.
std::size_t recorded_index(MeasuredData& into, const RecordedVariable& v) {
  for (std::size_t k = 0; k < into.recorded.size(); ++k)
    if (into.recorded[k].header == v.header) return k;
  into.recorded.push_back(v);
  return into.recorded.size() - 1;
}

}  // namespace

MeasuredData combine_measured(std::vector<MeasuredData> files, const std::vector<double>& loads) {
  if (!loads.empty() && loads.size() != 1 && loads.size() != files.size())
    throw InvalidArgument(
        "normal load", std::to_string(loads.size()) + " values",
        "give one load for every file or one a file (" + std::to_string(files.size()) + " files)");
  for (double n : loads) require_positive("normal load", n);
  if (files.size() == 1 && loads.empty()) return std::move(files.front());
  if (files.size() == 1) {  // one file and one load: its rows without Fz take that load
    for (MeasuredPoint& p : files.front().points)
      if (!p.normal_load) p.normal_load = loads.front();
    return std::move(files.front());
  }
  MeasuredData all;
  for (std::size_t f = 0; f < files.size(); ++f) {
    MeasuredData& d = files[f];
    all.source += (f ? ", " : "") + d.source;
    all.sources.push_back(d.source);
    for (const std::string& n : d.column_notes) all.column_notes.push_back(d.source + ": " + n);
    for (const std::string& n : d.columns_not_read)
      all.columns_not_read.push_back(d.source + ": " + n);
    for (const std::string& n : d.missing_values) all.missing_values.push_back(d.source + ": " + n);
    all.channel_units.push_back(d.channel_units.empty()
                                    ? std::array<MeasuredData::ChannelUnit, kChannels>{}
                                    : d.channel_units.front());
    std::vector<std::size_t> slot;
    for (const RecordedVariable& v : d.recorded) slot.push_back(recorded_index(all, v));
    for (MeasuredPoint& p : d.points) {
      std::vector<double> values(all.recorded.size(), std::nan(""));
      for (std::size_t k = 0; k < slot.size(); ++k) values[slot[k]] = p.recorded[k];
      p.recorded = std::move(values);
      p.source = static_cast<int>(f);
      if (!p.normal_load && !loads.empty()) p.normal_load = loads.size() == 1 ? loads[0] : loads[f];
      all.points.push_back(std::move(p));
    }
  }
  for (MeasuredPoint& p : all.points) p.recorded.resize(all.recorded.size(), std::nan(""));
  return all;
}

std::string MeasuredData::in_file_unit(std::size_t point, int channel, double si) const {
  const std::size_t s = static_cast<std::size_t>(points[point].source);
  if (s >= channel_units.size() || channel_units[s][channel].unit.empty()) return "";
  const ChannelUnit& u = channel_units[s][channel];
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g %s", si / u.to_si, u.unit.c_str());
  return buf;
}

std::string point_location(const MeasuredData& data, std::size_t point) {
  const MeasuredPoint& p = data.points[point];
  const std::size_t s = static_cast<std::size_t>(p.source);
  const std::string file = s < data.sources.size() ? data.sources[s] : data.source;
  return p.line > 0 ? file + ":" + std::to_string(p.line) : "point " + std::to_string(point);
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
  load.min_n = load.max_n = load.mean_n;
  for (const MeasuredPoint& p : data.points)
    if (p.normal_load) {
      load.spread = std::max(load.spread, std::abs(*p.normal_load - load.mean_n) / load.mean_n);
      load.min_n = std::min(load.min_n, *p.normal_load);
      load.max_n = std::max(load.max_n, *p.normal_load);
    }
  return load;
}

std::string LoadFromData::description() const {
  char buf[160];
  if (spread > 0.05)
    std::snprintf(buf, sizeof buf,
                  "mean of the Fz column over %d rows, %.6g to %.6g N, each row at its own load",
                  rows, min_n, max_n);
  else
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
