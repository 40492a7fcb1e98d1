#include "map_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

#include "axis_label.hpp"
#include "contensou/friction/file_output.hpp"
#include "gnuplot.hpp"
#include "map_geometry.hpp"

namespace contensou::app {
namespace {

// The map's axes and ranges, its coloured column where the cell is valid, and the cells it could
// not compute as black crosses counted in the key (gnuplot, columns by their CSV names).
std::string map_plot_body(const StabilityMap& m, const std::string& base,
                          const std::string& value) {
  const long invalid =
      std::count_if(m.cells.begin(), m.cells.end(), [](const MapCell& c) { return !c.valid; });
  const std::string xy = "\"" + m.x.parameter + "\":\"" + m.y.parameter + "\"";
  std::ostringstream gp;
  gp << "set datafile separator ','\nset datafile columnheaders\n"
     << "set xlabel '" << parameter_axis_label(m.x.parameter) << "'\nset ylabel '"
     << parameter_axis_label(m.y.parameter) << "'\nset xrange [" << m.x.from << ":" << m.x.to
     << "]\nset yrange [" << m.y.from << ":" << m.y.to << "]\nset key outside below\n"
     << "plot '" << base << ".csv' using " << xy << ":(column(\"valid\") > 0 ? column(\"" << value
     << "\") : NaN) with image notitle";
  if (invalid > 0)
    gp << ", '' using \"" << m.x.parameter << "\":(column(\"valid\") > 0 ? NaN : column(\""
       << m.y.parameter << "\")) with points pt 2 ps 0.8 lc rgb 'black' title '" << invalid
       << " of " << m.cells.size()
       << " cells not computed (brake short of its target slip or solve failed: CSV column "
          "error)'";
  return gp.str();
}

// The boundary as segments of the interpolated zero contour (two rows each, a blank line
// between segments: gnuplot draws each as a line).
std::string boundary_csv(const StabilityMap& m) {
  std::ostringstream o;
  o.precision(9);
  o << m.x.parameter << ',' << m.y.parameter << '\n';
  for (const auto& s : zero_contour(m))
    o << s[0] << ',' << s[1] << '\n' << s[2] << ',' << s[3] << "\n\n";
  return o.str();
}

// Every unstable lobe labelled inside the frame with its largest growth rate, and the operating
// point marked (or said to lie outside).
std::string map_labels(const StabilityMap& m, double x0, double y0) {
  std::ostringstream gp;
  gp.precision(10);
  gp << "set style textbox opaque noborder\n";
  int k = 0;
  PlacedLabels placed;
  for (const std::vector<int>& lobe : unstable_lobes(m)) {
    double g = -1e300;
    for (int c : lobe) g = std::max(g, m.cells[static_cast<std::size_t>(c)].growth_rate_per_s);
    const MapCell& c = lobe_centre(m, lobe);
    char text[96];
    std::snprintf(text, sizeof text, "unstable (%zu cells): up to %+.2f 1/s", lobe.size(), g);
    const auto at = place_clear(m, inside_frame(m, c.x, c.y), std::strlen(text), placed);
    gp << "set label " << ++k << " \"" << text << "\" at " << at.x << "," << at.y << " " << at.align
       << " front boxed font ',9'\n";
  }
  const bool in_x = (x0 - m.x.from) * (x0 - m.x.to) <= 0.0;
  const bool in_y = (y0 - m.y.from) * (y0 - m.y.to) <= 0.0;
  if (in_x && in_y)
    gp << "set label 99 'operating point' at " << x0 << "," << y0
       << " point pt 9 ps 2 lc rgb 'black' offset 1.2,-0.6 front boxed font ',9'\n";
  return gp.str();
}

// Writes the map's CSV and PNG; returns its summary.
nlohmann::json write_map(const OutputDir& dir, const ComputedMap& cm) {
  const StabilityMap& m = cm.map;
  const std::string base = "map_" + short_name(m.x.parameter) + "_" + short_name(m.y.parameter) +
                           "_" + (m.linear ? to_string(m.phase) : "simulated") + "_" +
                           to_string(m.contact);
  std::ostringstream csv;
  csv.precision(9);
  csv << m.x.parameter << ',' << m.y.parameter
      << ",growth_rate_per_s,frequency_Hz,final_amplitude_rad,shimmy,valid,error\n";
  double g_max = 1e-3;
  int shimmy_cells = 0, failed = 0, invalid = 0;
  for (int j = 0; j < m.y.points; ++j) {
    for (int i = 0; i < m.x.points; ++i) {
      const MapCell& c = m.cells[static_cast<std::size_t>(j * m.x.points + i)];
      invalid += !c.valid;
      csv << c.x << ',' << c.y << ',' << c.growth_rate_per_s << ',' << c.frequency_hz << ','
          << c.last_amplitude_rad << ',' << c.shimmy << ',' << c.valid << ",\"" << c.error
          << "\"\n";
      if (c.valid) g_max = std::max(g_max, std::abs(c.growth_rate_per_s));
      shimmy_cells += c.shimmy;
      failed += !c.error.empty();
    }
    csv << '\n';  // gnuplot reads blank-line-separated rows as a grid
  }
  dir.write(base + ".csv", csv.str());
  dir.write(base + "_boundary.csv", boundary_csv(m));
  const bool in_frame = (cm.operating_x - m.x.from) * (cm.operating_x - m.x.to) <= 0.0 &&
                        (cm.operating_y - m.y.from) * (cm.operating_y - m.y.to) <= 0.0;
  std::ostringstream gp;
  gp.precision(10);
  gp << "set terminal pngcairo noenhanced size 820,660 font ',10'\nset output '" << base
     << ".png'\nset title \"" << to_string(m.contact) << ", "
     << (m.linear ? std::string(to_string(m.phase)) + ": largest oscillatory eigenvalue real part"
                  : std::string("simulated landing: torsional growth rate"))
     << " [1/s]\\nblack line: stability boundary (growth = 0, interpolated)"
     << (in_frame ? "" : "; the operating point lies outside these axes") << "\"\n"
     << "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n"
     << "set cbrange [" << -g_max << ":" << g_max << "]\nset cblabel 'growth rate [1/s]'\n"
     << map_labels(m, cm.operating_x, cm.operating_y) << map_plot_body(m, base, "growth_rate_per_s")
     << ", '" << base << "_boundary.csv' using \"" << m.x.parameter << "\":\"" << m.y.parameter
     << "\" with lines lw 2 lc rgb 'black' title 'stability boundary'\n";
  run_gnuplot(dir, base, gp.str());
  return {{"x", m.x.parameter},
          {"y", m.y.parameter},
          {"method", m.linear ? "eigenvalues" : "simulation"},
          {"phase", m.linear ? nlohmann::json(to_string(m.phase)) : nlohmann::json(nullptr)},
          {"points", {m.x.points, m.y.points}},
          {"shimmy_cells", shimmy_cells},
          {"unstable_lobes", unstable_lobes(m).size()},
          {"failed_cells", failed},
          {"not_computed_cells", invalid},
          {"operating_point", {cm.operating_x, cm.operating_y}},
          {"csv", base + ".csv"},
          {"png", base + ".png"}};
}

// Writes a probability map's CSV and PNG (colour: the probability of shimmy over the draws).
nlohmann::json write_probability_map(const OutputDir& dir, const StabilityMap& m) {
  const std::string base = "prob_" + short_name(m.x.parameter) + "_" + short_name(m.y.parameter) +
                           "_" + to_string(m.phase) + "_" + to_string(m.contact);
  std::ostringstream csv;
  csv.precision(9);
  csv << m.x.parameter << ',' << m.y.parameter
      << ",shimmy_probability,median_growth_rate_per_s,valid,error\n";
  for (int j = 0; j < m.y.points; ++j) {
    for (int i = 0; i < m.x.points; ++i) {
      const MapCell& c = m.cells[static_cast<std::size_t>(j * m.x.points + i)];
      csv << c.x << ',' << c.y << ',' << c.shimmy_probability << ',' << c.growth_rate_per_s << ','
          << c.valid << ",\"" << c.error << "\"\n";
    }
    csv << '\n';
  }
  dir.write(base + ".csv", csv.str());
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 760,620 font ',10'\nset output '" << base
     << ".png'\nset title '" << to_string(m.contact) << ", " << to_string(m.phase)
     << ": probability of shimmy over the tire report draws'\n"
     << "set palette defined (0 '#f7f7f7', 0.5 '#f4a582', 1 '#b2182b')\nset cbrange [0:1]\n"
     << "set cblabel 'probability of shimmy'\n"
     << map_plot_body(m, base, "shimmy_probability") << "\n";
  run_gnuplot(dir, base, gp.str());
  return {{"x", m.x.parameter},          {"y", m.y.parameter},
          {"phase", to_string(m.phase)}, {"model", to_string(m.contact)},
          {"csv", base + ".csv"},        {"png", base + ".png"}};
}

}  // namespace

void report_maps(const OutputDir& out, const std::vector<ComputedMap>& maps,
                 const std::vector<Overlay>& overlays, nlohmann::json& summary) {
  std::vector<std::string> bases;
  for (const ComputedMap& m : maps) {
    summary["maps"].push_back(write_map(out, m));
    summary["maps"].back()["model"] = to_string(m.map.contact);
    bases.push_back(summary["maps"].back()["csv"].get<std::string>());
    bases.back().erase(bases.back().size() - 4);  // ".csv"
    if (m.probability)
      summary["probability_maps"].push_back(write_probability_map(out, *m.probability));
  }
  summary["overlays"] = write_boundary_overlays(out, maps, bases, overlays);
}

}  // namespace contensou::app
