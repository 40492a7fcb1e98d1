# The friction library's portable sources, relative to this folder. One list, read by
# src/friction/CMakeLists.txt and by the fuzz project (tests/fuzz), so a new source file cannot
# be missing from one of them. The AVX2/AVX-512 kernels are added by the library only.
set(contensou_friction_sources
  admissible_shape.cpp
  chebyshev_kernels.cpp
  contact_patch.cpp
  coulomb_envelope.cpp
  csv.cpp
  exact_law.cpp
  exact_law_jacobian.cpp
  exact_law_sampling.cpp
  exact_model.cpp
  exact_resultants.cpp
  file_output.cpp
  fractional_law.cpp
  limit_surface.cpp
  model_error.cpp
  piecewise_chebyshev.cpp
  pressure_profile.cpp
  quadrature.cpp
  slip_speed_measure.cpp
  slip_speed_rings.cpp
  table_far_sums.cpp
  units.cpp)
