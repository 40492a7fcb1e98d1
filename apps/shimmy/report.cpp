#include "report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "contensou/friction/file_output.hpp"
#include "gnuplot.hpp"
#include "history.hpp"
#include "history_plots.hpp"
#include "model_colours.hpp"
#include "scenarios.hpp"

namespace contensou::app {
namespace {

std::string csv_history(const LandingRun& run, const GearStructure& structure) {
  std::ostringstream o;
  o.precision(9);
  const std::vector<std::string>& columns = history_columns();
  for (std::size_t i = 0; i < columns.size(); ++i) o << (i ? "," : "") << columns[i];
  o << '\n';
  for (const LandingSample& s : run.samples) {
    const std::vector<double> row = history_row(s, structure);
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

// The landing table's header and one model's row (and the warning for a landing that changes at
// the tighter tolerance).
void print_landing_header() {
  std::printf("%-13s %6s %9s %10s %11s %11s %9s %7s %9s %8s\n", "model", "shimmy", "freq[Hz]",
              "growth[1/s]", "peak psi", "peak y[m]", "spinup[s]", "steps", "wall[ms]", "conv");
}

void print_landing_row(const LandingRun& r, const Convergence& c) {
  const OscillationEstimate& o = r.metrics.torsion;
  std::printf("%-13s %6s %9.2f %10.3f %11.3e %11.3e %9s %7ld %9.2f %8s\n", to_string(r.contact),
              r.metrics.shimmy ? "yes" : "no", o.frequency_hz, o.growth_rate_per_s,
              r.metrics.peak_torsion_rad, r.metrics.peak_lateral_m,
              r.spin_up_s ? std::to_string(*r.spin_up_s).substr(0, 6).c_str() : "-", r.steps,
              1e3 * r.wall_s, c.converged ? "ok" : "NO");
  if (!c.converged)
    std::fprintf(stderr,
                 "warning: %s: growth rate changes by %.3g 1/s and peak torsion by %.2g %% at "
                 "a 100x tighter tolerance; tighten solver.relative_tolerance\n",
                 to_string(r.contact), c.growth_rate_change_per_s,
                 100 * c.peak_torsion_relative_change);
}

nlohmann::json convergence_json(const Convergence& c) {
  return {{"tight_relative_tolerance", c.tight_relative_tolerance},
          {"growth_rate_change_per_s",
           c.measurable ? nlohmann::json(c.growth_rate_change_per_s) : nlohmann::json(nullptr)},
          {"peak_torsion_relative_change", c.peak_torsion_relative_change},
          {"converged", c.converged}};
}

nlohmann::json limit_cycle_json(const ModelAnalysis& a) {
  const LimitCycle& c = a.limit_cycle;
  return {{"measured", c.measured},
          {"state", to_string(c.state)},
          {"phase", a.limit_cycle_phase},
          {"amplitude_rad", c.amplitude_rad},
          {"earlier_amplitude_rad", c.earlier_amplitude_rad},
          {"start_amplitude_rad", c.start_amplitude_rad},
          {"trend_per_s", c.trend_per_s},
          {"settling_band_per_s", c.band_per_s},
          {"trend_periods", kTrendPeriods},
          {"midway_amplitude_rad", c.midway_amplitude_rad},
          {"midway_s", c.midway_s},
          {"drifting", c.drifting},
          {"run_end_s", c.run_end_s},
          {"eigenvalue_growth_rate_per_s", c.eigen_growth_per_s},
          {"torque_link_amplitude_nm", c.torque_link_nm},
          {"verdict", c.verdict}};
}

// The stability verdicts of both phases (docs/shimmy.md, "Stability criterion"), by the
// eigenvalues of the linearisation and the growth after the standard perturbation.
void print_stability(const ShimmyConfig& config, const Landings& landings,
                     const LandingAnalysis& analysis, nlohmann::json& summary) {
  std::printf(
      "\nstability: eigenvalues of the linearisation about the quasi-steady state, and the growth "
      "after psi' += 0.1 rad/s\n(growth: all modes; torsion: the torsional mode; pert.: growth "
      "fitted after the kick; spin damp. -dMz/dpsi' [N m s/rad])\n"
      "%-13s %-13s %11s %8s %12s %11s %11s %6s  %s\n",
      "model", "phase", "growth[1/s]", "freq[Hz]", "torsion[1/s]", "pert.[1/s]", "spin damp.", "f",
      "verdict");
  for (std::size_t k = 0; k < landings.runs.size(); ++k) {
    const ContactModel contact = landings.runs[k].contact;
    const ModelAnalysis& a = analysis.models[k];
    for (const PhaseStability* p : {&a.touchdown, &a.braked_slide}) {
      const StabilityReport* r = &p->report;
      std::printf("%-13s %-13s %11.3f %8.2f %12.3f %11.3f %11.4g %6.3f  %s\n", to_string(contact),
                  to_string(r->state.phase), r->growth_rate_per_s, r->frequency_hz,
                  r->torsion_growth_rate_per_s, r->perturbation_growth_rate_per_s,
                  r->spin_torque_damping_nms_per_rad, r->friction, p->verdict.c_str());
      nlohmann::json j = report_json(*r);
      j["verdict"] = p->verdict;
      summary["models"][to_string(contact)]["stability"][to_string(r->state.phase)] = j;
    }
    const StabilityReport& br = a.braked_slide.report;
    if (contact == ContactModel::decoupled && config.gear.structure.carcass_compliance())
      std::printf(
          "  note: the decoupled model's regularised Coulomb spin torque (M0 R / eps) acts in "
          "series with the carcass's torsional spring: %.3g N m s/rad of damping at the rim "
          "while braking; shown for reference only\n",
          br.spin_torque_damping_nms_per_rad);
    else if (contact == ContactModel::decoupled)
      std::printf(
          "  note: the decoupled model's spin torque is Coulomb spin friction, M0 whatever the "
          "sliding: at shimmy's small spin rates (|omega R| < eps) the patch sticks in spin, a "
          "torsional damper of %.3g N m s/rad (M0 R / eps) while braking that grows without bound "
          "as eps -> 0 (stick, not an artefact); the coupled law removes this stick while the "
          "patch slides (Mz -> M0 u / (sqrt(m) v))\n",
          br.spin_torque_damping_nms_per_rad);
  }
}

// The Monte Carlo over the report's covariance: growth band and P(shimmy) of both phases for
// the coupled model at the configuration.
void print_tire_uncertainty(const TireInput& tire, const TireAnalysis& a, nlohmann::json& summary) {
  const TireLawCoefficients& t = tire.mean;
  std::printf(
      "\ntire law from %s: a = %.4g +- %.2g, m = %.4g +- %.2g, kx = %.4g +- %.2g, M0/(F0 R) = "
      "%.4g +- %.2g (%zu draws, %d redrawn; the report's %s model)\n",
      tire.path.c_str(), t.a, a.sd_a, t.m, a.sd_m, t.kx, a.sd_kx, t.spin_ratio, a.sd_spin_ratio,
      tire.draws.draws.size(), tire.draws.rejected, tire.model.c_str());
  if (!tire.note.empty()) std::printf("note: %s\n", tire.note.c_str());
  std::printf("%-13s %-13s %14s %22s %10s\n", "model", "phase", "median[1/s]", "95 % band [1/s]",
              "P(shimmy)");
  nlohmann::json j;
  for (StabilityPhase phase : {StabilityPhase::touchdown, StabilityPhase::braked_slide}) {
    const GrowthBand& b = phase == StabilityPhase::touchdown ? a.touchdown : a.braked_slide;
    std::printf("%-13s %-13s %14.3f      [%7.3f, %7.3f] %10.3f\n", "coupled", to_string(phase),
                b.median, b.low, b.high, b.shimmy_probability);
    j[to_string(phase)] = {{"median_growth_rate_per_s", b.median},
                           {"band95_per_s", {b.low, b.high}},
                           {"shimmy_probability", b.shimmy_probability},
                           {"draws", b.draws}};
  }
  j["report"] = tire.path;
  j["report_model"] = tire.model;
  j["note"] = tire.note;
  j["draws"] = tire.draws.draws.size();
  j["redrawn"] = tire.draws.rejected;
  j["mean_law"] = {{"a", t.a}, {"m", t.m}, {"kx", t.kx}, {"spin_ratio", t.spin_ratio}};
  summary["tire_uncertainty"] = j;
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

// An unbraked scenario's window after the spin-up compares one tire: every sliding model rolls on
// the string tire from its spin-up on. Said plainly, with where the models do differ.
void print_same_tire_note(const nlohmann::json& scenarios) {
  for (const NamedScenario& n : named_scenarios()) {
    if (!scenarios.contains(n.name) || n.phase != StabilityPhase::touchdown) continue;
    const nlohmann::json& models = scenarios[n.name]["summary"]["models"];
    double spin_up = 0.0, start = 0.0;
    for (auto it = models.begin(); it != models.end(); ++it) {
      if ((*it)["spin_up_s"].is_number())
        spin_up = std::max(spin_up, (*it)["spin_up_s"].get<double>());
      start = (*it)["window_s"][0].get<double>();
    }
    const double td =
        scenarios[n.name]["summary"]["configuration"]["scenario"]["touchdown_time_s"].get<double>();
    if (spin_up > 0.0)
      std::printf(
          "note: %s: every model has spun up by %.3f s and then rolls on the same string tire, so "
          "its simulated window (from %.3f s) compares one tire; the models differ "
          "only during the %.3f s spin-up, which the touchdown eigenvalues (frozen slip, "
          "stability table) compare\n",
          n.name.c_str(), td + spin_up, start, spin_up);
  }
}

// What the coupled spin torque does in each scenario's dominant mode (energy per cycle), and the
// decoupled model's stick damping beside it: the reading of the comparison, from the results.
void print_spin_torque_reading(const nlohmann::json& scenarios) {
  std::string feeds, drains;
  for (const NamedScenario& n : named_scenarios()) {
    if (!scenarios.contains(n.name)) continue;
    const nlohmann::json& models = scenarios[n.name]["summary"]["models"];
    if (!models.contains("coupled")) continue;
    const nlohmann::json& e =
        models["coupled"]["stability"][to_string(n.phase)]["energy_per_cycle_J"];
    const double w = e["spin_torque"].get<double>();
    double scale = 0.0;  // the terms' sizes: a spin torque below 1e-3 of them does nothing
    for (const char* k : {"spin_torque", "trail_lateral_force", "offset_drag", "torsional_damping",
                          "lateral_friction", "lateral_damping", "carcass_lever"})
      scale += std::abs(e[k].get<double>());
    if (!(std::abs(w) > 1e-3 * scale)) continue;
    (w > 0.0 ? feeds : drains) += ((w > 0.0 ? feeds : drains).empty() ? "" : ", ") + n.name;
  }
  std::printf("  the coupled spin torque feeds the dominant mode in: %s; drains it in: %s\n",
              feeds.empty() ? "none" : feeds.c_str(), drains.empty() ? "none" : drains.c_str());
  if (feeds.empty() && !drains.empty())
    std::printf(
        "  so the coupling does not itself feed the mode here; what it changes is the spin stick "
        "the decoupled model has (its Coulomb spin torque damps the torsion while the coupled "
        "one, sliding, barely does)\n");
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
  print_spin_torque_reading(scenarios);
}

// The energy per cycle of each model's dominant mode by source (the run's phase), as a bar chart:
// energy.csv (one row a source, one column a model, mJ at 1 mrad or 1 mm) and energy.png.
void draw_energy(const OutputDir& out, const Landings& landings, const LandingAnalysis& analysis,
                 bool braking) {
  const std::vector<std::pair<const char*, double EnergyPerCycle::*>> sources{
      {"offset drag -l Fx", &EnergyPerCycle::offset_drag},
      {"contact torque Mz", &EnergyPerCycle::spin_torque},
      {"trail -e Fy", &EnergyPerCycle::trail_lateral_force},
      {"lateral friction", &EnergyPerCycle::lateral_friction},
      {"carcass lever", &EnergyPerCycle::carcass_lever},
      {"torsional damping", &EnergyPerCycle::torsional_damping},
      {"lateral damping", &EnergyPerCycle::lateral_damping}};
  const auto energy = [&](std::size_t k) -> const EnergyPerCycle& {
    const ModelAnalysis& a = analysis.models[k];
    return (braking ? a.braked_slide : a.touchdown).report.energy;
  };
  // A source that is zero in every model is switched off (the carcass lever without a carcass):
  // left out of the table and the chart, and said so.
  std::ostringstream csv;
  csv.precision(6);
  csv << "source";
  for (const LandingRun& r : landings.runs) csv << ',' << to_string(r.contact) << "_mJ";
  csv << '\n';
  std::string omitted;
  for (const auto& [name, member] : sources) {
    bool any = false;
    for (std::size_t k = 0; k < landings.runs.size(); ++k) any |= energy(k).*member != 0.0;
    if (!any) {
      omitted += (omitted.empty() ? "" : ", ") + std::string(name);
      continue;
    }
    csv << '"' << name << '"';
    for (std::size_t k = 0; k < landings.runs.size(); ++k) csv << ',' << 1e3 * energy(k).*member;
    csv << '\n';
  }
  csv << "\"total\"";
  for (std::size_t k = 0; k < landings.runs.size(); ++k) csv << ',' << 1e3 * energy(k).total();
  csv << '\n';
  out.write("energy.csv", csv.str());
  // One panel a model, each on its own scale: one model's large drain does not flatten the others.
  const std::size_t n = landings.runs.size();
  std::ostringstream gp;
  gp << "set terminal pngcairo noenhanced size 1000," << 90 + 250 * n
     << " font ',10'\nset output 'energy.png'\n"
     << "set datafile separator ','\nset datafile columnheaders\n"
     << "set multiplot layout " << n << ",1 title \"energy per cycle of each model's dominant "
     << "mode, by source (" << (braking ? "braked slide" : "touchdown")
     << " linearisation; 1 mrad of torsion or 1 mm of deflection)\\n> 0 feeds the mode, < 0 "
        "drains it; each model on its own scale"
     << (omitted.empty() ? "" : "; zero in every model (switched off), not shown: " + omitted)
     << "\"\n"
     << "set style data histograms\nset style histogram clustered gap 1\n"
     << "set style fill solid 0.85 border -1\nset boxwidth 0.6\nset grid ytics\n"
     << "set xzeroaxis lt -1\nset xtics rotate by -15 left\nset key inside right top\n"
     << "set lmargin 12\nset rmargin 6\n"
     << "set ylabel 'work per cycle [mJ]'\n";
  for (std::size_t k = 0; k < n; ++k) {
    const ContactModel m = landings.runs[k].contact;
    gp << "plot 'energy.csv' using \"" << to_string(m) << "_mJ\":xtic(1) lc rgb '"
       << model_colour(m) << "' title '" << to_string(m) << "'\n";
  }
  gp << "unset multiplot\n";
  run_gnuplot(out, "energy", gp.str());
}

}  // namespace

nlohmann::json report_landings(const ShimmyConfig& config, const Landings& landings,
                               const LandingAnalysis& analysis, const TireInput* tire,
                               const OutputDir& out) {
  nlohmann::json summary;
  print_landing_header();
  for (std::size_t k = 0; k < landings.runs.size(); ++k) {
    const LandingRun& r = landings.runs[k];
    const Convergence& c = analysis.models[k].convergence;
    out.write(std::string(to_string(r.contact)) + ".csv", csv_history(r, config.gear.structure));
    nlohmann::json j = run_json(r);
    j["convergence"] = convergence_json(c);
    summary["models"][to_string(r.contact)] = j;
    print_landing_row(r, c);
  }
  print_stability(config, landings, analysis, summary);
  for (std::size_t k = 0; k < landings.runs.size(); ++k)
    summary["models"][to_string(landings.runs[k].contact)]["limit_cycle"] =
        limit_cycle_json(analysis.models[k]);
  if (tire && analysis.tire) print_tire_uncertainty(*tire, *analysis.tire, summary);
  summary["gear"] = config.gear_name;
  summary["analysis_window_s"] = {landings.runs.front().window_start_s,
                                  landings.runs.front().window_end_s};
  summary["configuration"] = to_json(config);
  draw_histories(out, landings.runs, config.gear.structure);
  draw_energy(out, landings, analysis, config.gear.scenario.braking);
  return summary;
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
  print_same_tire_note(scenarios);
  std::printf(
      "\nat the end of each analysis window (settled: the trend of the amplitude over its last %d "
      "periods within the band and the amplitude within %.0f %% of the window's middle; a run "
      "that has not settled is run again, twice as long, up to %g s):\n",
      kTrendPeriods, 100 * kSettledChange, kLongestRun);
  for (const NamedScenario& n : named_scenarios()) {
    if (!scenarios.contains(n.name)) continue;
    const nlohmann::json& models = scenarios[n.name]["summary"]["models"];
    for (auto it = models.begin(); it != models.end(); ++it)
      std::printf("%-13s %-13s %s\n", n.name.c_str(), it.key().c_str(),
                  (*it)["limit_cycle"]["verdict"].get<std::string>().c_str());
  }
  print_seed_verdict(scenarios);
}

}  // namespace contensou::app
