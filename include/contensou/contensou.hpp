// contensou: coupled sliding-spinning dry friction over a contact patch. Umbrella header.
#pragma once

#include "contensou/contact_patch.hpp"
#include "contensou/csv.hpp"
#include "contensou/error.hpp"
#include "contensou/exact_resultants.hpp"
#include "contensou/fractional_law.hpp"
#include "contensou/kinematics.hpp"
#include "contensou/landing_gear.hpp"
#include "contensou/model_error.hpp"
#include "contensou/oscillation.hpp"
#include "contensou/pressure_profile.hpp"
#include "contensou/quadrature.hpp"
#include "contensou/version.hpp"
