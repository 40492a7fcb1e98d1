#include "contensou/friction/contact_patch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "contensou/friction/error.hpp"

namespace contensou {

namespace {

// Knots at rho a < b are far enough apart: b - a >= kMinProfileKnotStep up to the rounding of
// the two (a relative 1e-6 of the step: 0.999999999 and 1 are 1e-9 apart).
bool knots_apart(double a, double b) {
  return b - a >= kMinProfileKnotStep * (1.0 - 1e-6);
}

// The profile's shape and shift. A shape filled by hand (not by its factory) is checked here:
// an empty or inconsistent table would be read out of bounds by the interpolation (and by
// moment()).
void check_profile(const PressureProfile& profile) {
  if (const auto* t = std::get_if<TabulatedShape>(&profile.shape)) {
    const std::size_t n = t->rho.size();
    if (n < 2 || t->p.size() != n || t->slope.size() != n)
      throw InvalidArgument("profile", describe(profile),
                            "a tabulated shape needs >= 2 knots with as many p and slope values "
                            "(build it with tabulated_profile)");
    if (n > kMaxProfilePoints)
      throw InvalidArgument(
          "profile", describe(profile),
          "a tabulated shape takes at most " + std::to_string(kMaxProfilePoints) + " knots");
    for (std::size_t i = 0; i < n; ++i) {
      require_finite("tabulated rho", t->rho[i]);
      require_finite("tabulated p", t->p[i]);
      require_finite("tabulated slope", t->slope[i]);
      if (i > 0 && !knots_apart(t->rho[i - 1], t->rho[i]))
        throw InvalidArgument(
            "tabulated rho", format_value(t->rho[i]),
            "must increase by at least 1e-9 a knot (previous " + format_value(t->rho[i - 1]) + ")");
    }
    if (t->rho.front() != 0.0 || t->rho.back() != 1.0)
      throw InvalidArgument("profile", describe(profile),
                            "tabulated rho must start at the centre, 0, and end at the rim, 1");
  }
  if (const auto* c = std::get_if<ChebyshevShape>(&profile.shape)) {
    if (c->c.empty())
      throw InvalidArgument("profile", describe(profile), "needs at least one coefficient");
    for (double a : c->c) require_finite("Chebyshev series c_k", a);
  }
  if (const auto* c = std::get_if<CosineSeriesShape>(&profile.shape)) {
    require_positive("cosine series w", c->w);
    if (c->a.empty())
      throw InvalidArgument("profile", describe(profile), "needs at least one coefficient");
    for (double a : c->a) require_finite("cosine series a_k", a);
  }
  const double k = std::hypot(profile.kx, profile.ky);
  if (!(k < 1.0))
    throw InvalidArgument("|(kx, ky)|", format_value(k),
                          "the pressure shift must be < 1 so that the pressure stays positive");
}

}  // namespace

ContactPatch seed_tire_patch() {
  ContactPatch p;
  p.radius_m = 0.087;
  p.reference_pressure_pa = 2.1e5;
  p.friction = 0.3;
  p.profile = seed_tire_profile();
  return p;
}

ContactPatch ContactPatch::seed_tire() {
  return seed_tire_patch();
}

ContactPatch ContactPatch::from_normal_load(double radius_m, double normal_load_n,
                                            PressureProfile profile, double friction,
                                            double kappa) {
  require_positive("radius_m", radius_m);
  require_positive("normal_load", normal_load_n);
  check_profile(profile);  // before its moment is taken
  const double A1 = moment(profile, 1);
  if (!(A1 > 0.0) || !std::isfinite(A1))
    throw InvalidArgument(
        "profile", describe(profile),
        "its moment A^1 = " + format_value(A1) + " must be positive and finite to carry a load");
  ContactPatch p;
  p.radius_m = radius_m;
  p.friction = friction;
  p.kappa = kappa;
  p.profile = std::move(profile);
  // N = 2 pi R^2 p* A^1 (theory.md section 4), solved for p*.
  p.reference_pressure_pa = normal_load_n / (2.0 * std::numbers::pi * radius_m * radius_m * A1);
  validate(p);
  return p;
}

double ContactPatch::normal_load() const {
  return contensou::normal_load(*this);
}

double normal_load(const ContactPatch& patch) {
  validate(patch);
  return 2.0 * std::numbers::pi * patch.radius_m * patch.radius_m * patch.reference_pressure_pa *
         moment(patch.profile, 1);
}

void validate(const ContactPatch& patch) {
  // A default-constructed patch: R, p* and f unset (NaN), named before anything else.
  const std::pair<const char*, double> needed[] = {
      {"radius_m", patch.radius_m},
      {"reference_pressure_pa", patch.reference_pressure_pa},
      {"friction", patch.friction}};
  for (const auto& [name, value] : needed)
    if (std::isnan(value))
      throw InvalidArgument(name, "unset (NaN)",
                            "a patch needs its radius, its load and its friction: make it with "
                            "ContactPatch::from_normal_load(R, N, profile, f), set R, p* and f, "
                            "or take ContactPatch::seed_tire()");
  require_positive("radius_m", patch.radius_m);
  require_positive("reference_pressure_pa", patch.reference_pressure_pa);
  require_non_negative("friction", patch.friction);
  if (patch.friction > 0.0 && patch.friction < std::numeric_limits<double>::min())
    throw InvalidArgument("friction", format_value(patch.friction),
                          "is below 2.2e-308, the smallest normal double: use 0 for none");
  require_positive("kappa", patch.kappa);
  require_finite("kx", patch.profile.kx);
  require_finite("ky", patch.profile.ky);
  check_profile(patch.profile);
  if (patch.slip_speed_friction) {
    const auto& s = *patch.slip_speed_friction;
    require_non_negative("slip_speed_friction.static_coefficient", s.static_coefficient);
    require_non_negative("slip_speed_friction.kinetic_coefficient", s.kinetic_coefficient);
    require_positive("slip_speed_friction.reference_speed", s.reference_speed);
    require_positive("slip_speed_friction.exponent", s.exponent);
  }
  require_representable_scales(patch);
}

void require_representable_scales(const ContactPatch& patch) {
  // Finite in, finite out: the load N = 2 pi R^2 p* A^1 (theory.md section 4) and the torque
  // scale f N R, in logarithms so that the check itself cannot overflow, must lie well inside
  // the doubles (1e-300 ... 1e300); the profile's own values enter only through A^n.
  const double A1 = moment(patch.profile, 1), A2 = moment(patch.profile, 2);
  if (!std::isfinite(A1) || !std::isfinite(A2))
    throw InvalidArgument("profile", describe(patch.profile),
                          "its moments A^1, A^2 are not finite (" + format_value(A1) + ", " +
                              format_value(A2) + "): its values overflow a double");
  if (!(A1 > 0.0)) return;  // a negative pressure: refused by the exact model, naming it
  double f = patch.friction;
  if (patch.slip_speed_friction)
    f = std::max({f, patch.slip_speed_friction->static_coefficient,
                  patch.slip_speed_friction->kinetic_coefficient});
  const double log_n = std::log(2.0 * std::numbers::pi) + 2.0 * std::log(patch.radius_m) +
                       std::log(patch.reference_pressure_pa) + std::log(A1);
  const double log_m = log_n + std::log(patch.radius_m) + (f > 0.0 ? std::log(f) : 0.0);
  const double most = std::log(1e300), least = std::log(1e-300);
  const auto decade = [](double log_x) {
    return "1e" + std::to_string(static_cast<int>(std::floor(log_x / std::log(10.0))));
  };
  // The load in range but not the torque scale: the friction (with R) is what leaves it.
  if (log_n < most && log_n > least && !(log_m < most && log_m > least) && f > 0.0)
    throw InvalidArgument(
        "friction", format_value(f),
        "gives a torque scale f N R of " + decade(log_m) + " N m at N = " +
            format_value(std::exp(log_n)) + " N and R = " + format_value(patch.radius_m) +
            " m; f N R must lie within 1e-300 ... 1e300 (a friction coefficient is of order 0.01 "
            "to 2)");
  if (!(log_n < most && log_m < most && log_n > least && log_m > least))
    throw InvalidArgument(
        "radius_m, reference_pressure_pa",
        format_value(patch.radius_m) + " m, " + format_value(patch.reference_pressure_pa) + " Pa",
        "give a load N = 2 pi R^2 p* A^1 of " + decade(log_n) +
            " N; N and f N R must lie within 1e-300 ... 1e300: use other units");
}

}  // namespace contensou
