#include "boundary_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "axis_label.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "gnuplot.hpp"
#include "map_geometry.hpp"

namespace contensou::app {

std::string feeding_source(const GearModel& model, StabilityPhase phase) {
  StabilityOptions o;
  o.simulate_perturbation = false;
  const StabilityReport r = phase == StabilityPhase::touchdown ? assess_touchdown(model, o)
                                                               : assess_stability(model, phase, o);
  if (!r.state.converged) return "";
  if (r.mode_kind == "fore-aft") return "fore-aft (gear walk)";
  const EnergyPerCycle& e = r.energy;
  const std::vector<std::pair<const char*, double>> sources{
      {"offset drag", e.offset_drag},
      // Mz is spin friction on a sliding patch, the aligning moment on the string tire.
      {model.contact == ContactModel::von_schlippe ? "aligning torque" : "spin torque",
       e.spin_torque},
      {"lateral forces", e.trail_lateral_force + e.lateral_friction + e.carcass_lever}};
  const auto best =
      std::max_element(sources.begin(), sources.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  return best->second > 0.0 ? best->first : "";
}

namespace {

const char* const kColours[] = {"#d62728", "#1f77b4", "#2ca02c", "#9467bd"};

// The cell of `m` nearest to the centroid of the cells where `inside` holds (a point inside the
// region where it is convex enough), or nullptr if there is none.
template <class Inside>
const MapCell* central_cell(const StabilityMap& m, Inside inside) {
  double cx = 0.0, cy = 0.0;
  int n = 0;
  for (const MapCell& c : m.cells)
    if (inside(c)) {
      cx += c.x;
      cy += c.y;
      ++n;
    }
  if (n == 0) return nullptr;
  cx /= n;
  cy /= n;
  const double sx = m.x.to - m.x.from, sy = m.y.to - m.y.from;
  const MapCell* best = nullptr;
  double best_d = 0.0;
  for (const MapCell& c : m.cells) {
    if (!inside(c)) continue;
    const double d = std::hypot((c.x - cx) / sx, (c.y - cy) / sy);
    if (!best || d < best_d) {
      best = &c;
      best_d = d;
    }
  }
  return best;
}

// The region where every model of the group is stable.
struct AllStable {
  const std::vector<ComputedMap>* maps;
  const StabilityMap* first;
  const std::vector<int>* group;
  bool operator()(const MapCell& c) const {
    const std::size_t i = static_cast<std::size_t>(&c - first->cells.data());
    for (int g : *group) {
      const MapCell& d = (*maps)[static_cast<std::size_t>(g)].map.cells[i];
      if (!d.valid || d.shimmy) return false;
    }
    return true;
  }
};

Overlay analyse_overlay(const std::vector<ComputedMap>& maps, const std::vector<int>& group,
                        const std::function<GearModel(ContactModel)>& model_of) {
  Overlay o;
  for (int g : group) {
    const StabilityMap& m = maps[static_cast<std::size_t>(g)].map;
    OverlayModel om;
    om.map = g;
    om.unstable = std::count_if(m.cells.begin(), m.cells.end(),
                                [](const MapCell& c) { return c.valid && c.shimmy; });
    std::vector<std::vector<int>> lobes = unstable_lobes(m);
    std::sort(lobes.begin(), lobes.end(),
              [](const auto& a, const auto& b) { return a.size() > b.size(); });
    for (const std::vector<int>& lobe : lobes) {
      OverlayLobe l;
      l.cell = &lobe_centre(m, lobe);
      GearModel model = model_of(m.contact);
      *gear_parameter(model.config, m.x.parameter) = l.cell->x;
      *gear_parameter(model.config, m.y.parameter) = l.cell->y;
      l.source = feeding_source(model, m.phase);
      om.lobes.push_back(l);
    }
    if (!om.lobes.empty()) {
      om.label_cell = om.lobes.front().cell;
      om.source = om.lobes.front().source;
    }
    o.models.push_back(om);
  }
  const StabilityMap& first = maps[static_cast<std::size_t>(group.front())].map;
  o.stable_cell = central_cell(first, AllStable{&maps, &first, &group});
  return o;
}

// One overlay: the boundaries of its maps and their labels.
nlohmann::json write_overlay(const OutputDir& dir, const std::vector<ComputedMap>& maps,
                             const std::vector<std::string>& bases, const Overlay& overlay) {
  const StabilityMap& first = maps[static_cast<std::size_t>(overlay.models.front().map)].map;
  const std::string name = "overlay_" + short_name(first.x.parameter) + "_" +
                           short_name(first.y.parameter) + "_" + to_string(first.phase);
  std::ostringstream gp, labels, plots;
  gp.precision(10);
  nlohmann::json summary{{"png", name + ".png"}, {"phase", to_string(first.phase)}};
  PlacedLabels placed;
  for (std::size_t k = 0; k < overlay.models.size(); ++k) {
    const OverlayModel& om = overlay.models[k];
    const StabilityMap& m = maps[static_cast<std::size_t>(om.map)].map;
    const std::string colour = kColours[k % 4];
    // Every lobe labelled at its centre (kept inside the frame), in the model's colour.
    for (std::size_t q = 0; q < om.lobes.size(); ++q) {
      const MapCell* c = om.lobes[q].cell;
      const std::string text = std::string(to_string(m.contact)) + " unstable: " +
                               (om.lobes[q].source.empty() ? "?" : om.lobes[q].source);
      const auto at = place_clear(m, inside_frame(m, c->x, c->y), text.size(), placed);
      labels << "set label " << 10 * (k + 1) + q << " \"" << text << "\" at " << at.x << "," << at.y
             << " " << at.align << " front boxed tc rgb '" << colour << "' font ',9'\n";
    }
    // A model without a boundary has no line to plot: its key entry comes from NaN.
    plots << (k ? ", " : "");
    if (om.unstable > 0)
      plots << "'" << bases[static_cast<std::size_t>(om.map)] << "_boundary.csv' using \""
            << m.x.parameter << "\":\"" << m.y.parameter << "\"";
    else
      plots << "NaN";
    plots << " with lines lw 2 lc rgb '" << colour << "' title '" << to_string(m.contact)
          << ": unstable in " << om.unstable << " of " << m.cells.size() << " cells'";
    summary["models"][to_string(m.contact)] = {
        {"unstable_cells", om.unstable}, {"cells", m.cells.size()}, {"fed_by", om.source}};
  }
  // The region where every model is stable, labelled at its centre.
  if (const MapCell* c = overlay.stable_cell) {
    const auto at = inside_frame(first, c->x, c->y);
    labels << "set label 1 \"stable in every model\" at " << at.x << "," << at.y << " " << at.align
           << " front boxed\n";
  }
  // The operating point (the configuration's values of the two parameters).
  const ComputedMap& cm = maps[static_cast<std::size_t>(overlay.models.front().map)];
  if ((cm.operating_x - first.x.from) * (cm.operating_x - first.x.to) <= 0.0 &&
      (cm.operating_y - first.y.from) * (cm.operating_y - first.y.to) <= 0.0)
    labels << "set label 2 'operating point' at " << cm.operating_x << "," << cm.operating_y
           << " point pt 9 ps 2 lc rgb 'black' offset 1.2,-0.6 front boxed font ',9'\n";
  gp << "set terminal pngcairo noenhanced size 820,680 font ',10'\nset output '" << name
     << ".png'\nset datafile separator ','\nset datafile columnheaders\n"
     << "set title \"stability boundaries, " << to_string(first.phase)
     << " (eigenvalues); each model is unstable on the side of its label,\\nwhich names the "
        "source that feeds the mode there (energy per cycle)\"\n"
     << "set xlabel '" << parameter_axis_label(first.x.parameter) << "'\nset ylabel '"
     << parameter_axis_label(first.y.parameter) << "'\n"
     << "set xrange [" << first.x.from << ":" << first.x.to << "]\nset yrange [" << first.y.from
     << ":" << first.y.to << "]\nset grid\nset key outside below\n"
     << "set style textbox opaque noborder\n"
     << labels.str() << "plot " << plots.str() << "\n";
  run_gnuplot(dir, name, gp.str());
  return summary;
}

}  // namespace

std::vector<Overlay> analyse_overlays(const std::vector<ComputedMap>& maps,
                                      const std::function<GearModel(ContactModel)>& model_of) {
  std::map<std::string, std::vector<int>> groups;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    const StabilityMap& m = maps[i].map;
    if (m.linear)
      groups[m.x.parameter + "|" + m.y.parameter + "|" + to_string(m.phase)].push_back(
          static_cast<int>(i));
  }
  std::vector<Overlay> out;
  for (const auto& [key, group] : groups)
    if (group.size() >= 2) out.push_back(analyse_overlay(maps, group, model_of));
  return out;
}

nlohmann::json write_boundary_overlays(const OutputDir& dir, const std::vector<ComputedMap>& maps,
                                       const std::vector<std::string>& bases,
                                       const std::vector<Overlay>& overlays) {
  nlohmann::json out = nlohmann::json::array();
  for (const Overlay& o : overlays) out.push_back(write_overlay(dir, maps, bases, o));
  return out;
}

}  // namespace contensou::app
