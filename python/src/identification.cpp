// Identification: the fit and the closed loop on measured diagrams given as a CSV path or as
// arrays (a DataFrame's columns, from contensou/identification.py), with the app's report JSON.
#include <glog/logging.h>
#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>

#include "common.hpp"
#include "contensou/identification.hpp"

namespace contensou::python {
namespace {

using namespace nb::literals;
using Column = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

// A table's cells from a column given as numbers (NaN = empty) or as text.
std::vector<std::string> cells_of(const nb::handle& column) {
  Column numbers;
  if (nb::try_cast<Column>(column, numbers)) {
    std::vector<std::string> cells(numbers.shape(0));
    char buf[32];
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (std::isnan(numbers(i))) continue;  // not measured
      // The shortest text that reads back as the same double: its last digit is the one the
      // data were written to (the reader's checks of a second column compare to that digit).
      const auto end = std::to_chars(buf, buf + sizeof buf, numbers(i)).ptr;
      cells[i].assign(buf, end);
    }
    return cells;
  }
  return nb::cast<std::vector<std::string>>(column);
}

// Measured data from named columns (a DataFrame's): the CSV reader's table in memory, so that
// units in names, renames, near misses and bad cells are handled as for a file; errors name
// the row (1-based) and its index.
MeasuredData data_from_columns(const std::string& source, const std::vector<std::string>& names,
                               const nb::list& columns, const ColumnRenames& renames,
                               bool channels_optional = false) {
  CsvTable t;
  t.file = source;
  t.header = names;
  t.rows_numbered = true;
  std::vector<std::vector<std::string>> cells;
  for (nb::handle c : columns) cells.push_back(cells_of(c));
  const std::size_t n = cells.empty() ? 0 : cells.front().size();
  for (std::size_t j = 0; j < cells.size(); ++j)
    if (cells[j].size() != n)
      throw std::invalid_argument("column '" + names[j] + "' has " +
                                  std::to_string(cells[j].size()) + " rows, '" + names[0] +
                                  "' has " + std::to_string(n));
  t.rows.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    t.rows[i].line = static_cast<int>(i + 1);
    for (std::vector<std::string>& c : cells) t.rows[i].cells.push_back(std::move(c[i]));
  }
  return measured_data_from_table(t, renames, KeyStyle::python, channels_optional);
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

// The fitted rows as arrays: their index in the data given, kinematics and measured values
// (NaN = not measured, or left out as a gross error).
void put_fitted_rows(nb::dict& out, const MeasuredData& given, const MeasuredData& fitted) {
  std::map<int, std::size_t> index_of_line;
  for (std::size_t i = 0; i < given.points.size(); ++i) index_of_line[given.points[i].line] = i;
  const std::size_t n = fitted.points.size();
  std::vector<double> measured(3 * n, std::nan("")), k(3 * n), rows(n);
  for (std::size_t i = 0; i < n; ++i) {
    const MeasuredPoint& p = fitted.points[i];
    rows[i] = static_cast<double>(index_of_line[p.line]);
    k[3 * i] = p.kinematics.vx;
    k[3 * i + 1] = p.kinematics.vy;
    k[3 * i + 2] = p.kinematics.omega;
    for (int c = 0; c < kChannels; ++c)
      if (p.force[c]) measured[3 * i + c] = *p.force[c];
  }
  out["rows"] = to_numpy(std::move(rows), {n});
  out["kinematics"] = to_numpy(std::move(k), {n, 3});
  out["measured"] = to_numpy(std::move(measured), {n, 3});
}

// The report as text and JSON, the predictions and the loop's steps.
void put_results(nb::dict& out, const IdentifyRun& run) {
  const Identification& r = run.result;
  const std::size_t n = r.fitted.points.size();
  out["base_prediction"] = to_numpy(forces_of(r.fit.prediction), {n, 3});
  out["final_prediction"] = to_numpy(forces_of(r.final_fit().prediction), {n, 3});
  out["covariance"] = covariance_of(r.final_fit());
  nb::list steps;
  if (!r.loop) {
    out["json"] = fit_report_json(run.input, r.fit);
    out["text"] = fit_report_text_with_cautions(run.input, r.fit);
  } else {
    out["json"] = loop_report_json(run.input, *r.loop);
    out["text"] = loop_report_text(run.input, *r.loop);
    for (const LoopStep& st : r.loop->steps) {
      nb::dict s;
      s["prediction_before"] = to_numpy(forces_of(st.fit_before.prediction), {n, 3});
      s["prediction_after"] = to_numpy(forces_of(st.fit_after.prediction), {n, 3});
      steps.append(s);
    }
  }
  out["steps"] = steps;
}

// columns= as "vx=Speed,omega=Rate" or a mapping {quantity: header cell} (any characters in the
// cell, commas too; a list of cells for 'extra' and 'ignore'); errors name Python's keyword.
ColumnRenames renames_of(const nb::object& renames) {
  if (renames.is_none()) return {};
  if (nb::isinstance<nb::str>(renames))
    return parse_column_renames(nb::cast<std::string>(renames), KeyStyle::python);
  ColumnRenames out;
  for (const auto& [quantity, column] : nb::cast<nb::dict>(renames)) {
    const std::string q = nb::cast<std::string>(nb::str(quantity));
    if (nb::isinstance<nb::list>(column) || nb::isinstance<nb::tuple>(column)) {
      for (const nb::handle c : column)  // {'extra': ['T', 'P']}: several columns
        add_column_rename(out, q, nb::cast<std::string>(nb::str(c)), KeyStyle::python);
      continue;
    }
    add_column_rename(out, q, nb::cast<std::string>(nb::str(column)), KeyStyle::python);
  }
  return out;
}

// contensou.identify(): the data from a CSV path or named columns, the request as the app's.
// One table of contensou.identify(): a CSV path, or a source name with column names and columns.
MeasuredData read_table(const nb::tuple& item, const ColumnRenames& renames,
                        bool channels_optional = false) {
  const nb::object path = item[0];
  const std::string source = nb::cast<std::string>(item[1]);
  MeasuredData data =
      path.is_none() ? data_from_columns(source, nb::cast<std::vector<std::string>>(item[2]),
                                         nb::cast<nb::list>(item[3]), renames, channels_optional)
                     : read_measured_csv(nb::cast<std::string>(path), renames, KeyStyle::python,
                                         channels_optional);
  if (!source.empty()) data.source = source;
  return data;
}

// contensou.identify() on one table or several fitted together (combine_measured: each row
// keeps its table and line; `loads`, one a table, for their rows without Fz).
nb::dict identify(const nb::list& items, const std::vector<double>& loads,
                  const nb::object& renames, IdentifyRequest request) {
  const ColumnRenames column_renames = renames_of(renames);
  std::vector<MeasuredData> tables;
  for (const nb::handle item : items)
    tables.push_back(read_table(nb::cast<nb::tuple>(item), column_renames));
  MeasuredData data = combine_measured(std::move(tables), loads);
  request.style = KeyStyle::python;
  const IdentifyRun run = run_interruptible([&](const StopRequest& stop) {
    IdentifyRequest with_stop = request;
    with_stop.stop = stop;
    return contensou::identify(data, with_stop);
  });
  nb::dict out;
  put_fitted_rows(out, data, run.result.fitted);
  put_results(out, run);
  return out;
}

// IdentificationResult.predict(): the model of a report (its "model" object) at the rows of
// one table or several, both ways (prediction.hpp): wrench (n, 3), unit twist (n, 3; NaN where
// the row's measured wrench is incomplete), the misfit [deg] and the scores.
nb::dict predict(const nb::list& items, const std::vector<double>& loads, const nb::object& renames,
                 const std::string& model_json) {
  const ColumnRenames column_renames = renames_of(renames);
  std::vector<MeasuredData> tables;
  for (const nb::handle item : items)
    tables.push_back(read_table(nb::cast<nb::tuple>(item), column_renames, true));
  const MeasuredData data = combine_measured(std::move(tables), loads);
  const ModelSpec model = bind_to_data(model_from_json(model_json, "the report"), data);
  const std::vector<RowPrediction> pred = predict_rows(model, data);
  const std::size_t n = pred.size();
  std::vector<double> twist(3 * n), misfit(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) twist[3 * i + c] = pred[i].twist[c];
    misfit[i] = pred[i].wrench_misfit_rad * 180.0 / 3.14159265358979323846;
  }
  const PredictionScores sc = score_predictions(data, pred, model.radius_m);
  nb::dict scores;
  scores["rows"] = sc.rows;
  scores["median_motion_angle_deg"] = sc.median_motion_angle_deg;
  scores["mean_motion_angle_deg"] = sc.mean_motion_angle_deg;
  scores["median_force_relative_error"] = sc.median_force_error;
  scores["mean_force_relative_error"] = sc.mean_force_error;
  scores["median_force_angle_deg"] = sc.median_force_angle_deg;
  nb::dict out;
  out["wrench"] = to_numpy(forces_of(wrenches_of(pred)), {n, 3});
  out["twist"] = to_numpy(std::move(twist), {n, 3});
  out["misfit_deg"] = to_numpy(std::move(misfit), {n});
  out["scores"] = scores;
  out["text"] = prediction_scores_text(sc);
  return out;
}

// The request's keys as attributes (identify_request.hpp's table gives their meaning).
void bind_request(nb::module_& m) {
  nb::class_<IdentifyRequest>(m, "_IdentifyRequest")
      .def(nb::init<>())
      .def_rw("radius", &IdentifyRequest::radius_m)
      .def_rw("normal_load", &IdentifyRequest::normal_load_n)
      .def_rw("profile", &IdentifyRequest::profile)
      .def_rw("pressure", &IdentifyRequest::pressure_pa)
      .def_rw("profile_smoothing", &IdentifyRequest::profile_smoothing)
      .def_rw("profile_clip", &IdentifyRequest::profile_clip)
      .def_rw("fix", &IdentifyRequest::fix)
      .def_rw("loss", &IdentifyRequest::loss)
      .def_rw("loss_scale", &IdentifyRequest::loss_scale)
      .def_rw("noise_model", &IdentifyRequest::noise_model)
      .def_rw("noise_scale", &IdentifyRequest::noise_scale)
      .def_rw("loop", &IdentifyRequest::loop)
      .def_rw("alpha", &IdentifyRequest::alpha)
      .def_rw("speed_inside_integrals", &IdentifyRequest::speed_inside_integrals)
      .def_rw("outliers", &IdentifyRequest::outliers)
      .def_rw("resamples", &IdentifyRequest::resamples)
      .def_rw("admissible_law", &IdentifyRequest::admissible_law);
  std::vector<std::pair<std::string, std::string>> keys;
  for (const RequestKey& k : identify_request_keys()) keys.emplace_back(k.key, k.help);
  m.attr("_identify_keys") = keys;
}

}  // namespace

void bind_identification(nb::module_& m) {
  // Ceres logs through glog: quiet, as contensou-identify without --verbose.
  FLAGS_minloglevel = google::GLOG_FATAL;
  bind_request(m);
  m.def("_identify", &identify, "items"_a, "loads"_a, "renames"_a.none(), "request"_a);
  m.def("_predict", &predict, "items"_a, "loads"_a, "renames"_a.none(), "model_json"_a);
}

}  // namespace contensou::python
