#include "report.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <optional>

#include "gnuplot.hpp"

namespace contensou::app {
namespace {

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

}  // namespace

std::string format_loop(const ClosedLoopReport& loop) {
  std::string s = "\nclosed loop (score test, then LR at alpha / candidates, BIC and 5-fold CV):\n";
  s +=
      "step  effect              detail            LR p-value  threshold  BIC before -> after      "
      "error before -> after  verdict\n";
  int k = 0;
  for (const LoopStep& st : loop.steps) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "%-4d  %-18s  %-16s  %-10.2e  %-9.1e  %9.1f -> %-9.1f  %.4f -> %.4f  %s\n", ++k,
                  st.effect.c_str(), st.detail.c_str(), st.lr_p_value, st.threshold, st.bic_before,
                  st.bic_after, st.error_before, st.error_after,
                  st.removed    ? "removed (backward pass)"
                  : st.accepted ? "accepted"
                                : "rejected");
    s += line;
    if (st.accepted && !st.removed)
      for (const std::string& alt : st.ambiguous_with)
        s += "      ambiguous with " + alt + " (see its row; the lower BIC picks " + st.effect +
             ")\n";
  }
  s += "accepted effects:";
  std::vector<std::string> notes;
  for (const LoopStep& st : loop.steps)
    if (st.accepted && !st.removed) {
      s += " " + st.effect + (st.detail.empty() ? "" : " (" + st.detail + ")");
      if (!st.ambiguous_with.empty()) {
        s += " [or";
        for (std::size_t i = 0; i < st.ambiguous_with.size(); ++i)
          s += (i ? ", " : " ") + st.ambiguous_with[i];
        s += "]";
      }
      notes.insert(notes.end(), st.separation.begin(), st.separation.end());
    }
  if (loop.accepted_effects.empty()) s += " none";
  for (const std::string& n : notes) s += "\nAMBIGUOUS: " + n;
  s += "\nerror before " + fmt("%.4f", loop.base.error) + ", after " +
       fmt("%.4f", loop.final_fit.error) + "\n";
  if (loop.structure_remains)
    s += "STRUCTURE REMAINS: the final residual is still not white; the model lacks something the "
         "catalogue does not name.\n";
  return s;
}

namespace {

// The points with a positive sliding-spin ratio, in increasing psi.
std::vector<std::size_t> points_by_psi(const std::vector<double>& psi) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < psi.size(); ++i)
    if (std::isfinite(psi[i]) && psi[i] > 0.0) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return psi[a] < psi[b]; });
  return order;
}

// A cell of the pictures' CSV files: the value, or NaN where the channel was not measured.
std::string cell(std::optional<double> v) {
  return v ? fmt("%.10g", *v) : std::string("NaN");
}

const char* const kAxisLabel[kChannels] = {"Fx [N]", "Fy [N]", "Mz [N m]"};

}  // namespace

bool write_loop_plots(const std::string& dir, const MeasuredData& data,
                      const ClosedLoopReport& loop, double radius_m) {
  std::filesystem::create_directories(dir);
  const std::vector<double> psi = sliding_spin_ratio(data, radius_m);
  const std::vector<std::size_t> order = points_by_psi(psi);
  std::string gp =
      "set terminal pngcairo size 900,900 font ',10'\nset datafile separator ','\n"
      "set datafile columnheaders\nset datafile missing 'NaN'\n";
  int k = 0;
  for (const LoopStep& st : loop.steps) {
    const std::string csv = "loop_step_" + std::to_string(++k) + ".csv";
    std::string text = "psi";  // then the residual before and after the step, per channel
    for (int c = 0; c < kChannels; ++c)
      text += std::string(",before_") + kChannelColumns[c] + ",after_" + kChannelColumns[c];
    text += "\n";
    for (std::size_t i : order) {
      text += fmt("%.10g", psi[i]);
      for (int c = 0; c < kChannels; ++c) {
        const std::optional<double>& y = data.points[i].force[c];
        text += "," + cell(y ? std::optional(*y - st.fit_before.prediction[i].vector()(c)) : y) +
                "," + cell(y ? std::optional(*y - st.fit_after.prediction[i].vector()(c)) : y);
      }
      text += "\n";
    }
    write_file_atomically(dir + "/" + csv, text);
    gp += "set output 'loop_step_" + std::to_string(k) + ".png'\n";
    gp += "set multiplot layout 3,1 title 'step " + std::to_string(k) + ": " + st.effect +
          (st.detail.empty() ? "" : " (" + st.detail + ")") + ", " +
          (st.removed    ? "removed"
           : st.accepted ? "accepted"
                         : "rejected") +
          "'\n";
    gp += "set logscale x\nset format x '10^{%L}'\nset grid\nset key top right opaque box\n";
    gp += "set xlabel 'psi = v / (omega R) [-]'\n";
    for (int c = 0; c < kChannels; ++c) {
      if (data.count(c) == 0) continue;
      const std::string ch = kChannelColumns[c];
      gp += "set ylabel 'residual " + std::string(kAxisLabel[c]) + "'\n";
      gp +=
          "plot '" + csv + "' using \"psi\":\"before_" + ch +
          "\" with points pt 6 ps 0.7 lc rgb '#888888' title 'before', '' using \"psi\":\"after_" +
          ch + "\" with points pt 7 ps 0.6 lc rgb '#d62728' title 'after'\n";
    }
    gp += "unset multiplot\nunset xlabel\n";
  }
  if (k == 0) return true;
  return run_gnuplot(dir, "loop", gp);
}

std::string format_table(const RunInfo& info, const FitReport& fit) {
  std::string s;
  s += "data: " + info.file + ", " + std::to_string(info.points) + " points, " +
       std::to_string(info.values) + " measured values, R = " + fmt("%g", info.radius_m) + " m";
  if (info.normal_load_n) s += ", N = " + fmt("%g", *info.normal_load_n) + " N";
  if (!info.normal_load_source.empty()) s += " (" + info.normal_load_source + ")";
  for (const std::string& note : info.column_notes) s += "\ncolumn: " + note;
  if (!info.profile.empty()) {
    s += "\nprofile: " + info.profile;
    if (info.profile_rms_residual_pa)
      s += " (fit residual: rms " + fmt("%.4g", *info.profile_rms_residual_pa) + " Pa, max " +
           fmt("%.4g", *info.profile_max_residual_pa) + " Pa)";
  }
  s += "\n\nparameter   value          95 % interval                 unit\n";
  for (const ParameterEstimate& p : fit.parameters) {
    char line[160];
    std::string ci;
    if (p.derived)
      ci = "(from the profile)";
    else if (p.fixed)
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
  std::string csv = "psi,upsilon";  // then measured, fitted and residual, per channel
  for (int c = 0; c < kChannels; ++c)
    csv += std::string(",measured_") + kChannelColumns[c] + ",fit_" + kChannelColumns[c] +
           ",residual_" + kChannelColumns[c];
  csv += "\n";
  for (std::size_t i : points_by_psi(psi)) {
    csv += fmt("%.10g", psi[i]) + "," + fmt("%.10g", 1.0 / psi[i]);
    for (int c = 0; c < kChannels; ++c) {
      const std::optional<double>& y = data.points[i].force[c];
      const double m = model[i].vector()(c);
      csv += "," + cell(y) + "," + fmt("%.10g", m) + "," + cell(y ? std::optional(*y - m) : y);
    }
    csv += "\n";
  }
  write_file_atomically(dir + "/fit.csv", csv);
  std::string gp =
      "set terminal pngcairo size 900,720 font ',10'\nset datafile separator ','\n"
      "set datafile columnheaders\nset datafile missing 'NaN'\n";
  const char* title[3] = {"Fx: longitudinal force", "Fy: lateral force", "Mz: spin torque"};
  for (int c = 0; c < kChannels; ++c) {
    if (data.count(c) == 0) continue;
    const std::string ch = kChannelColumns[c], x = c == 0 ? "psi" : "upsilon";
    const std::string xlabel = c == 0 ? "psi = v / (omega R) [-]" : "upsilon = omega R / v [-]";
    gp += "set output 'fit_" + ch + ".png'\n";
    gp += "set multiplot layout 2,1 title '" + std::string(title[c]) + "'\n";
    gp += "set logscale x\nset format x '10^{%L}'\nset grid\nset key top right opaque box\n";
    gp += "set ylabel '" + std::string(kAxisLabel[c]) + "'\nset xlabel '" + xlabel + "'\n";
    gp += "plot 'fit.csv' using \"" + x + "\":\"measured_" + ch +
          "\" with points pt 7 ps 0.6 lc rgb '#1f77b4' title 'measured', '' using \"" + x +
          "\":\"fit_" + ch + "\" with lines lw 2 lc rgb '#d62728' title 'fitted law'\n";
    gp += "unset key\nset ylabel 'residual " + std::string(kAxisLabel[c]) + "'\n";
    gp += "plot 'fit.csv' using \"" + x + "\":\"residual_" + ch +
          "\" with impulses lc rgb '#555555' notitle, 0 with lines lc rgb 'black' notitle\n";
    gp += "unset multiplot\nunset logscale x\n";
  }
  return run_gnuplot(dir, "fit", gp);
}

}  // namespace contensou::app
