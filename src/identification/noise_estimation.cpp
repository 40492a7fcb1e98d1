// The noise scales of a fit from its residuals: additive, relative, robust and affine
// (sigma = a + b |y|) noise. See fit_problem.hpp and fit.hpp.
#include "fit_problem.hpp"
#include "test_seams.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace contensou {
using namespace detail;  // NOLINT: this file implements part of fit_problem.hpp

namespace {

// Smallest noise scale estimated from the scatter: 1e-6 of the channel's magnitude (additive),
// 1e-6 (relative). Below it the weights would come from rounding, not from noise.
constexpr double kNoiseFloor = 1e-6;

// Affine noise of one channel from its residuals e_i and |yhat_i|: sigma_i = a + b |yhat_i|
// by maximum likelihood of the Gaussian residuals (pseudo-likelihood of a variance function,
// Carroll & Ruppert 1988, ch. 3). Written sigma_i = s w_i(r), w_i = r + (1 - r) |yhat_i| / peak
// (s is sigma at the channel's peak), the scale has the closed form s^2(r) = sum (e_i / w_i)^2 /
// dof, and r in [1e-4, 1] minimises the profile -2 log L(r) = n log s^2(r) + 2 sum log w_i(r):
// a grid of 49 points in log r, then golden section in the best one's bracket. a = s r,
// b = s (1 - r) / peak; r = 1 is the additive model, r = 1e-4 (a = 1e-4 of sigma at the peak)
// is as near to purely relative noise (a = 0) as the weights of the values near zero allow.
std::array<double, 2> affine_noise(const std::vector<double>& e, const std::vector<double>& y,
                                   double peak, double dof, double s_floor) {
  const auto n = static_cast<double>(e.size());
  const auto sum_sq = [&](double r, double* log_w) {
    double ss = 0.0;
    *log_w = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) {
      const double w = r + (1.0 - r) * y[i] / peak;
      ss += e[i] * e[i] / (w * w);
      *log_w += std::log(w);
    }
    return std::max(ss, 1e-300);
  };
  // -2 log L at r = 10^u, u in [log10 r_min, 0].
  const auto m2ll = [&](double u) {
    double log_w = 0.0;
    const double ss = sum_sq(std::pow(10.0, u), &log_w);
    return n * std::log(ss) + 2.0 * log_w;
  };
  constexpr double u_min = -4.0;
  constexpr int grid = 48;
  const auto at = [&](int k) { return u_min * (1.0 - static_cast<double>(k) / grid); };
  int best = 0;
  for (int k = 1; k <= grid; ++k)
    if (m2ll(at(k)) < m2ll(at(best))) best = k;
  double lo = at(std::max(best - 1, 0)), hi = at(std::min(best + 1, grid));
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 40; ++it) {
    const double u1 = hi - g * (hi - lo), u2 = lo + g * (hi - lo);
    if (m2ll(u1) < m2ll(u2))
      hi = u2;
    else
      lo = u1;
  }
  double u = 0.5 * (lo + hi);
  if (m2ll(at(best)) < m2ll(u)) u = at(best);
  const double r = std::pow(10.0, u);
  double log_w = 0.0;
  const double sc = std::max(std::sqrt(sum_sq(r, &log_w) / std::max(dof, 1.0)), s_floor);
  return {sc * r, sc * (1.0 - r) / peak};
}

}  // namespace

namespace detail {

// Start noise scales: the given ones, or 5 % (of the channel's peak for additive and affine
// noise; affine noise starts as additive, b_c = 0).
std::array<double, kChannels> initial_noise_scales(const FitSetup& s) {
  std::array<double, kChannels> scale{};
  const bool started = !s.noise.given && s.noise.start && s.noise.start->model == s.noise.model;
  for (int c = 0; c < kChannels; ++c)
    scale[c] = s.noise.given ? (*s.noise.given)[c]
               : started && s.noise.start->scale[c] > 0.0
                   ? s.noise.start->scale[c]
                   : (s.noise.model == NoiseModel::relative ? 0.05 : s.floor_rel[c]);
  if (s.noise.given)
    for (int c = 0; c < kChannels; ++c)
      if (s.counts[c] > 0) require_positive("noise scale", scale[c]);
  return scale;
}

// Noise scales from the residual scatter of each channel, s_c^2 = sum e^2 / (n_c (1 - p / n))
// (e relative to the prediction for relative noise; affine_noise for affine noise); returns the
// largest relative change (of sigma at the channel's peak for affine noise).
double estimate_noise_scales(const FitSetup& s, const std::vector<Resultants<double>>& prediction,
                             std::array<double, kChannels>& scale,
                             std::array<double, kChannels>& slope) {
  double change = 0.0;
  const bool relative = s.noise.model == NoiseModel::relative;
  for (int c = 0; c < kChannels; ++c) {
    if (s.counts[c] == 0 || s.noise.given) continue;
    std::vector<double> e, y;
    for (std::size_t i = 0; i < s.data.points.size(); ++i) {
      const auto& yi = s.data.points[i].force[c];
      if (!yi || !s.used(i)) continue;
      const double yh = prediction[i].vector()(c);
      e.push_back((*yi - yh) / (relative ? std::max(std::abs(yh), s.floor_rel[c]) : 1.0));
      y.push_back(std::abs(yh));
    }
    const double dof_c = s.counts[c] * (1.0 - static_cast<double>(s.p_free) / s.n);
    const double s_floor = kNoiseFloor * (relative ? 1.0 : s.peak[c]);
    std::array<double, 2> ab{0.0, 0.0};
    if (s.noise.model == NoiseModel::affine) {
      ab = affine_noise(e, y, s.peak[c], dof_c, s_floor);
    } else if (s.noise.loss != RobustLoss::none) {
      // A robust fit's scale from the residuals' median, 1.4826 median |e| (the Gaussian's
      // sigma), which the few values the loss discounts do not inflate.
      std::vector<double> a(e.size());
      for (std::size_t i = 0; i < e.size(); ++i) a[i] = std::abs(e[i]);
      std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(a.size() / 2), a.end());
      const double med = a.empty() ? 0.0 : a[a.size() / 2];
      ab[0] = std::max(1.4826 * med * std::sqrt(s.counts[c] / std::max(dof_c, 1.0)), s_floor);
    } else {
      double ss = 0.0;
      for (double ei : e) ss += ei * ei;
      ab[0] = std::max(std::sqrt(ss / std::max(dof_c, 1.0)), s_floor);
    }
    const double at_peak = scale[c] + slope[c] * s.peak[c];
    change = std::max(
        change, (std::abs(ab[0] - scale[c]) + std::abs(ab[1] - slope[c]) * s.peak[c]) / at_peak);
    scale[c] = ab[0];
    slope[c] = ab[1];
  }
  return change;
}

}  // namespace detail

NoiseSettings noise_settings_for(const IdentificationOptions& o) {
  NoiseSettings n;
  n.model = o.noise_model;
  n.given = o.noise_scale;
  n.loss = o.loss;
  n.loss_scale = o.loss_scale;
  n.iterations = o.noise_iterations;
  testing::Seams::of(n) = testing::Seams::of(o);
  n.stop = o.stop;
  return n;
}

const char* noise_model_name(NoiseModel model) {
  switch (model) {
    case NoiseModel::relative:
      return "relative";
    case NoiseModel::affine:
      return "affine";
    case NoiseModel::additive:
      break;
  }
  return "additive";
}

NoiseScales noise_scales_of(const FitReport& fit) {
  return fit.noise_scales();
}

}  // namespace contensou
