# Project-wide warning and sanitizer flags, applied to the project's own targets.
function(contensou_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion)
  # GCC 12 reports false -Wrestrict positives inside std::string concatenation (GCC bug 105329).
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
  if(CONTENSOU_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# ASan and UBSan. Of UBSan's checks, five are left out: null and object-size, which ASan already
# catches (a null dereference is a SEGV report, an overrun an ASan report), alignment and
# pointer-overflow, which check every Eigen element access and more than double the compile
# time of the Eigen-heavy sources (gear/linear_stability.cpp: 97 s with them, 42 s without, GCC
# 12 at -O1) for no finding in this project, and vptr (the dynamic type behind a virtual call;
# the project's own classes have no virtual functions), a fifth of the compile time of the
# files that include CLI11, GoogleTest or Ceres. Every arithmetic check stays: signed overflow,
# shifts, division by zero, float-to-int overflow, bounds of arrays, enum and bool values.
if(CONTENSOU_SANITIZE)
  set(_contensou_sanitizers -fsanitize=address,undefined
      -fno-sanitize=null,object-size,alignment,pointer-overflow,vptr)
  add_compile_options(${_contensou_sanitizers} -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  add_link_options(${_contensou_sanitizers})
endif()
