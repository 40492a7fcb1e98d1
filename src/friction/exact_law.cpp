// The exact law's tables (exact_law.hpp): the six functions of t sampled from the adaptive
// integrator and interpolated piecewise.
#include "contensou/friction/exact_law.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "exact_law_sampling.hpp"
#include "parallel_for.hpp"

namespace contensou {

namespace {

// Bound on the resultants' error (relative to f N, f N R) from errors e[i] of the functions,
// for kappa and shift k (the formulas of exact_law.hpp, each term at its largest).
double resultant_error_bound(const double* e, double kappa, double k) {
  const double km = std::max(1.0, kappa);
  const double force = km * (e[kLawSlide] + k * (e[kLawSpin] + e[kLawSpinSum]));
  const double torque = e[kLawSpin] * (1.0 + kappa) + e[kLawSpinSum] * km +
                        k * (0.5 * (1.0 + kappa) * e[kLawShiftDiff] +
                             std::abs(kappa - 1.0) * (e[kLawShiftCross] + e[kLawShiftSum]));
  return std::max(force, torque);
}

// The rounding level of the sampled functions (relative to the load): no table is refined below.
constexpr double kNoiseFloor = 1e-13;

// The error weights of the table functions at t (piecewise_chebyshev.hpp): the functions
// divided by sigma enter the resultants multiplied by sigma = (1 + t) / 2 (exact_law.hpp), a
// only as it is; `blocks` consecutive sets of the six.
void sigma_weights(double t, int blocks, double* w) {
  const double sigma = 0.5 * (1.0 + t);
  for (int b = 0; b < blocks; ++b)
    for (int i = 0; i < kLawFunctions; ++i) w[b * kLawFunctions + i] = i == kLawSpin ? 1.0 : sigma;
}

// cos(j k pi / NZ), j, k = 0..NZ, for the z Lobatto transform (lobatto_to_chebyshev), and the
// points between the Lobatto points, cos((k + 1/2) pi / NZ), k < NZ (z_interpolation_error):
// computed once a build (the transform runs for every function of every sample).
struct ZBasis {
  static constexpr int NZ = kSlipDegreeZ;
  double cos_jk[NZ + 1][NZ + 1], between[NZ];
  ZBasis() {
    for (int j = 0; j <= NZ; ++j)
      for (int k = 0; k <= NZ; ++k) cos_jk[j][k] = std::cos(std::numbers::pi * j * k / NZ);
    for (int k = 0; k < NZ; ++k) between[k] = std::cos(std::numbers::pi * (k + 0.5) / NZ);
  }
};

// Coefficients of T_k(x), k = 0..NZ, from values at the Lobatto points x_k = cos(k pi / NZ)
// (values[k * stride]).
void lobatto_to_chebyshev(const ZBasis& z, const double* values, int stride, double* c) {
  constexpr int n = ZBasis::NZ;
  for (int k = 0; k <= n; ++k) {
    double s = 0.0;
    for (int j = 0; j <= n; ++j)
      s += (j == 0 || j == n ? 0.5 : 1.0) * values[j * stride] * z.cos_jk[j][k];
    c[k] = (k == 0 || k == n ? 1.0 : 2.0) * s / n;
  }
}

// Turns each (t-coefficient, piece) block of values at the z Lobatto points into Chebyshev
// coefficients in z (the layout [k_z][function] within a block stays).
void values_to_z_coefficients(const ZBasis& z, PiecewiseChebyshev& table) {
  constexpr int NZ = kSlipDegreeZ, M = kLawFunctions * (NZ + 1);
  for (std::size_t block = 0; block + M <= table.coefficients.size(); block += M) {
    double* v = table.coefficients.data() + block;
    double out[M];
    for (int i = 0; i < kLawFunctions; ++i) {
      double c[NZ + 1];
      lobatto_to_chebyshev(z, v + i, kLawFunctions, c);
      for (int k = 0; k <= NZ; ++k) out[k * kLawFunctions + i] = c[k];
    }
    std::copy(out, out + M, v);
  }
}

// The largest |value| of the z-interpolation error of one function at the NZ points between its
// Lobatto points, from its values v[k * stride] at all 2 NZ + 1 points (Lobatto points first).
double z_interpolation_error(const ZBasis& z, const double* v, int stride) {
  constexpr int NZ = kSlipDegreeZ;
  double c[NZ + 1], worst = 0.0;
  lobatto_to_chebyshev(z, v, stride, c);
  for (int k = 0; k < NZ; ++k) {
    const double x = z.between[k];
    double s = c[0] + c[1] * x, tp = 1.0, tc = x;
    for (int m = 2; m <= NZ; ++m) {
      const double tn = 2.0 * x * tc - tp;
      s += c[m] * tn;
      tp = tc;
      tc = tn;
    }
    worst = std::max(worst, std::abs(s - v[(NZ + 1 + k) * stride]));
  }
  return worst;
}

// The Lebesgue constant of interpolation at the n + 1 Chebyshev-Lobatto points x_j = cos(j pi /
// n), max over [-1, 1] of sum_j |l_j(x)| (about (2 / pi) ln n + 0.6, below 2 for n = 8): the
// factor by which errors at the points can grow between them. The Lebesgue function is a sum of
// |polynomials| with its maxima between the points; sampled at 64 points between each pair, with
// a margin of 1 % for what the samples miss.
double lobatto_lebesgue_constant(int n) {
  std::vector<double> x(n + 1), w(n + 1);
  for (int j = 0; j <= n; ++j) {  // barycentric weights (-1)^j, halved at the ends
    x[j] = std::cos(std::numbers::pi * j / n);
    w[j] = (j % 2 ? -1.0 : 1.0) * (j == 0 || j == n ? 0.5 : 1.0);
  }
  double worst = 1.0;
  for (int j = 0; j < n; ++j)
    for (int k = 1; k < 64; ++k) {
      const double y = x[j] + (x[j + 1] - x[j]) * k / 64.0;
      double num = 0.0, den = 0.0;
      for (int i = 0; i <= n; ++i) {
        num += std::abs(w[i] / (y - x[i]));
        den += w[i] / (y - x[i]);
      }
      worst = std::max(worst, num / std::abs(den));
    }
  return 1.01 * worst;
}

// The table of the falling part (exact_law.hpp, SlipSpeedTable). Pieces of 1 + z are added until
// the functions at the top of the last one are below the tolerance at a set of t (beyond
// it they are taken as 0: the tail). Then one adaptive build in t for all pieces at once (one
// slip-speed quadrature a sampled t, on `threads` threads): its functions are the six functions'
// values at every piece's Lobatto points in z, checked between the t nodes; at every sampled t
// the z-interpolation is checked at the points between the z nodes. Finally each piece's values
// become Chebyshev coefficients in z.
constexpr int kMaxFallingPieces = 128;

struct FallingBuild {
  SlipSpeedTable table;
  double achieved = 0.0;  // largest error found (t-interpolation, z-interpolation, tail)
  bool reached = true;
  int samples = 0;
};

int falling_pieces(const ExactModel<double>& unit, double delta,
                   const SlipSpeedMeasureOptions& measure, double tolerance, unsigned threads) {
  constexpr int W = kSlipOctaves, kMaxPieces = 40 / W;
  const std::vector<double> probe_t{-1.0, -0.9, -0.5, -0.1, -1e-3, 0.0, 1e-3, 0.1, 0.5, 0.99};
  std::vector<double> zs;
  for (int J = 1; J <= kMaxPieces; ++J) zs.push_back(std::ldexp(1.0, J * W) - 1.0);
  std::vector<double> top(probe_t.size() * zs.size() * kLawFunctions);
  detail::parallel_for(probe_t.size(), threads, [&](std::size_t i) {
    detail::falling_functions(unit, delta, measure, probe_t[i], zs,
                              top.data() + i * zs.size() * kLawFunctions);
  });
  for (int J = 1; J <= kMaxPieces; ++J) {
    if (std::pow(zs[J - 1], 1.0 / delta) >= measure.largest_q) return J;
    // Weighted as the tail is in build_falling (sigma_weights): a function divided by sigma
    // enters the resultants multiplied by it.
    double worst = 0.0;
    for (std::size_t i = 0; i < probe_t.size(); ++i) {
      double w[kLawFunctions];
      sigma_weights(probe_t[i], 1, w);
      for (int c = 0; c < kLawFunctions; ++c)
        worst = std::max(worst, w[c] * std::abs(top[(i * zs.size() + J - 1) * kLawFunctions + c]));
    }
    if (worst < tolerance) return J;
  }
  return kMaxPieces;
}

// Stores the J octaves of a build (its functions: per t-coefficient, the octaves' values at their
// z Lobatto points) as blocks of z coefficients (SlipSpeedTable): an (octave, piece) pair whose
// functions are bounded below `negligible` on the piece (the sum of its |coefficients|, each
// weighted by the largest sigma there, sigma_weights) shares the zero block. Returns the largest
// bound so dropped.
double store_falling_blocks(const PiecewiseChebyshev& built, int J, double negligible,
                            const ZBasis& z, SlipSpeedTable& out) {
  constexpr int M = kLawFunctions * (kSlipDegreeZ + 1);
  const int n = built.degree, P = built.pieces();
  const std::size_t size = static_cast<std::size_t>(M) * (n + 1);
  out.octaves = J;
  out.pieces = built;
  out.pieces.functions = M;
  out.pieces.coefficients = {};
  out.pieces.slope_at_start = out.pieces.slope_at_end = {};
  out.coefficients.assign(size, 0.0);  // the zero block
  out.block.assign(static_cast<std::size_t>(J) * P, 0);
  double dropped = 0.0;
  for (int k = 0; k < P; ++k) {
    double w[kLawFunctions];  // sigma at the piece's upper end: the largest on it
    sigma_weights(built.breaks[k + 1], 1, w);
    for (int j = 0; j < J; ++j) {
      PiecewiseChebyshev one;  // the block: n + 1 rows of the octave's M functions
      one.functions = M;
      one.degree = n;
      for (int row = 0; row <= n; ++row) {
        const auto at = built.coefficients.begin() +
                        (static_cast<std::ptrdiff_t>(k) * (n + 1) + row) * J * M + j * M;
        one.coefficients.insert(one.coefficients.end(), at, at + M);
      }
      values_to_z_coefficients(z, one);
      double bound[kLawFunctions] = {};
      for (std::size_t i = 0; i < size; ++i)
        bound[i % kLawFunctions] += std::abs(one.coefficients[i]);
      double worst = 0.0;
      for (int c = 0; c < kLawFunctions; ++c) worst = std::max(worst, w[c] * bound[c]);
      if (worst <= negligible) {
        dropped = std::max(dropped, worst);
        continue;
      }
      out.block[static_cast<std::size_t>(j) * P + k] =
          static_cast<std::uint32_t>(out.coefficients.size());
      out.coefficients.insert(out.coefficients.end(), one.coefficients.begin(),
                              one.coefficients.end());
    }
  }
  return dropped;
}

FallingBuild build_falling(const ExactModel<double>& model, double delta, double tolerance,
                           const PiecewiseChebyshevOptions& base, unsigned threads,
                           const StopRequest& stop) {
  constexpr int NZ = kSlipDegreeZ, M = kLawFunctions * (NZ + 1);
  const ExactModel<double> unit = detail::unit_model(model);
  SlipSpeedMeasureOptions measure;
  measure.largest_q = 1e6;
  // The samples' own error a thousandth of the budget (the default 1e-13 at most, 1e-11 at least).
  measure.ring_tolerance = std::clamp(1e-3 * tolerance, 1e-13, 1e-11);
  // 10 nodes a panel in nu where the budget allows: on the seed tire and the 101-point table the
  // samples then move by 5e-13 (12: below 1e-13; 8: 4e-10).
  if (tolerance >= 1e-9) measure.nodes = 10;
  const int J = falling_pieces(unit, delta, measure, tolerance, threads);
  // Per piece: its NZ + 1 Lobatto points in z, then the NZ points between them.
  std::vector<double> zs;
  for (int j = 0; j < J; ++j) {
    for (int k = 0; k <= NZ; ++k)
      zs.push_back(detail::octave_point(j, std::cos(std::numbers::pi * k / NZ)) - 1.0);
    for (int k = 0; k < NZ; ++k)
      zs.push_back(detail::octave_point(j, std::cos(std::numbers::pi * (k + 0.5) / NZ)) - 1.0);
  }
  const std::size_t per_t = zs.size() * kLawFunctions;
  const ZBasis basis;
  double z_error = 0.0, tail = 0.0;
  auto sample = [&](const std::vector<double>& ts, double* values) {
    std::vector<double> all(ts.size() * per_t);
    detail::parallel_for(ts.size(), threads, [&](std::size_t i) {
      throw_if_stopped(stop);
      detail::falling_functions(unit, delta, measure, ts[i], zs, all.data() + i * per_t);
    });
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double* v = all.data() + i * per_t;
      double w[kLawFunctions];
      sigma_weights(ts[i], 1, w);
      for (int j = 0; j < J; ++j) {
        const double* piece = v + j * (2 * NZ + 1) * kLawFunctions;
        std::copy(piece, piece + M, values + (i * J + j) * M);
        for (int c = 0; c < kLawFunctions; ++c) {
          z_error =
              std::max(z_error, w[c] * z_interpolation_error(basis, piece + c, kLawFunctions));
          if (j == J - 1) tail = std::max(tail, w[c] * std::abs(piece[c]));  // the top: x = 1
        }
      }
    }
  };
  PiecewiseChebyshevOptions o = base;
  o.tolerance = tolerance / lobatto_lebesgue_constant(NZ);  // the t-errors at the z points
  o.weight = [J](double t, double* w) { sigma_weights(t, J * (kSlipDegreeZ + 1), w); };
  // A table's profile makes the falling part wiggle at large q where the centre of sliding
  // crosses its knots (jumps of p''): there the build stops at a bounded number of pieces and
  // reports what it reached.
  o.max_pieces = kMaxFallingPieces;
  const PiecewiseChebyshevBuild b = build_piecewise_chebyshev_batch(J * M, sample, o);
  FallingBuild out;
  out.table.exponent = delta;
  out.table.tail = tail;
  const double dropped = store_falling_blocks(b.table, J, 1e-3 * tolerance, basis, out.table);
  out.achieved = std::max({lobatto_lebesgue_constant(NZ) * b.achieved, z_error, tail}) + dropped;
  out.reached = b.reached && out.achieved <= 2.0 * tolerance;
  out.samples = b.samples;
  return out;
}

// Adds the falling table of the model's slip-speed law to a law whose constant table is built
// (`achieved` its bound so far); o are the constant table's options, k = |(kx, ky)|.
void add_falling_table(const ExactModel<double>& model, const ExactLawOptions& options,
                       const PiecewiseChebyshevOptions& o, double k, ExactLaw& law) {
  // Relative to f_s N: the constant part carries f_k, the falling part f_s - f_k, so the falling
  // table needs f_s / |f_s - f_k| times less accuracy.
  const SlipSpeedFriction<double>& f = *model.slip_speed;
  const double fs = std::max(f.static_coefficient, f.kinetic_coefficient);
  const double fall = std::abs(f.static_coefficient - f.kinetic_coefficient);
  if (fall == 0.0) {  // constant after all
    law.parameters.slip_speed.reset();
    law.parameters.friction = f.kinetic_coefficient;
    return;
  }
  PiecewiseChebyshevOptions of = o;
  of.degree = options.falling_degree;
  // The falling table gets 80 % of what the constant one left of the tolerance: the bound below
  // is (f_k e_constant + |f_s - f_k| e_falling) / f_s plus the representation's share.
  double err[kLawFunctions];
  std::fill(err, err + kLawFunctions, 1.0);
  const double per_function = options.tolerance / resultant_error_bound(err, model.kappa, k);
  const double representation = model.representation_error() * std::numbers::pi / law.load_area;
  const double left =
      0.8 * options.tolerance * fs - f.kinetic_coefficient * law.achieved - fs * representation;
  const double budget =
      std::clamp(left > 0.0 ? left / (fall * resultant_error_bound(err, model.kappa, k))
                            : 0.5 * per_function * fs / fall,
                 10.0 * kNoiseFloor, 1e-3);
  const FallingBuild fb =
      build_falling(model, f.exponent, budget, of, options.threads, options.stop);
  law.falling = fb.table;
  std::fill(err, err + kLawFunctions, fb.achieved);
  law.achieved =
      (f.kinetic_coefficient * law.achieved + fall * resultant_error_bound(err, model.kappa, k)) /
      fs;
  law.reached = law.reached && fb.reached;
  law.samples += fb.samples;
}

}  // namespace

ExactLaw make_exact_law(const ExactModel<double>& model, const ExactLawOptions& options) {
  if (!(options.tolerance > 1e-14 && options.tolerance < 1e-2))
    throw InvalidArgument("tolerance", format_value(options.tolerance),
                          "must lie in (1e-14, 1e-2)");
  for (const auto& [name, d] :
       {std::pair{"degree", options.degree}, std::pair{"falling_degree", options.falling_degree}})
    if (d != 8 && d != 10 && d != 12 && d != 14 && d != 16)
      throw InvalidArgument(name, std::to_string(d), "must be one of 8, 10, 12, 14, 16");
  if (model.associated_orthotropy && model.kappa != 1.0)
    throw InvalidArgument("kappa", format_value(model.kappa),
                          "the associated orthotropic law is tabulated for kappa = 1 only");
  if (!(model.radius > 0.0) || !(model.load_area > 0.0))
    throw InvalidArgument("radius", format_value(model.radius), "the model is not built");
  ExactLaw law;
  law.radius = model.radius;
  law.parameters = {model.pressure, model.friction, model.kappa,
                    model.kx,       model.ky,       model.slip_speed};
  law.tolerance = options.tolerance;
  // The functions are certified to a share of the tolerance that leaves room for the shift and
  // kappa of the model (resultant_error_bound) and the integrator's own error.
  const double k = std::hypot(model.kx, model.ky);
  double unit[kLawFunctions];
  std::fill(unit, unit + kLawFunctions, 1.0);
  const double per_function = options.tolerance / resultant_error_bound(unit, model.kappa, k);
  const detail::ConstantSampler sampler(model, std::min(1e-3 * per_function, 1e-11));
  law.load_area = sampler.load();
  PiecewiseChebyshevOptions o;
  o.degree = options.degree;
  // Below about 1e-13 of the load the five integrals' rounding (and the differences that make
  // a, b, c, d of them) is all a check sees: the table is not refined for it, and says so.
  // With a slip-speed law the constant table (tens of milliseconds) takes a tenth of that, to
  // leave the rest of the tolerance to the falling table (seconds; its budget below).
  o.tolerance = std::max((model.slip_speed ? 0.05 : 0.5) * per_function, kNoiseFloor);
  o.max_pieces = 512;
  o.breaks = graded_breaks(6);
  o.singular_points = {0.0};  // the centre of sliding on the rim (exact_law.hpp)
  o.weight = [](double t, double* w) { sigma_weights(t, 1, w); };
  const PiecewiseChebyshevBuild b = build_piecewise_chebyshev_batch(
      kLawFunctions,
      [&](const std::vector<double>& ts, double* g) {
        detail::parallel_for(ts.size(), options.threads, [&](std::size_t i) {
          throw_if_stopped(options.stop);
          sampler(ts[i], g + i * kLawFunctions);
        });
      },
      o);
  law.table = b.table;
  double err[kLawFunctions];
  std::fill(err, err + kLawFunctions, b.achieved + 1e-3 * per_function);
  law.achieved = resultant_error_bound(err, model.kappa, k);
  law.reached = b.reached;
  law.samples = b.samples;
  if (model.slip_speed) add_falling_table(model, options, o, k, law);
  law.achieved += model.representation_error() * std::numbers::pi / law.load_area;
  law.reached = law.reached && law.achieved <= options.tolerance;
  return law;
}

}  // namespace contensou
