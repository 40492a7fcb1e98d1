// The FMI 2.0 C interface of a contensou FMU binary (Model Exchange and Co-Simulation) around an
// FmuModel (fmu_model.hpp). The state machine of the standard (FMI 2.0.4, section 2.1.5 and
// 4.2.4), simplified to what the models need: instantiated -> initialization -> event mode or
// continuous-time mode (Model Exchange, no states) / step complete (Co-Simulation) ->
// terminated; any error -> failed, after which only fmi2Reset and fmi2FreeInstance are taken.
// Every function checks its instance and its arguments, catches every exception and reports it
// to the logger with fmi2Error: nothing is thrown across the C boundary.
#include <fmi2Functions.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "fmu_model.hpp"

namespace contensou::fmu {
namespace {

enum class Phase {
  instantiated,
  initialization,
  event_mode,
  continuous,
  step_complete,
  terminated,
  failed
};

constexpr std::uint64_t kMagic = 0x636f6e74656e736fULL;  // "contenso"

struct Instance {
  std::uint64_t magic = kMagic;
  std::string name, guid, resources;
  fmi2CallbackFunctions callbacks{};
  bool cosimulation = false;
  bool logging = false;
  Phase phase = Phase::instantiated;
  double time = 0.0, start_time = 0.0;
  std::unique_ptr<FmuModel> model;
  std::vector<std::string> strings;  // what fmi2GetString returned last (valid until the next call)
};

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::instantiated:
      return "instantiated";
    case Phase::initialization:
      return "initialization mode";
    case Phase::event_mode:
      return "event mode";
    case Phase::continuous:
      return "continuous-time mode";
    case Phase::step_complete:
      return "step complete";
    case Phase::terminated:
      return "terminated";
    case Phase::failed:
      return "error (after an earlier error: fmi2Reset or fmi2FreeInstance)";
  }
  return "?";
}

void log(const Instance& in, fmi2Status status, const char* category, const std::string& text) {
  if (!in.callbacks.logger) return;
  // The message as an argument, never as the format: a '%' in it is printed as it is.
  in.callbacks.logger(in.callbacks.componentEnvironment, in.name.c_str(), status, category, "%s",
                      text.c_str());
}

Instance* instance(fmi2Component c) {
  auto* in = static_cast<Instance*>(c);
  return in && in->magic == kMagic ? in : nullptr;
}

// Runs `body` for the function `what` if the instance is in one of `allowed`; an exception or a
// phase outside them gives fmi2Error with a logged message, and an exception the failed phase.
constexpr unsigned bit(Phase p) {
  return 1u << static_cast<unsigned>(p);
}

template <class Body>
fmi2Status guarded(fmi2Component c, const char* what, unsigned allowed, Body&& body) {
  Instance* in = instance(c);
  if (!in) return fmi2Error;  // no instance to log to
  if (!(allowed & bit(in->phase))) {
    log(*in, fmi2Error, "logStatusError",
        std::string(what) + " is not allowed in the state " + phase_name(in->phase));
    return fmi2Error;
  }
  try {
    return body(*in);
  } catch (const std::exception& e) {
    log(*in, fmi2Error, "logStatusError", std::string(what) + ": " + e.what());
  } catch (...) {
    log(*in, fmi2Error, "logStatusError", std::string(what) + ": unknown error");
  }
  in->phase = Phase::failed;
  return fmi2Error;
}

constexpr unsigned kRunning =
    bit(Phase::event_mode) | bit(Phase::continuous) | bit(Phase::step_complete);
constexpr unsigned kInitialized = kRunning | bit(Phase::initialization) | bit(Phase::terminated);
constexpr unsigned kAfterInstantiation = kInitialized | bit(Phase::instantiated);
// Where fmi2Set* may be called: not once terminated (FMI 2.0 state machine, section 4.3.1).
constexpr unsigned kSettable = kAfterInstantiation & ~bit(Phase::terminated);

// A function of the standard this FMU does not provide (its capability flag is false).
fmi2Status unsupported(fmi2Component c, const char* what, const char* why) {
  Instance* in = instance(c);
  if (in) log(*in, fmi2Error, "logStatusError", std::string(what) + ": not provided (" + why + ")");
  return fmi2Error;
}

const Variable& variable(const Instance& in, fmi2ValueReference vr, VariableType type) {
  const auto vars = in.model->variables();
  if (vr >= vars.size())
    throw InvalidArgument("value reference", std::to_string(vr),
                          "no such variable (0 to " + std::to_string(vars.size() - 1) + ")");
  const Variable& v = vars[vr];
  if (v.type != type)
    throw InvalidArgument("value reference", std::to_string(vr) + " (" + v.name + ")",
                          "is a variable of another type");
  return v;
}

// Inputs may be set at any time after instantiation, parameters before the end of
// initialisation; outputs and locals never.
void check_settable(const Instance& in, const Variable& v) {
  if (v.causality == Causality::input) return;
  if (v.causality == Causality::parameter &&
      (in.phase == Phase::instantiated || in.phase == Phase::initialization))
    return;
  throw InvalidArgument(v.name, "(value reference " + std::to_string(v.reference) + ")",
                        v.causality == Causality::parameter
                            ? "a parameter can be set only before fmi2ExitInitializationMode"
                            : "is not an input or a parameter: it cannot be set");
}

template <class T>
void require_array(const T* p, size_t n, const char* what) {
  if (n > 0 && !p) throw InvalidArgument(what, "NULL", "must point to the values");
}

// An enum argument's value as the host passed it, read as bytes: a host may pass any int, and a
// typed load of a value outside the enum's would be undefined.
template <class Enum>
int raw(const Enum& e) {
  static_assert(sizeof(Enum) == sizeof(int));
  int v = 0;
  std::memcpy(&v, &e, sizeof v);
  return v;
}

std::unique_ptr<Instance> make_instance(fmi2String name, int type, fmi2String guid,
                                        fmi2String location, const fmi2CallbackFunctions* functions,
                                        fmi2Boolean logging) {
  auto in = std::make_unique<Instance>();
  in->name = name ? name : "";
  in->callbacks = *functions;
  in->cosimulation = type == static_cast<int>(fmi2CoSimulation);
  in->logging = logging == fmi2True;
  try {
    if (!name || !*name) throw InvalidArgument("instanceName", "empty", "must be a name");
    if (type != static_cast<int>(fmi2ModelExchange) && type != static_cast<int>(fmi2CoSimulation))
      throw InvalidArgument("fmuType", std::to_string(type), "must be 0 or 1");
    if (!guid) throw InvalidArgument("fmuGUID", "NULL", "must be the modelDescription's guid");
    in->guid = guid;
    in->resources = resource_path(location);
    in->model = make_fmu_model(in->resources, in->guid, in->cosimulation);
  } catch (const std::exception& e) {
    log(*in, fmi2Error, "logStatusError", std::string("fmi2Instantiate: ") + e.what());
    return nullptr;
  } catch (...) {
    log(*in, fmi2Error, "logStatusError", "fmi2Instantiate: unknown error");
    return nullptr;
  }
  return in;
}

// The law has no continuous states: nx and ni must be 0.
fmi2Status no_states(fmi2Component c, const char* what, size_t n) {
  return guarded(c, what, kInitialized, [&](Instance& in) {
    if (in.cosimulation)
      throw InvalidArgument(what, "called", "is Model Exchange: this is a Co-Simulation instance");
    if (n != 0) throw InvalidArgument("nx", std::to_string(n), "must be 0: this FMU has no states");
    return fmi2OK;
  });
}

}  // namespace
}  // namespace contensou::fmu

using contensou::InvalidArgument;
using contensou::fmu::Instance;
using contensou::fmu::Phase;
using contensou::fmu::VariableType;
namespace cf = contensou::fmu;

extern "C" {

const char* fmi2GetTypesPlatform(void) {
  return fmi2TypesPlatform;
}
const char* fmi2GetVersion(void) {
  return fmi2Version;
}

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t, const fmi2String[]) {
  return cf::guarded(c, "fmi2SetDebugLogging", cf::kAfterInstantiation, [&](Instance& in) {
    in.logging = on == fmi2True;
    return fmi2OK;
  });
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid, fmi2String location,
                              const fmi2CallbackFunctions* functions, fmi2Boolean,
                              fmi2Boolean logging) {
  if (!functions) return nullptr;  // no logger to say why
  try {
    return cf::make_instance(name, cf::raw(type), guid, location, functions, logging).release();
  } catch (...) {  // std::bad_alloc making the instance itself
    return nullptr;
  }
}

void fmi2FreeInstance(fmi2Component c) {
  Instance* in = cf::instance(c);
  if (!in) return;
  in->magic = 0;
  delete in;
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean, fmi2Real, fmi2Real start, fmi2Boolean,
                               fmi2Real) {
  return cf::guarded(c, "fmi2SetupExperiment", cf::bit(Phase::instantiated), [&](Instance& in) {
    contensou::require_finite("startTime", start);
    in.start_time = in.time = start;
    return fmi2OK;
  });
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c) {
  return cf::guarded(c, "fmi2EnterInitializationMode", cf::bit(Phase::instantiated),
                     [&](Instance& in) {
                       in.phase = Phase::initialization;
                       return fmi2OK;
                     });
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c) {
  return cf::guarded(c, "fmi2ExitInitializationMode", cf::bit(Phase::initialization),
                     [&](Instance& in) {
                       in.model->initialize(in.start_time);
                       in.phase = in.cosimulation ? Phase::step_complete : Phase::event_mode;
                       return fmi2OK;
                     });
}

fmi2Status fmi2Terminate(fmi2Component c) {
  return cf::guarded(c, "fmi2Terminate", cf::kRunning, [&](Instance& in) {
    in.phase = Phase::terminated;
    return fmi2OK;
  });
}

fmi2Status fmi2Reset(fmi2Component c) {
  Instance* in = cf::instance(c);
  if (!in) return fmi2Error;
  try {
    in->model->reset();
    in->phase = Phase::instantiated;
    in->time = in->start_time = 0.0;
    return fmi2OK;
  } catch (const std::exception& e) {
    cf::log(*in, fmi2Error, "logStatusError", std::string("fmi2Reset: ") + e.what());
  } catch (...) {
    cf::log(*in, fmi2Error, "logStatusError", "fmi2Reset: unknown error");
  }
  in->phase = Phase::failed;
  return fmi2Error;
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real value[]) {
  return cf::guarded(c, "fmi2GetReal", cf::kInitialized, [&](Instance& in) {
    cf::require_array(vr, n, "vr");
    cf::require_array(value, n, "value");
    for (size_t i = 0; i < n; ++i) {
      cf::variable(in, vr[i], VariableType::real);
      value[i] = in.model->get_real(vr[i]);
    }
    return fmi2OK;
  });
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real value[]) {
  return cf::guarded(c, "fmi2SetReal", cf::kSettable, [&](Instance& in) {
    cf::require_array(vr, n, "vr");
    cf::require_array(value, n, "value");
    for (size_t i = 0; i < n; ++i) {
      cf::check_settable(in, cf::variable(in, vr[i], VariableType::real));
      in.model->set_real(vr[i], value[i]);
    }
    return fmi2OK;
  });
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference[], size_t n, fmi2Integer[]) {
  return cf::guarded(c, "fmi2GetInteger", cf::kInitialized, [&](Instance&) {
    if (n > 0) throw InvalidArgument("vr", "given", "this FMU has no Integer variables");
    return fmi2OK;
  });
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference[], size_t n,
                          const fmi2Integer[]) {
  return cf::guarded(c, "fmi2SetInteger", cf::kSettable, [&](Instance&) {
    if (n > 0) throw InvalidArgument("vr", "given", "this FMU has no Integer variables");
    return fmi2OK;
  });
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          fmi2Boolean value[]) {
  return cf::guarded(c, "fmi2GetBoolean", cf::kInitialized, [&](Instance& in) {
    cf::require_array(vr, n, "vr");
    cf::require_array(value, n, "value");
    for (size_t i = 0; i < n; ++i) {
      cf::variable(in, vr[i], VariableType::boolean);
      value[i] = in.model->get_boolean(vr[i]) ? fmi2True : fmi2False;
    }
    return fmi2OK;
  });
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          const fmi2Boolean value[]) {
  return cf::guarded(c, "fmi2SetBoolean", cf::kSettable, [&](Instance& in) {
    cf::require_array(vr, n, "vr");
    cf::require_array(value, n, "value");
    for (size_t i = 0; i < n; ++i) {
      cf::check_settable(in, cf::variable(in, vr[i], VariableType::boolean));
      in.model->set_boolean(vr[i], value[i] != fmi2False);
    }
    return fmi2OK;
  });
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                         fmi2String value[]) {
  return cf::guarded(c, "fmi2GetString", cf::kInitialized, [&](Instance& in) {
    cf::require_array(vr, n, "vr");
    cf::require_array(value, n, "value");
    in.strings.assign(n, std::string());
    for (size_t i = 0; i < n; ++i) {
      cf::variable(in, vr[i], VariableType::string);
      in.strings[i] = in.model->get_string(vr[i]);
    }
    for (size_t i = 0; i < n; ++i) value[i] = in.strings[i].c_str();
    return fmi2OK;
  });
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                         const fmi2String value[]) {
  return cf::guarded(c, "fmi2SetString", cf::kSettable, [&](Instance& in) {
    cf::require_array(vr, n, "vr");
    cf::require_array(value, n, "value");
    for (size_t i = 0; i < n; ++i) {
      cf::check_settable(in, cf::variable(in, vr[i], VariableType::string));
      if (!value[i]) throw InvalidArgument("value", "NULL", "must be a string");
      in.model->set_string(vr[i], value[i]);
    }
    return fmi2OK;
  });
}

// No FMU state: canGetAndSetFMUstate and canSerializeFMUstate are false.
fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate*) {
  return cf::unsupported(c, "fmi2GetFMUstate", "canGetAndSetFMUstate is false");
}
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate) {
  return cf::unsupported(c, "fmi2SetFMUstate", "canGetAndSetFMUstate is false");
}
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate*) {
  return cf::unsupported(c, "fmi2FreeFMUstate", "canGetAndSetFMUstate is false");
}
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate, size_t*) {
  return cf::unsupported(c, "fmi2SerializedFMUstateSize", "canGetAndSetFMUstate is false");
}
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate, fmi2Byte[], size_t) {
  return cf::unsupported(c, "fmi2SerializeFMUstate", "canGetAndSetFMUstate is false");
}
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte[], size_t, fmi2FMUstate*) {
  return cf::unsupported(c, "fmi2DeSerializeFMUstate", "canGetAndSetFMUstate is false");
}

// dvUnknown = J dvKnown, J the outputs' partial derivatives with respect to the inputs.
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference unknown[],
                                        size_t n_unknown, const fmi2ValueReference known[],
                                        size_t n_known, const fmi2Real dv_known[],
                                        fmi2Real dv_unknown[]) {
  return cf::guarded(c, "fmi2GetDirectionalDerivative", cf::kInitialized, [&](Instance& in) {
    cf::require_array(unknown, n_unknown, "vUnknown_ref");
    cf::require_array(known, n_known, "vKnown_ref");
    cf::require_array(dv_known, n_known, "dvKnown");
    cf::require_array(dv_unknown, n_unknown, "dvUnknown");
    for (size_t j = 0; j < n_known; ++j) contensou::require_finite("dvKnown", dv_known[j]);
    for (size_t i = 0; i < n_unknown; ++i) {
      cf::variable(in, unknown[i], VariableType::real);
      double sum = 0.0;
      for (size_t j = 0; j < n_known; ++j) {
        cf::variable(in, known[j], VariableType::real);
        sum += in.model->partial(unknown[i], known[j]) * dv_known[j];
      }
      dv_unknown[i] = sum;
    }
    return fmi2OK;
  });
}

// ---- Model Exchange (the law only: no states, no event indicators) ----

fmi2Status fmi2EnterEventMode(fmi2Component c) {
  return cf::guarded(c, "fmi2EnterEventMode",
                     cf::bit(Phase::event_mode) | cf::bit(Phase::continuous), [&](Instance& in) {
                       if (in.cosimulation)
                         throw InvalidArgument("fmi2EnterEventMode", "called",
                                               "is Model Exchange: this is a Co-Simulation "
                                               "instance");
                       in.phase = Phase::event_mode;
                       return fmi2OK;
                     });
}

fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo* info) {
  return cf::guarded(c, "fmi2NewDiscreteStates", cf::bit(Phase::event_mode), [&](Instance&) {
    if (!info) throw InvalidArgument("fmi2eventInfo", "NULL", "must point to an fmi2EventInfo");
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0.0;
    return fmi2OK;
  });
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c) {
  return cf::guarded(c, "fmi2EnterContinuousTimeMode", cf::bit(Phase::event_mode),
                     [&](Instance& in) {
                       in.phase = Phase::continuous;
                       return fmi2OK;
                     });
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component c, fmi2Boolean, fmi2Boolean* enter_event,
                                       fmi2Boolean* terminate) {
  return cf::guarded(c, "fmi2CompletedIntegratorStep", cf::bit(Phase::continuous), [&](Instance&) {
    if (!enter_event || !terminate)
      throw InvalidArgument("enterEventMode, terminateSimulation", "NULL", "must be pointers");
    *enter_event = fmi2False;
    *terminate = fmi2False;
    return fmi2OK;
  });
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time) {
  return cf::guarded(c, "fmi2SetTime",
                     cf::bit(Phase::instantiated) | cf::bit(Phase::initialization) |
                         cf::bit(Phase::event_mode) | cf::bit(Phase::continuous),
                     [&](Instance& in) {
                       contensou::require_finite("time", time);
                       in.time = time;
                       return fmi2OK;
                     });
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real[], size_t nx) {
  return cf::no_states(c, "fmi2SetContinuousStates", nx);
}
fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real[], size_t nx) {
  return cf::no_states(c, "fmi2GetDerivatives", nx);
}
fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real[], size_t ni) {
  return cf::no_states(c, "fmi2GetEventIndicators", ni);
}
fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real[], size_t nx) {
  return cf::no_states(c, "fmi2GetContinuousStates", nx);
}
fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real[], size_t nx) {
  return cf::no_states(c, "fmi2GetNominalsOfContinuousStates", nx);
}

// ---- Co-Simulation ----

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                       const fmi2Integer[], const fmi2Real[]) {
  return cf::unsupported(c, "fmi2SetRealInputDerivatives",
                         "canInterpolateInputs is false, maxOutputDerivativeOrder 0");
}
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference[], size_t,
                                        const fmi2Integer[], fmi2Real[]) {
  return cf::unsupported(c, "fmi2GetRealOutputDerivatives",
                         "canInterpolateInputs is false, maxOutputDerivativeOrder 0");
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean) {
  return cf::guarded(c, "fmi2DoStep", cf::bit(Phase::step_complete), [&](Instance& in) {
    if (!in.cosimulation)
      throw InvalidArgument("fmi2DoStep", "called",
                            "is Co-Simulation: this is a Model Exchange instance");
    contensou::require_finite("currentCommunicationPoint", t);
    contensou::require_positive("communicationStepSize", h);
    // The host's time and the FMU's must agree (to rounding of their sums).
    if (std::abs(t - in.time) > 1e-9 * std::max(1.0, std::abs(in.time)))
      throw InvalidArgument(
          "currentCommunicationPoint", contensou::format_value(t),
          "must be the end of the previous step, " + contensou::format_value(in.time) + " s");
    in.model->do_step(t, h);
    in.time = t + h;
    return fmi2OK;
  });
}

fmi2Status fmi2CancelStep(fmi2Component c) {
  return cf::unsupported(c, "fmi2CancelStep", "canRunAsynchronuously is false");
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind, fmi2Status* value) {
  return cf::guarded(c, "fmi2GetStatus", cf::kInitialized, [&](Instance&) {
    if (!value) throw InvalidArgument("value", "NULL", "must be a pointer");
    *value = fmi2OK;  // doStep never runs asynchronously
    return fmi2OK;
  });
}
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Real* value) {
  return cf::guarded(c, "fmi2GetRealStatus", cf::kInitialized, [&](Instance& in) {
    if (!value) throw InvalidArgument("value", "NULL", "must be a pointer");
    if (cf::raw(kind) != static_cast<int>(fmi2LastSuccessfulTime))
      throw InvalidArgument("fmi2StatusKind", std::to_string(cf::raw(kind)),
                            "only fmi2LastSuccessfulTime is a Real status");
    *value = in.time;
    return fmi2OK;
  });
}
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind, fmi2Integer*) {
  return cf::unsupported(c, "fmi2GetIntegerStatus", "no such status of this FMU");
}
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind kind, fmi2Boolean* value) {
  return cf::guarded(c, "fmi2GetBooleanStatus", cf::kInitialized, [&](Instance&) {
    if (!value) throw InvalidArgument("value", "NULL", "must be a pointer");
    if (cf::raw(kind) != static_cast<int>(fmi2Terminated))
      throw InvalidArgument("fmi2StatusKind", std::to_string(cf::raw(kind)),
                            "only fmi2Terminated is a Boolean status");
    *value = fmi2False;
    return fmi2OK;
  });
}
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind, fmi2String*) {
  return cf::unsupported(c, "fmi2GetStringStatus", "no such status of this FMU");
}

}  // extern "C"
