#include "contensou/identification/effect_model.hpp"

#include "contensou/friction/error.hpp"

#include <limits>

namespace contensou {

namespace {
constexpr ParameterInfo kInfo[kModelParameters] = {{"F0_N", "N", 0.0},
                                                   {"a", "1", 1.0},
                                                   {"M0_Nm", "N m", 0.0},
                                                   {"m", "1", 64.0 / 9.0},
                                                   {"kx", "1", 0.0},
                                                   {"ky", "1", 0.0},
                                                   {"kappa", "1", 1.0},
                                                   {"speed_drop", "1", 0.0},
                                                   {"speed_ref_mps", "m/s", 1.0},
                                                   {"offset_Fx_N", "N", 0.0},
                                                   {"offset_Fy_N", "N", 0.0},
                                                   {"offset_Mz_Nm", "N m", 0.0},
                                                   {"crosstalk_Fx_from_Fy", "1", 0.0},
                                                   {"crosstalk_Fx_from_Mz", "1/m", 0.0},
                                                   {"crosstalk_Fy_from_Fx", "1", 0.0},
                                                   {"crosstalk_Fy_from_Mz", "1/m", 0.0},
                                                   {"crosstalk_Mz_from_Fx", "m", 0.0},
                                                   {"crosstalk_Mz_from_Fy", "m", 0.0},
                                                   {"shape_blend", "1", 0.0},
                                                   {"profile_b1", "1", 0.0},
                                                   {"profile_b2", "1", 0.0}};
}  // namespace

const ParameterInfo& parameter_info(int index) {
  if (index < 0 || index >= kModelParameters)
    throw InvalidArgument("parameter index", std::to_string(index), "out of range");
  return kInfo[index];
}

int parameter_index_by_name(const std::string& name) {
  for (int i = 0; i < kModelParameters; ++i)
    if (name == kInfo[i].name) return i;
  return -1;
}

ParameterBounds parameter_bounds(int index) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (index) {
    case kF0:
    case kA:
    case kM0:
    case kMShape:
      return {1e-12, inf};
    case kKappa:
      return {0.05, 20.0};
    case kSpeedRef:
      return {1e-3, inf};
    case kSpeedDrop:
      return {-0.9, 0.95};
    case kProfileB1:
    case kProfileB2:
      return {-0.45, 0.45};
    case kKx:
    case kKy:
      return {-0.95, 0.95};
    case kShapeBlend:
      return {0.0, 1.0};
    default:
      return {-inf, inf};
  }
}

int offset_parameter(int channel) {
  return kOffsetFx + channel;
}

int crosstalk_parameter(int channel, int source) {
  // Order: Fx<-Fy, Fx<-Mz, Fy<-Fx, Fy<-Mz, Mz<-Fx, Mz<-Fy.
  const int slot = source < channel ? source : source - 1;
  return kXFxFy + 2 * channel + slot;
}

ModelSpec base_model_spec(double radius_m, std::optional<double> normal_load_n) {
  ModelSpec s;
  s.radius_m = radius_m;
  s.normal_load_n = normal_load_n;
  for (int i = 0; i < kModelParameters; ++i) s.value[i] = kInfo[i].null_value;
  for (int i : {kF0, kA, kM0, kMShape, kKx}) s.free[i] = true;
  s.exact_laws = std::make_shared<ExactLawCache>(radius_m, std::nullopt, s.exact_tolerance);
  return s;
}

}  // namespace contensou
