#include "contensou/identification/sweeps.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <tuple>

#include "contensou/friction/error.hpp"

namespace contensou {

namespace {

// Level of each value: sorted, a new level where a value exceeds the previous one by more than
// 3 % (of the larger magnitude, and 1e-12 absolute). NaN values get level -1.
std::vector<int> levels(const std::vector<double>& v) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i])) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  std::vector<int> out(v.size(), -1);
  int level = -1;
  double previous = 0.0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const double x = v[order[k]];
    const double gap = 0.03 * std::max(std::abs(x), std::abs(previous)) + 1e-12;
    if (k == 0 || x - previous > gap) ++level;
    out[order[k]] = level;
    previous = x;
  }
  return out;
}

std::string number(const char* format, double x) {
  char b[64];
  std::snprintf(b, sizeof b, format, x);
  return b;
}

struct Key {
  int file, load, spin, sign, direction;  // direction: degrees, 1000 for pure spin
  bool operator<(const Key& o) const {
    return std::tie(file, load, spin, sign, direction) <
           std::tie(o.file, o.load, o.spin, o.sign, o.direction);
  }
};

// The label of each sweep: only the parts that vary between the sweeps.
void label(std::vector<Sweep>& sweeps, const std::vector<Key>& keys,
           const std::vector<std::string>& files) {
  auto varies = [&](int Key::*part) {
    for (const Key& k : keys)
      if (k.*part != keys.front().*part) return true;
    return false;
  };
  const bool file = varies(&Key::file), load = varies(&Key::load), spin = varies(&Key::spin);
  const bool sign = varies(&Key::sign), dir = varies(&Key::direction);
  for (Sweep& s : sweeps) {
    std::vector<std::string> parts;
    if (file && s.file < static_cast<int>(files.size())) parts.push_back(files[s.file]);
    if (load && s.load_n) parts.push_back("Fz " + number("%.3g", *s.load_n / 1e3) + " kN");
    if (spin) parts.push_back("u " + number("%.2g", s.spin_speed_mps) + " m/s");
    if (sign) parts.push_back(s.spin_sign > 0 ? "omega > 0" : "omega < 0");
    if (dir)
      parts.push_back(s.direction_rad
                          ? number("%.0f", *s.direction_rad * 180.0 / std::numbers::pi) + " deg"
                          : std::string("pure spin"));
    for (std::size_t k = 0; k < parts.size(); ++k) s.label += (k ? ", " : "") + parts[k];
    if (s.label.empty()) s.label = "all rows";
  }
}

// The grouping key of each point: file, load level, spin level, sign of omega, direction.
std::vector<Key> keys_of(const MeasuredData& data, const std::vector<double>& load,
                         const std::vector<double>& spin) {
  const std::vector<int> load_level = levels(load), spin_level = levels(spin);
  std::vector<Key> keys;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const Kinematics<double>& q = data.points[i].kinematics;
    const bool still = q.vx == 0.0 && q.vy == 0.0;
    int degrees = static_cast<int>(std::lround(std::atan2(q.vy, q.vx) * 180.0 / std::numbers::pi));
    if (degrees == -180) degrees = 180;
    keys.push_back({data.points[i].source, load_level[i], spin_level[i], q.omega < 0.0 ? -1 : 1,
                    still ? 1000 : degrees});
  }
  return keys;
}

}  // namespace

std::vector<Sweep> sweeps_of(const MeasuredData& data, double radius_m) {
  if (!(std::isfinite(radius_m) && radius_m > 0.0))
    throw InvalidArgument("radius_m", number("%g", radius_m), "must be positive and finite");
  const std::size_t n = data.points.size();
  std::vector<double> load(n), spin(n), psi(n);
  for (std::size_t i = 0; i < n; ++i) {
    const MeasuredPoint& p = data.points[i];
    load[i] = p.normal_load.value_or(std::nan(""));
    spin[i] = std::abs(p.kinematics.omega) * radius_m;
    const double v = std::hypot(p.kinematics.vx, p.kinematics.vy);
    psi[i] = spin[i] > 0.0 ? v / spin[i] : (v > 0.0 ? INFINITY : 0.0);
  }
  const std::vector<Key> keys = keys_of(data, load, spin);
  std::map<Key, std::size_t> index;  // each key's sweep, in key order
  for (const Key& key : keys) index.emplace(key, 0);
  std::vector<Sweep> sweeps;
  std::vector<Key> sweep_keys;
  for (auto& [key, at] : index) {
    at = sweeps.size();
    sweep_keys.push_back(key);
    Sweep s;
    s.file = key.file;
    s.spin_sign = key.sign;
    if (key.direction != 1000) s.direction_rad = key.direction * std::numbers::pi / 180.0;
    sweeps.push_back(s);
  }
  std::vector<double> load_sum(sweeps.size(), 0.0), spin_sum(sweeps.size(), 0.0);
  std::vector<int> loads(sweeps.size(), 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t s = index.at(keys[i]);
    sweeps[s].points.push_back(i);
    spin_sum[s] += spin[i];
    if (std::isfinite(load[i])) load_sum[s] += load[i], ++loads[s];
  }
  for (std::size_t s = 0; s < sweeps.size(); ++s) {
    Sweep& w = sweeps[s];
    w.spin_speed_mps = spin_sum[s] / static_cast<double>(w.points.size());
    if (loads[s] > 0) w.load_n = load_sum[s] / loads[s];
    std::stable_sort(w.points.begin(), w.points.end(),
                     [&](std::size_t a, std::size_t b) { return psi[a] < psi[b]; });
  }
  label(sweeps, sweep_keys, data.sources);
  return sweeps;
}

namespace {

// Marks the rows at the smallest and largest finite value of x(row).
template <class Value>
void keep_extremes(const MeasuredData& data, Value x, std::vector<char>& keep) {
  std::size_t lo = data.points.size(), hi = data.points.size();
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const double v = x(data.points[i]);
    if (!std::isfinite(v)) continue;
    if (lo == data.points.size() || v < x(data.points[lo])) lo = i;
    if (hi == data.points.size() || v > x(data.points[hi])) hi = i;
  }
  if (lo < keep.size()) keep[lo] = keep[hi] = 1;
}

}  // namespace

std::vector<char> stratified_sample(const MeasuredData& data, double radius_m, std::size_t target) {
  const std::size_t n = data.points.size();
  std::vector<char> keep(n, 1);
  if (n <= target || target == 0) return keep;
  std::fill(keep.begin(), keep.end(), 0);
  const double step = static_cast<double>(n) / static_cast<double>(target);
  for (const Sweep& s : sweeps_of(data, radius_m)) {
    const std::size_t m = s.points.size();
    for (double k = 0.0; k < static_cast<double>(m); k += step)
      keep[s.points[static_cast<std::size_t>(k)]] = 1;
    keep[s.points.back()] = 1;
  }
  const double nan = std::nan("");
  keep_extremes(
      data, [&](const MeasuredPoint& p) { return p.normal_load.value_or(nan); }, keep);
  keep_extremes(
      data, [&](const MeasuredPoint& p) { return p.time.value_or(nan); }, keep);
  keep_extremes(
      data, [](const MeasuredPoint& p) { return p.source * 4294967296.0 + p.line; }, keep);
  for (std::size_t r = 0; r < data.recorded.size(); ++r)
    keep_extremes(
        data, [&](const MeasuredPoint& p) { return r < p.recorded.size() ? p.recorded[r] : nan; },
        keep);
  return keep;
}

}  // namespace contensou
