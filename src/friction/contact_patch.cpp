#include "contensou/friction/contact_patch.hpp"

#include <numbers>

#include "contensou/friction/error.hpp"

namespace contensou {

ContactPatch seed_tire_patch() {
  ContactPatch p;
  p.radius_m = 0.087;
  p.reference_pressure_pa = 2.1e5;
  p.friction = 0.3;
  p.profile = seed_tire_profile();
  return p;
}

double normal_load(const ContactPatch& patch) {
  validate(patch);
  return 2.0 * std::numbers::pi * patch.radius_m * patch.radius_m * patch.reference_pressure_pa *
         moment(patch.profile, 1);
}

void validate(const ContactPatch& patch) {
  require_positive("radius_m", patch.radius_m);
  require_positive("reference_pressure_pa", patch.reference_pressure_pa);
  require_non_negative("friction", patch.friction);
  require_positive("kappa", patch.kappa);
  require_finite("kx", patch.profile.kx);
  require_finite("ky", patch.profile.ky);
  const double k = std::hypot(patch.profile.kx, patch.profile.ky);
  if (!(k < 1.0))
    throw InvalidArgument("|(kx, ky)|", format_value(k),
                          "the pressure shift must be < 1 so that the pressure stays positive");
  if (patch.slip_speed_friction) {
    const auto& s = *patch.slip_speed_friction;
    require_non_negative("slip_speed_friction.static_coefficient", s.static_coefficient);
    require_non_negative("slip_speed_friction.kinetic_coefficient", s.kinetic_coefficient);
    require_positive("slip_speed_friction.reference_speed", s.reference_speed);
    require_positive("slip_speed_friction.exponent", s.exponent);
  }
}

}  // namespace contensou
