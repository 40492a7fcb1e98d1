# FindMuJoCo: the MuJoCo headers and library shipped inside the `mujoco` Python wheels
# (mujoco-core puts include/mujoco/*.h and libmujoco.so.<version> next to mujoco/__init__.py).
#
# Hints: MuJoCo_ROOT (a directory holding include/mujoco/mujoco.h and libmujoco.so*), or
# MuJoCo_PYTHON (an interpreter that can find the package `mujoco`; default: the project's .venv;
# the package is located, not imported, so that its own dependencies need not be there).
# Result: MuJoCo_FOUND, MuJoCo_VERSION, MuJoCo_INCLUDE_DIR, MuJoCo_LIBRARY, MuJoCo_LIBRARY_DIR
# and the imported target MuJoCo::MuJoCo.
if(NOT MuJoCo_ROOT)
  if(NOT MuJoCo_PYTHON AND EXISTS "${PROJECT_SOURCE_DIR}/.venv/bin/python")
    set(MuJoCo_PYTHON "${PROJECT_SOURCE_DIR}/.venv/bin/python")
  endif()
  if(MuJoCo_PYTHON)
    execute_process(
      COMMAND "${MuJoCo_PYTHON}" -c
              "import importlib.util as u; print(u.find_spec('mujoco').submodule_search_locations[0])"
      OUTPUT_VARIABLE _mujoco_dir OUTPUT_STRIP_TRAILING_WHITESPACE
      RESULT_VARIABLE _mujoco_rc ERROR_QUIET)
    if(_mujoco_rc EQUAL 0 AND IS_DIRECTORY "${_mujoco_dir}")
      set(MuJoCo_ROOT "${_mujoco_dir}")
    endif()
  endif()
endif()

if(MuJoCo_ROOT)
  find_path(MuJoCo_INCLUDE_DIR mujoco/mujoco.h PATHS "${MuJoCo_ROOT}/include" NO_DEFAULT_PATH)
  # The wheel ships only the versioned file (libmujoco.so.X.Y.Z), no libmujoco.so link.
  file(GLOB _mujoco_libs "${MuJoCo_ROOT}/libmujoco.so*" "${MuJoCo_ROOT}/lib/libmujoco.so*")
  if(_mujoco_libs)
    list(SORT _mujoco_libs)
    list(GET _mujoco_libs 0 _mujoco_lib)
    set(MuJoCo_LIBRARY "${_mujoco_lib}" CACHE FILEPATH "libmujoco")
  endif()
endif()

if(MuJoCo_INCLUDE_DIR AND EXISTS "${MuJoCo_INCLUDE_DIR}/mujoco/mujoco.h")
  file(STRINGS "${MuJoCo_INCLUDE_DIR}/mujoco/mujoco.h" _mujoco_ver REGEX "#define mjVERSION_HEADER")
  string(REGEX MATCH "[0-9]+" MuJoCo_VERSION_HEADER "${_mujoco_ver}")
endif()
if(MuJoCo_LIBRARY)
  string(REGEX MATCH "[0-9]+\\.[0-9]+\\.[0-9]+$" MuJoCo_VERSION "${MuJoCo_LIBRARY}")
  get_filename_component(MuJoCo_LIBRARY_DIR "${MuJoCo_LIBRARY}" DIRECTORY)
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(MuJoCo REQUIRED_VARS MuJoCo_LIBRARY MuJoCo_INCLUDE_DIR
                                  VERSION_VAR MuJoCo_VERSION)
if(MuJoCo_FOUND AND NOT TARGET MuJoCo::MuJoCo)
  add_library(MuJoCo::MuJoCo SHARED IMPORTED)
  set_target_properties(MuJoCo::MuJoCo PROPERTIES
    IMPORTED_LOCATION "${MuJoCo_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${MuJoCo_INCLUDE_DIR}")
endif()
