// Fuzzes read_profile_csv: ParseError and InvalidArgument (from tabulated_profile, for knots
// that differ only by rounding at the rim) are the expected failures; a profile that is read
// must be a valid tabulated shape (rho increasing from [0, 1) to 1, finite values and slopes),
// with a finite positive reference pressure and finite moments.
#include <cmath>
#include <variant>

#include "contensou/friction/error.hpp"
#include "contensou/friction/pressure_profile.hpp"
#include "fuzz_input.hpp"

using namespace contensou;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = fuzz::write_input(data, size, "csv");
  MeasuredProfile m;
  try {
    m = read_profile_csv(path);
  } catch (const ParseError&) {
    return 0;
  } catch (const InvalidArgument&) {
    return 0;
  }
  fuzz::require(std::isfinite(m.reference_pressure_pa) && m.reference_pressure_pa > 0.0,
                "reference pressure " + format_value(m.reference_pressure_pa));
  const auto* t = std::get_if<TabulatedShape>(&m.profile.shape);
  fuzz::require(t != nullptr, "not a tabulated shape");
  fuzz::require(
      t->rho.size() >= 2 && t->p.size() == t->rho.size() && t->slope.size() == t->rho.size(),
      "knot vectors of different sizes");
  fuzz::require(t->rho.front() >= 0.0 && t->rho.back() == 1.0, "rho does not span [., 1]");
  for (std::size_t k = 0; k < t->rho.size(); ++k) {
    const std::string at = "knot " + std::to_string(k);
    fuzz::require(k == 0 || t->rho[k] > t->rho[k - 1], at + ": rho not increasing");
    fuzz::require(std::isfinite(t->p[k]), at + ": p = " + format_value(t->p[k]));
    fuzz::require(std::isfinite(t->slope[k]), at + ": slope = " + format_value(t->slope[k]));
  }
  for (int n = 0; n <= 3; ++n) {
    const double a = moment(m.profile, n);
    fuzz::require(std::isfinite(a), "moment " + std::to_string(n) + " = " + format_value(a));
  }
  fuzz::require(std::isfinite(shape_value(m.profile, 0.5)), "p(0.5) not finite");
  negative_intervals(m.profile);  // the sign-change scan and bisection must not fail
  return 0;
}
