// The closed loop's catalogue of effects, one table: each effect's name (as in the JSON report),
// what it adds to the model, its null, the words a report says it in and the measurement that
// tells it from the others. The loop, the reports and the docs read this table; an effect is one
// enumerator and one entry (a table that misses one does not compile).
#pragma once

#include <array>
#include <string>

namespace contensou {

enum class Effect {
  shape,
  profile_detail,
  anisotropy,
  pressure_shift_y,
  speed_dependence,
  channel_offset,
  channel_crosstalk,
  slip_angle_offset,
  spin_offset,
  patch_growth,
  friction_dependence,
  friction_dependence_curve,
  noise_growth,
};
inline constexpr int kEffects = 13;

struct EffectDescriptor {
  Effect effect;
  const char* name;      // "anisotropy": the JSON report's and the table's name
  const char* adds;      // what it adds to the model, for the docs' table
  const char* null;      // the parameter value at which it vanishes
  const char* words;     // in a test engineer's words; "{}" stands for the step's detail
  const char* separate;  // the measurement that shows it apart from effects it resembles
};

// The descriptor of an effect (the table's entry in enumerator order).
const EffectDescriptor& describe(Effect e);

// The effect of a name ("anisotropy"); false if there is none.
bool effect_by_name(const std::string& name, Effect* e);

// The words of an effect with its detail ("friction follows T [degC]").
std::string effect_in_words(Effect e, const std::string& detail);

// The table as Markdown (docs/identification.md holds it; a test compares the two).
std::string effect_catalogue_markdown();

}  // namespace contensou
