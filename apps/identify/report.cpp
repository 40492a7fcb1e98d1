#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>

#include "gnuplot.hpp"

namespace contensou::app {
namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

nlohmann::json model_json(const std::string& name, const std::vector<std::string>& effects,
                          const FitReport& fit) {
  nlohmann::json m;
  m["name"] = name;
  m["effects"] = effects;
  nlohmann::json params = nlohmann::json::object();
  for (const ParameterEstimate& p : fit.parameters) {
    nlohmann::json e;
    e["value"] = p.value;
    e["ci95"] = p.ci95 ? nlohmann::json::array({(*p.ci95)[0], (*p.ci95)[1]}) : nlohmann::json();
    e["unit"] = p.unit;
    e["fixed"] = p.fixed;
    e["determined"] = p.determined || p.fixed;
    e["std_error"] = std::isfinite(p.std_error) ? nlohmann::json(p.std_error) : nlohmann::json();
    params[p.name] = e;
  }
  m["params"] = params;
  nlohmann::json rms = nlohmann::json::object(), noise = nlohmann::json::object();
  nlohmann::json diag = nlohmann::json::array();
  for (const ChannelDiagnostics& c : fit.channels) {
    rms[c.channel] = c.rms;
    noise[c.channel] = c.noise_scale;
    diag.push_back({{"channel", c.channel},
                    {"points", c.points},
                    {"runs_p_value", c.runs_p_value},
                    {"lag1_autocorrelation", c.lag1},
                    {"durbin_watson", c.durbin_watson},
                    {"white", c.white}});
  }
  m["rms"] = rms;
  m["noise_scale"] = noise;
  m["diagnostics"] = diag;
  m["residual_white"] = fit.residual_white;
  m["aic"] = fit.aic;
  m["bic"] = fit.bic;
  m["chi2"] = fit.chi2;
  m["degrees_of_freedom"] = fit.degrees_of_freedom;
  m["error"] = fit.error;
  m["converged"] = fit.converged;
  nlohmann::json corr = nlohmann::json::object();
  corr["names"] = fit.correlation_names;
  nlohmann::json rows = nlohmann::json::array();
  for (Eigen::Index i = 0; i < fit.correlation.rows(); ++i) {
    nlohmann::json row = nlohmann::json::array();
    for (Eigen::Index j = 0; j < fit.correlation.cols(); ++j) row.push_back(fit.correlation(i, j));
    rows.push_back(row);
  }
  corr["matrix"] = rows;
  m["correlation"] = corr;
  return m;
}

nlohmann::json report_json(const RunInfo& info, const FitReport& base) {
  nlohmann::json r;
  r["input"] = {{"file", info.file},
                {"points", info.points},
                {"values", info.values},
                {"radius_m", info.radius_m},
                {"normal_load_N",
                 info.normal_load_n ? nlohmann::json(*info.normal_load_n) : nlohmann::json()}};
  r["base"] = model_json("fractional", {}, base);
  r["steps"] = nlohmann::json::array();
  r["accepted_effects"] = nlohmann::json::array();
  r["final"] = r["base"];
  r["error_before"] = base.error;
  r["error_after"] = base.error;
  r["error_definition"] =
      "root mean square over measured channels of (channel rms / channel's largest |value|)";
  return r;
}

std::string format_table(const RunInfo& info, const FitReport& fit) {
  std::string s;
  s += "data: " + info.file + ", " + std::to_string(info.points) + " points, " +
       std::to_string(info.values) + " measured values, R = " + fmt("%g", info.radius_m) + " m";
  if (info.normal_load_n) s += ", N = " + fmt("%g", *info.normal_load_n) + " N";
  s += "\n\nparameter   value          95 % interval                 unit\n";
  for (const ParameterEstimate& p : fit.parameters) {
    char line[160];
    std::string ci;
    if (p.fixed)
      ci = "(fixed)";
    else if (!p.determined)
      ci = "not determined by the data";
    else if (p.ci95)
      ci = "[" + fmt("%.6g", (*p.ci95)[0]) + ", " + fmt("%.6g", (*p.ci95)[1]) + "]";
    std::snprintf(line, sizeof line, "%-10s  %-13.6g  %-28s  %s\n", p.name.c_str(), p.value,
                  ci.c_str(), p.unit.c_str());
    s += line;
  }
  s += "\nchannel  points  rms          noise scale  runs p   lag-1   white\n";
  for (const ChannelDiagnostics& c : fit.channels) {
    char line[160];
    std::snprintf(line, sizeof line, "%-7s  %6d  %-11.4g  %-11.4g  %-7.3f  %+6.3f  %s\n",
                  c.channel.c_str(), c.points, c.rms, c.noise_scale, c.runs_p_value, c.lag1,
                  c.white ? "yes" : "no");
    s += line;
  }
  s += "\nfit: chi2 = " + fmt("%.4g", fit.chi2) + " on " + std::to_string(fit.degrees_of_freedom) +
       " degrees of freedom, AIC = " + fmt("%.2f", fit.aic) + ", BIC = " + fmt("%.2f", fit.bic) +
       ", error = " + fmt("%.4f", fit.error) + (fit.converged ? "" : "  (solver NOT converged)") +
       "\n";
  s += fit.residual_white
           ? "residuals: white (no structure found by the runs and lag-1 tests)\n"
           : "residuals: NOT white: the model misses something the data show (see the pictures)\n";
  return s;
}

bool write_plots(const std::string& dir, const MeasuredData& data, const FitReport& fit,
                 double radius_m) {
  std::filesystem::create_directories(dir);
  const std::vector<double> psi = sliding_spin_ratio(data, radius_m);
  const std::vector<Resultants<double>>& model = fit.prediction;
  std::vector<std::size_t> order(psi.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return psi[a] < psi[b]; });
  std::string dat =
      "# psi upsilon Fx_meas Fx_fit Fy_meas Fy_fit Mz_meas Mz_fit (NaN = not measured)\n";
  for (std::size_t i : order) {
    if (!std::isfinite(psi[i]) || psi[i] <= 0.0) continue;
    dat += fmt("%.8g", psi[i]) + " " + fmt("%.8g", 1.0 / psi[i]);
    for (int c = 0; c < kChannels; ++c) {
      const auto& y = data.points[i].force[c];
      dat += " " + (y ? fmt("%.8g", *y) : std::string("NaN")) + " " +
             fmt("%.8g", model[i].vector()(c));
    }
    dat += "\n";
  }
  write_file_atomically(dir + "/fit.dat", dat);
  std::string gp = "set terminal pngcairo size 900,720 font ',10'\nset datafile missing 'NaN'\n";
  const char* title[3] = {"Fx: longitudinal force", "Fy: lateral force", "Mz: spin torque"};
  const char* unit[3] = {"N", "N", "N m"};
  const char* label[3] = {"Fx", "Fy", "Mz"};
  const char* axis[3] = {"psi = v / (omega R)", "upsilon = omega R / v", "upsilon = omega R / v"};
  for (int c = 0; c < kChannels; ++c) {
    if (data.count(c) == 0) continue;
    const int x = c == 0 ? 1 : 2, ym = 3 + 2 * c, yf = 4 + 2 * c;
    gp += "set output 'fit_" + std::string(kChannelColumns[c]) + ".png'\n";
    gp += "set multiplot layout 2,1 title '" + std::string(title[c]) + "'\n";
    gp += "set logscale x\nset format x '10^{%L}'\nset grid\nset key top right opaque box\n";
    gp += "set ylabel '" + std::string(label[c]) + " [" + unit[c] + "]'\nunset xlabel\n";
    gp += "plot 'fit.dat' using " + std::to_string(x) + ":" + std::to_string(ym) +
          " with points pt 7 ps 0.6 lc rgb '#1f77b4' title 'measured', '' using " +
          std::to_string(x) + ":" + std::to_string(yf) +
          " with lines lw 2 lc rgb '#d62728' title 'fitted law'\n";
    gp += "unset key\nset xlabel '" + std::string(axis[c]) + "'\nset ylabel 'residual [" + unit[c] +
          "]'\n";
    gp += "plot 'fit.dat' using " + std::to_string(x) + ":($" + std::to_string(ym) + "-$" +
          std::to_string(yf) +
          ") with impulses lc rgb '#555555' notitle, 0 with lines lc rgb "
          "'black' notitle\n";
    gp += "unset multiplot\nunset logscale x\n";
  }
  return run_gnuplot(dir, "fit", gp);
}

}  // namespace contensou::app
