#include "contensou/identification/measured_data.hpp"

#include <algorithm>
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
void refuse_near_misses(const CsvTable& t) {
  for (const std::string& k : kKnownColumns) {
    if (t.column(k) >= 0) continue;
    const std::string close = t.closest_column(k, kKnownColumns);
    if (close.empty()) continue;
    const int col = t.column(close);
    throw ParseError(t.file, t.header_line, 0,
                     "column '" + close + "' (" + std::to_string(col + 1) +
                         ") is not a column this reader knows: did you mean '" + k +
                         "'? (columns: vx_mps, vy_mps, omega_radps, Fx_N, Fy_N, Mz_Nm, Fz_N, t_s, "
                         "in SI units; rename it, or convert the unit)");
  }
}

}  // namespace

MeasuredData read_measured_csv(const std::string& path) {
  const CsvTable t = read_csv(path);
  const char* required[3] = {"vx_mps", "vy_mps", "omega_radps"};
  if (header_looks_like_data(t))
    throw ParseError(path, t.header_line, 0,
                     "the first row holds numbers, not column names: the file needs a header row "
                     "(vx_mps,vy_mps,omega_radps and at least one of Fx_N,Fy_N,Mz_Nm)");
  int kin[3];
  for (int i = 0; i < 3; ++i) {
    kin[i] = t.column(required[i]);
    if (kin[i] < 0)
      throw ParseError(path, t.header_line, 0,
                       std::string("missing required column '") + required[i] + "'" +
                           did_you_mean(t, required[i]));
  }
  refuse_near_misses(t);
  int ch[kChannels];
  bool any = false;
  for (int c = 0; c < kChannels; ++c) {
    ch[c] = t.column(kChannelColumns[c]);
    any = any || ch[c] >= 0;
  }
  if (!any)
    throw ParseError(path, t.header_line, 0, "no measured channel (need Fx_N, Fy_N or Mz_Nm)");
  const int fz = t.column("Fz_N"), ts = t.column("t_s");
  MeasuredData data;
  data.source = path;
  for (const CsvRow& row : t.rows) {
    MeasuredPoint p;
    p.line = row.line;
    double k[3];
    for (int i = 0; i < 3; ++i) {
      const std::optional<double> v = t.number(row, kin[i]);
      if (!v) throw t.cell_error(row.line, kin[i], "empty (the kinematics must be given)");
      k[i] = *v;
    }
    p.kinematics = {k[0], k[1], k[2]};
    for (int c = 0; c < kChannels; ++c)
      if (ch[c] >= 0) p.force[c] = t.number(row, ch[c]);
    if (fz >= 0) {
      p.normal_load = t.number(row, fz);
      if (p.normal_load && !(*p.normal_load > 0.0))
        throw t.cell_error(row.line, fz, format_value(*p.normal_load) + " must be positive");
    }
    if (ts >= 0) p.time = t.number(row, ts);
    data.points.push_back(p);
  }
  if (data.points.empty())
    throw ParseError(path, t.header_line, 0, "no data rows after the header");
  return data;
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
