/// \file
/// The exact law: the exact resultants of a patch (theory.md §2) from tables of six functions of
/// t = (|v| - |omega| R) / (|v| + |omega| R), built once per pressure profile (make_exact_law),
/// evaluated at the cost of a closed-form law (exact_law_resultants) with the Jacobian and a
/// certified error bound (`achieved`, relative to f N and f N R). The derivation of the six
/// functions and of the resultants from them: docs/theory.md §7.4.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

#include "contensou/friction/contact_patch.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_resultants.hpp"
#include "contensou/friction/kinematics.hpp"
#include "contensou/friction/piecewise_chebyshev.hpp"
#include "contensou/friction/scalar.hpp"

namespace contensou {

/// How make_exact_law builds the law.
struct ExactLawOptions {
  /// Requested accuracy of the resultants, relative to f N (forces) and f N R (torque), for the
  /// model's own kappa and shift; in (1e-14, 1e-2).
  double tolerance = 1e-8;
  int degree = 12;         ///< of the Chebyshev pieces in t (8, 10, 12, 14 or 16)
  int falling_degree = 8;  ///< the same for the falling part of a slip-speed law
  unsigned threads = 0;    ///< of the build (0: one a core); the law is the same for any number
  StopRequest stop{};      ///< polled before every sample: Interrupted when it returns true
};

/// The table functions (exact_law.hpp header), in this order.
enum ExactLawFunction : int {
  kLawSlide,       ///< A / (sigma L)
  kLawSpin,        ///< a / L
  kLawSpinSum,     ///< (a + b) / (sigma L)
  kLawShiftCross,  ///< (alpha - c) / (sigma L)
  kLawShiftDiff,   ///< (c - d) / (sigma L)
  kLawShiftSum,    ///< (c + d) / (sigma L)
  kLawFunctions    ///< their number
};

/// What the table leaves free: the patch's scale and the parameters that enter the resultants
/// algebraically. T = double, or an automatic-differentiation type (ceres::Jet).
template <class T = double>
struct ExactLawParameters {
  T pressure{0};  ///< p* [Pa]
  T friction{0};  ///< f (unused if slip_speed is set)
  T kappa{1};     ///< lateral / longitudinal friction ratio
  T kx{0};        ///< pressure shift along x (relative to the law's radius)
  T ky{0};        ///< pressure shift along y (relative to the law's radius)
  /// f(w) = f_k + (f_s - f_k) exp(-(w / w_s)^delta) inside the integrals; delta must be the
  /// exponent the law's table was built for.
  std::optional<SlipSpeedFriction<T>> slip_speed;
};

/// The default degree in z of the falling part's table (SlipSpeedTable::degree_z).
inline constexpr int kSlipDegreeZ = 8;
inline constexpr int kSlipOctaves = 1;  ///< octaves of 1 + z a piece
/// The falling part g(w) = exp(-(w / w_s)^delta) of a slip-speed law: the six functions of
/// (t, z), z = (q)^delta, q = (|v| + |omega| R) / w_s, the speed in units of w_s. One table in t
/// per octave of 1 + z (1 + z in [2^j, 2^(j+1))), Chebyshev of degree degree_z in x = 2 (1 + z) /
/// 2^j - 3 within it: the 6 (degree_z + 1) "functions" of octave j are the coefficients c[k][i] of
/// T_k(x). Beyond the last octave the functions are taken as 0 (tail bounds them there). All
/// octaves share the pieces in t (`pieces`: breaks, map, index, no coefficients); each (octave,
/// piece) has a block of 6 (degree_z + 1) (degree + 1) coefficients in `coefficients`, at offset
/// block[octave * pieces + piece]. Block 0 is all zeros: the (octave, piece) pairs whose functions
/// are below a small share of the tolerance there (large z far from t = 0, where exp(-z nu) is
/// negligible) share it (the bound of what they drop is in the build's `achieved`).
struct SlipSpeedTable {
  double exponent = 1.0;        ///< delta
  int degree_z = kSlipDegreeZ;  ///< the Chebyshev degree in an octave's variable
  double tail = 0.0;            ///< largest |function| found at the top of the last octave
  int octaves = 0;              ///< octaves of 1 + z tabulated
  PiecewiseChebyshev pieces;    ///< the pieces in t (functions = 6 (degree_z + 1), no coefficients)
  std::vector<std::uint32_t> block;  ///< [octave][piece]: offset in coefficients
  std::vector<double> coefficients;  ///< the blocks, [k_t][k_z][function] within one
  /// The table's memory [bytes].
  std::size_t bytes() const {
    return pieces.bytes() + coefficients.size() * sizeof(double) +
           block.size() * sizeof(std::uint32_t);
  }
};

/// The exact law of a model: the tables of six functions of t (theory.md §2; docs/theory.md
/// §7.4), built by make_exact_law, evaluated by exact_law_resultants.
struct ExactLaw {
  double radius = 0.0;                    ///< R [m] (the model's integration radius)
  double load_area = 0.0;                 ///< L = N / (p* R^2) = 2 pi A^1
  ExactLawParameters<double> parameters;  ///< those of the model it was built from
  PiecewiseChebyshev table;               ///< the six functions of t, constant friction
  std::optional<SlipSpeedTable> falling;  ///< the falling part of a slip-speed law
  double tolerance = 0.0;                 ///< requested
  double achieved = 0.0;  ///< bound on the error found between the nodes (relative, see above)
  bool reached = true;    ///< achieved <= tolerance
  int samples = 0;        ///< adaptive-integrator calls of the build (each five integrals)
  /// The law's memory [bytes].
  std::size_t bytes() const { return table.bytes() + (falling ? falling->bytes() : 0); }
};

/// Builds the law of a model (the associated orthotropic law only for kappa = 1). A slip-speed
/// law adds the table of its falling part for its exponent delta. Throws InvalidArgument for a
/// tolerance outside (1e-14, 1e-2), a degree outside [4, 32], or a model the table cannot
/// represent.
ExactLaw make_exact_law(const ExactModel<double>& model, const ExactLawOptions& options = {});

namespace detail {

/// Chain rule through a table: value v and slope dv/dt at value_of(t), as a T that carries t's
/// derivatives (for double, just v).
template <class T>
T lift(double v, double slope, const T& t) {
  if constexpr (std::is_arithmetic_v<T>) {
    (void)slope;
    (void)t;
    return v;
  } else {
    return T(v) + slope * (t - T(value_of(t)));
  }
}

/// The six table functions at t, lifted to T.
template <class T>
void law_functions(const PiecewiseChebyshev& table, const T& t, T* g) {
  if constexpr (std::is_arithmetic_v<T>) {
    evaluate_chebyshev_fast(table, t, g);
  } else {
    double v[kLawFunctions], s[kLawFunctions];
    evaluate_chebyshev_fast(table, value_of(t), v, s);
    for (int i = 0; i < kLawFunctions; ++i) g[i] = lift(v[i], s[i], t);
  }
}

/// The piece j of a = 1 + z (a in [2^(jW), 2^((j+1)W)), W = kSlipOctaves, z >= 0) and its local
/// variable, the Moebius map x = (a - c) / (a + c) / x_max with c = 2^(jW + W/2) (the geometric
/// mean of the ends), which maps the half plane Re a > 0, where the functions are bounded, onto
/// a disk: the Chebyshev series converge like (x_max / (1 + sqrt(1 - x_max^2)))^n. From the bits
/// of the double; -1 beyond the table.
inline int octave_of(const SlipSpeedTable& s, double z, double& x, double& dxdz) {
  constexpr int W = kSlipOctaves;
  constexpr double r = W == 1 ? 1.4142135623730951 : (W == 2 ? 2.0 : 2.8284271247461903);
  constexpr double x_max = (r - 1.0) / (r + 1.0);  // at a = 2^(jW + W) (and -x_max at 2^(jW))
  const double a = 1.0 + z;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(a);
  const int e = static_cast<int>(bits >> 52) - 1023;
  if (e < 0) return -1;
  const int j = e / W;
  if (j >= s.octaves) return -1;
  const double c = std::ldexp(r, j * W), den = 1.0 / (a + c);
  x = (a - c) * den * (1.0 / x_max);
  dxdz = 2.0 * c * den * den * (1.0 / x_max);
  return j;
}

/// The points a = 1 + z of piece j at local variables x (the inverse of octave_of's map).
inline double octave_point(int j, double x) {
  constexpr int W = kSlipOctaves;
  constexpr double r = W == 1 ? 1.4142135623730951 : (W == 2 ? 2.0 : 2.8284271247461903);
  constexpr double x_max = (r - 1.0) / (r + 1.0);
  const double c = std::ldexp(r, j * W), u = x * x_max;
  return c * (1.0 + u) / (1.0 - u);
}

/// The falling part's six functions with their derivatives in t and z from the coefficients c of
/// a piece (t at x on it, x' = dx/dt; z at xz in its octave, xz' = dxz/dz), in one kernel where
/// the CPU's instruction set has one (AVX2 without AVX-512; chebyshev_kernels.cpp), else null.
using SlipSpeedKernel = void (*)(const double* c, double x, double dxdt, double xz, double dxzdz,
                                 double* g, double* gt, double* gz);
SlipSpeedKernel slip_speed_kernel(int degree);

/// The coefficients of the falling part's piece holding t in octave j, with the local variable
/// x of t on the piece and dx/dt.
inline const double* falling_block(const SlipSpeedTable& s, int j, double t, double& x,
                                   double& dxdt) {
  const int k = locate_piece_index(s.pieces, t, x, dxdt);
  return s.coefficients.data() + s.block[static_cast<std::size_t>(j) * s.pieces.pieces() + k];
}

/// The falling part's six functions at (t, z) and, if Slope, their derivatives in t and z.
template <bool Slope>
void falling_values(const SlipSpeedTable& s, double t, double z, double* g, double* gt,
                    double* gz) {
  constexpr int NZ = kSlipDegreeZ, M = kLawFunctions * (NZ + 1);
  double x = 0.0, dxdz = 0.0;  // set by octave_of when j >= 0
  const int j = octave_of(s, z, x, dxdz);
  for (int i = 0; i < kLawFunctions; ++i) g[i] = 0.0;
  if constexpr (Slope)
    for (int i = 0; i < kLawFunctions; ++i) gt[i] = gz[i] = 0.0;
  if (j < 0) return;
  double xt = 0.0, dxdt = 0.0;
  const double* c = falling_block(s, j, t, xt, dxdt);
  if constexpr (Slope) {
    if (const SlipSpeedKernel kernel = slip_speed_kernel(s.pieces.degree)) {
      kernel(c, xt, dxdt, x, dxdz, g, gt, gz);
      return;
    }
  }
  double B[M], dB[M], T[NZ + 1], D[NZ + 1];
  chebyshev_sums(c, M, s.pieces.degree, xt, B, Slope ? dB : nullptr);
  if constexpr (Slope)
    for (int i = 0; i < M; ++i) dB[i] *= dxdt;
  chebyshev_basis<NZ, Slope>(x, T, D);
  for (int k = 0; k <= NZ; ++k)
    for (int i = 0; i < kLawFunctions; ++i) {
      g[i] += B[k * kLawFunctions + i] * T[k];
      if constexpr (Slope) {
        gt[i] += dB[k * kLawFunctions + i] * T[k];
        gz[i] += B[k * kLawFunctions + i] * D[k] * dxdz;
      }
    }
}

/// G_i = f g_i (constant friction), or f_k g_i(t) + (f_s - f_k) h_i(t, z) with z = (S / w_s)^delta
/// (S = |v| + |omega| R [m/s]), as the product type R of the parameters P and kinematics K.
template <class R, class P, class K>
void friction_functions(const ExactLaw& law, const ExactLawParameters<P>& p, const K& t,
                        const K& speed, R* G) {
  using std::pow;
  K g[kLawFunctions];
  law_functions(law.table, t, g);
  if (!p.slip_speed) {
    for (int i = 0; i < kLawFunctions; ++i) G[i] = p.friction * g[i];
    return;
  }
  const SlipSpeedFriction<P>& f = *p.slip_speed;
  if (!law.falling)
    throw InvalidArgument("slip_speed", "set",
                          "the law has no table of a slip-speed law: build it from a model with "
                          "slip_speed_friction");
  if (value_of(f.exponent) != law.falling->exponent)
    throw InvalidArgument(
        "slip_speed.exponent", format_value(value_of(f.exponent)),
        "must be the exponent the law was built for, " + format_value(law.falling->exponent));
  const R q = speed / f.reference_speed;
  const R z = law.falling->exponent == 1.0 ? q : R(pow(q, law.falling->exponent));
  const P fall = f.static_coefficient - f.kinetic_coefficient;
  double h[kLawFunctions], ht[kLawFunctions], hz[kLawFunctions];
  if constexpr (std::is_arithmetic_v<R>) {
    falling_values<false>(*law.falling, t, z, h, ht, hz);
    for (int i = 0; i < kLawFunctions; ++i) G[i] = f.kinetic_coefficient * g[i] + fall * h[i];
  } else {
    falling_values<true>(*law.falling, value_of(t), value_of(z), h, ht, hz);
    const R dt = R(t) - R(value_of(t)), dz = z - R(value_of(z));
    for (int i = 0; i < kLawFunctions; ++i)
      G[i] = f.kinetic_coefficient * g[i] + fall * (R(h[i]) + ht[i] * dt + hz[i] * dz);
  }
}

}  // namespace detail

/// Fx, Fy, Mz of the law at kinematics k with parameters p (exact_law.hpp header). Zero at
/// v = omega = 0 (Coulomb friction is set-valued there; 0 is in the set), and below 1e-290 m/s.
/// Throws InvalidArgument for non-finite kinematics. The parameters and the kinematics may have
/// different scalar types (double parameters with differentiated kinematics for a Jacobian;
/// differentiated parameters with measured kinematics in a fit); the result has the type of their
/// product.
template <class P, class K>
auto exact_law_resultants(const ExactLaw& law, const ExactLawParameters<P>& p,
                          const Kinematics<K>& k) {
  using std::sqrt;
  using R = decltype(std::declval<P>() * std::declval<K>());
  require_finite("vx", value_of(k.vx));
  require_finite("vy", value_of(k.vy));
  require_finite("omega", value_of(k.omega));
  const double radius = law.radius;
  // Scaled velocities (the functions depend on ratios only): no square over- or underflows.
  const double scale = std::max(
      {std::abs(value_of(k.vx)), std::abs(value_of(k.vy)), std::abs(value_of(k.omega)) * radius});
  // Below 1e-290 m/s (where 1/speed, and with it the Jacobian, would overflow) it is rest.
  if (!(scale > 1e-290)) return Resultants<R>{R(0.0), R(0.0), R(0.0)};
  const double inv = 1.0 / scale;
  const K vx = k.vx * inv, vy = k.vy * inv, w = k.omega * (radius * inv);
  // e = v/|v|; at |v| = 0 (or below 1e-150 of the scale) any direction: every term that
  // depends on it vanishes there.
  const double vxv = value_of(vx), vyv = value_of(vy);
  K ex, ey, v;
  if (vxv * vxv + vyv * vyv > 1e-300) {
    v = sqrt(vx * vx + vy * vy);
    const K iv = 1.0 / v;
    ex = vx * iv;
    ey = vy * iv;
  } else {
    ex = K(1.0);
    ey = K(0.0);
    v = vxv < 0.0 ? -vx : vx;  // |v| to first order along e = x
  }
  const double sgn = value_of(w) < 0.0 ? -1.0 : 1.0;
  const K S = v + sgn * w;
  const K sigma = v / S;  // t = 2 sigma - 1
  R G[kLawFunctions];
  detail::friction_functions(law, p, K(2.0 * sigma - 1.0), K(S * scale), G);
  // With xi = v / S (sigma e: smooth at v = 0) and the terms whose coefficients vanish at v = 0
  // (a + b, and (c + d) - (alpha - c)) kept with e (f folded into G; z x k = (-ky, kx)):
  //   F = -p* R^2 L D [A/sigma xi + s (a (z x k) + (a + b)/sigma k_perp xi)]
  const K xi_x = vx / S, xi_y = vy / S;
  const R kperp = p.ky * ex - p.kx * ey;
  const R along = G[kLawSlide] + sgn * G[kLawSpinSum] * kperp;
  const R spin = sgn * G[kLawSpin];
  const P pN = p.pressure * (radius * radius * law.load_area);
  Resultants<R> r;
  r.Fx = -pN * (along * xi_x - spin * p.ky);
  r.Fy = -pN * p.kappa * (along * xi_y + spin * p.kx);
  //   Mz = -p* R^3 L [s (a (1 + kappa) - (a + b)/sigma xi'D e) + (1 + kappa)/2 (c - d)/sigma
  //        (ky xi_x - kx xi_y) + (kappa - 1)/2 ((alpha - c)/sigma (kx xi_y + ky xi_x)
  //        + ((c + d) - (alpha - c))/sigma (xi_x e_x - xi_y e_y) k_perp)]
  // (the kappa - 1 terms of docs/theory.md §7.4 combined: e_x e_y k_par + (e_x^2 - e_y^2) k_perp /
  // 2 = (kx e_y + ky e_x) / 2).
  const R spin_torque =
      spin * (1.0 + p.kappa) - sgn * G[kLawSpinSum] * (xi_x * ex + p.kappa * (xi_y * ey));
  const R shift_torque =
      0.5 * (1.0 + p.kappa) * G[kLawShiftDiff] * (p.ky * xi_x - p.kx * xi_y) +
      0.5 * (p.kappa - 1.0) *
          (G[kLawShiftCross] * (p.kx * xi_y + p.ky * xi_x) +
           (G[kLawShiftSum] - G[kLawShiftCross]) * (xi_x * ex - xi_y * ey) * kperp);
  r.Mz = -pN * radius * (spin_torque + shift_torque);
  return r;
}

/// The law at the parameters of the model it was built from.
inline Resultants<double> exact_law_resultants(const ExactLaw& law, const Kinematics<double>& k) {
  return exact_law_resultants(law, law.parameters, k);
}

/// The law and its Jacobian d(Fx, Fy, Mz)/d(vx, vy, omega), the exact derivative of the
/// interpolant (continuous, finite at every finite input; at v = 0 and omega = 0 the limits).
struct ExactLawWithJacobian {
  Resultants<double> resultants;  ///< Fx, Fy, Mz [N, N, N m]
  Eigen::Matrix3d jacobian;       ///< rows Fx, Fy, Mz; columns vx, vy, omega
};
/// The law and its Jacobian at the parameters of the model it was built from. Throws
/// InvalidArgument for non-finite velocities.
ExactLawWithJacobian exact_law_resultants_with_jacobian(const ExactLaw& law,
                                                        const Kinematics<double>& k);
/// The same at other parameters (exact_law_resultants).
ExactLawWithJacobian exact_law_resultants_with_jacobian(const ExactLaw& law,
                                                        const ExactLawParameters<double>& p,
                                                        const Kinematics<double>& k);

}  // namespace contensou
