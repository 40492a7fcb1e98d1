// The exact model: a ContactPatch in the form the exact resultants integrate (theory.md
// section 2). sigma = p* p(rho) (1 + kx x/R + ky y/R), with p a Chebyshev series in t = rho^2
// (times sqrt(1 - t) for a Hertz edge) or a table's cubic pieces in t, and the chord
// transforms of p (impl/chord_integrals.hpp) that make the chord integrals closed forms.
// exact_resultants.hpp evaluates it.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "contensou/friction/contact_patch.hpp"

namespace contensou {

// The integration-ready form of a ContactPatch. Build it once (make_exact_model), evaluate
// many times: exact_resultants does no heap allocation (but for a table whose kinks exhaust
// the stack store of its outer rule: integrate_table).
template <class T = double>
struct ExactModel {
  double radius = 0.0;  // integration radius [m] (the positive part of a clipped profile)
  T pressure{};         // p* [Pa]
  T friction{};         // f (unused if slip_speed is set)
  T kappa{1.0};
  // Orthotropy (kappa != 1): false, the law of theory.md section 2, tau = -sigma f D vc/|vc|,
  // D = diag(1, kappa); true, the associated (maximum-dissipation) law on the same local
  // ellipse of tractions, tau = -sigma f D^2 vc/|D vc|, the gradient of sigma f |D vc| with
  // respect to vc (the limit surface's law, limit_surface.hpp). The same for kappa = 1.
  bool associated_orthotropy = false;
  T kx{0.0}, ky{0.0};  // shift relative to `radius`
  // p = [sqrt(1 - t) if sqrt_edge] * sum_k chebyshev[k] T_k(2 t - 1), t = (r / radius)^2.
  std::vector<T> chebyshev;
  bool sqrt_edge = false;
  std::optional<SlipSpeedFriction<T>> slip_speed;
  // A table (TabulatedShape) instead: p = sum_j piece[k][j] (t - knot[k])^j on
  // [knot[k], knot[k+1]], knot from 0 to 1, and the knot terms of the chord integrals
  // (knot_m0, knot_m2; update_knot_terms, impl/table_pieces.hpp). Exact for the interpolant: no
  // representation error but that of the far pieces' series (update_far_sums).
  std::vector<double> knot;
  std::vector<std::array<double, 4>> piece;
  std::vector<std::array<double, 4>> knot_m0, knot_m2;
  std::vector<double> far_m0, far_m2;  // per knot interval: Chebyshev series of the far knots
  std::vector<unsigned char> near_integrated;  // per knot interval: near pieces integrated
  std::vector<std::size_t> far_from;           // per knot interval: its first far knot
  std::vector<T> chord_q0, chord_q2;           // chord transforms (update_chord_transforms)
  std::vector<double> chord_tail;              // sum_{j >= k} |q0_j| + |q2_j|: truncation bound
  double representation_error = 0.0;           // bound on |p - representation| (dimensionless)
  double load_area = 0.0;                      // N / p* = 2 pi R^2 A^1 [m^2]
  double friction_scale = 0.0;                 // f, or max(f_s, f_k)
};

// Builds the model: Chebyshev fit of p in t = rho^2 to representation_tolerance relative to
// the profile (exact for uniform and Hertz; a smooth profile such as the cosine series reaches
// 1e-15 with ~24 terms, a tabulated C1 cubic needs many more: loosen the tolerance for speed,
// the representation error enters every error estimate), shrinking the disk to the positive
// part if a clipped profile is negative only near the rim. Validates the patch (throws
// InvalidArgument).
ExactModel<double> make_exact_model(const ContactPatch& patch,
                                    double representation_tolerance = 1e-15);

// Casts a model to another scalar (e.g. ceres::Jet) with zero derivatives.
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
  out.chebyshev.reserve(m.chebyshev.size());
  for (double c : m.chebyshev) out.chebyshev.push_back(T(c));
  out.sqrt_edge = m.sqrt_edge;
  if (m.slip_speed) {
    const auto& s = *m.slip_speed;
    out.slip_speed = SlipSpeedFriction<T>{T(s.static_coefficient), T(s.kinetic_coefficient),
                                          T(s.reference_speed), T(s.exponent)};
  }
  out.knot = m.knot;
  out.piece = m.piece;
  out.knot_m0 = m.knot_m0;
  out.knot_m2 = m.knot_m2;
  out.far_m0 = m.far_m0;
  out.far_m2 = m.far_m2;
  out.far_from = m.far_from;
  out.near_integrated = m.near_integrated;
  for (double c : m.chord_q0) out.chord_q0.push_back(T(c));
  for (double c : m.chord_q2) out.chord_q2.push_back(T(c));
  out.chord_tail = m.chord_tail;
  out.representation_error = m.representation_error;
  out.load_area = m.load_area;
  out.friction_scale = m.friction_scale;
  return out;
}

}  // namespace contensou
