"""Ctrl-C in long calls (issue 22, Bounds): the C++ library polls a stop request that the
extension sets when Python's signal handler raises, so KeyboardInterrupt arrives within a
fraction of a second instead of when the call ends.

Each test starts a call that takes 5 to 15 s on a 2-core machine, sends SIGINT to this process
0.5 s in, and requires KeyboardInterrupt well before the call could have ended (2 s from the
start). Had the interrupt been honoured only at the end (the failure this guards against), the
test fails after the call's whole duration, which stays below 20 s.
"""

from __future__ import annotations

import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import contensou as c

SIGNAL_AFTER_S = 0.5
BOUND_S = 2.0  # from the call's start: the signal's 0.5 s, then at most 1.5 s to stop


def seconds_until_interrupted(call) -> float:
    """Runs call() with a SIGINT 0.5 s in; returns the seconds until KeyboardInterrupt."""
    timer = threading.Timer(SIGNAL_AFTER_S, os.kill, (os.getpid(), signal.SIGINT))
    ended_early = []
    start = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
            ended_early.append(time.monotonic() - start)  # before the signal: not a test
            time.sleep(5)  # the signal lands here
    finally:
        timer.cancel()
    assert not ended_early, f"the call ended after {ended_early[0]:.2f} s, before the signal"
    return time.monotonic() - start


@pytest.fixture(autouse=True)
def python_handles_sigint():
    """Python's own SIGINT handler for each test: a process started in the background by a
    non-interactive shell (a CI runner's `cmd &`) inherits SIGINT ignored, and Python then keeps
    it ignored, so no KeyboardInterrupt would ever come."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)


@pytest.fixture(scope="module")
def rows_600(identify_app, tmp_path_factory) -> str:
    """600 rows of the seed tire from the exact integrals (the closed loop: 5 to 10 s)."""
    path = tmp_path_factory.mktemp("interrupt") / "rows.csv"
    subprocess.run([str(identify_app), "simulate", "--out", str(path), "--points", "600"],
                   check=True, capture_output=True)
    return str(path)


def test_closed_loop_stops_on_ctrl_c(rows_600):
    elapsed = seconds_until_interrupted(lambda: c.identify(rows_600, radius=0.087))
    assert elapsed < BOUND_S
    # The extension is usable afterwards: the fit alone runs to its end.
    assert c.identify(rows_600, radius=0.087, loop=False).parameters["F0_N"].value > 0


def test_exact_resultants_over_a_large_array_stop_on_ctrl_c():
    model = c.ExactModel(c.seed_tire_patch())
    n = 1_000_000  # tens of microseconds a point: about 10 s on two threads
    vx = np.linspace(0.01, 2.0, n)
    elapsed = seconds_until_interrupted(
        lambda: c.exact_resultants(model, vx, 0.0, 11.5, tolerance=1e-10, threads=2))
    assert elapsed < BOUND_S


def test_native_stability_map_stops_on_ctrl_c():
    # 3600 landings of a few milliseconds each, about 12 s on two threads (stability_map, which
    # calls one cell at a time, returns to Python between cells anyway; one landing lasts
    # seconds at most).
    axes = (("scenario.forward_speed_mps", 40.0, 80.0, 60),
            ("structure.torsional_damping_nms_per_rad", 0.0, 300.0, 60))
    elapsed = seconds_until_interrupted(
        lambda: c.stability_map_native(c.LandingConfig.default(), axes, threads=2))
    assert elapsed < BOUND_S

