#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <numeric>
#include <optional>

#include "contensou/identification/sweeps.hpp"
#include "gnuplot.hpp"

namespace contensou::app {
namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

namespace {

// The points with a positive sliding-spin ratio, in increasing psi.
std::vector<std::size_t> points_by_psi(const std::vector<double>& psi) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < psi.size(); ++i)
    if (std::isfinite(psi[i]) && psi[i] > 0.0) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return psi[a] < psi[b]; });
  return order;
}

// A cell of the pictures' CSV files: the value, or NaN where the channel was not measured.
std::string cell(std::optional<double> v) {
  return v ? fmt("%.10g", *v) : std::string("NaN");
}

const char* const kAxisLabel[kChannels] = {"Fx [N]", "Fy [N]", "Mz [N m]"};

}  // namespace

bool write_loop_plots(const OutputDir& dir, const MeasuredData& data,
                      const ClosedLoopReport& loop) {
  std::string gp =
      "set terminal pngcairo size 900,900 font ',10'\nset datafile separator ','\n"
      "set datafile columnheaders\nset datafile missing 'NaN'\n";
  int k = 0;
  for (const LoopStep& st : loop.steps) {
    // The step's own rows (a large file's steps are decided on a sample of it).
    const std::vector<double>& psi = st.fit_before.psi;
    const std::vector<std::size_t> order = points_by_psi(psi);
    const std::string csv = "loop_step_" + std::to_string(++k) + ".csv";
    std::string text = "psi";  // then the residual before and after the step, per channel
    for (int c = 0; c < kChannels; ++c)
      text += std::string(",before_") + kChannelColumns[c] + ",after_" + kChannelColumns[c];
    text += "\n";
    for (std::size_t i : order) {
      if (i >= st.fit_before.residual.size() || i >= st.fit_after.residual.size()) continue;
      text += fmt("%.10g", psi[i]);
      for (int c = 0; c < kChannels; ++c)
        text += "," + cell(st.fit_before.residual[i][c]) + "," + cell(st.fit_after.residual[i][c]);
      text += "\n";
    }
    dir.write(csv, text);
    gp += "set output 'loop_step_" + std::to_string(k) + ".png'\n";
    gp += "set multiplot layout 3,1 title 'step " + std::to_string(k) + ": " + st.effect +
          (st.detail.empty() ? "" : " (" + st.detail + ")") + ", " +
          (st.removed    ? "removed"
           : st.accepted ? "accepted"
                         : "rejected") +
          "' noenhanced\n";  // effect names hold underscores, not subscripts
    gp += "set logscale x\nset format x '10^{%L}'\nset grid\nset key top right opaque box\n";
    gp += "set xlabel 'psi = v / (omega R) [-]'\n";
    for (int c = 0; c < kChannels; ++c) {
      if (data.count(c) == 0) continue;
      const std::string ch = kChannelColumns[c];
      gp += "set ylabel 'residual " + std::string(kAxisLabel[c]) + "'\n";
      gp +=
          "plot '" + csv + "' using \"psi\":\"before_" + ch +
          "\" with points pt 6 ps 0.7 lc rgb '#888888' title 'before', '' using \"psi\":\"after_" +
          ch + "\" with points pt 7 ps 0.6 lc rgb '#d62728' title 'after'\n";
    }
    gp += "unset multiplot\nunset xlabel\n";
  }
  if (k == 0) return true;
  return run_gnuplot(dir, "loop", gp);
}

namespace {

std::string number_or_inf(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt("%.10g", v);
}

// A CSV text cell, quoted (labels hold commas).
std::string quoted(const std::string& s) {
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

// Whether a channel is in another unit than SI in some file (fit.csv then carries both).
bool has_file_unit(const MeasuredData& data, int c) {
  for (const auto& units : data.channel_units)
    if (!units[c].unit.empty()) return true;
  return false;
}

// For each point of the data given, its index in the fitted data (-1: left out entirely).
std::vector<int> fitted_index(const PlotInput& in) {
  std::vector<int> j(in.data.points.size(), -1);
  for (std::size_t k = 0; k < in.origin.size(); ++k)
    if (in.origin[k] >= 0 && static_cast<std::size_t>(in.origin[k]) < j.size())
      j[static_cast<std::size_t>(in.origin[k])] = static_cast<int>(k);
  return j;
}

std::string fit_csv_header(const MeasuredData& data) {
  std::string h = "file,line,sweep,Fz_N,psi,upsilon";
  for (int c = 0; c < kChannels; ++c) {
    const std::string ch = kChannelColumns[c];
    h += ",measured_" + ch + ",fit_" + ch + ",residual_" + ch + ",outlier_" + ch;
    if (has_file_unit(data, c)) h += ",measured_" + ch + "_in_file,unit_" + ch + "_in_file";
  }
  return h + "\n";
}

// One row of fit.csv: where it came from, its sweep, psi, and per channel the measured value,
// the fitted law, the residual and (for a value left out as a gross error) the value again.
std::string fit_csv_row(const PlotInput& in, const FitReport& fit, std::size_t i, int j,
                        std::size_t sweep, const std::vector<std::array<bool, kChannels>>& out) {
  const MeasuredPoint& p = in.data.points[i];
  const std::string file = p.source < static_cast<int>(in.data.sources.size())
                               ? in.data.sources[static_cast<std::size_t>(p.source)]
                               : in.data.source;
  const double u = std::abs(p.kinematics.omega) * in.radius_m;
  const double v = std::hypot(p.kinematics.vx, p.kinematics.vy);
  const double psi = u > 0.0 ? v / u : (v > 0.0 ? INFINITY : 0.0);
  std::string row = quoted(file) + "," + std::to_string(p.line) + "," + std::to_string(sweep + 1) +
                    "," + cell(p.normal_load) + "," + number_or_inf(psi) + "," +
                    number_or_inf(v > 0.0 ? u / v : INFINITY);
  for (int c = 0; c < kChannels; ++c) {
    const bool left_out = out[i][c] && p.force[c];
    std::string model = "NaN", residual = "NaN";
    if (j >= 0) {
      const auto k = static_cast<std::size_t>(j);
      model = fmt("%.10g", fit.prediction[k].vector()(c));
      residual = cell(fit.residual[k][c]);
    }
    row += "," + cell(p.force[c]) + "," + model + "," + residual + "," +
           (left_out ? cell(p.force[c]) : std::string("NaN"));
    if (!has_file_unit(in.data, c)) continue;
    const auto& units = in.data.channel_units[std::min<std::size_t>(
        static_cast<std::size_t>(p.source), in.data.channel_units.size() - 1)][c];
    // The value in the file's own unit (GCC's -O3 flow analysis misreads a local optional here).
    const std::string own = p.force[c] ? fmt("%.10g", *p.force[c] / units.to_si) : "NaN";
    row += "," + own + "," + (units.unit.empty() ? std::string(c == 2 ? "N m" : "N") : units.unit);
  }
  return row + "\n";
}

// The sweeps' table: number, label, file, load, direction, spin speed, rows.
std::string sweeps_csv(const MeasuredData& data, const std::vector<Sweep>& sweeps) {
  std::string t = "sweep,label,file,Fz_N,direction_deg,u_mps,omega_sign,rows\n";
  for (std::size_t k = 0; k < sweeps.size(); ++k) {
    const Sweep& s = sweeps[k];
    const std::string file = s.file < static_cast<int>(data.sources.size())
                                 ? data.sources[static_cast<std::size_t>(s.file)]
                                 : data.source;
    t += std::to_string(k + 1) + "," + quoted(s.label) + "," + quoted(file) + "," + cell(s.load_n) +
         "," +
         cell(s.direction_rad ? std::optional<double>(*s.direction_rad * 180.0 / std::numbers::pi)
                              : std::nullopt) +
         "," + fmt("%.6g", s.spin_speed_mps) + "," + std::to_string(s.spin_sign) + "," +
         std::to_string(s.points.size()) + "\n";
  }
  return t;
}

// The gnuplot clauses of one channel's upper panel: measured points and the fitted law, one
// colour a sweep (up to kMaxCurves, each named in the key up to kMaxKeyed; beyond, all rows
// alike, the law as points), then the values left out as gross errors.
constexpr std::size_t kMaxCurves = 40;
constexpr std::size_t kMaxKeyed = 12;
constexpr std::size_t kDrawnRows = 5000;

// Whether a channel's picture draws each sweep in its own colour (the title says so only then).
bool coloured_by_sweep(const std::vector<Sweep>& sweeps) {
  return sweeps.size() <= kMaxCurves;
}

// Sweep k of n's colour: gnuplot's own line colours up to 8 sweeps, else hues around the wheel
// (alternately darker) as '#rrggbb'.
std::string sweep_colour(std::size_t k, std::size_t n) {
  if (n <= 8) return std::to_string(k + 1);
  const double h = 6.0 * static_cast<double>(k) / static_cast<double>(n);
  const double v = k % 2 ? 0.65 : 0.95, x = v * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  const int sector = static_cast<int>(h) % 6;
  const double rgb[6][3] = {{v, x, 0}, {x, v, 0}, {0, v, x}, {0, x, v}, {x, 0, v}, {v, 0, x}};
  char buf[16];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", static_cast<int>(255 * rgb[sector][0]),
                static_cast<int>(255 * rgb[sector][1]), static_cast<int>(255 * rgb[sector][2]));
  return "rgb '" + std::string(buf) + "'";
}

std::string channel_clauses(const std::vector<Sweep>& sweeps, const std::string& x,
                            const std::string& ch, bool any_outlier, const std::string& every) {
  std::string plot = "plot ";
  const std::string file = "'fit.csv'" + every + " using \"" + x + "\":";
  const std::string again = "''" + every + " using \"" + x + "\":";
  auto only = [](std::size_t k, const std::string& col) {
    return "(column(\"sweep\")==" + std::to_string(k + 1) + "?column(\"" + col + "\"):NaN)";
  };
  const std::size_t n = sweeps.size();
  if (coloured_by_sweep(sweeps)) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::string title =
          n <= kMaxKeyed ? "title '" + sweeps[k].label + "'"
          : k == 0       ? "title 'measured, " + std::to_string(n) + " sweeps (sweeps.csv)'"
                         : "notitle";
      plot += std::string(k ? ", " : "") + file + only(k, "measured_" + ch) +
              " with points pt 7 ps 0.4 lc " + sweep_colour(k, n) + " " + title;
    }
    for (std::size_t k = 0; k < n; ++k)  // the law over every sweep's points
      plot += ", " + again + only(k, "fit_" + ch) + " with lines lw 1.5 lc rgb 'black' " +
              (k == 0 ? "title 'fitted law'" : "notitle");
  } else {
    plot += file + "\"measured_" + ch +
            "\" with points pt 7 ps 0.5 lc rgb '#1f77b4' title 'measured (" + std::to_string(n) +
            " sweeps)', " + again + "\"fit_" + ch +
            "\" with points pt 6 ps 0.5 lc rgb '#d62728' title 'fitted law'";
  }
  if (any_outlier)  // every gross error marked, however many rows are drawn
    plot += ", 'fit.csv' using \"" + x + "\":\"outlier_" + ch +
            "\" with points pt 2 ps 1.6 lw 2 lc rgb 'black' title 'gross error (left out)'";
  return plot + "\n";
}

// The gnuplot script of the fit pictures: per channel, measured and fitted per sweep, the gross
// errors marked, the residuals below.
std::string fit_script(const PlotInput& in, const std::vector<Sweep>& sweeps) {
  std::string gp =
      "set terminal pngcairo size 1100,760 font ',10'\nset datafile separator ','\n"
      "set datafile columnheaders\nset datafile missing 'NaN'\n";
  const char* title[3] = {"Fx: longitudinal force", "Fy: lateral force", "Mz: spin torque"};
  // Above kDrawnRows rows, every k-th row of fit.csv is drawn (it is in sweep and psi order, so
  // each curve keeps its shape); every gross error is marked; fit.csv keeps every row.
  const std::size_t rows = in.data.points.size(), thin = (rows + kDrawnRows - 1) / kDrawnRows;
  const std::string every = thin > 1 ? " every " + std::to_string(thin) : "";
  const std::string drawn =
      thin > 1 ? " (1 row in " + std::to_string(thin) + " of " + std::to_string(rows) + " drawn)"
               : "";
  for (int c = 0; c < kChannels; ++c) {
    if (in.data.count(c) == 0) continue;
    bool any_outlier = false;
    for (const Outlier& o : in.outliers) any_outlier = any_outlier || o.channel == c;
    const std::string ch = kChannelColumns[c], x = c == 0 ? "psi" : "upsilon";
    const std::string xlabel = c == 0 ? "psi = v / (omega R) [-]" : "upsilon = omega R / v [-]";
    gp += "set output 'fit_" + ch + ".png'\n";
    gp += "set multiplot layout 2,1 title '" + std::string(title[c]) + ": measured and fitted, " +
          (coloured_by_sweep(sweeps) ? "one colour a sweep" : "all sweeps in one colour") + drawn +
          "' noenhanced\n";
    gp +=
        "set logscale x\nset format x '10^{%L}'\nset grid\n"
        "set key outside right top box noenhanced\nset lmargin 12\nset rmargin 34\n";
    gp += "set ylabel '" + std::string(kAxisLabel[c]) + "'\nset xlabel '" + xlabel + "'\n";
    gp += channel_clauses(sweeps, x, ch, any_outlier, every);
    gp += "unset key\nset ylabel 'residual " + std::string(kAxisLabel[c]) + "'\n";
    gp += "plot 'fit.csv'" + every + " using \"" + x + "\":\"residual_" + ch +
          "\" with impulses lc rgb '#555555' notitle, 0 with lines lc rgb 'black' notitle\n";
    gp += "unset multiplot\nunset logscale x\n";
  }
  return gp;
}

}  // namespace

bool write_plots(const OutputDir& dir, const PlotInput& in, const FitReport& fit) {
  const std::vector<Sweep> sweeps = sweeps_of(in.data, in.radius_m);
  const std::vector<int> j = fitted_index(in);
  std::vector<std::array<bool, kChannels>> out(in.data.points.size());
  for (const Outlier& o : in.outliers)
    if (o.point >= 0 && static_cast<std::size_t>(o.point) < out.size())
      out[static_cast<std::size_t>(o.point)][o.channel] = true;
  std::string csv = fit_csv_header(in.data);
  for (std::size_t k = 0; k < sweeps.size(); ++k)
    for (std::size_t i : sweeps[k].points) csv += fit_csv_row(in, fit, i, j[i], k, out);
  dir.write("fit.csv", csv);
  dir.write("sweeps.csv", sweeps_csv(in.data, sweeps));
  return run_gnuplot(dir, "fit", fit_script(in, sweeps));
}

}  // namespace contensou::app
