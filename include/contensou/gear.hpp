/// \file
/// The gear module (target contensou::gear, SUNDIALS CVODE): the one-wheel main landing gear
/// with its contact models, the landing simulation, oscillation analysis, stability by eigenvalues,
/// stability maps, limit cycles and their bifurcation sweeps, and the tire-uncertainty Monte Carlo
/// (docs/shimmy.md). Includes the friction module.
#pragma once

#include "contensou/friction.hpp"
#include "contensou/gear/bifurcation.hpp"
#include "contensou/gear/cycle_trend.hpp"
#include "contensou/gear/gear_parameters.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "contensou/gear/linear_stability.hpp"
#include "contensou/gear/oscillation.hpp"
#include "contensou/gear/stability_map.hpp"
#include "contensou/gear/tire_uncertainty.hpp"
