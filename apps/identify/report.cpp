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

bool write_loop_plots(const OutputDir& dir, const MeasuredData& data,
                      const ClosedLoopReport& loop) {
  const std::vector<double>& psi = loop.final_fit.psi;  // every fit of the loop has the same data
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
      for (int c = 0; c < kChannels; ++c)
        text += "," + cell(st.fit_before.residual[i][c]) + "," + cell(st.fit_after.residual[i][c]);
      text += "\n";
    }
    dir.write(csv, text);
    gp += "set output 'loop_step_" + std::to_string(k) + ".png'\n";
    gp += "set multiplot layout 3,1 title 'step " + std::to_string(k) + ": " + st.effect +
          (st.detail.empty() ? "" : " (" + st.detail + ")") + ", " +
          (st.removed    ? "removed"
           : st.accepted ? "accepted"
                         : "rejected") +
          "' noenhanced\n";  // effect names hold underscores, not subscripts
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

bool write_plots(const OutputDir& dir, const MeasuredData& data, const FitReport& fit) {
  const std::vector<double>& psi = fit.psi;
  const std::vector<Resultants<double>>& model = fit.prediction;
  std::string csv = "psi,upsilon";  // then measured, fitted and residual, per channel
  for (int c = 0; c < kChannels; ++c)
    csv += std::string(",measured_") + kChannelColumns[c] + ",fit_" + kChannelColumns[c] +
           ",residual_" + kChannelColumns[c];
  csv += "\n";
  for (std::size_t i : points_by_psi(psi)) {
    csv += fmt("%.10g", psi[i]) + "," + fmt("%.10g", 1.0 / psi[i]);
    for (int c = 0; c < kChannels; ++c)
      csv += "," + cell(data.points[i].force[c]) + "," + fmt("%.10g", model[i].vector()(c)) + "," +
             cell(fit.residual[i][c]);
    csv += "\n";
  }
  dir.write("fit.csv", csv);
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
