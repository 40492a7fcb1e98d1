#include "contensou/gear/gear_parameters.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "contensou/friction/error.hpp"
#include "contensou/gear/landing_gear.hpp"

namespace contensou {
namespace {

constexpr ParameterRange kAny{ParameterRange::unchecked};
constexpr ParameterRange kFinite{ParameterRange::finite};
constexpr ParameterRange kPositive{ParameterRange::positive};

// lo <= v < hi with one message for both sides.
constexpr ParameterRange interval(double lo, double hi, std::string_view rule) {
  return {ParameterRange::interval, lo, hi, false, false, rule, {}};
}

// The table's rows by type; `field` is a captureless lambda returning the field.
template <class Field>
constexpr GearParameter number(std::string_view name, std::string_view unit, ParameterRange range,
                               std::string_view help, Field field,
                               ParameterSwitch when = ParameterSwitch::always) {
  GearParameter p;
  p.name = name;
  p.unit = unit;
  p.range = range;
  p.when = when;
  p.help = help;
  p.number = +field;
  return p;
}

template <class Field>
constexpr GearParameter flag(std::string_view name, std::string_view help, Field field) {
  GearParameter p;
  p.name = name;
  p.type = ParameterType::flag;
  p.help = help;
  p.flag = +field;
  return p;
}

template <class Field>
constexpr GearParameter choice(std::string_view name, std::string_view choices,
                               std::string_view help, Field field) {
  GearParameter p;
  p.name = name;
  p.type = ParameterType::choice;
  p.choices = choices;
  p.help = help;
  p.text = +field;
  return p;
}

constexpr GearParameter with_relation(GearParameter p, void (*relation)(const GearConfig&),
                                      std::string_view text) {
  p.relation = relation;
  p.relation_text = text;
  return p;
}

// Relations between keys, each naming the key whose row carries it.
void one_wheel_with_carcass(const GearConfig& c) {
  const GearStructure& g = c.structure;
  if (g.carcass_compliance() && g.wheel_spacing_m > 0.0)
    throw InvalidArgument("structure.wheel_spacing_m", format_value(g.wheel_spacing_m),
                          "must be 0 with carcass compliance (implemented for one wheel)");
}

void both_carcass_stiffnesses(const GearConfig& c) {
  const GearStructure& g = c.structure;
  if (!g.carcass_compliance()) return;
  if (!(g.carcass_lateral_stiffness_n_per_m > 0.0))
    throw InvalidArgument("structure.carcass_lateral_stiffness_n_per_m",
                          format_value(g.carcass_lateral_stiffness_n_per_m),
                          "must be positive when structure.carcass_torsional_stiffness_nm_per_rad "
                          "is (both 0: rigid carcass)");
  if (!(g.carcass_torsional_stiffness_nm_per_rad > 0.0))
    throw InvalidArgument("structure.carcass_torsional_stiffness_nm_per_rad",
                          format_value(g.carcass_torsional_stiffness_nm_per_rad),
                          "must be positive when structure.carcass_lateral_stiffness_n_per_m is "
                          "(both 0: rigid carcass)");
}

void sliding_above_rolling(const GearConfig& c) {
  const LandingScenario& s = c.scenario;
  if (!(s.sliding_slip > s.rolling_slip && s.sliding_slip < 1.0))
    throw InvalidArgument("scenario.sliding_slip", format_value(s.sliding_slip),
                          "must lie between rolling_slip and 1");
}

void brake_off_after_on(const GearConfig& c) {
  const LandingScenario& s = c.scenario;
  if (!(s.brake_off_s > s.brake_on_s && s.brake_on_s >= 0.0))
    throw InvalidArgument("scenario.brake_off_s", format_value(s.brake_off_s),
                          "must come after brake_on_s >= 0");
}

// An explicit analysis window (negative: automatic) lies inside the run, its end after its start.
void window_inside_run(const GearConfig& c) {
  const LandingScenario& s = c.scenario;
  const double start = s.window_start_s, end = s.window_end_s;
  if (start >= 0.0 && !(start < s.end_time_s))
    throw InvalidArgument("scenario.window_start_s", format_value(start),
                          "must come before scenario.end_time_s = " + format_value(s.end_time_s) +
                              " (negative: automatic)");
  if (end >= 0.0 && !(end <= s.end_time_s))
    throw InvalidArgument("scenario.window_end_s", format_value(end),
                          "must not pass scenario.end_time_s = " + format_value(s.end_time_s) +
                              " (negative: automatic)");
  if (start >= 0.0 && end >= 0.0 && !(end > start))
    throw InvalidArgument("scenario.window_end_s", format_value(end),
                          "must come after scenario.window_start_s = " + format_value(start) +
                              " (the analysis window runs from start to end; negative: "
                              "automatic)");
}

// Longitudinal relaxation: off (0) or a length the integrator resolves at landing speeds
// (V / sigma_x up to 1e4 1/s at 100 m/s).
void longitudinal_relaxation_resolved(const GearConfig& c) {
  const double sigma_x = c.tire.longitudinal_relaxation_length_m;
  if (sigma_x > 0.0 && sigma_x < 0.01)
    throw InvalidArgument("tire.longitudinal_relaxation_length_m", format_value(sigma_x),
                          "must be 0 (no relaxation) or at least 0.01 m (a shorter one relaxes "
                          "faster than the integrator's steps)");
}

constexpr ParameterSwitch kBraking = ParameterSwitch::braking;
constexpr ParameterSwitch kCarcass = ParameterSwitch::carcass;

// The structure (landing_gear.hpp, GearStructure; docs/shimmy.md section 1), in the order the
// rows are checked (the positive masses, stiffnesses and inertias first, as validate() always
// has: a configuration with several bad values names the same one).
constexpr std::array kStructure{
    number("structure.lateral_mass_kg", "kg", kPositive, "m_y, modal mass of lateral bending",
           [](GearConfig& c) -> double& { return c.structure.lateral_mass_kg; }),
    number("structure.lateral_stiffness_n_per_m", "N/m", kPositive,
           "k_y, lateral bending stiffness at the wheel",
           [](GearConfig& c) -> double& { return c.structure.lateral_stiffness_n_per_m; }),
    number("structure.torsional_inertia_kgm2", "kg m^2", kPositive,
           "I_psi, inertia of the strut's torsion about its axis",
           [](GearConfig& c) -> double& { return c.structure.torsional_inertia_kgm2; }),
    number("structure.torsional_stiffness_nm_per_rad", "N m/rad", kPositive,
           "k_psi, torsional stiffness (torque link)",
           [](GearConfig& c) -> double& { return c.structure.torsional_stiffness_nm_per_rad; }),
    number("structure.lateral_damping_ns_per_m", "N s/m", kFinite, "c_y, lateral bending damping",
           [](GearConfig& c) -> double& { return c.structure.lateral_damping_ns_per_m; }),
    number("structure.torsional_damping_nms_per_rad", "N m s/rad", kFinite,
           "c_psi, strut damping and shimmy damper together",
           [](GearConfig& c) -> double& { return c.structure.torsional_damping_nms_per_rad; }),
    number("structure.trail_m", "m", kFinite, "e, patch centre behind the strut axis",
           [](GearConfig& c) -> double& { return c.structure.trail_m; }),
    number("structure.offset_m", "m", kFinite, "l, patch centre left of the strut axis",
           [](GearConfig& c) -> double& { return c.structure.offset_m; }),
    number("structure.wheel_radius_m", "m", kPositive, "r, rolling radius",
           [](GearConfig& c) -> double& { return c.structure.wheel_radius_m; }),
    number("structure.wheel_inertia_kgm2", "kg m^2", kPositive, "I_w, wheel spin inertia",
           [](GearConfig& c) -> double& { return c.structure.wheel_inertia_kgm2; }),
    number("structure.fore_aft_stiffness_n_per_m", "N/m",
           interval(0.0, 1e12, "must be >= 0 and finite (0: no fore-aft bending)"),
           "k_x, fore-aft bending stiffness (0: rigid fore-aft)",
           [](GearConfig& c) -> double& { return c.structure.fore_aft_stiffness_n_per_m; }),
    number("structure.fore_aft_mass_kg", "kg", kPositive, "m_x, modal mass of fore-aft bending",
           [](GearConfig& c) -> double& { return c.structure.fore_aft_mass_kg; }),
    number("structure.fore_aft_damping_ns_per_m", "N s/m", kFinite, "c_x, fore-aft damping",
           [](GearConfig& c) -> double& { return c.structure.fore_aft_damping_ns_per_m; }),
    number("structure.wheel_spacing_m", "m",
           interval(0.0, 100.0, "must be >= 0 and finite (0: one wheel)"),
           "b, spacing of a twin gear's two wheels (0: one wheel; carcass compliance needs one)",
           [](GearConfig& c) -> double& { return c.structure.wheel_spacing_m; }),
    number("structure.freeplay_rad", "rad",
           interval(0.0, 1.0, "must lie in [0, 1) rad (0: no freeplay)"),
           "delta, half-width of the torque link's freeplay (0: none)",
           [](GearConfig& c) -> double& { return c.structure.freeplay_rad; }),
    number("structure.gyroscopic_length_m", "m",
           interval(0.0, 1e6, "must be >= 0 and finite (0: no gyroscopic coupling)"),
           "L, pendulum length of lateral bending for the wheel's gyroscopic coupling (0: off)",
           [](GearConfig& c) -> double& { return c.structure.gyroscopic_length_m; }),
    number("structure.carcass_lateral_stiffness_n_per_m", "N/m",
           interval(0.0, 1e15, "must be >= 0 and finite (0 with the torsional one: rigid carcass)"),
           "k_cy, lateral carcass stiffness of the sliding tire (0 with k_cpsi: rigid carcass)",
           [](GearConfig& c) -> double& { return c.structure.carcass_lateral_stiffness_n_per_m; }),
    with_relation(
        number(
            "structure.carcass_torsional_stiffness_nm_per_rad", "N m/rad",
            interval(0.0, 1e15, "must be >= 0 and finite (0 with the lateral one: rigid carcass)"),
            "k_cpsi, torsional carcass stiffness (0 with k_cy: rigid carcass)",
            [](GearConfig& c) -> double& {
              return c.structure.carcass_torsional_stiffness_nm_per_rad;
            }),
        both_carcass_stiffnesses, "both carcass stiffnesses > 0 or both 0"),
    number(
        "structure.carcass_lateral_damping_ns_per_m", "N s/m", kPositive,
        "c_cy, lateral carcass damping",
        [](GearConfig& c) -> double& { return c.structure.carcass_lateral_damping_ns_per_m; },
        kCarcass),
    // The last row of the carcass: its relation, that the carcass is implemented for one wheel,
    // is checked after both dampings (as validate() always has).
    with_relation(number(
                      "structure.carcass_torsional_damping_nms_per_rad", "N m s/rad", kPositive,
                      "c_cpsi, torsional carcass damping",
                      [](GearConfig& c) -> double& {
                        return c.structure.carcass_torsional_damping_nms_per_rad;
                      },
                      kCarcass),
                  one_wheel_with_carcass, "one wheel (structure.wheel_spacing_m = 0)"),
};

// The sliding tire (SlidingTire; theory.md sections 4 and 5).
constexpr std::array kTire{
    number("tire.inflation_pressure_pa", "Pa", kPositive,
           "p*, inflation pressure (the patch radius follows from the load)",
           [](GearConfig& c) -> double& { return c.tire.inflation_pressure_pa; }),
    number("tire.rolling_shift", "1",
           {ParameterRange::interval,
            -1.0,
            1.0,
            true,
            true,
            "must lie in (-1, 1) so that the pressure stays positive",
            {}},
           "kx, fore-aft shift of the pressure profile (seed eq. 10)",
           [](GearConfig& c) -> double& { return c.tire.rolling_shift; }),
    number("tire.friction.static_coefficient", "1", kPositive, "f_s, friction at zero slip speed",
           [](GearConfig& c) -> double& { return c.tire.friction.static_coefficient; }),
    number("tire.friction.kinetic_coefficient", "1", kPositive, "f_k, friction at high slip speed",
           [](GearConfig& c) -> double& { return c.tire.friction.kinetic_coefficient; }),
    number("tire.friction.reference_speed", "m/s", kPositive,
           "w_s, slip speed of the fall f_s -> f_k",
           [](GearConfig& c) -> double& { return c.tire.friction.reference_speed; }),
    number("tire.friction.exponent", "1", kPositive,
           "delta, f(w) = f_k + (f_s - f_k) exp(-(w / w_s)^delta)",
           [](GearConfig& c) -> double& { return c.tire.friction.exponent; }),
    number("tire.regularization_speed", "m/s", kPositive,
           "eps, regularisation speed of the sliding laws",
           [](GearConfig& c) -> double& { return c.tire.regularization_speed; }),
    choice("tire.law_coefficients", "fitted|asymptotic|seed",
           "a, m of the coupled law: least squares to the exact integrals, asymptotic, or seed "
           "Table 3",
           [](GearConfig& c) -> std::string& { return c.tire.law_coefficients; }),
    flag("tire.exact_integrals", "coupled model: the exact law instead of the fractional one",
         [](GearConfig& c) -> bool& { return c.tire.exact_integrals; }),
    with_relation(
        number("tire.longitudinal_relaxation_length_m", "m",
               interval(0.0, 10.0, "must lie in [0, 10) m (0: no relaxation)"),
               "sigma_x, longitudinal relaxation length of every contact model (0: none)",
               [](GearConfig& c) -> double& { return c.tire.longitudinal_relaxation_length_m; }),
        longitudinal_relaxation_resolved, "0 or at least 0.01 m"),
};

// The rolling tire (RollingTire; Pacejka 2012, ch. 5).
constexpr std::array kRolling{
    number("rolling.relaxation_length_m", "m", kPositive, "sigma, the string's relaxation length",
           [](GearConfig& c) -> double& { return c.rolling.relaxation_length_m; }),
    number("rolling.cornering_coefficient", "1/rad", kPositive,
           "C_Fa, cornering stiffness per load",
           [](GearConfig& c) -> double& { return c.rolling.cornering_coefficient; }),
    number("rolling.aligning_coefficient_m", "m/rad", kFinite, "C_Ma, aligning stiffness per load",
           [](GearConfig& c) -> double& { return c.rolling.aligning_coefficient_m; }),
    number("rolling.tread_moment_nm2_per_rad", "N m^2/rad", kFinite,
           "kappa_t, tread-width moment at full load",
           [](GearConfig& c) -> double& { return c.rolling.tread_moment_nm2_per_rad; }),
    number("rolling.longitudinal_slip_coefficient", "1", kPositive,
           "C_x, longitudinal slip stiffness per load",
           [](GearConfig& c) -> double& { return c.rolling.longitudinal_slip_coefficient; }),
};

// The landing (LandingScenario; docs/shimmy.md section 1).
constexpr std::array kScenario{
    number("scenario.forward_speed_mps", "m/s", kPositive, "V, forward speed",
           [](GearConfig& c) -> double& { return c.scenario.forward_speed_mps; }),
    number("scenario.drift_speed_mps", "m/s", kFinite,
           "Vd, lateral ground speed (crosswind drift, constant over the run)",
           [](GearConfig& c) -> double& { return c.scenario.drift_speed_mps; }),
    number("scenario.static_load_n", "N", kPositive, "N_s, vertical load after the ramp",
           [](GearConfig& c) -> double& { return c.scenario.static_load_n; }),
    number("scenario.touchdown_time_s", "s",
           {ParameterRange::interval, 0.0, 1e6, false, false, "must be >= 0", "must be finite"},
           "t_td, load onset",
           [](GearConfig& c) -> double& { return c.scenario.touchdown_time_s; }),
    number("scenario.load_ramp_s", "s", kPositive, "T, duration of the smooth load ramp",
           [](GearConfig& c) -> double& { return c.scenario.load_ramp_s; }),
    number("scenario.end_time_s", "s", kPositive, "end of the run",
           [](GearConfig& c) -> double& { return c.scenario.end_time_s; }),
    number("scenario.initial_torsion_rad", "rad", kFinite, "psi(0)",
           [](GearConfig& c) -> double& { return c.scenario.initial_torsion_rad; }),
    number("scenario.initial_lateral_m", "m", kFinite, "y(0)",
           [](GearConfig& c) -> double& { return c.scenario.initial_lateral_m; }),
    number("scenario.rolling_slip", "1", kPositive,
           "sliding -> rolling when the slip ratio falls below (end of spin-up)",
           [](GearConfig& c) -> double& { return c.scenario.rolling_slip; }),
    with_relation(number("scenario.sliding_slip", "1", kAny,
                         "rolling -> sliding when the slip ratio rises above",
                         [](GearConfig& c) -> double& { return c.scenario.sliding_slip; }),
                  sliding_above_rolling, "> scenario.rolling_slip and < 1"),
    flag("scenario.braking", "brake between brake_on_s and brake_off_s",
         [](GearConfig& c) -> bool& { return c.scenario.braking; }),
    number("scenario.brake_on_s", "s", kAny, "brake command on",
           [](GearConfig& c) -> double& { return c.scenario.brake_on_s; }),
    with_relation(number(
                      "scenario.brake_off_s", "s", kAny, "brake command off",
                      [](GearConfig& c) -> double& { return c.scenario.brake_off_s; }, kBraking),
                  brake_off_after_on, "> scenario.brake_on_s >= 0"),
    number(
        "scenario.brake_max_torque_nm", "N m", kPositive, "T_max, the anti-skid's largest torque",
        [](GearConfig& c) -> double& { return c.scenario.brake_max_torque_nm; }, kBraking),
    number(
        "scenario.brake_target_slip", "1",
        {ParameterRange::interval, 0.0, 1.0, true, false, "must lie in (0, 1)", {}},
        "s*, the anti-skid's wheel-speed slip",
        [](GearConfig& c) -> double& { return c.scenario.brake_target_slip; }, kBraking),
    number(
        "scenario.brake_slip_band", "1", kPositive, "ds, width of the anti-skid's switch",
        [](GearConfig& c) -> double& { return c.scenario.brake_slip_band; }, kBraking),
    number("scenario.window_start_s", "s", kFinite,
           "start of the shimmy analysis window (negative: automatic)",
           [](GearConfig& c) -> double& { return c.scenario.window_start_s; }),
    with_relation(number("scenario.window_end_s", "s", kFinite,
                         "end of the shimmy analysis window (negative: automatic)",
                         [](GearConfig& c) -> double& { return c.scenario.window_end_s; }),
                  window_inside_run,
                  "after scenario.window_start_s when both are set, both within "
                  "scenario.end_time_s"),
};

template <std::size_t... N>
constexpr auto join(const std::array<GearParameter, N>&... parts) {
  std::array<GearParameter, (N + ...)> all{};
  std::size_t k = 0;
  ((std::copy(parts.begin(), parts.end(), all.begin() + static_cast<std::ptrdiff_t>(k)),
    k += parts.size()),
   ...);
  return all;
}

constexpr auto kParameters = join(kStructure, kTire, kRolling, kScenario);

bool switched_on(ParameterSwitch when, const GearConfig& c) {
  switch (when) {
    case ParameterSwitch::braking:
      return c.scenario.braking;
    case ParameterSwitch::carcass:
      return c.structure.carcass_compliance();
    case ParameterSwitch::always:
      break;
  }
  return true;
}

void check_range(std::string_view name, const ParameterRange& r, double v) {
  const std::string key(name);
  switch (r.kind) {
    case ParameterRange::unchecked:
      return;
    case ParameterRange::finite:
      return require_finite(key.c_str(), v);
    case ParameterRange::positive:
      return require_positive(key.c_str(), v);
    case ParameterRange::interval:
      break;
  }
  if (r.finite_first) require_finite(key.c_str(), v);
  if (!(r.lo_open ? v > r.lo : v >= r.lo))
    throw InvalidArgument(key, format_value(v), std::string(r.rule));
  if (!(v < r.hi))
    throw InvalidArgument(key, format_value(v),
                          std::string(r.rule_above.empty() ? r.rule : r.rule_above));
}

// "a, b or c" from "a|b|c".
std::string in_words(std::string_view choices) {
  std::string out;
  std::size_t start = 0;
  while (true) {
    const std::size_t bar = choices.find('|', start);
    const std::string_view part = choices.substr(start, bar - start);
    if (start > 0) out += bar == std::string_view::npos ? " or " : ", ";
    out += part;
    if (bar == std::string_view::npos) return out;
    start = bar + 1;
  }
}

void check(const GearParameter& p, GearConfig& c) {
  if (!switched_on(p.when, c)) return;
  if (p.number) check_range(p.name, p.range, p.number(c));
  if (p.text) {
    const std::string& v = p.text(c);
    bool known = false;
    for (std::size_t start = 0; start != std::string_view::npos && !known;) {
      const std::size_t bar = p.choices.find('|', start);
      known = p.choices.substr(start, bar - start) == v;
      start = bar == std::string_view::npos ? bar : bar + 1;
    }
    if (!known) throw InvalidArgument(std::string(p.name), v, "must be " + in_words(p.choices));
  }
  if (p.relation) p.relation(c);
}

}  // namespace

std::span<const GearParameter> gear_parameters() {
  return kParameters;
}

const GearParameter* find_gear_parameter(std::string_view name) {
  for (const GearParameter& p : kParameters)
    if (p.name == name) return &p;
  return nullptr;
}

void check_gear_parameter(const GearParameter& p, const GearConfig& config) {
  GearConfig c = config;  // the fields are reached through non-const accessors; read only
  check(p, c);
}

void validate(const GearConfig& config) {
  GearConfig c = config;  // one copy for every row (read only)
  for (const GearParameter& p : kParameters) check(p, c);
}

double* gear_parameter(GearConfig& config, std::string_view name) {
  const GearParameter* p = find_gear_parameter(name);
  return p && p->number ? &p->number(config) : nullptr;
}

std::vector<std::string> gear_parameter_names() {
  std::vector<std::string> names;
  for (const GearParameter& p : kParameters)
    if (p.number) names.emplace_back(p.name);
  return names;
}

std::string describe_range(const GearParameter& p) {
  std::string out;
  const ParameterRange& r = p.range;
  if (p.type == ParameterType::flag) out = "true or false";
  if (p.type == ParameterType::choice) out = in_words(p.choices);
  if (p.type == ParameterType::number && r.kind == ParameterRange::finite) out = "finite";
  if (p.type == ParameterType::number && r.kind == ParameterRange::positive) out = "> 0";
  if (p.type == ParameterType::number && r.kind == ParameterRange::interval)
    out = (r.lo_open ? "(" : "[") + format_value(r.lo) + ", " + format_value(r.hi) + ")";
  if (!p.relation_text.empty()) out += (out.empty() ? "" : "; ") + std::string(p.relation_text);
  if (out.empty()) out = "any";
  if (p.when == ParameterSwitch::braking) out += " while scenario.braking";
  if (p.when == ParameterSwitch::carcass) out += " with carcass compliance";
  return out;
}

}  // namespace contensou
