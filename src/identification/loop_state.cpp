// The closed loop's state between its steps: see loop_state.hpp.
#include "loop_state.hpp"

namespace contensou::detail {

void say(const ClosedLoopOptions& o, const std::string& line) {
  if (o.progress) o.progress(line);
}

// f(w) at the local slip speed inside the integrals when asked for and when the model has a
// speed dependence and the exact integrals.
void set_speed_inside(ModelSpec& s, const ClosedLoopOptions& loop) {
  s.speed_in_exact = loop.speed_inside_integrals && s.uses_exact() &&
                     (s.free[kSpeedDrop] || s.value[kSpeedDrop] != 0.0);
}

// Builds the exact laws a spec evaluates, if not yet built, here rather than inside the solver's
// first evaluation, so that the caller's stop request reaches the build (seconds for the
// slip-speed table).
void build_laws(const ModelSpec& s, const StopRequest& stop) {
  throw_if_stopped(stop);
  if (s.uses_exact() && s.exact_laws) s.exact_laws->laws(s.speed_in_exact, stop, s.law_degree());
}

LoopState fit_state(const MeasuredData& data, ModelSpec spec, const NoiseSettings& noise) {
  build_laws(spec, noise.stop);
  LoopState st;
  st.fit = fit_model(data, spec, noise, &st.theta);
  spec.value = st.theta;
  st.spec = spec;
  return st;
}

}  // namespace contensou::detail
