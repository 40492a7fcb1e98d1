// contensou: coupled sliding-spinning dry friction over a contact patch.
// The dependency-free core (Eigen only): the friction module. Identification (Ceres) and the
// landing gear (SUNDIALS) have umbrellas of their own: contensou/identification.hpp and
// contensou/gear.hpp. See docs/architecture.md.
#pragma once

#include "contensou/friction.hpp"
#include "contensou/version.hpp"
