#include "history.hpp"

#include <cmath>
#include <stdexcept>

namespace contensou::app {

const std::vector<HistoryColumn>& history_column_table() {
  static_assert(kStateSize == 13, "history_column_table: one entry per state");
  static const std::vector<HistoryColumn> table{
      {"t_s", "time t", "s"},
      {"y_m", "lateral deflection y of the strut at the axle", "m"},
      {"ydot_mps", "lateral deflection rate dy/dt", "m/s"},
      {"psi_rad", "torsion psi of the strut", "rad"},
      {"psidot_radps", "torsion rate dpsi/dt", "rad/s"},
      {"wheel_spin_radps", "wheel spin", "rad/s"},
      {"lambda_m", "string lateral deflection lambda", "m"},
      {"x_m", "fore-aft bending x", "m"},
      {"xdot_mps", "fore-aft bending rate dx/dt", "m/s"},
      {"wheel_spin2_radps", "second wheel spin", "rad/s"},
      {"carcass_y_m", "carcass lateral deflection", "m"},
      {"carcass_psi_rad", "carcass torsion", "rad"},
      {"u_x_m", "longitudinal tire deflection u (longitudinal relaxation)", "m"},
      {"u_x2_m", "second wheel's longitudinal tire deflection", "m"},
      {"load_n", "normal load N", "N"},
      {"patch_radius_m", "patch radius R", "m"},
      {"vx_mps", "patch sliding velocity vx", "m/s"},
      {"vy_mps", "patch sliding velocity vy", "m/s"},
      {"omega_radps", "patch spin omega", "rad/s"},
      {"slip_ratio", "slip ratio vx/V", "1"},
      {"friction", "friction coefficient f", "1"},
      {"Fx_n", "friction force Fx", "N"},
      {"Fy_n", "friction force Fy", "N"},
      {"Mz_nm", "friction torque Mz", "N m"},
      {"brake_nm", "brake torque", "N m"},
      {"rolling", "rolling (1) or sliding (0)", "1"},
      {"offset_drag_moment_nm", "offset drag moment -l Fx", "N m"},
      {"trail_moment_nm", "trail moment -e Fy", "N m"},
      {"torque_link_nm", "torque-link moment -k psi - c psi'", "N m"}};
  return table;
}

const std::vector<std::string>& history_columns() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const HistoryColumn& c : history_column_table()) n.push_back(c.name);
    return n;
  }();
  return names;
}

std::vector<double> history_row(const LandingSample& s, const GearStructure& g) {
  const ContactState& c = s.contact;
  std::vector<double> row{s.t};
  for (int i = 0; i < kStateSize; ++i) row.push_back(s.x[i]);
  for (double v :
       {c.load_n, c.patch_radius_m, c.slip.vx, c.slip.vy, c.slip.omega, c.slip_ratio, c.friction,
        c.force.Fx, c.force.Fy, c.force.Mz, c.brake_torque_nm, s.rolling ? 1.0 : 0.0})
    row.push_back(v);
  // The torsion equation's moments (landing_gear.hpp): the drag's lever grows by e_y with
  // carcass compliance; d(psi) the torque link's smooth dead zone (GearStructure::freeplay_rad).
  const double lever = g.offset_m + (g.carcass_compliance() ? s.x[kCarcassY] : 0.0);
  const double psi = s.x[kPsi], delta = g.freeplay_rad;
  double d = psi;
  if (delta > 0.0) {
    const double w = delta / 20.0, a = psi - delta, b = psi + delta;
    d = 0.5 * (a + std::sqrt(a * a + w * w)) + 0.5 * (b - std::sqrt(b * b + w * w));
  }
  row.push_back(-lever * c.force.Fx);
  row.push_back(-g.trail_m * c.force.Fy);
  row.push_back(-g.torsional_stiffness_nm_per_rad * d -
                g.torsional_damping_nms_per_rad * s.x[kPsiDot]);
  return row;
}

const HistoryColumn& history_column(const std::string& name) {
  for (const HistoryColumn& c : history_column_table())
    if (c.name == name) return c;
  throw std::invalid_argument("no history column '" + name + "'");
}

}  // namespace contensou::app
