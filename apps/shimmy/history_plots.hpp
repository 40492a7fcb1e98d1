// The time-history pictures of the shimmy demo: one PNG per quantity, the models side by side
// on one y-range, columns selected by their CSV header names.
#pragma once

#include <string>
#include <vector>

#include "contensou/gear/landing_simulation.hpp"
#include "output_folder.hpp"

namespace contensou::app {

struct HistoryPanel {
  std::string name;                  // the PNG's base name: "torque"
  std::string axis;                  // the y axis in words, without unit: "friction torque"
  std::vector<std::string> columns;  // history columns, all of one unit
};

const std::vector<HistoryPanel>& history_panels();

// "Mz [N m]"-style axis label: the panel's axis and the unit of its columns ("-" for a pure
// number). Throws std::logic_error if the columns do not share a unit.
std::string panel_axis_label(const HistoryPanel& panel);

// The gnuplot script of one panel over the runs, which read <model>.csv in the same folder.
std::string history_plot_script(const HistoryPanel& panel, const std::vector<LandingRun>& runs);

// Writes and runs every panel's script in `dir`.
void draw_histories(const OutputDir& dir, const std::vector<LandingRun>& runs);

}  // namespace contensou::app
