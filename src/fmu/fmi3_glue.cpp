// The FMI 3.0 C interface of a contensou FMU binary (Model Exchange and Co-Simulation, no
// scheduled execution) around the same FmuModel as the FMI 2.0 glue (fmi2_glue.cpp), in the
// same binary: the archive's modelDescription.xml says which standard a host uses. The state
// machine of FMI 3.0, sections 3.2 and 4.2, simplified as there: instantiated -> initialization
// -> event mode / continuous-time mode (Model Exchange, no states) or step mode (Co-Simulation,
// no event mode) -> terminated; any error -> failed, after which only fmi3Reset and
// fmi3FreeInstance are taken. Every exception stops here with fmi3Error and a logged message.
#include <fmi3Functions.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "fmu_model.hpp"

namespace contensou::fmu {
namespace {

enum class Phase3 {
  instantiated,
  initialization,
  event_mode,
  continuous,
  step_mode,
  terminated,
  failed
};

constexpr std::uint64_t kMagic3 = 0x636f6e74656e3366ULL;

struct Instance3 {
  std::uint64_t magic = kMagic3;
  std::string name;
  fmi3InstanceEnvironment environment = nullptr;
  fmi3LogMessageCallback logger = nullptr;
  bool cosimulation = false;
  Phase3 phase = Phase3::instantiated;
  double time = 0.0, start_time = 0.0;
  std::unique_ptr<FmuModel> model;
  std::vector<std::string> strings;
};

constexpr unsigned bit(Phase3 p) {
  return 1u << static_cast<unsigned>(p);
}
constexpr unsigned kRunning3 =
    bit(Phase3::event_mode) | bit(Phase3::continuous) | bit(Phase3::step_mode);
constexpr unsigned kInitialized3 =
    kRunning3 | bit(Phase3::initialization) | bit(Phase3::terminated);
constexpr unsigned kAll3 = kInitialized3 | bit(Phase3::instantiated);
// Where fmi3Set* may be called: not once terminated (FMI 3.0 state machine).
constexpr unsigned kSettable3 = kAll3 & ~bit(Phase3::terminated);

void log(const Instance3& in, fmi3Status status, const std::string& text) {
  if (in.logger) in.logger(in.environment, status, "logStatusError", text.c_str());
}

Instance3* instance(fmi3Instance c) {
  auto* in = static_cast<Instance3*>(c);
  return in && in->magic == kMagic3 ? in : nullptr;
}

template <class Body>
fmi3Status guarded(fmi3Instance c, const char* what, unsigned allowed, Body&& body) {
  Instance3* in = instance(c);
  if (!in) return fmi3Error;
  if (!(allowed & bit(in->phase))) {
    log(*in, fmi3Error,
        std::string(what) + " is not allowed in this state" +
            (in->phase == Phase3::failed ? " (after an earlier error: fmi3Reset or "
                                           "fmi3FreeInstance)"
                                         : ""));
    return fmi3Error;
  }
  try {
    return body(*in);
  } catch (const std::exception& e) {
    log(*in, fmi3Error, std::string(what) + ": " + e.what());
  } catch (...) {
    log(*in, fmi3Error, std::string(what) + ": unknown error");
  }
  in->phase = Phase3::failed;
  return fmi3Error;
}

fmi3Status unsupported(fmi3Instance c, const char* what) {
  if (Instance3* in = instance(c))
    log(*in, fmi3Error, std::string(what) + ": not provided by this FMU");
  return fmi3Error;
}

const Variable& variable(const Instance3& in, fmi3ValueReference vr, VariableType type) {
  const auto vars = in.model->variables();
  if (vr >= vars.size())
    throw InvalidArgument("value reference", std::to_string(vr),
                          "no such variable (0 to " + std::to_string(vars.size() - 1) + ")");
  if (vars[vr].type != type)
    throw InvalidArgument("value reference", std::to_string(vr) + " (" + vars[vr].name + ")",
                          "is a variable of another type");
  return vars[vr];
}

void check_settable(const Instance3& in, const Variable& v) {
  if (v.causality == Causality::input) return;
  if (v.causality == Causality::parameter &&
      (in.phase == Phase3::instantiated || in.phase == Phase3::initialization))
    return;
  throw InvalidArgument(v.name, "(value reference " + std::to_string(v.reference) + ")",
                        v.causality == Causality::parameter
                            ? "a parameter can be set only before fmi3ExitInitializationMode"
                            : "is not an input or a parameter: it cannot be set");
}

void require_arrays(const void* vr, const void* values, size_t n, size_t n_values) {
  if (n > 0 && (!vr || !values)) throw InvalidArgument("valueReferences, values", "NULL", "");
  if (n != n_values)
    throw InvalidArgument(
        "nValues", std::to_string(n_values),
        "must be nValueReferences (" + std::to_string(n) + "): every variable here is a scalar");
}

fmi3Instance make(fmi3String name, fmi3String token, fmi3String resources, bool cosimulation,
                  fmi3InstanceEnvironment environment, fmi3LogMessageCallback logger) {
  std::unique_ptr<Instance3> in;
  try {
    in = std::make_unique<Instance3>();
  } catch (...) {
    return nullptr;
  }
  in->name = name ? name : "";
  in->environment = environment;
  in->logger = logger;
  in->cosimulation = cosimulation;
  try {
    if (!name || !*name) throw InvalidArgument("instanceName", "empty", "must be a name");
    if (!token)
      throw InvalidArgument("instantiationToken", "NULL", "must be the modelDescription's");
    in->model = make_fmu_model(resource_path(resources), token, cosimulation);
  } catch (const std::exception& e) {
    log(*in, fmi3Error, std::string("fmi3Instantiate: ") + e.what());
    return nullptr;
  } catch (...) {
    log(*in, fmi3Error, "fmi3Instantiate: unknown error");
    return nullptr;
  }
  return in.release();
}

// No continuous states and no event indicators: the counts are 0.
fmi3Status no_states3(fmi3Instance c, const char* what, size_t n) {
  return guarded(c, what, kAll3, [&](Instance3& in) {
    if (in.cosimulation)
      throw InvalidArgument(what, "called", "is Model Exchange: this is a Co-Simulation instance");
    if (n != 0) throw InvalidArgument("n", std::to_string(n), "must be 0: this FMU has no states");
    return fmi3OK;
  });
}
}  // namespace
}  // namespace contensou::fmu

using contensou::InvalidArgument;
using contensou::fmu::Instance3;
using contensou::fmu::Phase3;
using contensou::fmu::VariableType;
namespace cf = contensou::fmu;

extern "C" {

const char* fmi3GetVersion(void) {
  return fmi3Version;
}

fmi3Status fmi3SetDebugLogging(fmi3Instance c, fmi3Boolean, size_t, const fmi3String[]) {
  return cf::guarded(c, "fmi3SetDebugLogging", cf::kAll3, [](Instance3&) { return fmi3OK; });
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String name, fmi3String token, fmi3String resources,
                                          fmi3Boolean, fmi3Boolean,
                                          fmi3InstanceEnvironment environment,
                                          fmi3LogMessageCallback logger) {
  return cf::make(name, token, resources, false, environment, logger);
}

fmi3Instance fmi3InstantiateCoSimulation(fmi3String name, fmi3String token, fmi3String resources,
                                         fmi3Boolean, fmi3Boolean, fmi3Boolean event_mode,
                                         fmi3Boolean, const fmi3ValueReference[], size_t,
                                         fmi3InstanceEnvironment environment,
                                         fmi3LogMessageCallback logger,
                                         fmi3IntermediateUpdateCallback) {
  // #lizard forgives: the eleven parameters are the FMI 3.0 standard's signature
  if (event_mode) {  // hasEventMode is false
    if (logger)
      logger(environment, fmi3Error, "logStatusError",
             "fmi3InstantiateCoSimulation: eventModeUsed: this FMU has no event mode");
    return nullptr;
  }
  return cf::make(name, token, resources, true, environment, logger);
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String, fmi3String, fmi3String, fmi3Boolean,
                                               fmi3Boolean, fmi3InstanceEnvironment environment,
                                               fmi3LogMessageCallback logger,
                                               fmi3ClockUpdateCallback, fmi3LockPreemptionCallback,
                                               fmi3UnlockPreemptionCallback) {
  // #lizard forgives: the ten parameters are the FMI 3.0 standard's signature
  if (logger)
    logger(environment, fmi3Error, "logStatusError",
           "fmi3InstantiateScheduledExecution: not provided by this FMU");
  return nullptr;
}

void fmi3FreeInstance(fmi3Instance c) {
  Instance3* in = cf::instance(c);
  if (!in) return;
  in->magic = 0;
  delete in;
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance c, fmi3Boolean, fmi3Float64, fmi3Float64 start,
                                       fmi3Boolean, fmi3Float64) {
  return cf::guarded(c, "fmi3EnterInitializationMode", cf::bit(Phase3::instantiated),
                     [&](Instance3& in) {
                       contensou::require_finite("startTime", start);
                       in.start_time = in.time = start;
                       in.phase = Phase3::initialization;
                       return fmi3OK;
                     });
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance c) {
  return cf::guarded(c, "fmi3ExitInitializationMode", cf::bit(Phase3::initialization),
                     [&](Instance3& in) {
                       in.model->initialize(in.start_time);
                       in.phase = in.cosimulation ? Phase3::step_mode : Phase3::event_mode;
                       return fmi3OK;
                     });
}

fmi3Status fmi3EnterEventMode(fmi3Instance c) {
  return cf::guarded(c, "fmi3EnterEventMode",
                     cf::bit(Phase3::event_mode) | cf::bit(Phase3::continuous), [&](Instance3& in) {
                       in.phase = Phase3::event_mode;
                       return fmi3OK;
                     });
}

fmi3Status fmi3Terminate(fmi3Instance c) {
  return cf::guarded(c, "fmi3Terminate", cf::kRunning3, [&](Instance3& in) {
    in.phase = Phase3::terminated;
    return fmi3OK;
  });
}

fmi3Status fmi3Reset(fmi3Instance c) {
  Instance3* in = cf::instance(c);
  if (!in) return fmi3Error;
  try {
    in->model->reset();
    in->phase = Phase3::instantiated;
    in->time = in->start_time = 0.0;
    return fmi3OK;
  } catch (const std::exception& e) {
    cf::log(*in, fmi3Error, std::string("fmi3Reset: ") + e.what());
  }
  in->phase = Phase3::failed;
  return fmi3Error;
}

fmi3Status fmi3GetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                          fmi3Float64 values[], size_t n_values) {
  return cf::guarded(c, "fmi3GetFloat64", cf::kInitialized3, [&](Instance3& in) {
    cf::require_arrays(vr, values, n, n_values);
    const std::size_t time = in.model->variables().size();  // the independent variable's
    for (size_t i = 0; i < n; ++i) {
      if (vr[i] == time) {
        values[i] = in.time;
        continue;
      }
      cf::variable(in, vr[i], VariableType::real);
      values[i] = in.model->get_real(vr[i]);
    }
    return fmi3OK;
  });
}

fmi3Status fmi3SetFloat64(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                          const fmi3Float64 values[], size_t n_values) {
  return cf::guarded(c, "fmi3SetFloat64", cf::kSettable3, [&](Instance3& in) {
    cf::require_arrays(vr, values, n, n_values);
    for (size_t i = 0; i < n; ++i) {
      cf::check_settable(in, cf::variable(in, vr[i], VariableType::real));
      in.model->set_real(vr[i], values[i]);
    }
    return fmi3OK;
  });
}

fmi3Status fmi3GetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                          fmi3Boolean values[], size_t n_values) {
  return cf::guarded(c, "fmi3GetBoolean", cf::kInitialized3, [&](Instance3& in) {
    cf::require_arrays(vr, values, n, n_values);
    for (size_t i = 0; i < n; ++i) {
      cf::variable(in, vr[i], VariableType::boolean);
      values[i] = in.model->get_boolean(vr[i]);
    }
    return fmi3OK;
  });
}

fmi3Status fmi3SetBoolean(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                          const fmi3Boolean values[], size_t n_values) {
  return cf::guarded(c, "fmi3SetBoolean", cf::kSettable3, [&](Instance3& in) {
    cf::require_arrays(vr, values, n, n_values);
    for (size_t i = 0; i < n; ++i) {
      cf::check_settable(in, cf::variable(in, vr[i], VariableType::boolean));
      in.model->set_boolean(vr[i], values[i]);
    }
    return fmi3OK;
  });
}

fmi3Status fmi3GetString(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                         fmi3String values[], size_t n_values) {
  return cf::guarded(c, "fmi3GetString", cf::kInitialized3, [&](Instance3& in) {
    cf::require_arrays(vr, values, n, n_values);
    in.strings.assign(n, std::string());
    for (size_t i = 0; i < n; ++i) {
      cf::variable(in, vr[i], VariableType::string);
      in.strings[i] = in.model->get_string(vr[i]);
    }
    for (size_t i = 0; i < n; ++i) values[i] = in.strings[i].c_str();
    return fmi3OK;
  });
}

fmi3Status fmi3SetString(fmi3Instance c, const fmi3ValueReference vr[], size_t n,
                         const fmi3String values[], size_t n_values) {
  return cf::guarded(c, "fmi3SetString", cf::kSettable3, [&](Instance3& in) {
    cf::require_arrays(vr, values, n, n_values);
    for (size_t i = 0; i < n; ++i) {
      cf::check_settable(in, cf::variable(in, vr[i], VariableType::string));
      if (!values[i]) throw InvalidArgument("values", "NULL", "must be a string");
      in.model->set_string(vr[i], values[i]);
    }
    return fmi3OK;
  });
}

// The types this FMU has no variables of: nothing to get or set (an empty call succeeds).
#define CONTENSOU_FMI3_NONE(Type, CType)                                                        \
  fmi3Status fmi3Get##Type(fmi3Instance c, const fmi3ValueReference[], size_t n, CType[],       \
                           size_t) {                                                            \
    return cf::guarded(c, "fmi3Get" #Type, cf::kInitialized3, [&](Instance3&) {                 \
      if (n) throw InvalidArgument("valueReferences", "given", "no " #Type " variables here");  \
      return fmi3OK;                                                                            \
    });                                                                                         \
  }                                                                                             \
  fmi3Status fmi3Set##Type(fmi3Instance c, const fmi3ValueReference[], size_t n, const CType[], \
                           size_t) {                                                            \
    return cf::guarded(c, "fmi3Set" #Type, cf::kSettable3, [&](Instance3&) {                    \
      if (n) throw InvalidArgument("valueReferences", "given", "no " #Type " variables here");  \
      return fmi3OK;                                                                            \
    });                                                                                         \
  }
CONTENSOU_FMI3_NONE(Float32, fmi3Float32)
CONTENSOU_FMI3_NONE(Int8, fmi3Int8)
CONTENSOU_FMI3_NONE(UInt8, fmi3UInt8)
CONTENSOU_FMI3_NONE(Int16, fmi3Int16)
CONTENSOU_FMI3_NONE(UInt16, fmi3UInt16)
CONTENSOU_FMI3_NONE(Int32, fmi3Int32)
CONTENSOU_FMI3_NONE(UInt32, fmi3UInt32)
CONTENSOU_FMI3_NONE(Int64, fmi3Int64)
CONTENSOU_FMI3_NONE(UInt64, fmi3UInt64)
#undef CONTENSOU_FMI3_NONE

fmi3Status fmi3GetBinary(fmi3Instance c, const fmi3ValueReference[], size_t, size_t[], fmi3Binary[],
                         size_t) {
  return cf::unsupported(c, "fmi3GetBinary");
}
fmi3Status fmi3SetBinary(fmi3Instance c, const fmi3ValueReference[], size_t, const size_t[],
                         const fmi3Binary[], size_t) {
  return cf::unsupported(c, "fmi3SetBinary");
}
fmi3Status fmi3GetClock(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3Clock[]) {
  return cf::unsupported(c, "fmi3GetClock");
}
fmi3Status fmi3SetClock(fmi3Instance c, const fmi3ValueReference[], size_t, const fmi3Clock[]) {
  return cf::unsupported(c, "fmi3SetClock");
}
fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance c, fmi3ValueReference, size_t*) {
  return cf::unsupported(c, "fmi3GetNumberOfVariableDependencies");
}
fmi3Status fmi3GetVariableDependencies(fmi3Instance c, fmi3ValueReference, size_t[],
                                       fmi3ValueReference[], size_t[], fmi3DependencyKind[],
                                       size_t) {
  return cf::unsupported(c, "fmi3GetVariableDependencies");
}
fmi3Status fmi3GetFMUState(fmi3Instance c, fmi3FMUState*) {
  return cf::unsupported(c, "fmi3GetFMUState");
}
fmi3Status fmi3SetFMUState(fmi3Instance c, fmi3FMUState) {
  return cf::unsupported(c, "fmi3SetFMUState");
}
fmi3Status fmi3FreeFMUState(fmi3Instance c, fmi3FMUState*) {
  return cf::unsupported(c, "fmi3FreeFMUState");
}
fmi3Status fmi3SerializedFMUStateSize(fmi3Instance c, fmi3FMUState, size_t*) {
  return cf::unsupported(c, "fmi3SerializedFMUStateSize");
}
fmi3Status fmi3SerializeFMUState(fmi3Instance c, fmi3FMUState, fmi3Byte[], size_t) {
  return cf::unsupported(c, "fmi3SerializeFMUState");
}
fmi3Status fmi3DeserializeFMUState(fmi3Instance c, const fmi3Byte[], size_t, fmi3FMUState*) {
  return cf::unsupported(c, "fmi3DeserializeFMUState");
}

// sensitivity = J seed, J the outputs' partial derivatives with respect to the inputs.
fmi3Status fmi3GetDirectionalDerivative(fmi3Instance c, const fmi3ValueReference unknowns[],
                                        size_t n_unknowns, const fmi3ValueReference knowns[],
                                        size_t n_knowns, const fmi3Float64 seed[], size_t n_seed,
                                        fmi3Float64 sensitivity[], size_t n_sensitivity) {
  return cf::guarded(c, "fmi3GetDirectionalDerivative", cf::kInitialized3, [&](Instance3& in) {
    cf::require_arrays(knowns, seed, n_knowns, n_seed);
    cf::require_arrays(unknowns, sensitivity, n_unknowns, n_sensitivity);
    for (size_t j = 0; j < n_knowns; ++j) contensou::require_finite("seed", seed[j]);
    for (size_t i = 0; i < n_unknowns; ++i) {
      cf::variable(in, unknowns[i], VariableType::real);
      double sum = 0.0;
      for (size_t j = 0; j < n_knowns; ++j) {
        cf::variable(in, knowns[j], VariableType::real);
        sum += in.model->partial(unknowns[i], knowns[j]) * seed[j];
      }
      sensitivity[i] = sum;
    }
    return fmi3OK;
  });
}

// seed^T J: the adjoint of the same Jacobian.
fmi3Status fmi3GetAdjointDerivative(fmi3Instance c, const fmi3ValueReference unknowns[],
                                    size_t n_unknowns, const fmi3ValueReference knowns[],
                                    size_t n_knowns, const fmi3Float64 seed[], size_t n_seed,
                                    fmi3Float64 sensitivity[], size_t n_sensitivity) {
  return cf::guarded(c, "fmi3GetAdjointDerivative", cf::kInitialized3, [&](Instance3& in) {
    cf::require_arrays(unknowns, seed, n_unknowns, n_seed);
    cf::require_arrays(knowns, sensitivity, n_knowns, n_sensitivity);
    for (size_t i = 0; i < n_unknowns; ++i) contensou::require_finite("seed", seed[i]);
    for (size_t j = 0; j < n_knowns; ++j) {
      cf::variable(in, knowns[j], VariableType::real);
      double sum = 0.0;
      for (size_t i = 0; i < n_unknowns; ++i) {
        cf::variable(in, unknowns[i], VariableType::real);
        sum += seed[i] * in.model->partial(unknowns[i], knowns[j]);
      }
      sensitivity[j] = sum;
    }
    return fmi3OK;
  });
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance c) {
  return cf::unsupported(c, "fmi3EnterConfigurationMode");
}
fmi3Status fmi3ExitConfigurationMode(fmi3Instance c) {
  return cf::unsupported(c, "fmi3ExitConfigurationMode");
}
fmi3Status fmi3GetIntervalDecimal(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3Float64[],
                                  fmi3IntervalQualifier[]) {
  return cf::unsupported(c, "fmi3GetIntervalDecimal");
}
fmi3Status fmi3GetIntervalFraction(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                   fmi3UInt64[], fmi3IntervalQualifier[]) {
  return cf::unsupported(c, "fmi3GetIntervalFraction");
}
fmi3Status fmi3GetShiftDecimal(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3Float64[]) {
  return cf::unsupported(c, "fmi3GetShiftDecimal");
}
fmi3Status fmi3GetShiftFraction(fmi3Instance c, const fmi3ValueReference[], size_t, fmi3UInt64[],
                                fmi3UInt64[]) {
  return cf::unsupported(c, "fmi3GetShiftFraction");
}
fmi3Status fmi3SetIntervalDecimal(fmi3Instance c, const fmi3ValueReference[], size_t,
                                  const fmi3Float64[]) {
  return cf::unsupported(c, "fmi3SetIntervalDecimal");
}
fmi3Status fmi3SetIntervalFraction(fmi3Instance c, const fmi3ValueReference[], size_t,
                                   const fmi3UInt64[], const fmi3UInt64[]) {
  return cf::unsupported(c, "fmi3SetIntervalFraction");
}
fmi3Status fmi3SetShiftDecimal(fmi3Instance c, const fmi3ValueReference[], size_t,
                               const fmi3Float64[]) {
  return cf::unsupported(c, "fmi3SetShiftDecimal");
}
fmi3Status fmi3SetShiftFraction(fmi3Instance c, const fmi3ValueReference[], size_t,
                                const fmi3UInt64[], const fmi3UInt64[]) {
  return cf::unsupported(c, "fmi3SetShiftFraction");
}
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance c) {
  return cf::guarded(c, "fmi3EvaluateDiscreteStates", cf::kInitialized3,
                     [](Instance3&) { return fmi3OK; });
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance c, fmi3Boolean* update, fmi3Boolean* terminate,
                                    fmi3Boolean* nominals, fmi3Boolean* values,
                                    fmi3Boolean* next_defined, fmi3Float64* next) {
  return cf::guarded(c, "fmi3UpdateDiscreteStates", cf::bit(Phase3::event_mode), [&](Instance3&) {
    if (!update || !terminate || !nominals || !values || !next_defined || !next)
      throw InvalidArgument("fmi3UpdateDiscreteStates", "a NULL pointer", "six pointers expected");
    *update = *terminate = *nominals = *values = *next_defined = fmi3False;
    *next = 0.0;
    return fmi3OK;
  });
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance c) {
  return cf::guarded(c, "fmi3EnterContinuousTimeMode", cf::bit(Phase3::event_mode),
                     [&](Instance3& in) {
                       in.phase = Phase3::continuous;
                       return fmi3OK;
                     });
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance c, fmi3Boolean, fmi3Boolean* enter_event,
                                       fmi3Boolean* terminate) {
  return cf::guarded(
      c, "fmi3CompletedIntegratorStep", cf::bit(Phase3::continuous), [&](Instance3&) {
        if (!enter_event || !terminate)
          throw InvalidArgument("enterEventMode, terminateSimulation", "NULL", "must be pointers");
        *enter_event = *terminate = fmi3False;
        return fmi3OK;
      });
}

fmi3Status fmi3SetTime(fmi3Instance c, fmi3Float64 time) {
  return cf::guarded(c, "fmi3SetTime", cf::bit(Phase3::event_mode) | cf::bit(Phase3::continuous),
                     [&](Instance3& in) {
                       contensou::require_finite("time", time);
                       in.time = time;
                       return fmi3OK;
                     });
}

fmi3Status fmi3SetContinuousStates(fmi3Instance c, const fmi3Float64[], size_t n) {
  return cf::no_states3(c, "fmi3SetContinuousStates", n);
}
fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance c, fmi3Float64[], size_t n) {
  return cf::no_states3(c, "fmi3GetContinuousStateDerivatives", n);
}
fmi3Status fmi3GetEventIndicators(fmi3Instance c, fmi3Float64[], size_t n) {
  return cf::no_states3(c, "fmi3GetEventIndicators", n);
}
fmi3Status fmi3GetContinuousStates(fmi3Instance c, fmi3Float64[], size_t n) {
  return cf::no_states3(c, "fmi3GetContinuousStates", n);
}
fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance c, fmi3Float64[], size_t n) {
  return cf::no_states3(c, "fmi3GetNominalsOfContinuousStates", n);
}
fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance c, size_t* n) {
  return cf::guarded(c, "fmi3GetNumberOfEventIndicators", cf::kAll3, [&](Instance3&) {
    if (!n) throw InvalidArgument("nEventIndicators", "NULL", "must be a pointer");
    *n = 0;
    return fmi3OK;
  });
}
fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance c, size_t* n) {
  return cf::guarded(c, "fmi3GetNumberOfContinuousStates", cf::kAll3, [&](Instance3&) {
    if (!n) throw InvalidArgument("nContinuousStates", "NULL", "must be a pointer");
    *n = 0;
    return fmi3OK;
  });
}

fmi3Status fmi3EnterStepMode(fmi3Instance c) {
  return cf::unsupported(c, "fmi3EnterStepMode");
}
fmi3Status fmi3GetOutputDerivatives(fmi3Instance c, const fmi3ValueReference[], size_t,
                                    const fmi3Int32[], fmi3Float64[], size_t) {
  return cf::unsupported(c, "fmi3GetOutputDerivatives");
}

fmi3Status fmi3DoStep(fmi3Instance c, fmi3Float64 t, fmi3Float64 h, fmi3Boolean,
                      fmi3Boolean* event_needed, fmi3Boolean* terminate, fmi3Boolean* early,
                      fmi3Float64* last) {
  return cf::guarded(c, "fmi3DoStep", cf::bit(Phase3::step_mode), [&](Instance3& in) {
    if (!event_needed || !terminate || !early || !last)
      throw InvalidArgument("fmi3DoStep", "a NULL pointer", "four result pointers expected");
    contensou::require_finite("currentCommunicationPoint", t);
    contensou::require_positive("communicationStepSize", h);
    if (std::abs(t - in.time) > 1e-9 * std::max(1.0, std::abs(in.time)))
      throw InvalidArgument(
          "currentCommunicationPoint", contensou::format_value(t),
          "must be the end of the previous step, " + contensou::format_value(in.time) + " s");
    in.model->do_step(t, h);
    in.time = t + h;
    *event_needed = *terminate = *early = fmi3False;
    *last = in.time;
    return fmi3OK;
  });
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance c, fmi3ValueReference, fmi3Float64) {
  return cf::unsupported(c, "fmi3ActivateModelPartition");
}

}  // extern "C"
