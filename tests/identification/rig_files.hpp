// Synthetic tire-test files as a rig writes them (for the identification tests): sweeps in
// several sliding directions at several normal loads, a time stamp, recorded channels the law
// does not know (a temperature), friction that falls with the load, drifts over the run or
// follows the temperature, a misaligned rig, glitches, rows in any order. The forces are the
// seed tire's exact law (its Table 1 profile, R = 0.087 m, kx = 0.14) at each row's own load:
// pressure in proportion to the load at fixed radius.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <vector>

#include "contensou/friction/exact_law.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou::testing {

struct RigFile {
  std::vector<double> loads{4535.0};  // [N], a programme of sweeps at each
  std::vector<double> directions{0.0, 0.5 * std::numbers::pi};
  int points = 20;          // per sweep, psi = v / u log-spaced in [0.01, 100]
  double spin_speed = 1.0;  // u = |omega| R [m/s]
  double friction = 0.3;    // f at the reference load
  double reference_load = 4535.0;
  double time_step = 0.5;  // [s] between rows
  // f(row) = friction * factor(row): the load, the time and the recorded temperature of the row.
  std::function<double(double load, double time, double temperature)> factor;
  // The recorded temperature of a row (a column "T [degC]"); empty: no such column.
  std::function<double(int sweep, double time)> temperature;
  double slip_angle_offset = 0.0;  // [rad]: the file's vy is the rig's vy - vx tan(delta)
  double noise = 0.01;             // of each channel's peak, white
  unsigned seed = 7;
  bool shuffle = false;
};

// The seed tire's exact law at unit pressure and unit friction (built once).
inline const ExactLaw& seed_law() {
  static const ExactLaw law = [] {
    ContactPatch p = seed_tire_patch();
    p.reference_pressure_pa = 1.0;
    p.friction = 1.0;
    return make_exact_law(make_exact_model(p), ExactLawOptions{1e-8});
  }();
  return law;
}

inline MeasuredData make_rig_file(const RigFile& s) {
  const ExactLaw& law = seed_law();
  MeasuredData d;
  d.source = "rig.csv";
  const double R = law.radius;
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> gauss;
  int row = 0, sweep = 0;
  for (double load : s.loads)
    for (double dir : s.directions) {
      for (int i = 0; i < s.points; ++i, ++row) {
        const double psi = 0.01 * std::pow(1e4, i / (s.points - 1.0));
        const double v = psi * s.spin_speed, w = s.spin_speed / R;
        MeasuredPoint p;
        p.line = row + 2;
        p.time = row * s.time_step;
        p.normal_load = load;
        const double temp = s.temperature ? s.temperature(sweep, *p.time) : 0.0;
        if (s.temperature) p.recorded.push_back(temp + 273.15);
        // The rig drives (vx, vy_true); the file records vy_true - vx tan(delta).
        const Kinematics<double> truth{v * std::cos(dir), v * std::sin(dir), w};
        p.kinematics = {truth.vx, truth.vy - truth.vx * std::tan(s.slip_angle_offset), w};
        ExactLawParameters<double> lp;
        lp.pressure = load / (R * R * law.load_area);
        lp.friction = s.friction * (s.factor ? s.factor(load, *p.time, temp) : 1.0);
        lp.kx = 0.14;
        const Resultants<double> f = exact_law_resultants(law, lp, truth);
        p.force = {f.Fx, f.Fy, f.Mz};
        d.points.push_back(p);
      }
      ++sweep;
    }
  if (s.temperature)
    d.recorded.push_back({"T", "T [degC]", 8, "degC", "K", "temperature", 1.0, 273.15});
  std::array<double, kChannels> peak{};
  for (const MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c) peak[c] = std::max(peak[c], std::abs(*p.force[c]));
  for (MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c) *p.force[c] += s.noise * peak[c] * gauss(rng);
  if (s.shuffle) std::shuffle(d.points.begin(), d.points.end(), rng);
  return d;
}

}  // namespace contensou::testing
