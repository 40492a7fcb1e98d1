#include "contensou/gear/cycle_trend.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contensou {

const char* to_string(CycleState s) {
  switch (s) {
    case CycleState::not_measured:
      return "not_measured";
    case CycleState::limit_cycle:
      return "limit_cycle";
    case CycleState::settled_small:
      return "settled_below_threshold";
    case CycleState::growing:
      return "still_growing";
    case CycleState::decaying:
      return "decaying";
  }
  return "?";
}

double settling_band(double eigen_growth_per_s) {
  return std::max(0.1 * std::abs(eigen_growth_per_s), 0.03);
}

namespace {

// Least-squares slope of ln(a) against t (a > 0 only); 0 with fewer than three.
double log_slope(const std::vector<double>& t, const std::vector<double>& a) {
  double n = 0, st = 0, sl = 0, stt = 0, stl = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (!(a[k] > 0.0)) continue;
    const double l = std::log(a[k]);
    n += 1;
    st += t[k];
    sl += l;
    stt += t[k] * t[k];
    stl += t[k] * l;
  }
  const double d = n * stt - st * st;
  return n >= 3 && d > 0.0 ? (n * stl - st * sl) / d : 0.0;
}

// Half the swing of psi over the samples in [from, to].
double half_swing(const std::vector<double>& t, const std::vector<double>& psi, double from,
                  double to) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= from && t[i] <= to) {
      lo = std::min(lo, psi[i]);
      hi = std::max(hi, psi[i]);
    }
  return lo <= hi ? 0.5 * (hi - lo) : 0.0;
}

}  // namespace

CycleTrend cycle_trend(const std::vector<double>& t, const std::vector<double>& psi,
                       const std::vector<double>& psi_rate, const GearStructure& g,
                       const CycleWindow& w, double eigen_growth_per_s, double threshold_rad) {
  CycleTrend c;
  c.band_per_s = settling_band(eigen_growth_per_s);
  const double P = w.period_s, end = w.end_s;
  if (!(P > 0.0) || t.empty() || end - kTrendPeriods * P < w.start_s) return c;
  // Per period k (0: the last): the extremes of psi and of the torsional moment.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> lo(kTrendPeriods, kInf), hi(kTrendPeriods, -kInf);
  double mlo = kInf, mhi = -kInf;
  for (std::size_t i = 0; i < t.size(); ++i) {
    const double back = end - t[i];
    if (back < 0.0 || back > kTrendPeriods * P) continue;
    const int k = std::min(static_cast<int>(back / P), kTrendPeriods - 1);
    lo[static_cast<std::size_t>(k)] = std::min(lo[static_cast<std::size_t>(k)], psi[i]);
    hi[static_cast<std::size_t>(k)] = std::max(hi[static_cast<std::size_t>(k)], psi[i]);
    if (k == 0) {
      const double m =
          g.torsional_stiffness_nm_per_rad * psi[i] + g.torsional_damping_nms_per_rad * psi_rate[i];
      mlo = std::min(mlo, m);
      mhi = std::max(mhi, m);
    }
  }
  std::vector<double> mid, swing;
  for (int k = kTrendPeriods - 1; k >= 0; --k) {
    const auto u = static_cast<std::size_t>(k);
    mid.push_back(end - (k + 0.5) * P);
    swing.push_back(lo[u] <= hi[u] ? 0.5 * (hi[u] - lo[u]) : 0.0);
  }
  c.measured = true;
  c.earlier_amplitude_rad = swing.front();
  c.amplitude_rad = swing.back();
  c.torque_link_nm = mlo <= mhi ? 0.5 * (mhi - mlo) : 0.0;
  c.trend_per_s = log_slope(mid, swing);
  // The window holds kTrendPeriods >= 2 periods, so the period ending at its middle lies in it.
  c.start_amplitude_rad = half_swing(t, psi, w.start_s, w.start_s + P);
  c.midway_s = 0.5 * (w.start_s + end);
  c.midway_amplitude_rad = half_swing(t, psi, c.midway_s - P, c.midway_s);
  const double change = c.amplitude_rad - c.midway_amplitude_rad;
  const bool in_band = std::abs(c.trend_per_s) <= c.band_per_s;
  c.drifting = in_band && std::abs(change) > kSettledChange * c.midway_amplitude_rad;
  if (!in_band)
    c.state = c.trend_per_s > 0.0 ? CycleState::growing : CycleState::decaying;
  else if (c.drifting)
    c.state = change > 0.0 ? CycleState::growing : CycleState::decaying;
  else
    c.state = c.amplitude_rad > threshold_rad ? CycleState::limit_cycle : CycleState::settled_small;
  return c;
}

}  // namespace contensou
