// The unrolled Chebyshev kernels compiled for AVX2 with FMA (chebyshev_kernels.cpp chooses
// them on a CPU that has both). This file alone is compiled with -mavx2 -mfma.
#include "chebyshev_kernels.hpp"

namespace contensou::detail::avx2 {
#include "chebyshev_kernels.inc"
}  // namespace contensou::detail::avx2
