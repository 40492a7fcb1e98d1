#include "contensou/identification/outliers.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

namespace contensou {

namespace {

double median(std::vector<double> v) {
  const std::size_t n = v.size(), h = n / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h), v.end());
  if (n % 2 == 1) return v[h];
  const double upper = v[h];
  return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(h)));
}

// Two rows in the same regime: both at rest, or spinning the same way with the sliding
// direction within 0.2 rad and v / |omega| within a factor 5 (both pure spin or both pure
// sliding counting as equal). A glitch is judged only against rows like it: a lone row of
// another regime (pure spin after a sweep) may differ from its neighbours for good reason.
bool same_regime(const Kinematics<double>& a, const Kinematics<double>& b) {
  const double va = std::hypot(a.vx, a.vy), vb = std::hypot(b.vx, b.vy);
  const double wa = std::abs(a.omega), wb = std::abs(b.omega);
  if ((va == 0.0) != (vb == 0.0) || (wa == 0.0) != (wb == 0.0)) return false;
  if (va == 0.0 && wa == 0.0) return true;  // both at rest
  if (wa > 0.0 && (a.omega > 0.0) != (b.omega > 0.0)) return false;
  if (va > 0.0) {
    const double turn = std::remainder(std::atan2(a.vy, a.vx) - std::atan2(b.vy, b.vx), 2 * M_PI);
    if (std::abs(turn) > 0.2) return false;
  }
  if (va > 0.0 && wa > 0.0) return std::abs(std::log((va / wa) / (vb / wb))) < std::log(5.0);
  return true;
}

// d_k = e_k - median of those of the (up to) two values before and two after it that are in
// its regime; NaN where fewer than two are (nothing to compare with).
std::vector<double> neighbour_differences(const std::vector<double>& e,
                                          const std::vector<const Kinematics<double>*>& k) {
  const std::size_t n = e.size();
  std::vector<double> d(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> around;
    for (std::size_t j = i >= 2 ? i - 2 : 0; j <= std::min(n - 1, i + 2); ++j)
      if (j != i && same_regime(*k[i], *k[j])) around.push_back(e[j]);
    if (around.size() >= 2) d[i] = e[i] - median(around);
  }
  return d;
}

// The robust noise scale at value k: 1.4826 median |d| / 1.14 over the 16 values up to it and
// over the 16 from it on, the larger of the two. Local, because the noise of a channel changes
// along a file (load-cell noise that grows with the load, sweeps in other directions); the
// larger side, so that a value next to a noisier stretch is judged by that one.
double local_sigma(const std::vector<double>& d, std::size_t k) {
  const std::size_t side = 15, n = d.size();
  auto side_median = [&](std::size_t from, std::size_t to) {
    std::vector<double> window;
    for (std::size_t j = from; j < to; ++j)
      if (std::isfinite(d[j])) window.push_back(std::abs(d[j]));
    return window.size() >= 4 ? median(window) : 0.0;
  };
  const double before = side_median(k >= side ? k - side : 0, k + 1);
  const double after = side_median(k, std::min(n, k + side + 1));
  return 1.4826 * std::max(before, after) / 1.14;
}

// Where a row stands among the others, whatever the file's order: its load (in steps of 2 %),
// its spin sense, its sliding direction (in steps of 0.05 rad), then its log v / |omega| and
// |omega|. Rows next to each other in this order are neighbours in the rig's programme.
struct KinematicKey {
  long load, spin, direction;
  double ratio, rate;
  bool operator<(const KinematicKey& o) const {
    return std::tie(load, spin, direction, ratio, rate) <
           std::tie(o.load, o.spin, o.direction, o.ratio, o.rate);
  }
};

KinematicKey key_of(const MeasuredPoint& p) {
  const Kinematics<double>& k = p.kinematics;
  const double v = std::hypot(k.vx, k.vy), w = std::abs(k.omega);
  KinematicKey key{};
  key.load = p.normal_load && *p.normal_load > 0.0
                 ? std::lround(std::log(*p.normal_load) / std::log(1.02))
                 : 0;
  key.spin = k.omega > 0.0 ? 1 : (k.omega < 0.0 ? -1 : 0);
  key.direction = v > 0.0 ? std::lround(std::atan2(k.vy, k.vx) / 0.05) : 1000;
  key.ratio = v > 0.0 && w > 0.0 ? std::log(v / w) : (v > 0.0 ? 1e300 : -1e300);
  key.rate = w;
  return key;
}

// A channel's measured rows in kinematic order, with their residuals.
struct OrderedChannel {
  std::vector<int> rows;
  std::vector<double> e;
  std::vector<const Kinematics<double>*> kinematics;
};

OrderedChannel ordered_channel(const MeasuredData& data,
                               const std::vector<Resultants<double>>& prediction, int c) {
  std::vector<std::pair<KinematicKey, int>> keyed;
  for (std::size_t i = 0; i < data.points.size(); ++i)
    if (data.points[i].force[c]) keyed.emplace_back(key_of(data.points[i]), static_cast<int>(i));
  std::stable_sort(keyed.begin(), keyed.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  OrderedChannel out;
  for (const auto& [key, i] : keyed) {
    out.rows.push_back(i);
    out.e.push_back(*data.points[i].force[c] - prediction[i].vector()(c));
    out.kinematics.push_back(&data.points[i].kinematics);
  }
  return out;
}

void examine_channel(const MeasuredData& data, const std::vector<Resultants<double>>& prediction,
                     int c, double threshold, std::vector<Outlier>& out) {
  const OrderedChannel ch = ordered_channel(data, prediction, c);
  const std::vector<int>& rows = ch.rows;
  if (ch.e.size() < 8) return;
  const std::vector<double> d = neighbour_differences(ch.e, ch.kinematics);
  double largest = 0.0;
  for (int i : rows) largest = std::max(largest, std::abs(*data.points[i].force[c]));
  for (std::size_t k = 0; k < d.size(); ++k) {
    const double sigma = std::max(local_sigma(d, k), 1e-9 * largest);  // exact data: no scatter
    // The row's own residual must carry the difference (at least half of it, with its sign): a
    // good row beside glitched ones differs from its neighbours by their residual, not its own.
    const bool own = ch.e[k] * d[k] > 0.0 && std::abs(ch.e[k]) >= 0.5 * std::abs(d[k]);
    if (std::isfinite(d[k]) && sigma > 0.0 && std::abs(d[k]) > threshold * sigma && own) {
      const MeasuredPoint& p = data.points[rows[k]];
      const std::size_t i = static_cast<std::size_t>(rows[k]);
      out.push_back({rows[k], p.line, c, *p.force[c], d[k] / sigma, point_location(data, i),
                     data.in_file_unit(i, c, *p.force[c])});
    }
  }
}

}  // namespace

std::string Outlier::describe(const std::string& source) const {
  char buf[96];
  std::snprintf(buf, sizeof buf, " %s %+.1f sigma (%.6g %s", kChannelColumns[channel],
                residual_sigma, value, channel == 2 ? "N m" : "N");
  const std::string at = !where.empty() ? where
                         : line > 0     ? source + ":" + std::to_string(line)
                                        : "point " + std::to_string(point);
  return at + buf + (file_value.empty() ? "" : " = " + file_value) + ")";
}

std::array<double, kChannels> neighbour_scatter(
    const MeasuredData& data, const std::vector<Resultants<double>>& prediction,
    const std::function<double(int c, std::size_t i)>& row_scale) {
  std::array<double, kChannels> scale{};
  if (prediction.size() != data.points.size()) return scale;
  for (int c = 0; c < kChannels; ++c) {
    const OrderedChannel ch = ordered_channel(data, prediction, c);
    // The rms of d over its smaller 98 % (a glitch left in does not set it), / 1.067 (d of
    // Gaussian noise, 1.14 sigma, trimmed of its largest 2 %: 1.067 sigma, by simulation of
    // 2e5 values): comparable
    // with the residual's rms whatever the noise does along the file (a median would follow
    // the quietest half: sweeps at small loads, a channel near zero in a lateral sweep). The
    // 98 % by d / row scale when the noise grows with the value.
    std::vector<std::pair<double, double>> ad;  // (|d| / scale, |d|)
    const std::vector<double> d = neighbour_differences(ch.e, ch.kinematics);
    for (std::size_t k = 0; k < d.size(); ++k) {
      if (!std::isfinite(d[k])) continue;
      const double s = row_scale ? row_scale(c, static_cast<std::size_t>(ch.rows[k])) : 1.0;
      ad.emplace_back(s > 0.0 ? std::abs(d[k]) / s : std::abs(d[k]), std::abs(d[k]));
    }
    std::sort(ad.begin(), ad.end());
    const std::size_t kept = ad.size() - ad.size() / 50;
    double ss = 0.0;
    for (std::size_t k = 0; k < kept; ++k) ss += ad[k].second * ad[k].second;
    scale[c] = ad.size() >= 4 ? std::sqrt(ss / static_cast<double>(kept)) / 1.067 : 0.0;
  }
  return scale;
}

std::vector<Outlier> find_outliers(const MeasuredData& data,
                                   const std::vector<Resultants<double>>& prediction,
                                   double threshold_sigma) {
  std::vector<Outlier> out;
  if (prediction.size() != data.points.size()) return out;
  for (int c = 0; c < kChannels; ++c) examine_channel(data, prediction, c, threshold_sigma, out);
  std::sort(out.begin(), out.end(), [](const Outlier& a, const Outlier& b) {
    return std::abs(a.residual_sigma) > std::abs(b.residual_sigma);
  });
  return out;
}

MeasuredData without_outliers(const MeasuredData& data, const std::vector<Outlier>& outliers) {
  MeasuredData clean = data;
  for (const Outlier& o : outliers)
    if (o.point >= 0 && o.point < static_cast<int>(clean.points.size()) && o.channel >= 0 &&
        o.channel < kChannels)
      clean.points[o.point].force[o.channel].reset();
  std::erase_if(clean.points,
                [](const MeasuredPoint& p) { return !p.force[0] && !p.force[1] && !p.force[2]; });
  return clean;
}

}  // namespace contensou
