// The gear FMU's model (Co-Simulation): the one-wheel landing gear of the shimmy demo driven by
// the host's forward speed and brake command, integrated by CVODE inside (LandingStepper,
// landing_simulation.hpp). Its parameters are the demo's configuration keys, read at
// initialisation by the demo's own reader (parse_shimmy_config: the same ranges, relations and
// messages as contensou-shimmy's); its outputs the columns of the demo's time history.
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <vector>

#include "config.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"
#include "contensou/gear/landing_simulation.hpp"
#include "fmu_model.hpp"
#include "gear_variables.hpp"
#include "history.hpp"

namespace contensou::fmu {
namespace {

// A parameter's value as JSON, from its start text.
nlohmann::json start_value(const GearVariable& v) {
  switch (v.variable.type) {
    case VariableType::real:
      return std::stod(v.start);
    case VariableType::boolean:
      return v.start == "true";
    case VariableType::string:
      return v.start;
  }
  return nullptr;
}

class GearFmuModel final : public FmuModel {
 public:
  GearFmuModel() { reset(); }

  std::span<const Variable> variables() const override { return gear_variable_table(); }

  void set_real(unsigned vr, double v) override {
    const GearVariable& var = gear_variables()[vr];
    require_finite(var.name.c_str(), v);
    if (vr == kGearForwardSpeed) {
      inputs_.forward_speed_mps = v;
    } else if (vr == kGearBrakeTorque) {
      require_non_negative(var.name.c_str(), v);
      inputs_.brake_torque_nm = v;
    } else {
      set_parameter(vr, v);
    }
    // An input set in initialisation mode is the start of the run.
    if (stepper_ && vr <= kGearBrakeTorque && !running_) stepper_.reset();
  }

  double get_real(unsigned vr) override {
    if (vr == kGearForwardSpeed) return inputs_.forward_speed_mps;
    if (vr == kGearBrakeTorque) return inputs_.brake_torque_nm;
    const GearVariable& var = gear_variables()[vr];
    if (var.variable.causality == Causality::parameter) return values_[vr].get<double>();
    ensure_stepper();
    if (outputs_.empty()) record();
    return outputs_[vr - kGearFirstOutput];
  }

  void set_boolean(unsigned vr, bool v) override { set_parameter(vr, v); }
  bool get_boolean(unsigned vr) override { return values_[vr].get<bool>(); }
  void set_string(unsigned vr, const std::string& v) override { set_parameter(vr, v); }
  std::string get_string(unsigned vr) override { return values_[vr].get<std::string>(); }

  void initialize(double start_time) override {
    if (start_time < 0.0)
      throw InvalidArgument("startTime", format_value(start_time),
                            "must be >= 0 (the scenario's time: touchdown at "
                            "scenario.touchdown_time_s)");
    stepper_.reset();
    ensure_stepper();
    if (start_time > 0.0) stepper_->advance_to(start_time);
    record();
    running_ = true;
  }

  void do_step(double t, double h) override {
    stepper_->set_inputs(inputs_);
    stepper_->advance_to(t + h);
    record();
  }

  void reset() override {
    const auto& vars = gear_variables();
    values_.assign(vars.size(), nullptr);
    for (std::size_t k = 0; k < vars.size(); ++k)
      if (vars[k].variable.causality == Causality::parameter) values_[k] = start_value(vars[k]);
    inputs_ = {std::stod(vars[kGearForwardSpeed].start), 0.0};
    stepper_.reset();
    outputs_.clear();
    running_ = false;
  }

 private:
  template <class T>
  void set_parameter(unsigned vr, const T& v) {
    values_[vr] = v;
    stepper_.reset();
    outputs_.clear();
  }

  // The configuration from the parameters, through the demo's reader (errors name the key).
  void ensure_stepper() {
    if (stepper_) return;
    nlohmann::json j = nlohmann::json::object();
    const auto& vars = gear_variables();
    std::string contact = "coupled";
    for (std::size_t k = 0; k < vars.size(); ++k) {
      if (vars[k].variable.causality != Causality::parameter) continue;
      if (vars[k].key.empty()) {
        contact = values_[k].get<std::string>();
        continue;
      }
      nlohmann::json* node = &j;
      const std::string& key = vars[k].key;
      for (std::size_t a = 0, b; (b = key.find('.', a)) != std::string::npos; a = b + 1)
        node = &(*node)[key.substr(a, b - a)];
      (*node)[key.substr(key.rfind('.') + 1)] = values_[k];
    }
    const app::ShimmyConfig config = app::parse_shimmy_config(j.dump(1), "the FMU's parameters");
    const GearModel model = make_gear_model(config.gear, contact_model_from_string(contact));
    stepper_ = std::make_unique<LandingStepper>(model, config.solver, inputs_);
    outputs_.clear();
  }

  void record() {
    const LandingSample s = stepper_->sample();
    const std::vector<double> row = app::history_row(s, stepper_->model().config.structure);
    const auto& vars = gear_variables();
    outputs_.clear();
    for (std::size_t k = kGearFirstOutput;
         k < vars.size() && vars[k].variable.causality == Causality::output; ++k)
      outputs_.push_back(row[static_cast<std::size_t>(vars[k].history_column)]);
    for (double v : outputs_)
      if (!std::isfinite(v))
        throw std::runtime_error("the gear's state is not finite at t = " + format_value(s.t) +
                                 " s");
  }

  std::vector<nlohmann::json> values_;
  LandingInputs inputs_;
  std::unique_ptr<LandingStepper> stepper_;
  std::vector<double> outputs_;
  bool running_ = false;
};

}  // namespace

std::unique_ptr<FmuModel> make_fmu_model(const std::string&, const std::string& guid,
                                         bool cosimulation) {
  if (!cosimulation)
    throw InvalidArgument("fmuType", "fmi2ModelExchange",
                          "the gear FMU is Co-Simulation only (CVODE inside)");
  if (guid != gear_guid())
    throw InvalidArgument(
        "fmuGUID", guid,
        "is not this binary's (" + gear_guid() + "): the modelDescription.xml is of another build");
  return std::make_unique<GearFmuModel>();
}

}  // namespace contensou::fmu
