#include "contensou/identification/simulation.hpp"

#include <cmath>
#include <numbers>
#include <random>

#include "contensou/friction/error.hpp"
#include "contensou/friction/random.hpp"

namespace contensou {

MeasuredData diagram_kinematics(const DiagramSpec& s) {
  require_positive("radius", s.radius_m);
  require_positive("psi_min", s.psi_min);
  if (!(s.psi_max >= s.psi_min))
    throw InvalidArgument("psi_max", format_value(s.psi_max), "must be >= psi_min");
  if (s.points < 1) throw InvalidArgument("points", std::to_string(s.points), "must be >= 1");
  require_positive("spin speed", s.spin_speed_mps);
  MeasuredData d;
  d.source = "simulated";
  for (int i = 0; i < s.points; ++i) {
    const double frac = s.points == 1 ? 0.0 : static_cast<double>(i) / (s.points - 1);
    const double psi = s.psi_min * std::pow(s.psi_max / s.psi_min, frac);
    const double v = psi * s.spin_speed_mps;
    MeasuredPoint p;
    p.kinematics = {v * std::cos(s.direction_rad), v * std::sin(s.direction_rad),
                    s.spin_speed_mps / s.radius_m};
    if (s.time_step_s > 0.0) p.time = i * s.time_step_s;
    d.points.push_back(p);
  }
  return d;
}

void add_noise(MeasuredData& d, const DiagramSpec& s) {
  require_non_negative("noise level", s.noise_level);
  require_non_negative("noise growth", s.noise_growth);
  const bool growth = s.noise == SimulatedNoise::load_cell && s.noise_growth > 0.0;
  if (s.noise == SimulatedNoise::none || (s.noise_level == 0.0 && !growth)) return;
  // The same numbers with every standard library (contensou/friction/random.hpp).
  std::mt19937_64 rng(s.seed);
  StandardNormal normal;
  std::array<double, kChannels> peak{};
  for (const MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c)
      if (p.force[c]) peak[c] = std::max(peak[c], std::abs(*p.force[c]));
  for (MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c) {
      if (!p.force[c]) continue;
      double& y = *p.force[c];
      switch (s.noise) {
        case SimulatedNoise::relative_uniform:
          y *= 1.0 + s.noise_level * uniform_pm1(rng);
          break;
        case SimulatedNoise::relative_gaussian:
          y *= 1.0 + s.noise_level * normal(rng);
          break;
        case SimulatedNoise::additive_gaussian:
          y += s.noise_level * peak[c] * normal(rng);
          break;
        case SimulatedNoise::load_cell:
          y += (s.noise_level * peak[c] + s.noise_growth * std::abs(y)) * normal(rng);
          break;
        case SimulatedNoise::none:
          break;
      }
    }
}

template <class Eval>
MeasuredData simulate_with(const DiagramSpec& s, Eval&& eval) {
  MeasuredData d = diagram_kinematics(s);
  for (MeasuredPoint& p : d.points) {
    const Resultants<double> r = eval(p.kinematics);
    const double t = p.time.value_or(0.0);
    const double y[kChannels] = {
        r.Fx,
        r.Fy + s.rig.periodic_amplitude_n *
                   std::sin(2.0 * std::numbers::pi * t / s.rig.periodic_period_s),
        r.Mz - s.rig.viscous_torque * p.kinematics.omega};
    for (int c = 0; c < kChannels; ++c) {
      double v = y[c] + s.rig.offset[c];
      for (int src = 0; src < kChannels; ++src)
        if (src != c) v += s.rig.crosstalk[c][src] * y[src];
      p.force[c] = v;
    }
  }
  add_noise(d, s);
  return d;
}

MeasuredData simulate_diagrams(const FractionalLaw<double>& law, const DiagramSpec& s) {
  validate(law);
  return simulate_with(s,
                       [&](const Kinematics<double>& k) { return fractional_resultants(law, k); });
}

MeasuredData simulate_diagrams(const ExactModel<double>& model, const DiagramSpec& s) {
  return simulate_with(s, [&](const Kinematics<double>& k) {
    return exact_resultants(model, k, {1e-10}).resultants;
  });
}

SimulatedNoise parse_noise(const std::string& name) {
  if (name == "none") return SimulatedNoise::none;
  if (name == "relative-uniform") return SimulatedNoise::relative_uniform;
  if (name == "relative-gaussian") return SimulatedNoise::relative_gaussian;
  if (name == "additive-gaussian") return SimulatedNoise::additive_gaussian;
  if (name == "load-cell") return SimulatedNoise::load_cell;
  throw InvalidArgument(
      "noise", name,
      "use none, relative-uniform, relative-gaussian, additive-gaussian or load-cell");
}

std::string noise_name(SimulatedNoise n) {
  switch (n) {
    case SimulatedNoise::none:
      return "none";
    case SimulatedNoise::relative_uniform:
      return "relative-uniform";
    case SimulatedNoise::relative_gaussian:
      return "relative-gaussian";
    case SimulatedNoise::additive_gaussian:
      return "additive-gaussian";
    case SimulatedNoise::load_cell:
      return "load-cell";
  }
  return "?";
}

}  // namespace contensou
