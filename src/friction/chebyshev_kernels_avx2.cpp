// The unrolled Chebyshev kernels compiled for AVX2 with FMA (chebyshev_kernels.cpp chooses
// them on a CPU that has both). This file alone is compiled with -mavx2 -mfma.
#include <immintrin.h>

#include "chebyshev_kernels.hpp"

namespace contensou::detail::avx2 {
#include "chebyshev_kernels.inc"

namespace {

// The values and slopes of F functions (F = 4 V or 4 V + 2) of an M-function table of degree
// N, the 2 V (+ 2) running sums in registers: with 16 ymm registers the 54 functions of a
// slip-speed table with slopes (27 vectors) do not fit at once, blocks of 18 do (10 sums, the
// two basis values and a load). Not inlined: the compiler would share the broadcasts of the
// basis between the blocks and spill them.
template <int M, int N, int F>
[[gnu::noinline]] void slope_block(const double* c, const double* T, const double* D,
                                   double* __restrict out, double* __restrict slope) {
  static_assert(F % 4 == 0 || F % 4 == 2);
  constexpr int V = F / 4;
  constexpr bool tail = F % 4 == 2;
  __m256d a[V], d[V];
  __m128d at = _mm_setzero_pd(), dt = _mm_setzero_pd();
#pragma GCC unroll 8
  for (int v = 0; v < V; ++v) a[v] = d[v] = _mm256_setzero_pd();
#pragma GCC unroll 17
  for (int k = 0; k <= N; ++k) {
    const double* ck = c + k * M;
    const __m256d tk = _mm256_broadcast_sd(T + k), dk = _mm256_broadcast_sd(D + k);
#pragma GCC unroll 8
    for (int v = 0; v < V; ++v) {
      const __m256d cv = _mm256_loadu_pd(ck + 4 * v);
      a[v] = _mm256_fmadd_pd(cv, tk, a[v]);
      d[v] = _mm256_fmadd_pd(cv, dk, d[v]);
    }
    if constexpr (tail) {
      const __m128d cv = _mm_loadu_pd(ck + 4 * V);
      at = _mm_fmadd_pd(cv, _mm256_castpd256_pd128(tk), at);
      dt = _mm_fmadd_pd(cv, _mm256_castpd256_pd128(dk), dt);
    }
  }
#pragma GCC unroll 8
  for (int v = 0; v < V; ++v) {
    _mm256_storeu_pd(out + 4 * v, a[v]);
    _mm256_storeu_pd(slope + 4 * v, d[v]);
  }
  if constexpr (tail) {
    _mm_storeu_pd(out + 4 * V, at);
    _mm_storeu_pd(slope + 4 * V, dt);
  }
}

// sums<M, N, true> of the slip-speed table (M = 54) in three blocks of 18 functions.
template <int N>
void blocked_slope_sums(const double* c, double x, double* out, double* slope) {
  constexpr int M = contensou::kLawFunctions * (contensou::kSlipDegreeZ + 1), F = M / 3;
  static_assert(M % 3 == 0);
  double T[N + 1], D[N + 1];
  contensou::detail::chebyshev_basis<N, true>(x, T, D);
  slope_block<M, N, F>(c, T, D, out, slope);
  slope_block<M, N, F>(c + F, T, D, out + F, slope + F);
  slope_block<M, N, F>(c + 2 * F, T, D, out + 2 * F, slope + 2 * F);
}

// The Chebyshev basis in z of falling_sums and the chain factors of its slopes.
struct ZPointBasis {
  const double* T;  // T_k(x), k = 0..8, x the z point's place in its octave
  const double* D;  // T_k'(x)
  double dxdt;      // factor of the t-slopes
  double dxdz;      // factor of the z-slopes
};

// The z sums of falling_sums: the rows B (values) and dB (t-slopes) of the 54 = 9 x 6 flat
// functions (z degree k, function i: flat 6 k + i, 32-byte aligned) times T_k(x) and T_k'(x)
// (the basis z; the slopes times dx/dt and dx/dz).
// A vector at flat 4 v holds the functions of phase 4 v mod 12: 0 (i = 0..3 of k = 2m), 4
// (i = 4, 5 of 2m, 0, 1 of 2m + 1) or 8 (i = 2..5 of 2m + 1); one sum per phase and kind.
void z_sums(const double* B, const double* dB, const ZPointBasis& z, double* __restrict g,
            double* __restrict gt, double* __restrict gz) {
  const double* Tz = z.T;
  const double* Dz = z.D;
  __m256d s[3][3] = {};          // [kind: value, t-slope, z-slope][phase 0, 4, 8]
  for (int m = 0; m < 4; ++m) {  // k = 2m, 2m + 1: flats 12m .. 12m + 11
    const __m256d ta = _mm256_broadcast_sd(Tz + 2 * m), tb = _mm256_broadcast_sd(Tz + 2 * m + 1);
    const __m256d da = _mm256_broadcast_sd(Dz + 2 * m), db = _mm256_broadcast_sd(Dz + 2 * m + 1);
    const __m256d wt[3] = {ta, _mm256_blend_pd(ta, tb, 0b1100), tb};
    const __m256d wd[3] = {da, _mm256_blend_pd(da, db, 0b1100), db};
    for (int p = 0; p < 3; ++p) {
      const __m256d b = _mm256_load_pd(B + 12 * m + 4 * p),
                    db_ = _mm256_load_pd(dB + 12 * m + 4 * p);
      s[0][p] = _mm256_fmadd_pd(b, wt[p], s[0][p]);
      s[1][p] = _mm256_fmadd_pd(db_, wt[p], s[1][p]);
      s[2][p] = _mm256_fmadd_pd(b, wd[p], s[2][p]);
    }
  }
  // k = 8: flats 48 .. 51 (phase 0) and 52, 53 (i = 4, 5).
  const __m256d t8 = _mm256_broadcast_sd(Tz + 8), d8 = _mm256_broadcast_sd(Dz + 8);
  const __m256d b8 = _mm256_load_pd(B + 48), db8 = _mm256_load_pd(dB + 48);
  s[0][0] = _mm256_fmadd_pd(b8, t8, s[0][0]);
  s[1][0] = _mm256_fmadd_pd(db8, t8, s[1][0]);
  s[2][0] = _mm256_fmadd_pd(b8, d8, s[2][0]);
  const __m128d b8h = _mm_load_pd(B + 52), db8h = _mm_load_pd(dB + 52);
  const __m128d tail[3] = {_mm_mul_pd(b8h, _mm256_castpd256_pd128(t8)),
                           _mm_mul_pd(db8h, _mm256_castpd256_pd128(t8)),
                           _mm_mul_pd(b8h, _mm256_castpd256_pd128(d8))};
  // i = 0..3: phase 0, lanes 2, 3 of phase 4 and 0, 1 of phase 8; i = 4, 5: lanes 0, 1 of phase
  // 4 and 2, 3 of phase 8.
  double* out[3] = {g, gt, gz};
  const double factor[3] = {1.0, z.dxdt, z.dxdz};
  for (int kind = 0; kind < 3; ++kind) {
    const __m256d f = _mm256_set1_pd(factor[kind]);
    const __m256d lo =
        _mm256_add_pd(s[kind][0], _mm256_permute2f128_pd(s[kind][1], s[kind][2], 0x21));
    const __m128d hi = _mm_add_pd(
        _mm_add_pd(_mm256_castpd256_pd128(s[kind][1]), _mm256_extractf128_pd(s[kind][2], 1)),
        tail[kind]);
    _mm256_storeu_pd(out[kind], kind ? _mm256_mul_pd(lo, f) : lo);
    _mm_storeu_pd(out[kind] + 4, kind ? _mm_mul_pd(hi, _mm256_castpd256_pd128(f)) : hi);
  }
}

// The falling part's six functions at (t, z) with their slopes in t and z (falling_values<true>)
// from the coefficients c of its piece, x and dx/dt of t there, x and dx/dz of z in its octave:
// the t sums of the 54 flat functions in blocks of 20, 20 and 14 (starting on whole vectors)
// into aligned rows, then the z sums of those.
template <int N>
void falling_sums(const double* c, double xt, double dxdt, double xz, double dxdz, double* g,
                  double* gt, double* gz) {
  constexpr int NZ = contensou::kSlipDegreeZ, M = contensou::kLawFunctions * (NZ + 1);
  static_assert(NZ == 8 && M == 54, "z_sums is written for 9 x 6 flat functions");
  double T[N + 1], D[N + 1], Tz[NZ + 1], Dz[NZ + 1];
  contensou::detail::chebyshev_basis<N, true>(xt, T, D);
  alignas(32) double B[56], dB[56];
  slope_block<M, N, 20>(c, T, D, B, dB);
  slope_block<M, N, 20>(c + 20, T, D, B + 20, dB + 20);
  slope_block<M, N, 14>(c + 40, T, D, B + 40, dB + 40);
  contensou::detail::chebyshev_basis<NZ, true>(xz, Tz, Dz);
  z_sums(B, dB, {Tz, Dz, dxdt, dxdz}, g, gt, gz);
}

}  // namespace

void register_blocked_kernels(KernelTable& table) {
  table[1][0][1] = &blocked_slope_sums<8>;
  table[1][1][1] = &blocked_slope_sums<10>;
  table[1][2][1] = &blocked_slope_sums<12>;
  table[1][3][1] = &blocked_slope_sums<14>;
  table[1][4][1] = &blocked_slope_sums<16>;
}

void register_falling_kernels(FallingTable& table) {
  table[0] = &falling_sums<8>;
  table[1] = &falling_sums<10>;
  table[2] = &falling_sums<12>;
  table[3] = &falling_sums<14>;
  table[4] = &falling_sums<16>;
}

}  // namespace contensou::detail::avx2
