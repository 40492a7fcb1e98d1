/// \file
/// The friction module (target contensou::friction, Eigen only): pressure profiles and their
/// moments, the contact patch, the exact resultants by adaptive cubature and the exact law built
/// from them, the fractional laws and the model-error report (theory.md sections 1-5).
#pragma once

#include "contensou/friction/admissible_shape.hpp"
#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/coulomb_envelope.hpp"
#include "contensou/friction/csv.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/limit_surface.hpp"
#include "contensou/friction/model_error.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "contensou/friction/quadrature.hpp"
#include "contensou/friction/slip_speed_measure.hpp"
#include "contensou/version.hpp"
