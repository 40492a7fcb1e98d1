// contensou-shimmy: a one-wheel main landing gear through touchdown, sliding and spin-up, with
// three contact models (docs/shimmy.md). One way through: config (config.cpp, overrides.cpp,
// scenarios.cpp) -> simulate (simulate.cpp) -> analyse (analysis.cpp, boundary_overlay.cpp) ->
// report (report.cpp, map_report.cpp).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <thread>

#include "analysis.hpp"
#include "boundary_overlay.hpp"
#include "cli.hpp"
#include "config.hpp"
#include "config_keys.hpp"
#include "contensou/friction/file_output.hpp"
#include "map_report.hpp"
#include "overrides.hpp"
#include "report.hpp"
#include "run_guard.hpp"
#include "scenarios.hpp"
#include "sensitivity.hpp"
#include "simulate.hpp"
#include "sweeps.hpp"

using namespace contensou;
using namespace contensou::app;

namespace {

constexpr const char* kName = "contensou-shimmy";

void progress_bar(const std::string& label, int done, int total) {
  if (!isatty(STDERR_FILENO)) return;
  const int width = 40, filled = total > 0 ? width * done / total : width;
  std::fprintf(stderr, "\r%-36s [%s%s] %d/%d", label.c_str(), std::string(filled, '#').c_str(),
               std::string(width - filled, '.').c_str(), done, total);
  if (done == total) std::fputc('\n', stderr);
  std::fflush(stderr);
}

// One configuration, one way: simulate every model's landing, analyse the landings, report
// them into `out`; returns the summary (without writing it).
nlohmann::json run_landings(const ShimmyConfig& config, const app::OutputDir& out, unsigned threads,
                            const TireInput* tire) {
  if (const std::string unusual = unusual_gear_inputs(config.gear); !unusual.empty())
    std::printf("note: inputs far from the default gear's: %s\n", unusual.c_str());
  const Landings landings = simulate_landings(config, tire);
  const LandingAnalysis analysis = analyse_landings(config, landings, tire, threads, progress_bar);
  return report_landings(config, landings, analysis, tire, out);
}

// The configuration's stability maps, each model's, into `out`; their summaries into `summary`.
void run_maps(const ShimmyConfig& config, const app::OutputDir& out, int map_size, unsigned threads,
              const TireInput* tire, nlohmann::json& summary) {
  const std::vector<ComputedMap> maps = compute_maps(config, map_size, threads, tire, progress_bar);
  const std::vector<Overlay> overlays =
      analyse_overlays(maps, [&](ContactModel cm) { return gear_model(config, cm, tire); });
  report_maps(out, maps, overlays, summary);
}

// The named scenarios, each in out/<name>/ with its own summary; then the table over all.
nlohmann::json run_scenarios(const ShimmyConfig& config, const std::vector<std::string>& names,
                             const std::vector<std::string>& overrides, const app::OutputDir& out,
                             unsigned threads, const TireInput* tire) {
  nlohmann::json scenarios;
  for (const std::string& name : names) {
    const NamedScenario& n = named_scenario(name);
    std::vector<std::string> sets = n.overrides;
    sets.insert(sets.end(), overrides.begin(), overrides.end());
    const ShimmyConfig c = apply_overrides(config, sets);
    std::printf("\n== scenario %s: %s\n", n.name.c_str(), n.description.c_str());
    const app::OutputDir folder = out.sub(n.name);
    nlohmann::json summary = run_landings(c, folder, threads, tire);
    folder.write("summary.json",
                 summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
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
  bool maps = false, bifurcation = false, print_config = false, print_keys = false;
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
                 "216 N m s/rad: 1.4 times what the classical tire needs) or legacy (the same "
                 "gear with 100 N m s/rad, which shimmies on the classical tire)")
      ->check(CLI::IsMember({"default", "legacy"}))
      ->capture_default_str();
  app.add_option("--out", o.out, "output directory")->capture_default_str();
  app.add_flag("--map", o.maps, "also draw the stability maps of the configuration");
  app.add_flag("--bifurcation", o.bifurcation,
               "also sweep the braked slide's limit cycle over the configuration's sweeps "
               "(speed, offset, torsional damping by default), up and down, for every model: "
               "amplitude, torque-link load, growth, frequency and time to onset");
  app.add_option("--map-size", o.map_size,
                 "points per map axis (overrides the configuration); a run's maps take at most "
                 "500000 eigenvalue cells and 20000 simulated landings")
      ->check(CLI::Range(2, 1000));
  app.add_option("--threads", o.threads,
                 "threads for the maps, sweeps and draws (0 or more than the machine's cores: "
                 "one per core)")
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

// The config step: the named gear, then the file (--config), then --set.
ShimmyConfig configuration(const Options& o) {
  ShimmyConfig config;
  config.gear_name = o.gear;
  config.gear = gear_config_by_name(o.gear);
  if (!o.config_path.empty()) config = read_shimmy_config(o.config_path, o.gear);
  return apply_overrides(config, o.overrides);
}

int run(const Options& o) {
  if (o.print_keys) {
    std::cout << config_keys_markdown();
    return 0;
  }
  const ShimmyConfig config = configuration(o);
  if (o.print_config) {
    std::cout << to_json(config).dump(2) << '\n';
    return 0;
  }
  app::OutputFolder folder(o.out);  // checked and locked: a second run into o.out stops here
  const app::OutputDir out(folder);
  for (const std::string& name : scenarios_to_run(o)) {  // every scenario checked before any runs
    std::vector<std::string> sets = named_scenario(name).overrides;
    sets.insert(sets.end(), o.overrides.begin(), o.overrides.end());
    require_landing(apply_overrides(config, sets).gear.scenario);
  }
  if (scenarios_to_run(o).empty()) require_landing(config.gear.scenario);
  std::optional<TireInput> tire;
  if (!o.tire_path.empty()) tire = read_tire_input(o.tire_path, o.draws, o.seed);
  const std::vector<std::string> names = scenarios_to_run(o);
  const TireInput* t = tire ? &*tire : nullptr;
  if (o.maps) check_map_work(config, o.map_size, t);  // bounded before anything runs
  if (o.bifurcation) check_sweep_work(config);
  nlohmann::json summary;
  if (names.empty()) {
    summary = run_landings(config, out, o.threads, t);
  } else {
    summary["scenarios"] = run_scenarios(config, names, o.overrides, out, o.threads, t);
    summary["gear"] = config.gear_name;
    summary["configuration"] = to_json(config);
  }
  const auto& models = config.models;
  if (std::find(models.begin(), models.end(), ContactModel::von_schlippe) != models.end())
    report_sensitivity(classical_sensitivity(config, t), summary);
  if (o.maps) run_maps(config, out, o.map_size, o.threads, t, summary);
  if (o.bifurcation)
    report_sweeps(out, compute_sweeps(config, o.threads, t, progress_bar), sweep_options(config),
                  summary);
  out.write("summary.json",
            summary.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
  const int stale = folder.commit();  // an earlier run's files this one did not rewrite
  std::printf("wrote %s/summary.json, CSV time histories and PNGs%s", o.out.c_str(),
              names.empty() ? "" : " (a folder per scenario)");
  if (stale > 0) std::printf("; removed %d file(s) an earlier run had written there", stale);
  std::printf("\n");
  return 0;
}

// --threads beyond the machine's cores: as many threads as cores, said on stderr.
unsigned usable_threads(unsigned asked) {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  if (asked <= cores) return asked;
  std::fprintf(stderr, "%s: --threads %u: this machine has %u core%s; using %u\n", kName, asked,
               cores, cores == 1 ? "" : "s", cores);
  return cores;
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
    options.threads = usable_threads(options.threads);
    return app::finish_output(run(options));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", kName, e.what());
    return 1;
  }
}
