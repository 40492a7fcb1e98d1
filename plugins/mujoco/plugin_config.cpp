// The plugin's configuration keys (plugin_config.hpp).
#include "plugin_config.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace contensou::mujoco_plugin {
[[noreturn]] void fail(const std::string& message) {
  mju_error("%s", (std::string(kName) + ": " + message).c_str());
  std::abort();  // mju_error does not return
}

std::string attribute(const mjModel* m, int instance, const char* key) {
  const char* v = mj_getPluginConfig(m, instance, key);
  return v ? std::string(v) : std::string();
}

// config `key` as a positive finite number, or `fallback` when the key is absent (MuJoCo
// compiles an empty value as an absent key: the plugin cannot tell them apart, docs/mujoco.md).
static double number(const mjModel* m, int instance, const char* key, double fallback) {
  const std::string s = attribute(m, instance, key);
  if (s.empty()) return fallback;
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  if (end == s.c_str() || *end != '\0' || !std::isfinite(x) || !(x > 0))
    fail(std::string("config '") + key + "' = '" + s + "' is not a positive number");
  return x;
}

std::string format(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

// The valid ranges of the numeric keys (docs/mujoco.md, "Valid values"). MuJoCo holds no
// position or speed beyond mjMAXVAL = 1e10 (it resets the simulation) and divides by nothing
// below mjMINVAL = 1e-15, so lengths lie in [1e-15, 1e10] m, a patch no wider than its tire
// geom (its bounding radius). With these, the law's numbers stay finite for any normal force
// below 1e270 N: the exact law's v / R <= 1e25, the fractional law's largest slope
// 16 max(F0, M0) max(1, R) / eps (fractional_law.hpp) <= 1.6e38 times N for f <= 100.
constexpr double kFrictionMin = 1e-6, kFrictionMax = 100.0;
constexpr double kKappaMin = 1e-3, kKappaMax = 1e3;
constexpr double kEpsMin = mjMINVAL, kEpsMax = mjMAXVAL;  // [m/s]

// A value of config `key` (as given: `text`) outside its range [lo, hi] (unit; why: what the
// range means) is an error naming all of them.
void require_within(const char* key, const std::string& text, double x, double lo, double hi,
                    const std::string& unit, const std::string& why) {
  // The range as the message shows it (6 digits) is the range enforced: its end is a value the
  // user may give.
  if (x >= std::strtod(format(lo).c_str(), nullptr) &&
      x <= std::strtod(format(hi).c_str(), nullptr))
    return;
  fail(std::string("config '") + key + "' = '" + text + "' is outside [" + format(lo) + ", " +
       format(hi) + "]" + (unit.empty() ? "" : " " + unit) + ": " + why);
}

// config 'pairs': "tire road; tire road; ...".
std::vector<std::pair<std::string, std::string>> read_pair_names(const mjModel* m, int instance) {
  std::vector<std::pair<std::string, std::string>> names;
  std::stringstream pairs(attribute(m, instance, "pairs"));
  std::string item;
  while (std::getline(pairs, item, ';')) {
    std::stringstream words(item);
    std::string a, b, extra;
    if (!(words >> a)) continue;
    if (!(words >> b) || (words >> extra))
      fail("config 'pairs': '" + item + "' is not two geom names (tire road)");
    names.emplace_back(a, b);
  }
  if (names.empty()) fail("config 'pairs' is empty: name the geom pairs (tire road; ...)");
  return names;
}

// config 'tolerance': the exact law's requested error bound, in (1e-14, 1e-2) (make_exact_law);
// the limit surface's integrals', in [1e-14, 1e-6] (make_limit_surface); no fractional key.
static double read_tolerance(const mjModel* m, int instance, Law law) {
  const std::string s = attribute(m, instance, "tolerance");
  if (s.empty()) return 1e-8;
  if (law == Law::fractional)
    fail("config 'tolerance' = '" + s +
         "' applies to laws 'exact' and 'set-valued' only (law is 'fractional')");
  const double t = number(m, instance, "tolerance", 1e-8);
  const bool exact = law == Law::exact;
  if (exact ? !(t > 1e-14 && t < 1e-2) : !(t >= 1e-14 && t <= 1e-6))
    fail("config 'tolerance' = '" + s + "' is outside " +
         (exact ? "(1e-14, 1e-2) for law 'exact'" : "[1e-14, 1e-6] for law 'set-valued'"));
  return t;
}

// config 'law', 'surface' and 'regularization' into c (a key of another law is an error).
static void read_law(const mjModel* m, int instance, Config& c) {
  const std::string law = attribute(m, instance, "law");
  if (law.empty() || law == "fractional")
    c.law = Law::fractional;
  else if (law == "exact")
    c.law = Law::exact;
  else if (law == "set-valued")
    c.law = Law::set_valued;
  else
    fail("config 'law' = '" + law + "': use fractional, exact or set-valued");
  const std::string surface = attribute(m, instance, "surface");
  if (!surface.empty() && c.law != Law::set_valued)
    fail("config 'surface' = '" + surface + "' needs law 'set-valued' (law is '" +
         (law.empty() ? std::string("fractional") : law) + "')");
  if (!surface.empty() && surface != "exact" && surface != "ellipsoid")
    fail("config 'surface' = '" + surface + "': use exact or ellipsoid");
  c.ellipsoid = surface == "ellipsoid";
  const std::string eps = attribute(m, instance, "regularization");
  if (!eps.empty() && c.law != Law::fractional)
    fail("config 'regularization' applies to law 'fractional' only (law is '" + law + "')");
  c.regularization = number(m, instance, "regularization", 1e-4);
  require_within("regularization", eps, c.regularization, kEpsMin, kEpsMax, "m/s",
                 "the fractional law's eps, within MuJoCo's speeds (from mjMINVAL, its "
                 "smallest divisor, to mjMAXVAL, its largest speed: a larger eps makes every "
                 "speed viscous)");
}

Config read_config(const mjModel* m, int instance) {
  Config c;
  c.pair_names = read_pair_names(m, instance);
  const std::string profile = attribute(m, instance, "profile");
  if (!profile.empty()) c.profile = profile;
  if (c.profile != "uniform" && c.profile != "hertz" && c.profile != "seed-tire")
    fail("config 'profile' = '" + c.profile + "': use uniform, hertz or seed-tire");
  const std::string friction = attribute(m, instance, "friction");
  if (friction.empty()) fail("config 'friction' (f) is required");
  c.friction = number(m, instance, "friction", 0.0);
  require_within("friction", friction, c.friction, kFrictionMin, kFrictionMax, "",
                 "the friction coefficient f (no dry pair has f > 10; for no friction, leave "
                 "the pair out of 'pairs')");
  c.radius = number(m, instance, "radius", 0.0);
  c.stiffness = number(m, instance, "stiffness", 0.0);
  if ((c.radius > 0) == (c.stiffness > 0))
    fail("give exactly one of config 'radius' [m] and 'stiffness' [N/m^3]");
  // The ranges without the model's geometry, when the model is compiled; those of the tire
  // geom's size and the weight it carries when its data is made (check_patch_size).
  if (c.radius > 0)
    require_within("radius", attribute(m, instance, "radius"), c.radius, kShortest, kLongest, "m",
                   "a length MuJoCo holds (mjMINVAL to mjMAXVAL), and at most the tire geom's "
                   "bounding radius");
  else
    require_within("stiffness", attribute(m, instance, "stiffness"), c.stiffness,
                   mjMINVAL / (kLongest * kLongest * kLongest),
                   mjMAXVAL / (kShortest * kShortest * kShortest), "N/m^3",
                   "the patch (N / k)^(1/3) must be a length MuJoCo holds (1e-15 to 1e10 m) for "
                   "some force N it holds (1e-15 to 1e10 N), and at most the tire geom's "
                   "bounding radius under the weight the tire carries");
  read_law(m, instance, c);
  c.kappa = number(m, instance, "kappa", 1.0);
  require_within("kappa", attribute(m, instance, "kappa"), c.kappa, kKappaMin, kKappaMax, "",
                 "the lateral/longitudinal friction ratio (beyond, one direction's friction "
                 "vanishes next to the other's, and the exact law's tables cannot reach a "
                 "tolerance relative to f N)");
  c.tolerance = read_tolerance(m, instance, c.law);
  return c;
}

}  // namespace contensou::mujoco_plugin
