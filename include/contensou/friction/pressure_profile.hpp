/// \file
/// Axisymmetric contact-pressure profiles p(rho) and their moments (theory.md sections 2, 4, 5).
///
/// The pressure on the patch is sigma(x, y) = p* p(rho) (1 + kx x/R + ky y/R), rho = r/R
/// (seed eq. 1 and 9): p is a dimensionless radial shape, p* a reference pressure [Pa], and
/// (kx, ky) the dimensionless linear shift of the pressure centre (rolling, camber).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace contensou {

/// p(rho) = 1.
struct UniformShape {};

/// p(rho) = sqrt(1 - rho^2) (Hertz contact of a sphere; here scaled to p(0) = 1).
struct HertzShape {};

/// p(rho) = sum_k a_k cos(pi k w rho) (seed eq. 8; the seed's x in [-1, 1] is rho along a
/// diameter).
struct CosineSeriesShape {
  double w = 1.0;         ///< the series' frequency factor
  std::vector<double> a;  ///< the coefficients a_k
};

/// A radial profile tabulated at increasing rho in [0, 1] and interpolated by a monotone
/// piecewise cubic in t = rho^2 (Fritsch-Carlson PCHIP: no new extrema, C1). In t an
/// axisymmetric pressure is smooth at the centre (it is even in rho), and each piece is a
/// polynomial on every chord, so the exact integrals take it piece by piece, exactly
/// (exact_resultants.hpp). Values are dimensionless (divided by the reference pressure).
struct TabulatedShape {
  std::vector<double> rho;    ///< knots, increasing, 0 to 1
  std::vector<double> p;      ///< p at the knots (dimensionless)
  std::vector<double> slope;  ///< dp/dt at the knots (t = rho^2), set by tabulated_profile
};

/// p(rho) = sum_k c_k T_k(2 rho^2 - 1): a Chebyshev series in t = rho^2, smooth and even in rho
/// (what a smoothing fit of noisy film data gives, smoothed_profile). The exact integrals take
/// it as it is, at the speed of any smooth profile.
struct ChebyshevShape {
  std::vector<double> c;  ///< the coefficients c_k
};

/// The radial shape p(rho) of a PressureProfile.
using ProfileShape =
    std::variant<UniformShape, HertzShape, CosineSeriesShape, TabulatedShape, ChebyshevShape>;

/// A pressure profile: the radial shape, the linear shift and what to do with a negative part.
/// A contact pressure cannot be negative, and friction would generate energy where it is:
/// make_exact_model refuses a profile with a negative part unless the caller chooses to clip it
/// (clip_negative) or to keep it as given (keep_negative, as the seed tire's published series).
struct PressureProfile {
  ProfileShape shape = UniformShape{};  ///< p(rho)
  double kx = 0.0;             ///< shift along x (seed eq. 9; 0.14 for the seed's rolling tire)
  double ky = 0.0;             ///< shift along y
  bool clip_negative = false;  ///< if true, p is replaced by max(p, 0)
  bool keep_negative = false;  ///< if true (and not clipped), a negative part is used as given
};

/// The most points a tabulated profile takes (tabulated_profile, read_profile_table,
/// validate(ContactPatch)): its exact model holds about 0.4 KB a knot, and building the model
/// and its exact law takes about 1.7 KB a knot (1.7 GB at the limit; docs/speed.md);
/// a denser measurement is better resampled, or fitted (smoothed_profile). Beyond 2.7e8 knots
/// the outer rule's interval counts (int) would overflow.
inline constexpr std::size_t kMaxProfilePoints = 1'000'000;

/// The closest two knots of a tabulated profile may be in rho (a fraction of the patch radius):
/// the monotone cubic lives in t = rho^2, and knots closer than this would give steps in t that
/// a double resolves to no better than 1e-7 of themselves (near the rim) or not at all (near
/// the centre: rho = 5e-324 squares to 0), and slopes that are noise or NaN.
inline constexpr double kMinProfileKnotStep = 1e-9;

/// p = 1, no shift.
PressureProfile uniform_profile();
/// p = sqrt(1 - rho^2), no shift.
PressureProfile hertz_profile();
/// p = sum_k a_k cos(pi k w rho), no shift. Throws InvalidArgument for a non-finite or
/// non-positive w, or an empty or non-finite a.
PressureProfile cosine_series_profile(double w, std::vector<double> a);
/// The largest exponent power_profile takes: rho^256 already puts 90 % of the load beyond
/// rho = 0.99 (a ring at the rim), and its series has 129 terms.
inline constexpr int kMaxPowerProfileExponent = 256;
/// p = rho^n for an even n in [0, kMaxPowerProfileExponent], no shift: the radial power law, from
/// uniform (n = 0) to a ring at the rim (n large), with moments A^j = 1/(n + j + 1). Held
/// exactly as the Chebyshev series of t^(n/2) in t = rho^2 (n/2 + 1 terms; a polynomial, so no
/// representation error). Throws InvalidArgument for an odd or out-of-range n.
PressureProfile power_profile(int n);
/// Validates rho (strictly increasing, from the centre, 0, to the rim, 1, knots at least
/// kMinProfileKnotStep apart, 2 to kMaxProfilePoints points; a first rho within 1e-9 of 0 is
/// the centre and a last within 1e-9 of 1 the rim) and p (finite, with an interpolant that
/// stays finite). A table that starts past the centre is refused, not extended: add the knot at
/// rho = 0. Errors name the knot (rho[k], p[k]) and its value.
PressureProfile tabulated_profile(std::vector<double> rho, std::vector<double> p);

/// A least-squares Chebyshev series in t = rho^2 with `terms` terms through tabulated values
/// (for noisy pressure-film data, instead of the interpolating table), and how far the data
/// are from it. Validates rho and p as tabulated_profile does; terms in [1, points - 1].
struct SmoothedProfile {
  PressureProfile profile;    ///< the fitted series (a ChebyshevShape)
  double rms_residual = 0.0;  ///< root-mean-square of p_i - fit(rho_i), in the units of p
  double max_residual = 0.0;  ///< largest |p_i - fit(rho_i)|
};
/// The least-squares series through (rho, p) (SmoothedProfile). Throws InvalidArgument for bad
/// data (as tabulated_profile) or terms outside [1, points - 1].
SmoothedProfile smoothed_profile(const std::vector<double>& rho, const std::vector<double>& p,
                                 int terms);

/// The tire of the seed (Table 1): w = 0.848, a_0..a_7, no shift, not clipped.
PressureProfile seed_tire_profile();

/// A tabulated profile read from a CSV with columns rho and pressure_Pa (any order, header
/// row, '#' comments). The shape is the pressure divided by reference_pressure_pa, the mean
/// contact pressure N / (pi R^2), so that 2 A^1 = 1. Errors name file, line and column.
struct MeasuredProfile {
  PressureProfile profile;             ///< the tabulated shape
  double reference_pressure_pa = 0.0;  ///< p* [Pa]
};
/// Reads a measured profile (MeasuredProfile). With `clip_negative` the table is clipped at zero
/// (PressureProfile::clip_negative) before its mean is taken: p* is then the clipped table's
/// mean pressure, as the patch carries it. Throws ParseError for a malformed file or a mean
/// pressure that is not positive, and InvalidArgument for a table tabulated_profile refuses.
MeasuredProfile read_profile_csv(const std::string& path, bool clip_negative = false);

/// The same file as its rows (rho, pressure in Pa), validated, for a smoothing fit.
struct ProfileTable {
  std::vector<double> rho;          ///< in [0, 1]
  std::vector<double> pressure_pa;  ///< [Pa]
};
/// Reads the rows of a profile file (ProfileTable); the errors of read_profile_csv.
ProfileTable read_profile_table(const std::string& path);

/// The dimensionless shape p(rho) for rho in [0, 1], after clipping if enabled (no shift).
double shape_value(const PressureProfile& profile, double rho);

/// A^n = integral_0^1 p(rho) rho^n d rho (theory.md section 4). Closed forms for uniform, Hertz
/// and the cosine series (integer n); exact piecewise Gauss-Legendre for the tabulated cubic.
/// Clipping, if enabled, is honoured (exact integration between the sign changes).
double moment(const PressureProfile& profile, int n);

/// Intervals of rho in [0, 1] where the unclipped shape is negative (empty for a physical
/// profile). The seed tire is negative on (0.9936, 1].
std::vector<std::pair<double, double>> negative_intervals(const PressureProfile& profile);

/// Share of the unclipped shape's negative part in its load, integral of max(-p, 0) rho d rho
/// over integral of |p| rho d rho (0 for a physical profile; 1.8e-4 for the seed tire).
double negative_load_share(const PressureProfile& profile);

/// A short human-readable name ("uniform", "Hertz", "cosine series (8 terms)", ...).
std::string describe(const PressureProfile& profile);

}  // namespace contensou
