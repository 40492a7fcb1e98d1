// The closed loop's state between its steps (closed_loop.cpp) and its backward pass and noise
// step (loop_backward.cpp): internal, not installed.
#pragma once

#include <array>
#include <string>

#include "contensou/identification/closed_loop.hpp"

namespace contensou::detail {

// The model the loop stands on: its spec, its estimate and its fit.
struct LoopState {
  ModelSpec spec;
  std::array<double, kModelParameters> theta{};
  FitReport fit;
};

// A line of progress, if the caller asked for them.
void say(const ClosedLoopOptions& o, const std::string& line);

// f(w) at the local slip speed inside the integrals when asked for and when the model has a
// speed dependence and the exact integrals.
void set_speed_inside(ModelSpec& s, const ClosedLoopOptions& loop);

// Builds the exact laws a spec evaluates, if not yet built, here rather than inside the solver's
// first evaluation, so that the caller's stop request reaches the build (seconds for the
// slip-speed table).
void build_laws(const ModelSpec& s, const StopRequest& stop);

// The spec fitted to the data (its laws built first): the state at its estimate.
LoopState fit_state(const MeasuredData& data, ModelSpec spec, const NoiseSettings& noise);

// Backward pass: an effect accepted early may stand in for ones found later. Refit without
// each accepted effect (shape excepted) and remove it if it is no longer significant at
// alpha / (number accepted) or BIC prefers the model without it; repeat until none goes.
void prune(const MeasuredData& data, const NoiseSettings& noise, const ClosedLoopOptions& loop,
           LoopState& st, ClosedLoopReport& report);

// The noise step (ClosedLoopOptions::choose_noise_model), after the effects: a noise scale that
// grows with the value against one constant scale per channel (loop_backward.cpp).
void test_noise_growth(const MeasuredData& data, const NoiseSettings& noise,
                       const ClosedLoopOptions& loop, LoopState& st, ClosedLoopReport& report);

}  // namespace contensou::detail
