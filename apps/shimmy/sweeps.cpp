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

SweepOptions sweep_options(const ShimmyConfig& config) {
  SweepOptions o;
  o.relative_tolerance = config.solver.relative_tolerance;
  o.output_interval_s = config.solver.output_interval_s;
  o.amplitude_threshold_rad = config.criterion.amplitude_threshold_rad;
  return o;
}

std::vector<BifurcationSweep> compute_sweeps(const ShimmyConfig& config, unsigned threads,
                                             const TireInput* tire, const Progress& progress) {
  check_sweep_work(config);
  std::vector<GearModel> models;
  for (ContactModel cm : config.models) models.push_back(gear_model(config, cm, tire));
  return bifurcation_sweeps(
      models, config.sweeps, sweep_options(config), threads,
      [&](int done, int total) { progress("bifurcation sweeps (up and down)", done, total); });
}

namespace {

double finite_or_nan(double v, bool ok) {
  return ok && std::isfinite(v) ? v : std::nan("");
}

// Whether a point's amplitude is an end state: a settled cycle or motion, or a decay already
// below the threshold (the diagram's rest branch); the others ran out of time still moving.
bool settled_point(const SweepPoint& p, double threshold_rad) {
  return p.valid && (p.state == CycleState::limit_cycle || p.state == CycleState::settled_small ||
                     (p.state == CycleState::decaying && p.amplitude_rad < threshold_rad));
}

// One direction of a sweep as CSV: the parameter's column, then the point's numbers (NaN where
// the point failed: gnuplot leaves a gap); the amplitudes again split into settled (the
// diagram's branches) and unsettled (still growing or decaying when the run ended).
std::string sweep_csv(const BifurcationSweep& s, const std::vector<SweepPoint>& points,
                      double threshold_rad) {
  std::ostringstream o;
  o.precision(9);
  o << s.axis.parameter
    << ",state,amplitude_rad,torque_link_nm,trend_per_s,frequency_hz,eigen_growth_rate_per_s,"
       "eigen_frequency_hz,onset_s,run_s,valid,settled_amplitude_rad,settled_torque_link_nm,"
       "unsettled_amplitude_rad,unsettled_torque_link_nm,error\n";
  for (const SweepPoint& p : points) {
    const bool cycle = p.valid && p.state == CycleState::limit_cycle;
    const bool settled = settled_point(p, threshold_rad);
    o << p.value << ',' << to_string(p.state) << ',' << finite_or_nan(p.amplitude_rad, p.valid)
      << ',' << finite_or_nan(p.torque_link_nm, p.valid) << ','
      << finite_or_nan(p.trend_per_s, p.valid) << ','
      << finite_or_nan(p.frequency_hz, cycle && p.frequency_hz > 0) << ','
      << finite_or_nan(p.eigen_growth_per_s, p.error.empty()) << ','
      << finite_or_nan(p.eigen_frequency_hz, p.error.empty()) << ','
      << finite_or_nan(p.onset_s, p.valid) << ',' << p.run_s << ',' << p.valid << ','
      << finite_or_nan(p.amplitude_rad, settled) << ',' << finite_or_nan(p.torque_link_nm, settled)
      << ',' << finite_or_nan(p.amplitude_rad, p.valid && !settled) << ','
      << finite_or_nan(p.torque_link_nm, p.valid && !settled) << ",\"" << p.error << "\"\n";
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

// One panel: the settled `what` of every model, up (solid, filled) and down (dashed, open), and
// the points that were still moving when their run ended as crosses (one key entry for all).
std::string panel(const std::vector<const BifurcationSweep*>& group, const std::string& what,
                  double longest_s) {
  std::ostringstream gp;
  gp << "plot ";
  bool first = true;
  for (const BifurcationSweep* s : group)
    for (const bool up : {true, false}) {
      const std::string file = "'" + base_name(*s, up) + ".csv' using \"" + s->axis.parameter +
                               "\":\"",
                        colour = model_colour(s->contact);
      gp << (first ? "" : ", ") << file << "settled_" << what << "\" with linespoints lw 1.5 "
         << (up ? "dt 1 pt 7" : "dt 2 pt 6") << " ps 0.7 lc rgb '" << colour << "' title '"
         << to_string(s->contact) << (up ? ", swept up" : ", swept down") << "', " << file
         << "unsettled_" << what << "\" with points pt 2 ps 1.2 lc rgb '" << colour << "' ";
      if (first)
        gp << "title 'x: not settled in " << longest_s << " s'";
      else
        gp << "notitle";
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
     << "set datafile columnheaders\n"
     << "set multiplot layout " << rows << ",1 title \"" << title << "\"\n"
     << "set xlabel '" << parameter_axis_label(parameter) << "'\nset xrange [" << axis.from << ":"
     << axis.to << "]\nset grid\n"
     << "set key outside right top vertical\n"
     // The same plot width in every panel, whatever its key: the key in the right quarter.
     << "set lmargin at screen 0.09\nset rmargin at screen 0.74\n";
  return gp.str();
}

// Whether any point of the group has a finite `get` (gnuplot refuses a plot with none).
template <class Get>
bool any_finite(const std::vector<const BifurcationSweep*>& group, bool up_only, Get get) {
  for (const BifurcationSweep* s : group)
    for (const bool up : {true, false})
      if (up || !up_only)
        for (const SweepPoint& p : up ? s->up : s->down)
          if (p.valid && std::isfinite(get(p))) return true;
  return false;
}

// Whether any up-sweep point has a linearisation (its eigenvalue is written when it has no
// error, whether or not its run was valid).
bool any_linearisation(const std::vector<const BifurcationSweep*>& group) {
  for (const BifurcationSweep* s : group)
    for (const SweepPoint& p : s->up)
      if (p.error.empty() && std::isfinite(p.eigen_growth_per_s)) return true;
  return false;
}

// Why a sweep has no point at all ("" if some point ran): its first point's error, and the count.
std::string why_no_point(const BifurcationSweep& s) {
  std::size_t failed = 0;
  const SweepPoint* first = nullptr;
  for (const bool up : {true, false})
    for (const SweepPoint& p : up ? s.up : s.down) {
      if (p.valid || p.error.empty()) return "";
      ++failed;
      if (first == nullptr) first = &p;
    }
  if (first == nullptr) return "";
  return "no point of this sweep ran (" + std::to_string(failed) + " of " + std::to_string(failed) +
         "; at " + format_value(first->value) + ": " + first->error + ")";
}

// A panel with nothing to draw, saying why (no y tics: a range that holds no data has no scale
// to read).
std::string empty_panel(const std::string& why) {
  return "set yrange [0:1]\nunset ytics\nset label 1 '" + why +
         "' at graph 0.5, 0.5 center\nplot NaN notitle\nunset label 1\nset ytics\n"
         "set autoscale y\n";
}

// Amplitude and torque-link load against the parameter, every model, both directions.
void draw_amplitudes(const OutputDir& out, const std::vector<const BifurcationSweep*>& group,
                     double longest_s) {
  const std::string& parameter = group.front()->axis.parameter;
  const std::string name = "bifurcation_" + short_name(parameter);
  std::ostringstream gp;
  gp << header(name, group.front()->axis, 2,
               "braked slide: limit cycle against " + parameter_axis_label(parameter) +
                   "\\ndotted: linear boundaries (" + boundary_words(group) +
                   ")\\nx: still growing or decaying when its run ended (its last swing); where "
                   "both directions settle apart: hysteresis (a subcritical branch)")
     << boundary_arrows(group);
  const bool any = any_finite(group, false, [](const SweepPoint& p) { return p.amplitude_rad; });
  const std::string none = empty_panel("no point of any sweep finished its run");
  gp << "set ylabel 'limit-cycle amplitude of psi [rad]'\n"
     << (any ? panel(group, "amplitude_rad", longest_s) : none)
     << "set ylabel 'torque-link load amplitude [N m]'\n"
     << (any ? panel(group, "torque_link_nm", longest_s) : none) << "unset multiplot\n";
  run_gnuplot(out, name, gp.str());
}

// Growth rate, frequencies and time to onset against the parameter (the up sweeps).
void draw_linear(const OutputDir& out, const std::vector<const BifurcationSweep*>& group,
                 const SweepOptions& o) {
  const std::string& parameter = group.front()->axis.parameter;
  const std::string name = "bifurcation_" + short_name(parameter) + "_growth";
  std::ostringstream gp, freq, growth, onset;
  gp << header(name, group.front()->axis, 3,
               "braked slide against " + parameter_axis_label(parameter) +
                   ": linear growth rate, shimmy frequency, time to onset\\n(onset: from a "
                   "kick of psi' = " +
                   format_value(o.seed_rate_radps) + " rad/s until a swing first reaches " +
                   format_value(o.amplitude_threshold_rad) +
                   " rad; none where it decays or settles below)")
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
  const bool linear = any_linearisation(group);
  const std::string none = empty_panel(
      "no point has a quasi-steady braked slide to linearise (the CSV column error says why)");
  gp << "set ylabel 'growth rate of the linearisation [1/s]'\nset xzeroaxis lt -1\n"
     << (linear ? growth.str() + "\n" : none) << "set ylabel 'shimmy frequency [Hz]'\n"
     << (linear ? freq.str() + "\n" : none) << "set ylabel 'time to onset [s]'\n";
  const bool ran = std::any_of(group.begin(), group.end(), [](const BifurcationSweep* s) {
    return std::any_of(s->up.begin(), s->up.end(), [](const SweepPoint& p) { return p.valid; });
  });
  if (any_finite(group, true, [](const SweepPoint& p) { return p.onset_s; }))
    gp << onset.str() << "\n";
  else if (!ran)
    gp << empty_panel("no onset to show: no up-sweep point finished its run");
  else
    gp << empty_panel("no onset: no up-sweep point reaches " +
                      format_value(o.amplitude_threshold_rad) + " rad from the kick");
  gp << "unset multiplot\n";
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
                   const SweepOptions& options, nlohmann::json& summary) {
  std::map<std::string, std::vector<const BifurcationSweep*>> by_parameter;
  std::vector<std::string> order;
  std::printf(
      "\nbifurcation sweeps of the braked slide (limit cycle by continuation, up from a small "
      "kick and down from a large swing; where each holds a settled cycle):\n"
      "%-13s %-40s %14s %16s %16s\n",
      "model", "parameter", "linear bound.", "cycle (up)", "cycle (down)");
  for (const BifurcationSweep& s : sweeps) {
    for (const bool up : {true, false})
      out.write(base_name(s, up) + ".csv",
                sweep_csv(s, up ? s.up : s.down, options.amplitude_threshold_rad));
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
    const std::string why = why_no_point(s);
    if (!why.empty()) std::printf("%13s %s\n", "", why.c_str());
    j["no_point_ran"] = why.empty() ? nlohmann::json() : nlohmann::json(why);
    summary["bifurcation"].push_back(std::move(j));
  }
  for (const std::string& p : order) {
    draw_amplitudes(out, by_parameter[p], options.longest_s);
    draw_linear(out, by_parameter[p], options);
  }
}

}  // namespace contensou::app
