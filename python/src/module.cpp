// contensou._core: the extension module of the Python package (python/contensou).
#include <nanobind/nanobind.h>

#include "common.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/version.hpp"

NB_MODULE(_core, m) {
  namespace nb = nanobind;
  m.doc() =
      "contensou's C++ library: coupled sliding-spinning dry friction (friction, "
      "identification, gear). Use the package contensou, which wraps this module.";
  m.attr("version") = contensou::kVersion;  // contensou.__version__
  // Bad input is a ValueError carrying the library's message: InvalidArgument already derives
  // from std::invalid_argument (ValueError); a malformed file (ParseError, a runtime_error)
  // is bad input too.
  nb::register_exception_translator([](const std::exception_ptr& p, void*) {
    try {
      std::rethrow_exception(p);
    } catch (const contensou::ParseError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const contensou::InvalidArgument& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const contensou::Interrupted&) {
      // A call stopped by Ctrl-C raises the signal handler's exception itself
      // (run_interruptible); a stop from anywhere else is a KeyboardInterrupt too.
      if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    }
  });
  contensou::python::bind_friction(m);
  contensou::python::bind_exact_law(m);
  contensou::python::bind_limit_surface(m);
  // identification (Ceres) and gear (SUNDIALS) are in the build when their libraries' dependencies
  // were found (python/CMakeLists.txt); contensou/_build.py lists them.
#ifdef CONTENSOU_PYTHON_IDENTIFICATION
  contensou::python::bind_identification(m);
#endif
#ifdef CONTENSOU_PYTHON_GEAR
  contensou::python::bind_gear(m);
#endif
}
