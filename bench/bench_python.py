#!/usr/bin/env python3
"""Per-call overhead of the Python package (issue 13): contensou.exact_resultants,
contensou.exact_law_resultants and contensou.fractional_resultants on 10^5 points against the plain C++ loop over the same points
(contensou._core._cpp_loop_*: a std::vector of kinematics in, a std::vector of results out,
timed inside C++, results into a new std::vector). Both on one thread, alternated; minimum
and median over repetitions. Reported, not asserted (target:
the Python call at most 1.2x the C++ loop).

    .venv/bin/python bench/bench_python.py [--points N] [--repeat R]
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np

import contensou as c


def paired_times(python_call, cpp_loop, repeat: int) -> tuple[list[float], list[float]]:
    """Alternates the two so that both see the same load on a shared machine."""
    py, cpp = [], []
    for _ in range(repeat):
        t0 = time.perf_counter()
        python_call()
        py.append(time.perf_counter() - t0)
        cpp.append(cpp_loop())
    return py, cpp


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=100_000)
    ap.add_argument("--repeat", type=int, default=5)
    args = ap.parse_args()
    n = args.points
    patch = c.seed_tire_patch()
    patch.profile.kx = 0.14
    model = c.ExactModel(patch)
    law = c.fractional_law_from_patch(patch)
    # Sliding at 35 degrees, psi = v / (omega R) log-spread over [0.01, 100] (every regime).
    rng = np.random.default_rng(1)
    omega = 10.0
    psi = 10 ** rng.uniform(-2, 2, n)
    v = psi * omega * patch.radius_m
    vx, vy = v * np.cos(np.radians(35)), v * np.sin(np.radians(35))
    w = np.full(n, omega)

    rows = []
    for tol in (1e-10, 1e-6):
        rows.append((f"exact resultants, tol {tol:g}", *paired_times(
            lambda: c.exact_resultants(model, vx, vy, w, tolerance=tol),
            lambda: c._core._cpp_loop_exact(model, vx, vy, w, tol), args.repeat)))
    exact = c.ExactLaw(patch, tolerance=1e-8)
    for jac in (False, True):
        rows.append(("exact law" + (" + Jacobian" if jac else ""), *paired_times(
            lambda: c.exact_law_resultants(exact, vx, vy, w, jacobian=jac),
            lambda: c._core._cpp_loop_exact_law(exact, vx, vy, w, jac), 50 * args.repeat)))
    for jac in (False, True):
        rows.append(("fractional law" + (" + Jacobian" if jac else ""), *paired_times(
            lambda: c.fractional_resultants(law, vx, vy, w, jacobian=jac),
            lambda: c._core._cpp_loop_fractional(law, vx, vy, w, jac), 50 * args.repeat)))

    print(f"contensou {c.__version__}: {n} points per call, one thread; C++ loop = the same "
          "points in a std::vector, results into a new std::vector")
    print(f"{'call':30s} {'Python min/median [ms]':>22s} {'C++ min/median [ms]':>20s} "
          f"{'ratio of min':>12s} {'of median':>10s}")
    for name, py, cpp in rows:
        pm, pd_, cm, cd = min(py), statistics.median(py), min(cpp), statistics.median(cpp)
        print(f"{name:30s} {1e3 * pm:10.2f} / {1e3 * pd_:9.2f} {1e3 * cm:9.2f} / {1e3 * cd:8.2f} "
              f"{pm / cm:12.3f} {pd_ / cd:10.3f}")


if __name__ == "__main__":
    main()
