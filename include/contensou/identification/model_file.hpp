/// \file
/// The identified model in a file: everything needed to evaluate it at rows it never saw (the
/// form, the profile as given, the constants the diagrams do not identify, every parameter's
/// value and the scaling of the variables friction follows), as the JSON object the report
/// carries under "model" (report.hpp) and `contensou-identify predict --model` reads back.
///
/// ~~~
///   {"format": "contensou-model 1", "radius_m": 0.0525, "normal_load_N": 8.8,
///    "reference_load_N": null, "law_constants": {"c": 4, "a_k": 1, "mk_ratio": 0.375},
///    "profile": null | {"shape": "uniform" | "hertz" | "cosine_series" | "table" | "chebyshev",
///                       ... its numbers, "clip_negative": false, "keep_negative": false},
///    "profile_degree": 2, "profile_corrected": false, "exact_only": false,
///    "speed_in_exact": false, "admissible_shape": true, "profile_constants": {...},
///    "exact_tolerance": 1e-6, "regularization_speed_mps": 1e-6,
///    "parameters": {"F0_N": 2.6, "a": 1.1, ...every parameter of effect_model.hpp...},
///    "dependence": [null | {"kind": "load" | "time" | "order" | "recorded", "name": "T",
///                           "unit": "K", "mid": 300, "half_range": 10}, ...],
///    "motion_patch": null | {"radius_m": 0.0525, "contact_radius_ratio": 1, "exponent": 2,
///                            "kx": 0.2, "ky": 0, "force_scale_N": 2.46,
///                            "median_angle_deg": 16.4, "rows": 300}}
/// ~~~
/// (motion_patch: the rigid patch of the motion from the force, rigid_patch.hpp; a file without
/// the member, as earlier versions wrote, has none)
/// ~~~
/// ~~~
#pragma once

#include <string>

#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/measured_data.hpp"

namespace contensou {

/// The format's name and version, the file's "format" member.
inline constexpr const char* kModelFileFormat = "contensou-model 1";

/// The model `spec` at its values (ModelSpec::value) as the JSON object above; `indent` as
/// nlohmann::json::dump (-1: one line).
std::string model_to_json(const ModelSpec& spec, int indent = -1);

/// The model of a JSON object as model_to_json writes it, or of a whole report
/// (contensou-identify --json: its "model" member), ready to evaluate (evaluate_model): the
/// exact laws are built on first use. `source` names the text in errors (a file name). Throws
/// ParseError for text that is not JSON, and InvalidArgument naming the member for a missing
/// member, a wrong type, another format or a value outside its range.
ModelSpec model_from_json(const std::string& text, const std::string& source = "model");

/// The model's variables (ModelSpec::dependence) bound to the columns of `data`: a recorded
/// variable is found by its name among data.recorded (its index there). Throws
/// InvalidArgument naming the variable when the data lack it.
ModelSpec bind_to_data(ModelSpec spec, const MeasuredData& data);

}  // namespace contensou
