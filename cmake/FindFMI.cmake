# FindFMI: the FMI 2.0 and 3.0 C headers shipped inside the `fmpy` Python wheel (fmpy/c-code:
# fmi2Functions.h, fmi2FunctionTypes.h, fmi2TypesPlatform.h, fmi3*.h), a build requirement of
# the FMUs in src/fmu (python/requirements.txt pins fmpy), not copied into the tree.
#
# Hints: FMI_ROOT (a directory holding fmi2Functions.h), or FMI_PYTHON (an interpreter that can
# find the package `fmpy`; default: the project's .venv; located, not imported).
# Result: FMI_FOUND, FMI_INCLUDE_DIR.
if(NOT FMI_ROOT)
  if(NOT FMI_PYTHON AND EXISTS "${PROJECT_SOURCE_DIR}/.venv/bin/python")
    set(FMI_PYTHON "${PROJECT_SOURCE_DIR}/.venv/bin/python")
  endif()
  if(FMI_PYTHON)
    execute_process(
      COMMAND "${FMI_PYTHON}" -c
              "import importlib.util as u; print(u.find_spec('fmpy').submodule_search_locations[0])"
      OUTPUT_VARIABLE _fmi_dir OUTPUT_STRIP_TRAILING_WHITESPACE
      RESULT_VARIABLE _fmi_rc ERROR_QUIET)
    if(_fmi_rc EQUAL 0 AND IS_DIRECTORY "${_fmi_dir}/c-code")
      set(FMI_ROOT "${_fmi_dir}/c-code")
    endif()
  endif()
endif()
if(FMI_ROOT)
  find_path(FMI_INCLUDE_DIR fmi2Functions.h PATHS "${FMI_ROOT}" NO_DEFAULT_PATH)
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(FMI REQUIRED_VARS FMI_INCLUDE_DIR)
