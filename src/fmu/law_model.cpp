// The law FMU's model: Fx, Fy, Mz of a contact patch from vx, vy, omega and the normal load N,
// with the exact law's tables or the fractional law read from resources/law.txt
// (law_resource.hpp). Both laws are linear in the load (the pressure p* = N / (R^2 L), theory.md
// section 4; F0, M0, Mk proportional to N for the fractional law), so the FMU evaluates the law
// of the unit load and scales it by N: d(F)/dN is that unit law, and the directional
// derivatives are the law's Jacobian d(Fx, Fy, Mz)/d(vx, vy, omega) times N.
#include <Eigen/Core>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/fractional_law.hpp"
#include "fmu_model.hpp"
#include "law_resource.hpp"

namespace contensou::fmu {
namespace {

enum LawVariable : unsigned {
  kVx,
  kVy,
  kOmega,
  kLoad,
  kFx,
  kFy,
  kMz,
  kRadius,
  kFriction,
  kKappa,
  kShiftX,
  kShiftY,
  kErrorBound,
  kLawVariables
};

constexpr std::array<Variable, kLawVariables> kVariables{{
    {kVx, "vx", Causality::input, VariableType::real},
    {kVy, "vy", Causality::input, VariableType::real},
    {kOmega, "omega", Causality::input, VariableType::real},
    {kLoad, "N", Causality::input, VariableType::real},
    {kFx, "Fx", Causality::output, VariableType::real},
    {kFy, "Fy", Causality::output, VariableType::real},
    {kMz, "Mz", Causality::output, VariableType::real},
    {kRadius, "patch.radius", Causality::local, VariableType::real},
    {kFriction, "patch.friction", Causality::local, VariableType::real},
    {kKappa, "patch.kappa", Causality::local, VariableType::real},
    {kShiftX, "patch.kx", Causality::local, VariableType::real},
    {kShiftY, "patch.ky", Causality::local, VariableType::real},
    {kErrorBound, "law.error_bound", Causality::local, VariableType::real},
}};

class LawModel final : public FmuModel {
 public:
  explicit LawModel(LawResource resource) : r_(std::move(resource)) {
    if (r_.exact) {
      unit_ = r_.exact->parameters;
      unit_.pressure = 1.0 / (r_.exact->radius * r_.exact->radius * r_.exact->load_area);
    } else {
      if (!(r_.normal_load_n > 0.0))
        throw std::runtime_error("law.txt: the fractional law needs the export load > 0");
      unit_fractional_ = *r_.fractional;
      unit_fractional_.F0 /= r_.normal_load_n;
      unit_fractional_.M0 /= r_.normal_load_n;
      unit_fractional_.Mk /= r_.normal_load_n;
    }
    reset();
  }

  std::span<const Variable> variables() const override { return kVariables; }

  void set_real(unsigned vr, double v) override {
    const char* name = kVariables[vr].name;
    require_finite(name, v);
    if (vr == kLoad && v < 0.0)
      throw InvalidArgument("N", format_value(v), "the normal load must be >= 0 [N]");
    input_[vr] = v;
    dirty_ = true;
  }

  double get_real(unsigned vr) override {
    switch (vr) {
      case kVx:
      case kVy:
      case kOmega:
      case kLoad:
        return input_[vr];
      case kFx:
      case kFy:
      case kMz:
        evaluate();
        return output_[vr - kFx];
      case kRadius:
        return r_.radius_m;
      case kFriction:
        return r_.friction;
      case kKappa:
        return r_.kappa;
      case kShiftX:
        return r_.kx;
      case kShiftY:
        return r_.ky;
      default:
        return r_.error_bound;
    }
  }

  void initialize(double) override { evaluate(); }
  void do_step(double, double) override { evaluate(); }

  double partial(unsigned unknown, unsigned known) override {
    if (unknown < kFx || unknown > kMz || known > kLoad)
      throw InvalidArgument("directional derivative",
                            std::string(kVariables[unknown].name) + " by " + kVariables[known].name,
                            "only of the outputs Fx, Fy, Mz by the inputs vx, vy, omega, N");
    evaluate();
    const int row = static_cast<int>(unknown - kFx);
    return known == kLoad ? unit_out_[row] : input_[kLoad] * jacobian_(row, int(known));
  }

  void reset() override {
    input_ = {0.0, 0.0, 0.0, r_.normal_load_n};
    dirty_ = true;
  }

 private:
  // The unit-load law and its Jacobian at the inputs, then the outputs (finite, or an error).
  void evaluate() {
    if (!dirty_) return;
    const Kinematics<double> k{input_[kVx], input_[kVy], input_[kOmega]};
    Resultants<double> unit;
    if (r_.exact) {
      const ExactLawWithJacobian e = exact_law_resultants_with_jacobian(*r_.exact, unit_, k);
      unit = e.resultants;
      jacobian_ = e.jacobian;
    } else {
      const FractionalWithJacobian f = fractional_resultants_with_jacobian(unit_fractional_, k);
      unit = f.resultants;
      jacobian_ = f.jacobian;
    }
    unit_out_ = {unit.Fx, unit.Fy, unit.Mz};
    const double N = input_[kLoad];
    for (int i = 0; i < 3; ++i) output_[i] = N * unit_out_[i];
    if (!(std::isfinite(output_[0]) && std::isfinite(output_[1]) && std::isfinite(output_[2]) &&
          (N * jacobian_).allFinite()))
      throw InvalidArgument("vx, vy, omega, N",
                            format_value(k.vx) + ", " + format_value(k.vy) + ", " +
                                format_value(k.omega) + ", " + format_value(N),
                            "the resultants or their derivatives overflow a double");
    dirty_ = false;
  }

  LawResource r_;
  ExactLawParameters<double> unit_;
  FractionalLaw<double> unit_fractional_;
  std::array<double, 4> input_{};
  std::array<double, 3> output_{}, unit_out_{};
  Eigen::Matrix3d jacobian_ = Eigen::Matrix3d::Zero();
  bool dirty_ = true;
};

}  // namespace

std::unique_ptr<FmuModel> make_fmu_model(const std::string& resource_dir, const std::string& guid,
                                         bool) {
  const std::string path = resource_dir + "/" + kLawResourceName;
  LawResource r = read_law_resource(read_resource_file(path), path);
  if (r.guid != guid)
    throw InvalidArgument("fmuGUID", guid,
                          "is not the guid of " + path + " (" + r.guid +
                              "): the modelDescription.xml and the resources are of different "
                              "exports");
  return std::make_unique<LawModel>(std::move(r));
}

}  // namespace contensou::fmu
