/// \file
/// The identification module (target contensou::identification, Ceres): measured diagrams and
/// their CSV, the diagram simulator, the weighted fit with confidence intervals, the effect
/// catalogue and the closed loop (seed section 5). Includes the friction module.
#pragma once

#include "contensou/friction.hpp"
#include "contensou/identification/closed_loop.hpp"
#include "contensou/identification/data_checks.hpp"
#include "contensou/identification/effect_model.hpp"
#include "contensou/identification/fit.hpp"
#include "contensou/identification/held_out.hpp"
#include "contensou/identification/identify.hpp"
#include "contensou/identification/identify_request.hpp"
#include "contensou/identification/lab_columns.hpp"
#include "contensou/identification/measured_data.hpp"
#include "contensou/identification/model_file.hpp"
#include "contensou/identification/outliers.hpp"
#include "contensou/identification/prediction.hpp"
#include "contensou/identification/profile_choice.hpp"
#include "contensou/identification/report.hpp"
#include "contensou/identification/report_text.hpp"
#include "contensou/identification/simulation.hpp"
#include "contensou/identification/statistics.hpp"
