// A landing's time history as a table: one list of columns (name, quantity, unit) serves the
// CSV header, the rows, the Python package's arrays and the plots' labels.
#pragma once

#include <string>
#include <vector>

#include "contensou/gear/landing_simulation.hpp"

namespace contensou::app {

struct HistoryColumn {
  std::string name;      // CSV header, with the unit as suffix: "Mz_nm"
  std::string quantity;  // in words, for legends: "friction torque Mz"
  std::string unit;      // for axis labels: "N m" ("1" for a pure number)
};

// t, the state vector (kStateSize entries, in the order of the gear's state indices), then the
// contact's load, patch, slip, friction, forces, brake torque and the rolling flag, then the
// moments about the strut axis of the torsion equation (landing_gear.hpp): the offset drag
// -(l + e_y) Fx, the trail's -e Fy and the torque link's -k_psi d(psi) - c_psi psi'.
const std::vector<HistoryColumn>& history_column_table();

// The names alone, in order.
const std::vector<std::string>& history_columns();

// One sample's values, in the order of history_columns().
std::vector<double> history_row(const LandingSample& s, const GearStructure& structure);

// The column named `name`; throws std::invalid_argument naming it if there is none.
const HistoryColumn& history_column(const std::string& name);

}  // namespace contensou::app
