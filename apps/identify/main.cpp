// contensou-identify: fit the fractional law to measured friction diagrams (and simulate them).
#include <unistd.h>

#include <glog/logging.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "contensou/contensou.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/identify.hpp"
#include "contensou/identification/report.hpp"
#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"
#include "gnuplot.hpp"
#include "report.hpp"
#include "run_guard.hpp"

using namespace contensou;

namespace {

constexpr const char* kName = "contensou-identify";

std::pair<std::string, double> parse_fix(const std::string& s) {
  const auto eq = s.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::runtime_error("--fix " + s + ": expected NAME=VALUE, e.g. --fix a=1.03");
  const std::string value = s.substr(eq + 1);
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || !std::isfinite(v))
    throw std::runtime_error("--fix " + s + ": '" + value + "' is not a finite number");
  return {s.substr(0, eq), v};
}

// What the fit's command line gives (main binds the options to these fields).
struct FitArgs {
  std::string data_path, json_path, plots_dir, profile_spec, columns;
  std::string loss = "none", noise_model = "additive";
  double radius = 0.0, loss_scale = 2.0, alpha = 1e-3;
  std::optional<double> load, pressure;
  std::vector<std::string> fixes;
  std::vector<double> noise_scale;
  bool no_loop = false, speed_inside = true, profile_clip = false, progress = false;
  int failing_point = -1, smoothing = 0;
};

// The library's options from the command line, and the profile chosen.
IdentificationOptions identification_options(const FitArgs& a, ProfileChoice& profile) {
  IdentificationOptions o;
  o.radius_m = a.radius;
  require_positive("--radius", a.radius);
  if (a.smoothing > 0 && (a.profile_spec.empty() || !std::filesystem::exists(a.profile_spec)))
    throw std::runtime_error("--profile-smoothing needs --profile with a CSV file");
  if (a.load) require_positive("--normal-load", *a.load);
  o.normal_load_n = a.load;
  if (!a.profile_spec.empty()) {
    profile = choose_profile(a.profile_spec, a.smoothing, a.profile_clip);
    o.profile = profile.profile;
    const std::optional<double> ps =
        profile.reference_pressure ? profile.reference_pressure : a.pressure;
    if (ps) {
      ContactPatch patch;
      patch.radius_m = a.radius;
      patch.reference_pressure_pa = *ps;
      patch.profile = profile.profile;
      o.normal_load_n = normal_load(patch);
    }
  }
  for (const std::string& f : a.fixes) o.fixed.insert(parse_fix(f));
  o.failing_point = a.failing_point;
  o.loss = a.loss == "huber"    ? RobustLoss::huber
           : a.loss == "cauchy" ? RobustLoss::cauchy
                                : RobustLoss::none;
  o.loss_scale = a.loss_scale;
  o.noise_model = a.noise_model == "relative" ? NoiseModel::relative : NoiseModel::additive;
  if (!a.noise_scale.empty()) {
    if (a.noise_scale.size() != 3)
      throw std::runtime_error("--noise-scale needs three values: Fx,Fy,Mz");
    o.noise_scale = std::array<double, 3>{a.noise_scale[0], a.noise_scale[1], a.noise_scale[2]};
  }
  return o;
}

// Progress for people (on a terminal, or with --progress): a line per stage of the loop on
// stderr, each with the time since the loop began; in scripts and pipes stderr keeps errors
// only.
void show_progress(ClosedLoopOptions& lo, bool asked) {
  if (!asked && !isatty(fileno(stderr))) return;
  const auto start = std::chrono::steady_clock::now();
  lo.progress = [start](const std::string& line) {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "[closed loop %7.1f s] %s\n", s, line.c_str());
    std::fflush(stderr);
  };
}

int print_and_write(const FitArgs& a, const Identification& run, const app::RunInfo& info) {
  const MeasuredData& data = run.fitted;
  if (!run.loop) {
    std::printf("%s %s: fractional law (seed eqs. 5-7)\n%s", kName, kVersion,
                fit_report_text(info, run.fit).c_str());
    if (!a.plots_dir.empty() && app::write_plots(a.plots_dir, data, run.fit, a.radius))
      std::printf("pictures: %s/fit_*.png\n", a.plots_dir.c_str());
    if (!a.json_path.empty()) {
      write_file_atomically(a.json_path, fit_report_json(info, run.fit) + "\n");
      std::printf("report: %s\n", a.json_path.c_str());
    }
    return 0;
  }
  const ClosedLoopReport& loop = *run.loop;
  std::printf("%s %s\n%s", kName, kVersion, loop_report_text(info, loop).c_str());
  if (!a.plots_dir.empty()) {
    const bool p = app::write_plots(a.plots_dir, data, loop.final_fit, a.radius);
    const bool q = app::write_loop_plots(a.plots_dir, data, loop, a.radius);
    if (p && q)
      std::printf("pictures: %s/fit_*.png (final model), %s/loop_step_*.png\n", a.plots_dir.c_str(),
                  a.plots_dir.c_str());
  }
  if (!a.json_path.empty()) {
    write_file_atomically(a.json_path, loop_report_json(info, loop) + "\n");
    std::printf("report: %s\n", a.json_path.c_str());
  }
  return 0;
}

int run_fit(const FitArgs& a) {
  ProfileChoice profile;
  std::string load_source;
  IdentificationOptions o = identification_options(a, profile);
  const MeasuredData data = read_measured_csv(a.data_path, parse_column_renames(a.columns));
  if (!o.normal_load_n)
    if (const std::optional<LoadFromData> l = normal_load_from_data(data)) {
      o.normal_load_n = l->mean_n;  // f = F0 / N is then reported
      load_source = l->description();
    }
  IdentifyOptions io;
  io.fit = o;
  if (!a.no_loop) {
    io.loop = ClosedLoopOptions{};
    io.loop->alpha = a.alpha;
    io.loop->speed_inside_integrals = a.speed_inside;
    show_progress(*io.loop, a.progress);
  }
  const Identification run = identify(data, io);
  app::RunInfo info = describe_run(a.data_path, data, a.radius, o.normal_load_n, profile);
  info.normal_load_source = load_source;
  info.outliers = run.outliers;
  return print_and_write(a, run, info);
}

struct SimulateArgs {
  std::string out;
  double radius = 0.087;
  std::string profile = "seed-tire";
  std::optional<double> pressure;
  double friction = 0.3, kx = 0.14, ky = 0.0, kappa = 1.0;
  std::string model = "exact";
  DiagramSpec spec;
  std::string noise = "additive-gaussian";
  double speed_drop = 0.0, speed_ref = 5.0;
  std::vector<double> offset;
  std::vector<double> directions;
  std::vector<std::string> crosstalk;
};

int run_simulate(SimulateArgs a) {
  const ProfileChoice p = choose_profile(a.profile);
  ContactPatch patch;
  patch.radius_m = a.radius;
  patch.reference_pressure_pa =
      p.reference_pressure ? *p.reference_pressure : a.pressure.value_or(2.1e5);
  patch.friction = a.friction;
  patch.kappa = a.kappa;
  patch.profile = p.profile;
  patch.profile.kx = a.kx;
  patch.profile.ky = a.ky;
  if (a.speed_drop != 0.0)
    patch.slip_speed_friction =
        SlipSpeedFriction<double>{a.friction, a.friction * (1.0 - a.speed_drop), a.speed_ref, 1.0};
  if (a.offset.size() == 3) a.spec.rig.offset = {a.offset[0], a.offset[1], a.offset[2]};
  validate(patch);
  a.spec.radius_m = a.radius;
  a.spec.noise = parse_noise(a.noise);
  // One sweep per sliding direction, one after another in time.
  if (a.directions.empty()) a.directions = {a.spec.direction_rad};
  for (const std::string& x : a.crosstalk) {
    const auto arrow = x.find("<-"), eq = x.find('=');
    int ci = -1, di = -1;
    if (arrow != std::string::npos && eq != std::string::npos && eq > arrow)
      for (int k = 0; k < kChannels; ++k) {
        if (x.substr(0, arrow) == kChannelColumns[k]) ci = k;
        if (x.substr(arrow + 2, eq - arrow - 2) == kChannelColumns[k]) di = k;
      }
    if (ci < 0 || di < 0 || ci == di)
      throw std::runtime_error("--crosstalk " + x + ": expected e.g. Mz_Nm<-Fx_N=0.002");
    a.spec.rig.crosstalk[ci][di] = std::stod(x.substr(eq + 1));
  }
  MeasuredData d;
  const std::uint64_t seed = a.spec.seed;
  for (std::size_t k = 0; k < a.directions.size(); ++k) {
    DiagramSpec sweep = a.spec;
    sweep.direction_rad = a.directions[k];
    sweep.seed = seed + 1000 * k;
    MeasuredData part = a.model == "exact"
                            ? simulate_diagrams(make_exact_model(patch), sweep)
                            : simulate_diagrams(fractional_law_from_patch(patch), sweep);
    for (MeasuredPoint& point : part.points) {
      if (point.time) *point.time += static_cast<double>(k) * sweep.points * sweep.time_step_s;
      d.points.push_back(point);
    }
  }
  std::ostringstream c;
  c << "simulated by " << kName << " " << kVersion << ": " << a.model << " model, profile "
    << a.profile << ", R = " << a.radius << " m, p* = " << patch.reference_pressure_pa
    << " Pa (N = " << normal_load(patch) << " N), f = " << a.friction << ", kx = " << a.kx
    << ", ky = " << a.ky << ", kappa = " << a.kappa << "\nnoise " << a.noise << " level "
    << a.spec.noise_level << ", seed " << a.spec.seed << ", psi in [" << a.spec.psi_min << ", "
    << a.spec.psi_max << "], u = omega R = " << a.spec.spin_speed_mps << " m/s";
  write_measured_csv(a.out, d, c.str());
  std::printf("wrote %s: %zu points (N = %.1f N)\n", a.out.c_str(), d.points.size(),
              normal_load(patch));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Fits the coupled dry-friction law (Kireenkov & Zhavoronok 2020, eqs. 5-7) to measured\n"
      "diagrams Fx, Fy, Mz against the sliding velocity and spin (CSV, theory.md section 6),\n"
      "and reports the parameters with 95 % confidence intervals."};
  app.set_version_flag("--version", std::string(kName) + " " + kVersion);
  FitArgs a;
  bool effective_speed = false, verbose = false;
  app.add_option("data", a.data_path,
                 "measured diagrams (CSV: vx_mps, vy_mps, omega_radps, Fx_N, ...)");
  auto* radius_opt = app.add_option("--radius", a.radius, "patch radius R [m]");
  auto* load_opt =
      app.add_option("--normal-load", a.load, "normal load N [N] (f = F0/N is reported)");
  app.add_option("--profile", a.profile_spec,
                 "pressure profile: CSV rho,pressure_Pa or uniform|hertz|seed-tire (fixes the "
                 "shape constants; with a CSV or --pressure it also gives N)")
      ->excludes(load_opt);
  app.add_option("--pressure", a.pressure, "reference pressure p* [Pa] for a built-in profile");
  app.add_option("--json", a.json_path, "write the report as JSON (whole or not at all)");
  app.add_option("--plots", a.plots_dir, "write pictures (PNG via gnuplot) and their data here");
  app.add_option("--columns", a.columns,
                 "read columns under other names: QUANTITY=COLUMN,... with QUANTITY one of vx, "
                 "vy, omega, Fx, Fy, Mz, Fz, t; a unit in the name ('Speed [km/h]') or a units "
                 "row is converted");
  app.add_option("--fix", a.fixes, "hold a parameter fixed: NAME=VALUE (F0_N, a, M0_Nm, m, kx)");
  app.add_option("--loss", a.loss, "robust loss")
      ->check(CLI::IsMember({"none", "huber", "cauchy"}));
  app.add_option("--loss-scale", a.loss_scale, "robust loss threshold in noise scales")
      ->check(CLI::PositiveNumber);
  app.add_option("--noise-model", a.noise_model,
                 "noise: additive (constant per channel) or relative")
      ->check(CLI::IsMember({"additive", "relative"}));
  app.add_option("--noise-scale", a.noise_scale, "given noise scales Fx,Fy,Mz (else estimated)")
      ->delimiter(',');
  app.add_flag("--no-loop", a.no_loop, "fit the fractional law only; do not close the loop");
  app.add_option("--alpha", a.alpha, "closed loop: family-wise level of the LR test per step")
      ->check(CLI::Range(1e-12, 0.5));
  auto* inside = app.add_flag("--speed-inside-integrals", a.speed_inside,
                              "closed loop: slip-speed friction at the local slip speed inside "
                              "the exact integrals (the default)");
  app.add_flag("--effective-speed", effective_speed,
               "closed loop: slip-speed friction at the effective speed (v^2 + (2u/3)^2)^(1/2) "
               "outside the exact integrals instead")
      ->excludes(inside);

  app.add_option("--profile-smoothing", a.smoothing,
                 "fit the --profile CSV by a Chebyshev series in rho^2 of N terms (noisy film "
                 "data) instead of interpolating it; the fit's residual is reported")
      ->check(CLI::Range(1, 64));
  app.add_flag("--profile-clip", a.profile_clip,
               "clip a --profile CSV that dips below zero at zero (otherwise refused)");
  app.add_flag("--progress", a.progress,
               "closed loop: a line per stage on stderr with the time so far (the default on "
               "a terminal)");
  app.add_flag("--verbose", verbose, "show the solver's own log (Ceres, glog) on stderr");
  // Testing only (hidden): the residual of this data point fails to evaluate.
  app.add_option("--test-failing-point", a.failing_point)->group("");

  SimulateArgs sim;
  auto* simulate =
      app.add_subcommand("simulate", "write synthetic diagrams in the same CSV format");
  simulate->add_option("--out", sim.out, "output CSV")->required();
  simulate->add_option("--radius", sim.radius, "patch radius R [m]");
  simulate->add_option("--profile", sim.profile, "CSV rho,pressure_Pa or uniform|hertz|seed-tire");
  simulate->add_option("--pressure", sim.pressure, "reference pressure p* [Pa] (built-in profile)");
  simulate->add_option("--friction", sim.friction, "friction coefficient f");
  simulate->add_option("--kx", sim.kx, "pressure shift along x");
  simulate->add_option("--ky", sim.ky, "pressure shift along y");
  simulate->add_option("--kappa", sim.kappa, "lateral/longitudinal friction ratio");
  simulate->add_option("--model", sim.model, "exact integrals or fractional law")
      ->check(CLI::IsMember({"exact", "fractional"}));
  simulate->add_option("--points", sim.spec.points, "number of points");
  simulate->add_option("--psi-min", sim.spec.psi_min, "smallest psi = v/(omega R)");
  simulate->add_option("--psi-max", sim.spec.psi_max, "largest psi");
  simulate->add_option("--spin-speed", sim.spec.spin_speed_mps, "u = omega R [m/s]");
  simulate->add_option("--direction", sim.spec.direction_rad, "sliding direction [rad]");
  simulate
      ->add_option("--directions", sim.directions,
                   "several sweeps, one per sliding direction [rad], e.g. 0,1.5708")
      ->delimiter(',');
  simulate->add_option("--noise", sim.noise,
                       "none|relative-uniform|relative-gaussian|additive-gaussian");
  simulate->add_option("--noise-level", sim.spec.noise_level, "noise amplitude (relative)");
  simulate->add_option("--seed", sim.spec.seed, "random seed");
  simulate->add_option("--time-step", sim.spec.time_step_s, "t_s step between points [s]");
  simulate->add_option("--speed-drop", sim.speed_drop,
                       "friction falls by this fraction with slip speed (inside the integrals)");
  simulate->add_option("--speed-ref", sim.speed_ref, "reference slip speed w_s [m/s]");
  simulate->add_option("--offset", sim.offset, "channel offsets Fx,Fy,Mz [N, N, N m]")
      ->delimiter(',')
      ->expected(3);
  simulate->add_option("--crosstalk", sim.crosstalk,
                       "a channel picks up another, e.g. Mz_Nm<-Fx_N=0.002 (repeatable)");
  simulate->add_option("--periodic", sim.spec.rig.periodic_amplitude_n,
                       "a periodic disturbance of Fy in time [N] (outside the catalogue)");

  app::prepare_output();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (effective_speed) a.speed_inside = false;
  // Ceres logs through glog: quiet unless asked for.
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = verbose ? google::GLOG_INFO : google::GLOG_FATAL;
  google::InitGoogleLogging(argv[0]);
  try {
    if (simulate->parsed()) return app::finish_output(run_simulate(sim));
    if (a.data_path.empty()) throw std::runtime_error("no data file given (see --help)");
    if (radius_opt->count() == 0)
      throw std::runtime_error("--radius is required (patch radius in m)");
    if (a.pressure && a.profile_spec.empty())
      throw std::runtime_error("--pressure " + format_value(*a.pressure) +
                               " is the reference pressure of a built-in --profile (uniform, "
                               "hertz, seed-tire); give one, or the load as --normal-load");
    std::optional<app::OutputFolderLock> lock;
    if (!a.plots_dir.empty()) lock.emplace(a.plots_dir);  // before the fit: a second run stops
    const int status = run_fit(a);
    if (lock && status == 0) lock->commit();  // an earlier run's plots not redrawn are removed
    return app::finish_output(status);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
    return 1;
  }
}
