// Friction: profiles, the contact patch, the exact resultants and the fractional law, with loops
// over flat numpy arrays in C++ (GIL released, optional threads). Broadcasting and shapes are
// handled by the Python side (contensou/friction.py).
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include <chrono>
#include <type_traits>
#include <variant>

#include "common.hpp"
#include "contensou/friction.hpp"
#include "contensou/friction/units.hpp"

namespace contensou::python {
namespace {

using namespace nb::literals;

const char* shape_kind(const PressureProfile& p) {
  return std::visit(
      [](const auto& s) -> const char* {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, UniformShape>) return "uniform";
        if constexpr (std::is_same_v<S, HertzShape>) return "hertz";
        if constexpr (std::is_same_v<S, CosineSeriesShape>) return "cosine_series";
        if constexpr (std::is_same_v<S, TabulatedShape>) return "tabulated";
        return "chebyshev";
      },
      p.shape);
}

// kinematics = (vx, vy, omega), flat arrays of one length n; outputs (n, 3), (n, 3) and (n,).
void exact_loop(const ExactModel<double>& model,
                const std::tuple<InArray, InArray, InArray>& kinematics, OutArray2 force,
                OutArray2 error, nb::ndarray<bool, nb::ndim<1>, nb::c_contig> conv,
                double tolerance, unsigned threads) {
  const InArray& vx = std::get<0>(kinematics);
  const InArray& vy = std::get<1>(kinematics);
  const InArray& omega = std::get<2>(kinematics);
  const std::size_t n = force.shape(0);
  check_lengths(vx, vy, omega, n);
  if (force.shape(1) != 3 || error.shape(0) != n || error.shape(1) != 3 || conv.shape(0) != n)
    throw std::invalid_argument("outputs must be (n, 3), (n, 3) and (n,)");
  const ExactOptions options{tolerance};
  double* F = force.data();
  double* E = error.data();
  bool* C = conv.data();
  const Strided x(vx), y(vy), w(omega);
  // Tens of microseconds a point: Ctrl-C is polled from a thousand points on.
  run_interruptible_if(n >= 1000, [&](const StopRequest& stop) {
    parallel_for(n, threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) {
        throw_if_stopped(stop);
        ExactResult<double> r;
        try {
          r = exact_resultants(model, Kinematics<double>{x[i], y[i], w[i]}, options);
        } catch (const std::invalid_argument& e) {
          rethrow_at_point(e, i);
        }
        F[3 * i] = r.resultants.Fx;
        F[3 * i + 1] = r.resultants.Fy;
        F[3 * i + 2] = r.resultants.Mz;
        E[3 * i] = r.error.Fx;
        E[3 * i + 1] = r.error.Fy;
        E[3 * i + 2] = r.error.Mz;
        C[i] = r.converged;
      }
    });
  });
}

void fractional_loop(const FractionalLaw<double>& law, InArray vx, InArray vy, InArray omega,
                     OutArray2 force, OutArray3 jacobian, unsigned threads) {
  const std::size_t n = force.shape(0);
  check_lengths(vx, vy, omega, n);
  const bool with_jacobian = jacobian.is_valid();
  check_law_outputs(force, jacobian, n);
  validate(law);
  double* F = force.data();
  double* J = with_jacobian ? jacobian.data() : nullptr;
  const Strided x(vx), y(vy), w(omega);
  // Tens of nanoseconds a point: Ctrl-C is polled from a million points on, every 4096.
  run_interruptible_if(n >= (1u << 20), [&](const StopRequest& stop) {
    parallel_for(n, threads, [&](std::size_t begin, std::size_t end) {
      const FractionalLaw<double> local = law;  // a copy the output stores cannot alias
      for (std::size_t i = begin; i < end; ++i) {
        if (i % 4096 == 0) throw_if_stopped(stop);
        const Kinematics<double> k{x[i], y[i], w[i]};
        try {
          if (J) {
            const FractionalWithJacobian r = fractional_resultants_with_jacobian(local, k);
            F[3 * i] = r.resultants.Fx;
            F[3 * i + 1] = r.resultants.Fy;
            F[3 * i + 2] = r.resultants.Mz;
            for (int a = 0; a < 3; ++a)
              for (int b = 0; b < 3; ++b)
                J[9 * i + 3 * static_cast<std::size_t>(a) + b] = r.jacobian(a, b);
          } else {
            const Resultants<double> r = fractional_resultants(local, k);
            F[3 * i] = r.Fx;
            F[3 * i + 1] = r.Fy;
            F[3 * i + 2] = r.Mz;
          }
        } catch (const std::invalid_argument& e) {
          rethrow_at_point(e, i);
        }
      }
    });
  });
}

std::vector<Kinematics<double>> kinematics_of(InArray vx, InArray vy, InArray omega) {
  const std::size_t n = vx.shape(0);
  check_lengths(vx, vy, omega, n);
  std::vector<Kinematics<double>> k(n);
  const Strided x(vx), y(vy), w(omega);
  for (std::size_t i = 0; i < n; ++i) k[i] = {x[i], y[i], w[i]};
  return k;
}

// The baseline of bench/bench_python.py: the plain C++ loop over the same points into a
// std::vector allocated in the timed region (as the Python call allocates its arrays), one
// thread, timed here. Returns seconds.
double cpp_loop_exact(const ExactModel<double>& model, InArray vx, InArray vy, InArray omega,
                      double tolerance) {
  const std::vector<Kinematics<double>> k = kinematics_of(vx, vy, omega);
  const ExactOptions options{tolerance};
  nb::gil_scoped_release release;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<ExactResult<double>> out(k.size());  // the results' memory is part of a call
  for (std::size_t i = 0; i < k.size(); ++i) out[i] = exact_resultants(model, k[i], options);
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count();
}

double cpp_loop_fractional(const FractionalLaw<double>& law, InArray vx, InArray vy, InArray omega,
                           bool jacobian) {
  const std::vector<Kinematics<double>> k = kinematics_of(vx, vy, omega);
  nb::gil_scoped_release release;
  double sink = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  if (jacobian) {
    std::vector<FractionalWithJacobian> out(k.size());
    for (std::size_t i = 0; i < k.size(); ++i)
      out[i] = fractional_resultants_with_jacobian(law, k[i]);
    sink = out.empty() ? 0.0 : out.back().resultants.Fx;
  } else {
    std::vector<Resultants<double>> out(k.size());
    for (std::size_t i = 0; i < k.size(); ++i) out[i] = fractional_resultants(law, k[i]);
    sink = out.empty() ? 0.0 : out.back().Fx;
  }
  const auto t1 = std::chrono::steady_clock::now();
  volatile double keep = sink;
  (void)keep;
  return std::chrono::duration<double>(t1 - t0).count();
}

// A patch argument: a ContactPatch, else a short TypeError naming the argument.
const ContactPatch& patch_argument(const char* name, nb::handle value) {
  return object_argument<ContactPatch>(name, value, "a ContactPatch");
}

// The arguments of ContactPatch(...), each checked by the package's rule (common.hpp).
struct PatchArguments {
  nb::object radius_m, pressure, friction, kappa, profile, slip, normal_load;
};

// ContactPatch(radius_m, reference_pressure_pa, friction, kappa, profile, slip_speed_friction,
// *, normal_load): every argument checked here, so that a bad patch fails where it is made; a
// profile is a PressureProfile or a built-in profile's name, as identify(profile=...) takes.
ContactPatch make_patch(const PatchArguments& a) {
  const char* const how =
      "ContactPatch(radius_m=..., normal_load=... or reference_pressure_pa=..., friction=...); "
      "ContactPatch.seed_tire() is the seed's tire";
  const std::optional<double> radius_m = optional_number_argument("radius_m", a.radius_m);
  const std::optional<double> pressure =
      optional_number_argument("reference_pressure_pa", a.pressure);
  const std::optional<double> friction = optional_number_argument("friction", a.friction);
  const std::optional<double> normal_load = optional_number_argument("normal_load", a.normal_load);
  const double kappa = number_argument("kappa", a.kappa);
  const PressureProfile shape =
      a.profile.is_none()
          ? uniform_profile()
          : nb::cast<PressureProfile>(checked_argument("profile", "profile", a.profile));
  std::optional<SlipSpeedFriction<double>> slip;
  if (!a.slip.is_none())
    slip = object_argument<SlipSpeedFriction<double>>("slip_speed_friction", a.slip,
                                                      "a SlipSpeedFriction or None");
  if (!radius_m) throw InvalidArgument("radius_m", "missing", std::string("needed: ") + how);
  require_positive("radius_m", *radius_m);
  if (!friction) throw InvalidArgument("friction", "missing", std::string("needed: ") + how);
  if (normal_load.has_value() == pressure.has_value())
    throw InvalidArgument("normal_load, reference_pressure_pa",
                          normal_load ? "both given" : "neither given",
                          "give one: the load N [N] or the reference pressure p* [Pa]");
  ContactPatch p;
  if (normal_load) {
    p = ContactPatch::from_normal_load(*radius_m, *normal_load, shape, *friction, kappa);
  } else {
    p.radius_m = *radius_m;
    p.reference_pressure_pa = *pressure;
    p.friction = *friction;
    p.kappa = kappa;
    p.profile = shape;
  }
  p.slip_speed_friction = slip;
  validate(p);
  return p;
}

// The profiles' factories and readers, their numbers checked by the package's rule.
void bind_profile_functions(nb::module_& m) {
  m.def("uniform_profile", &uniform_profile, "p(rho) = 1");
  m.def("hertz_profile", &hertz_profile, "p(rho) = sqrt(1 - rho^2)");
  m.def(
      "cosine_series_profile",
      [](nb::handle w, nb::handle a) {
        return cosine_series_profile(number_argument("w", w), numbers_argument("a", a));
      },
      "w"_a, "a"_a,
      nb::sig("def cosine_series_profile(w: float, a: collections.abc.Sequence[float]) -> "
              "PressureProfile"),
      "p(rho) = sum_k a_k cos(pi k w rho) (seed eq. 8)");
  m.def(
      "tabulated_profile",
      [](nb::handle rho, nb::handle p) {
        return tabulated_profile(numbers_argument("rho", rho), numbers_argument("p", p));
      },
      "rho"_a, "p"_a,
      nb::sig("def tabulated_profile(rho: collections.abc.Sequence[float], p: "
              "collections.abc.Sequence[float]) -> PressureProfile"),
      "a table p(rho) at increasing rho from the centre, 0, to the rim, 1 (knots at least 1e-9 "
      "apart), monotone cubic in rho^2");
  m.def("seed_tire_profile", &seed_tire_profile, "the tire of the seed (Table 1)");
  m.def(
      "read_profile_csv",
      [](const std::string& path) {
        MeasuredProfile r = read_profile_csv(path);
        return std::make_pair(r.profile, r.reference_pressure_pa);
      },
      "path"_a,
      "a profile CSV (rho, pressure_Pa): (profile, reference pressure = mean pressure [Pa])");
  m.def(
      "smoothed_profile",
      [](nb::handle rho, nb::handle p, nb::handle terms) {
        SmoothedProfile s = smoothed_profile(numbers_argument("rho", rho), numbers_argument("p", p),
                                             integer_argument("terms", terms));
        return std::make_pair(s.profile, std::make_pair(s.rms_residual, s.max_residual));
      },
      "rho"_a, "p"_a, "terms"_a,
      nb::sig("def smoothed_profile(rho: collections.abc.Sequence[float], p: "
              "collections.abc.Sequence[float], terms: int) -> tuple[PressureProfile, "
              "tuple[float, float]]"),
      "least-squares Chebyshev series in rho^2: (profile, (rms residual, max residual))");
}

void bind_profiles(nb::module_& m) {
  nb::class_<PressureProfile>(m, "PressureProfile",
                              "A pressure profile p(rho): radial shape, shift kx, ky and what to "
                              "do with a negative part (contensou/friction/pressure_profile.hpp).")
      .def_prop_ro("kind", &shape_kind, "uniform, hertz, cosine_series, tabulated or chebyshev")
      .def_rw("kx", &PressureProfile::kx, "shift along x (0.14 for the seed's rolling tire)")
      .def_rw("ky", &PressureProfile::ky, "shift along y")
      .def_rw("clip_negative", &PressureProfile::clip_negative, "replace p by max(p, 0)")
      .def_rw("keep_negative", &PressureProfile::keep_negative,
              "use a negative part as given (else make_exact_model refuses it)")
      .def(
          "moment",
          [](const PressureProfile& p, nb::handle n) {
            return moment(p, integer_argument("n", n));
          },
          "n"_a, nb::sig("def moment(self, n: int) -> float"),
          "A^n = integral_0^1 p(rho) rho^n d rho")
      .def("negative_intervals", &negative_intervals,
           "intervals of rho where the unclipped shape is negative")
      .def("negative_load_share", &negative_load_share)
      .def("describe", &describe)
      .def("__repr__",
           [](const PressureProfile& p) {
             return "<PressureProfile " + describe(p) + ", kx=" + format_value(p.kx) +
                    ", ky=" + format_value(p.ky) + ">";
           })
      .def(
          "_shape_values",
          [](const PressureProfile& p, InArray rho, OutArray2 out) {
            if (out.shape(0) != rho.shape(0) || out.shape(1) != 1)
              throw std::invalid_argument("output must be (n, 1)");
            for (std::size_t i = 0; i < rho.shape(0); ++i) {
              if (!(rho(i) >= 0.0 && rho(i) <= 1.0))
                throw std::invalid_argument("rho = " + format_value(rho(i)) +
                                            ": must lie in [0, 1] (point " + std::to_string(i) +
                                            " of the flattened input)");
              out(i, 0) = shape_value(p, rho(i));
            }
          },
          "rho"_a, "out"_a);

  bind_profile_functions(m);
}

// SlipSpeedFriction, its numbers checked by the package's rule (common.hpp).
void bind_slip_speed_friction(nb::module_& m) {
  nb::class_<SlipSpeedFriction<double>>(
      m, "SlipSpeedFriction", "f(w) = f_k + (f_s - f_k) exp(-(w / w_s)^delta), w the slip speed")
      .def(
          "__init__",
          [](SlipSpeedFriction<double>* s, nb::handle fs, nb::handle fk, nb::handle ws,
             nb::handle delta) {
            new (s) SlipSpeedFriction<double>{number_argument("static_coefficient", fs),
                                              number_argument("kinetic_coefficient", fk),
                                              number_argument("reference_speed", ws),
                                              number_argument("exponent", delta)};
          },
          "static_coefficient"_a = 0.3, "kinetic_coefficient"_a = 0.3, "reference_speed"_a = 1.0,
          "exponent"_a = 1.0,
          nb::sig("def __init__(self, static_coefficient: float = 0.3, kinetic_coefficient: "
                  "float = 0.3, reference_speed: float = 1.0, exponent: float = 1.0) -> None"))
      .def_rw("static_coefficient", &SlipSpeedFriction<double>::static_coefficient)
      .def_rw("kinetic_coefficient", &SlipSpeedFriction<double>::kinetic_coefficient)
      .def_rw("reference_speed", &SlipSpeedFriction<double>::reference_speed)
      .def_rw("exponent", &SlipSpeedFriction<double>::exponent);
}

void bind_patch(nb::module_& m) {
  bind_slip_speed_friction(m);
  nb::class_<ContactPatch>(m, "ContactPatch",
                           "Geometry, load, pressure and friction of the exact model (SI units). "
                           "Give radius_m, friction and either normal_load [N] (p* = N / (2 pi "
                           "R^2 A^1) is derived) or reference_pressure_pa; checked at once. "
                           "ContactPatch.seed_tire() is the seed's tire.")
      .def(
          "__init__",
          [](ContactPatch* self, nb::object radius_m, nb::object pressure, nb::object friction,
             nb::object kappa, nb::object profile, nb::object slip, nb::object normal_load) {
            new (self) ContactPatch(
                make_patch({radius_m, pressure, friction, kappa, profile, slip, normal_load}));
          },
          "radius_m"_a.none() = nb::none(), "reference_pressure_pa"_a.none() = nb::none(),
          "friction"_a.none() = nb::none(), "kappa"_a = 1.0, "profile"_a.none() = nb::none(),
          "slip_speed_friction"_a.none() = nb::none(), nb::kw_only(),
          "normal_load"_a.none() = nb::none(),
          nb::sig("def __init__(self, radius_m: float | None = None, reference_pressure_pa: "
                  "float | None = None, friction: float | None = None, kappa: float = 1.0, "
                  "profile: PressureProfile | str | None = None, slip_speed_friction: "
                  "SlipSpeedFriction | None = None, *, normal_load: float | None = None) -> None"))
      .def_static(
          "from_normal_load",
          [](nb::handle radius_m, nb::handle normal_load, nb::handle profile, nb::handle friction,
             nb::handle kappa) {
            return ContactPatch::from_normal_load(
                number_argument("radius_m", radius_m), number_argument("normal_load", normal_load),
                nb::cast<PressureProfile>(checked_argument("profile", "profile", profile)),
                number_argument("friction", friction), number_argument("kappa", kappa));
          },
          "radius_m"_a, "normal_load"_a, "profile"_a, "friction"_a, "kappa"_a = 1.0,
          nb::sig("def from_normal_load(radius_m: float, normal_load: float, profile: "
                  "PressureProfile | str, friction: float, kappa: float = 1.0) -> ContactPatch"),
          "the patch carrying the load N [N]: p* = N / (2 pi R^2 A^1)")
      .def_static("seed_tire", &ContactPatch::seed_tire,
                  "the seed's tire: R = 0.087 m, p* = 210 kPa (N = 4535 N), f = 0.3")
      .def_rw("radius_m", &ContactPatch::radius_m)
      .def_rw("reference_pressure_pa", &ContactPatch::reference_pressure_pa)
      .def_rw("friction", &ContactPatch::friction)
      .def_rw("kappa", &ContactPatch::kappa)
      .def_prop_rw(
          "profile", [](ContactPatch& p) -> PressureProfile& { return p.profile; },
          [](ContactPatch& p, nb::handle profile) {
            p.profile = nb::cast<PressureProfile>(checked_argument("profile", "profile", profile));
          },
          nb::for_getter(nb::rv_policy::reference_internal),  // patch.profile.kx = 0.1 sets it
          nb::for_setter(nb::sig("def profile(self, arg: PressureProfile | str, /) -> None")),
          "the pressure profile (set: a PressureProfile or a built-in profile's name)")
      .def_rw("slip_speed_friction", &ContactPatch::slip_speed_friction, nb::arg().none())
      .def_prop_ro(
          "normal_load", [](const ContactPatch& p) { return p.normal_load(); },
          "N = 2 pi R^2 p* A^1 [N]")
      .def("validate", [](const ContactPatch& p) { validate(p); })
      .def("__repr__", [](const ContactPatch& p) {
        return "<ContactPatch R=" + format_value(p.radius_m) +
               " m, p*=" + format_value(p.reference_pressure_pa) +
               " Pa, f=" + format_value(p.friction) + ", kappa=" + format_value(p.kappa) + ", " +
               describe(p.profile) + ">";
      });
  m.def("seed_tire_patch", &seed_tire_patch, "the seed's tire: R = 0.087 m, p* = 210 kPa, f = 0.3");
}

void bind_laws(nb::module_& m) {
  nb::class_<ExactModel<double>>(m, "ExactModel",
                                 "The integration-ready form of a ContactPatch: build once, "
                                 "evaluate many times")
      .def(
          "__init__",
          [](ExactModel<double>* e, nb::handle patch, nb::handle tol) {
            new (e) ExactModel<double>(make_exact_model(
                patch_argument("patch", patch), number_argument("representation_tolerance", tol)));
          },
          "patch"_a, "representation_tolerance"_a = 1e-15,
          nb::sig("def __init__(self, patch: ContactPatch, representation_tolerance: float = "
                  "1e-15) -> None"))
      .def_ro("radius", &ExactModel<double>::radius)
      .def_prop_ro("representation_error", &ExactModel<double>::representation_error)
      .def_ro("load_area", &ExactModel<double>::load_area);

  nb::class_<FractionalLaw<double>>(m, "FractionalLaw",
                                    "The fractional (Pade-type) law, seed eqs. 5-7 in vector form")
      .def(
          "__init__",
          [](FractionalLaw<double>* l, nb::handle F0, nb::handle M0, nb::handle a, nb::handle mm,
             nb::handle kx, nb::handle ky, nb::handle kappa, nb::handle c, nb::handle Mk,
             nb::handle a_k, nb::handle radius, nb::handle eps) {
            // Every value checked here (a number, then validate), as ContactPatch's: a bad law
            // fails where it is made.
            const FractionalLaw<double> law{
                number_argument("F0", F0),         number_argument("M0", M0),
                number_argument("a", a),           number_argument("m", mm),
                number_argument("kx", kx),         number_argument("ky", ky),
                number_argument("kappa", kappa),   number_argument("c", c),
                number_argument("Mk", Mk),         number_argument("a_k", a_k),
                number_argument("radius", radius), number_argument("regularization_speed", eps)};
            validate(law);
            new (l) FractionalLaw<double>(law);
          },
          "F0"_a = 0.0, "M0"_a = 0.0, "a"_a = 1.0, "m"_a = 64.0 / 9.0, "kx"_a = 0.0, "ky"_a = 0.0,
          "kappa"_a = 1.0, "c"_a = 4.0, "Mk"_a = 0.0, "a_k"_a = 1.0, "radius"_a = 0.1,
          "regularization_speed"_a = 1e-4,
          nb::sig("def __init__(self, F0: float = 0.0, M0: float = 0.0, a: float = 1.0, m: float "
                  "= 7.111111111111111, kx: float = 0.0, ky: float = 0.0, kappa: float = 1.0, c: "
                  "float = 4.0, Mk: float = 0.0, a_k: float = 1.0, radius: float = 0.1, "
                  "regularization_speed: float = 0.0001) -> None"))
      .def_rw("F0", &FractionalLaw<double>::F0)
      .def_rw("M0", &FractionalLaw<double>::M0)
      .def_rw("a", &FractionalLaw<double>::a)
      .def_rw("m", &FractionalLaw<double>::m)
      .def_rw("kx", &FractionalLaw<double>::kx)
      .def_rw("ky", &FractionalLaw<double>::ky)
      .def_rw("kappa", &FractionalLaw<double>::kappa)
      .def_rw("c", &FractionalLaw<double>::c)
      .def_rw("Mk", &FractionalLaw<double>::Mk)
      .def_rw("a_k", &FractionalLaw<double>::a_k)
      .def_rw("radius", &FractionalLaw<double>::radius)
      .def_rw("regularization_speed", &FractionalLaw<double>::regularization_speed)
      .def("validate", [](const FractionalLaw<double>& l) { validate(l); })
      .def("__repr__", [](const FractionalLaw<double>& l) {
        return "<FractionalLaw F0=" + format_value(l.F0) + " N, M0=" + format_value(l.M0) +
               " N m, a=" + format_value(l.a) + ", m=" + format_value(l.m) +
               ", kx=" + format_value(l.kx) + ", ky=" + format_value(l.ky) +
               ", kappa=" + format_value(l.kappa) + ", R=" + format_value(l.radius) + " m>";
      });
  m.def(
      "fractional_law_from_patch",
      [](nb::handle patch) { return fractional_law_from_patch(patch_argument("patch", patch)); },
      "patch"_a, nb::sig("def fractional_law_from_patch(patch: ContactPatch) -> FractionalLaw"),
      "asymptote-matched coefficients from the patch's moments");
  m.def(
      "fractional_law_fitted",
      [](nb::handle patch, nb::handle psi_min, nb::handle psi_max, nb::handle n) {
        return fractional_law_fitted(patch_argument("patch", patch),
                                     number_argument("psi_min", psi_min),
                                     number_argument("psi_max", psi_max), integer_argument("n", n));
      },
      "patch"_a, "psi_min"_a = 1e-2, "psi_max"_a = 1e2, "n"_a = 41,
      nb::sig("def fractional_law_fitted(patch: ContactPatch, psi_min: float = 0.01, psi_max: "
              "float = 100.0, n: int = 41) -> FractionalLaw"),
      "a and m (c, a_k) fitted by least squares to the exact integrals over psi");
}

void bind_loops(nb::module_& m) {
  m.def("_exact_loop", &exact_loop, "model"_a, "kinematics"_a, "force"_a, "error"_a, "converged"_a,
        "tolerance"_a, "threads"_a);
  m.def("_fractional_loop", &fractional_loop, "law"_a, "vx"_a, "vy"_a, "omega"_a, "force"_a,
        "jacobian"_a.none(), "threads"_a);
  m.def("_cpp_loop_exact", &cpp_loop_exact, "model"_a, "vx"_a, "vy"_a, "omega"_a,
        "tolerance"_a = 1e-10, "seconds of the plain C++ loop (benchmark baseline)");
  m.def("_cpp_loop_fractional", &cpp_loop_fractional, "law"_a, "vx"_a, "vy"_a, "omega"_a,
        "jacobian"_a = false, "seconds of the plain C++ loop (benchmark baseline)");
}

// The unit table of the C++ readers (units.hpp), for the package's own column reading.
void bind_units(nb::module_& m) {
  m.def(
      "_split_name_and_unit",
      [](const std::string& header) {
        const NameAndUnit nu = split_name_and_unit(header);
        return std::make_pair(nu.name, nu.unit);
      },
      "header"_a, "(name, unit) of a column header: 'omega [rpm]' -> ('omega', 'rpm')");
  m.def(
      "_unit",
      [](const std::string& text) -> std::optional<std::tuple<std::string, double, double>> {
        const Unit* u = find_unit(text);
        if (u == nullptr) return std::nullopt;
        return std::make_tuple(std::string(dimension_name(u->dimension)), u->to_si, u->offset_si);
      },
      "text"_a, "(dimension, to_si, offset_si) of a unit, or None: SI = to_si * value + offset_si");
  m.def(
      "_units_of",
      [](const std::string& dimension) {
        for (Dimension d : {Dimension::speed, Dimension::rate, Dimension::force, Dimension::moment,
                            Dimension::time, Dimension::temperature, Dimension::pressure,
                            Dimension::angle, Dimension::length, Dimension::ratio})
          if (dimension == dimension_name(d)) return units_of(d);
        return std::string();
      },
      "dimension"_a, "the units of a dimension the readers know, for messages");
}

}  // namespace

void bind_friction(nb::module_& m) {
  bind_units(m);
  bind_profiles(m);
  bind_patch(m);
  bind_laws(m);
  bind_loops(m);
}

}  // namespace contensou::python
