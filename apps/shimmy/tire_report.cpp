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

// <model>.params.<name>: the value into d.mean[i], the standard error (0 for a fixed parameter)
// into se[i]; a parameter the data could not determine has no distribution to draw from.
void read_parameter(const ReportSource& r, const nlohmann::json& params, const std::string& model,
                    int i, TireLawDistribution& d, Vector5& se) {
  const std::string name = TireLawDistribution::kNames[static_cast<std::size_t>(i)];
  const std::string key = model + ".params." + name;
  if (!params.contains(name) || !params[name].is_object() || !params[name].contains("value"))
    r.fail(key + ".value missing");
  d.mean[i] = r.number(params[name]["value"], key + ".value");
  // Computed from the pressure profile (the exact law's a, M0, m): known, without a variance.
  const nlohmann::json& derived = params[name].value("derived_from_profile", nlohmann::json(false));
  if (derived.is_boolean() && derived.get<bool>()) return;
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

// <model>.correlation over its names (the identity where it is missing); other names are skipped.
Matrix5 read_correlation(const ReportSource& r, const nlohmann::json& model_node,
                         const std::string& model) {
  Matrix5 corr = Matrix5::Identity();
  const nlohmann::json& c = model_node.value("correlation", nlohmann::json());
  if (!c.is_object() || !c.contains("names") || !c.contains("matrix")) return corr;
  const nlohmann::json &names = c["names"], &matrix = c["matrix"];
  if (!names.is_array() || !matrix.is_array() || matrix.size() != names.size())
    r.fail(model + ".correlation: names and matrix differ in size");
  for (std::size_t row = 0; row < names.size(); ++row) {
    if (!matrix[row].is_array() || matrix[row].size() != names.size())
      r.fail(model + ".correlation.matrix row " + std::to_string(row + 1) +
             " has the wrong length");
    const int i = law_index(names[row]);
    for (std::size_t q = 0; q < names.size(); ++q) {
      const int k = law_index(names[q]);
      const double v = r.number(matrix[row][q], model + ".correlation.matrix");
      if (i >= 0 && k >= 0) corr(i, k) = v;
    }
  }
  return corr;
}

}  // namespace

namespace {

// The report's model `key` ("final" or "base") has every parameter of the fractional law.
bool has_law(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_object() || !j[key].contains("params") ||
      !j[key]["params"].is_object())
    return false;
  for (const char* name : TireLawDistribution::kNames)
    if (!j[key]["params"].contains(name)) return false;
  return true;
}

// The model's name and its effects, as the report writes them ("fractional + b1_b2").
std::string model_words(const nlohmann::json& m) {
  std::string out = m.value("name", std::string("model"));
  const nlohmann::json effects = m.value("effects", nlohmann::json::array());
  if (effects.is_array())
    for (const nlohmann::json& e : effects)
      if (e.is_string()) out += " + " + e.get<std::string>();
  return out;
}

// The final model's parameters beyond the fractional law's five, comma-separated.
std::string extra_parameters(const nlohmann::json& final_node) {
  std::string out;
  for (auto it = final_node["params"].begin(); it != final_node["params"].end(); ++it) {
    bool law = it.key() == "f";  // the friction coefficient F0 / N: F0 restated
    for (const char* name : TireLawDistribution::kNames) law = law || it.key() == name;
    if (!law) out += (out.empty() ? "" : ", ") + it.key();
  }
  return out;
}

// Which model of the report the gear takes, and what it leaves out, in words. The gear's tire
// is the fractional law: a final fractional model is taken (its further effects named); a final
// exact model (the exact integrals over a given or identified pressure profile, whose a, m, M0
// are the profile's asymptotic values or absent) is not that law, and the report's base fit,
// the fractional law fitted to the same data, is taken instead.
void choose_model(const ReportSource& r, const nlohmann::json& j, TireReport& out) {
  if (!j.is_object() || !j.contains("final") || !j["final"].is_object() ||
      !j["final"].contains("params") || !j["final"]["params"].is_object())
    r.fail("no final.params (write it with contensou-identify --json)");
  const nlohmann::json& fin = j["final"];
  const bool exact = fin.value("name", std::string()) == "exact";
  if (!exact && has_law(j, "final")) {
    const std::string extra = extra_parameters(fin);
    if (!extra.empty())
      out.note = "the final model (" + model_words(fin) + ") also has " + extra +
                 ", which the gear's tire does not carry: only F0, a, M0, m, kx are taken";
    return;
  }
  if (!has_law(j, "base"))
    r.fail(
        "final.params.a.value missing, and no base fit to fall back on (write the report "
        "with contensou-identify --json)");
  out.model = "base";
  const std::string extra = extra_parameters(fin);
  out.note =
      "the final model (" + model_words(fin) + (extra.empty() ? "" : ": " + extra) + ") " +
      (exact ? std::string("is the exact law over a pressure profile") +
                   (has_law(j, "final") ? " (its a, M0, m the profile's asymptotic values)" : "") +
                   ", "
             : std::string()) +
      "not the fractional law the gear's tire is; the report's base fit, the fractional "
      "law fitted to the same data, is the tire instead (the final model's effects are "
      "not carried)";
}

}  // namespace

TireReport read_tire_report(const std::string& path) {
  const ReportSource r{path};
  const nlohmann::json j = r.load();
  TireReport out;
  choose_model(r, j, out);
  TireLawDistribution& d = out.distribution;
  if (!j.contains("input") || !j["input"].is_object() || !j["input"].contains("radius_m"))
    r.fail("no input.radius_m");
  d.radius_m = r.number(j["input"]["radius_m"], "input.radius_m");
  if (!(d.radius_m > 0)) r.fail("input.radius_m must be positive");
  const nlohmann::json& model = j[out.model];
  Vector5 se = Vector5::Zero();
  for (int i = 0; i < 5; ++i) read_parameter(r, model["params"], out.model, i, d, se);
  // Covariance = diag(se) C diag(se) over the correlation's names; the rest uncorrelated.
  d.covariance = se.asDiagonal() * read_correlation(r, model, out.model) * se.asDiagonal();
  return out;
}

}  // namespace contensou::app
