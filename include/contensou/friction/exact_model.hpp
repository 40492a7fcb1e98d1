/// \file
/// The exact model: a ContactPatch in the form the exact resultants integrate (theory.md §2,
/// "The exact model"; docs/theory.md, "The representation of the profile"). Built once by
/// make_exact_model, evaluated many times by exact_resultants (exact_resultants.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/error.hpp"

namespace contensou {

/// A tabulated profile as the exact model holds it: the interpolant's cubic pieces in
/// t = rho^2, p(t) = sum_j piece[k][j] (t - knot[k])^j on [knot[k], knot[k+1]] (knots from 0 to
/// 1, dimensionless), and the terms of its chord integrals precomputed once a build
/// (docs/theory.md, "Tabulated profiles"). Exact for the interpolant: no representation error
/// but that of the far pieces' series.
struct TablePieces {
  std::vector<double> knot;                    ///< n + 1 knots in t, 0 ... 1
  std::vector<std::array<double, 4>> piece;    ///< n cubics, each about its lower knot
  std::vector<std::array<double, 4>> knot_m0;  ///< knot terms of M0 (update_knot_terms)
  std::vector<std::array<double, 4>> knot_m2;  ///< knot terms of M2 (update_knot_terms)
  std::vector<double> far_m0;                  ///< per interval: Chebyshev series of the far M0
  std::vector<double> far_m2;                  ///< per interval: Chebyshev series of the far M2
  std::vector<unsigned char> near_integrated;  ///< per interval: near pieces integrated (1)
  std::vector<std::size_t> far_from;           ///< per interval: its first far knot
};

template <class T>
struct ExactModel;

template <class T>
ExactModel<T> promote(const ExactModel<double>& m);

namespace detail {
template <class T>
void update_chord_transforms(ExactModel<T>& m);
}  // namespace detail

/// The integration-ready form of a ContactPatch: sigma = p* p(rho) (1 + kx x/R + ky y/R), with
/// p a Chebyshev series in t = rho^2 (times sqrt(1 - t) for a Hertz edge) or a table's cubic
/// pieces in t (theory.md §2). The parameters are public; the profile's representation (the
/// series, the table, the chord transforms) is set by make_exact_model and read through
/// accessors. exact_resultants does no heap allocation on it (but for a table whose kinks
/// exhaust the stack store of its outer rule). T = double or ceres::Jet (promote).
template <class T = double>
struct ExactModel {
  double radius = 0.0;  ///< integration radius [m] (the positive part of a clipped profile)
  T pressure{};         ///< p* [Pa]
  T friction{};         ///< f (unused if slip_speed is set)
  T kappa{1.0};         ///< lateral / longitudinal friction ratio
  /// Orthotropy (kappa != 1): false, the law of theory.md §2, tau = -sigma f D vc/|vc|,
  /// D = diag(1, kappa); true, the associated (maximum-dissipation) law on the same local
  /// ellipse of tractions, tau = -sigma f D^2 vc/|D vc| (limit_surface.hpp). The same for
  /// kappa = 1.
  bool associated_orthotropy = false;
  T kx{0.0};                                       ///< pressure shift along x, relative to `radius`
  T ky{0.0};                                       ///< pressure shift along y, relative to `radius`
  std::optional<SlipSpeedFriction<T>> slip_speed;  ///< f(w) instead of `friction` if set
  double load_area = 0.0;                          ///< N / p* = 2 pi R^2 A^1 [m^2]
  double friction_scale = 0.0;  ///< f, or max(f_s, f_k): the scale of the tolerance

  /// The profile's Chebyshev series in z = 2 t - 1 (empty for a table).
  const std::vector<T>& chebyshev() const { return chebyshev_; }
  /// True if p carries the Hertz edge factor sqrt(1 - t).
  bool sqrt_edge() const { return sqrt_edge_; }
  /// The table's pieces, or nothing for a series profile.
  const std::optional<TablePieces>& table() const { return table_; }
  /// Chord transform Q0 of the series (Chebyshev series in t_f; empty for a table).
  const std::vector<T>& chord_q0() const { return chord_q0_; }
  /// Chord transform Q2 of the series (Chebyshev series in t_f; empty for a table).
  const std::vector<T>& chord_q2() const { return chord_q2_; }
  /// chord_tail()[k] = sum_{j >= k} |Q0_j| + |Q2_j|: the truncation bound of the transforms.
  const std::vector<double>& chord_tail() const { return chord_tail_; }
  /// Bound on |p - representation| (dimensionless, relative to p*).
  double representation_error() const { return representation_error_; }

  /// Sets the profile to a Chebyshev series (with the Hertz edge if sqrt_edge) whose
  /// representation error is `error`, and recomputes the chord transforms. Throws
  /// InvalidArgument for an empty series.
  void set_series(std::vector<T> coefficients, bool sqrt_edge, double error);
  /// Sets the profile to a table (its chord-integral terms computed by the caller: see
  /// make_exact_model) whose representation error is `error`.
  void set_table(TablePieces table, double error) {
    chebyshev_.clear();
    chord_q0_.clear();
    chord_q2_.clear();
    chord_tail_.clear();
    sqrt_edge_ = false;
    table_ = std::move(table);
    representation_error_ = error;
  }

 private:
  std::vector<T> chebyshev_;
  bool sqrt_edge_ = false;
  std::optional<TablePieces> table_;
  std::vector<T> chord_q0_, chord_q2_;
  std::vector<double> chord_tail_;
  double representation_error_ = 0.0;

  template <class U>
  friend ExactModel<U> promote(const ExactModel<double>& m);
  template <class U>
  friend struct ExactModel;
  friend void detail::update_chord_transforms<T>(ExactModel<T>& m);
};

/// Builds the model of a patch (theory.md §2): p as it is for uniform, Hertz and Chebyshev
/// profiles (exact), a table's cubic pieces as they are (clipped at zero if the profile says; a
/// table of more than 256 knots, a finite-element or film profile, thinned at a tolerance of
/// 1e-12 or more to the knots whose cubics stay within it relative to its largest value, the
/// deviation added to the representation error; the default keeps every knot),
/// else a Chebyshev fit in t = rho^2 to representation_tolerance relative to the profile (a
/// smooth profile reaches 1e-15 with ~24 terms; loosen it for speed, the representation error
/// enters every error estimate). A clipped profile negative only near the rim shrinks the disk
/// to its positive part. Throws InvalidArgument for an invalid patch (validate), a profile
/// negative somewhere without clip_negative or keep_negative, a load integral A^1 <= 0, or a
/// tolerance outside (0, 1e-3).
ExactModel<double> make_exact_model(const ContactPatch& patch,
                                    double representation_tolerance = 1e-15);

/// Casts a model to another scalar (e.g. ceres::Jet) with zero derivatives; the tables are
/// copied, not recomputed.
template <class T>
ExactModel<T> promote(const ExactModel<double>& m) {
  ExactModel<T> out;
  out.radius = m.radius;
  out.pressure = T(m.pressure);
  out.friction = T(m.friction);
  out.kappa = T(m.kappa);
  out.associated_orthotropy = m.associated_orthotropy;
  out.kx = T(m.kx);
  out.ky = T(m.ky);
  if (m.slip_speed) {
    const auto& s = *m.slip_speed;
    out.slip_speed = SlipSpeedFriction<T>{T(s.static_coefficient), T(s.kinetic_coefficient),
                                          T(s.reference_speed), T(s.exponent)};
  }
  out.load_area = m.load_area;
  out.friction_scale = m.friction_scale;
  out.chebyshev_.reserve(m.chebyshev_.size());
  for (double c : m.chebyshev_) out.chebyshev_.push_back(T(c));
  out.sqrt_edge_ = m.sqrt_edge_;
  out.table_ = m.table_;
  for (double c : m.chord_q0_) out.chord_q0_.push_back(T(c));
  for (double c : m.chord_q2_) out.chord_q2_.push_back(T(c));
  out.chord_tail_ = m.chord_tail_;
  out.representation_error_ = m.representation_error_;
  return out;
}

}  // namespace contensou

// set_series needs the chord transforms (impl/chord_integrals.hpp), which need the model.
#include "contensou/friction/impl/chord_integrals.hpp"  // IWYU pragma: export

namespace contensou {

template <class T>
void ExactModel<T>::set_series(std::vector<T> coefficients, bool sqrt_edge, double error) {
  if (coefficients.empty())
    throw InvalidArgument("coefficients", "an empty series", "must hold at least one term");
  table_.reset();
  chebyshev_ = std::move(coefficients);
  sqrt_edge_ = sqrt_edge;
  representation_error_ = error;
  detail::update_chord_transforms(*this);
}

}  // namespace contensou
