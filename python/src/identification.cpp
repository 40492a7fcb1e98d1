// Identification: the fit and the closed loop on measured diagrams given as a CSV path or as
// arrays (a DataFrame's columns, from contensou/identification.py), with the app's report JSON.
#include <glog/logging.h>
#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

#include "common.hpp"
#include "contensou/identification.hpp"

namespace contensou::python {
namespace {

using namespace nb::literals;
using Column = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

// Measured data from columns: kinematics (finite), channels (NaN = not measured; a missing
// column = None), optional Fz_N (positive) and t_s. Rows are numbered from 1 in messages.
MeasuredData data_from_columns(const std::string& source, Column vx, Column vy, Column omega,
                               const std::array<std::optional<Column>, kChannels>& channels,
                               std::optional<Column> fz, std::optional<Column> ts) {
  const std::size_t n = vx.shape(0);
  auto check_length = [&](const Column& c, const char* name) {
    if (c.shape(0) != n)
      throw std::invalid_argument(std::string("column '") + name + "' has " +
                                  std::to_string(c.shape(0)) + " rows, vx_mps has " +
                                  std::to_string(n));
  };
  check_length(vy, "vy_mps");
  check_length(omega, "omega_radps");
  bool any = false;
  for (int c = 0; c < kChannels; ++c)
    if (channels[c]) {
      check_length(*channels[c], kChannelColumns[c]);
      any = true;
    }
  if (!any)
    throw std::invalid_argument(source + ": no measured channel (need Fx_N, Fy_N or Mz_Nm)");
  if (fz) check_length(*fz, "Fz_N");
  if (ts) check_length(*ts, "t_s");
  if (n == 0) throw std::invalid_argument(source + ": no data rows");
  auto bad = [&](std::size_t i, const char* column, double v, const char* rule) {
    throw std::invalid_argument(source + ": row " + std::to_string(i + 1) + ": column '" + column +
                                "': " + format_value(v) + " " + rule);
  };
  MeasuredData d;
  d.source = source;
  d.points.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    MeasuredPoint& p = d.points[i];
    p.line = static_cast<int>(i + 1);
    p.kinematics = {vx(i), vy(i), omega(i)};
    const double k[3] = {vx(i), vy(i), omega(i)};
    const char* names[3] = {"vx_mps", "vy_mps", "omega_radps"};
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(k[j]))
        bad(i, names[j], k[j], "is not finite (the kinematics must be given)");
    for (int c = 0; c < kChannels; ++c) {
      if (!channels[c]) continue;
      const double y = (*channels[c])(i);
      if (std::isnan(y)) continue;  // not measured
      if (!std::isfinite(y)) bad(i, kChannelColumns[c], y, "is not finite");
      p.force[c] = y;
    }
    if (fz && !std::isnan((*fz)(i))) {
      const double v = (*fz)(i);
      if (!(v > 0.0) || !std::isfinite(v)) bad(i, "Fz_N", v, "must be positive");
      p.normal_load = v;
    }
    if (ts && !std::isnan((*ts)(i))) {
      if (!std::isfinite((*ts)(i))) bad(i, "t_s", (*ts)(i), "is not finite");
      p.time = (*ts)(i);
    }
  }
  return d;
}

std::vector<double> forces_of(const std::vector<Resultants<double>>& r) {
  std::vector<double> out;
  out.reserve(3 * r.size());
  for (const Resultants<double>& x : r) {
    out.push_back(x.Fx);
    out.push_back(x.Fy);
    out.push_back(x.Mz);
  }
  return out;
}

// Covariance of the free, determined parameters: correlation scaled by the standard errors.
nb::dict covariance_of(const FitReport& fit) {
  const std::size_t k = fit.correlation_names.size();
  std::vector<double> se(k, std::nan("")), cov(k * k);
  for (std::size_t i = 0; i < k; ++i)
    if (const ParameterEstimate* p = fit.parameter(fit.correlation_names[i])) se[i] = p->std_error;
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j)
      cov[i * k + j] = fit.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) *
                       se[i] * se[j];
  nb::dict d;
  d["names"] = fit.correlation_names;
  d["matrix"] = to_numpy(std::move(cov), {k, k});
  return d;
}

nb::dict identify(std::optional<std::string> path, std::string source, std::optional<Column> vx,
                  std::optional<Column> vy, std::optional<Column> omega, std::optional<Column> fx,
                  std::optional<Column> fy, std::optional<Column> mz, std::optional<Column> fz,
                  std::optional<Column> ts, double radius, std::optional<double> load,
                  std::optional<std::string> profile_spec, std::optional<double> pressure,
                  const std::map<std::string, double>& fixed, const std::string& loss,
                  double loss_scale, const std::string& noise_model,
                  std::optional<std::vector<double>> noise_scale, bool loop_on, double alpha,
                  bool speed_inside, int smoothing, bool profile_clip) {
  // The option handling of contensou-identify (apps/identify/main.cpp, run_fit).
  IdentificationOptions o;
  o.radius_m = radius;
  require_positive("radius", radius);
  if (load && profile_spec)
    throw std::invalid_argument("give normal_load or profile, not both (the profile gives N)");
  if (smoothing > 0 && (!profile_spec || !std::filesystem::exists(*profile_spec)))
    throw std::invalid_argument("profile_smoothing needs profile with a CSV file");
  if (load) require_positive("normal_load", *load);
  o.normal_load_n = load;
  ProfileChoice profile;
  if (profile_spec) {
    try {
      profile = choose_profile(*profile_spec, smoothing, profile_clip);
    } catch (const ParseError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(e.what());  // a missing file or a refused table: bad input
    }
    o.profile = profile.profile;
    const std::optional<double> ps =
        profile.reference_pressure ? profile.reference_pressure : pressure;
    if (ps) {
      ContactPatch patch;
      patch.radius_m = radius;
      patch.reference_pressure_pa = *ps;
      patch.profile = profile.profile;
      o.normal_load_n = normal_load(patch);
    }
  }
  o.fixed = fixed;
  if (loss != "none" && loss != "huber" && loss != "cauchy")
    throw std::invalid_argument("loss = " + loss + ": must be none, huber or cauchy");
  o.loss = loss == "huber"    ? RobustLoss::huber
           : loss == "cauchy" ? RobustLoss::cauchy
                              : RobustLoss::none;
  require_positive("loss_scale", loss_scale);
  o.loss_scale = loss_scale;
  if (noise_model != "additive" && noise_model != "relative")
    throw std::invalid_argument("noise_model = " + noise_model + ": must be additive or relative");
  o.noise_model = noise_model == "relative" ? NoiseModel::relative : NoiseModel::additive;
  if (noise_scale) {
    if (noise_scale->size() != 3)
      throw std::invalid_argument("noise_scale needs three values: Fx, Fy, Mz");
    o.noise_scale = std::array<double, 3>{(*noise_scale)[0], (*noise_scale)[1], (*noise_scale)[2]};
  }
  if (!(alpha >= 1e-12 && alpha <= 0.5))
    throw std::invalid_argument("alpha = " + format_value(alpha) + ": must lie in [1e-12, 0.5]");

  MeasuredData data;
  if (path) {
    data = read_measured_csv(*path);
    if (source.empty()) source = *path;
  } else {
    if (!vx || !vy || !omega)
      throw std::invalid_argument("the kinematics vx_mps, vy_mps and omega_radps are required");
    data = data_from_columns(source, *vx, *vy, *omega, {fx, fy, mz}, fz, ts);
  }
  const ReportInput info = describe_run(source, data, radius, o.normal_load_n, profile);
  const std::size_t n = data.points.size();
  std::vector<double> measured(3 * n, std::nan(""));
  for (std::size_t i = 0; i < n; ++i)
    for (int c = 0; c < kChannels; ++c)
      if (data.points[i].force[c]) measured[3 * i + c] = *data.points[i].force[c];

  nb::dict out;
  out["measured"] = to_numpy(std::move(measured), {n, 3});
  out["kinematics"] = [&] {
    std::vector<double> k;
    for (const MeasuredPoint& p : data.points) {
      k.push_back(p.kinematics.vx);
      k.push_back(p.kinematics.vy);
      k.push_back(p.kinematics.omega);
    }
    return to_numpy(std::move(k), {n, 3});
  }();
  if (!loop_on) {
    const FitReport fit = run_interruptible([&](const StopRequest& stop) {
      IdentificationOptions with_stop = o;
      with_stop.stop = stop;
      return fit_fractional_law(data, with_stop);
    });
    out["json"] = fit_report_json(info, fit);
    out["base_prediction"] = to_numpy(forces_of(fit.prediction), {n, 3});
    out["final_prediction"] = to_numpy(forces_of(fit.prediction), {n, 3});
    out["covariance"] = covariance_of(fit);
    return out;
  }
  ClosedLoopOptions lo;
  lo.alpha = alpha;
  lo.speed_inside_integrals = speed_inside;
  const ClosedLoopReport loop = run_interruptible([&](const StopRequest& stop) {
    IdentificationOptions with_stop = o;
    with_stop.stop = stop;
    return close_the_loop(data, with_stop, lo);
  });
  out["json"] = loop_report_json(info, loop);
  out["base_prediction"] = to_numpy(forces_of(loop.base.prediction), {n, 3});
  out["final_prediction"] = to_numpy(forces_of(loop.final_fit.prediction), {n, 3});
  out["covariance"] = covariance_of(loop.final_fit);
  nb::list steps;
  for (const LoopStep& st : loop.steps) {
    nb::dict s;
    s["prediction_before"] = to_numpy(forces_of(st.fit_before.prediction), {n, 3});
    s["prediction_after"] = to_numpy(forces_of(st.fit_after.prediction), {n, 3});
    steps.append(s);
  }
  out["steps"] = steps;
  return out;
}

}  // namespace

void bind_identification(nb::module_& m) {
  // Ceres logs through glog: quiet, as contensou-identify without --verbose.
  FLAGS_minloglevel = google::GLOG_FATAL;
  m.def("_identify", &identify, "path"_a.none(), "source"_a, "vx"_a.none(), "vy"_a.none(),
        "omega"_a.none(), "fx"_a.none(), "fy"_a.none(), "mz"_a.none(), "fz"_a.none(), "t"_a.none(),
        "radius"_a, "normal_load"_a.none(), "profile"_a.none(), "pressure"_a.none(), "fixed"_a,
        "loss"_a, "loss_scale"_a, "noise_model"_a, "noise_scale"_a.none(), "loop"_a, "alpha"_a,
        "speed_inside_integrals"_a, "profile_smoothing"_a, "profile_clip"_a);
}

}  // namespace contensou::python
