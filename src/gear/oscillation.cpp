#include "contensou/gear/oscillation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"

namespace contensou {

OscillationEstimate analyse_oscillation(std::span<const double> t, std::span<const double> rate,
                                        std::span<const double> position) {
  if (rate.size() != t.size() || position.size() != t.size())
    throw InvalidArgument("rate, position",
                          std::to_string(rate.size()) + ", " + std::to_string(position.size()),
                          "must have as many samples as t (" + std::to_string(t.size()) + ")");
  // Zero crossings of the rate, located by linear interpolation; position at each.
  std::vector<double> tc, pc;
  std::vector<std::size_t> ic;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if ((rate[i - 1] < 0.0) == (rate[i] < 0.0) || rate[i - 1] == rate[i]) continue;
    const double w = rate[i - 1] / (rate[i - 1] - rate[i]);
    tc.push_back(t[i - 1] + w * (t[i] - t[i - 1]));
    pc.push_back(position[i - 1] + w * (position[i] - position[i - 1]));
    ic.push_back(i);
  }
  OscillationEstimate e;
  if (tc.size() < 5) return e;
  e.half_cycles = static_cast<int>(tc.size()) - 1;
  e.frequency_hz = e.half_cycles / (2.0 * (tc.back() - tc.front()));
  e.first_amplitude = 0.5 * std::abs(pc[1] - pc[0]);
  e.last_amplitude = 0.5 * std::abs(pc.back() - pc[pc.size() - 2]);
  // ln of the rate's peak in each half cycle against the peak's time.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (std::size_t k = 1; k < ic.size(); ++k) {
    std::size_t best = ic[k - 1];
    for (std::size_t i = ic[k - 1]; i < ic[k]; ++i)
      if (std::abs(rate[i]) > std::abs(rate[best])) best = i;
    if (!(std::abs(rate[best]) > 0.0)) continue;
    const double x = t[best], y = std::log(std::abs(rate[best]));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  const double den = n * sxx - sx * sx;
  e.growth_rate_per_s = n >= 2 && den > 0.0 ? (n * sxy - sx * sy) / den : 0.0;
  return e;
}

}  // namespace contensou
