#include "map_report.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "axis_label.hpp"
#include "contensou/friction/file_output.hpp"
#include "gnuplot.hpp"

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

// Writes the map's CSV and PNG; returns its summary.
nlohmann::json write_map(const OutputDir& dir, const StabilityMap& m) {
  const std::string base = "map_" + short_name(m.x.parameter) + "_" + short_name(m.y.parameter) +
                           "_" + (m.linear ? to_string(m.phase) : "simulated") + "_" +
                           to_string(m.contact);
  std::ostringstream csv, boundary;
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
      // Shimmy boundary: midpoints between computed neighbours that disagree.
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= m.x.points || j + dj >= m.y.points) continue;
        const MapCell& d = m.cells[static_cast<std::size_t>((j + dj) * m.x.points + i + di)];
        if (c.valid && d.valid && d.shimmy != c.shimmy)
          boundary << 0.5 * (c.x + d.x) << ',' << 0.5 * (c.y + d.y) << '\n';
      }
    }
    csv << '\n';  // gnuplot reads blank-line-separated rows as a grid
  }
  dir.write(base + ".csv", csv.str());
  dir.write(base + "_boundary.csv",
            m.x.parameter + ',' + m.y.parameter + '\n' + boundary.str() + "\n");
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 760,620 font ',10'\nset output '" << base
     << ".png'\nset title '" << to_string(m.contact) << ", "
     << (m.linear ? std::string(to_string(m.phase)) + ": largest oscillatory eigenvalue real part"
                  : std::string("simulated landing: torsional growth rate"))
     << " [1/s]; black: stability boundary'\n"
     << "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n"
     << "set cbrange [" << -g_max << ":" << g_max << "]\nset cblabel 'growth rate [1/s]'\n"
     << map_plot_body(m, base, "growth_rate_per_s") << ", '" << base << "_boundary.csv' using \""
     << m.x.parameter << "\":\"" << m.y.parameter
     << "\" with points pt 7 ps 0.5 lc rgb 'black' title 'stability boundary'\n";
  run_gnuplot(dir, base, gp.str());
  return {{"x", m.x.parameter},
          {"y", m.y.parameter},
          {"method", m.linear ? "eigenvalues" : "simulation"},
          {"phase", m.linear ? nlohmann::json(to_string(m.phase)) : nlohmann::json(nullptr)},
          {"points", {m.x.points, m.y.points}},
          {"shimmy_cells", shimmy_cells},
          {"failed_cells", failed},
          {"not_computed_cells", invalid},
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
    summary["maps"].push_back(write_map(out, m.map));
    summary["maps"].back()["model"] = to_string(m.map.contact);
    bases.push_back(summary["maps"].back()["csv"].get<std::string>());
    bases.back().erase(bases.back().size() - 4);  // ".csv"
    if (m.probability)
      summary["probability_maps"].push_back(write_probability_map(out, *m.probability));
  }
  summary["overlays"] = write_boundary_overlays(out, maps, bases, overlays);
}

}  // namespace contensou::app
