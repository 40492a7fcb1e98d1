#include "contensou/identification/fit.hpp"

#include <ceres/ceres.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "contensou/friction/error.hpp"
#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/outliers.hpp"
#include "contensou/identification/statistics.hpp"
#include "point_batch.hpp"

namespace contensou {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int K = kModelParameters;

// Weighted residuals of one point, w_c (y_c - yhat_c) for each measured channel c, as a
// function of the active parameters only (packed); the others are held at theta_const.
struct PointResidual {
  const ModelSpec* spec;
  Kinematics<double> k;
  PointConditions conditions;
  std::array<double, kChannels> y{};
  std::array<double, kChannels> w{};  // 0 = not measured
  std::array<int, kChannels> slot{};  // residual index of each measured channel
  const std::vector<int>* active = nullptr;
  const std::array<double, K>* theta_const = nullptr;
  bool fail = false;  // NoiseSettings::failing_point (testing the failed-solve path)

  template <class T>
  bool operator()(T const* const* packed, T* r) const {
    if (fail) return false;
    std::array<T, K> theta;
    for (int i = 0; i < K; ++i) theta[i] = T((*theta_const)[i]);
    for (std::size_t j = 0; j < active->size(); ++j) theta[(*active)[j]] = packed[0][j];
    Resultants<T> f;
    try {
      f = evaluate_model(*spec, theta.data(), k, conditions);
    } catch (const InvalidArgument&) {
      return false;  // a parameter outside the model's domain: Ceres rejects the step
    }
    const T model[kChannels] = {f.Fx, f.Fy, f.Mz};
    for (int c = 0; c < kChannels; ++c)
      if (w[c] != 0.0) r[slot[c]] = w[c] * (y[c] - model[c]);
    return true;
  }
};

// Threads of Ceres' evaluations of the residuals and the Jacobian: one. With more, Ceres 2.1
// adds up the cost and the gradient per thread over chunks of residual blocks that the threads
// claim as they finish, so the sums' order, their last bits and so the fit's last digits change
// from run to run (seen: the app and Python differing in the 14th digit of chi2 under load).
// The same input gives the same bits; the blocks themselves are evaluated in parallel by
// point_batch.hpp, deterministically.
int evaluation_threads() {
  return 1;
}

// Ceres' evaluation of a whole problem, on evaluation_threads().
ceres::Problem::EvaluateOptions evaluate_options() {
  ceres::Problem::EvaluateOptions o;
  o.num_threads = evaluation_threads();
  return o;
}

// Derivatives in passes of 8 parameters (ceres::Jet<double, 8>), for more than 8 active.
using PointCost = ceres::DynamicAutoDiffCostFunction<PointResidual, 8>;

// Up to 8 active parameters (every fit of the closed loop but the largest): the derivatives in
// one pass of ceres::Jet<double, 8> on the stack. The same arithmetic as PointCost's first pass
// (the unused dual parts are zero), without its allocations and copies.
class PointCostOnePass final : public ceres::CostFunction {
 public:
  static constexpr int kWidth = 8;
  PointCostOnePass(PointResidual* f, int parameters, int residuals) : f_(f) {
    set_num_residuals(residuals);
    mutable_parameter_block_sizes()->push_back(parameters);
  }
  bool Evaluate(double const* const* x, double* r, double** jacobian) const override {
    if (!jacobian || !jacobian[0]) return (*f_)(x, r);
    using Jet = ceres::Jet<double, kWidth>;
    const int n = parameter_block_sizes()[0], m = num_residuals();
    std::array<Jet, kWidth> p;
    for (int j = 0; j < n; ++j) p[j] = Jet(x[0][j], j);
    const Jet* packed = p.data();
    std::array<Jet, kChannels> out;
    if (!(*f_)(&packed, out.data())) return false;
    for (int i = 0; i < m; ++i) {
      r[i] = out[i].a;
      for (int j = 0; j < n; ++j) jacobian[0][i * n + j] = out[i].v[j];
    }
    return true;
  }

 private:
  std::unique_ptr<PointResidual> f_;
};

double channel_peak(const MeasuredData& d, int c) {
  double m = 0.0;
  for (const MeasuredPoint& p : d.points)
    if (p.force[c]) m = std::max(m, std::abs(*p.force[c]));
  return m;
}

// The magnitude of each channel: its largest |y|, but at least 1e-3 of the data's force scale
// (the largest |Fx|, |Fy|, |Mz| / R; times R for Mz), so that a channel measured as zero (Fy of
// a symmetric tire sliding straight) gets a finite noise floor and weight.
std::array<double, kChannels> channel_magnitudes(const MeasuredData& d, double radius) {
  std::array<double, kChannels> peak{};
  for (int c = 0; c < kChannels; ++c) peak[c] = channel_peak(d, c);
  const double force = std::max({peak[0], peak[1], peak[2] / radius, 1e-300});
  for (int c = 0; c < kChannels; ++c)
    peak[c] = std::max(peak[c], 1e-3 * force * (c == 2 ? radius : 1.0));
  return peak;
}

// The forces a fit is made for: the data's force scale (the largest |Fx|, |Fy| and |Mz| / R)
// in [1e-6, 1e8] N. Outside it fixed thresholds stop treating the parameters alike (the
// positivity bounds of F0 and M0 at 1e-12, Ceres' step tolerance relative to the norm of all
// parameters together, the rank test of the Jacobian's columns): on the bundled set scaled by
// 1e-20 or 1e9 the fits went wrong without a word. Data of zero force have nothing to fit.
void check_force_scale(const MeasuredData& data, double radius_m) {
  constexpr double kLowest = 1e-6, kHighest = 1e8;  // [N]
  double force = 0.0;
  for (int c = 0; c < kChannels; ++c)
    force = std::max(force, channel_peak(data, c) / (c == 2 ? radius_m : 1.0));
  const std::string where = data.source.empty() ? std::string("data") : data.source;
  if (force == 0.0)
    throw InvalidArgument(where, "every measured Fx, Fy and Mz zero",
                          "there is no friction to fit");
  if (force < kLowest || force > kHighest)
    throw InvalidArgument(
        where, "largest measured force " + format_value(force) + " N",
        "outside the range a fit is made for, " + format_value(kLowest) + " to " +
            format_value(kHighest) +
            " N (|Mz| / R counted as a force, R = " + format_value(radius_m) +
            " m): check the units of the force columns (kN read as N, say) and of the radius");
}

// Smallest noise scale estimated from the scatter: 1e-6 of the channel's magnitude (additive),
// 1e-6 (relative). Below it the weights would come from rounding, not from noise.
constexpr double kNoiseFloor = 1e-6;

// Noise parameters estimated per measured channel: none when given, a_c and b_c for affine
// noise, else s_c.
int noise_parameters(const NoiseSettings& noise) {
  if (noise.given) return 0;
  return noise.model == NoiseModel::affine ? 2 : 1;
}

// Bounds that keep the model physical, on the packed active parameters.
void set_bounds(ceres::Problem& problem, double* packed, const std::vector<int>& active) {
  for (std::size_t j = 0; j < active.size(); ++j) {
    const ParameterBounds b = parameter_bounds(active[j]);
    const int jj = static_cast<int>(j);
    if (std::isfinite(b.lower)) problem.SetParameterLowerBound(packed, jj, b.lower);
    if (std::isfinite(b.upper)) problem.SetParameterUpperBound(packed, jj, b.upper);
  }
}

// The noise scale of one value of channel c with prediction (or, in a first round, datum) yh:
// s_c, s_c max(|yh|, floor_rel_c) or a_c + b_c |yh| (NoiseModel).
double value_scale(const NoiseScales& n, int c, double yh, double floor_rel) {
  switch (n.model) {
    case NoiseModel::relative:
      return n.scale[c] * std::max(std::abs(yh), floor_rel);
    case NoiseModel::affine:
      return n.scale[c] + n.slope[c] * std::abs(yh);
    case NoiseModel::additive:
      break;
  }
  return n.scale[c];
}

// How add_points weights the residuals: the noise scales, the relative noise's floor per
// channel, the predictions the scales are taken at (empty: the data), the robust loss.
struct Weighting {
  NoiseScales noise;
  std::array<double, kChannels> floor_rel{};
  const std::vector<Resultants<double>>* prediction = nullptr;
  RobustLoss loss = RobustLoss::none;
  double loss_scale = 1.0;
  int failing_point = -1;  // NoiseSettings::failing_point
};

// Adds one residual block per point with measured values (weights 1 / s_ic); returns the number
// of residuals.
int add_points(ceres::Problem& problem, const MeasuredData& data, const ModelSpec& spec,
               const std::vector<int>& active, const std::array<double, K>& theta_const,
               double* packed, const Weighting& wt, const std::vector<char>& use) {
  int total = 0;
  const std::size_t used = use.empty()
                               ? data.points.size()
                               : static_cast<std::size_t>(std::count_if(
                                     use.begin(), use.end(), [](char u) { return u != 0; }));
  auto batch = std::make_shared<detail::PointBatch>(static_cast<int>(active.size()),
                                                    detail::batch_threads(used));
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    if (!use.empty() && !use[i]) continue;
    const MeasuredPoint& pt = data.points[i];
    auto* f = new PointResidual{&spec,
                                pt.kinematics,
                                conditions_of(spec, pt),
                                {},
                                {},
                                {},
                                &active,
                                &theta_const,
                                static_cast<int>(i) == wt.failing_point};
    int m = 0;
    for (int c = 0; c < kChannels; ++c) {
      if (!pt.force[c]) continue;
      f->y[c] = *pt.force[c];
      const bool predicted = wt.prediction && !wt.prediction->empty();
      const double yh = predicted ? (*wt.prediction)[i].vector()(c) : *pt.force[c];
      f->w[c] = 1.0 / value_scale(wt.noise, c, yh, wt.floor_rel[c]);
      f->slot[c] = m++;
    }
    if (m == 0) {
      delete f;
      continue;
    }
    ceres::CostFunction* cost = nullptr;
    if (static_cast<int>(active.size()) <= PointCostOnePass::kWidth) {
      cost = new PointCostOnePass(f, static_cast<int>(active.size()), m);
    } else {
      auto* dynamic = new PointCost(f);
      dynamic->AddParameterBlock(static_cast<int>(active.size()));
      dynamic->SetNumResiduals(m);
      cost = dynamic;
    }
    ceres::LossFunction* loss = nullptr;
    if (wt.loss == RobustLoss::huber) loss = new ceres::HuberLoss(wt.loss_scale);
    if (wt.loss == RobustLoss::cauchy) loss = new ceres::CauchyLoss(wt.loss_scale);
    problem.AddResidualBlock(batch->add(batch, cost), loss, packed);
    total += m;
  }
  return total;
}

std::vector<Resultants<double>> evaluate_all(const ModelSpec& spec, const double* theta,
                                             const MeasuredData& d) {
  std::vector<Resultants<double>> out;
  out.reserve(d.points.size());
  for (const MeasuredPoint& p : d.points)
    out.push_back(evaluate_model(spec, theta, p.kinematics, conditions_of(spec, p)));
  return out;
}

// Whether a parameter belongs in the report of a model.
bool reported(const ModelSpec& s, int i) {
  if (s.exact_only && (i == kA || i == kM0 || i == kMShape || i == kShapeBlend)) return false;
  if ((i == kProfileB1 || i == kProfileB2) && (s.profile_model || !s.uses_exact())) return false;
  if (i == kSpeedRef) return s.free[kSpeedDrop] || s.value[kSpeedDrop] != 0.0;
  return s.free[i] || i <= kKx || s.value[i] != parameter_info(i).null_value;
}

// The fit named by its model and free parameters, for the error of a failed solve.
std::string fit_name(const ModelSpec& s) {
  std::string name = s.exact_only ? "exact integrals" : "fractional law";
  std::string sep = " (free: ";
  for (int i = 0; i < K; ++i)
    if (s.free[i]) {
      name += sep + parameter_info(i).name;
      sep = ", ";
    }
  return name + (sep == ", " ? ")" : "");
}

}  // namespace

ModelSpec base_spec_for(const MeasuredData& data, const IdentificationOptions& o) {
  require_positive("radius", o.radius_m);
  if (o.normal_load_n) require_positive("normal load", *o.normal_load_n);
  ModelSpec s = base_model_spec(o.radius_m, o.normal_load_n);
  s.regularization_speed = o.regularization_speed;
  // Rows with their own load (an Fz column): each at rho = N_i / N_ref, N_ref the load given (or
  // the rows' mean), at which F0 and M0 are reported.
  if (const std::optional<LoadFromData> rows = normal_load_from_data(data)) {
    s.reference_load_n = o.normal_load_n.value_or(rows->mean_n);
    s.normal_load_n = s.reference_load_n;
  }
  if (o.profile) {
    // Only the profile's shape matters here: a unit load and unit friction.
    PressureProfile shape = *o.profile;
    shape.kx = shape.ky = 0.0;
    const ContactPatch patch = ContactPatch::from_normal_load(o.radius_m, 1.0, shape, 1.0);
    const FractionalLaw<double> law = fractional_law_from_patch(patch);
    s.c = law.c;
    s.a_k = law.a_k;
    s.mk_ratio = law.Mk / law.M0;
    s.value[kA] = law.a;
    s.value[kMShape] = law.m;
    s.profile_a = law.a;
    s.profile_m = law.m;
    s.profile_m0_ratio = law.M0 / (law.F0 * o.radius_m);
    // 1e-6 of the profile is far below any measurement noise and keeps a tabulated profile's
    // series short (its PCHIP is only C1).
    s.profile_model = make_exact_model(patch, 1e-6);
    s.exact_laws = std::make_shared<ExactLawCache>(o.radius_m, s.profile_model, s.exact_tolerance);
  }
  double f0 = 0.0, m0 = 0.0;
  for (const MeasuredPoint& p : data.points) {
    f0 = std::max(f0, std::hypot(p.force[0].value_or(0.0), p.force[1].value_or(0.0)));
    m0 = std::max(m0, std::abs(p.force[2].value_or(0.0)));
  }
  s.value[kF0] = f0 > 0.0 ? f0 : 1.0;
  s.value[kM0] = m0 > 0.0 ? m0 : 0.3 * s.value[kF0] * o.radius_m;
  for (const auto& [name, value] : o.fixed) {
    const int i = parameter_index_by_name(name);
    if (i < 0 || i > kKx)
      throw InvalidArgument("fix", name, "unknown parameter (use F0_N, a, M0_Nm, m or kx)");
    require_finite(name.c_str(), value);
    const ParameterBounds b = parameter_bounds(i);
    if (!(value >= b.lower && value <= b.upper))
      throw InvalidArgument("fix " + name, format_value(value),
                            "must lie in [" + format_value(b.lower) + ", " + format_value(b.upper) +
                                "], the fit's bounds for it");
    s.free[i] = false;
    s.value[i] = value;
  }
  return s;
}

NoiseSettings noise_settings_for(const IdentificationOptions& o) {
  NoiseSettings n;
  n.model = o.noise_model;
  n.given = o.noise_scale;
  n.loss = o.loss;
  n.loss_scale = o.loss_scale;
  n.iterations = o.noise_iterations;
  n.failing_point = o.failing_point;
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

bool FitReport::within_noise() const {
  return std::all_of(channels.begin(), channels.end(), [](const ChannelDiagnostics& c) {
    return c.neighbour_scale <= 0.0 || c.rms <= 1.5 * c.neighbour_scale;
  });
}

const ParameterEstimate* FitReport::parameter(const std::string& name) const {
  for (const ParameterEstimate& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<Resultants<double>> predict(const FractionalLaw<double>& law,
                                        const MeasuredData& data) {
  std::vector<Resultants<double>> out;
  out.reserve(data.points.size());
  for (const MeasuredPoint& p : data.points)
    out.push_back(fractional_resultants(law, p.kinematics));
  return out;
}

// The sliding-spin ratio psi = |v| / u with v = (vx, vy) and u = |omega| R (seed eqs. 12-13;
// theory.md sections 1 and 4); infinity for pure sliding (u = 0).
std::vector<double> sliding_spin_ratio(const MeasuredData& data, double radius_m) {
  std::vector<double> psi;
  psi.reserve(data.points.size());
  for (const MeasuredPoint& p : data.points) {
    const double v = std::hypot(p.kinematics.vx, p.kinematics.vy);
    const double u = std::abs(p.kinematics.omega) * radius_m;
    psi.push_back(u > 0.0 ? v / u : std::numeric_limits<double>::infinity());
  }
  return psi;
}

std::vector<ChannelDiagnostics> residual_diagnostics(const MeasuredData& data,
                                                     const std::vector<Resultants<double>>& model,
                                                     double radius_m,
                                                     const std::array<double, kChannels>& scale) {
  // Order along time if every point has one, else along psi.
  std::vector<std::size_t> order(data.points.size());
  std::iota(order.begin(), order.end(), 0);
  const bool timed = std::all_of(data.points.begin(), data.points.end(),
                                 [](const MeasuredPoint& p) { return p.time.has_value(); });
  const std::vector<double> psi = sliding_spin_ratio(data, radius_m);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return timed ? *data.points[a].time < *data.points[b].time : psi[a] < psi[b];
  });
  std::vector<ChannelDiagnostics> out;
  int measured = 0;
  for (int c = 0; c < kChannels; ++c) measured += data.count(c) > 0;
  const double alpha = 0.01 / std::max(1, 2 * measured);  // Bonferroni: channels x two tests
  for (int c = 0; c < kChannels; ++c) {
    if (data.count(c) == 0) continue;
    ChannelDiagnostics d;
    d.channel = kChannelColumns[c];
    std::vector<double> r;
    double ss = 0.0;
    for (std::size_t i : order) {
      const auto& y = data.points[i].force[c];
      if (!y) continue;
      const double e = *y - model[i].vector()(c);
      r.push_back(e);
      ss += e * e;
    }
    d.points = static_cast<int>(r.size());
    d.rms = std::sqrt(ss / static_cast<double>(std::max<std::size_t>(1, r.size())));
    d.noise_scale = scale[c];
    const RunsTest rt = runs_test(r);
    d.runs_p_value = rt.p_value;
    d.lag1 = lag1_autocorrelation(r);
    d.durbin_watson = durbin_watson(r);
    const double lag_p =
        2.0 * normal_cdf(-std::abs(d.lag1) * std::sqrt(static_cast<double>(r.size())));
    d.white = d.runs_p_value >= alpha && lag_p >= alpha;
    out.push_back(d);
  }
  return out;
}

namespace {

// What a fit works on: the used points, the measured values per channel, the active (free)
// parameters and the start values the inactive ones are held at. Ceres' cost functions point
// into it, so it outlives the problem.
struct FitSetup {
  FitSetup(const MeasuredData& d, const ModelSpec& sp, const NoiseSettings& ns,
           const std::vector<char>& u)
      : data(d), spec(sp), noise(ns), use(u) {}
  const MeasuredData& data;
  const ModelSpec& spec;
  const NoiseSettings& noise;
  const std::vector<char>& use;
  std::array<int, kChannels> counts{};  // measured values per channel
  int n = 0;                            // measured values in all
  int p_free = 0;
  std::array<double, kChannels> peak{};       // magnitude per channel (channel_magnitudes)
  std::array<double, kChannels> floor_rel{};  // 5 % of the peak: floor of relative noise
  std::vector<int> active;                    // free parameters, in index order
  std::array<double, K> theta_const{};        // values of the others

  bool used(std::size_t i) const { return use.empty() || use[i]; }
};

FitSetup prepare_fit(const MeasuredData& data, const ModelSpec& spec, const NoiseSettings& noise,
                     const std::vector<char>& use) {
  require_positive("radius", spec.radius_m);
  FitSetup s(data, spec, noise, use);
  for (std::size_t i = 0; i < data.points.size(); ++i)
    if (s.used(i))
      for (int c = 0; c < kChannels; ++c) s.counts[c] += data.points[i].force[c].has_value();
  for (int c = 0; c < kChannels; ++c) s.n += s.counts[c];
  s.p_free = static_cast<int>(std::count(spec.free.begin(), spec.free.end(), true));
  // Rows at rest (v = omega = 0) measure only the offsets: a fit needs motion.
  bool moving = false;
  for (std::size_t i = 0; i < data.points.size(); ++i) {
    const Kinematics<double>& k = data.points[i].kinematics;
    moving = moving || (s.used(i) && (k.vx != 0.0 || k.vy != 0.0 || k.omega != 0.0));
  }
  if (!moving)
    throw InvalidArgument("data", std::to_string(data.points.size()) + " rows",
                          "every row is at rest (v = omega = 0): the friction law needs rows with "
                          "sliding or spin");
  // Refused before fitting: nothing free (Ceres cannot take an empty parameter block), or too
  // little data (measured_values_needed).
  if (s.p_free == 0)
    throw InvalidArgument("fix", "F0_N, a, M0_Nm, m and kx",
                          "every parameter is fixed, nothing is left to fit: leave one free");
  int scales = 0;
  for (int c = 0; c < kChannels; ++c) scales += s.counts[c] > 0 ? noise_parameters(noise) : 0;
  if (noise.given)
    for (double g : *noise.given)
      if (!(g >= 1e-12 && g <= 1e12))  // chi^2 finite for forces up to 1e8 N
        throw InvalidArgument("noise scale", format_value(g), "must lie in [1e-12, 1e12]");
  if (noise.given && noise.model == NoiseModel::affine)
    throw InvalidArgument("noise scale", "given",
                          "given noise scales are constant: use the additive or relative model");
  const int needed = s.p_free + scales + 1;
  if (s.n < needed)
    throw InvalidArgument("data", std::to_string(s.n) + " measured values",
                          "too little data: the fit needs at least " + std::to_string(needed) +
                              " (" + std::to_string(s.p_free) + " free parameters + " +
                              std::to_string(scales) + " estimated noise scales + 1)");
  check_force_scale(data, spec.radius_m);
  s.peak = channel_magnitudes(data, spec.radius_m);
  for (int c = 0; c < kChannels; ++c) s.floor_rel[c] = 0.05 * s.peak[c];
  for (int i = 0; i < K; ++i)
    if (spec.free[i]) s.active.push_back(i);
  s.theta_const = spec.value;
  return s;
}

// A solved problem: the estimate, the noise scales and the predictions at the optimum.
struct Solution {
  std::unique_ptr<ceres::Problem> problem;
  std::vector<double> packed;  // the active parameters (Ceres' parameter block)
  std::array<double, K> theta{};
  std::array<double, kChannels> scale{};
  std::array<double, kChannels> slope{};  // b_c of affine noise
  std::vector<Resultants<double>> prediction;
  ceres::Solver::Summary summary;
};

// Start noise scales: the given ones, or 5 % (of the channel's peak for additive and affine
// noise; affine noise starts as additive, b_c = 0).
std::array<double, kChannels> initial_noise_scales(const FitSetup& s) {
  std::array<double, kChannels> scale{};
  for (int c = 0; c < kChannels; ++c)
    scale[c] = s.noise.given ? (*s.noise.given)[c]
                             : (s.noise.model == NoiseModel::relative ? 0.05 : s.floor_rel[c]);
  if (s.noise.given)
    for (int c = 0; c < kChannels; ++c)
      if (s.counts[c] > 0) require_positive("noise scale", scale[c]);
  return scale;
}

// Affine noise of one channel from its residuals e_i and |yhat_i|: sigma_i = a + b |yhat_i|
// by maximum likelihood of the Gaussian residuals (pseudo-likelihood of a variance function,
// Carroll & Ruppert 1988, ch. 3). Written sigma_i = s w_i(t), w_i = (1 - t) + t |yhat_i| / peak
// (s is sigma at the channel's peak), the scale has the closed form s^2(t) = sum (e_i / w_i)^2 /
// dof, and t in [0, 0.99] minimises the profile -2 log L(t) = n log s^2(t) + 2 sum log w_i(t):
// a grid of 34 points, then golden section in the best one's bracket. a = s (1 - t),
// b = s t / peak; t = 0 is the additive model, t = 0.99 keeps a >= 1 % of sigma at the peak.
std::array<double, 2> affine_noise(const std::vector<double>& e, const std::vector<double>& y,
                                   double peak, double dof, double s_floor) {
  const auto n = static_cast<double>(e.size());
  const auto sum_sq = [&](double t, double* log_w) {
    double ss = 0.0;
    *log_w = 0.0;
    for (std::size_t i = 0; i < e.size(); ++i) {
      const double w = (1.0 - t) + t * y[i] / peak;
      ss += e[i] * e[i] / (w * w);
      *log_w += std::log(w);
    }
    return std::max(ss, 1e-300);
  };
  const auto m2ll = [&](double t) {
    double log_w = 0.0;
    const double ss = sum_sq(t, &log_w);
    return n * std::log(ss) + 2.0 * log_w;
  };
  constexpr double t_max = 0.99;
  constexpr int grid = 33;
  int best = 0;
  for (int k = 1; k <= grid; ++k)
    if (m2ll(t_max * k / grid) < m2ll(t_max * best / grid)) best = k;
  double lo = t_max * std::max(best - 1, 0) / grid, hi = t_max * std::min(best + 1, grid) / grid;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 40; ++it) {
    const double t1 = hi - g * (hi - lo), t2 = lo + g * (hi - lo);
    if (m2ll(t1) < m2ll(t2))
      hi = t2;
    else
      lo = t1;
  }
  double t = 0.5 * (lo + hi);
  if (m2ll(t_max * best / grid) < m2ll(t)) t = t_max * best / grid;
  double log_w = 0.0;
  const double s = std::max(std::sqrt(sum_sq(t, &log_w) / std::max(dof, 1.0)), s_floor);
  return {s * (1.0 - t), s * t / peak};
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

// After a failed solve: the first row whose residuals or derivatives are not finite at the
// current parameters, as " (first at file:line, vx = ...)", or "".
std::string failing_row(ceres::Problem& problem, const FitSetup& s) {
  std::vector<ceres::ResidualBlockId> blocks;
  problem.GetResidualBlocks(&blocks);
  std::size_t b = 0;
  for (std::size_t i = 0; i < s.data.points.size() && b < blocks.size(); ++i) {
    const MeasuredPoint& pt = s.data.points[i];
    if (!s.used(i) || std::none_of(pt.force.begin(), pt.force.end(),
                                   [](const std::optional<double>& f) { return f.has_value(); }))
      continue;
    const ceres::ResidualBlockId id = blocks[b++];
    const int m = problem.GetCostFunctionForResidualBlock(id)->num_residuals();
    std::vector<double> r(static_cast<std::size_t>(m));
    std::vector<double> jac(static_cast<std::size_t>(m) * s.active.size());
    double* jp[1] = {jac.data()};
    double cost = 0.0;
    const bool ok = problem.EvaluateResidualBlock(id, false, &cost, r.data(), jp);
    const auto finite = [](double x) { return std::isfinite(x); };
    if (ok && std::all_of(r.begin(), r.end(), finite) &&
        std::all_of(jac.begin(), jac.end(), finite))
      continue;
    return " (first at " +
           (pt.line > 0 ? s.data.source + ":" + std::to_string(pt.line)
                        : "point " + std::to_string(i)) +
           ", vx = " + format_value(pt.kinematics.vx) +
           " m/s, vy = " + format_value(pt.kinematics.vy) +
           " m/s, omega = " + format_value(pt.kinematics.omega) +
           " rad/s: the model or its derivatives are not finite there)";
  }
  return "";
}

// Ends a solve (SOLVER_ABORT) after the iteration in which the caller's stop request fired.
class StopCallback : public ceres::IterationCallback {
 public:
  explicit StopCallback(const StopRequest& stop) : stop_(stop) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary&) override {
    return stop_ && stop_() ? ceres::SOLVER_ABORT : ceres::SOLVER_CONTINUE;
  }

 private:
  const StopRequest& stop_;
};

// Ends a solve once a parameter has sat on one of its bounds through kPinnedIterations
// successful iterations in a row (the values are current in the callback:
// Solver::Options::update_state_every_iteration).
class BoundWatch : public ceres::IterationCallback {
 public:
  static constexpr int kPinnedIterations = 3;
  BoundWatch(const std::vector<double>& packed, const std::vector<int>& active)
      : packed_(packed), active_(active), run_(active.size(), 0) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override {
    if (it.iteration == 0 || !it.step_is_successful) return ceres::SOLVER_CONTINUE;
    bool pinned = false;
    for (std::size_t j = 0; j < active_.size(); ++j) {
      run_[j] = at_bound(j) ? run_[j] + 1 : 0;
      pinned = pinned || run_[j] >= kPinnedIterations;
    }
    return pinned ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
  // Ceres keeps a bound by clipping the step to it: a parameter on its bound equals it.
  bool at_bound(std::size_t j) const {
    const ParameterBounds b = parameter_bounds(active_[j]);
    return packed_[j] == b.lower || packed_[j] == b.upper;
  }

 private:
  const std::vector<double>& packed_;
  const std::vector<int>& active_;
  std::vector<int> run_;
};

// The parameters on their bounds whose gradient g_j (of the cost) points out of the box: at a
// lower bound g_j > 0, at an upper bound g_j < 0 (the cost would rise going inside). Those
// the data hold on their bounds (the Karush-Kuhn-Tucker condition); the others are free to go.
std::vector<int> held_on_bounds(ceres::Problem& problem, const std::vector<double>& packed,
                                const std::vector<int>& active, const BoundWatch& watch) {
  double cost = 0.0;
  std::vector<double> gradient;
  ceres::Problem::EvaluateOptions o = evaluate_options();
  if (!problem.Evaluate(o, &cost, nullptr, &gradient, nullptr)) return {};
  std::vector<int> held;
  for (std::size_t j = 0; j < active.size(); ++j) {
    if (!watch.at_bound(j)) continue;
    const bool lower = packed[j] == parameter_bounds(active[j]).lower;
    if (lower ? gradient[j] > 0.0 : gradient[j] < 0.0) held.push_back(static_cast<int>(j));
  }
  return held;
}

// Ceres' trust region keeps bounds by clipping each step; with a parameter that the data press
// against its bound, the clipped part of every step makes the model promise more than the cost
// gives, the radius shrinks at each iteration and the solve crawls (on 1,000 points with the
// profile's weight b1 on its bound: 50 iterations, ending short of the optimum). So the solve
// stops once a parameter has sat on its bound for a few iterations (BoundWatch); the
// parameters held there by their gradient stay on it (SubsetManifold) while the others are
// solved; and a last solve with all free follows if the bound no longer holds one of them.
void solve_bounded(ceres::Solver::Options opt, ceres::Problem& problem, std::vector<double>& packed,
                   const std::vector<int>& active, ceres::Solver::Summary& summary) {
  BoundWatch watch(packed, active);
  opt.update_state_every_iteration = true;
  opt.callbacks.push_back(&watch);
  ceres::Solve(opt, &problem, &summary);
  opt.callbacks.pop_back();
  if (summary.termination_type != ceres::USER_SUCCESS) return;
  const std::vector<int> held = held_on_bounds(problem, packed, active, watch);
  const int n = static_cast<int>(active.size());
  if (!held.empty() && static_cast<int>(held.size()) < n) {
    problem.SetManifold(packed.data(), new ceres::SubsetManifold(n, held));
    ceres::Solve(opt, &problem, &summary);
    problem.SetManifold(packed.data(), nullptr);
    if (!summary.IsSolutionUsable()) return;
  }
  if (held.empty() || held_on_bounds(problem, packed, active, watch) != held)
    ceres::Solve(opt, &problem, &summary);
}

// Build the problem, solve, estimate the noise scales; repeated (warm-started) until the
// scales settle, once when they are given and additive.
Solution solve(const FitSetup& s) {
  Solution sol;
  sol.theta = s.spec.value;
  sol.scale = initial_noise_scales(s);
  sol.packed.resize(s.active.size());
  for (std::size_t j = 0; j < s.active.size(); ++j) sol.packed[j] = sol.theta[s.active[j]];
  // The model at the start values, outside Ceres: a parameter outside its domain (a fixed
  // kappa < 0, say) is reported by name here instead of as a failed solve, and so is a row
  // whose kinematics the model cannot evaluate (speeds far beyond any rig).
  const std::vector<Resultants<double>> start = evaluate_all(s.spec, sol.theta.data(), s.data);
  for (std::size_t i = 0; i < start.size(); ++i) {
    if (!s.used(i) || start[i].vector().allFinite()) continue;
    const MeasuredPoint& pt = s.data.points[i];
    throw InvalidArgument("data",
                          (pt.line > 0 ? s.data.source + ":" + std::to_string(pt.line)
                                       : "point " + std::to_string(i)),
                          "the model is not finite at vx = " + format_value(pt.kinematics.vx) +
                              " m/s, vy = " + format_value(pt.kinematics.vy) +
                              " m/s, omega = " + format_value(pt.kinematics.omega) +
                              " rad/s with R = " + format_value(s.spec.radius_m) +
                              " m: check the units of the kinematic columns and of the radius");
  }
  const bool fixed_scales = s.noise.given && s.noise.model == NoiseModel::additive;
  const int rounds = fixed_scales ? 1 : std::max(1, s.noise.iterations);
  for (int round = 0; round < rounds; ++round) {
    sol.problem = std::make_unique<ceres::Problem>();
    const Weighting wt{{s.noise.model, sol.scale, sol.slope},
                       s.floor_rel,
                       &sol.prediction,
                       s.noise.loss,
                       s.noise.loss_scale,
                       s.noise.failing_point};
    add_points(*sol.problem, s.data, s.spec, s.active, s.theta_const, sol.packed.data(), wt, s.use);
    set_bounds(*sol.problem, sol.packed.data(), s.active);
    ceres::Solver::Options opt;
    opt.linear_solver_type = ceres::DENSE_QR;
    opt.max_num_iterations = s.noise.solver_iterations;
    opt.function_tolerance = 1e-12;
    opt.gradient_tolerance = 1e-12;
    opt.parameter_tolerance = 1e-10;
    opt.logging_type = ceres::SILENT;
    opt.num_threads = evaluation_threads();
    StopCallback stop_callback(s.noise.stop);
    if (s.noise.stop) opt.callbacks.push_back(&stop_callback);
    throw_if_stopped(s.noise.stop);
    solve_bounded(opt, *sol.problem, sol.packed, s.active, sol.summary);
    throw_if_stopped(s.noise.stop);  // the solve was aborted (or is over): not a result
    // Never go on (covariance, report) from a failed solve.
    if (!sol.summary.IsSolutionUsable())
      throw std::runtime_error("fit of the " + fit_name(s.spec) +
                               " failed: " + sol.summary.message + failing_row(*sol.problem, s));
    for (std::size_t j = 0; j < s.active.size(); ++j) sol.theta[s.active[j]] = sol.packed[j];
    sol.prediction = evaluate_all(s.spec, sol.theta.data(), s.data);
    if (fixed_scales) break;
    const double change = estimate_noise_scales(s, sol.prediction, sol.scale, sol.slope);
    if (round > 0 && change < 1e-3) break;
  }
  return sol;
}

// The weighted Jacobian at the optimum (free parameters only); sets the report's residual
// count and chi^2. Throws, naming the fit, if residuals or Jacobian are not finite: no
// covariance is ever computed from them.
Eigen::MatrixXd jacobian_at_optimum(ceres::Problem& problem, const ModelSpec& spec,
                                    FitReport* report) {
  ceres::CRSMatrix crs;
  std::vector<double> residuals;
  double cost = 0.0;
  const bool evaluated = problem.Evaluate(evaluate_options(), &cost, &residuals, nullptr, &crs);
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int r = 0; r < crs.num_rows; ++r)
    for (int k = crs.rows[r]; k < crs.rows[r + 1]; ++k) J(r, crs.cols[k]) = crs.values[k];
  const bool finite =
      std::all_of(residuals.begin(), residuals.end(), [](double r) { return std::isfinite(r); });
  if (!evaluated || !finite || !J.allFinite())
    throw std::runtime_error("fit of the " + fit_name(spec) +
                             " failed: non-finite residuals or Jacobian at the optimum");
  report->residuals = static_cast<int>(residuals.size());
  report->chi2 = 0.0;
  for (double r : residuals) report->chi2 += r * r;
  return J;
}

// Parameters the data cannot determine: zero columns of J, or a large share in a singular
// vector of the column-normalised J (singular value below 1e-7 of the largest).
std::array<bool, K> undetermined_parameters(const Eigen::MatrixXd& J,
                                            const std::vector<int>& active) {
  std::array<bool, K> undetermined{};
  if (J.cols() == 0) return undetermined;
  const Eigen::VectorXd norms = J.colwise().norm();
  Eigen::MatrixXd Jn = J;
  for (int j = 0; j < J.cols(); ++j)
    if (norms(j) > 0.0) Jn.col(j) /= norms(j);
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  for (int j = 0; j < J.cols(); ++j)
    if (!(norms(j) > 1e-12 * norms.maxCoeff())) undetermined[active[j]] = true;
  for (int sidx = 0; sidx < sv.size(); ++sidx) {
    if (sv(sidx) > 1e-7 * sv(0)) continue;
    for (int j = 0; j < J.cols(); ++j)
      if (std::abs(svd.matrixV()(j, sidx)) > 0.3) undetermined[active[j]] = true;
  }
  return undetermined;
}

// Covariance of the determined parameters, s^2 (J_e^T J_e)^-1 with s^2 = chi^2 / (n - p) and
// J_e the Jacobian's columns of those parameters, from the SVD of the column-normalised J_e:
// (J_e^T J_e)^-1 = D^-1 V S^-2 V^T D^-1, D = diag(column norms). Normalising first keeps the
// result accurate when the columns differ by many orders of magnitude (a channel measured as
// zero, say). A K x K matrix, or nothing when it cannot be had.
std::optional<Eigen::MatrixXd> parameter_covariance(const Eigen::MatrixXd& J,
                                                    const std::vector<int>& active,
                                                    const std::vector<int>& est,
                                                    const FitReport& report) {
  if (est.empty() || report.degrees_of_freedom <= 0 || !J.allFinite()) return std::nullopt;
  const auto p = static_cast<Eigen::Index>(est.size());
  Eigen::MatrixXd Je(J.rows(), p);
  for (Eigen::Index a = 0; a < p; ++a) {
    const auto col = std::find(active.begin(), active.end(), est[static_cast<std::size_t>(a)]);
    Je.col(a) = J.col(static_cast<Eigen::Index>(col - active.begin()));
  }
  const Eigen::VectorXd norms = Je.colwise().norm();
  if (!(norms.minCoeff() > 0.0)) return std::nullopt;
  const Eigen::MatrixXd Jn = Je * norms.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  if (!(sv(p - 1) > 1e-12 * sv(0))) return std::nullopt;
  const Eigen::MatrixXd Vs = svd.matrixV() * sv.cwiseInverse().asDiagonal();
  const Eigen::MatrixXd inv =
      norms.cwiseInverse().asDiagonal() * (Vs * Vs.transpose()) * norms.cwiseInverse().asDiagonal();
  const double s2 = report.chi2 / (report.residuals - report.free_parameters);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(K, K);
  for (Eigen::Index a = 0; a < p; ++a)
    for (Eigen::Index b = 0; b < p; ++b)
      cov(est[static_cast<std::size_t>(a)], est[static_cast<std::size_t>(b)]) = s2 * inv(a, b);
  return cov;
}

// A friction_dependence parameter in the variable's units, at the middle of the range (z = 0,
// f = f_ref (1 - b2)): (1/f) df/dX = b1 / (h (1 - b2)) and (1/f) d2f/dX2 = 4 b2 / (h^2 (1 - b2)),
// h the half range (the note of each parameter shows its own term, the other at 0).
std::string dependence_note(const ModelSpec& spec, int i, const ParameterEstimate& e) {
  if (i < kDependence1 || i > kDependence3Curve) return "";
  const int slot = (i - kDependence1) / 2;
  const bool curve = (i - kDependence1) % 2 == 1;
  if (!spec.dependence[slot]) return "";
  const Covariate& c = *spec.dependence[slot];
  const std::string unit = c.unit.empty() ? "row" : c.unit;
  char buf[320];
  const double per = curve ? 4.0 * e.value / (c.half_range * c.half_range * (1.0 - e.value))
                           : e.value / c.half_range;
  std::snprintf(
      buf, sizeof buf,
      "%s of f (1 + b1 z + b2 (2 z^2 - 1)), z = %s over %.6g to %.6g %s: %s = %.4g 1/%s%s",
      curve ? "b2" : "b1", c.name.c_str(), c.mid - c.half_range, c.mid + c.half_range, unit.c_str(),
      curve ? "(1/f) d2f/dX2" : "(1/f) df/dX", per, unit.c_str(), curve ? "^2" : "");
  return buf;
}

ParameterEstimate estimate_of(int i, double value) {
  ParameterEstimate e;
  e.name = parameter_info(i).name;
  e.unit = parameter_info(i).unit;
  e.value = value;
  return e;
}

// Values, standard errors and Student-t 95 % intervals (n - p degrees of freedom) of the
// reported parameters; the profile's derived a, M0, m for the exact model; f = F0 / N when the
// load is known; the correlation matrix of the determined parameters.
void report_parameters(const ModelSpec& spec, const std::array<double, K>& theta,
                       const std::array<bool, K>& undetermined, const std::vector<int>& est,
                       const std::optional<Eigen::MatrixXd>& cov, FitReport& report) {
  const double tq =
      report.degrees_of_freedom > 0 ? student_t_quantile(0.975, report.degrees_of_freedom) : kNaN;
  for (int i = 0; i < K; ++i) {
    if (!reported(spec, i)) continue;
    ParameterEstimate e = estimate_of(i, theta[i]);
    e.fixed = !spec.free[i];
    e.determined = spec.free[i] && !undetermined[i];
    if (e.determined && cov && (*cov)(i, i) >= 0.0) {
      e.std_error = std::sqrt((*cov)(i, i));
      e.ci95 = std::array<double, 2>{e.value - tq * e.std_error, e.value + tq * e.std_error};
    } else {
      e.determined = false;
    }
    e.note = dependence_note(spec, i, e);
    report.parameters.push_back(e);
  }
  if (spec.exact_only && spec.profile_model) {
    // The exact model has no a, m, M0 of its own: report the profile's asymptote-matched
    // values (fixed, no interval), so that a report always carries the law's parameters.
    const double derived[3] = {spec.profile_a, theta[kF0] * spec.radius_m * spec.profile_m0_ratio,
                               spec.profile_m};
    const int index[3] = {kA, kM0, kMShape};
    for (int j = 0; j < 3; ++j) {
      ParameterEstimate e = estimate_of(index[j], derived[j]);
      e.fixed = true;
      e.determined = false;
      e.derived = true;
      report.parameters.insert(report.parameters.begin() + 1 + j, e);
    }
  }
  if (spec.normal_load_n) {
    const ParameterEstimate& F0 = report.parameters[0];
    const double N = *spec.normal_load_n;
    ParameterEstimate f;
    f.name = "f";
    f.unit = "1";
    f.value = F0.value / N;
    f.fixed = F0.fixed;
    f.determined = F0.determined;
    f.std_error = F0.std_error / N;
    if (F0.ci95) f.ci95 = std::array<double, 2>{(*F0.ci95)[0] / N, (*F0.ci95)[1] / N};
    report.parameters.push_back(f);
  }
  report.correlation = Eigen::MatrixXd::Identity(est.size(), est.size());
  for (std::size_t a = 0; a < est.size(); ++a) {
    report.correlation_names.push_back(parameter_info(est[a]).name);
    if (!cov) continue;
    for (std::size_t b = 0; b < est.size(); ++b)
      if ((*cov)(est[a], est[a]) > 0 && (*cov)(est[b], est[b]) > 0)
        report.correlation(a, b) =
            (*cov)(est[a], est[b]) / std::sqrt((*cov)(est[a], est[a]) * (*cov)(est[b], est[b]));
  }
}

// Diagnostics on the used points: residual whiteness per channel, the dimensionless error,
// the Gaussian -2 log L with the noise scales, AIC and BIC.
void report_quality(const FitSetup& s, const Solution& sol, FitReport& report) {
  MeasuredData subset;
  std::vector<Resultants<double>> sub_pred;
  for (std::size_t i = 0; i < s.data.points.size(); ++i)
    if (s.used(i)) {
      subset.points.push_back(s.data.points[i]);
      sub_pred.push_back(sol.prediction[i]);
    }
  report.prediction = sol.prediction;
  report.psi = sliding_spin_ratio(s.data, s.spec.radius_m);
  report.residual.resize(s.data.points.size());
  for (std::size_t i = 0; i < s.data.points.size(); ++i)
    for (int c = 0; c < kChannels; ++c)
      if (const std::optional<double>& y = s.data.points[i].force[c])
        report.residual[i][c] = *y - sol.prediction[i].vector()(c);
  report.noise_model = s.noise.model;
  report.noise_scale = sol.scale;
  report.noise_slope = sol.slope;
  report.channels = residual_diagnostics(subset, sub_pred, s.spec.radius_m, sol.scale);
  const std::array<double, kChannels> scatter = neighbour_scatter(subset, sub_pred);
  for (ChannelDiagnostics& d : report.channels)
    for (int c = 0; c < kChannels; ++c)
      if (d.channel == kChannelColumns[c]) {
        d.noise_slope = sol.slope[c];
        d.neighbour_scale = scatter[c];
      }
  report.residual_white = std::all_of(report.channels.begin(), report.channels.end(),
                                      [](const ChannelDiagnostics& d) { return d.white; });
  double log_det = 0.0, err2 = 0.0;
  for (std::size_t i = 0; i < s.data.points.size(); ++i) {
    if (!s.used(i)) continue;
    for (int c = 0; c < kChannels; ++c) {
      if (!s.data.points[i].force[c]) continue;
      const double sc =
          value_scale(report.noise_scales(), c, sol.prediction[i].vector()(c), s.floor_rel[c]);
      log_det += std::log(2.0 * std::numbers::pi * sc * sc);
    }
  }
  const int measured = static_cast<int>(report.channels.size());
  for (int c = 0, k = 0; c < kChannels; ++c) {
    if (s.counts[c] == 0) continue;
    const double rel = report.channels[k++].rms / s.peak[c];
    err2 += rel * rel;
  }
  report.error = std::sqrt(err2 / std::max(measured, 1));
  const int k_params = report.free_parameters + measured * noise_parameters(s.noise);
  report.m2ll = log_det + report.chi2;
  report.aic = report.m2ll + 2.0 * k_params;
  report.bic = report.m2ll + k_params * std::log(static_cast<double>(report.residuals));
}

}  // namespace

int measured_values_needed(const MeasuredData& data, const ModelSpec& spec,
                           const NoiseSettings& noise) {
  int needed = static_cast<int>(std::count(spec.free.begin(), spec.free.end(), true)) + 1;
  for (int c = 0; c < kChannels; ++c) needed += data.count(c) > 0 ? noise_parameters(noise) : 0;
  return needed;
}

FitReport fit_model(const MeasuredData& data, const ModelSpec& spec, const NoiseSettings& noise,
                    std::array<double, K>* estimate, const std::vector<char>& use) {
  const FitSetup setup = prepare_fit(data, spec, noise, use);
  Solution sol = solve(setup);
  FitReport report;
  report.converged = sol.summary.IsSolutionUsable();
  report.solver_summary = sol.summary.BriefReport();
  const Eigen::MatrixXd J = jacobian_at_optimum(*sol.problem, spec, &report);
  const std::array<bool, K> undetermined = undetermined_parameters(J, setup.active);
  std::vector<int> est;  // free and determined
  for (int i : setup.active)
    if (!undetermined[i]) est.push_back(i);
  report.free_parameters = static_cast<int>(est.size());
  int estimated_scales = 0;  // each estimated noise parameter uses up a degree of freedom too
  for (int c = 0; c < kChannels; ++c)
    estimated_scales += setup.counts[c] > 0 ? noise_parameters(noise) : 0;
  report.degrees_of_freedom = report.residuals - report.free_parameters - estimated_scales;
  const std::optional<Eigen::MatrixXd> cov = parameter_covariance(J, setup.active, est, report);
  report_parameters(spec, sol.theta, undetermined, est, cov, report);
  if (!spec.exact_only) report.law = fractional_law_of(spec, sol.theta.data());
  report_quality(setup, sol, report);
  if (estimate) *estimate = sol.theta;
  return report;
}

void weighted_jacobian(const MeasuredData& data, const ModelSpec& spec,
                       const std::array<double, K>& theta_in, const NoiseScales& noise,
                       Eigen::VectorXd* r, Eigen::MatrixXd* J, const std::vector<char>& use,
                       std::vector<int>* row_point) {
  std::array<double, K> theta = theta_in;
  const std::array<double, kChannels> peak = channel_magnitudes(data, spec.radius_m);
  std::array<double, kChannels> floor_rel{};
  for (int c = 0; c < kChannels; ++c) floor_rel[c] = 0.05 * peak[c];
  const std::vector<Resultants<double>> pred = evaluate_all(spec, theta.data(), data);
  // Columns for the parameters that are free or scored (non-null or listed as free); the
  // others get zero columns.
  std::vector<int> active;
  for (int i = 0; i < K; ++i)
    if (spec.free[i] || spec.value[i] != parameter_info(i).null_value || i <= kKx ||
        (i >= kKy && i <= kXMzFy) || i == kShapeBlend ||
        (i >= kSlipAngleOffset && i <= kFrictionScale))
      active.push_back(i);
  std::vector<double> packed(active.size());
  for (std::size_t j = 0; j < active.size(); ++j) packed[j] = theta[active[j]];
  ceres::Problem problem;
  const Weighting wt{noise, floor_rel, &pred, RobustLoss::none, 1.0, -1};
  add_points(problem, data, spec, active, theta, packed.data(), wt, use);
  if (row_point) {
    row_point->clear();
    for (std::size_t i = 0; i < data.points.size(); ++i) {
      if (!use.empty() && !use[i]) continue;
      for (int c = 0; c < kChannels; ++c)
        if (data.points[i].force[c]) row_point->push_back(static_cast<int>(i));
    }
  }
  ceres::CRSMatrix crs;
  std::vector<double> res;
  double cost = 0.0;
  problem.Evaluate(evaluate_options(), &cost, &res, nullptr, &crs);
  *r = Eigen::Map<Eigen::VectorXd>(res.data(), static_cast<Eigen::Index>(res.size()));
  *J = Eigen::MatrixXd::Zero(crs.num_rows, K);
  for (int row = 0; row < crs.num_rows; ++row)
    for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k)
      (*J)(row, active[crs.cols[k]]) = crs.values[k];
}

FitReport fit_fractional_law(const MeasuredData& data, const IdentificationOptions& o) {
  return fit_model(data, base_spec_for(data, o), noise_settings_for(o));
}

}  // namespace contensou
