#include "tire_report.hpp"

#include "config.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace contensou::app {

TireLawDistribution read_tire_report(const std::string& path) {
  const auto fail = [&](const std::string& what) {
    throw std::runtime_error("--tire " + path + ": " + what);
  };
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot open the report");
  std::stringstream buf;
  buf << in.rdbuf();
  nlohmann::json j;
  try {
    j = parse_json_without_duplicates(buf.str(), path);
  } catch (const nlohmann::json::exception& e) {
    fail(std::string("not a JSON report (") + e.what() + ")");
  }
  const auto number = [&](const nlohmann::json& node, const std::string& key) {
    if (!node.is_number() || !std::isfinite(node.get<double>()))
      fail(key + " must be a finite number, got " + node.dump());
    return node.get<double>();
  };
  if (!j.is_object() || !j.contains("final") || !j["final"].is_object() ||
      !j["final"].contains("params") || !j["final"]["params"].is_object())
    fail("no final.params (write it with contensou-identify --json)");
  const nlohmann::json& params = j["final"]["params"];
  TireLawDistribution d;
  if (!j.contains("input") || !j["input"].is_object() || !j["input"].contains("radius_m"))
    fail("no input.radius_m");
  d.radius_m = number(j["input"]["radius_m"], "input.radius_m");
  if (!(d.radius_m > 0)) fail("input.radius_m must be positive");
  Eigen::Matrix<double, 5, 1> se = Eigen::Matrix<double, 5, 1>::Zero();
  for (int i = 0; i < 5; ++i) {
    const std::string name = TireLawDistribution::kNames[static_cast<std::size_t>(i)];
    if (!params.contains(name) || !params[name].is_object() || !params[name].contains("value"))
      fail("final.params." + name + ".value missing");
    d.mean[i] = number(params[name]["value"], "final.params." + name + ".value");
    // A parameter the data could not determine has no distribution to draw from.
    const nlohmann::json& determined = params[name].value("determined", nlohmann::json(true));
    if (!determined.is_boolean() || !determined.get<bool>())
      fail("final.params." + name +
           " was not determined by the data (\"determined\": false): its value is arbitrary and "
           "it has no interval; identify the tire on data that determine it");
    const nlohmann::json& s = params[name].value("std_error", nlohmann::json());
    if (!s.is_null()) se[i] = number(s, "final.params." + name + ".std_error");
    if (se[i] < 0) fail("final.params." + name + ".std_error must be >= 0");
  }
  // Covariance = diag(se) C diag(se) over the correlation's names; the rest uncorrelated.
  Eigen::Matrix<double, 5, 5> corr = Eigen::Matrix<double, 5, 5>::Identity();
  const nlohmann::json& c = j["final"].value("correlation", nlohmann::json());
  if (c.is_object() && c.contains("names") && c.contains("matrix")) {
    const nlohmann::json &names = c["names"], &matrix = c["matrix"];
    if (!names.is_array() || !matrix.is_array() || matrix.size() != names.size())
      fail("final.correlation: names and matrix differ in size");
    const auto index = [&](const nlohmann::json& n) {
      for (int i = 0; i < 5; ++i)
        if (n.is_string() &&
            n.get<std::string>() == TireLawDistribution::kNames[static_cast<std::size_t>(i)])
          return i;
      return -1;
    };
    for (std::size_t r = 0; r < names.size(); ++r) {
      if (!matrix[r].is_array() || matrix[r].size() != names.size())
        fail("final.correlation.matrix row " + std::to_string(r + 1) + " has the wrong length");
      const int i = index(names[r]);
      for (std::size_t q = 0; q < names.size(); ++q) {
        const int k = index(names[q]);
        const double v = number(matrix[r][q], "final.correlation.matrix");
        if (i >= 0 && k >= 0) corr(i, k) = v;
      }
    }
  }
  d.covariance = se.asDiagonal() * corr * se.asDiagonal();
  return d;
}

}  // namespace contensou::app
