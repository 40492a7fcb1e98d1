#include "contensou/identification/effect_catalogue.hpp"

#include <cstdio>
#include <stdexcept>

namespace contensou {

namespace {

using E = Effect;

// One entry an effect, in enumerator order (checked at compile time below).
constexpr std::array<EffectDescriptor, kEffects> kCatalogue = {{
    {E::shape, "shape",
     "the law's own approximation error: the exact integrals over `--profile` replace the law "
     "(without a profile, a quadratic profile in s = rho^2, p = (1-s)^2 + 2 w1 s(1-s) + w2 s^2 "
     "with w1, w2 >= 0 (never negative; uniform at 1, 1), is identified with them)",
     "blend lambda = 0",
     "the pressure profile's shape matters (the exact integrals fit better than the fractional "
     "law)",
     "more points with psi between 0.1 and 10, where the law's own error is largest"},
    {E::profile_detail, "profile_detail",
     "the identified profile (no `--profile`) one degree richer: its quadratic in rho^2 becomes "
     "a quartic (Bernstein weights w1..w4 >= 0, started at the quadratic raised to degree 4), "
     "tested right after the shape is accepted",
     "the quartic equal to the quadratic",
     "the pressure profile has more structure than a quadratic in rho^2 describes",
     "a measured pressure profile (`--profile`), or more points with psi between 0.1 and 10"},
    {E::profile_correction, "profile_correction",
     "the `--profile` given times a factor q(s) = (1-s)^2 + 2 w1 s(1-s) + w2 s^2 in s = rho^2 "
     "(w1, w2 >= 0: never negative; 1, 1 leaves the profile as given), tested right after the "
     "shape is accepted: the data's pressure is not the profile given",
     "w1 = w2 = 1",
     "the pressure profile given is not the one the data show (they fit it times a factor {})",
     "a pressure measurement of this tire at the rows' loads (a pressure film), or more points "
     "with psi between 0.1 and 10"},
    {E::anisotropy, "anisotropy", "lateral friction kappa f != f", "kappa = 1",
     "friction differs along and across the patch", "a lateral sweep (sliding along y)"},
    {E::pressure_shift_y, "pressure_shift_y", "lateral pressure shift ky (camber, asymmetric load)",
     "ky = 0", "the pressure centre is shifted sideways",
     "pure-spin rows in both spin directions (Fx from ky changes sign with omega)"},
    {E::centre_offset, "centre_offset",
     "the patch's centre at x_c (or y_c) = R centre_x off the body's centre, where the torque is "
     "taken: the patch slides with v + omega z x c and adds x_c Fy - y_c Fx to Mz (a body that "
     "touches off its centre: the physical alternative to a torque offset or crosstalk)",
     "centre_x = 0", "the contact's centre is off the body's centre along {}",
     "a static load at a known point with no motion (the torque sensor's calibration), or pure "
     "spin (v = 0): an off-centre patch slides there and shows a force, an offset does not"},
    {E::contact_radius, "contact_radius",
     "the contact a centred disk of radius c_R R, c_R in [0.1, 1] (the given radius an upper "
     "bound): spin enters as omega c_R R, the torque scales with c_R",
     "c_R = 1", "the contact is smaller than the body (it touches within a smaller radius)",
     "rows across psi = omega R / |v| from 0.1 to 10 (where the spin weakens the sliding force "
     "tells the contact's size), or a print of the contact"},
    {E::speed_dependence, "speed_dependence",
     "f(w) = f (1 - beta (1 - e^(-w/w_s))) at the local slip speed w inside the exact integrals "
     "(`--effective-speed`: outside them, at the effective slip speed w = (v^2 + (2u/3)^2)^(1/2)); "
     "w_s is scanned",
     "beta = 0", "friction changes with the slip speed",
     "a second sweep at another spin speed u = |omega| R (the slip speed changes, the ratio psi "
     "does not)"},
    {E::channel_offset, "channel_offset", "a constant in one measured channel", "0",
     "a channel reads a constant offset (load-cell zero drift)",
     "rows at rest (v = omega = 0) and sweeps with both signs of v and omega (an offset does not "
     "change sign with the motion)"},
    {E::channel_crosstalk, "channel_crosstalk",
     "one channel picks up g times another (load-cell misalignment)", "g = 0",
     "one load-cell channel picks up another (crosstalk)",
     "sweeps in other sliding directions (a crosstalk follows its source channel, friction "
     "follows the motion)"},
    {E::slip_angle_offset, "slip_angle_offset",
     "the rig's slip angle is off by delta: the lateral slip speed is vy + vx tan(delta)",
     "delta = 0", "the rig's slip angle is offset (the wheel is misaligned on the rig)",
     "sweeps in several sliding directions between longitudinal and lateral (an angle offset "
     "turns the force with the sliding direction and changes Fx too; a crosstalk adds a share "
     "of Fx to Fy in every direction)"},
    {E::spin_offset, "spin_offset", "the rig's spin reads omega - omega_0", "omega_0 = 0",
     "the spin reading is offset",
     "pure-spin rows in both spin directions and pure sliding (an offset of omega shows as spin "
     "where none is driven)"},
    {E::patch_growth, "patch_growth",
     "the patch grows with the load, R = R0 (N/N0)^q (at fixed radius the pressure follows the "
     "load)",
     "q = 0", "the contact patch grows with the load",
     "pure-spin rows at several loads (the spin torque grows as N^(1+q), the sliding force as N)"},
    {E::friction_dependence, "friction_dependence",
     "f follows a recorded variable X (the load, the time or row order, any numeric column): "
     "f (1 + b1 z), z = X scaled to [-1, 1] over the data",
     "b1 = 0", "friction follows {}",
     "rows at several values of {} with the other conditions held (a sweep repeated at another "
     "value)"},
    {E::friction_dependence_curve, "friction_dependence_curve",
     "the same along a curve: f (1 + b1 z + b2 (2 z^2 - 1))", "b2 = 0",
     "friction follows {} along a curve",
     "rows at three or more values of {} (a curve needs more than two)"},
    {E::noise_growth, "noise_growth",
     "the noise grows with the value, sigma = a + b |y| per channel (a load cell's)", "b = 0",
     "the noise grows with the value (sigma = a + b |y| per channel, as a load cell's)",
     "repeated rows at the same point, small and large loads (their scatter shows how the noise "
     "grows)"},
}};

constexpr bool in_order() {
  for (int i = 0; i < kEffects; ++i)
    if (static_cast<int>(kCatalogue[static_cast<std::size_t>(i)].effect) != i) return false;
  return true;
}
static_assert(in_order(), "the catalogue lists every effect once, in enumerator order");
static_assert(static_cast<int>(Effect::noise_growth) + 1 == kEffects,
              "kEffects counts the enumerators");

std::string with_detail(const char* text, const std::string& detail) {
  std::string s = text;
  for (std::size_t at = s.find("{}"); at != std::string::npos; at = s.find("{}"))
    s.replace(at, 2, detail.empty() ? std::string("a recorded variable") : detail);
  return s;
}

}  // namespace

const EffectDescriptor& describe(Effect e) {
  return kCatalogue[static_cast<std::size_t>(e)];
}

bool effect_by_name(const std::string& name, Effect* e) {
  for (const EffectDescriptor& d : kCatalogue)
    if (name == d.name) {
      *e = d.effect;
      return true;
    }
  return false;
}

std::string profile_correction_detail(double w1, double w2) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3g at rho 0.71 and %.3g at the rim, 1 at the centre",
                0.25 + 0.5 * w1 + 0.25 * w2, w2);
  return buf;
}

std::string effect_in_words(Effect e, const std::string& detail) {
  return with_detail(describe(e).words, detail);
}

namespace {

// A table cell: '|' escaped, so that |y| does not end the cell.
std::string markdown_cell(const std::string& text) {
  std::string s;
  for (char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
  return s;
}

}  // namespace

std::string effect_catalogue_markdown() {
  std::string s = "| effect | what it adds | null | what separates it |\n|---|---|---|---|\n";
  for (const EffectDescriptor& d : kCatalogue)
    s += "| `" + std::string(d.name) + "` | " + markdown_cell(d.adds) + " | " +
         markdown_cell(d.null) + " | " + markdown_cell(with_detail(d.separate, "X")) + " |\n";
  return s;
}

}  // namespace contensou
