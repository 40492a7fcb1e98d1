// The kernel table shared by the two builds of chebyshev_kernels.inc (internal).
#pragma once

#include <array>

#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/piecewise_chebyshev.hpp"

namespace contensou::detail {

// [table: 0 constant friction, 1 falling part][degree 8, 10, ..., 16][slope]
using KernelTable = std::array<std::array<std::array<ChebyshevKernel, 2>, 5>, 2>;
// [degree 8, 10, ..., 16] of the falling part's pieces in t (null where there is none)
using FallingTable = std::array<SlipSpeedKernel, 5>;

#if CONTENSOU_HAVE_AVX2_KERNELS
namespace avx2 {
void register_kernels(KernelTable& table);
// The slip-speed table's kernels with slopes in register-sized blocks (16 ymm registers).
void register_blocked_kernels(KernelTable& table);
// falling_values<true> in one kernel on the same blocks (exact_law.hpp, slip_speed_kernel).
void register_falling_kernels(FallingTable& table);
}  // namespace avx2
namespace avx512 {
void register_kernels(KernelTable& table);
}  // namespace avx512
#endif

}  // namespace contensou::detail
