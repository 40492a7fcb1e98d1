/// \file
/// The friction of a patch distributed over the local slip speed: a quadrature rule in the
/// normalised slip speed nu = |vc| / (|v| + |omega| R) that integrates any slip-speed law
/// f(|vc|) at once (theory.md section 2; the tables of f(w) in exact_law.hpp).
///
/// In the sliding frame (R = 1, v = sigma x, omega = eta > 0, sigma + eta = 1, t = sigma - eta)
/// the centre of sliding is r_c = (0, eps), eps = sigma / eta, and |vc| = eta s with s = |r - r_c|.
/// In polar coordinates (s, beta) about r_c the slip direction is u_hat = (-sin beta, cos beta), so
/// every integral of the six functions of exact_law.hpp with a weight G(|vc|) is
///   W_i = integral_0^inf G(eta s) m_i(s) ds,   m_i(s) = s integral_arc(s) p(|r|) B_i u_hat_j d
///   beta,
/// a ring integral over the arc of |r - r_c| = s inside the disk (B_i = 1, x, y, x^2, x y, y^2).
/// The rule is built on panels in nu in [max(t, 0), 1], graded geometrically towards the points
/// where m has square-root singularities (the ring tangent to the rim: nu = |t| and nu = 1) and
/// towards the smallest slip speed, where G(q nu) for large q = (|v| + |omega| R) / w_s is a
/// boundary layer of width 1/q.
#pragma once

#include <array>
#include <vector>

#include "contensou/friction/exact_resultants.hpp"

namespace contensou {

/// The six integrals of exact_law.hpp (R = 1, p* = 1, f = 1, the model's profile, no shift),
/// raw: A = int p u_x, a = int p x u_y, b = int p y u_x, alpha = int p x^2 u_x,
/// c = int p x y u_y, d = int p y^2 u_x.
using SlipMoments = std::array<double, 6>;

/// A quadrature rule in the normalised slip speed nu for the six integrals.
struct SlipSpeedMeasure {
  std::vector<double> nu;           ///< nodes (normalised slip speed, in [0, 1])
  std::vector<SlipMoments> weight;  ///< W_i(G) = sum_k weight[k][i] G(nu[k])
};

/// How slip_speed_measure builds its rule.
struct SlipSpeedMeasureOptions {
  double largest_q = 1e4;  ///< the rule resolves G(q nu) = exp(-(q nu)^delta) up to this q
  /// Of each ring integral, relative to the load; a table's ring is integrated piece by piece to
  /// 1e-2 of it relative to the piece (the default: about 1e-15), and the rule of a piece of a
  /// panel between a table's knot tangencies aims at 1e2 of it relative to the piece.
  double ring_tolerance = 1e-13;
  int nodes = 12;      ///< Gauss-Legendre nodes a panel in nu
  int ring_nodes = 6;  ///< Gauss-Legendre nodes a knot piece of a table's ring, at most
  /// ... a piece of a panel between a table's knot tangencies: this many where the piece's
  /// integrand is singular at both ends, fewer (3 at least) where the singular points nearest to
  /// it allow
  int piece_nodes = 10;
};

/// The rule at t in [-1, 1] (t = 1: pure sliding, one node at nu = 1). The model's radius,
/// pressure, friction and shift are ignored (its profile is used on the unit disk).
SlipSpeedMeasure slip_speed_measure(const ExactModel<double>& model, double t,
                                    const SlipSpeedMeasureOptions& options = {});

}  // namespace contensou
