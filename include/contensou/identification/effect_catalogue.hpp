/// \file
/// The closed loop's catalogue of effects, one table: each effect's name (as in the JSON report),
/// what it adds to the model, its null, the words a report says it in and the measurement that
/// tells it from the others. The loop, the reports and the docs read this table; an effect is one
/// enumerator and one entry (a table that misses one does not compile).
#pragma once

#include <array>
#include <string>

namespace contensou {

/// An effect the closed loop can add to the model (its name: describe(e).name).
enum class Effect {
  shape,                      ///< the exact integrals over the profile replace the law
  profile_detail,             ///< the identified profile a quartic instead of a quadratic in rho^2
  profile_correction,         ///< the given profile times a quadratic in rho^2
  anisotropy,                 ///< lateral friction kappa f, kappa != 1
  pressure_shift_y,           ///< lateral pressure shift ky
  centre_offset,              ///< the patch's centre off the body's, x_c or y_c
  contact_radius,             ///< a contact smaller than the body, radius c_R R, c_R < 1
  speed_dependence,           ///< friction falling with the slip speed, f(w)
  channel_offset,             ///< a constant in one measured channel
  channel_crosstalk,          ///< one channel picks up a share of another
  slip_angle_offset,          ///< the rig's slip angle off by delta
  spin_offset,                ///< the rig's spin reading off by omega_0
  patch_growth,               ///< the patch radius grows with the load, R = R0 (N/N0)^q
  friction_dependence,        ///< friction follows a recorded variable, f (1 + b1 z)
  friction_dependence_curve,  ///< the same along a curve, + b2 (2 z^2 - 1)
  noise_growth,               ///< the noise grows with the value, sigma = a + b |y|
};
/// The number of effects (enumerators of Effect).
inline constexpr int kEffects = 16;

/// One entry of the catalogue: an effect and its texts.
struct EffectDescriptor {
  Effect effect;         ///< the effect
  const char* name;      ///< "anisotropy": the JSON report's and the table's name
  const char* adds;      ///< what it adds to the model, for the docs' table
  const char* null;      ///< the parameter value at which it vanishes
  const char* words;     ///< in a test engineer's words; "{}" stands for the step's detail
  const char* separate;  ///< the measurement that shows it apart from effects it resembles
};

/// The descriptor of an effect (the table's entry in enumerator order).
const EffectDescriptor& describe(Effect e);

/// The effect of a name ("anisotropy") into *e; false (e untouched) if there is none.
bool effect_by_name(const std::string& name, Effect* e);

/// The words of an effect with its detail in place of "{}" ("friction follows T [degC]"); an
/// empty detail reads "a recorded variable".
std::string effect_in_words(Effect e, const std::string& detail);

/// The detail of a profile_correction with weights w1, w2: its factor
/// q(s) = (1-s)^2 + 2 w1 s(1-s) + w2 s^2 (1 at the centre) at rho = 0.71 (s = 1/2) and at the
/// rim, "1.2 at rho 0.71 and 1.37 at the rim, 1 at the centre".
std::string profile_correction_detail(double w1, double w2);

/// The table as Markdown (docs/identification.md holds it; a test compares the two).
std::string effect_catalogue_markdown();

}  // namespace contensou
