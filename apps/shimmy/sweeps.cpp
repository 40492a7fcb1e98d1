#include "sweeps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "axis_label.hpp"
#include "contensou/friction/error.hpp"
#include "gnuplot.hpp"
#include "model_colours.hpp"

namespace contensou::app {

void check_sweep_work(const ShimmyConfig& config) {
  long points = 0;
  for (const MapAxis& a : config.sweeps) points += a.points;
  points *= 2 * static_cast<long>(config.models.size());
  if (points > kMostSweepPoints)
    throw InvalidArgument("sweeps", std::to_string(config.sweeps.size()) + " sweeps",
                          "they would take " + std::to_string(points) +
                              " points (points x models x 2 directions, each up to 8 s of "
                              "simulated slide); at most " +
                              std::to_string(kMostSweepPoints) + " in one run");
}

std::vector<BifurcationSweep> compute_sweeps(const ShimmyConfig& config, unsigned threads,
                                             const TireInput* tire, const Progress& progress) {
  check_sweep_work(config);
  std::vector<GearModel> models;
  for (ContactModel cm : config.models) models.push_back(gear_model(config, cm, tire));
  SweepOptions o;
  o.relative_tolerance = config.solver.relative_tolerance;
  o.output_interval_s = config.solver.output_interval_s;
  o.amplitude_threshold_rad = config.criterion.amplitude_threshold_rad;
  return bifurcation_sweeps(models, config.sweeps, o, threads, [&](int done, int total) {
    progress("bifurcation sweeps (up and down)", done, total);
  });
}

namespace {

double finite_or_nan(double v, bool ok) {
  return ok && std::isfinite(v) ? v : std::nan("");
}

// One direction of a sweep as CSV: the parameter's column, then the point's numbers (NaN where
// the point failed: gnuplot leaves a gap).
std::string sweep_csv(const BifurcationSweep& s, const std::vector<SweepPoint>& points) {
  std::ostringstream o;
  o.precision(9);
  o << s.axis.parameter
    << ",state,amplitude_rad,torque_link_nm,trend_per_s,frequency_hz,eigen_growth_rate_per_s,"
       "eigen_frequency_hz,onset_s,run_s,valid,error\n";
  for (const SweepPoint& p : points) {
    const bool cycle = p.valid && p.state == CycleState::limit_cycle;
    o << p.value << ',' << to_string(p.state) << ',' << finite_or_nan(p.amplitude_rad, p.valid)
      << ',' << finite_or_nan(p.torque_link_nm, p.valid) << ','
      << finite_or_nan(p.trend_per_s, p.valid) << ','
      << finite_or_nan(p.frequency_hz, cycle && p.frequency_hz > 0) << ','
      << finite_or_nan(p.eigen_growth_per_s, p.error.empty()) << ','
      << finite_or_nan(p.eigen_frequency_hz, p.error.empty()) << ','
      << finite_or_nan(p.onset_s, cycle) << ',' << p.run_s << ',' << p.valid << ",\"" << p.error
      << "\"\n";
  }
  return o.str();
}

std::string base_name(const BifurcationSweep& s, bool up) {
  return "bifurcation_" + short_name(s.axis.parameter) + "_" + to_string(s.contact) +
         (up ? "_up" : "_down");
}

// The vertical line of each model's linear boundary, labelled at the top.
std::string boundary_arrows(const std::vector<const BifurcationSweep*>& group) {
  std::ostringstream gp;
  int k = 0;
  for (const BifurcationSweep* s : group)
    for (const double b : s->linear_boundaries)
      gp << "set arrow " << ++k << " from " << b << ", graph 0 to " << b
         << ", graph 1 nohead dt 3 lw 1.5 lc rgb '" << model_colour(s->contact) << "'\n";
  return gp.str();
}

// The key's words for the linear boundaries.
std::string boundary_words(const std::vector<const BifurcationSweep*>& group) {
  std::string out;
  for (const BifurcationSweep* s : group) {
    std::string b;
    for (const double v : s->linear_boundaries) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.3g", v);
      b += (b.empty() ? "" : ", ") + std::string(buf);
    }
    out += (out.empty() ? "" : ", ") + std::string(to_string(s->contact)) + " " +
           (b.empty() ? "none" : b);
  }
  return out;
}

// One panel: `column` of every model, up (solid, filled) and down (dashed, open).
std::string panel(const std::vector<const BifurcationSweep*>& group, const std::string& column) {
  std::ostringstream gp;
  gp << "plot ";
  bool first = true;
  for (const BifurcationSweep* s : group)
    for (const bool up : {true, false}) {
      gp << (first ? "" : ", ") << "'" << base_name(*s, up) << ".csv' using \"" << s->axis.parameter
         << "\":\"" << column << "\" with linespoints lw 1.5 " << (up ? "dt 1 pt 7" : "dt 2 pt 6")
         << " ps 0.7 lc rgb '" << model_colour(s->contact) << "' title '" << to_string(s->contact)
         << (up ? ", swept up" : ", swept down") << "'";
      first = false;
    }
  return gp.str() + "\n";
}

std::string header(const std::string& name, const MapAxis& axis, int rows,
                   const std::string& title) {
  const std::string& parameter = axis.parameter;
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 960," << 60 + 320 * rows << " font ',10'\n"
     << "set output '" << name << ".png'\nset datafile separator ','\n"
     << "set datafile columnheaders\nset datafile missing 'nan'\n"
     << "set multiplot layout " << rows << ",1 title \"" << title << "\"\n"
     << "set xlabel '" << parameter_axis_label(parameter) << "'\nset xrange [" << axis.from << ":"
     << axis.to << "]\nset grid\n"
     << "set key outside right top vertical\nset lmargin 12\n";
  return gp.str();
}

// Amplitude and torque-link load against the parameter, every model, both directions.
void draw_amplitudes(const OutputDir& out, const std::vector<const BifurcationSweep*>& group) {
  const std::string& parameter = group.front()->axis.parameter;
  const std::string name = "bifurcation_" + short_name(parameter);
  std::ostringstream gp;
  gp << header(name, group.front()->axis, 2,
               "braked slide: limit cycle against " + parameter_axis_label(parameter) +
                   "\\ndotted: linear boundaries (" + boundary_words(group) +
                   ")\\nwhere both directions settle apart: hysteresis (a subcritical branch)")
     << boundary_arrows(group) << "set ylabel 'limit-cycle amplitude of psi [rad]'\n"
     << panel(group, "amplitude_rad") << "set ylabel 'torque-link load amplitude [N m]'\n"
     << panel(group, "torque_link_nm") << "unset multiplot\n";
  run_gnuplot(out, name, gp.str());
}

// Growth rate, frequencies and time to onset against the parameter (the up sweeps).
void draw_linear(const OutputDir& out, const std::vector<const BifurcationSweep*>& group) {
  const std::string& parameter = group.front()->axis.parameter;
  const std::string name = "bifurcation_" + short_name(parameter) + "_growth";
  std::ostringstream gp, freq, growth, onset;
  gp << header(name, group.front()->axis, 3,
               "braked slide against " + parameter_axis_label(parameter) +
                   ": linear growth rate, shimmy frequency, time to onset\\n(onset: from a "
                   "kick of psi' = 0.01 rad/s to half the settled amplitude)")
     << boundary_arrows(group);
  growth << "plot ";
  freq << "plot ";
  onset << "plot ";
  bool first = true;
  for (const BifurcationSweep* s : group) {
    const std::string file =
        "'" + base_name(*s, true) + ".csv' using \"" + s->axis.parameter + "\":\"";
    const std::string colour = " lc rgb '" + std::string(model_colour(s->contact)) + "'";
    const std::string sep = first ? "" : ", ", m = to_string(s->contact);
    growth << sep << file << "eigen_growth_rate_per_s\" with lines lw 2" << colour << " title '"
           << m << "'";
    freq << sep << file << "eigen_frequency_hz\" with lines lw 2" << colour << " title '" << m
         << ", eigenvalue', " << file << "frequency_hz\" with points pt 7 ps 0.7" << colour
         << " title '" << m << ", simulated'";
    onset << sep << file << "onset_s\" with linespoints pt 7 ps 0.7 lw 1.5" << colour << " title '"
          << m << "'";
    first = false;
  }
  gp << "set ylabel 'growth rate of the linearisation [1/s]'\nset xzeroaxis lt -1\n"
     << growth.str() << "\nset ylabel 'shimmy frequency [Hz]'\n"
     << freq.str() << "\nset ylabel 'time to onset [s]'\n"
     << onset.str() << "\nunset multiplot\n";
  run_gnuplot(out, name, gp.str());
}

nlohmann::json point_json(const SweepPoint& p) {
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {{"value", p.value},
          {"state", to_string(p.state)},
          {"amplitude_rad", num(p.amplitude_rad)},
          {"torque_link_nm", num(p.torque_link_nm)},
          {"trend_per_s", num(p.trend_per_s)},
          {"frequency_Hz", num(p.frequency_hz)},
          {"eigen_growth_rate_per_s", num(p.eigen_growth_per_s)},
          {"eigen_frequency_Hz", num(p.eigen_frequency_hz)},
          {"onset_s", num(p.onset_s)},
          {"valid", p.valid},
          {"error", p.error}};
}

// The smallest and largest parameter with a settled limit cycle (null if none).
nlohmann::json cycle_range(const std::vector<SweepPoint>& points) {
  double lo = std::nan(""), hi = std::nan("");
  for (const SweepPoint& p : points)
    if (p.state == CycleState::limit_cycle) {
      lo = std::isnan(lo) ? p.value : std::min(lo, p.value);
      hi = std::isnan(hi) ? p.value : std::max(hi, p.value);
    }
  return std::isnan(lo) ? nlohmann::json() : nlohmann::json::array({lo, hi});
}

// What the diagram says in numbers: the linear boundary and where each direction holds a cycle.
nlohmann::json sweep_json(const BifurcationSweep& s) {
  nlohmann::json up = nlohmann::json::array(), down = nlohmann::json::array();
  for (const SweepPoint& p : s.up) up.push_back(point_json(p));
  for (const SweepPoint& p : s.down) down.push_back(point_json(p));
  const auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  return {{"model", to_string(s.contact)},
          {"parameter", s.axis.parameter},
          {"linear_boundary", num(s.linear_boundary)},
          {"linear_boundaries", s.linear_boundaries},
          {"limit_cycle_range_up", cycle_range(s.up)},
          {"limit_cycle_range_down", cycle_range(s.down)},
          {"up", up},
          {"down", down}};
}

}  // namespace

void report_sweeps(const OutputDir& out, const std::vector<BifurcationSweep>& sweeps,
                   nlohmann::json& summary) {
  std::map<std::string, std::vector<const BifurcationSweep*>> by_parameter;
  std::vector<std::string> order;
  std::printf(
      "\nbifurcation sweeps of the braked slide (limit cycle by continuation, up from a small "
      "kick and down from a large swing; where each holds a settled cycle):\n"
      "%-13s %-40s %14s %16s %16s\n",
      "model", "parameter", "linear bound.", "cycle (up)", "cycle (down)");
  for (const BifurcationSweep& s : sweeps) {
    for (const bool up : {true, false})
      out.write(base_name(s, up) + ".csv", sweep_csv(s, up ? s.up : s.down));
    if (!by_parameter.count(s.axis.parameter)) order.push_back(s.axis.parameter);
    by_parameter[s.axis.parameter].push_back(&s);
    nlohmann::json j = sweep_json(s);
    const auto text = [](const nlohmann::json& v) {
      char buf[48];
      if (v.is_number()) {
        std::snprintf(buf, sizeof buf, "%.4g", v.get<double>());
      } else if (v.is_array()) {
        std::snprintf(buf, sizeof buf, "%.4g..%.4g", v[0].get<double>(), v[1].get<double>());
      } else {
        return std::string("none");
      }
      return std::string(buf);
    };
    std::string boundaries;
    for (const double v : s.linear_boundaries) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.4g", v);
      boundaries += (boundaries.empty() ? "" : ", ") + std::string(buf);
    }
    if (boundaries.empty()) boundaries = "none";
    std::printf("%-13s %-40s %14s %16s %16s\n", to_string(s.contact), s.axis.parameter.c_str(),
                boundaries.c_str(), text(j["limit_cycle_range_up"]).c_str(),
                text(j["limit_cycle_range_down"]).c_str());
    summary["bifurcation"].push_back(std::move(j));
  }
  for (const std::string& p : order) {
    draw_amplitudes(out, by_parameter[p]);
    draw_linear(out, by_parameter[p]);
  }
}

}  // namespace contensou::app
