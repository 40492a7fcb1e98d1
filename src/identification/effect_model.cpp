#include "contensou/identification/effect_model.hpp"

#include "contensou/friction/error.hpp"

#include <algorithm>
#include <cmath>
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
                                                   {"profile_w1", "1", 1.0},
                                                   {"profile_w2", "1", 1.0},
                                                   {"profile_w3", "1", 1.0},
                                                   {"profile_w4", "1", 1.0},
                                                   {"slip_angle_offset_rad", "rad", 0.0},
                                                   {"spin_offset_radps", "rad/s", 0.0},
                                                   {"patch_growth_q", "1", 0.0},
                                                   {"friction_scale", "1", 1.0},
                                                   {"friction_b1_1", "1", 0.0},
                                                   {"friction_b2_1", "1", 0.0},
                                                   {"friction_b1_2", "1", 0.0},
                                                   {"friction_b2_2", "1", 0.0},
                                                   {"friction_b1_3", "1", 0.0},
                                                   {"friction_b2_3", "1", 0.0},
                                                   {"centre_x", "1", 0.0},
                                                   {"centre_y", "1", 0.0},
                                                   {"contact_ratio", "1", 1.0}};
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
  if (index >= kDependence1 && index <= kDependence3Curve)  // b1, b2 of each slot in turn
    return (index - kDependence1) % 2 == 0 ? ParameterBounds{-0.8, 0.8}
                                           // with |b2| <= 0.19: the factor stays above
                                           : ParameterBounds{-0.19, 0.19};  // 0.01 for |z| <= 1
  switch (index) {
    case kF0:
    case kM0:
      return {1e-12, inf};
    case kA:
      return {1e-12, 4.0};  // a = (2 A^1 / A^0)^2 <= 4 for any p >= 0 (theory.md section 4)
    case kMShape:
      return {4.0, inf};  // m = (2 A^2 / A^3)^2 >= 4 for any p >= 0
    case kKappa:
      return {0.05, 20.0};
    case kSpeedRef:
      return {1e-3, inf};
    case kSpeedDrop:
      return {-0.9, 0.95};
    case kProfileW1:
    case kProfileW2:
    case kProfileW3:
    case kProfileW4:
      return {0.0, 20.0};  // Bernstein weights >= 0: the profile is never negative
    case kKx:
    case kKy:
      return {-0.95, 0.95};
    case kShapeBlend:
      return {0.0, 1.0};
    case kCentreX:
    case kCentreY:
      return {-0.9, 0.9};  // the patch's centre inside the body
    case kContactRatio:
      return {0.1, 1.0};  // the given radius an upper bound
    case kSlipAngleOffset:
      return {-0.2, 0.2};  // 11 degrees: beyond, a rig is not misaligned but mislabelled
    case kPatchGrowth:
      return {-0.5, 2.0};
    default:
      return {-inf, inf};
  }
}

ParameterBounds parameter_bounds(const ModelSpec& spec, int index) {
  if (!spec.admissible_shape && (index == kA || index == kMShape))
    return {1e-12, std::numeric_limits<double>::infinity()};
  return parameter_bounds(index);
}

const char* bound_meaning(int index, bool upper) {
  switch (index) {
    case kA:
      return upper ? "a = 4 is the most any non-negative pressure gives (all of it on the rim): "
                     "the data's sliding force weakens with spin faster than any patch's"
                   : "a at 0: the sliding force does not weaken with spin at all (no patch of "
                     "finite size: the pressure gathered at the centre)";
    case kMShape:
      return upper ? ""
                   : "m = 4 is the least any non-negative pressure gives (all of it on the "
                     "rim): the data's torque falls with sliding more slowly than any "
                     "patch's";
    case kF0:
    case kM0:
      return "the scale at zero: the data carry no such force or torque";
    case kKx:
    case kKy:
      return "|k| = 0.95: at |k| = 1 the shifted pressure p (1 + kx x/R + ky y/R) turns negative "
             "at the rim";
    case kKappa:
      return "kappa at the end of [0.05, 20]: friction across 20 times weaker or stronger than "
             "along is no tread's; another effect is being absorbed";
    case kSpeedDrop:
      return upper ? "beta = 0.95: friction would vanish at high slip speed"
                   : "beta = -0.9: friction nearly doubles with slip speed, beyond any rubber's "
                     "or metal's";
    case kSpeedRef:
      return "w_s = 1 mm/s: the fall is over before the slowest row, so f is the friction at "
             "rest, extrapolated below every row";
    case kSlipAngleOffset:
      return "|delta| = 0.2 rad (11 degrees): beyond a rig's misalignment";
    case kCentreX:
    case kCentreY:
      return "the patch's centre 0.9 R off the body's: at the edge of the body, no rigid "
             "patch's; another effect is being absorbed";
    case kContactRatio:
      return upper ? "the contact as large as the body: the given radius"
                   : "a contact of a tenth of the body's radius: the torque carries no patch's "
                     "size";
    case kShapeBlend:
    case kProfileW1:
    case kProfileW2:
    case kProfileW3:
    case kProfileW4:
      return upper ? "a weight at its upper end (20 times the centre's pressure)"
                   : "a weight at zero: the pressure vanishes around that radius (at the rim for "
                     "the last weight), as a real contact's often does";
    default:
      return "at the end of its range";
  }
}

int dependence_parameter(int slot, bool curve) {
  return kDependence1 + 2 * slot + (curve ? 1 : 0);
}

double Covariate::value(const MeasuredPoint& p) const {
  switch (kind) {
    case Kind::load:
      return p.normal_load ? *p.normal_load : std::numeric_limits<double>::quiet_NaN();
    case Kind::time:
      return p.time ? *p.time : std::numeric_limits<double>::quiet_NaN();
    case Kind::order:
      return static_cast<double>(p.source) * 4294967296.0 + static_cast<double>(p.line);
    case Kind::recorded:
      break;
  }
  return recorded >= 0 && recorded < static_cast<int>(p.recorded.size())
             ? p.recorded[static_cast<std::size_t>(recorded)]
             : std::numeric_limits<double>::quiet_NaN();
}

double Covariate::scaled(const MeasuredPoint& p) const {
  const double x = value(p);
  return std::isfinite(x) && half_range > 0.0 ? std::clamp((x - mid) / half_range, -1.0, 1.0) : 0.0;
}

PointConditions conditions_of(const ModelSpec& s, const MeasuredPoint& p) {
  PointConditions c;
  if (s.reference_load_n && p.normal_load) c.load_ratio = *p.normal_load / *s.reference_load_n;
  for (int j = 0; j < kDependenceSlots; ++j)
    if (s.dependence[j]) c.z[j] = s.dependence[j]->scaled(p);
  return c;
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
