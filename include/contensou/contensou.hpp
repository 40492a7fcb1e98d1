// contensou: coupled sliding-spinning dry friction over a contact patch. Umbrella header.
#pragma once

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/model_error.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/oscillation.hpp"
#include "contensou/version.hpp"
