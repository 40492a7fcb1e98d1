// The fit as a Ceres problem: one residual block per row, the bounds, the solve (with the bound
// watch and the noise rounds). See fit_problem.hpp.
#include "fit_problem.hpp"
#include "test_seams.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>

#include "contensou/friction/error.hpp"
#include "contensou/identification/effect_model.hpp"
#include "point_batch.hpp"

namespace contensou {
using namespace detail;  // NOLINT: this file implements part of fit_problem.hpp

namespace {

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

// The bounds of the active parameters under the spec (parameter_bounds).
std::vector<ParameterBounds> active_bounds(const ModelSpec& spec, const std::vector<int>& active) {
  std::vector<ParameterBounds> out;
  for (int i : active) out.push_back(parameter_bounds(spec, i));
  return out;
}

// Bounds that keep the model physical, on the packed active parameters.
void set_bounds(ceres::Problem& problem, double* packed,
                const std::vector<ParameterBounds>& bounds) {
  for (std::size_t j = 0; j < bounds.size(); ++j) {
    const ParameterBounds b = bounds[j];
    const int jj = static_cast<int>(j);
    if (std::isfinite(b.lower)) problem.SetParameterLowerBound(packed, jj, b.lower);
    if (std::isfinite(b.upper)) problem.SetParameterUpperBound(packed, jj, b.upper);
  }
}

// The law's shape held inside the laws a non-negative pressure gives jointly
// (admissible_shape.hpp, theory.md section 4.1): with t = sqrt(a)/2, r = 2/sqrt(m) and
// q = M0 / (F0 R), the conditions g1 = t - r <= 0, g2 = q - r <= 0 and
// g3 = (1 - q)^2 - (1 - t) q (1 - r) / t <= 0 (divided by t, so that it keeps its scale as a
// goes to 0; a <= 4 and m >= 4 are the bounds). Each residual is
// W max(0, g_i): zero inside, and with W = 1e4 sqrt(n) so stiff that an optimum pressed against
// the edge stays within about 1e-8 of it. It is removed before the covariance.
struct ShapePenalty {
  const std::vector<int>* active;
  const std::array<double, K>* theta_const;
  double radius, weight;
  template <class T>
  bool operator()(T const* const* p, T* r) const {
    const auto value = [&](int i) {
      for (std::size_t j = 0; j < active->size(); ++j)
        if ((*active)[j] == i) return p[0][j];
      return T((*theta_const)[static_cast<std::size_t>(i)]);
    };
    using std::sqrt;
    const T t = sqrt(value(kA)) / 2.0, rr = 2.0 / sqrt(value(kMShape));
    const T q = value(kM0) / (value(kF0) * radius);
    const T g[3] = {t - rr, q - rr, (1.0 - q) * (1.0 - q) - (1.0 - t) * q * (1.0 - rr) / t};
    for (int k = 0; k < 3; ++k) r[k] = g[k] > T(0.0) ? weight * g[k] : T(0.0);
    return true;
  }
};

// Adds the penalty when the law takes part and its shape is to be admissible (a, m, M0 or F0
// free); returns its block, or nullptr.
ceres::ResidualBlockId add_shape_penalty(ceres::Problem& problem, const FitSetup& s,
                                         double* packed) {
  const ModelSpec& spec = s.spec;
  if (!spec.joint_admissibility || spec.exact_only ||
      !(spec.free[kA] || spec.free[kMShape] || spec.free[kM0] || spec.free[kF0]))
    return nullptr;
  auto* cost = new ceres::DynamicAutoDiffCostFunction<ShapePenalty, 8>(new ShapePenalty{
      &s.active, &s.theta_const, spec.radius_m, 1e4 * std::sqrt(static_cast<double>(s.n))});
  cost->AddParameterBlock(static_cast<int>(s.active.size()));
  cost->SetNumResiduals(3);
  return problem.AddResidualBlock(cost, nullptr, packed);
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
  BoundWatch(const std::vector<double>& packed, const std::vector<ParameterBounds>& bounds)
      : packed_(packed), bounds_(bounds), run_(bounds.size(), 0) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& it) override {
    if (it.iteration == 0 || !it.step_is_successful) return ceres::SOLVER_CONTINUE;
    bool pinned = false;
    for (std::size_t j = 0; j < bounds_.size(); ++j) {
      run_[j] = at_bound(j) ? run_[j] + 1 : 0;
      pinned = pinned || run_[j] >= kPinnedIterations;
    }
    return pinned ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }
  // Ceres keeps a bound by clipping the step to it: a parameter on its bound equals it.
  bool at_bound(std::size_t j) const {
    return packed_[j] == bounds_[j].lower || packed_[j] == bounds_[j].upper;
  }
  bool at_lower(std::size_t j) const { return packed_[j] == bounds_[j].lower; }

 private:
  const std::vector<double>& packed_;
  const std::vector<ParameterBounds>& bounds_;
  std::vector<int> run_;
};

// The parameters on their bounds whose gradient g_j (of the cost) points out of the box: at a
// lower bound g_j > 0, at an upper bound g_j < 0 (the cost would rise going inside). Those
// the data hold on their bounds (the Karush-Kuhn-Tucker condition); the others are free to go.
std::vector<int> held_on_bounds(ceres::Problem& problem, std::size_t active,
                                const BoundWatch& watch) {
  double cost = 0.0;
  std::vector<double> gradient;
  ceres::Problem::EvaluateOptions o = evaluate_options();
  if (!problem.Evaluate(o, &cost, nullptr, &gradient, nullptr)) return {};
  std::vector<int> held;
  for (std::size_t j = 0; j < active; ++j) {
    if (!watch.at_bound(j)) continue;
    const bool lower = watch.at_lower(j);
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
                   const std::vector<ParameterBounds>& bounds, ceres::Solver::Summary& summary) {
  BoundWatch watch(packed, bounds);
  opt.update_state_every_iteration = true;
  opt.callbacks.push_back(&watch);
  ceres::Solve(opt, &problem, &summary);
  opt.callbacks.pop_back();
  if (summary.termination_type != ceres::USER_SUCCESS) return;
  const std::vector<int> held = held_on_bounds(problem, bounds.size(), watch);
  const int n = static_cast<int>(bounds.size());
  if (!held.empty() && static_cast<int>(held.size()) < n) {
    problem.SetManifold(packed.data(), new ceres::SubsetManifold(n, held));
    ceres::Solve(opt, &problem, &summary);
    problem.SetManifold(packed.data(), nullptr);
    if (!summary.IsSolutionUsable()) return;
  }
  if (held.empty() || held_on_bounds(problem, bounds.size(), watch) != held)
    ceres::Solve(opt, &problem, &summary);
}

}  // namespace

namespace detail {

// Ceres' evaluation of a whole problem, on evaluation_threads().
ceres::Problem::EvaluateOptions evaluate_options() {
  ceres::Problem::EvaluateOptions o;
  o.num_threads = evaluation_threads();
  return o;
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

// Noise parameters estimated per measured channel: none when given, a_c and b_c for affine
// noise, else s_c.
int noise_parameters(const NoiseSettings& noise) {
  if (noise.given) return 0;
  return noise.model == NoiseModel::affine ? 2 : 1;
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

// Build the problem, solve, estimate the noise scales; repeated (warm-started) until the
// scales settle, once when they are given and additive.
Solution solve(const FitSetup& s) {
  Solution sol;
  sol.theta = s.spec.value;
  sol.scale = initial_noise_scales(s);
  if (!s.noise.given && s.noise.start && s.noise.start->model == NoiseModel::affine &&
      s.noise.model == NoiseModel::affine)
    sol.slope = s.noise.start->slope;
  // The start within the bounds (a profile given with m < 4, say, starts at m = 4).
  const std::vector<ParameterBounds> bounds = active_bounds(s.spec, s.active);
  sol.packed.resize(s.active.size());
  for (std::size_t j = 0; j < s.active.size(); ++j) {
    sol.packed[j] = std::clamp(sol.theta[s.active[j]], bounds[j].lower, bounds[j].upper);
    sol.theta[s.active[j]] = sol.packed[j];
  }
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
                       testing::Seams::of(s.noise).failing_point};
    add_points(*sol.problem, s.data, s.spec, s.active, s.theta_const, sol.packed.data(), wt, s.use);
    sol.shape_penalty = add_shape_penalty(*sol.problem, s, sol.packed.data());
    set_bounds(*sol.problem, sol.packed.data(), bounds);
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
    solve_bounded(opt, *sol.problem, sol.packed, bounds, sol.summary);
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
  if (sol.shape_penalty) sol.problem->RemoveResidualBlock(sol.shape_penalty);
  sol.shape_penalty = nullptr;
  return sol;
}

}  // namespace detail

}  // namespace contensou
