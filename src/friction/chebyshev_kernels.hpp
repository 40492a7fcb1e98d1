// The kernel table shared by the two builds of chebyshev_kernels.inc (internal).
#pragma once

#include <array>

#include "contensou/friction/exact_law.hpp"
#include "contensou/friction/piecewise_chebyshev.hpp"

namespace contensou::detail {

// [table: 0 constant friction, 1 falling part][degree 8, 10, ..., 16][slope]
using KernelTable = std::array<std::array<std::array<ChebyshevKernel, 2>, 5>, 2>;

#if CONTENSOU_HAVE_AVX2_KERNELS
namespace avx2 {
void register_kernels(KernelTable& table);
// The slip-speed table's kernels with slopes in register-sized blocks (16 ymm registers).
void register_blocked_kernels(KernelTable& table);
}  // namespace avx2
namespace avx512 {
void register_kernels(KernelTable& table);
}  // namespace avx512
#endif

}  // namespace contensou::detail
