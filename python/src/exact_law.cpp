// Python bindings of the exact law (contensou/friction/exact_law.hpp): the tables built once
// from an ExactModel (GIL released during the build), their certified accuracy, and the loop
// over flat numpy arrays of kinematics (GIL released, optional threads) with the analytic
// Jacobian. contensou.ExactLaw (python/contensou/friction.py) derives from the class bound here
// and adds the Python signature; broadcasting and shapes are handled there too.
#include <nanobind/nanobind.h>
#include <nanobind/stl/string.h>

#include <chrono>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "common.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/exact_law.hpp"

namespace contensou::python {
namespace {

using namespace nb::literals;

void exact_law_loop(const ExactLaw& law, InArray vx, InArray vy, InArray omega, OutArray2 force,
                    OutArray3 jacobian, unsigned threads) {
  const std::size_t n = force.shape(0);
  check_lengths(vx, vy, omega, n);
  const bool with_jacobian = jacobian.is_valid();
  check_law_outputs(force, jacobian, n);
  double* F = force.data();
  double* J = with_jacobian ? jacobian.data() : nullptr;
  const Strided x(vx), y(vy), w(omega);
  // Tens of nanoseconds a point: Ctrl-C is polled from a million points on, every 4096.
  run_interruptible_if(n >= (1u << 20), [&](const StopRequest& stop) {
    parallel_for(n, threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        if (i % 4096 == 0) throw_if_stopped(stop);
        const Kinematics<double> k{x[i], y[i], w[i]};
        try {
          Resultants<double> r;
          if (J) {
            const ExactLawWithJacobian rj = exact_law_resultants_with_jacobian(law, k);
            r = rj.resultants;
            for (int a = 0; a < 3; ++a)
              for (int b = 0; b < 3; ++b)
                J[9 * i + 3 * static_cast<std::size_t>(a) + b] = rj.jacobian(a, b);
          } else {
            r = exact_law_resultants(law, k);
          }
          F[3 * i] = r.Fx;
          F[3 * i + 1] = r.Fy;
          F[3 * i + 2] = r.Mz;
        } catch (const std::invalid_argument& e) {
          rethrow_at_point(e, i);
        }
      }
    });
  });
}

// The baseline of bench/bench_python.py: the plain C++ loop over the same points into a
// std::vector allocated in the timed region, one thread, timed here. Returns seconds.
double cpp_loop_exact_law(const ExactLaw& law, InArray vx, InArray vy, InArray omega,
                          bool jacobian) {
  const std::size_t n = vx.shape(0);
  if (vy.shape(0) != n || omega.shape(0) != n)
    throw std::invalid_argument("vx, vy and omega must have the same length");
  std::vector<Kinematics<double>> k(n);
  for (std::size_t i = 0; i < n; ++i) k[i] = {vx(i), vy(i), omega(i)};
  nb::gil_scoped_release release;
  double sink = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  if (jacobian) {
    std::vector<ExactLawWithJacobian> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = exact_law_resultants_with_jacobian(law, k[i]);
    sink = out.empty() ? 0.0 : out.back().resultants.Fx;
  } else {
    std::vector<Resultants<double>> out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = exact_law_resultants(law, k[i]);
    sink = out.empty() ? 0.0 : out.back().Fx;
  }
  const auto t1 = std::chrono::steady_clock::now();
  volatile double keep = sink;
  (void)keep;
  return std::chrono::duration<double>(t1 - t0).count();
}

// Three significant digits (an error bound).
std::string short_value(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

std::string law_repr(const ExactLaw& law) {
  const ExactLawParameters<double>& p = law.parameters;
  std::string friction = "f=" + format_value(p.friction);
  if (p.slip_speed)
    friction = "f(w) from " + format_value(p.slip_speed->static_coefficient) + " to " +
               format_value(p.slip_speed->kinetic_coefficient) +
               " (w_s=" + format_value(p.slip_speed->reference_speed) +
               " m/s, delta=" + format_value(p.slip_speed->exponent) + ")";
  return "<ExactLaw R=" + format_value(law.radius) + " m, " + friction +
         ", kappa=" + format_value(p.kappa) + ", achieved=" + short_value(law.achieved) +
         (law.reached ? " <= " : " > ") + "tolerance=" + format_value(law.tolerance) + ", " +
         std::to_string((law.bytes() + 512) / 1024) + " KiB>";
}

}  // namespace

void bind_exact_law(nb::module_& m) {
  nb::class_<ExactLaw>(m, "_ExactLaw",
                       "The exact law's tables (contensou/friction/exact_law.hpp); use "
                       "contensou.ExactLaw, which derives from it")
      .def(
          "__init__",
          [](ExactLaw* self, const ExactModel<double>& model, double tolerance, unsigned threads) {
            ExactLawOptions options;
            options.tolerance = tolerance;
            options.threads = threads;
            ExactLaw law = run_interruptible([&](const StopRequest& stop) {
              ExactLawOptions o = options;
              o.stop = stop;
              return make_exact_law(model, o);
            });
            new (self) ExactLaw(std::move(law));
          },
          "model"_a, "tolerance"_a, "threads"_a)
      .def_ro("radius", &ExactLaw::radius, "R [m], the model's integration radius")
      .def_ro("load_area", &ExactLaw::load_area, "L = N / (p* R^2) = 2 pi A^1")
      .def_ro("tolerance", &ExactLaw::tolerance, "the requested accuracy")
      .def_ro("achieved", &ExactLaw::achieved,
              "certified bound on the error, relative to f N (forces) and f N R (torque)")
      .def_ro("reached", &ExactLaw::reached, "achieved <= tolerance")
      .def_ro("samples", &ExactLaw::samples, "adaptive-integrator calls of the build")
      .def_prop_ro(
          "bytes", [](const ExactLaw& l) { return l.bytes(); }, "memory of the tables")
      .def_prop_ro(
          "has_slip_speed", [](const ExactLaw& l) { return l.falling.has_value(); },
          "True if the friction depends on the slip speed (a table of its falling part)")
      .def("__repr__", &law_repr);

  m.def("_exact_law_loop", &exact_law_loop, "law"_a, "vx"_a, "vy"_a, "omega"_a, "force"_a,
        "jacobian"_a.none(), "threads"_a);
  m.def("_cpp_loop_exact_law", &cpp_loop_exact_law, "law"_a, "vx"_a, "vy"_a, "omega"_a,
        "jacobian"_a = false, "seconds of the plain C++ loop (benchmark baseline)");
}

}  // namespace contensou::python
