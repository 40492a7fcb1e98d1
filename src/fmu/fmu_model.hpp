// What an FMU binary's model gives the FMI glue (fmi2_glue.cpp): its variables and their values,
// initialisation and steps. The glue owns the FMI state machine, the checks of the calls, the
// logger and the C boundary: every exception a model throws becomes fmi2Error with its message.
// Each FMU binary (the law's, the gear's) defines make_fmu_model.
#pragma once

#include <memory>
#include <span>
#include <string>

namespace contensou::fmu {

enum class Causality { input, output, parameter, local };
enum class VariableType { real, boolean, string };

struct Variable {
  unsigned reference = 0;
  const char* name = "";
  Causality causality = Causality::local;
  VariableType type = VariableType::real;
};

class FmuModel {
 public:
  virtual ~FmuModel() = default;
  // The model's variables, indexed by value reference (variables()[vr].reference == vr).
  virtual std::span<const Variable> variables() const = 0;
  // Setters and getters; throw InvalidArgument (naming the variable and the value) to refuse.
  virtual void set_real(unsigned vr, double value) = 0;
  virtual double get_real(unsigned vr) = 0;
  virtual void set_boolean(unsigned vr, bool value);
  virtual bool get_boolean(unsigned vr);
  virtual void set_string(unsigned vr, const std::string& value);
  virtual std::string get_string(unsigned vr);
  // After the parameters are set: ready to step from start_time.
  virtual void initialize(double start_time) = 0;
  // Co-Simulation: from t to t + h with the inputs held.
  virtual void do_step(double t, double h) = 0;
  // d(output unknown)/d(input known) at the current inputs; throws if the model has none.
  virtual double partial(unsigned unknown, unsigned known);
  // Back to the state after instantiation (the parameters' start values).
  virtual void reset() = 0;
};

// The model of this binary, from its resources folder (a local path) and the guid the host read
// from modelDescription.xml; throws (a missing or damaged resource, another guid).
std::unique_ptr<FmuModel> make_fmu_model(const std::string& resource_dir, const std::string& guid,
                                         bool cosimulation);

// The local path of an FMI resource location: a file:// URI (file:/path, file:///path,
// file://localhost/path, percent-encoded) or a plain path. Throws InvalidArgument otherwise.
std::string resource_path(const char* location);

// The whole file, or throws naming the path and the reason (e.g. a missing resource).
std::string read_resource_file(const std::string& path);

// "{8-4-4-4-12}" from a hash of `text` (FNV-1a, two seeds): the guid of an export.
std::string guid_of(const std::string& text);

}  // namespace contensou::fmu
