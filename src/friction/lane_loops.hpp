// Lane loops: branch-free loops over kLanes values side by side, which the compiler vectorises
// (slip_speed_measure.cpp, exact_law_sampling.cpp). With GCC on x86-64 a function marked
// CONTENSOU_LANE_CLONES is also built for AVX2 + FMA and AVX-512 and the version for the CPU is
// chosen at load time (an ifunc); the rest of the library keeps the baseline instruction set.
// Not with clang: clang 14 drops the x86-64-v3 clone and chooses between the others on the
// CPU's vendor, not its features. Internal to the friction module.
#pragma once

namespace contensou::detail {

inline constexpr int kLanes = 8;

}  // namespace contensou::detail

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
#define CONTENSOU_LANE_CLONES [[gnu::target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")]]
// A helper inlined into the clones, so that it is built for their instruction sets too.
#define CONTENSOU_LANE_INLINE [[gnu::always_inline]] inline
#else
#define CONTENSOU_LANE_CLONES
#define CONTENSOU_LANE_INLINE inline
#endif
