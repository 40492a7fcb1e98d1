#include "contensou/friction/model_error.hpp"

#include <cmath>
#include <cstdio>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"

namespace contensou {

ModelErrorReport model_error_report(const ContactPatch& patch, double psi_min, double psi_max,
                                    int points) {
  require_positive("psi_min", psi_min);
  if (!(psi_max > psi_min))
    throw InvalidArgument("psi_max", format_value(psi_max), "must exceed psi_min");
  if (points < 2) throw InvalidArgument("points", std::to_string(points), "need at least 2");
  ModelErrorReport report;
  report.psi_min = psi_min;
  report.psi_max = psi_max;
  report.points = points;
  const ExactModel<double> model = make_exact_model(patch);
  const double R = patch.radius_m, u = 1.0;  // u = omega R [m/s]
  std::vector<double> psi(points);
  std::vector<Resultants<double>> exact(points);
  for (int i = 0; i < points; ++i) {
    psi[i] = psi_min * std::pow(psi_max / psi_min, static_cast<double>(i) / (points - 1));
    exact[i] =
        exact_resultants(model, Kinematics<double>{psi[i] * u, 0.0, u / R}, {1e-10}).resultants;
  }
  const bool lateral = patch.profile.kx != 0.0;
  for (int which = 0; which < 2; ++which) {
    LawError le;
    le.name = which == 0 ? "asymptote-matched" : "least-squares";
    le.law = which == 0 ? fractional_law_from_patch(patch) : fractional_law_fitted(patch);
    const double F0 = le.law.F0, M0 = le.law.M0;
    ChannelError fpar{"F_par"}, flat{"F_lat"}, mz{"Mz"};
    for (int i = 0; i < points; ++i) {
      const Resultants<double> r =
          fractional_resultants(le.law, Kinematics<double>{psi[i] * u, 0.0, u / R});
      const double e[3] = {std::abs(r.Fx - exact[i].Fx) / F0, std::abs(r.Fy - exact[i].Fy) / F0,
                           std::abs(r.Mz - exact[i].Mz) / M0};
      ChannelError* ch[3] = {&fpar, &flat, &mz};
      for (int c = 0; c < 3; ++c) {
        ch[c]->rms_error += e[c] * e[c];
        if (e[c] > ch[c]->max_error) {
          ch[c]->max_error = e[c];
          ch[c]->worst_psi = psi[i];
        }
      }
    }
    for (ChannelError* c : {&fpar, &flat, &mz}) c->rms_error = std::sqrt(c->rms_error / points);
    le.channels.push_back(fpar);
    if (lateral) le.channels.push_back(flat);
    le.channels.push_back(mz);
    report.laws.push_back(le);
  }
  return report;
}

std::string format_report(const ModelErrorReport& report) {
  std::string out;
  char line[256];
  std::snprintf(line, sizeof line,
                "Fractional law vs exact integrals, psi = v/(omega R) in [%g, %g], %d points\n"
                "(errors relative to F0 for forces, M0 for the torque)\n",
                report.psi_min, report.psi_max, report.points);
  out += line;
  out += "coefficients        a        m        channel  max error  at psi    rms error\n";
  for (const LawError& le : report.laws) {
    for (const ChannelError& c : le.channels) {
      std::snprintf(line, sizeof line, "%-18s  %-7.4f  %-7.4f  %-7s  %7.2f %%  %-8.3g %7.2f %%\n",
                    le.name.c_str(), le.law.a, le.law.m, c.channel.c_str(), 100.0 * c.max_error,
                    c.worst_psi, 100.0 * c.rms_error);
      out += line;
    }
  }
  return out;
}

}  // namespace contensou
