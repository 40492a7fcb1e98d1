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

}  // namespace

void register_blocked_kernels(KernelTable& table) {
  table[1][0][1] = &blocked_slope_sums<8>;
  table[1][1][1] = &blocked_slope_sums<10>;
  table[1][2][1] = &blocked_slope_sums<12>;
  table[1][3][1] = &blocked_slope_sums<14>;
  table[1][4][1] = &blocked_slope_sums<16>;
}

}  // namespace contensou::detail::avx2
