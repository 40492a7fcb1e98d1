#include "contensou/identification/measured_data.hpp"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"

namespace contensou {

int MeasuredData::count(int channel) const {
  int n = 0;
  for (const MeasuredPoint& p : points) n += p.force[channel].has_value();
  return n;
}

MeasuredData read_measured_csv(const std::string& path) {
  const CsvTable t = read_csv(path);
  const char* required[3] = {"vx_mps", "vy_mps", "omega_radps"};
  int kin[3];
  for (int i = 0; i < 3; ++i) {
    kin[i] = t.column(required[i]);
    if (kin[i] < 0)
      throw ParseError(path, t.header_line, 1,
                       std::string("missing required column '") + required[i] + "'");
  }
  int ch[kChannels];
  bool any = false;
  for (int c = 0; c < kChannels; ++c) {
    ch[c] = t.column(kChannelColumns[c]);
    any = any || ch[c] >= 0;
  }
  if (!any)
    throw ParseError(path, t.header_line, 1, "no measured channel (need Fx_N, Fy_N or Mz_Nm)");
  const int fz = t.column("Fz_N"), ts = t.column("t_s");
  MeasuredData data;
  data.source = path;
  for (const CsvRow& row : t.rows) {
    MeasuredPoint p;
    p.line = row.line;
    double k[3];
    for (int i = 0; i < 3; ++i) {
      if (!row.cells[kin[i]])
        throw ParseError(path, row.line, row.columns[kin[i]],
                         std::string("empty ") + required[i] + " (kinematics must be given)");
      k[i] = *row.cells[kin[i]];
    }
    p.kinematics = {k[0], k[1], k[2]};
    for (int c = 0; c < kChannels; ++c)
      if (ch[c] >= 0) p.force[c] = row.cells[ch[c]];
    if (fz >= 0) {
      p.normal_load = row.cells[fz];
      if (p.normal_load && !(*p.normal_load > 0.0))
        throw ParseError(path, row.line, row.columns[fz],
                         "Fz_N = " + format_value(*p.normal_load) + " must be positive");
    }
    if (ts >= 0) p.time = row.cells[ts];
    data.points.push_back(p);
  }
  return data;
}

void write_measured_csv(const std::string& path, const MeasuredData& data,
                        const std::string& comment) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot open for writing");
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
  if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace contensou
