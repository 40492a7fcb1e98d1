/// \file
/// One identification as a user asks for it, by the keys that contensou-identify's options and
/// Python's contensou.identify() keywords share (normal_load is --normal-load there): one table
/// of keys with their meaning, validated once and turned into the library's options once.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/identification/identify.hpp"
#include "contensou/identification/lab_columns.hpp"
#include "contensou/identification/report.hpp"

namespace contensou {

/// An identification as asked for: one member per key (identify_request_keys gives each key's
/// meaning), checked by validate().
struct IdentifyRequest {
  double radius_m = 0.0;                ///< radius: patch radius R [m] (required, positive)
  std::optional<double> normal_load_n;  ///< normal_load: N [N] (else from the profile or Fz)
  /// profile: uniform, hertz, seed-tire or the path of a CSV rho,pressure_Pa ("" = none).
  std::string profile;
  std::optional<double> pressure_pa;  ///< pressure: p* [Pa] of a built-in profile
  int profile_smoothing = 0;          ///< profile_smoothing: 0..64 (0 = interpolate)
  bool profile_clip = false;          ///< profile_clip: clip a CSV profile that dips below zero
  std::map<std::string, double> fix;  ///< fix: parameter name (F0_N, a, M0_Nm, m, kx) to value
  std::string loss = "none";          ///< loss: none, huber or cauchy
  double loss_scale = 2.0;            ///< loss_scale: robust loss threshold, in noise scales
  /// noise_model: auto, additive, relative or affine (auto: additive, and the closed loop tests
  /// a noise growing with the value when the scales are estimated).
  std::string noise_model = "auto";
  /// noise_scale: Fx, Fy, Mz [N, N, N m], each in [1e-12, 1e12] (empty = estimated).
  std::vector<double> noise_scale;
  bool loop = true;     ///< loop: close the loop (else the fractional law only)
  double alpha = 1e-3;  ///< alpha: the loop's level per step, in [1e-12, 0.5]
  /// speed_inside_integrals: the loop's slip-speed friction at the local slip speed inside the
  /// exact integrals (else at an effective speed).
  bool speed_inside_integrals = true;
  bool outliers = true;  ///< outliers: find gross errors and leave them out
  /// resamples: the loop run again on this many subsamples of about 80 % of the rows, in
  /// [0, 100]; an effect accepted in fewer than 80 % of them is reported unstable and left out.
  int resamples = 5;
  /// admissible_law: hold a, m and M0 / (F0 R) together to what a non-negative pressure gives.
  bool admissible_law = false;
  /// Called with a line per stage of the closed loop (ClosedLoopOptions::progress).
  std::function<void(const std::string&)> progress;
  StopRequest stop{};  ///< polled by the fit and the loop (IdentificationOptions::stop)
  KeyStyle style = KeyStyle::python;  ///< how errors name the keys

 private:
  detail::TestSeams seams_;
  friend struct testing::Seams;
};

/// A key of the request with what it means (units included).
struct RequestKey {
  const char* key;   ///< as Python writes it ("normal_load"; key_name gives the app's spelling)
  const char* help;  ///< its meaning, units included
};
/// The keys in the order of the docs, each with what it means.
const std::vector<RequestKey>& identify_request_keys();

/// The key's help (key_name, key_style.hpp: the key as the app or Python writes it); throws
/// std::logic_error for a key that is not one of identify_request_keys().
const char* key_help(std::string_view key);

/// What identify(data, request) returns: the identification and the report's input.
struct IdentifyRun {
  Identification result;  ///< the outliers, the fits and the loop (identify.hpp)
  /// The report's description of the input (data.source names the data), with the load's
  /// source and the outliers left out.
  ReportInput input;
};

/// The words a key that names a choice accepts ("loss": none, huber, cauchy; "noise_model":
/// auto, additive, relative, affine), empty for a key that does not name one.
const std::vector<std::string>& key_choices(std::string_view key);

/// The checks of the request alone (no file read): each key's range, the keys that go together,
/// a fixed parameter within the fit's bounds for it (kx in [-0.95, 0.95]: |kx| >= 1 makes the
/// pressure negative). Throws std::invalid_argument (InvalidArgument for a value out of its
/// range) naming the key, the value and the range.
/// profile_smoothing: 0 (the default) interpolates a profile table, 1..64 fits a series of that
/// many terms (a CSV profile needed), the same rule for the app and for Python.
void validate(const IdentifyRequest& request);

/// The library's options from a request, and the profile it chooses (N from the profile with
/// its pressure when the load is not given). Throws std::invalid_argument naming the key (as
/// request.style writes it), the value and the range, or a profile file that is missing or
/// refused; ParseError for a malformed profile CSV.
IdentifyOptions identify_options(const IdentifyRequest& request, ProfileChoice& profile);

/// Validates the request, takes N as given, else from the profile and its pressure, else from
/// the data's Fz column (the report says so), and runs identify(data, options). Throws as
/// identify_options and identify(data, options) do.
IdentifyRun identify(const MeasuredData& data, const IdentifyRequest& request);

}  // namespace contensou
