/// \file
/// Piecewise Chebyshev interpolation of several functions of one variable on [-1, 1], built
/// adaptively against a sampler and certified at the points between its nodes (the tables of
/// the exact law, exact_law.hpp).
///
/// On a piece [a, b] each function is the polynomial of degree n through its values at the
/// n + 1 Chebyshev-Lobatto points x_j = cos(j pi / n) of the piece's local variable
/// x = (2 t - a - b) / (b - a), written as sum_k c_k T_k(x). Neighbouring pieces share their
/// end point, so the interpolant is continuous (to rounding) wherever the sampled function is.
#pragma once

#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

namespace contensou {

/// m functions of t in [-1, 1] as Chebyshev series of one degree on shared pieces: the tables
/// of the exact law (exact_law.hpp), built by build_piecewise_chebyshev.
struct PiecewiseChebyshev {
  int functions = 0;                 ///< m functions share the pieces
  int degree = 0;                    ///< n: n + 1 nodes a piece
  std::vector<double> breaks;        ///< piece ends, increasing, from -1 to 1
  std::vector<double> coefficients;  ///< [piece][k][function], k = 0..n (functions innermost)
  /// Derivatives d/dt at the two ends (t = -1 and t = 1) of every function, for the limits of
  /// the exact law at v = 0 and omega = 0 (exact_law.hpp).
  std::vector<double> slope_at_start;
  std::vector<double> slope_at_end;  ///< as slope_at_start, at t = 1
  /// x = t * map[2k] + map[2k + 1] on piece k; and a lookup index: the first piece of each cell
  /// of |t| in steps of 1/16 octave (detail::cell_of), so that finding the piece costs a shift,
  /// a load and rarely a step. Filled by build_piecewise_chebyshev (index_pieces).
  std::vector<double> map;
  std::vector<std::uint16_t> index;  ///< the lookup index (map, above)

  int pieces() const { return static_cast<int>(breaks.size()) - 1; }  ///< their number
  /// The table's memory [bytes].
  std::size_t bytes() const {
    return (breaks.size() + coefficients.size() + slope_at_start.size() + slope_at_end.size() +
            map.size()) *
               sizeof(double) +
           index.size() * sizeof(std::uint16_t);
  }
};

/// Samples the m functions at t: writes values[0..m-1].
using ChebyshevSampler = std::function<void(double t, double* values)>;
/// Samples the m functions at every t of ts (values[k * m + i]); may work on them in parallel.
using ChebyshevBatchSampler = std::function<void(const std::vector<double>& ts, double* values)>;

/// How build_piecewise_chebyshev refines the pieces.
struct PiecewiseChebyshevOptions {
  int degree = 16;  ///< of every piece's series
  /// Each function's largest error between the nodes must be <= tolerance * scale[i].
  double tolerance = 1e-9;
  std::vector<double> scale;  ///< m entries (default 1)
  /// Optional weights of the errors at t (w[0..m-1], default 1): an error that enters the
  /// result multiplied by a small factor there (the exact law's functions divided by sigma)
  /// needs that much less accuracy, and sampling noise divided by it must not drive refinement.
  std::function<void(double t, double* w)> weight;
  std::vector<double> breaks;     ///< initial partition (default: halves graded towards t = 0)
  double smallest_width = 1e-13;  ///< pieces are not split below this width
  /// Points where the functions have an x log|x| singularity (the errors of a piece ending there
  /// shrink like its width squared): such a piece that misses the tolerance is split towards the
  /// point at once into as many halvings as its error asks for (the pieces bisection would reach).
  std::vector<double> singular_points;
  int max_pieces = 4000;  ///< the build stops refining (reached = false) beyond it
};

/// A table and what its build found.
struct PiecewiseChebyshevBuild {
  PiecewiseChebyshev table;  ///< the pieces and their coefficients
  double achieved = 0.0;     ///< largest error between the nodes / (scale), over all pieces
  bool reached = true;       ///< false if a piece at the smallest width still missed the tolerance
  double worst_t = 0.0;      ///< where the largest error was found
  int samples = 0;           ///< calls of the sampler
};

/// Adaptive build: each piece is checked at the n midpoints between its Lobatto nodes
/// (x = cos((j + 1/2) pi / n)) against the sampler and bisected while it misses the tolerance.
/// Throws std::invalid_argument for functions < 1 or a degree outside [2, 40]; what the sampler
/// throws (Interrupted from a stop request) passes through.
PiecewiseChebyshevBuild build_piecewise_chebyshev(int functions, const ChebyshevSampler& sample,
                                                  const PiecewiseChebyshevOptions& options);
/// The same with the points of each piece sampled in one call.
PiecewiseChebyshevBuild build_piecewise_chebyshev_batch(int functions,
                                                        const ChebyshevBatchSampler& sample,
                                                        const PiecewiseChebyshevOptions& options);

/// Fills the table's map and index from its breaks (after editing breaks by hand).
void index_pieces(PiecewiseChebyshev& table);

/// The initial partition: -1, -1/2, ..., -2^-levels, 0, 2^-levels, ..., 1/2, 1 (geometric towards
/// the singular point t = 0, where the centre of sliding crosses the rim).
std::vector<double> graded_breaks(int levels);

namespace detail {

/// The lookup cells: |t| >= 2^-40 in sixteenths of an octave (the top 16 bits of the double,
/// which grow with it), mirrored for t < 0; |t| < 2^-40 is one cell each side.
inline constexpr int kCellsPerSide = 642;
inline int cell_of(double t) {
  constexpr std::uint64_t low = std::bit_cast<std::uint64_t>(0x1p-40) >> 48;
  const double a = t < 0.0 ? -t : t;
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(a) >> 48;
  const int key = bits >= low ? static_cast<int>(bits - low) + 1 : 0;  // 0 .. 641
  return t < 0.0 ? kCellsPerSide - 1 - key : kCellsPerSide + key;
}

/// Index of the piece holding t in [-1, 1].
inline int piece_of(const PiecewiseChebyshev& p, double t) {
  const double* b = p.breaks.data();
  const int last = p.pieces() - 1;
  if (!p.index.empty()) {
    int k = p.index[cell_of(t)];
    while (k < last && b[k + 1] <= t) ++k;
    return k;
  }
  int lo = 0, n = last + 1;
  while (n > 1) {  // branch-free binary search on breaks[1..pieces-1]
    const int half = n / 2;
    lo = (b[lo + half] <= t) ? lo + half : lo;
    n -= half;
  }
  return lo;
}

/// The piece holding t, with the local variable x in [-1, 1] and dx/dt.
inline int locate_piece_index(const PiecewiseChebyshev& p, double t, double& x, double& dxdt) {
  t = t < -1.0 ? -1.0 : (t > 1.0 ? 1.0 : t);
  const int k = piece_of(p, t);
  dxdt = p.map[2 * k];
  x = t * dxdt + p.map[2 * k + 1];
  x = x < -1.0 ? -1.0 : (x > 1.0 ? 1.0 : x);
  return k;
}

/// The coefficients of the piece holding t, with the local variable x in [-1, 1] and dx/dt.
inline const double* locate_piece(const PiecewiseChebyshev& p, double t, double& x, double& dxdt) {
  const int k = locate_piece_index(p, t, x, dxdt);
  return p.coefficients.data() + static_cast<std::size_t>(k) * p.functions * (p.degree + 1);
}

/// T_0..T_N at x with a short dependency chain: T_0..T_4 directly, then T_(4b + k) = 2 T_(4b) T_k
/// - T_(4b - k) with T_(4b) = 2 T_(2b)^2 - 1 (from T_(m+n) = 2 T_m T_n - T_(m-n)); and with D
/// the derivatives T_j'(x) by the same identities differentiated.
template <int N, bool Slope>
inline void chebyshev_basis(double x, double* T, double* D) {
  static_assert(N >= 4);
  T[0] = 1.0;
  T[1] = x;
  T[2] = 2.0 * x * x - 1.0;
  T[3] = x * (2.0 * T[2] - 1.0);
  T[4] = 2.0 * T[2] * T[2] - 1.0;
  if constexpr (Slope) {
    D[0] = 0.0;
    D[1] = 1.0;
    D[2] = 4.0 * x;
    D[3] = 12.0 * x * x - 3.0;
    D[4] = 4.0 * T[2] * D[2];
  }
  for (int b = 4; b + 1 <= N; b += 4) {
    if (b > 4) {
      T[b] = 2.0 * T[b / 2] * T[b / 2] - 1.0;
      if constexpr (Slope) D[b] = 4.0 * T[b / 2] * D[b / 2];
    }
    for (int k = 1; k < 4 && b + k <= N; ++k) {
      T[b + k] = 2.0 * T[b] * T[k] - T[b - k];
      if constexpr (Slope) D[b + k] = 2.0 * (D[b] * T[k] + T[b] * D[k]) - D[b - k];
    }
  }
  if constexpr (N >= 8 && N % 4 == 0) {
    T[N] = 2.0 * T[N / 2] * T[N / 2] - 1.0;
    if constexpr (Slope) D[N] = 4.0 * T[N / 2] * D[N / 2];
  }
}

/// sum_k c[k][i] T_k(x) for M functions of degree n (and the slopes d/dx if slope is not null),
/// unrolled for the tables of the exact law: M = 6 (constant friction) or 6 (kSlipDegreeZ + 1)
/// (the falling part of a slip-speed law) and n in {8, 10, 12, 14, 16}; compiled for the
/// baseline instruction set and for AVX2 with FMA, chosen once from the CPU
/// (chebyshev_kernels.cpp). Null for other sizes.
using ChebyshevKernel = void (*)(const double* c, double x, double* out, double* slope);
ChebyshevKernel chebyshev_kernel(int functions, int degree, bool slope);

/// sum_k c[k][i] T_k(x) (and d/dx into slope if not null) of m functions of degree n from their
/// coefficients c ([k][function]): the kernel where one exists.
void chebyshev_sums(const double* c, int m, int n, double x, double* out, double* slope);

}  // namespace detail

/// Values of all m functions at t (out[0..m-1]); t outside [-1, 1] is clamped.
void evaluate_chebyshev(const PiecewiseChebyshev& p, double t, double* out);

/// Values and derivatives d/dt of all m functions at t.
void evaluate_chebyshev(const PiecewiseChebyshev& p, double t, double* out, double* slope);

namespace detail {
/// The coefficients, in `p`, of the piece of `partition` that holds t (tables on the same pieces).
inline const double* coefficients_at(const PiecewiseChebyshev& partition,
                                     const PiecewiseChebyshev& p, double t, double& x,
                                     double& dxdt) {
  const double* c = locate_piece(partition, t, x, dxdt);
  return p.coefficients.data() +
         (c - partition.coefficients.data()) / partition.functions * p.functions;
}
}  // namespace detail

/// evaluate_chebyshev through the unrolled kernels where one exists (the hot path of the exact
/// law), with the pieces of `partition` and the coefficients of `coefficients` (a table on the
/// same pieces, by default the partition's own).
inline void evaluate_chebyshev_fast(const PiecewiseChebyshev& partition, double t, double* out,
                                    const PiecewiseChebyshev* coefficients = nullptr) {
  const PiecewiseChebyshev& p = coefficients ? *coefficients : partition;
  double x, dxdt;
  const double* c = detail::coefficients_at(partition, p, t, x, dxdt);
  if (const detail::ChebyshevKernel k = detail::chebyshev_kernel(p.functions, p.degree, false))
    k(c, x, out, nullptr);
  else
    evaluate_chebyshev(p, t, out);
}

/// The same with the slopes d/dt.
inline void evaluate_chebyshev_fast(const PiecewiseChebyshev& partition, double t, double* out,
                                    double* slope,
                                    const PiecewiseChebyshev* coefficients = nullptr) {
  const PiecewiseChebyshev& p = coefficients ? *coefficients : partition;
  double x, dxdt;
  const double* c = detail::coefficients_at(partition, p, t, x, dxdt);
  if (const detail::ChebyshevKernel k = detail::chebyshev_kernel(p.functions, p.degree, true)) {
    k(c, x, out, slope);
    for (int i = 0; i < p.functions; ++i) slope[i] *= dxdt;
  } else {
    evaluate_chebyshev(p, t, out, slope);
  }
}

}  // namespace contensou
