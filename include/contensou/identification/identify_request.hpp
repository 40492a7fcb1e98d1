// One identification as a user asks for it, by the keys that contensou-identify's options and
// Python's contensou.identify() keywords share (normal_load is --normal-load there): one table
// of keys with their meaning, validated once and turned into the library's options once.
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

struct IdentifyRequest {
  double radius_m = 0.0;                // radius
  std::optional<double> normal_load_n;  // normal_load
  std::string profile;                  // profile ("" = none)
  std::optional<double> pressure_pa;    // pressure
  int profile_smoothing = 0;            // profile_smoothing (0 = interpolate)
  bool profile_clip = false;            // profile_clip
  std::map<std::string, double> fix;    // fix
  std::string loss = "none";            // loss
  double loss_scale = 2.0;              // loss_scale
  std::string noise_model = "auto";     // noise_model
  std::vector<double> noise_scale;      // noise_scale (empty = estimated)
  bool loop = true;                     // loop
  double alpha = 1e-3;                  // alpha
  bool speed_inside_integrals = true;   // speed_inside_integrals
  bool outliers = true;                 // outliers: find gross errors and leave them out
  int failing_point = -1;               // testing only (IdentificationOptions::failing_point)
  std::function<void(const std::string&)> progress;  // a line per stage of the loop
  StopRequest stop{};
  KeyStyle style = KeyStyle::python;  // how errors name the keys
};

// The keys in the order of the docs, each with what it means (units included).
struct RequestKey {
  const char* key;
  const char* help;
};
const std::vector<RequestKey>& identify_request_keys();

// The key's help (key_name, key_style.hpp: the key as the app or Python writes it).
const char* key_help(std::string_view key);

struct IdentifyRun {
  Identification result;
  ReportInput input;  // the report's description of the input (data.source names the data)
};

// The words a key that names a choice accepts ("loss": none, huber, cauchy; "noise_model"),
// empty for a key that does not name one.
const std::vector<std::string>& key_choices(std::string_view key);

// The checks of the request alone (no file read): each key's range, the keys that go together,
// a fixed parameter within the fit's bounds for it (kx in [-0.95, 0.95]: |kx| >= 1 makes the
// pressure negative). Throws std::invalid_argument naming the key, the value and the range.
// profile_smoothing: 0 (the default) interpolates a profile table, 1..64 fits a series of that
// many terms (a CSV profile needed), the same rule for the app and for Python.
void validate(const IdentifyRequest& request);

// The library's options from a request, and the profile it chooses. Throws
// std::invalid_argument naming the key (as request.style writes it), the value and the range.
IdentifyOptions identify_options(const IdentifyRequest& request, ProfileChoice& profile);

// Validates the request, takes N from the profile and its pressure, or else from the data's Fz
// column (the report says so), and runs identify(data, options).
IdentifyRun identify(const MeasuredData& data, const IdentifyRequest& request);

}  // namespace contensou
