/// \file
/// The exact laws of an identification model's profile (exact_law.hpp), built on first use and
/// shared by every spec copied from one base spec.
///
/// A given profile has one law. The parametric profile, a quadratic (or quartic)
/// p = c0 + c1 T1(2 t - 1) + c2 T2(2 t - 1) in t = rho^2 (its coefficients from non-negative
/// Bernstein weights: detail::parametric_profile_coefficients), is linear in (c0, c1, c2), and so
/// are the resultants: it has the laws of the basis shapes phi0 = 1, phi1 = 1 + T1,
/// phi2 = 1 + T2, with p = (c0 - c1 - c2) phi0 + c1 phi1 + c2 phi2; at degree 4 also
/// phi3 = 1 + T3, phi4 = 1 + T4. A given profile p_g corrected by the same quadratic (the
/// profile_correction effect, p = p_g q with q = sum_k w_k B_k2(rho^2)) has the laws of p_g phi0,
/// p_g phi1 and p_g phi2, combined with the same coefficients. The laws for f(w) = 1 - beta (1 -
/// exp(-w / w_s)) inside the integrals (exponent 1) carry the table of its falling part, so that
/// f(w) costs what constant friction does; they are built only when asked for (a second, slower
/// build).
#pragma once

#include <mutex>
#include <optional>
#include <vector>

#include "contensou/friction/exact_law.hpp"

namespace contensou {

/// The exact laws of one profile (a given one, or the parametric profile's basis shapes), each
/// set built once, on first use, and shared by the copies of a ModelSpec.
class ExactLawCache {
 public:
  /// radius_m: the patch radius R [m]; profile: the model of a given profile (unset: the
  /// parametric one); tolerance: the laws' build tolerance relative to f N
  /// (ExactLawOptions::tolerance). Builds nothing yet.
  ExactLawCache(double radius_m, std::optional<ExactModel<double>> profile, double tolerance);
  /// The laws (for a given profile one at `degree` 0, and at 2 the three of the profile times
  /// phi0, phi1, phi2; else the basis laws of the parametric profile of `degree` 2 or 4: three
  /// or five), for constant friction or, with
  /// `slip_speed`, with the table of the falling part, each set built on the first call that asks
  /// for it (thread-safe). Throws InvalidArgument for a model or tolerance the build refuses
  /// (make_exact_model, make_exact_law) and Interrupted when `stop` asks; a stopped or failed
  /// build leaves nothing behind: the next call builds again.
  const std::vector<ExactLaw>& laws(bool slip_speed, const StopRequest& stop = {},
                                    int degree = 2) const;
  /// Whether the profile is the parametric one (three or five basis laws).
  bool parametric() const { return !profile_; }

 private:
  double radius_m_, tolerance_;
  std::optional<ExactModel<double>> profile_;
  // constant f, f(w); the same at degree 4 (parametric) or 2 (a corrected given profile)
  mutable std::once_flag once_[4];
  mutable std::vector<ExactLaw> laws_[4];
};

}  // namespace contensou
