// The gear's key table (contensou/gear/gear_parameters.hpp): the numeric parameters' names in the
// order validate() checks them, SI units in the names, and validate()'s messages, row by row, as
// they were when validate() checked each field by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/gear_parameters.hpp"
#include "contensou/gear/landing_gear.hpp"

namespace contensou {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// validate()'s message for the default gear with `name` set to v ("" if valid).
std::string message(const std::string& name, double v, GearConfig c = {}) {
  *gear_parameter(c, name) = v;
  try {
    validate(c);
  } catch (const InvalidArgument& e) {
    return e.what();
  }
  return "";
}

TEST(GearParameters, NumericNamesInTheOrderOfValidation) {
  const std::vector<std::string> expected{"structure.lateral_mass_kg",
                                          "structure.lateral_stiffness_n_per_m",
                                          "structure.torsional_inertia_kgm2",
                                          "structure.torsional_stiffness_nm_per_rad",
                                          "structure.lateral_damping_ns_per_m",
                                          "structure.torsional_damping_nms_per_rad",
                                          "structure.trail_m",
                                          "structure.offset_m",
                                          "structure.wheel_radius_m",
                                          "structure.wheel_inertia_kgm2",
                                          "structure.fore_aft_stiffness_n_per_m",
                                          "structure.fore_aft_mass_kg",
                                          "structure.fore_aft_damping_ns_per_m",
                                          "structure.wheel_spacing_m",
                                          "structure.freeplay_rad",
                                          "structure.gyroscopic_length_m",
                                          "structure.carcass_lateral_stiffness_n_per_m",
                                          "structure.carcass_torsional_stiffness_nm_per_rad",
                                          "structure.carcass_lateral_damping_ns_per_m",
                                          "structure.carcass_torsional_damping_nms_per_rad",
                                          "tire.inflation_pressure_pa",
                                          "tire.rolling_shift",
                                          "tire.friction.static_coefficient",
                                          "tire.friction.kinetic_coefficient",
                                          "tire.friction.reference_speed",
                                          "tire.friction.exponent",
                                          "tire.regularization_speed",
                                          "tire.longitudinal_relaxation_length_m",
                                          "rolling.relaxation_length_m",
                                          "rolling.cornering_coefficient",
                                          "rolling.aligning_coefficient_m",
                                          "rolling.tread_moment_nm2_per_rad",
                                          "rolling.longitudinal_slip_coefficient",
                                          "scenario.forward_speed_mps",
                                          "scenario.drift_speed_mps",
                                          "scenario.static_load_n",
                                          "scenario.touchdown_time_s",
                                          "scenario.load_ramp_s",
                                          "scenario.end_time_s",
                                          "scenario.initial_torsion_rad",
                                          "scenario.initial_lateral_m",
                                          "scenario.rolling_slip",
                                          "scenario.sliding_slip",
                                          "scenario.brake_on_s",
                                          "scenario.brake_off_s",
                                          "scenario.brake_max_torque_nm",
                                          "scenario.brake_target_slip",
                                          "scenario.brake_slip_band",
                                          "scenario.window_start_s",
                                          "scenario.window_end_s"};
  EXPECT_EQ(gear_parameter_names(), expected);
  GearConfig c;
  EXPECT_EQ(gear_parameter(c, "structure.offset_m"), &c.structure.offset_m);
  EXPECT_EQ(gear_parameter(c, "tire.law_coefficients"), nullptr);  // a name, not a number
  ASSERT_NE(find_gear_parameter("scenario.braking"), nullptr);
  EXPECT_EQ(find_gear_parameter("scenario.braking")->type, ParameterType::flag);
}

// The unit a key's name ends with; keys without a unit suffix are pure numbers, but for the two
// speeds named before the rule.
TEST(GearParameters, SiUnitsInTheNames) {
  const std::vector<std::pair<std::string, std::string>> suffixes{{"_n_per_m", "N/m"},
                                                                  {"_ns_per_m", "N s/m"},
                                                                  {"_nm_per_rad", "N m/rad"},
                                                                  {"_nms_per_rad", "N m s/rad"},
                                                                  {"_nm2_per_rad", "N m^2/rad"},
                                                                  {"_kgm2", "kg m^2"},
                                                                  {"_kg", "kg"},
                                                                  {"_mps", "m/s"},
                                                                  {"_rad", "rad"},
                                                                  {"_pa", "Pa"},
                                                                  {"_nm", "N m"},
                                                                  {"_n", "N"},
                                                                  {"_s", "s"},
                                                                  {"_m", "m"}};
  for (const GearParameter& p : gear_parameters()) {
    if (p.type != ParameterType::number) continue;
    const std::string name(p.name);
    std::string unit = "1";
    for (const auto& [suffix, u] : suffixes)
      if (name.size() > suffix.size() && name.ends_with(suffix)) {
        unit = u;
        break;
      }
    if (name == "tire.friction.reference_speed" || name == "tire.regularization_speed")
      unit = "m/s";
    if (name == "rolling.cornering_coefficient") unit = "1/rad";
    if (name == "rolling.aligning_coefficient_m") unit = "m/rad";
    EXPECT_EQ(std::string(p.unit), unit) << name;
    EXPECT_FALSE(p.help.empty()) << name;
  }
}

TEST(GearParameters, MessagesNameTheKeyAndTheRange) {
  EXPECT_EQ(message("structure.lateral_mass_kg", -1),
            "structure.lateral_mass_kg = -1: must be positive and finite");
  EXPECT_EQ(message("structure.trail_m", kInf), "structure.trail_m = inf: must be finite");
  EXPECT_EQ(message("structure.freeplay_rad", 1),
            "structure.freeplay_rad = 1: must lie in [0, 1) rad (0: no freeplay)");
  EXPECT_EQ(message("structure.fore_aft_stiffness_n_per_m", kNaN),
            "structure.fore_aft_stiffness_n_per_m = nan: must be >= 0 and finite (0: no fore-aft "
            "bending)");
  EXPECT_EQ(message("tire.rolling_shift", kNaN), "tire.rolling_shift = nan: must be finite");
  EXPECT_EQ(message("tire.rolling_shift", -1),
            "tire.rolling_shift = -1: must lie in (-1, 1) so that the pressure stays positive");
  EXPECT_EQ(message("scenario.touchdown_time_s", -0.5),
            "scenario.touchdown_time_s = -0.5: must be >= 0");
  EXPECT_EQ(message("scenario.touchdown_time_s", kInf),
            "scenario.touchdown_time_s = inf: must be finite");
  EXPECT_EQ(message("scenario.sliding_slip", 0.01),
            "scenario.sliding_slip = 0.01: must lie between rolling_slip and 1");
  EXPECT_EQ(message("scenario.brake_on_s", 2),
            "scenario.brake_off_s = 0.95: must come after brake_on_s >= 0");
  EXPECT_EQ(message("scenario.brake_target_slip", 0),
            "scenario.brake_target_slip = 0: must lie in (0, 1)");
  // Checked only while their switch is on.
  GearConfig unbraked;
  unbraked.scenario.braking = false;
  EXPECT_EQ(message("scenario.brake_max_torque_nm", -1, unbraked), "");
  EXPECT_EQ(message("structure.carcass_lateral_damping_ns_per_m", -1), "");
  GearConfig carcass = carcass_from_string_tire(GearConfig{});
  EXPECT_EQ(message("structure.carcass_lateral_damping_ns_per_m", -1, carcass),
            "structure.carcass_lateral_damping_ns_per_m = -1: must be positive and finite");
  EXPECT_EQ(message("structure.carcass_lateral_stiffness_n_per_m", 0, carcass),
            "structure.carcass_lateral_stiffness_n_per_m = 0: must be positive when "
            "structure.carcass_torsional_stiffness_nm_per_rad is (both 0: rigid carcass)");
  EXPECT_EQ(message("structure.wheel_spacing_m", 0.8, carcass),
            "structure.wheel_spacing_m = 0.8: must be 0 with carcass compliance (implemented for "
            "one wheel)");
  // Several bad values: the first in validate()'s order is named.
  GearConfig two;
  two.structure.freeplay_rad = 2;
  two.structure.fore_aft_mass_kg = -1;
  EXPECT_EQ(message("structure.fore_aft_stiffness_n_per_m", -1, two),
            "structure.fore_aft_stiffness_n_per_m = -1: must be >= 0 and finite (0: no fore-aft "
            "bending)");
  EXPECT_EQ(message("structure.fore_aft_stiffness_n_per_m", 0, two),
            "structure.fore_aft_mass_kg = -1: must be positive and finite");
  GearConfig law;
  law.tire.law_coefficients = "guessed";
  EXPECT_THROW(validate(law), InvalidArgument);
  try {
    validate(law);
  } catch (const InvalidArgument& e) {
    EXPECT_EQ(std::string(e.what()),
              "tire.law_coefficients = guessed: must be fitted, asymptotic or seed");
  }
}

TEST(GearParameters, RangesInWords) {
  const auto words = [](const char* name) { return describe_range(*find_gear_parameter(name)); };
  EXPECT_EQ(words("structure.lateral_mass_kg"), "> 0");
  EXPECT_EQ(words("structure.offset_m"), "finite");
  EXPECT_EQ(words("structure.freeplay_rad"), "[0, 1)");
  EXPECT_EQ(words("tire.rolling_shift"), "(-1, 1)");
  EXPECT_EQ(words("tire.law_coefficients"), "fitted, asymptotic or seed");
  EXPECT_EQ(words("scenario.braking"), "true or false");
  EXPECT_EQ(words("scenario.sliding_slip"), "> scenario.rolling_slip and < 1");
  EXPECT_EQ(words("scenario.brake_max_torque_nm"), "> 0 while scenario.braking");
}

}  // namespace
}  // namespace contensou
