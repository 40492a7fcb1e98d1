// contensou-identify: fit the fractional law to measured friction diagrams (and simulate them).
#include <unistd.h>

#include <glog/logging.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>

#include "cli.hpp"
#include "contensou/contensou.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/held_out.hpp"
#include "contensou/identification/identify.hpp"
#include "contensou/identification/identify_request.hpp"
#include "contensou/identification/model_file.hpp"
#include "contensou/identification/prediction.hpp"
#include "contensou/identification/report.hpp"
#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"
#include "gnuplot.hpp"
#include "report.hpp"
#include "run_guard.hpp"
#include "test_seams.hpp"  // the hidden --test-failing-point

using namespace contensou;

namespace {

constexpr const char* kName = "contensou-identify";

// The bounds of `simulate`: at most this many points in all (the directions' sweeps together),
// refused before any work; a million rows is a long rig recording, and the file it writes
// (about 72 bytes a row) is read back by every reader well within their limits.
constexpr long long kMaxSimulatedPoints = 1'000'000;
constexpr std::size_t kMaxDirections = 1000;

// Runs `f`; memory exhausted becomes an error naming what was being done ("fitting the 1000000
// rows of big.csv"), not a bare std::bad_alloc.
template <class F>
auto within_memory(const std::string& what, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const std::bad_alloc&) {
    throw std::runtime_error("out of memory " + what +
                             ": too large for this machine's memory (or its limit, ulimit -v)");
  }
}

// A finite number in [lo, hi], or an error naming the option, the value and the range.
void require_in(const std::string& option, double v, double lo, double hi,
                const std::string& unit = "") {
  if (v >= lo && v <= hi) return;
  throw InvalidArgument(option, format_value(v),
                        "must lie in [" + format_value(lo) + ", " + format_value(hi) + "]" +
                            (unit.empty() ? "" : " " + unit));
}

// A number from the text of an option's value, or a usage error naming the option.
double number_of(const std::string& option, const std::string& text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  if (r.ec == std::errc::result_out_of_range)
    throw InvalidArgument(option, text, "is beyond the range of a double");
  if (r.ec != std::errc() || r.ptr != end)
    throw app::UsageError(option + " " + text + ": '" + text + "' is not a number");
  return v;
}

std::pair<std::string, double> parse_fix(const std::string& s) {
  const auto eq = s.find('=');
  if (eq == std::string::npos || eq == 0)
    throw app::UsageError("--fix " + s + ": expected NAME=VALUE, e.g. --fix a=1.03");
  const std::string value = s.substr(eq + 1);
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size())
    throw app::UsageError("--fix " + s + ": '" + value + "' is not a number");
  if (!std::isfinite(v)) throw InvalidArgument("--fix " + s.substr(0, eq), value, "must be finite");
  return {s.substr(0, eq), v};
}

// What the fit's command line gives besides the request (main binds the options to these).
struct FitArgs {
  IdentifyRequest request;
  std::vector<std::string> data_paths;
  std::string json_path, plots_dir, columns;
  std::vector<double> loads;  // --normal-load: one, or one a file
  std::vector<std::string> fixes;
  bool progress = false;
  std::vector<std::string> validate;  // --validate: files to judge the fits on
  double holdout = 0.0;               // --holdout: the share of rows held out of the fit
  std::string group;                  // --group: the column whose values form the groups
  unsigned holdout_seed = 1;          // --holdout-seed
};

// The data's rows as a file of several files would be read (one file keeps its own name).
MeasuredData read_files(const std::vector<std::string>& paths, const ColumnRenames& renames,
                        const std::vector<double>& loads, bool channels_optional = false) {
  std::vector<MeasuredData> files;
  for (const std::string& path : paths)
    files.push_back(within_memory("reading " + path, [&] {
      return read_measured_csv(path, renames, KeyStyle::command_line, channels_optional);
    }));
  return combine_measured(std::move(files), loads);
}

// The fits judged on the rows held out and on each --validate file (held_out.hpp).
void judge_held_out(const FitArgs& a, const ColumnRenames& renames,
                    const std::optional<HoldoutSplit>& split, IdentifyRun& run) {
  const Identification& r = run.result;
  const ClosedLoopReport* loop = r.loop ? &*r.loop : nullptr;
  if (split) {
    char name[200];
    std::snprintf(name, sizeof name,
                  "held out: %.3g %% of the rows (%d of %d groups by %s, seed %u)",
                  100.0 * a.holdout, split->held_groups, split->groups, split->grouped_by.c_str(),
                  a.holdout_seed);
    run.input.held_out.push_back(judge_on_rows(r.fit, loop, split->held_out, name));
  }
  for (const std::string& path : a.validate) {
    const MeasuredData rows =
        read_files({path}, renames, a.loads.size() == 1 ? a.loads : std::vector<double>{});
    run.input.held_out.push_back(judge_on_rows(r.fit, loop, rows, "validation file " + path));
  }
}

// Progress for people (on a terminal, or with --progress): a line per stage of the loop on
// stderr, each with the time since the loop began; in scripts and pipes stderr keeps errors
// only.
void show_progress(IdentifyRequest& r, bool asked) {
  if (!asked && !isatty(fileno(stderr))) return;
  const auto start = std::chrono::steady_clock::now();
  r.progress = [start](const std::string& line) {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::fprintf(stderr, "[closed loop %7.1f s] %s\n", s, line.c_str());
    std::fflush(stderr);
  };
}

int print_and_write(const FitArgs& a, const MeasuredData& read, const Identification& run,
                    const ReportInput& info, app::OutputFolder* plots) {
  const MeasuredData& data = run.fitted;
  const app::PlotInput shown{read, run.outliers, run.origin, a.request.radius_m};
  if (!run.loop) {
    std::printf("%s %s: fractional law (seed eqs. 5-7)\n%s", kName, kVersion,
                fit_report_text_with_cautions(info, run.fit).c_str());
    if (plots != nullptr && app::write_plots(app::OutputDir(*plots), shown, run.fit))
      std::printf("pictures: %s/fit_*.png\n", a.plots_dir.c_str());
    if (!a.json_path.empty()) {
      app::write_output_file(plots, a.json_path, fit_report_json(info, run.fit) + "\n");
      std::printf("report: %s\n", a.json_path.c_str());
    }
    return 0;
  }
  const ClosedLoopReport& loop = *run.loop;
  std::printf("%s %s\n%s", kName, kVersion, loop_report_text(info, loop).c_str());
  if (plots != nullptr) {
    const bool p = app::write_plots(app::OutputDir(*plots), shown, loop.final_fit);
    const bool q = app::write_loop_plots(app::OutputDir(*plots), data, loop);
    if (p && q)
      std::printf("pictures: %s/fit_*.png (final model), %s/loop_step_*.png\n", a.plots_dir.c_str(),
                  a.plots_dir.c_str());
  }
  if (!a.json_path.empty()) {
    app::write_output_file(plots, a.json_path, loop_report_json(info, loop) + "\n");
    std::printf("report: %s\n", a.json_path.c_str());
  }
  return 0;
}

int run_fit(FitArgs a, app::OutputFolder* plots) {
  for (const std::string& f : a.fixes) {
    const auto [name, value] = parse_fix(f);
    const std::vector<std::string> names = {"F0_N", "a", "M0_Nm", "m", "kx"};
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      const std::string close = closest_name(names, name);
      throw app::UsageError("--fix " + name + ": no such parameter (use F0_N, a, M0_Nm, m or kx" +
                            (close.empty() ? ")" : "; did you mean " + close + "?)"));
    }
    const auto [it, inserted] = a.request.fix.emplace(name, value);
    if (!inserted)
      throw app::UsageError("--fix " + name + " given twice (" + format_value(it->second) +
                            " and " + format_value(value) + "): fix each parameter once");
  }
  show_progress(a.request, a.progress);
  // One load: the request's N (F0 and M0 are at it). One a file: each file's rows at theirs.
  if (a.loads.size() == 1) a.request.normal_load_n = a.loads.front();
  if (a.loads.size() > 1 && a.loads.size() != a.data_paths.size())
    throw app::UsageError("--normal-load: " + std::to_string(a.loads.size()) + " values for " +
                          std::to_string(a.data_paths.size()) +
                          " files: give one load, or one a file in the files' order");
  validate(a.request);  // the options' ranges before the data are read
  const ColumnRenames renames = parse_column_renames(a.columns);
  MeasuredData data =
      read_files(a.data_paths, renames, a.loads.size() > 1 ? a.loads : std::vector<double>{});
  std::optional<HoldoutSplit> split;
  if (a.holdout > 0.0) {
    split = holdout_split(data, a.request.radius_m, a.holdout, a.group, a.holdout_seed);
    data = split->fit;
  } else if (!a.group.empty()) {
    throw app::UsageError("--group " + a.group +
                          " needs --holdout (the share of rows to hold out)");
  }
  IdentifyRun run =
      within_memory("fitting the " + std::to_string(data.points.size()) + " rows of " + data.source,
                    [&] { return identify(data, a.request); });
  within_memory("judging the fits on rows they never saw",
                [&] { judge_held_out(a, renames, split, run); });
  return within_memory("writing the report",
                       [&] { return print_and_write(a, data, run.result, run.input, plots); });
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
  std::vector<double> loads;  // --normal-load: the sweeps at each load, an Fz_N column
  std::vector<std::string> crosstalk;
  std::string seed = "1";  // read here: CLI11 would clamp 2^64 to 2^64 - 1 without a word
};

// The seed: a whole number in [0, 2^64 - 1].
std::uint64_t parse_seed(const std::string& text) {
  std::uint64_t v = 0;
  const char* end = text.data() + text.size();
  const auto r = std::from_chars(text.data(), end, v);
  if (r.ec == std::errc::result_out_of_range)
    throw InvalidArgument("--seed", text, "must lie in [0, 18446744073709551615] (2^64 - 1)");
  if (r.ec != std::errc() || r.ptr != end)
    throw app::UsageError("--seed " + text +
                          ": not a whole number (one in [0, 18446744073709551615])");
  return v;
}

// The patch's options, each within its range (finite answers: the forces stay far from
// overflow); the shift and the profile are checked by validate(ContactPatch).
void check_patch_options(const SimulateArgs& a) {
  require_in("--radius", a.radius, 1e-9, 1e3, "m");
  if (a.pressure) require_in("--pressure", *a.pressure, 1e-3, 1e12, "Pa");
  require_in("--friction", a.friction, 1e-9, 100.0, "(a friction coefficient)");
  require_in("--kx", a.kx, -1.0, 1.0);
  require_in("--ky", a.ky, -1.0, 1.0);
  require_in("--kappa", a.kappa, 1e-3, 1e3);
  require_in("--speed-drop", a.speed_drop, -0.9, 0.95);
  require_in("--speed-ref", a.speed_ref, 1e-3, 1e6, "m/s");
}

// The sweep's options, each within its range, and the size of the run before it starts.
void check_sweep_options(const SimulateArgs& a) {
  const DiagramSpec& s = a.spec;
  require_in("--points", s.points, 1, static_cast<double>(kMaxSimulatedPoints));
  if (a.directions.size() > kMaxDirections)
    throw InvalidArgument("--directions", std::to_string(a.directions.size()) + " directions",
                          "at most " + std::to_string(kMaxDirections));
  if (a.loads.size() > kMaxDirections)
    throw InvalidArgument("--normal-load", std::to_string(a.loads.size()) + " loads",
                          "at most " + std::to_string(kMaxDirections));
  for (double n : a.loads) require_in("--normal-load", n, 1e-3, 1e9, "N");
  const long long total = static_cast<long long>(s.points) *
                          static_cast<long long>(std::max<std::size_t>(1, a.directions.size())) *
                          static_cast<long long>(std::max<std::size_t>(1, a.loads.size()));
  if (total > kMaxSimulatedPoints)
    throw InvalidArgument("--points x --directions x --normal-load",
                          std::to_string(total) + " points",
                          "at most " + std::to_string(kMaxSimulatedPoints) + " in all");
  require_in("--psi-min", s.psi_min, 1e-9, 1e9);
  require_in("--psi-max", s.psi_max, s.psi_min, 1e9, "(from --psi-min)");
  require_in("--spin-speed", s.spin_speed_mps, 1e-9, 1e4, "m/s");
  require_in("--direction", s.direction_rad, -1e3, 1e3, "rad");
  for (double d : a.directions) require_in("--directions", d, -1e3, 1e3, "rad");
  require_in("--noise-level", s.noise_level, 0.0, 100.0);
  require_in("--noise-growth", s.noise_growth, 0.0, 100.0);
  require_in("--time-step", s.time_step_s, 0.0, 1e6, "s (0: no t_s column)");
  for (double o : a.offset) require_in("--offset", o, -1e12, 1e12, "N or N m");
  require_in("--periodic", s.rig.periodic_amplitude_n, -1e12, 1e12, "N");
}

// --crosstalk C<-D=VALUE into the rig's matrix.
void add_crosstalk(const std::string& x, RigEffects& rig) {
  const auto arrow = x.find("<-"), eq = x.find('=');
  int ci = -1, di = -1;
  if (arrow != std::string::npos && eq != std::string::npos && eq > arrow)
    for (int k = 0; k < kChannels; ++k) {
      if (x.substr(0, arrow) == kChannelColumns[k]) ci = k;
      if (x.substr(arrow + 2, eq - arrow - 2) == kChannelColumns[k]) di = k;
    }
  if (ci < 0 || di < 0 || ci == di)
    throw app::UsageError("--crosstalk " + x + ": expected e.g. Mz_Nm<-Fx_N=0.002");
  const double v = number_of("--crosstalk " + x.substr(0, eq), x.substr(eq + 1));
  require_in("--crosstalk " + x.substr(0, eq), v, -10.0, 10.0);
  rig.crosstalk[ci][di] = v;
}

// Every simulated value finite (a last check: the options' ranges are meant to ensure it).
void check_finite(const MeasuredData& d) {
  for (const MeasuredPoint& p : d.points)
    for (int c = 0; c < kChannels; ++c)
      if (p.force[c] && !std::isfinite(*p.force[c]))
        throw std::runtime_error(std::string("the simulated ") + kChannelColumns[c] +
                                 " is not finite: the options are too extreme together");
}

// One sweep a sliding direction, one after another in time.
// The sweeps: each direction in turn, at each load in turn (at fixed radius, the pressure in
// proportion to the load); the time runs on across them.
MeasuredData simulate_sweeps(const SimulateArgs& a, const ContactPatch& base) {
  MeasuredData d;
  const std::vector<std::optional<double>> loads =
      a.loads.empty() ? std::vector<std::optional<double>>{std::nullopt}
                      : std::vector<std::optional<double>>(a.loads.begin(), a.loads.end());
  d.points.reserve(static_cast<std::size_t>(a.spec.points) * a.directions.size() * loads.size());
  const std::uint64_t seed = a.spec.seed;
  std::size_t k = 0;
  for (const std::optional<double>& load : loads) {
    ContactPatch patch = base;
    if (load) patch.reference_pressure_pa *= *load / normal_load(base);
    for (double direction : a.directions) {
      DiagramSpec sweep = a.spec;
      sweep.direction_rad = direction;
      sweep.seed = seed + 1000 * k;
      MeasuredData part = a.model == "exact"
                              ? simulate_diagrams(make_exact_model(patch), sweep)
                              : simulate_diagrams(fractional_law_from_patch(patch), sweep);
      for (MeasuredPoint& point : part.points) {
        if (point.time) *point.time += static_cast<double>(k) * sweep.points * sweep.time_step_s;
        point.normal_load = load;
        d.points.push_back(point);
      }
      ++k;
    }
  }
  return d;
}

int run_simulate(SimulateArgs a) {
  a.spec.seed = parse_seed(a.seed);
  check_patch_options(a);
  check_sweep_options(a);
  a.spec.noise = parse_noise(a.noise);
  for (const std::string& x : a.crosstalk) add_crosstalk(x, a.spec.rig);
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
  // One sweep per sliding direction, one after another in time.
  if (a.directions.empty()) a.directions = {a.spec.direction_rad};
  const long long total = static_cast<long long>(a.spec.points) *
                          static_cast<long long>(a.directions.size()) *
                          static_cast<long long>(std::max<std::size_t>(1, a.loads.size()));
  MeasuredData d = within_memory("simulating " + std::to_string(total) + " points",
                                 [&] { return simulate_sweeps(a, patch); });
  check_finite(d);
  std::ostringstream c;
  c << "simulated by " << kName << " " << kVersion << ": " << a.model << " model, profile "
    << a.profile << ", R = " << a.radius << " m, p* = " << patch.reference_pressure_pa
    << " Pa (N = " << normal_load(patch) << " N), f = " << a.friction << ", kx = " << a.kx
    << ", ky = " << a.ky << ", kappa = " << a.kappa << "\nnoise " << a.noise << " level "
    << a.spec.noise_level;
  if (a.spec.noise == SimulatedNoise::load_cell) c << " growth " << a.spec.noise_growth;
  c << ", seed " << a.spec.seed << ", psi in [" << a.spec.psi_min << ", " << a.spec.psi_max
    << "], u = omega R = " << a.spec.spin_speed_mps << " m/s";
  if (!a.loads.empty()) {
    c << "\nsweeps at N =";
    for (double n : a.loads) c << " " << n;
    c << " N (pressure in proportion, fixed radius; the Fz_N column)";
  }
  within_memory("writing " + std::to_string(total) + " points to " + a.out,
                [&] { write_measured_csv(a.out, d, c.str()); });
  std::printf("wrote %s: %zu points (N = %.1f N)\n", a.out.c_str(), d.points.size(),
              normal_load(patch));
  return 0;
}

// `contensou-identify predict`: a model from a report, the rows of data files, predictions.
struct PredictArgs {
  std::string model, out, columns;
  std::vector<std::string> data_paths;
  std::vector<double> loads;
};

// The whole text of a file, or an error naming it (missing, unreadable, over 1 GB).
std::string file_text(const std::string& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) throw std::runtime_error(path + ": cannot read the model: " + ec.message());
  if (size > (1u << 30)) throw std::runtime_error(path + ": over 1 GB: not a model file");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw std::runtime_error(path + ": cannot read the model");
  return text.str();
}

int run_predict(const PredictArgs& p) {
  const ModelSpec read = model_from_json(file_text(p.model), p.model);
  if (p.loads.size() > 1 && p.loads.size() != p.data_paths.size())
    throw app::UsageError("--normal-load: one load, or one a file in the files' order");
  const MeasuredData data =
      read_files(p.data_paths, parse_column_renames(p.columns), p.loads, true);
  const ModelSpec model = bind_to_data(read, data);
  const std::vector<RowPrediction> pred = within_memory("predicting the rows of " + data.source,
                                                        [&] { return predict_rows(model, data); });
  app::write_output_file(nullptr, p.out, predictions_csv(data, pred));
  std::printf("%s %s predict: the model of %s at the %zu rows of %s\n%s", kName, kVersion,
              p.model.c_str(), data.points.size(), data.source.c_str(),
              prediction_scores_text(score_predictions(data, pred, model.radius_m)).c_str());
  std::printf("predictions: %s\n", p.out.c_str());
  return 0;
}

CLI::App* add_predict_options(CLI::App& app, PredictArgs& p) {
  auto* predict = app.add_subcommand(
      "predict",
      "predict rows with a fitted model, both ways: the force from the motion and the motion "
      "its measured force would cause (the normal of the model's limit surface)");
  predict->add_option("--model", p.model, "the report of a fit (--json), or its \"model\" object")
      ->required();
  predict->add_option("data", p.data_paths, "the rows (CSV, the fit's format; forces optional)")
      ->required();
  predict
      ->add_option("--out", p.out,
                   "the predictions (CSV: the rows, then pred_Fx_N, pred_Fy_N, pred_Mz_Nm, "
                   "pred_twist_vx, pred_twist_vy, pred_twist_omegaR)")
      ->required();
  predict->add_option("--columns", p.columns, "read columns under other names (as for the fit)");
  predict->add_option("--normal-load", p.loads, "the rows' load [N], one or one a file")
      ->delimiter(',');
  return predict;
}

}  // namespace

// The fit's options: the request's keys (identify_request.hpp) with their help from its table,
// and the app's own (files, pictures, progress).
struct FitOptionHandles {
  CLI::Option* radius = nullptr;
  bool effective_speed = false, no_loop = false, no_outliers = false, verbose = false;
};

void add_fit_options(CLI::App& app, FitArgs& a, FitOptionHandles& h) {
  IdentifyRequest& r = a.request;
  const auto opt = [](const char* key) { return key_name(key, KeyStyle::command_line); };
  app.add_option("data", a.data_paths,
                 "measured diagrams (CSV: vx_mps, vy_mps, omega_radps, Fx_N, ...); several files "
                 "are fitted together, each row keeping its file and line");
  h.radius = app.add_option(opt("radius"), r.radius_m, key_help("radius"));
  app.add_option(opt("normal_load"), a.loads,
                 std::string(key_help("normal_load")) +
                     "; with several files, one load a file (N1,N2,...) for their rows without an "
                     "Fz value")
      ->delimiter(',');
  app.add_option(opt("profile"), r.profile, key_help("profile"));
  app.add_option(opt("pressure"), r.pressure_pa, key_help("pressure"));
  app.add_option("--json", a.json_path, "write the report as JSON (whole or not at all)");
  app.add_option("--plots", a.plots_dir, "write pictures (PNG via gnuplot) and their data here");
  app.add_option("--columns", a.columns,
                 "read columns under other names: QUANTITY=COLUMN,... with QUANTITY one of vx, "
                 "vy, omega, Fx, Fy, Mz, Fz, t; a unit in the name ('Speed [km/h]') or a units "
                 "row is converted; extra=COLUMN keeps a column that looks like a channel as a "
                 "recorded variable, ignore=COLUMN leaves it out (every other numeric column is "
                 "kept as a recorded variable and listed in the report)");
  app.add_option(opt("fix"), a.fixes, key_help("fix"));
  app.add_option(opt("loss"), r.loss, key_help("loss"))->check(app::one_of(key_choices("loss")));
  app.add_option(opt("loss_scale"), r.loss_scale, key_help("loss_scale"));
  app.add_option(opt("noise_model"), r.noise_model, key_help("noise_model"))
      ->check(app::one_of(key_choices("noise_model")));
  app.add_option(opt("noise_scale"), r.noise_scale, key_help("noise_scale"))->delimiter(',');
  app.add_flag("--no-loop", h.no_loop, "fit the fractional law only; do not close the loop");
  app.add_option(opt("alpha"), r.alpha, key_help("alpha"));
  auto* inside = app.add_flag(opt("speed_inside_integrals"), r.speed_inside_integrals,
                              key_help("speed_inside_integrals"));
  app.add_flag("--effective-speed", h.effective_speed,
               "closed loop: slip-speed friction at the effective speed (v^2 + (2u/3)^2)^(1/2) "
               "outside the exact integrals instead")
      ->excludes(inside);
  app.add_option(opt("resamples"), r.resamples, key_help("resamples"));
  app.add_flag(opt("admissible_law"), r.admissible_law, key_help("admissible_law"));
  app.add_flag("--no-outliers", h.no_outliers,
               "keep every row in the fit (no search for gross errors)");
  app.add_option(opt("profile_smoothing"), r.profile_smoothing, key_help("profile_smoothing"));
  app.add_flag(opt("profile_clip"), r.profile_clip, key_help("profile_clip"));
  app.add_option("--validate", a.validate,
                 "judge the fits on these files, which they never saw: each model's error there "
                 "and its predictions both ways (the force from the motion, the motion from the "
                 "force)");
  app.add_option("--holdout", a.holdout,
                 "hold this share of the rows, in (0, 0.9], out of every fit (whole sweeps, or "
                 "whole groups of --group, drawn at random) and judge the fits on them, each loop "
                 "step included")
      ->check(CLI::Range(0.0, 0.9));
  app.add_option("--group", a.group,
                 "with --holdout: the recorded column whose values form the groups held out "
                 "together (a test run, a specimen)");
  app.add_option("--holdout-seed", a.holdout_seed, "with --holdout: the random draw's seed");
  app.add_flag("--progress", a.progress,
               "closed loop: a line per stage on stderr with the time so far (the default on "
               "a terminal)");
  app.add_flag("--verbose", h.verbose, "show the solver's own log (Ceres, glog) on stderr");
  // Testing only (hidden): the residual of this data point fails to evaluate.
  app.add_option("--test-failing-point", testing::Seams::of(r).failing_point)->group("");
}

// The options of `contensou-identify simulate`.
CLI::App* add_simulate_options(CLI::App& app, SimulateArgs& sim) {
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
      ->check(app::one_of({"exact", "fractional"}));
  simulate->add_option(
      "--points", sim.spec.points,
      "number of points (at most " + std::to_string(kMaxSimulatedPoints) + " in all directions)");
  simulate->add_option("--psi-min", sim.spec.psi_min, "smallest psi = v/(omega R)");
  simulate->add_option("--psi-max", sim.spec.psi_max, "largest psi");
  simulate->add_option("--spin-speed", sim.spec.spin_speed_mps, "u = omega R [m/s]");
  simulate->add_option("--direction", sim.spec.direction_rad, "sliding direction [rad]");
  simulate
      ->add_option("--directions", sim.directions,
                   "several sweeps, one per sliding direction [rad], e.g. 0,1.5708")
      ->delimiter(',');
  simulate
      ->add_option("--normal-load", sim.loads,
                   "the sweeps at each of these normal loads [N], e.g. 3000,4500,6000 (pressure "
                   "in proportion to the load at fixed radius; writes an Fz_N column)")
      ->delimiter(',');
  simulate
      ->add_option("--noise", sim.noise,
                   "none|relative-uniform|relative-gaussian|additive-gaussian|load-cell")
      ->check(app::one_of(
          {"none", "relative-uniform", "relative-gaussian", "additive-gaussian", "load-cell"}));
  simulate->add_option("--noise-level", sim.spec.noise_level,
                       "noise amplitude (relative; of the channel's peak for additive-gaussian "
                       "and the constant part a of load-cell)");
  simulate->add_option("--noise-growth", sim.spec.noise_growth,
                       "load-cell noise: sigma = level max|y| + growth |y|");
  simulate->add_option("--seed", sim.seed, "random seed, a whole number in [0, 2^64 - 1]");
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

  return simulate;
}

int main(int argc, char** argv) {
  CLI::App app{
      "Fits the coupled dry-friction law (Kireenkov & Zhavoronok 2020, eqs. 5-7) to measured\n"
      "diagrams Fx, Fy, Mz against the sliding velocity and spin (CSV, theory.md section 6),\n"
      "and reports the parameters with 95 % confidence intervals."};
  app::add_conventions(app, kName);
  FitArgs a;
  a.request.style = KeyStyle::command_line;
  FitOptionHandles h;
  add_fit_options(app, a, h);

  SimulateArgs sim;
  CLI::App* simulate = add_simulate_options(app, sim);
  PredictArgs pred;
  CLI::App* predict = add_predict_options(app, pred);

  app::prepare_output();
  if (const std::optional<int> status = app::parse(app, argc, argv)) return *status;
  if (h.effective_speed) a.request.speed_inside_integrals = false;
  if (h.no_loop) a.request.loop = false;
  if (h.no_outliers) a.request.outliers = false;
  // Ceres logs through glog: quiet unless asked for.
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = h.verbose ? google::GLOG_INFO : google::GLOG_FATAL;
  google::InitGoogleLogging(argv[0]);
  try {
    if (simulate->parsed()) return app::finish_output(run_simulate(sim));
    if (predict->parsed()) return app::finish_output(run_predict(pred));
    if (a.data_paths.empty()) throw app::UsageError("no data file given (see --help)");
    if (h.radius->count() == 0) throw app::UsageError("--radius is required (patch radius in m)");
    std::optional<app::OutputFolder> plots;
    if (!a.plots_dir.empty()) plots.emplace(a.plots_dir);  // before the fit: a second run stops
    const int status = run_fit(a, plots ? &*plots : nullptr);
    if (plots && status == 0) plots->commit();  // an earlier run's plots not redrawn are removed
    return app::finish_output(status);
  } catch (const app::UsageError& e) {
    std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
    return app::kExitUsage;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "%s: error: out of memory (the machine's memory or ulimit -v)\n", kName);
    return app::kExitFailure;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: error: %s\n", kName, e.what());
    return app::kExitFailure;
  }
}
