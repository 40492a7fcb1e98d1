// The dispatch of the unrolled Chebyshev kernels (piecewise_chebyshev.hpp): the baseline build
// here, the AVX2 + FMA and AVX-512 builds in chebyshev_kernels_avx2.cpp and _avx512.cpp, chosen
// once from the CPU (the wide kernel of a slip-speed table fits AVX-512's 32 registers).
#include "chebyshev_kernels.hpp"

namespace contensou::detail {

namespace baseline {
#include "chebyshev_kernels.inc"
}  // namespace baseline

namespace {

const KernelTable& kernels() {
  static const KernelTable table = [] {
    KernelTable t{};
#if CONTENSOU_HAVE_AVX2_KERNELS
    if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
        __builtin_cpu_supports("avx512vl")) {
      avx512::register_kernels(t);
      return t;
    }
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
      avx2::register_kernels(t);
      avx2::register_blocked_kernels(t);
      return t;
    }
#endif
    baseline::register_kernels(t);
    return t;
  }();
  return table;
}

}  // namespace

ChebyshevKernel chebyshev_kernel(int functions, int degree, bool slope) {
  const int which = functions == kLawFunctions                        ? 0
                    : functions == kLawFunctions * (kSlipDegreeZ + 1) ? 1
                                                                      : -1;
  if (which < 0 || degree < 8 || degree > 16 || degree % 2) return nullptr;
  return kernels()[which][(degree - 8) / 2][slope ? 1 : 0];
}

SlipSpeedKernel slip_speed_kernel(int degree) {
  static const FallingTable table = [] {
    FallingTable t{};
#if CONTENSOU_HAVE_AVX2_KERNELS
    // AVX-512 keeps the generic path: its wide kernel holds all 54 sums in registers.
    if (!(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq") &&
          __builtin_cpu_supports("avx512vl")) &&
        __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      avx2::register_falling_kernels(t);
#endif
    return t;
  }();
  if (degree < 8 || degree > 16 || degree % 2) return nullptr;
  return table[(degree - 8) / 2];
}

}  // namespace contensou::detail
