#include "tire_report.hpp"

#include "config.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace contensou::app {

namespace {

using Vector5 = Eigen::Matrix<double, 5, 1>;
using Matrix5 = Eigen::Matrix<double, 5, 5>;

// Errors name --tire, the file and the key.
struct ReportSource {
  std::string path;

  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("--tire " + path + ": " + what);
  }

  double number(const nlohmann::json& node, const std::string& key) const {
    if (!node.is_number() || !std::isfinite(node.get<double>()))
      fail(key + " must be a finite number, got " + node.dump());
    return node.get<double>();
  }

  nlohmann::json load() const {
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot open the report");
    std::stringstream buf;
    buf << in.rdbuf();
    try {
      return parse_json_without_duplicates(buf.str(), path);
    } catch (const nlohmann::json::exception& e) {
      fail(std::string("not a JSON report (") + e.what() + ")");
    }
  }
};

// final.params.<name>: the value into d.mean[i], the standard error (0 for a fixed parameter)
// into se[i]; a parameter the data could not determine has no distribution to draw from.
void read_parameter(const ReportSource& r, const nlohmann::json& params, int i,
                    TireLawDistribution& d, Vector5& se) {
  const std::string name = TireLawDistribution::kNames[static_cast<std::size_t>(i)];
  const std::string key = "final.params." + name;
  if (!params.contains(name) || !params[name].is_object() || !params[name].contains("value"))
    r.fail(key + ".value missing");
  d.mean[i] = r.number(params[name]["value"], key + ".value");
  const nlohmann::json& determined = params[name].value("determined", nlohmann::json(true));
  if (!determined.is_boolean() || !determined.get<bool>())
    r.fail(key +
           " was not determined by the data (\"determined\": false): its value is arbitrary and "
           "it has no interval; identify the tire on data that determine it");
  const nlohmann::json& s = params[name].value("std_error", nlohmann::json());
  if (!s.is_null()) se[i] = r.number(s, key + ".std_error");
  if (se[i] < 0) r.fail(key + ".std_error must be >= 0");
}

// The law's index of a name in final.correlation.names; -1 for another name.
int law_index(const nlohmann::json& n) {
  for (int i = 0; i < 5; ++i)
    if (n.is_string() &&
        n.get<std::string>() == TireLawDistribution::kNames[static_cast<std::size_t>(i)])
      return i;
  return -1;
}

// final.correlation over its names (the identity where it is missing); other names are skipped.
Matrix5 read_correlation(const ReportSource& r, const nlohmann::json& final_node) {
  Matrix5 corr = Matrix5::Identity();
  const nlohmann::json& c = final_node.value("correlation", nlohmann::json());
  if (!c.is_object() || !c.contains("names") || !c.contains("matrix")) return corr;
  const nlohmann::json &names = c["names"], &matrix = c["matrix"];
  if (!names.is_array() || !matrix.is_array() || matrix.size() != names.size())
    r.fail("final.correlation: names and matrix differ in size");
  for (std::size_t row = 0; row < names.size(); ++row) {
    if (!matrix[row].is_array() || matrix[row].size() != names.size())
      r.fail("final.correlation.matrix row " + std::to_string(row + 1) + " has the wrong length");
    const int i = law_index(names[row]);
    for (std::size_t q = 0; q < names.size(); ++q) {
      const int k = law_index(names[q]);
      const double v = r.number(matrix[row][q], "final.correlation.matrix");
      if (i >= 0 && k >= 0) corr(i, k) = v;
    }
  }
  return corr;
}

}  // namespace

TireLawDistribution read_tire_report(const std::string& path) {
  const ReportSource r{path};
  const nlohmann::json j = r.load();
  if (!j.is_object() || !j.contains("final") || !j["final"].is_object() ||
      !j["final"].contains("params") || !j["final"]["params"].is_object())
    r.fail("no final.params (write it with contensou-identify --json)");
  TireLawDistribution d;
  if (!j.contains("input") || !j["input"].is_object() || !j["input"].contains("radius_m"))
    r.fail("no input.radius_m");
  d.radius_m = r.number(j["input"]["radius_m"], "input.radius_m");
  if (!(d.radius_m > 0)) r.fail("input.radius_m must be positive");
  Vector5 se = Vector5::Zero();
  for (int i = 0; i < 5; ++i) read_parameter(r, j["final"]["params"], i, d, se);
  // Covariance = diag(se) C diag(se) over the correlation's names; the rest uncorrelated.
  d.covariance = se.asDiagonal() * read_correlation(r, j["final"]) * se.asDiagonal();
  return d;
}

}  // namespace contensou::app
