// Python bindings of the limit surface (contensou/friction/limit_surface.hpp): the patch's set
// of friction wrenches, its support function D, gauge and projection, the fitted ellipsoid and
// the one-contact Moreau-Jean step. The C++ free functions become methods of the two surface
// classes; vectors are numpy arrays of 3 (twist (vx, vy, omega), wrench (Fx, Fy, Mz)).
#include <nanobind/eigen/dense.h>
#include <nanobind/nanobind.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <string>
#include <vector>

#include "common.hpp"
#include "contensou/friction/error.hpp"
#include "contensou/friction/limit_surface.hpp"

namespace contensou::python {

using namespace nb::literals;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
// Inputs as sequences (lists, tuples, numpy arrays of any layout), checked for 3 components
// (a ValueError naming the argument); outputs as numpy arrays.
using In = std::vector<double>;
using In2 = std::vector<std::vector<double>>;

namespace {

Vec3 vec(const char* name, const In& a) {
  if (a.size() != 3)
    throw InvalidArgument(name, std::to_string(a.size()) + " components",
                          "must have 3 ((vx, vy, omega) or (Fx, Fy, Mz))");
  return {a[0], a[1], a[2]};
}
Mat3 mat(const char* name, const In2& a) {
  if (a.size() != 3)
    throw InvalidArgument(name, std::to_string(a.size()) + " rows", "must be 3 x 3");
  Mat3 m;
  for (int i = 0; i < 3; ++i) {
    if (a[i].size() != 3)
      throw InvalidArgument(
          name, "row " + std::to_string(i) + " of " + std::to_string(a[i].size()) + " entries",
          "must be 3 x 3");
    for (int j = 0; j < 3; ++j) m(i, j) = a[i][j];
  }
  return m;
}

ProjectionOptions projection_options(double tolerance, double inside_tolerance,
                                     int max_iterations) {
  ProjectionOptions o;
  o.tolerance = tolerance;
  o.inside_tolerance = inside_tolerance;
  o.max_iterations = max_iterations;
  return o;
}

// The methods both surfaces share (the C++ overloads on LimitSurface and
// EllipsoidalLimitSurface).
template <class Surface, class Class>
void bind_surface_methods(Class& c) {
  c.def(
       "support", [](const Surface& s, const In& d) { return support(s, vec("direction", d)); },
       "direction"_a,
       "max over the set of w . d = D(d) [W] for a twist direction d (vx, vy, omega)")
      .def(
          "dissipation_with_derivatives",
          [](const Surface& s, const In& t) {
            return dissipation_with_derivatives(s, vec("twist", t));
          },
          "twist"_a, "D, its gradient (= -wrench of the twist) and Hessian at the twist")
      .def(
          "surface_point",
          [](const Surface& s, const In& n) { return surface_point(s, vec("normal", n)); },
          "normal"_a, "the boundary wrench whose outward normal is the twist direction n")
      .def(
          "gauge", [](const Surface& s, const In& w) { return gauge(s, vec("wrench", w)); },
          "wrench"_a,
          "the smallest g with wrench in g C (inside iff g <= 1) and the boundary normal")
      .def(
          "project",
          [](const Surface& s, const In& trial, const In2& metric, double tolerance,
             double inside_tolerance, int max_iterations) {
            return project(s, vec("trial", trial), mat("metric", metric),
                           projection_options(tolerance, inside_tolerance, max_iterations));
          },
          "trial"_a, "metric"_a, "tolerance"_a = 1e-10, "inside_tolerance"_a = 1e-10,
          "max_iterations"_a = 60,
          "nearest admissible wrench to `trial` in the SPD metric (w - trial)^T G (w - trial), "
          "with the twist G (w - trial) whose friction it is (normality)")
      .def(
          "moreau_jean_step",
          [](const Surface& s, double mass, double inertia, const In& twist, const In& applied,
             double step) {
            return moreau_jean_step(s, PlanarBody{mass, inertia}, vec("twist", twist),
                                    vec("applied", applied), step);
          },
          "mass"_a, "inertia"_a, "twist"_a, "applied"_a, "step"_a,
          "one implicit step of a planar body on the patch: M (s+ - s) = h (applied + w), w in "
          "the set, -s+ normal to it at w (exactly 0 when it sticks)");
}

// EllipsoidalLimitSurface, its numbers checked by the package's rule (common.hpp).
void bind_ellipsoid(nb::module_& m) {
  auto ellipsoid = nb::class_<EllipsoidalLimitSurface>(
      m, "EllipsoidalLimitSurface",
      "(Fx/F)^2 + (Fy/(kappa F))^2 + (Mz/(F L))^2 <= 1 (MuJoCo's elliptic cone)");
  ellipsoid
      .def(
          "__init__",
          [](EllipsoidalLimitSurface* e, nb::handle force_limit, nb::handle torsional_length,
             nb::handle radius, nb::handle kappa) {
            new (e) EllipsoidalLimitSurface{number_argument("force_limit", force_limit),
                                            number_argument("torsional_length", torsional_length),
                                            number_argument("radius", radius),
                                            number_argument("kappa", kappa)};
          },
          "force_limit"_a, "torsional_length"_a, "radius"_a, "kappa"_a = 1.0,
          nb::sig("def __init__(self, force_limit: float, torsional_length: float, radius: float, "
                  "kappa: float = 1.0) -> None"))
      .def_ro("force_limit", &EllipsoidalLimitSurface::force_limit)
      .def_ro("torsional_length", &EllipsoidalLimitSurface::torsional_length)
      .def_ro("radius", &EllipsoidalLimitSurface::radius)
      .def_ro("kappa", &EllipsoidalLimitSurface::kappa)
      .def("__repr__", [](const EllipsoidalLimitSurface& e) {
        return "<EllipsoidalLimitSurface F=" + std::to_string(e.force_limit) +
               " N, L=" + std::to_string(e.torsional_length) +
               " m, kappa=" + std::to_string(e.kappa) + ">";
      });
  bind_surface_methods<EllipsoidalLimitSurface>(ellipsoid);
}

}  // namespace

void bind_limit_surface(nb::module_& m) {
  nb::class_<Dissipation>(m, "Dissipation", "D [W], its gradient and Hessian in the twist")
      .def_ro("value", &Dissipation::value)
      .def_ro("gradient", &Dissipation::gradient)
      .def_ro("hessian", &Dissipation::hessian);
  nb::class_<Gauge>(m, "Gauge", "gauge of a wrench and the normal of its boundary point")
      .def_ro("value", &Gauge::value)
      .def_ro("normal", &Gauge::normal)
      .def_ro("iterations", &Gauge::iterations);
  nb::class_<Projection>(m, "Projection", "result of LimitSurface.project")
      .def_ro("wrench", &Projection::wrench)
      .def_ro("twist", &Projection::twist)
      .def_ro("inside", &Projection::inside)
      .def_ro("gauge", &Projection::gauge)
      .def_ro("residual", &Projection::residual)
      .def_ro("iterations", &Projection::iterations)
      .def_ro("converged", &Projection::converged);
  nb::class_<ContactStep>(m, "ContactStep", "result of a Moreau-Jean step")
      .def_ro("twist", &ContactStep::twist)
      .def_ro("wrench", &ContactStep::wrench)
      .def_ro("stick", &ContactStep::stick)
      .def_ro("iterations", &ContactStep::iterations);
  nb::class_<EllipsoidError>(m, "EllipsoidError", "radial error of the ellipsoid")
      .def_ro("max_radial_error", &EllipsoidError::max_radial_error)
      .def_ro("rms_radial_error", &EllipsoidError::rms_radial_error)
      .def_ro("worst_normal", &EllipsoidError::worst_normal);

  auto exact = nb::class_<LimitSurface>(
      m, "LimitSurface",
      "The exact limit surface of a contact patch: the set of friction wrenches (Fx, Fy, Mz) "
      "it can transmit (constant f; any profile, shift and kappa)");
  exact
      .def(
          "__init__",
          [](LimitSurface* s, nb::handle patch, nb::handle tolerance) {
            new (s) LimitSurface(
                make_limit_surface(object_argument<ContactPatch>("patch", patch, "a ContactPatch"),
                                   number_argument("tolerance", tolerance)));
          },
          "patch"_a, "tolerance"_a = 1e-12,
          nb::sig("def __init__(self, patch: ContactPatch, tolerance: float = 1e-12) -> None"))
      .def_ro("radius", &LimitSurface::radius)
      .def_ro("force_scale", &LimitSurface::force_scale)
      .def_ro("tolerance", &LimitSurface::tolerance)
      .def(
          "fit_ellipsoid", [](const LimitSurface& s) { return fit_ellipsoid(s); },
          "the engines' ellipsoid matched at pure slide (x, y) and pure spin")
      .def(
          "ellipsoid_error",
          [](const LimitSurface& s, const EllipsoidalLimitSurface& e, int n_theta, int n_phi) {
            return ellipsoid_error(s, e, n_theta, n_phi);
          },
          "ellipsoid"_a, "n_theta"_a = 24, "n_phi"_a = 24,
          "radial error 1/g_E - 1 of an ellipsoid at the exact surface's boundary points");
  bind_surface_methods<LimitSurface>(exact);

  bind_ellipsoid(m);
}

}  // namespace contensou::python
