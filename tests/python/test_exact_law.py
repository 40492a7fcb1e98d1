"""contensou.ExactLaw and exact_law_resultants: against the adaptive integrator
(exact_resultants) within the law's certified bound, the Jacobian against central differences
of the law, the GIL released during the loop, bad input, broadcasting and a patch with
slip-speed friction."""

from __future__ import annotations

import inspect
import threading
import time

import numpy as np
import pytest

import contensou as c
from test_friction import patches


@pytest.fixture(scope="module")
def laws() -> dict[str, tuple[c.ContactPatch, c.ExactLaw]]:
    """One law a patch of test_friction.patches() (the slip-speed one takes about a second)."""
    return {name: (p, c.ExactLaw(p)) for name, p in patches().items()}


def random_kinematics(rng: np.random.Generator, radius: float, n: int) -> np.ndarray:
    """(n, 3) kinematics with |v| / (|omega| R) log-uniform over 6 decades, a tenth within 1 % of
    the rim, and exact zeros: pure spin, pure sliding and rest."""
    angle = rng.uniform(-np.pi, np.pi, n)
    eps = np.exp(6.9 * rng.uniform(-1, 1, n))
    eps[::10] = np.exp(0.01 * rng.uniform(-1, 1, eps[::10].size))
    w = np.exp(4.0 * rng.uniform(-1, 1, n)) * rng.choice([-1.0, 1.0], n)
    v = eps * np.abs(w) * radius
    k = np.stack([v * np.cos(angle), v * np.sin(angle), w], axis=1)
    k[1::97, :2] = 0.0  # pure spin
    k[2::89, 2] = 0.0  # pure sliding
    k[3::83] = 0.0  # rest
    return k


def friction_scale(patch: c.ContactPatch) -> float:
    """f N: with slip-speed friction, the larger of f_s and f_k."""
    s = patch.slip_speed_friction
    f = patch.friction if s is None else max(s.static_coefficient, s.kinetic_coefficient)
    return f * patch.normal_load


def relative_error(a: np.ndarray, b: np.ndarray, patch: c.ContactPatch) -> float:
    scale = friction_scale(patch) * np.array([1.0, 1.0, patch.radius_m])
    return float(np.max(np.abs(a - b) / scale))


@pytest.mark.parametrize("name",
                         ["uniform", "hertz_shifted", "seed_tire", "cosine_series", "tabulated"])
def test_law_matches_the_integrator_within_its_bound(laws, name):
    patch, law = laws[name]
    assert law.reached and law.achieved <= law.tolerance == 1e-8
    k = random_kinematics(np.random.default_rng(7), patch.radius_m, 2000)
    assert (k == 0).all(axis=1).any() and ((k[:, :2] == 0).all(axis=1) & (k[:, 2] != 0)).any()
    assert ((k[:, 2] == 0) & (k[:, 0] != 0)).any()
    exact = c.exact_resultants(patch, *k.T, tolerance=1e-13, threads=2).resultants
    fast = c.exact_law_resultants(law, *k.T)
    assert relative_error(fast, exact, patch) <= law.achieved
    assert not fast[(k == 0).all(axis=1)].any()  # zero at rest


def test_slip_speed_friction(laws):
    """f(w) = f_k + (f_s - f_k) exp(-w / w_s) inside the integrals (f_s = 0.5, f_k = 0.3,
    w_s = 2 m/s), on slip speeds from far below w_s to far above."""
    patch, law = laws["slip_speed"]
    assert law.has_slip_speed and not laws["uniform"][1].has_slip_speed
    assert law.reached and law.achieved <= 1e-8
    assert "f(w) from 0.5 to 0.3 (w_s=2 m/s, delta=1)" in repr(law)
    k = random_kinematics(np.random.default_rng(17), patch.radius_m, 300)
    speed = np.hypot(k[:, 0], k[:, 1]) + np.abs(k[:, 2]) * patch.radius_m
    assert speed[speed > 0].min() < 0.01 * 2.0 and speed.max() > 100 * 2.0
    exact = c.exact_resultants(patch, *k.T, tolerance=1e-11, threads=2).resultants
    fast = c.exact_law_resultants(law, *k.T)
    assert relative_error(fast, exact, patch) <= law.achieved
    # Pure sliding at speed w: every point slips at w, F = -f(w) N.
    w = np.array([0.2, 2.0, 8.0])
    F = c.exact_law_resultants(law, w, 0.0, 0.0)
    np.testing.assert_allclose(F[:, 0], -(0.3 + 0.2 * np.exp(-w / 2.0)) * patch.normal_load,
                               rtol=0, atol=law.achieved * friction_scale(patch))


@pytest.mark.parametrize("name", ["hertz_shifted", "seed_tire", "slip_speed"])
def test_jacobian_matches_central_differences_of_the_law(laws, name):
    patch, law = laws[name]
    R = patch.radius_m
    k = random_kinematics(np.random.default_rng(11), R, 300)
    k = k[~(k == 0).all(axis=1)]  # rest: the law is not differentiable there
    F, J = c.exact_law_resultants(law, *k.T, jacobian=True, threads=2)
    # the Jacobian path is a separate (hand-differentiated) evaluation: equal to rounding
    np.testing.assert_allclose(F, c.exact_law_resultants(law, *k.T), rtol=1e-12,
                               atol=1e-12 * np.abs(F).max())
    speed = np.hypot(k[:, 0], k[:, 1]) + np.abs(k[:, 2]) * R
    fN = friction_scale(patch)
    for col in range(3):
        h = 1e-6 * speed / (R if col == 2 else 1.0)
        up, down = k.copy(), k.copy()
        up[:, col] += h
        down[:, col] -= h
        numeric = (c.exact_law_resultants(law, *up.T) - c.exact_law_resultants(law, *down.T)) / (
            2 * h[:, None])
        scale = fN / speed[:, None] * (R if col == 2 else 1.0) * np.array([1.0, 1.0, R])
        assert np.all(np.abs(J[:, :, col] - numeric) <= 1e-6 * scale), col


def test_gil_is_released_during_the_loop(laws):
    """A Python thread keeps running while a long call is in C++: the largest pause between its
    ticks is a small part of the call (it would be the whole loop with the GIL held)."""
    _, law = laws["seed_tire"]
    vx = np.linspace(-1.0, 1.0, 400_000)
    c.exact_law_resultants(law, vx[:1000], 0.3, 5.0, jacobian=True)  # warm
    ticks: list[float] = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            time.sleep(1e-3)

    thread = threading.Thread(target=tick)
    thread.start()
    time.sleep(0.02)
    t0 = time.perf_counter()
    c.exact_law_resultants(law, vx, 0.3, 5.0, jacobian=True)
    t1 = time.perf_counter()
    stop.set()
    thread.join()
    inside = [t0] + [t for t in ticks if t0 < t < t1] + [t1]
    assert t1 - t0 > 0.05, "the call is too short to tell"
    assert max(np.diff(inside)) < 0.5 * (t1 - t0)


def test_bad_input_raises_errors_naming_the_value(laws):
    patch, law = laws["uniform"]
    with pytest.raises(ValueError,
                       match=r"^vx = nan: must be finite \(point 2 of the flattened input\)$"):
        c.exact_law_resultants(law, [0.1, 0.2, np.nan, np.nan], 0.0, 1.0, threads=2)
    with pytest.raises(ValueError, match=r"^omega = inf: must be finite \(point 1 of"):
        c.exact_law_resultants(law, 0.1, 0.0, [1.0, np.inf], jacobian=True)
    with pytest.raises(ValueError, match=r"^vy = nan: must be finite \(point 3 of"):
        c.exact_law_resultants(law, np.zeros((2, 2)), [[0.0, 0.0], [0.0, np.nan]], 1.0)
    for tol, text in ((1e-2, "0.01"), (1e-15, "1e-15"), (0.0, "0"), (np.nan, "nan")):
        with pytest.raises(ValueError, match=rf"^tolerance = {text}: must lie in \(1e-14, 1e-2\)$"):
            c.ExactLaw(patch, tolerance=tol)
    with pytest.raises(TypeError, match="^tolerance: a number is required, not str 'small'$"):
        c.ExactLaw(patch, tolerance="small")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^radius_m = -0.1: must be positive and finite$"):
        c.ContactPatch(radius_m=-0.1)  # refused where it is made
    with pytest.raises(TypeError, match="model: expected an ExactModel or a ContactPatch"):
        c.ExactLaw(law)  # type: ignore[arg-type]
    for threads in (-1, 100000, 1.5):
        with pytest.raises(ValueError, match="threads"):
            c.exact_law_resultants(law, 0.1, 0.0, 1.0, threads=threads)  # type: ignore[arg-type]
        with pytest.raises(ValueError, match="threads"):
            c.ExactLaw(patch, threads=threads)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="do not broadcast"):
        c.exact_law_resultants(law, np.zeros(3), np.zeros(4), 1.0)


def test_broadcasting_and_shapes(laws):
    _, law = laws["seed_tire"]
    vx = np.linspace(-1, 1, 4).reshape(4, 1, 1)
    vy = np.array([0.0, 0.3])[None, :, None]
    omega = np.array([-5.0, 0.0, 12.0])
    F = c.exact_law_resultants(law, vx, vy, omega)
    G, J = c.exact_law_resultants(law, vx, vy, omega, jacobian=True)
    assert F.shape == G.shape == (4, 2, 3, 3) and J.shape == (4, 2, 3, 3, 3)
    np.testing.assert_allclose(F, G, rtol=1e-12, atol=1e-12 * np.abs(F).max())
    for i, j, k in [(0, 0, 0), (3, 1, 2), (2, 0, 1), (1, 1, 0)]:
        one = c.exact_law_resultants(law, vx[i, 0, 0], vy[0, j, 0], omega[k])
        f1, j1 = c.exact_law_resultants(law, vx[i, 0, 0], vy[0, j, 0], omega[k], jacobian=True)
        assert one.shape == (3,) and j1.shape == (3, 3)
        np.testing.assert_array_equal(F[i, j, k], one)
        np.testing.assert_array_equal(J[i, j, k], j1)
    grid = np.arange(12.0).reshape(3, 4)
    np.testing.assert_array_equal(c.exact_law_resultants(law, grid[:, ::2], 0, 1),
                                  c.exact_law_resultants(law, grid[:, ::2].copy(), 0.0, 1.0))
    assert c.exact_law_resultants(law, [1, 2], [0], 3).shape == (2, 3)
    assert c.exact_law_resultants(law, np.empty((0, 5)), 0.0, 1.0).shape == (0, 5, 3)
    empty, jac = c.exact_law_resultants(law, np.empty((0, 5)), 0.0, 1.0, jacobian=True)
    assert empty.shape == (0, 5, 3) and jac.shape == (0, 5, 3, 3)
    k = np.random.default_rng(3).normal(size=(3, 401))
    one = c.exact_law_resultants(law, *k)
    for threads in (2, 3, 0):
        np.testing.assert_array_equal(c.exact_law_resultants(law, *k, threads=threads), one)


def test_properties_repr_and_signature(laws):
    patch, law = laws["uniform"]
    assert law.radius == patch.radius_m
    assert law.load_area == pytest.approx(np.pi, rel=1e-12)  # 2 pi A^1, A^1 = 1/2
    assert law.tolerance == 1e-8 and 0 < law.achieved <= 1e-8 and law.reached
    assert law.samples > 0 and 0 < law.bytes < 1 << 20
    assert repr(law).startswith("<ExactLaw R=0.1 m, f=0.4, kappa=1, achieved=")
    params = inspect.signature(c.ExactLaw).parameters
    assert list(params) == ["model", "tolerance", "threads"]
    assert params["tolerance"].default == 1e-8 and params["threads"].default == 0
    with pytest.raises(AttributeError):
        law.achieved = 0.0  # type: ignore[misc]
    # From the model or the patch, on one thread or all: the same law.
    k = random_kinematics(np.random.default_rng(5), patch.radius_m, 200)
    same = c.ExactLaw(c.ExactModel(patch), threads=1)
    np.testing.assert_array_equal(c.exact_law_resultants(same, *k.T),
                                  c.exact_law_resultants(law, *k.T))
    coarse = c.ExactLaw(patch, tolerance=1e-4)
    assert coarse.bytes < law.bytes and coarse.achieved <= 1e-4
