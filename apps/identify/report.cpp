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

bool write_loop_plots(const std::string& dir, const MeasuredData& data,
                      const ClosedLoopReport& loop, double radius_m) {
  std::filesystem::create_directories(dir);
  const std::vector<double> psi = sliding_spin_ratio(data, radius_m);
  std::vector<std::size_t> order(psi.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return psi[a] < psi[b]; });
  std::string gp = "set terminal pngcairo size 900,900 font ',10'\nset datafile missing 'NaN'\n";
  int k = 0;
  for (const LoopStep& st : loop.steps) {
    ++k;
    const std::string dat = "loop_step_" + std::to_string(k) + ".dat";
    std::string text = "# psi, then residual before and after for Fx, Fy, Mz\n";
    for (std::size_t i : order) {
      if (!std::isfinite(psi[i]) || psi[i] <= 0.0) continue;
      text += fmt("%.8g", psi[i]);
      for (int c = 0; c < kChannels; ++c) {
        const auto& y = data.points[i].force[c];
        text += y ? " " + fmt("%.8g", *y - st.fit_before.prediction[i].vector()(c)) + " " +
                        fmt("%.8g", *y - st.fit_after.prediction[i].vector()(c))
                  : std::string(" NaN NaN");
      }
      text += "\n";
    }
    write_file_atomically(dir + "/" + dat, text);
    gp += "set output 'loop_step_" + std::to_string(k) + ".png'\n";
    gp += "set multiplot layout 3,1 title 'step " + std::to_string(k) + ": " + st.effect +
          (st.detail.empty() ? "" : " (" + st.detail + ")") + ", " +
          (st.removed    ? "removed"
           : st.accepted ? "accepted"
                         : "rejected") +
          "'\n";
    gp += "set logscale x\nset format x '10^{%L}'\nset grid\nset key top right opaque box\n";
    const char* name[3] = {"Fx [N]", "Fy [N]", "Mz [N m]"};
    for (int c = 0; c < kChannels; ++c) {
      if (data.count(c) == 0) continue;
      gp += "set ylabel 'residual " + std::string(name[c]) + "'\n";
      if (c == 2) gp += "set xlabel 'psi = v / (omega R)'\n";
      gp += "plot '" + dat + "' using 1:" + std::to_string(2 + 2 * c) +
            " with points pt 6 ps 0.7 lc rgb '#888888' title 'before', '' using 1:" +
            std::to_string(3 + 2 * c) + " with points pt 7 ps 0.6 lc rgb '#d62728' title 'after'\n";
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
