#include "contensou/identification/identify_request.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/identification/effect_model.hpp"
#include "test_seams.hpp"

namespace contensou {

const std::vector<RequestKey>& identify_request_keys() {
  static const std::vector<RequestKey> keys = {
      {"radius", "patch radius R [m] (required)"},
      {"normal_load",
       "normal load N [N]: f = F0/N is reported, at this load (else N is the mean of an Fz "
       "column, or comes from the profile with its pressure; rows with an Fz value are each "
       "fitted at their own load); with a profile, the profile gives only the shape"},
      {"profile",
       "pressure profile: uniform, hertz, seed-tire or a CSV rho,pressure_Pa (fixes "
       "the shape constants; a CSV, or a built-in one with its pressure, gives N when the rows "
       "carry no Fz)"},
      {"pressure", "reference pressure p* [Pa] of a built-in profile"},
      {"profile_smoothing",
       "fit the profile CSV by a Chebyshev series in rho^2 of this many "
       "terms (noisy film data) instead of interpolating it"},
      {"profile_clip", "clip a profile CSV that dips below zero at zero (otherwise refused)"},
      {"fix", "hold parameters fixed: NAME=VALUE (F0_N, a, M0_Nm, m, kx)"},
      {"loss", "robust loss: none, huber or cauchy"},
      {"loss_scale", "robust loss threshold, in noise scales"},
      {"noise_model",
       "noise: auto (one constant scale per channel, or a + b|y| per channel when the closed "
       "loop's test prefers it; without the loop, constant), additive (constant per channel), "
       "relative, or affine (a + b|y| per channel, as load cells)"},
      {"noise_scale", "given noise scales Fx, Fy, Mz [N, N, N m] (else estimated)"},
      {"loop", "close the loop (else fit the fractional law only)"},
      {"alpha",
       "closed loop: family-wise level of the likelihood-ratio test per step, in "
       "[1e-12, 0.5]"},
      {"speed_inside_integrals",
       "closed loop: slip-speed friction at the local slip speed "
       "inside the exact integrals (else at an effective speed)"},
      {"outliers", "find gross errors (glitched rows) and leave them out of the fit"},
      {"admissible_law",
       "hold the law's a, m and M0 / (F0 R) together to what a non-negative pressure on the patch "
       "gives (a m <= 16 and the torque ratio's range; a <= 4 and m >= 4 always hold): the law is "
       "then one some patch produces"},
      {"resamples",
       "closed loop: run the loop again on this many subsamples of about 80 % of the rows "
       "(whole sweeps), in [0, 100]; an effect accepted in fewer than 80 % of them is reported "
       "unstable and left out of the model (0: no resampling)"},
  };
  return keys;
}

const char* key_help(std::string_view key) {
  for (const RequestKey& k : identify_request_keys())
    if (key == k.key) return k.help;
  throw std::logic_error("no identification key '" + std::string(key) + "'");
}

const std::vector<std::string>& key_choices(std::string_view key) {
  static const std::vector<std::string> loss = {"none", "huber", "cauchy"};
  static const std::vector<std::string> noise = {"auto", "additive", "relative", "affine"};
  static const std::vector<std::string> none;
  if (key == "loss") return loss;
  if (key == "noise_model") return noise;
  return none;
}

namespace {

// Keys that name a choice among words: the value must be one of them.
void require_one_of(const std::string& name, const std::string& value,
                    const std::vector<std::string>& words) {
  if (std::find(words.begin(), words.end(), value) != words.end()) return;
  std::string list;
  for (const std::string& w : words) list += (list.empty() ? "" : ", ") + w;
  throw InvalidArgument(name, value, "must be one of " + list);
}

// A fixed parameter: a name of the fit's, a value within the fit's bounds for it (the bounds the
// free parameter keeps, effect_model.cpp).
void check_fix(const std::string& key, const std::string& name, double value) {
  const int i = parameter_index_by_name(name);
  if (i < 0 || i > kKx)
    throw InvalidArgument(key, name + "=" + format_value(value),
                          "unknown parameter (use F0_N, a, M0_Nm, m or kx)");
  if (!std::isfinite(value))
    throw InvalidArgument(key + " " + name, format_value(value), "must be finite");
  const ParameterBounds b = parameter_bounds(i);
  if (!(value >= b.lower && value <= b.upper))
    throw InvalidArgument(key + " " + name, format_value(value),
                          "must lie in [" + format_value(b.lower) + ", " + format_value(b.upper) +
                              "]" +
                              (i == kKx       ? " (|kx| >= 1 makes the pressure negative)"
                               : i == kA      ? " (a <= 4 for any non-negative pressure)"
                               : i == kMShape ? " (m >= 4 for any non-negative pressure)"
                                              : ""));
}

}  // namespace

// The checks that involve more than one key, and the ranges of single keys.
void validate(const IdentifyRequest& r) {
  const auto key = [&](std::string_view k) { return key_name(k, r.style); };
  require_positive(key("radius").c_str(), r.radius_m);
  if (r.normal_load_n) require_positive(key("normal_load").c_str(), *r.normal_load_n);
  if (r.normal_load_n && r.pressure_pa)
    throw std::invalid_argument("give " + key("normal_load") + " or " + key("pressure") +
                                ", not both (with the profile, either gives the other)");
  if (r.pressure_pa && r.profile.empty())
    throw std::invalid_argument(key("pressure") + " " + format_value(*r.pressure_pa) +
                                " is the reference pressure of a built-in " + key("profile") +
                                " (uniform, hertz, seed-tire); give one, or the load as " +
                                key("normal_load"));
  if (r.pressure_pa) require_positive(key("pressure").c_str(), *r.pressure_pa);
  if (r.profile_smoothing < 0 || r.profile_smoothing > 64)
    throw InvalidArgument(key("profile_smoothing"), std::to_string(r.profile_smoothing),
                          "must lie in [0, 64]");
  if (r.profile_smoothing > 0 && (r.profile.empty() || !std::filesystem::exists(r.profile)))
    throw std::invalid_argument(key("profile_smoothing") + " needs " + key("profile") +
                                " with a CSV file");
  require_one_of(key("loss"), r.loss, key_choices("loss"));
  require_positive(key("loss_scale").c_str(), r.loss_scale);
  require_one_of(key("noise_model"), r.noise_model, key_choices("noise_model"));
  if (r.noise_model == "affine" && !r.noise_scale.empty())
    throw std::invalid_argument(key("noise_scale") + " gives constant scales: use " +
                                key("noise_model") + " additive or relative with it");
  if (!r.noise_scale.empty() && r.noise_scale.size() != kChannels)
    throw std::invalid_argument(key("noise_scale") + " needs three values: Fx, Fy, Mz");
  // Scales in [1e-12, 1e12] (N, N m) keep chi^2 and the criteria finite for forces in the fit's
  // range (1e-6 to 1e8 N): a scale of 1e-300 would make chi^2 overflow to inf.
  for (double s : r.noise_scale)
    if (!(s >= 1e-12 && s <= 1e12))
      throw InvalidArgument(key("noise_scale"), format_value(s), "must lie in [1e-12, 1e12]");
  if (!(r.alpha >= 1e-12 && r.alpha <= 0.5))
    throw InvalidArgument(key("alpha"), format_value(r.alpha), "must lie in [1e-12, 0.5]");
  for (const auto& [name, value] : r.fix) check_fix(key("fix"), name, value);
  if (r.resamples < 0 || r.resamples > 100)
    throw InvalidArgument(key("resamples"), std::to_string(r.resamples), "must lie in [0, 100]");
}

namespace {

// The profile as named, and N from it when its pressure is known.
std::optional<double> load_from_profile(const IdentifyRequest& r, ProfileChoice& profile) {
  if (r.profile.empty()) return std::nullopt;
  try {
    profile = choose_profile(r.profile, r.profile_smoothing, r.profile_clip, r.style);
  } catch (const ParseError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a missing file or a refused table: bad input
  }
  if (r.normal_load_n) return r.normal_load_n;  // the load given: the profile gives the shape
  const std::optional<double> ps =
      profile.reference_pressure ? profile.reference_pressure : r.pressure_pa;
  if (!ps) return std::nullopt;
  ContactPatch patch;
  patch.radius_m = r.radius_m;
  patch.reference_pressure_pa = *ps;
  patch.friction = 1.0;  // not known here, and no part of N
  patch.profile = profile.profile;
  return normal_load(patch);
}

}  // namespace

IdentifyOptions identify_options(const IdentifyRequest& r, ProfileChoice& profile) {
  validate(r);
  IdentifyOptions o;
  IdentificationOptions& f = o.fit;
  f.radius_m = r.radius_m;
  f.normal_load_n = r.normal_load_n;
  if (const std::optional<double> n = load_from_profile(r, profile)) f.normal_load_n = n;
  if (!r.profile.empty()) f.profile = profile.profile;
  f.fixed = r.fix;
  testing::Seams::of(f) = testing::Seams::of(r);
  f.loss = r.loss == "huber"    ? RobustLoss::huber
           : r.loss == "cauchy" ? RobustLoss::cauchy
                                : RobustLoss::none;
  f.loss_scale = r.loss_scale;
  f.noise_model = r.noise_model == "relative" ? NoiseModel::relative
                  : r.noise_model == "affine" ? NoiseModel::affine
                                              : NoiseModel::additive;
  if (!r.noise_scale.empty())
    f.noise_scale =
        std::array<double, kChannels>{r.noise_scale[0], r.noise_scale[1], r.noise_scale[2]};
  f.stop = r.stop;
  f.joint_admissibility = r.admissible_law;
  o.leave_out_outliers = r.outliers;
  o.resamples = r.loop ? r.resamples : 0;
  if (r.loop) {
    o.loop = ClosedLoopOptions{};
    o.loop->alpha = r.alpha;
    o.loop->speed_inside_integrals = r.speed_inside_integrals;
    o.loop->progress = r.progress;
    o.loop->choose_noise_model = r.noise_model == "auto" && r.noise_scale.empty();
  }
  return o;
}

IdentifyRun identify(const MeasuredData& data, const IdentifyRequest& request) {
  ProfileChoice profile;
  IdentifyOptions o = identify_options(request, profile);
  // The rows' own loads (an Fz column) win over a profile's pressure, which then gives only the
  // shape; a load given directly wins over both.
  std::string load_source;
  if (!request.normal_load_n)
    if (const std::optional<LoadFromData> l = normal_load_from_data(data)) {
      if (o.fit.normal_load_n && std::abs(*o.fit.normal_load_n - l->mean_n) > 1e-3 * l->mean_n)
        load_source = "; the profile's pressure, " +
                      std::to_string(std::lround(*o.fit.normal_load_n)) +
                      " N over the patch, gives only its shape";
      o.fit.normal_load_n = l->mean_n;  // f = F0 / N is then reported
      load_source = l->description() + load_source;
    }
  IdentifyRun run;
  run.result = identify(data, o);
  run.input = describe_run(data.source, data, request.radius_m, o.fit.normal_load_n, profile);
  run.input.normal_load_source = load_source;
  run.input.outliers = run.result.outliers;
  run.input.put_back = run.result.put_back;
  return run;
}

}  // namespace contensou
