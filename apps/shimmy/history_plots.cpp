#include "history_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "gnuplot.hpp"
#include "history.hpp"

namespace contensou::app {

const std::vector<HistoryPanel>& history_panels() {
  static const std::vector<HistoryPanel> panels{
      {"torsion", "torsion psi of the strut", {"psi_rad"}},
      {"lateral", "lateral deflection y at the axle", {"y_m"}},
      {"slip", "sliding velocity of the patch", {"vx_mps", "vy_mps"}},
      {"slip_ratio", "slip ratio vx/V", {"slip_ratio"}},
      {"spin", "spin of the patch omega", {"omega_radps"}},
      {"forces", "friction force on the tire", {"Fx_n", "Fy_n"}},
      {"torque", "friction torque on the tire Mz", {"Mz_nm"}},
      {"fore_aft", "fore-aft bending x (0 when the gear has none)", {"x_m"}}};
  return panels;
}

std::string panel_axis_label(const HistoryPanel& panel) {
  const std::string unit = history_column(panel.columns.front()).unit;
  for (const std::string& c : panel.columns)
    if (history_column(c).unit != unit)
      throw std::logic_error("history panel " + panel.name + ": columns of different units");
  return panel.axis + " [" + (unit == "1" ? "-" : unit) + "]";
}

namespace {

// The smallest and largest value of the panel's columns over every run, padded by 5 %.
std::pair<double, double> panel_range(const HistoryPanel& panel,
                                      const std::vector<LandingRun>& runs) {
  const std::vector<std::string>& names = history_columns();
  std::vector<std::size_t> index;
  for (const std::string& c : panel.columns)
    index.push_back(
        static_cast<std::size_t>(std::find(names.begin(), names.end(), c) - names.begin()));
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const LandingRun& r : runs)
    for (const LandingSample& s : r.samples) {
      const std::vector<double> row = history_row(s);
      for (std::size_t i : index) {
        if (!std::isfinite(row[i])) continue;
        lo = std::min(lo, row[i]);
        hi = std::max(hi, row[i]);
      }
    }
  if (!(lo <= hi)) return {-1.0, 1.0};
  const double pad = hi > lo ? 0.05 * (hi - lo) : std::max(1e-12, 0.05 * std::abs(hi) + 1e-9);
  return {lo - pad, hi + pad};
}

}  // namespace

std::string history_plot_script(const HistoryPanel& panel, const std::vector<LandingRun>& runs) {
  const auto [lo, hi] = panel_range(panel, runs);
  std::ostringstream gp;
  gp.precision(10);
  gp << "set terminal pngcairo noenhanced size " << 520 * std::max<std::size_t>(runs.size(), 1)
     << ",460 font ',10'\nset output '" << panel.name << ".png'\n"
     << "set datafile separator ','\nset datafile columnheaders\n"
     << "set multiplot layout 1," << std::max<std::size_t>(runs.size(), 1) << " title \""
     << panel_axis_label(panel)
     << "\\ngrey band: the analysis window, where growth rate and frequency are measured\"\n"
     << "set xlabel '"
     << "time t [s]'\nset ylabel '" << panel_axis_label(panel) << "'\n"
     << "set yrange [" << lo << ":" << hi << "]\nset grid\nset key outside below horizontal\n";
  for (const LandingRun& r : runs) {
    const std::string model = to_string(r.contact);
    gp << "set title '" << model << (r.metrics.shimmy ? ": shimmy" : ": no shimmy") << "'\n"
       << "set object 1 rect from " << r.window_start_s << ", graph 0 to " << r.window_end_s
       << ", graph 1 behind fillcolor rgb '#e4e4e4' fillstyle solid noborder\nplot ";
    for (std::size_t k = 0; k < panel.columns.size(); ++k)
      gp << (k ? ", " : "") << "'" << model << ".csv' using \"t_s\":\"" << panel.columns[k]
         << "\" with lines lw 1 "
         << (panel.columns.size() > 1 ? "title '" + history_column(panel.columns[k]).quantity + "'"
                                      : std::string("notitle"));
    gp << "\n";
  }
  gp << "unset multiplot\n";
  return gp.str();
}

void draw_histories(const OutputDir& dir, const std::vector<LandingRun>& runs) {
  for (const HistoryPanel& p : history_panels())
    run_gnuplot(dir, p.name, history_plot_script(p, runs));
}

}  // namespace contensou::app
