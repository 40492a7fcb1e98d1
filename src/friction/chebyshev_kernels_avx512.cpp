// The unrolled Chebyshev kernels compiled for AVX-512 (chebyshev_kernels.cpp chooses them on a
// CPU that has AVX-512F, DQ and VL). This file alone is compiled with those flags.
#include "chebyshev_kernels.hpp"

namespace contensou::detail::avx512 {
#include "chebyshev_kernels.inc"
}  // namespace contensou::detail::avx512
