// contensou-shimmy: a one-wheel main landing gear through touchdown, sliding and spin-up, with
// three contact models (docs/shimmy.md).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "axis_label.hpp"
#include "boundary_overlay.hpp"
#include "cli.hpp"
#include "config.hpp"
#include "config_keys.hpp"
#include "contensou/friction/error.hpp"
#include "gnuplot.hpp"
#include "history_plots.hpp"
#include "limit_cycle.hpp"
#include "overrides.hpp"
#include "run_guard.hpp"
#include "scenarios.hpp"
#include "tire_report.hpp"

using namespace contensou;
using namespace contensou::app;

namespace {

constexpr const char* kName = "contensou-shimmy";

std::string csv_history(const LandingRun& run) {
  std::ostringstream o;
  o.precision(9);
  const std::vector<std::string>& columns = history_columns();
  for (std::size_t i = 0; i < columns.size(); ++i) o << (i ? "," : "") << columns[i];
  o << '\n';
  for (const LandingSample& s : run.samples) {
    const std::vector<double> row = history_row(s);
    for (std::size_t i = 0; i < row.size(); ++i) o << (i ? "," : "") << row[i];
    o << '\n';
  }
  return o.str();
}

nlohmann::json run_json(const LandingRun& r) {
  const OscillationEstimate& o = r.metrics.torsion;
  nlohmann::json j{{"shimmy", r.metrics.shimmy},
                   {"frequency_Hz", o.valid() ? nlohmann::json(o.frequency_hz) : nullptr},
                   {"growth_rate_per_s", o.valid() ? nlohmann::json(o.growth_rate_per_s) : nullptr},
                   {"peak_torsion_rad", r.metrics.peak_torsion_rad},
                   {"peak_lateral_m", r.metrics.peak_lateral_m},
                   {"spin_up_s", r.spin_up_s ? nlohmann::json(*r.spin_up_s) : nullptr},
                   {"steps", r.steps},
                   {"wall_s", r.wall_s},
                   {"final_torsion_amplitude_rad", o.last_amplitude},
                   {"half_cycles", o.half_cycles},
                   {"window_s", {r.window_start_s, r.window_end_s}}};
  for (const LandingEvent& e : r.events) j["events"].push_back({{"t_s", e.t}, {"event", e.what}});
  return j;
}

nlohmann::json report_json(const StabilityReport& r) {
  nlohmann::json eig = nlohmann::json::array();
  for (const auto& e : r.eigenvalues) eig.push_back({e.real(), e.imag()});
  const auto finite_or_null = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  return {{"stable", r.stable()},
          {"quasi_steady_state_converged", r.state.converged},
          {"growth_rate_per_s", r.growth_rate_per_s},
          {"frequency_Hz", r.frequency_hz},
          {"max_real_part_per_s", r.max_real_part},
          {"eigenvalues_per_s", eig},
          {"perturbation_growth_rate_per_s", finite_or_null(r.perturbation_growth_rate_per_s)},
          {"perturbation_frequency_Hz", finite_or_null(r.perturbation_frequency_hz)},
          {"torsion_share", r.torsion_share},
          {"mode", r.mode_kind},
          {"torsion_growth_rate_per_s", r.torsion_growth_rate_per_s},
          {"torsion_frequency_Hz", r.torsion_frequency_hz},
          {"spin_torque_damping_nms_per_rad", r.spin_torque_damping_nms_per_rad},
          {"drag_slope_ns_per_m", r.drag_slope_ns_per_m},
          {"friction", r.friction},
          {"frozen_slip_ratio",
           r.state.frozen_spin ? nlohmann::json(r.state.touchdown_slip) : nlohmann::json(nullptr)},
          {"energy_per_cycle_J",
           {{"spin_torque", r.energy.spin_torque},
            {"trail_lateral_force", r.energy.trail_lateral_force},
            {"offset_drag", r.energy.offset_drag},
            {"torsional_damping", r.energy.torsional_damping},
            {"lateral_friction", r.energy.lateral_friction},
            {"lateral_damping", r.energy.lateral_damping},
            {"carcass_lever", r.energy.carcass_lever},
            {"of_which_fall_of_friction", r.energy.fall_of_friction},
            {"total", r.energy.total()}}}};
}

// The tire from a contensou-identify report (--tire), if any: its mean law and the draws.
struct TireInput {
  std::string path;
  TireLawDistribution distribution;
  TireLawCoefficients mean;
  TireLawDraws draws;
};

// The gear model of a contact model, with the report's mean tire law when given.
GearModel gear_model(const ShimmyConfig& config, ContactModel cm, const TireInput* tire) {
  const GearModel m = make_gear_model(config.gear, cm);
  return tire ? with_tire_law(m, tire->mean) : m;
}

// The stability verdicts of both phases (docs/shimmy.md, "Stability criterion"), by the
// eigenvalues of the linearisation and the growth after the standard perturbation.
void print_stability(const ShimmyConfig& config, const std::vector<LandingRun>& runs,
                     const TireInput* tire, nlohmann::json& summary) {
  std::printf(
      "\nstability: eigenvalues of the linearisation about the quasi-steady state, and the growth "
      "after psi' += 0.1 rad/s\n(growth: all modes; torsion: the torsional mode; pert.: growth "
      "fitted after the kick; spin damp. -dMz/dpsi' [N m s/rad])\n"
      "%-13s %-13s %11s %8s %12s %11s %11s %6s  %s\n",
      "model", "phase", "growth[1/s]", "freq[Hz]", "torsion[1/s]", "pert.[1/s]", "spin damp.", "f",
      "verdict");
  for (const LandingRun& run : runs) {
    const GearModel model = gear_model(config, run.contact, tire);
    const StabilityReport td = assess_touchdown(model);
    const StabilityReport br = assess_stability(model, StabilityPhase::braked_slide);
    for (const StabilityReport* r : {&td, &br}) {
      std::string verdict;
      char buf[200];
      if (!r->state.converged) {
        verdict = "no quasi-steady state found";
      } else if (r == &td && run.contact == ContactModel::von_schlippe) {
        const double crit = classical_critical_damping(model);
        const double c = config.gear.structure.torsional_damping_nms_per_rad;
        if (crit > 0)
          std::snprintf(buf, sizeof buf,
                        "%s; classical critical damping %.1f N m s/rad, margin %.2f",
                        r->stable() ? "stable" : "SHIMMY", crit, c / crit);
        else
          std::snprintf(buf, sizeof buf, "%s; stable without torsional damping",
                        r->stable() ? "stable" : "SHIMMY");
        verdict = buf;
      } else if (r == &td) {
        const double T = run.spin_up_s.value_or(0.0);
        const double growth = std::exp(r->growth_rate_per_s * T);
        std::snprintf(buf, sizeof buf,
                      "%s: x%.3g over the %.3f s spin-up (%.1f cycles), worst at slip %.1f",
                      r->growth_rate_per_s <= 0       ? "stable"
                      : r->growth_rate_per_s * T >= 1 ? "GROWS within spin-up"
                                                      : "grows, too slowly to matter",
                      growth, T, r->frequency_hz * T, r->state.touchdown_slip);
        verdict = buf;
        if (r->growth_rate_per_s > 0) verdict += " (" + r->mode_kind + " mode)";
      } else if (r->stable()) {
        verdict = "stable";
      } else if (r->mode_kind == "fore-aft") {
        verdict = "UNSTABLE while braking: fore-aft mode (gear walk), not shimmy";
      } else {
        verdict = "SHIMMY while braking (" + r->mode_kind + " mode)";
      }
      std::printf("%-13s %-13s %11.3f %8.2f %12.3f %11.3f %11.4g %6.3f  %s\n",
                  to_string(run.contact), to_string(r->state.phase), r->growth_rate_per_s,
                  r->frequency_hz, r->torsion_growth_rate_per_s, r->perturbation_growth_rate_per_s,
                  r->spin_torque_damping_nms_per_rad, r->friction, verdict.c_str());
      nlohmann::json j = report_json(*r);
      j["verdict"] = verdict;
      summary["models"][to_string(run.contact)]["stability"][to_string(r->state.phase)] = j;
    }
    if (run.contact == ContactModel::decoupled && config.gear.structure.carcass_compliance())
      std::printf(
          "  note: the decoupled model's regularised Coulomb spin torque (M0 R / eps) acts in "
          "series with the carcass's torsional spring: %.3g N m s/rad of damping at the rim "
          "while braking; shown for reference only\n",
          br.spin_torque_damping_nms_per_rad);
    else if (run.contact == ContactModel::decoupled)
      std::printf(
          "  note: the decoupled model's regularised Coulomb spin torque acts on the torsion as a "
          "damper of %.3g N m s/rad (M0 R / eps) while braking: an artefact of the regularisation, "
          "not a physical damper; shown for reference only\n",
          br.spin_torque_damping_nms_per_rad);
  }
}

void progress_bar(const std::string& label, int done, int total) {
  if (!isatty(STDERR_FILENO)) return;
  const int width = 40, filled = total > 0 ? width * done / total : width;
  std::fprintf(stderr, "\r%-36s [%s%s] %d/%d", label.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, '.').c_str(), done, total);
  if (done == total) std::fputc('\n', stderr);
  std::fflush(stderr);
}

// The map's axes and ranges, its coloured column where the cell is valid, and the cells it could
// not compute as black crosses counted in the key (gnuplot, columns by their CSV names).
std::string map_plot_body(const StabilityMap& m, const std::string& base,
                          const std::string& value) {
  const long invalid =
      std::count_if(m.cells.begin(), m.cells.end(), [](const MapCell& c) { return !c.valid; });
  const std::string xy = "\"" + m.x.parameter + "\":\"" + m.y.parameter + "\"";
  std::ostringstream gp;
  gp << "set datafile separator ','\nset datafile columnheaders\n"
     << "set xlabel '" << parameter_axis_label(m.x.parameter) << "'\nset ylabel '"
     << parameter_axis_label(m.y.parameter) << "'\nset xrange [" << m.x.from << ":" << m.x.to
     << "]\nset yrange [" << m.y.from << ":" << m.y.to << "]\nset key outside below\n"
     << "plot '" << base << ".csv' using " << xy << ":(column(\"valid\") > 0 ? column(\"" << value
     << "\") : NaN) with image notitle";
  if (invalid > 0)
    gp << ", '' using \"" << m.x.parameter << "\":(column(\"valid\") > 0 ? NaN : column(\""
       << m.y.parameter << "\")) with points pt 2 ps 0.8 lc rgb 'black' title '" << invalid
       << " of " << m.cells.size()
       << " cells not computed (brake short of its target slip or solve failed: CSV column "
          "error)'";
  return gp.str();
}

// Writes the map's CSV and PNG; returns its summary.
nlohmann::json write_map(const std::string& dir, const StabilityMap& m) {
  const std::string base = "map_" + short_name(m.x.parameter) + "_" + short_name(m.y.parameter) +
                           "_" + (m.linear ? to_string(m.phase) : "simulated") + "_" +
                           to_string(m.contact);
  std::ostringstream csv, boundary;
  csv.precision(9);
  csv << m.x.parameter << ',' << m.y.parameter
      << ",growth_rate_per_s,frequency_Hz,final_amplitude_rad,shimmy,valid,error\n";
  double g_max = 1e-3;
  int shimmy_cells = 0, failed = 0, invalid = 0;
  for (int j = 0; j < m.y.points; ++j) {
    for (int i = 0; i < m.x.points; ++i) {
      const MapCell& c = m.cells[static_cast<std::size_t>(j * m.x.points + i)];
      invalid += !c.valid;
      csv << c.x << ',' << c.y << ',' << c.growth_rate_per_s << ',' << c.frequency_hz << ','
          << c.last_amplitude_rad << ',' << c.shimmy << ',' << c.valid << ",\"" << c.error
          << "\"\n";
      if (c.valid) g_max = std::max(g_max, std::abs(c.growth_rate_per_s));
      shimmy_cells += c.shimmy;
      failed += !c.error.empty();
      // Shimmy boundary: midpoints between computed neighbours that disagree.
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        if (i + di >= m.x.points || j + dj >= m.y.points) continue;
        const MapCell& d = m.cells[static_cast<std::size_t>((j + dj) * m.x.points + i + di)];
        if (c.valid && d.valid && d.shimmy != c.shimmy)
          boundary << 0.5 * (c.x + d.x) << ',' << 0.5 * (c.y + d.y) << '\n';
      }
    }
    csv << '\n';  // gnuplot reads blank-line-separated rows as a grid
  }
  write_file_atomically(dir + "/" + base + ".csv", csv.str());
  write_file_atomically(dir + "/" + base + "_boundary.csv",
                        m.x.parameter + ',' + m.y.parameter + '\n' + boundary.str() + "\n");
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 760,620 font ',10'\nset output '" << base
     << ".png'\nset title '" << to_string(m.contact) << ", "
     << (m.linear ? std::string(to_string(m.phase)) + ": largest oscillatory eigenvalue real part"
                  : std::string("simulated landing: torsional growth rate"))
     << " [1/s]; black: stability boundary'\n"
     << "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n"
     << "set cbrange [" << -g_max << ":" << g_max << "]\nset cblabel 'growth rate [1/s]'\n"
     << map_plot_body(m, base, "growth_rate_per_s") << ", '" << base << "_boundary.csv' using \""
     << m.x.parameter << "\":\"" << m.y.parameter
     << "\" with points pt 7 ps 0.5 lc rgb 'black' title 'stability boundary'\n";
  run_gnuplot(dir, base, gp.str());
  return {{"x", m.x.parameter},
          {"y", m.y.parameter},
          {"method", m.linear ? "eigenvalues" : "simulation"},
          {"phase", m.linear ? nlohmann::json(to_string(m.phase)) : nlohmann::json(nullptr)},
          {"points", {m.x.points, m.y.points}},
          {"shimmy_cells", shimmy_cells},
          {"failed_cells", failed},
          {"not_computed_cells", invalid},
          {"csv", base + ".csv"},
          {"png", base + ".png"}};
}

// Writes a probability map's CSV and PNG (colour: the probability of shimmy over the draws).
nlohmann::json write_probability_map(const std::string& dir, const StabilityMap& m) {
  const std::string base = "prob_" + short_name(m.x.parameter) + "_" + short_name(m.y.parameter) +
                           "_" + to_string(m.phase) + "_" + to_string(m.contact);
  std::ostringstream csv;
  csv.precision(9);
  csv << m.x.parameter << ',' << m.y.parameter
      << ",shimmy_probability,median_growth_rate_per_s,valid,error\n";
  for (int j = 0; j < m.y.points; ++j) {
    for (int i = 0; i < m.x.points; ++i) {
      const MapCell& c = m.cells[static_cast<std::size_t>(j * m.x.points + i)];
      csv << c.x << ',' << c.y << ',' << c.shimmy_probability << ',' << c.growth_rate_per_s << ','
          << c.valid << ",\"" << c.error << "\"\n";
    }
    csv << '\n';
  }
  write_file_atomically(dir + "/" + base + ".csv", csv.str());
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 760,620 font ',10'\nset output '" << base
     << ".png'\nset title '" << to_string(m.contact) << ", " << to_string(m.phase)
     << ": probability of shimmy over the tire report draws'\n"
     << "set palette defined (0 '#f7f7f7', 0.5 '#f4a582', 1 '#b2182b')\nset cbrange [0:1]\n"
     << "set cblabel 'probability of shimmy'\n"
     << map_plot_body(m, base, "shimmy_probability") << "\n";
  run_gnuplot(dir, base, gp.str());
  return {{"x", m.x.parameter},          {"y", m.y.parameter},
          {"phase", to_string(m.phase)}, {"model", to_string(m.contact)},
          {"csv", base + ".csv"},        {"png", base + ".png"}};
}

// The Monte Carlo over the report's covariance: growth band and P(shimmy) of both phases for
// the coupled model at the configuration.
void print_tire_uncertainty(const ShimmyConfig& config, const TireInput& tire, unsigned threads,
                            nlohmann::json& summary) {
  const auto sd = [&](auto get) {
    double m = 0, q = 0;
    for (const TireLawCoefficients& d : tire.draws.draws) m += get(d);
    m /= static_cast<double>(tire.draws.draws.size());
    for (const TireLawCoefficients& d : tire.draws.draws) q += (get(d) - m) * (get(d) - m);
    return std::sqrt(q /
                     static_cast<double>(std::max<std::size_t>(tire.draws.draws.size() - 1, 1)));
  };
  const TireLawCoefficients& t = tire.mean;
  std::printf(
      "\ntire law from %s: a = %.4g +- %.2g, m = %.4g +- %.2g, kx = %.4g +- %.2g, M0/(F0 R) = "
      "%.4g +- %.2g (%zu draws, %d redrawn)\n",
      tire.path.c_str(), t.a, sd([](const TireLawCoefficients& d) { return d.a; }), t.m,
      sd([](const TireLawCoefficients& d) { return d.m; }), t.kx,
      sd([](const TireLawCoefficients& d) { return d.kx; }), t.spin_ratio,
      sd([](const TireLawCoefficients& d) { return d.spin_ratio; }), tire.draws.draws.size(),
      tire.draws.rejected);
  std::printf("%-13s %-13s %14s %22s %10s\n", "model", "phase", "median[1/s]", "95 % band [1/s]",
              "P(shimmy)");
  const GearModel base = make_gear_model(config.gear, ContactModel::coupled);
  nlohmann::json j;
  for (StabilityPhase phase : {StabilityPhase::touchdown, StabilityPhase::braked_slide}) {
    const std::string label = std::string("monte carlo ") + to_string(phase);
    const GrowthBand b =
        growth_band(base, tire.draws.draws, phase, threads,
                    [&](int done, int total) { progress_bar(label, done, total); });
    std::printf("%-13s %-13s %14.3f      [%7.3f, %7.3f] %10.3f\n", "coupled", to_string(phase),
                b.median, b.low, b.high, b.shimmy_probability);
    j[to_string(phase)] = {{"median_growth_rate_per_s", b.median},
                           {"band95_per_s", {b.low, b.high}},
                           {"shimmy_probability", b.shimmy_probability},
                           {"draws", b.draws}};
  }
  j["report"] = tire.path;
  j["draws"] = tire.draws.draws.size();
  j["redrawn"] = tire.draws.rejected;
  j["mean_law"] = {{"a", t.a}, {"m", t.m}, {"kx", t.kx}, {"spin_ratio", t.spin_ratio}};
  summary["tire_uncertainty"] = j;
}

// Each run's oscillation at the end of its window against the eigenvalues of the phase it is in
// (braked slide when braking, else touchdown), into the summary (limit_cycle.hpp).
void add_limit_cycles(const ShimmyConfig& config, const std::vector<LandingRun>& runs,
                      nlohmann::json& summary) {
  const char* phase = config.gear.scenario.braking ? "braked_slide" : "touchdown";
  for (const LandingRun& r : runs) {
    nlohmann::json& model = summary["models"][to_string(r.contact)];
    const nlohmann::json& st = model["stability"][phase];
    const LimitCycle c =
        assess_limit_cycle(r, config.gear.structure, st["growth_rate_per_s"].get<double>(),
                           st["frequency_Hz"].get<double>(), config.criterion);
    model["limit_cycle"] = {{"measured", c.measured},
                            {"phase", phase},
                            {"amplitude_rad", c.amplitude_rad},
                            {"earlier_amplitude_rad", c.earlier_amplitude_rad},
                            {"trend_per_s", c.trend_per_s},
                            {"torque_link_amplitude_nm", c.torque_link_nm},
                            {"verdict", c.verdict}};
  }
}

// One configuration: every model's landing, its CSV and pictures, and the stability verdicts of
// both phases, all in `out`; returns the summary (without writing it).
// The demo analyses a landing: the gear must be fully loaded before the run ends (the library
// also simulates a gear that never lands, as free vibration; the demo would call it "stable").
void require_landing(const LandingScenario& s) {
  if (!(s.touchdown_time_s + s.load_ramp_s < s.end_time_s))
    throw InvalidArgument("scenario.touchdown_time_s", format_value(s.touchdown_time_s),
                          "with load_ramp_s = " + format_value(s.load_ramp_s) +
                              " the gear is not fully loaded before end_time_s = " +
                              format_value(s.end_time_s) + ": there is no landing to analyse");
}

nlohmann::json run_landings(const ShimmyConfig& config, const std::string& out, unsigned threads,
                            const TireInput* tire) {
  require_landing(config.gear.scenario);
  std::filesystem::create_directories(out);
  nlohmann::json summary;
  std::vector<LandingRun> runs;
  std::printf("%-13s %6s %9s %10s %11s %11s %9s %7s %9s %8s\n", "model", "shimmy", "freq[Hz]",
              "growth[1/s]", "peak psi", "peak y[m]", "spinup[s]", "steps", "wall[ms]", "conv");
  for (ContactModel cm : config.models) {
    const GearModel model = gear_model(config, cm, tire);
    LandingRun r = simulate_landing(model, config.solver, config.criterion);
    // Convergence: the same landing at a 100 times tighter tolerance.
    SolverOptions tight = config.solver;
    tight.relative_tolerance *= 1e-2;
    tight.record = false;
    const LandingRun t = simulate_landing(model, tight, config.criterion);
    // A growth rate is compared only where there is an oscillation to measure: both runs see
    // one, above a noise floor of 1e-3 of the shimmy amplitude threshold (a torsion stuck by
    // Coulomb spin friction leaves crossings of integration noise only).
    const double floor = 1e-3 * config.criterion.amplitude_threshold_rad;
    const bool measurable =
        r.metrics.torsion.valid() && t.metrics.torsion.valid() &&
        std::min(r.metrics.torsion.last_amplitude, t.metrics.torsion.last_amplitude) > floor;
    const double d_growth =
        measurable
            ? std::abs(r.metrics.torsion.growth_rate_per_s - t.metrics.torsion.growth_rate_per_s)
            : 0.0;
    const double d_peak = std::abs(r.metrics.peak_torsion_rad - t.metrics.peak_torsion_rad) /
                          std::max(t.metrics.peak_torsion_rad, 1e-12);
    const bool converged =
        d_growth <= 0.05 + 0.02 * std::abs(t.metrics.torsion.growth_rate_per_s) && d_peak <= 0.02 &&
        r.metrics.shimmy == t.metrics.shimmy;
    write_file_atomically(out + "/" + to_string(cm) + ".csv", csv_history(r));
    nlohmann::json j = run_json(r);
    j["convergence"] = {{"tight_relative_tolerance", tight.relative_tolerance},
                        {"growth_rate_change_per_s",
                         measurable ? nlohmann::json(d_growth) : nlohmann::json(nullptr)},
                        {"peak_torsion_relative_change", d_peak},
                        {"converged", converged}};
    summary["models"][to_string(cm)] = j;
    const OscillationEstimate& o = r.metrics.torsion;
    std::printf("%-13s %6s %9.2f %10.3f %11.3e %11.3e %9s %7ld %9.2f %8s\n", to_string(cm),
                r.metrics.shimmy ? "yes" : "no", o.frequency_hz, o.growth_rate_per_s,
                r.metrics.peak_torsion_rad, r.metrics.peak_lateral_m,
                r.spin_up_s ? std::to_string(*r.spin_up_s).substr(0, 6).c_str() : "-", r.steps,
                1e3 * r.wall_s, converged ? "ok" : "NO");
    if (!converged)
      std::fprintf(stderr,
                   "warning: %s: growth rate changes by %.3g 1/s and peak torsion by %.2g %% at "
                   "a 100x tighter tolerance; tighten solver.relative_tolerance\n",
                   to_string(cm), d_growth, 100 * d_peak);
    runs.push_back(std::move(r));
  }
  print_stability(config, runs, tire, summary);
  add_limit_cycles(config, runs, summary);
  if (tire) print_tire_uncertainty(config, *tire, threads, summary);
  summary["gear"] = config.gear_name;
  summary["analysis_window_s"] = {runs.front().window_start_s, runs.front().window_end_s};
  summary["configuration"] = to_json(config);
  draw_histories(out, runs);
  return summary;
}

// The configuration's stability maps, each model's, into `out`; their summaries into `summary`.
void run_maps(const ShimmyConfig& config, const std::string& out, int map_size, unsigned threads,
              const TireInput* tire, nlohmann::json& summary) {
  std::vector<StabilityMap> linear_maps;
  std::vector<std::string> bases;
  for (const MapSpec& spec : config.maps) {
    MapAxis x = spec.x, y = spec.y;
    if (map_size > 0) x.points = y.points = map_size;
    for (ContactModel cm : config.models) {
      const GearModel model = gear_model(config, cm, tire);
      const std::string label = std::string(to_string(cm)) + " " + short_name(x.parameter) + " x " +
                                short_name(y.parameter);
      const auto bar = [&](int done, int total) { progress_bar(label, done, total); };
      const StabilityMap m =
          spec.method == "simulation"
              ? stability_map(model, x, y, config.solver, config.criterion, threads, bar)
              : linear_stability_map(model, x, y, spec.phase, threads, bar);
      summary["maps"].push_back(write_map(out, m));
      summary["maps"].back()["model"] = to_string(cm);
      bases.push_back(summary["maps"].back()["csv"].get<std::string>());
      bases.back().erase(bases.back().size() - 4);  // ".csv"
      linear_maps.push_back(m);
      if (tire && cm == ContactModel::coupled && spec.method != "simulation") {
        // A draw per cell costs a linearisation: at most 25 x 25 cells unless --map-size.
        MapAxis px = x, py = y;
        if (map_size <= 0) {
          px.points = std::min(px.points, 25);
          py.points = std::min(py.points, 25);
        }
        const StabilityMap p = probability_map(
            make_gear_model(config.gear, cm), px, py, spec.phase, tire->draws.draws, threads,
            [&](int done, int total) { progress_bar("P(shimmy) " + label, done, total); });
        summary["probability_maps"].push_back(write_probability_map(out, p));
      }
    }
  }
  summary["overlays"] = write_boundary_overlays(
      out, linear_maps, bases, [&](ContactModel cm) { return gear_model(config, cm, tire); });
}

// What feeds the oscillation of one model in one scenario: the energy its dominant mode gains
// per cycle from each source (linear_stability.hpp, EnergyPerCycle), from the summary.
void print_energy_row(const std::string& scenario, const std::string& model,
                      const nlohmann::json& run, const char* phase) {
  const nlohmann::json& st = run["stability"][phase];
  const nlohmann::json& e = st["energy_per_cycle_J"];
  const auto get = [&](const char* key) { return e[key].get<double>(); };
  const std::vector<std::pair<const char*, double>> sources{
      {"offset drag", get("offset_drag")},
      {model == "von_schlippe" ? "aligning torque" : "spin torque", get("spin_torque")},
      {"lateral forces",
       get("trail_lateral_force") + get("lateral_friction") + get("carcass_lever")},
      {"damping", get("torsional_damping") + get("lateral_damping")}};
  const auto fed =
      std::max_element(sources.begin(), sources.end(),
                       [](const auto& a, const auto& b) { return a.second < b.second; });
  const auto number = [](const nlohmann::json& v) {
    return v.is_number() ? v.get<double>() : std::nan("");
  };
  std::printf("%-13s %-13s %6s %9.3f %8.2f %9.3f %-9s", scenario.c_str(), model.c_str(),
              run["shimmy"].get<bool>() ? "yes" : "no", number(run["growth_rate_per_s"]),
              number(run["frequency_Hz"]), st["growth_rate_per_s"].get<double>(),
              st["mode"].get<std::string>().c_str());
  for (const auto& [name, value] : sources) std::printf(" %10.3g", value);
  std::printf(" %10.3g", get("of_which_fall_of_friction"));
  double scale = 0.0;
  for (const auto& source : sources) scale += std::abs(source.second);
  std::string fed_by = fed->second > 1e-3 * scale ? fed->first : "-";
  if (fed_by != "-" && get("of_which_fall_of_friction") > 0.5 * fed->second)
    fed_by += " (the fall of f)";
  std::printf(" %10.3g  %s\n", get("total"), fed_by.c_str());
}

// The seed's claim (the coupling of sliding and spin excites shimmy), as the scenarios find it:
// where the coupled model is unstable and the classical tire is not, and where it grows faster.
void print_seed_verdict(const nlohmann::json& scenarios) {
  std::string only, faster;
  for (const NamedScenario& n : named_scenarios()) {
    if (!scenarios.contains(n.name)) continue;
    const nlohmann::json& models = scenarios[n.name]["summary"]["models"];
    if (!models.contains("coupled") || !models.contains("von_schlippe")) continue;
    const char* phase = to_string(n.phase);
    const double c = models["coupled"]["stability"][phase]["growth_rate_per_s"].get<double>();
    const double k = models["von_schlippe"]["stability"][phase]["growth_rate_per_s"].get<double>();
    if (c > 0 && k <= 0) only += (only.empty() ? "" : ", ") + n.name;
    if (c > 0 && c > k) faster += (faster.empty() ? "" : ", ") + n.name;
  }
  std::printf(
      "\nthe seed's claim (the coupling of sliding and spin excites shimmy), by the eigenvalues:\n"
      "  coupled unstable where the classical tire is stable: %s\n"
      "  coupled growing faster than the classical tire: %s\n",
      only.empty() ? "none of these scenarios" : only.c_str(),
      faster.empty() ? "none of these scenarios" : faster.c_str());
}

// The table that closes a run of scenarios: the simulated verdict, the eigenvalue verdict of
// the scenario's phase, and the energy balance of its dominant mode.
void print_scenario_table(const nlohmann::json& scenarios) {
  std::printf(
      "\nsummary: the simulated landing (shimmy, growth and frequency on the analysis window) "
      "and the\nlinearisation about the scenario's phase (eig. growth, the mode it moves most), "
      "with the energy the\nmode gains per cycle [J] at 1 mrad of torsion or 1 mm of deflection, "
      "from each source (> 0 feeds it, < 0 drains it):\noffset drag -l Fx, the spin torque Mz, the "
      "lateral "
      "forces (trail, lateral friction, carcass), damping.\nThe fall of f with slip speed acts "
      "through the drag, spin torque and lateral forces;\n'f(w) part' is their share due to it "
      "(the same mode with f held at its operating value).\n"
      "%-13s %-13s %6s %9s %8s %9s %-9s %10s %10s %10s %10s %10s %10s  %s\n",
      "scenario", "model", "shimmy", "growth", "freq[Hz]", "eig.", "mode", "offset", "spin",
      "lateral", "damping", "f(w) part", "total", "fed by");
  for (const NamedScenario& n : named_scenarios()) {
    if (!scenarios.contains(n.name)) continue;
    const nlohmann::json& models = scenarios[n.name]["summary"]["models"];
    for (auto it = models.begin(); it != models.end(); ++it)
      print_energy_row(n.name, it.key(), *it, to_string(n.phase));
  }
  std::printf("\nat the end of each analysis window (last 3 periods against the 3 before):\n");
  for (const NamedScenario& n : named_scenarios()) {
    if (!scenarios.contains(n.name)) continue;
    const nlohmann::json& models = scenarios[n.name]["summary"]["models"];
    for (auto it = models.begin(); it != models.end(); ++it)
      std::printf("%-13s %-13s %s\n", n.name.c_str(), it.key().c_str(),
                  (*it)["limit_cycle"]["verdict"].get<std::string>().c_str());
  }
  print_seed_verdict(scenarios);
}

// The named scenarios, each in out/<name>/ with its own summary; then the table over all.
nlohmann::json run_scenarios(const ShimmyConfig& config, const std::vector<std::string>& names,
                             const std::vector<std::string>& overrides, const std::string& out,
                             unsigned threads, const TireInput* tire) {
  nlohmann::json scenarios;
  for (const std::string& name : names) {
    const NamedScenario& n = named_scenario(name);
    std::vector<std::string> sets = n.overrides;
    sets.insert(sets.end(), overrides.begin(), overrides.end());
    const ShimmyConfig c = apply_overrides(config, sets);
    std::printf("\n== scenario %s: %s\n", n.name.c_str(), n.description.c_str());
    nlohmann::json summary = run_landings(c, out + "/" + n.name, threads, tire);
    write_file_atomically(out + "/" + n.name + "/summary.json", summary.dump(2) + "\n");
    scenarios[n.name] = {{"description", n.description},
                         {"overrides", n.overrides},
                         {"phase", to_string(n.phase)},
                         {"folder", n.name},
                         {"summary", std::move(summary)}};
  }
  print_scenario_table(scenarios);
  return scenarios;
}

// The command line (one struct, filled by add_options).
struct Options {
  std::string config_path, out = "out/shimmy", gear = "default", tire_path;
  bool maps = false, print_config = false, print_keys = false;
  int map_size = 0, draws = 300;
  unsigned threads = 0, seed = 1;
  std::vector<std::string> overrides, scenarios;
};

void add_options(CLI::App& app, Options& o) {
  app.add_option("--config", o.config_path, "JSON configuration (defaults: docs/shimmy.md)")
      ->check(CLI::ExistingFile);
  app.add_option("--gear", o.gear,
                 "named gear the configuration starts from: default (a one-wheel main gear, 80 kN "
                 "static load, 0.57 m wheel, wheel 0.25 m beside the strut axis, torsional damping "
                 "245 N m s/rad: 1.4 times what the classical tire needs) or legacy (the same "
                 "gear with 100 N m s/rad, which shimmies on the classical tire)")
      ->check(CLI::IsMember({"default", "legacy"}))
      ->capture_default_str();
  app.add_option("--out", o.out, "output directory")->capture_default_str();
  app.add_flag("--map", o.maps, "also draw the stability maps of the configuration");
  app.add_option("--map-size", o.map_size, "points per map axis (overrides the configuration)")
      ->check(CLI::Range(2, 1000));
  app.add_option("--threads", o.threads, "threads for the maps (0: all cores)")
      ->capture_default_str();
  app.add_option("--set", o.overrides,
                 "KEY=VALUE: one configuration value by its JSON name, after --gear and --config "
                 "(repeatable; e.g. --set structure.offset_m=0.45 --set "
                 "scenario.forward_speed_mps=58; --print-config lists the keys)")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  std::string scenario_help =
      "a named scenario (repeatable, or all); by default all of them "
      "unless --config or --set is given, which run the configuration "
      "as it is:";
  for (const NamedScenario& n : named_scenarios())
    scenario_help += "\n  " + n.name + ": " + n.description;
  app.add_option("--scenario", o.scenarios, scenario_help)
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  app.add_flag("--print-config", o.print_config,
               "print the configuration (after --config and --set) as JSON and exit");
  app.add_flag("--print-keys", o.print_keys,
               "print every configuration key with its type, unit, valid values, default and "
               "meaning (the table of docs/shimmy.md, Markdown) and exit");
  app.add_option("--tire", o.tire_path,
                 "a contensou-identify report (--json): its fitted law is the tire, and a Monte "
                 "Carlo over its covariance gives the growth rate's 95 % band and P(shimmy)")
      ->check(CLI::ExistingFile);
  app.add_option("--draws", o.draws, "Monte Carlo draws for --tire")
      ->check(CLI::Range(10, 100000))
      ->capture_default_str();
  app.add_option("--seed", o.seed, "random seed of the draws")->capture_default_str();
}

// The report of --tire, its mean law and the Monte Carlo draws.
TireInput read_tire_input(const Options& o) {
  TireInput tire;
  tire.path = o.tire_path;
  tire.distribution = read_tire_report(o.tire_path);
  tire.mean = tire_law_coefficients(tire.distribution.mean, tire.distribution.radius_m);
  try {
    tire.draws = draw_tire_laws(tire.distribution, o.draws, o.seed);
  } catch (const InvalidArgument& e) {
    throw std::runtime_error("--tire " + o.tire_path + ": " + e.what());
  }
  return tire;
}

// The scenarios to run: those named (checked before anything runs), all of them for "all" or by
// default, none when a configuration is given (--config, --set) without --scenario.
std::vector<std::string> scenarios_to_run(const Options& o) {
  std::vector<std::string> names;
  for (const std::string& n : o.scenarios)
    if (n != "all") names.push_back(named_scenario(n).name);
  const bool all = std::find(o.scenarios.begin(), o.scenarios.end(), "all") != o.scenarios.end();
  if (all || (o.scenarios.empty() && o.config_path.empty() && o.overrides.empty())) {
    names.clear();
    for (const NamedScenario& n : named_scenarios()) names.push_back(n.name);
  }
  return names;
}

int run(const Options& o) {
  if (o.print_keys) {
    std::cout << config_keys_markdown();
    return 0;
  }
  ShimmyConfig config;
  config.gear_name = o.gear;
  config.gear = gear_config_by_name(o.gear);
  if (!o.config_path.empty()) config = read_shimmy_config(o.config_path, o.gear);
  config = apply_overrides(config, o.overrides);
  if (o.print_config) {
    std::cout << to_json(config).dump(2) << '\n';
    return 0;
  }
  app::OutputFolderLock lock(o.out);                     // a second run into o.out stops here
  for (const std::string& name : scenarios_to_run(o)) {  // every scenario checked before any runs
    std::vector<std::string> sets = named_scenario(name).overrides;
    sets.insert(sets.end(), o.overrides.begin(), o.overrides.end());
    require_landing(apply_overrides(config, sets).gear.scenario);
  }
  if (scenarios_to_run(o).empty()) require_landing(config.gear.scenario);
  std::optional<TireInput> tire;
  if (!o.tire_path.empty()) tire = read_tire_input(o);
  const std::vector<std::string> names = scenarios_to_run(o);
  const TireInput* t = tire ? &*tire : nullptr;
  nlohmann::json summary;
  if (names.empty()) {
    summary = run_landings(config, o.out, o.threads, t);
  } else {
    summary["scenarios"] = run_scenarios(config, names, o.overrides, o.out, o.threads, t);
    summary["gear"] = config.gear_name;
    summary["configuration"] = to_json(config);
  }
  if (o.maps) run_maps(config, o.out, o.map_size, o.threads, t, summary);
  write_file_atomically(o.out + "/summary.json", summary.dump(2) + "\n");
  const int stale = lock.commit();  // an earlier run's files this one did not rewrite
  std::printf("wrote %s/summary.json, CSV time histories and PNGs%s", o.out.c_str(),
              names.empty() ? "" : " (a folder per scenario)");
  if (stale > 0) std::printf("; removed %d file(s) an earlier run had written there", stale);
  std::printf("\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "A one-wheel main landing gear through touchdown, sliding and spin-up: shimmy "
      "with coupled, decoupled and von_schlippe (classical string) tire contact (docs/shimmy.md)",
      kName};
  Options options;
  add_options(app, options);
  app::add_conventions(app, kName);
  app::prepare_output();
  if (const std::optional<int> status = app::parse(app, argc, argv)) return *status;
  try {
    return app::finish_output(run(options));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", kName, e.what());
    return 1;
  }
}
