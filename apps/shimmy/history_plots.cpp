#include "history_plots.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "gnuplot.hpp"
#include "history.hpp"
#include "model_colours.hpp"

namespace contensou::app {

std::vector<HistoryFigure> history_figures(const GearStructure& structure) {
  std::vector<HistoryFigure> f{
      {"torsion", "torsion of the strut", {{"torsion psi of the strut", "psi_rad"}}},
      {"lateral", "lateral bending of the strut", {{"lateral deflection y at the axle", "y_m"}}},
      {"spin",
       "the strut's torsion rate (the patch's spin omega) and the wheel's spin",
       {{"torsion rate dpsi/dt = patch spin omega", "psidot_radps"},
        {"wheel spin Omega about the axle", "wheel_spin_radps"}}},
      {"slip",
       "the patch's sliding velocity and slip ratio",
       {{"sliding velocity vx", "vx_mps"},
        {"sliding velocity vy", "vy_mps"},
        {"slip ratio vx/V", "slip_ratio"}}},
      {"forces",
       "friction force on the tire (wheel frame)",
       {{"drag Fx", "Fx_n"}, {"lateral force Fy", "Fy_n"}}},
      {"torque",
       "moments on the strut about its axis: the torsion equation's terms",
       {{"offset drag -l Fx", "offset_drag_moment_nm"},
        {"contact torque Mz (spin or aligning)", "Mz_nm", true},
        {"trail -e Fy", "trail_moment_nm"},
        {"torque link -k psi - c dpsi/dt", "torque_link_nm"}}}};
  if (structure.fore_aft_stiffness_n_per_m > 0.0)
    f.push_back({"fore_aft", "fore-aft bending of the strut", {{"fore-aft bending x", "x_m"}}});
  return f;
}

std::string panel_axis_label(const HistoryPanel& panel) {
  const std::string unit = history_column(panel.column).unit;
  return panel.axis + " [" + (unit == "1" ? "-" : unit) + "]";
}

namespace {

// The events as vertical lines: the first run's common ones in grey, each model's spin-up in its
// colour; labelled near the top of the first panel only.
std::string event_marks(const std::vector<LandingRun>& runs, bool labels) {
  std::ostringstream gp;
  gp.precision(10);
  int k = 10;
  const auto mark = [&](double t, const std::string& colour, const std::string& text,
                        double height) {
    gp << "set arrow " << ++k << " from " << t << ", graph 0 to " << t
       << ", graph 1 nohead dt 2 lw 1 lc rgb '" << colour << "' back\n";
    if (labels && !text.empty())
      gp << "set label " << k << " '" << text << "' at " << t << ", graph " << height
         << " left offset 0.4,0 font ',8' tc rgb '" << colour << "'\n";
  };
  const std::vector<std::pair<std::string, std::string>> shown{{"load onset", "touchdown"},
                                                               {"full load", "full load"},
                                                               {"brake on", "brake on"},
                                                               {"brake off", "brake off"}};
  for (const auto& [event, text] : shown)
    for (const LandingEvent& e : runs.front().events)
      if (e.what == event) {
        mark(e.t, "#555555", text, 0.94);
        break;
      }
  // Each model's (first) spin-up in its colour; one label for those within 5 ms of each other.
  double labelled = -1.0, height = 0.86;
  for (const LandingRun& r : runs)
    for (const LandingEvent& e : r.events)
      if (e.what == "spin-up") {
        const bool near = labelled >= 0.0 && std::abs(e.t - labelled) < 5e-3;
        mark(e.t, model_colour(r.contact), near ? "" : "spin-up", height);
        if (!near) {
          labelled = e.t;
          height -= 0.08;
        }
        break;
      }
  return gp.str();
}

// Ranges for a panel with the decoupled model on the right axis: both symmetric about zero, so
// that the two axes share their zero, each 5 % beyond its largest |value| in the runs' samples.
std::string same_zero_ranges(const std::string& column, const std::vector<LandingRun>& runs,
                             const GearStructure& structure) {
  const std::vector<std::string>& names = history_columns();
  const auto at =
      static_cast<std::size_t>(std::find(names.begin(), names.end(), column) - names.begin());
  double left = 0.0, right = 0.0;
  for (const LandingRun& r : runs) {
    double& side = r.contact == ContactModel::decoupled ? right : left;
    for (const LandingSample& s : r.samples) {
      const std::vector<double> row = history_row(s, structure);
      if (at < row.size() && std::isfinite(row[at])) side = std::max(side, std::abs(row[at]));
    }
  }
  const auto range = [](double v) { return 1.05 * (v > 0.0 ? v : 1.0); };
  std::ostringstream gp;
  gp.precision(10);
  gp << "set yrange [" << -range(left) << ":" << range(left) << "]\nset y2range [" << -range(right)
     << ":" << range(right) << "]\n";
  return gp.str();
}

std::string panel_plot(const HistoryPanel& p, const std::vector<LandingRun>& runs,
                       const GearStructure& structure) {
  std::ostringstream gp;
  const bool right =
      p.decoupled_right &&
      std::any_of(runs.begin(), runs.end(),
                  [](const LandingRun& r) { return r.contact == ContactModel::decoupled; }) &&
      runs.size() > 1;
  gp << "set ylabel '" << panel_axis_label(p) << "'\n";
  if (right)
    gp << "set y2label 'decoupled (right axis) [N m]' tc rgb '"
       << model_colour(ContactModel::decoupled) << "'\nset y2tics\nset ytics nomirror\n"
       << same_zero_ranges(p.column, runs, structure);
  else
    gp << "unset y2label\nunset y2tics\nset ytics mirror\nset autoscale y\n";
  gp << "plot ";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const std::string model = to_string(runs[k].contact);
    const bool y2 = right && runs[k].contact == ContactModel::decoupled;
    gp << (k ? ", " : "") << "'" << model << ".csv' using \"t_s\":\"" << p.column
       << "\" with lines lw 1.3 lc rgb '" << model_colour(runs[k].contact) << "'"
       << (y2 ? " axes x1y2" : "") << " title '" << model << (y2 ? " (right axis)" : "")
       << (runs[k].metrics.shimmy ? ": shimmy" : "") << "'";
  }
  return gp.str() + "\n";
}

}  // namespace

std::string history_plot_script(const HistoryFigure& figure, const std::vector<LandingRun>& runs,
                                const GearStructure& structure) {
  std::ostringstream gp;
  gp.precision(10);
  const std::size_t n = figure.panels.size();
  const LandingRun& first = runs.front();
  gp << "set terminal pngcairo noenhanced size 1000," << 80 + 270 * n << " font ',10'\n"
     << "set output '" << figure.name << ".png'\n"
     << "set datafile separator ','\nset datafile columnheaders\n"
     << "set multiplot layout " << n << ",1 title \"" << figure.title
     << "\\ngrey band: the analysis window; dashed: events\"\n"
     << "set xlabel 'time t [s]'\nset grid\nset key outside right top vertical\n"
     << "set lmargin 12\nset rmargin 34\n"
     << "set object 1 rect from " << first.window_start_s << ", graph 0 to " << first.window_end_s
     << ", graph 1 behind fillcolor rgb '#ececec' fillstyle solid noborder\n";
  for (std::size_t k = 0; k < n; ++k) {
    gp << "unset arrow\nunset label\n" << event_marks(runs, k == 0);
    gp << panel_plot(figure.panels[k], runs, structure);
  }
  gp << "unset multiplot\n";
  return gp.str();
}

void draw_histories(const OutputDir& dir, const std::vector<LandingRun>& runs,
                    const GearStructure& structure) {
  if (runs.empty()) return;
  for (const HistoryFigure& f : history_figures(structure))
    run_gnuplot(dir, f.name, history_plot_script(f, runs, structure));
}

}  // namespace contensou::app
