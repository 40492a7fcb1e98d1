// Shared pieces of the Python extension contensou._core (nanobind).
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/vector.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <initializer_list>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#include "contensou/friction/error.hpp"

namespace contensou::python {

namespace nb = nanobind;

// A flat input of n points, or of one point broadcast to all (length 1).
using InArray = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;
// Outputs allocated by the Python side: (n, 3) and (n, 3, 3), C-contiguous.
using OutArray2 = nb::ndarray<double, nb::ndim<2>, nb::c_contig, nb::device::cpu>;
using OutArray3 = nb::ndarray<double, nb::ndim<3>, nb::c_contig, nb::device::cpu>;

void bind_friction(nb::module_& m);
void bind_limit_surface(nb::module_& m);
void bind_identification(nb::module_& m);
void bind_gear(nb::module_& m);
void bind_exact_law(nb::module_& m);

// A numpy array that owns `values` (row-major, the given shape).
inline nb::object to_numpy(std::vector<double> values, std::initializer_list<std::size_t> shape) {
  auto* owned = new std::vector<double>(std::move(values));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<double>*>(p); });
  return nb::cast(nb::ndarray<nb::numpy, double>(owned->data(), shape, owner));
}

// Element i of an input of length n or 1, by pointer and stride (0 for one value broadcast),
// taken once before a loop.
struct Strided {
  const double* data;
  std::size_t stride;
  explicit Strided(const InArray& a) : data(a.data()), stride(a.shape(0) == 1 ? 0 : 1) {}
  double operator[](std::size_t i) const { return data[i * stride]; }
};

// Inputs of n points each, or of one broadcast to all.
inline void check_lengths(const InArray& vx, const InArray& vy, const InArray& omega,
                          std::size_t n) {
  for (const InArray* a : {&vx, &vy, &omega})
    if (a->shape(0) != n && a->shape(0) != 1)
      throw std::invalid_argument("inputs of " + std::to_string(a->shape(0)) +
                                  " points do not broadcast to " + std::to_string(n));
}

// The outputs of a law loop: force (n, 3) and, when given, jacobian (n, 3, 3).
inline void check_law_outputs(const OutArray2& force, const OutArray3& jacobian, std::size_t n) {
  if (force.shape(1) != 3 ||
      (jacobian.is_valid() &&
       (jacobian.shape(0) != n || jacobian.shape(1) != 3 || jacobian.shape(2) != 3)))
    throw std::invalid_argument("outputs must be (n, 3) and (n, 3, 3)");
}

// Runs body(begin, end) over [0, n) in `threads` contiguous chunks (0: one per core). An
// exception in a chunk stops that chunk; the one of the lowest chunk is rethrown after all have
// joined, so the first bad point is reported whatever the number of threads. Call with the GIL
// released.
template <class Body>
void parallel_for(std::size_t n, unsigned threads, Body&& body) {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(n, 1)));
  if (threads <= 1) {
    body(std::size_t{0}, n);
    return;
  }
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  const std::size_t chunk = (n + threads - 1) / threads;
  for (unsigned t = 0; t < threads; ++t) {
    const std::size_t begin = std::min(n, t * chunk), end = std::min(n, begin + chunk);
    pool.emplace_back([&, t, begin, end] {
      try {
        body(begin, end);
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  }
  for (std::thread& th : pool) th.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// Runs body(stop) -- a long C++ call -- with the GIL released on a helper thread, while the
// calling thread polls Python's signal handlers every 50 ms (PyErr_CheckSignals, with the GIL,
// where they run: Ctrl-C). When a handler raises (KeyboardInterrupt), `stop` starts returning
// true (an atomic flag: cheap and safe from any of the library's threads), the library stops
// at its next poll with Interrupted, and the handler's exception is raised here, whatever the
// body did meanwhile. Call with the GIL held; returns what body returns.
template <class Body>
auto run_interruptible(Body&& body) -> decltype(body(StopRequest{})) {
  using Result = decltype(body(StopRequest{}));
  std::atomic<bool> stop_flag{false};
  const StopRequest stop = [&stop_flag] { return stop_flag.load(std::memory_order_relaxed); };
  std::optional<std::conditional_t<std::is_void_v<Result>, bool, Result>> result;
  std::exception_ptr error;
  bool done = false, raised = false;
  std::mutex lock;
  std::condition_variable finished;
  {
    nb::gil_scoped_release release;
    std::thread worker([&] {
      try {
        if constexpr (std::is_void_v<Result>) {
          body(stop);
          result = true;
        } else {
          result.emplace(body(stop));
        }
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> guard(lock);
      done = true;
      finished.notify_one();
    });
    std::unique_lock<std::mutex> wait(lock);
    while (!finished.wait_for(wait, std::chrono::milliseconds(50), [&] { return done; })) {
      if (raised) continue;
      wait.unlock();
      {
        nb::gil_scoped_acquire acquire;
        raised = PyErr_CheckSignals() != 0;  // the handler's exception stays set
      }
      if (raised) stop_flag = true;
      wait.lock();
    }
    wait.unlock();
    worker.join();
  }
  if (raised) throw nb::python_error();
  if (error) std::rethrow_exception(error);
  if constexpr (!std::is_void_v<Result>) return std::move(*result);
}

// run_interruptible when `long_call`, else body() inline with the GIL released and no stop
// request (a helper thread costs tens of microseconds: too much for a short loop).
template <class Body>
auto run_interruptible_if(bool long_call, Body&& body) -> decltype(body(StopRequest{})) {
  if (long_call) return run_interruptible(std::forward<Body>(body));
  nb::gil_scoped_release release;
  return body(StopRequest{});
}

// The package's one rule for an argument (python/contensou/_args.py): `check`(name, value) of
// that module, whose TypeError names the argument and what it accepts (a number is an int, a
// float or a numpy scalar, never a str or a bool; a profile a PressureProfile or a built-in
// profile's name).
inline nb::object checked_argument(const char* check, const char* name, nb::handle value) {
  return nb::module_::import_("contensou._args").attr(check)(name, value);
}

// A value of the wrong type for argument `name` (accepted: what it takes, in words): the
// package's short TypeError.
[[noreturn]] inline void wrong_type(const char* name, nb::handle value, const char* accepted) {
  nb::module_::import_("contensou._args").attr("wrong_type")(name, value, accepted);
  throw std::logic_error("contensou._args.wrong_type returned");  // it always raises
}

// A bound object of type T as argument `name`, or the short TypeError.
template <class T>
const T& object_argument(const char* name, nb::handle value, const char* accepted) {
  T* p = nullptr;
  if (!nb::try_cast<T*>(value, p) || !p) wrong_type(name, value, accepted);
  return *p;
}

inline double number_argument(const char* name, nb::handle value) {
  return nb::cast<double>(checked_argument("number", name, value));
}

inline int integer_argument(const char* name, nb::handle value) {
  return nb::cast<int>(checked_argument("integer", name, value));
}

inline std::vector<double> numbers_argument(const char* name, nb::handle value) {
  return nb::cast<std::vector<double>>(checked_argument("numbers", name, value));
}

inline std::optional<double> optional_number_argument(const char* name, nb::handle value) {
  if (value.is_none()) return std::nullopt;
  return number_argument(name, value);
}

// Names the point of a bad input: "<the library's message> (point i of the flattened input)".
[[noreturn]] inline void rethrow_at_point(const std::exception& e, std::size_t i) {
  throw std::invalid_argument(std::string(e.what()) + " (point " + std::to_string(i) +
                              " of the flattened input)");
}

}  // namespace contensou::python
