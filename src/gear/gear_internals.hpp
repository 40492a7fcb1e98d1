// The landing gear's contact, shared by its right-hand side (landing_gear.cpp), its structured
// Jacobian (gear_jacobian.cpp) and the rolling tire (rolling_tire.cpp). Private to the gear
// module.
#pragma once

#include <Eigen/Core>
#include <array>
#include <utility>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/gear/landing_gear.hpp"

namespace contensou::detail {

// The seed tire's unit patch (R = 1 m, p* = 1 Pa, f = 1) with the tire's rolling shift kx.
ContactPatch unit_patch(const SlidingTire& tire);

// The torsional spring's deflection d(psi) across the torque-link freeplay and its slope
// (landing_gear.hpp, GearStructure::freeplay_rad).
std::pair<double, double> freeplay_deflection(double psi, double delta);

// g = I_w Omega / L, zero without a gyroscopic length.
double gyroscopic_coefficient(const GearStructure& g, double spin);

// The rolling tire's forces (landing_gear.hpp, RollingTire) from cs.slip, cs.slip_ratio,
// cs.load_n and the string's deflection lambda; fills cs.force and cs.friction.
void rolling_forces(const GearConfig& c, double lambda, ContactState& cs);

// The friction on the tire from the patch kinematics cs.slip (and slip_ratio), the string's
// deflection lambda, at cs.load_n > 0 and cs.patch_radius_m; fills cs.force and cs.friction.
void contact_forces(const GearModel& model, bool rolling, double lambda, ContactState& cs);

// K = d(Fx, Fy, Mz)/d(vx, vy, omega) of the sliding law at fixed load and patch radius.
Eigen::Matrix3d sliding_law_jacobian(const GearModel& model, const ContactState& w);

// One wheel's contact: its patch state, its lateral offset l_i and its spin state.
struct WheelContact {
  ContactState cs;
  double offset = 0.0;
  int spin = kSpin;
};

// The wheels of the gear, each with its contact; returns their number (1 or 2).
int wheel_contacts(const GearModel& model, const GearMode& mode, double t, const GearState& x,
                   std::array<WheelContact, 2>& wheels);

}  // namespace contensou::detail
