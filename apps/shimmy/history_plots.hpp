// The time-history pictures of the shimmy demo: one PNG per quantity, the models overlaid in
// their colours (model_colours.hpp) panel by panel, the events marked (touchdown, full load,
// each model's spin-up, brake on and off), the analysis window shaded; columns selected by
// their CSV header names. A degree of freedom that is off has no picture.
#pragma once

#include <string>
#include <vector>

#include "contensou/gear/landing_simulation.hpp"
#include "output_folder.hpp"

namespace contensou::app {

struct HistoryPanel {
  std::string axis;    // the y axis in words, without unit: "torsion psi of the strut"
  std::string column;  // a history column
  // The decoupled model on the right axis (its Coulomb spin torque's spikes would squash the
  // other models' curves).
  bool decoupled_right = false;
};

struct HistoryFigure {
  std::string name;   // the PNG's base name: "torque"
  std::string title;  // what the figure shows
  std::vector<HistoryPanel> panels;
};

// The figures for a gear (fore-aft only when structure.fore_aft_stiffness_n_per_m > 0).
std::vector<HistoryFigure> history_figures(const GearStructure& structure);

// "torsion psi of the strut [rad]": the panel's axis and its column's unit ("-" for a pure
// number).
std::string panel_axis_label(const HistoryPanel& panel);

// The gnuplot script of one figure over the runs, which read <model>.csv in the same folder
// (written with `structure`, history_row()).
std::string history_plot_script(const HistoryFigure& figure, const std::vector<LandingRun>& runs,
                                const GearStructure& structure);

// Writes and runs every figure's script in `dir`.
void draw_histories(const OutputDir& dir, const std::vector<LandingRun>& runs,
                    const GearStructure& structure);

}  // namespace contensou::app
