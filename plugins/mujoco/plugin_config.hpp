// The configuration of the MuJoCo plugin "contensou.friction": its keys read and checked
// against their ranges (docs/mujoco.md, "Valid values"); a bad value is an error at init
// naming the key, the value as written and the range (fail: mju_error). Internal to the plugin.
#pragma once

#include <mujoco/mujoco.h>

#include <string>
#include <utility>
#include <vector>

namespace contensou::mujoco_plugin {

inline constexpr const char* kName = "contensou.friction";

enum class Law { fractional, exact, set_valued };

// The plugin instance's configuration (docs/mujoco.md, "The plugin").
struct Config {
  std::vector<std::pair<std::string, std::string>> pair_names;
  std::string profile = "uniform";
  double friction = 0.0;
  double kappa = 1.0;
  double radius = 0.0;     // 0: from the stiffness
  double stiffness = 0.0;  // N/m^3
  Law law = Law::fractional;
  bool ellipsoid = false;  // set-valued: the fitted ellipsoid instead of the exact surface
  double regularization = 1e-4;
  double tolerance = 1e-8;
};

// The valid lengths [m]: MuJoCo holds no position beyond mjMAXVAL and divides by nothing below
// mjMINVAL.
inline constexpr double kShortest = mjMINVAL, kLongest = mjMAXVAL;

// mju_error naming the plugin (does not return).
[[noreturn]] void fail(const std::string& message);
// x with 6 significant digits, as the messages write numbers.
std::string format(double x);
// The text of config `key` ("" when absent or empty).
std::string attribute(const mjModel* m, int instance, const char* key);
// A value of config `key` (as given: `text`) outside [lo, hi] (unit; why: what the range means)
// is an error naming all of them.
void require_within(const char* key, const std::string& text, double x, double lo, double hi,
                    const std::string& unit, const std::string& why);
// config 'pairs': "tire road; tire road; ...".
std::vector<std::pair<std::string, std::string>> read_pair_names(const mjModel* m, int instance);
// Every key of an instance, checked (fail on the first bad one).
Config read_config(const mjModel* m, int instance);

}  // namespace contensou::mujoco_plugin
