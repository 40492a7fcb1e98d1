// contensou-fmu: writes Functional Mock-up Units (FMI 2.0, or 3.0 with --fmi 3) of contensou
// (docs/fmu.md).
//   contensou-fmu law --out law.fmu --radius 0.087 --pressure 2.1e5 --profile seed-tire
//                     --friction 0.3 [--kx 0.14] [--law exact|fractional] [--tolerance 1e-8]
//   contensou-fmu gear --out gear.fmu
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli.hpp"
#include "contensou/fmu/fmu_export.hpp"
#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "run_guard.hpp"

namespace {

using namespace contensou;

struct LawArguments {
  std::string out, profile = "uniform", law = "exact", model_name = "contensou_law";
  std::string profile_name;  // how the model description names a CSV profile (else its path)
  std::optional<double> radius, load, pressure, friction;
  std::vector<double> slip_speed;
  int fmi = 2;
  double kappa = 1.0, kx = 0.0, ky = 0.0, tolerance = 1e-8;
  bool clip_negative = false, keep_negative = false;
};

// "cosine:W:a0,a1,..." -> the cosine series p = sum a_k cos(pi k W rho) (seed eq. 8).
PressureProfile cosine_profile(const std::string& spec) {
  const std::string body = spec.substr(7);
  const std::size_t colon = body.find(':');
  if (colon == std::string::npos)
    throw InvalidArgument("--profile", spec, "a cosine series is cosine:W:a0,a1,...");
  std::vector<double> a;
  std::stringstream list(body.substr(colon + 1));
  for (std::string item; std::getline(list, item, ',');) {
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != item.size() || item.empty())
      throw InvalidArgument("--profile", spec, "'" + item + "' is not a number");
    a.push_back(v);
  }
  std::size_t used = 0;
  double w = 0.0;
  try {
    w = std::stod(body.substr(0, colon), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != colon || colon == 0)
    throw InvalidArgument("--profile", spec, "the frequency W of cosine:W:a0,... is not a number");
  return cosine_series_profile(w, a);
}

// The profile and, for a measured one (a CSV file), its reference pressure (of the table
// clipped at zero with `clip`).
PressureProfile profile_of(const std::string& spec, bool clip,
                           std::optional<double>& file_pressure) {
  if (spec == "uniform") return uniform_profile();
  if (spec == "hertz") return hertz_profile();
  if (spec == "seed-tire") return seed_tire_profile();
  if (spec.rfind("cosine:", 0) == 0) return cosine_profile(spec);
  if (spec.size() > 4 && spec.substr(spec.size() - 4) == ".csv") {
    MeasuredProfile m = read_profile_csv(spec, clip);
    file_pressure = m.reference_pressure_pa;
    return m.profile;
  }
  throw InvalidArgument("--profile", spec,
                        "uniform, hertz, seed-tire, cosine:W:a0,a1,... or a CSV file (rho, "
                        "pressure_Pa)");
}

// Every number given on the command line finite, named by its option (the library's own checks
// then name the patch's field).
void require_finite_options(const LawArguments& a) {
  const std::pair<const char*, std::optional<double>> given[] = {{"--radius", a.radius},
                                                                 {"--load", a.load},
                                                                 {"--pressure", a.pressure},
                                                                 {"--friction", a.friction},
                                                                 {"--kappa", a.kappa},
                                                                 {"--kx", a.kx},
                                                                 {"--ky", a.ky},
                                                                 {"--tolerance", a.tolerance}};
  for (const auto& [name, value] : given)
    if (value) require_finite(name, *value);
  for (double v : a.slip_speed) require_finite("--slip-speed-friction", v);
}

// The patch of the options; `scaled` says how a CSV profile's pressures were scaled to carry
// --load ("" when they are taken as the file gives them).
ContactPatch patch_of(const LawArguments& a, std::string& scaled) {
  require_finite_options(a);
  std::optional<double> file_pressure;
  PressureProfile profile = profile_of(a.profile, a.clip_negative, file_pressure);
  if (file_pressure && a.pressure)
    throw InvalidArgument(
        "--pressure", format_value(*a.pressure) + " Pa",
        "a CSV profile gives the pressures in Pa (its mean p* = " + format_value(*file_pressure) +
            " Pa): --pressure would rescale the measured table. Leave it out, "
            "or give --load N to carry another load with the table's shape");
  profile.kx = a.kx;
  profile.ky = a.ky;
  profile.clip_negative = profile.clip_negative || a.clip_negative;
  profile.keep_negative = profile.keep_negative || a.keep_negative;
  if (a.friction.has_value() == !a.slip_speed.empty())
    throw InvalidArgument("--friction, --slip-speed-friction", "both or neither",
                          "give one: a constant f, or f_s,f_k,w_s,delta");
  if (!a.slip_speed.empty() && a.slip_speed.size() != 4)
    throw InvalidArgument("--slip-speed-friction", std::to_string(a.slip_speed.size()) + " values",
                          "takes four: f_s,f_k,w_s,delta");
  if (a.load && a.pressure)
    throw InvalidArgument("--load, --pressure", "both", "give one of the two");
  if (!a.load && !a.pressure && !file_pressure)
    throw InvalidArgument("--load, --pressure", "neither",
                          "give the normal load N [N] or the reference pressure p* [Pa]");
  const double radius = a.radius.value_or(ContactPatch::kUnset);
  const double f = a.friction.value_or(a.slip_speed.empty() ? 0.0 : a.slip_speed[0]);
  ContactPatch patch;
  if (a.load) {
    patch = ContactPatch::from_normal_load(radius, *a.load, profile, f, a.kappa);
  } else {
    patch.radius_m = radius;
    patch.reference_pressure_pa = a.pressure.value_or(file_pressure.value_or(0.0));
    patch.friction = f;
    patch.kappa = a.kappa;
    patch.profile = profile;
  }
  if (file_pressure && a.load)
    scaled = ", the profile file's pressures x " +
             format_value(patch.reference_pressure_pa / *file_pressure) + " to carry it";
  if (!a.slip_speed.empty())
    patch.slip_speed_friction = SlipSpeedFriction<double>{a.slip_speed[0], a.slip_speed[1],
                                                          a.slip_speed[2], a.slip_speed[3]};
  validate(patch);
  return patch;
}

void add_law_options(CLI::App& law, LawArguments& a) {
  law.add_option("--out,-o", a.out, "the .fmu to write")->required();
  law.add_option("--radius", a.radius, "patch radius R [m]")->required();
  law.add_option("--load", a.load, "normal load N [N] (or --pressure)");
  law.add_option("--pressure", a.pressure, "reference pressure p* [Pa] (or --load)");
  law.add_option("--profile", a.profile,
                 "pressure profile: uniform, hertz, seed-tire, cosine:W:a0,a1,... or a CSV "
                 "file with columns rho, pressure_Pa (then p* is its mean pressure)")
      ->capture_default_str();
  law.add_option("--friction", a.friction, "friction coefficient f");
  law.add_option("--slip-speed-friction", a.slip_speed,
                 "f(w) = f_k + (f_s - f_k) exp(-(w/w_s)^delta): f_s,f_k,w_s,delta (exact law)")
      ->delimiter(',');
  law.add_option("--kappa", a.kappa, "lateral / longitudinal friction ratio")
      ->capture_default_str();
  law.add_option("--kx", a.kx, "pressure shift along x (0.14: the seed's rolling tire)");
  law.add_option("--ky", a.ky, "pressure shift along y");
  law.add_flag("--clip-negative", a.clip_negative, "clip a negative part of the profile to 0");
  law.add_flag("--keep-negative", a.keep_negative, "keep a negative part of the profile as given");
  law.add_option("--law", a.law, "exact (tables of the exact integrals) or fractional")
      ->check(CLI::IsMember({"exact", "fractional"}))
      ->capture_default_str();
  law.add_option("--tolerance", a.tolerance,
                 "the exact law's accuracy relative to f N and f N R, in (1e-14, 1e-2)")
      ->capture_default_str();
  law.add_option("--model-name", a.model_name, "modelName in modelDescription.xml")
      ->capture_default_str();
  law.add_option("--profile-name", a.profile_name,
                 "how the model description names a CSV profile (default: the file's path)");
  law.add_option("--fmi", a.fmi, "the standard: 2 (FMI 2.0) or 3 (FMI 3.0)")
      ->check(CLI::IsMember({2, 3}))
      ->capture_default_str();
}

void print(const fmu::FmuExport& e, const char* what) {
  std::printf("%s: %s (%zu bytes, guid %s)\n", what, e.path.c_str(), e.bytes, e.guid.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "Writes Functional Mock-up Units (FMI 2.0, Model Exchange and Co-Simulation) of "
      "the friction law of a contact patch and of the landing gear (docs/fmu.md)"};
  app.require_subcommand(1);
  LawArguments a;
  CLI::App* law = app.add_subcommand("law",
                                     "the friction law of a patch: vx, vy, omega, N in; "
                                     "Fx, Fy, Mz out");
  add_law_options(*law, a);
  std::string gear_out;
  int gear_fmi = 2;
  CLI::App* gear = app.add_subcommand("gear",
                                      "the shimmy demo's landing gear (Co-Simulation, "
                                      "CVODE inside)");
  gear->add_option("--out,-o", gear_out, "the .fmu to write")->required();
  gear->add_option("--fmi", gear_fmi, "the standard: 2 (FMI 2.0) or 3 (FMI 3.0)")
      ->check(CLI::IsMember({2, 3}))
      ->capture_default_str();
  contensou::app::add_conventions(app, "contensou-fmu");
  contensou::app::prepare_output();
  if (const std::optional<int> status = contensou::app::parse(app, argc, argv)) return *status;
  try {
    if (law->parsed()) {
      std::string scaled;
      const ContactPatch patch = patch_of(a, scaled);
      fmu::LawFmuOptions o;
      o.law = a.law == "exact" ? fmu::FmuLaw::exact : fmu::FmuLaw::fractional;
      o.tolerance = a.tolerance;
      o.model_name = a.model_name;
      o.fmi_version = a.fmi;
      o.profile_text = a.profile.size() > 4 && a.profile.substr(a.profile.size() - 4) == ".csv"
                           ? describe(patch.profile) + " from " +
                                 (a.profile_name.empty() ? a.profile : a.profile_name)
                           : "";
      const fmu::FmuExport e = fmu::export_law_fmu(patch, a.out, o);
      print(e, "law FMU");
      std::printf("patch: R = %g m, N = %g N%s; %s law", patch.radius_m, normal_load(patch),
                  scaled.c_str(), a.law.c_str());
      if (o.law == fmu::FmuLaw::exact)
        std::printf(", tables in %.2f s, %zu bytes, within %.2g of f N and f N R", e.build_s,
                    e.table_bytes, e.error_bound);
      std::printf("\n");
    } else if (gear->parsed()) {
      print(fmu::export_gear_fmu(gear_out, gear_fmi), "gear FMU");
    }
    return contensou::app::finish_output(contensou::app::kExitSuccess);
  } catch (const std::exception& e) {
    std::cerr << "contensou-fmu: " << e.what() << "\n";
    return contensou::app::kExitFailure;
  }
}
