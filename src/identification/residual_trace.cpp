#include "contensou/identification/residual_trace.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numeric>
#include <set>

#include "contensou/identification/fit.hpp"
#include "contensou/identification/statistics.hpp"

namespace contensou {

namespace {

// The range of a variable over the rows that have it: {min, max, distinct values (up to 3)}.
struct Range {
  double lo = INFINITY, hi = -INFINITY;
  int distinct = 0;
};

Range range_of(const MeasuredData& d, const Covariate& c) {
  Range r;
  std::set<double> seen;
  for (const MeasuredPoint& p : d.points) {
    const double x = c.value(p);
    if (!std::isfinite(x)) continue;
    r.lo = std::min(r.lo, x);
    r.hi = std::max(r.hi, x);
    if (seen.size() < 3) seen.insert(x);
  }
  r.distinct = static_cast<int>(seen.size());
  return r;
}

// Scaled to [-1, 1] over its range; false if it takes fewer than three values.
bool scale_over_data(const MeasuredData& d, Covariate& c) {
  const Range r = range_of(d, c);
  if (r.distinct < 3 || !(r.hi > r.lo)) return false;
  c.mid = 0.5 * (r.lo + r.hi);
  c.half_range = 0.5 * (r.hi - r.lo);
  return std::isfinite(c.mid) && c.half_range > 0.0 && std::isfinite(c.half_range);
}

// Average ranks (1-based; ties share their mean rank).
std::vector<double> ranks(const std::vector<double>& x) {
  std::vector<std::size_t> order(x.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(x.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && x[order[j + 1]] == x[order[i]]) ++j;
    const double mean = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = mean;
    i = j + 1;
  }
  return r;
}

double pearson(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  const double ma = std::accumulate(a.begin(), a.end(), 0.0) / n;
  const double mb = std::accumulate(b.begin(), b.end(), 0.0) / n;
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

// A channel's standardised residuals paired with a variable, over the rows that have both.
struct Sample {
  std::vector<double> e, x;
};

// Spearman's rho_s and its two-sided p (Student's t, n - 2 degrees of freedom).
void spearman(const Sample& s, TracedVariable& t) {
  const double n = static_cast<double>(s.e.size());
  const double rho = pearson(ranks(s.e), ranks(s.x));
  const double tstat = rho * std::sqrt((n - 2.0) / std::max(1.0 - rho * rho, 1e-300));
  t.test = "Spearman";
  t.statistic = rho;
  t.p_value = std::min(1.0, 2.0 * (1.0 - student_t_cdf(std::abs(tstat), n - 2.0)));
  t.size = rho * rho;
}

// Kruskal-Wallis' H over k quantile bins of x (rows with equal x in one bin), p from
// chi-square with (bins - 1) degrees of freedom; the bins' mean residual spread.
void kruskal_wallis(const Sample& s, TracedVariable& t) {
  const std::size_t n = s.e.size();
  const int k = std::clamp(static_cast<int>(n / 30), 3, 10);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
  const std::vector<double> re = ranks(s.e);
  std::vector<double> rank_sum, mean_e;
  std::vector<int> count;
  for (std::size_t i = 0; i < n;) {
    std::size_t end = std::max(i + 1, (rank_sum.size() + 1) * n / static_cast<std::size_t>(k));
    while (end < n && s.x[order[end]] == s.x[order[end - 1]]) ++end;  // ties in one bin
    double rs = 0.0, es = 0.0;
    for (std::size_t j = i; j < end; ++j) {
      rs += re[order[j]];
      es += s.e[order[j]];
    }
    rank_sum.push_back(rs);
    mean_e.push_back(es / static_cast<double>(end - i));
    count.push_back(static_cast<int>(end - i));
    i = end;
  }
  const double N = static_cast<double>(n);
  double h = 0.0;
  for (std::size_t b = 0; b < rank_sum.size(); ++b) h += rank_sum[b] * rank_sum[b] / count[b];
  h = 12.0 / (N * (N + 1.0)) * h - 3.0 * (N + 1.0);
  const int bins = static_cast<int>(rank_sum.size());
  t.test = "Kruskal-Wallis";
  t.statistic = std::max(h, 0.0);
  t.p_value = bins > 1 ? chi2_survival(t.statistic, bins - 1.0) : 1.0;
  t.size = t.statistic / (N - 1.0);
  const auto [lo, hi] = std::minmax_element(mean_e.begin(), mean_e.end());
  t.spread_sigma = *hi - *lo;
}

// The noise scale of a value (the fit's noise model, without the relative model's floor).
double scale_at(const FitReport& f, int c, double yhat) {
  if (f.noise_model == NoiseModel::relative)
    return f.noise_scale[c] * std::max(std::abs(yhat), 1e-300);
  return f.noise_scale[c] + f.noise_slope[c] * std::abs(yhat);
}

// A variable of the trace: its name and its value at a row (NaN where none).
struct Variable {
  std::string name;
  bool kinematic;
  int covariate;
  bool ordered;  // false: an angle (Kruskal-Wallis only)
  std::function<double(const MeasuredPoint&)> at;
};

std::vector<Variable> variables(const std::vector<Covariate>& covariates, double R) {
  std::vector<Variable> v;
  for (std::size_t i = 0; i < covariates.size(); ++i) {
    const Covariate c = covariates[i];
    v.push_back({c.name, false, static_cast<int>(i), true,
                 [c](const MeasuredPoint& p) { return c.value(p); }});
  }
  v.push_back({"slip speed", true, -1, true, [](const MeasuredPoint& p) {
                 return std::hypot(p.kinematics.vx, p.kinematics.vy);
               }});
  v.push_back({"psi", true, -1, true, [R](const MeasuredPoint& p) {
                 const double u = std::abs(p.kinematics.omega) * R;
                 const double s = std::hypot(p.kinematics.vx, p.kinematics.vy);
                 return u > 0.0 ? s / u : (s > 0.0 ? INFINITY : NAN);
               }});
  v.push_back({"spin speed", true, -1, true,
               [R](const MeasuredPoint& p) { return std::abs(p.kinematics.omega) * R; }});
  v.push_back({"sliding direction", true, -1, false, [](const MeasuredPoint& p) {
                 return p.kinematics.vx == 0.0 && p.kinematics.vy == 0.0
                            ? NAN
                            : std::atan2(p.kinematics.vy, p.kinematics.vx);
               }});
  return v;
}

// Holm's step-down adjustment: p_(i) (m - i + 1), made monotone, capped at 1.
void holm(std::vector<TracedVariable>& tests) {
  std::vector<std::size_t> order(tests.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return tests[a].p_value < tests[b].p_value; });
  double running = 0.0;
  const double m = static_cast<double>(tests.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    running =
        std::max(running, std::min(1.0, tests[order[i]].p_value * (m - static_cast<double>(i))));
    tests[order[i]].p_adjusted = running;
  }
}

std::string fmt(const char* f, double v) {
  char b[48];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::vector<Covariate> covariates_of(const MeasuredData& data) {
  std::vector<Covariate> out;
  Covariate load{Covariate::Kind::load, -1, "Fz_N", "N"};
  const Range lr = range_of(data, load);
  if (lr.distinct >= 3 && lr.hi > 1.01 * lr.lo && scale_over_data(data, load)) out.push_back(load);
  const bool timed = std::all_of(data.points.begin(), data.points.end(),
                                 [](const MeasuredPoint& p) { return p.time.has_value(); });
  Covariate run = timed ? Covariate{Covariate::Kind::time, -1, "t_s", "s"}
                        : Covariate{Covariate::Kind::order, -1, "row order", ""};
  if (scale_over_data(data, run)) out.push_back(run);
  for (std::size_t k = 0; k < data.recorded.size(); ++k) {
    const RecordedVariable& r = data.recorded[k];
    Covariate c{Covariate::Kind::recorded, static_cast<int>(k), r.header, r.si_unit};
    if (scale_over_data(data, c)) out.push_back(c);
  }
  return out;
}

std::string TracedVariable::describe() const {
  std::string s = channel + " follows " + variable + " (" + test + " ";
  s += test == "Spearman" ? "rho = " + fmt("%+.2f", statistic) : "H = " + fmt("%.3g", statistic);
  s += ", p = " + fmt("%.2g", p_adjusted);
  if (spread_sigma > 0.0) s += ", bins span " + fmt("%.2g", spread_sigma) + " sigma";
  return s + ")";
}

std::string ResidualTrace::where() const {
  std::vector<std::string> names;
  std::vector<std::string> channels;
  for (const TracedVariable& t : followed) {
    const auto it = std::find(names.begin(), names.end(), t.variable);
    if (it == names.end()) {
      names.push_back(t.variable);
      channels.push_back(t.channel);
    } else if (channels[it - names.begin()].find(t.channel) == std::string::npos) {
      channels[it - names.begin()] += ", " + t.channel;
    }
  }
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += (i ? "; " : "") + names[i] + " (" + channels[i] + ")";
  return s;
}

ResidualTrace trace_residual(const MeasuredData& data, const FitReport& fit, double radius_m,
                             const std::vector<Covariate>& covariates, double alpha) {
  ResidualTrace trace;
  trace.alpha = alpha;
  if (fit.residual.size() != data.points.size() || fit.prediction.size() != data.points.size())
    return trace;
  std::vector<TracedVariable> all;
  const std::vector<Variable> vars = variables(covariates, radius_m);
  for (int c = 0; c < kChannels; ++c) {
    for (const Variable& v : vars) {
      Sample s;
      std::set<double> distinct;
      for (std::size_t i = 0; i < data.points.size(); ++i) {
        const std::optional<double>& r = fit.residual[i][c];
        const double x = v.at(data.points[i]);
        const double sc = scale_at(fit, c, fit.prediction[i].vector()(c));
        if (!r || std::isnan(x) || !(sc > 0.0)) continue;
        s.e.push_back(*r / sc);
        s.x.push_back(x);
        if (distinct.size() < 3) distinct.insert(x);
      }
      if (s.e.size() < 12 || distinct.size() < 3) continue;
      TracedVariable base;
      base.channel = kChannelColumns[c];
      base.variable = v.name;
      base.kinematic = v.kinematic;
      base.covariate = v.covariate;
      TracedVariable kw = base;
      kruskal_wallis(s, kw);
      all.push_back(kw);
      if (!v.ordered) continue;
      TracedVariable sp = base;
      spearman(s, sp);
      sp.spread_sigma = kw.spread_sigma;
      all.push_back(sp);
    }
  }
  holm(all);
  trace.tests = static_cast<int>(all.size());
  for (const TracedVariable& t : all)
    if (t.p_adjusted < alpha) trace.followed.push_back(t);
  // Strongest first; a variable's second test (the weaker) dropped.
  std::sort(trace.followed.begin(), trace.followed.end(),
            [](const TracedVariable& a, const TracedVariable& b) { return a.size > b.size; });
  std::vector<TracedVariable> kept;
  for (const TracedVariable& t : trace.followed)
    if (std::none_of(kept.begin(), kept.end(), [&](const TracedVariable& k) {
          return k.channel == t.channel && k.variable == t.variable;
        }))
      kept.push_back(t);
  trace.followed = kept;
  return trace;
}

}  // namespace contensou
