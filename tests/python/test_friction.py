"""contensou.friction against the C++ library (reference_values.cpp), closed forms and
derivatives computed here, and the array conventions (broadcasting, shapes, threads, errors)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import contensou as c

RTOL = 1e-12


def patches() -> dict[str, c.ContactPatch]:
    """The patches of reference_values.cpp, built through the Python API."""
    uniform = c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.4,
                             profile=c.uniform_profile())
    hertz = c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.4, kappa=0.8,
                           profile=c.hertz_profile())
    hertz.profile.kx = 0.1
    hertz.profile.ky = -0.05
    seed = c.seed_tire_patch()
    seed.profile.kx = 0.14
    cosine = c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.4,
                            profile=c.cosine_series_profile(0.5, [0.6, 0.3, 0.1]))
    table = c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.4,
                           profile=c.tabulated_profile([0, 0.25, 0.5, 0.75, 1], [1, 0.95, 0.8, 0.5, 0]))
    slip = c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.4,
                          slip_speed_friction=c.SlipSpeedFriction(0.5, 0.3, 2.0, 1.0))
    return {"uniform": uniform, "hertz_shifted": hertz, "seed_tire": seed,
            "cosine_series": cosine, "tabulated": table, "slip_speed": slip}


def columns(rows, names):
    return np.array([[float(r[n]) for n in names] for r in rows])


def assert_close(actual, expected, scale):
    np.testing.assert_allclose(actual, expected, rtol=RTOL, atol=RTOL * scale)


@pytest.mark.parametrize("kind,tol", [("exact", 1e-10), ("exact_1e-6", 1e-6)])
def test_exact_resultants_equal_the_cpp_values(reference_rows, kind, tol):
    seen = 0
    for name, patch in patches().items():
        rows = [r for r in reference_rows if r["kind"] == kind and r["case"] == name]
        assert rows, name
        k = columns(rows, ["vx", "vy", "omega"])
        # One vectorised call over all kinematics of the case, on two threads.
        r = c.exact_resultants(c.ExactModel(patch), k[:, 0], k[:, 1], k[:, 2], tolerance=tol,
                               threads=2)
        scale = patch.friction * patch.normal_load
        assert_close(r.resultants, columns(rows, ["Fx", "Fy", "Mz"]), scale)
        assert_close(r.error, columns(rows, ["e_Fx", "e_Fy", "e_Mz"]), scale)
        assert r.converged.all()
        seen += len(rows)
    assert seen == len(patches()) * 8  # every case, every kinematics


@pytest.mark.parametrize("kind", ["fractional", "fractional_fitted"])
def test_fractional_law_and_jacobian_equal_the_cpp_values(reference_rows, kind):
    for name, patch in patches().items():
        rows = [r for r in reference_rows if r["kind"] == kind and r["case"] == name]
        if name == "slip_speed":
            assert not rows
            continue
        law = (c.fractional_law_fitted(patch) if kind == "fractional_fitted"
               else c.fractional_law_from_patch(patch))
        k = columns(rows, ["vx", "vy", "omega"])
        F, J = c.fractional_resultants(law, k[:, 0], k[:, 1], k[:, 2], jacobian=True)
        assert_close(F, columns(rows, ["Fx", "Fy", "Mz"]), law.F0)
        expected_j = columns(rows, [f"J{i}{j}" for i in range(3) for j in range(3)]).reshape(-1, 3, 3)
        assert_close(J, expected_j, law.F0 / 0.01)
        assert_close(c.fractional_resultants(law, k[:, 0], k[:, 1], k[:, 2]), F, law.F0)


def elliptic_ke(k: float) -> tuple[float, float]:
    """Complete elliptic integrals K(k), E(k) of modulus k by the arithmetic-geometric mean."""
    a, b, cn = 1.0, math.sqrt(1.0 - k * k), k
    total, power = 0.5 * cn * cn, 0.5
    for _ in range(40):  # quadratic convergence: a few steps reach rounding
        if abs(cn) < 1e-17:
            break
        a, b, cn = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        power *= 2.0
        total += power * cn * cn
    K = math.pi / (2.0 * a)
    return K, K * (1.0 - total)


def test_elliptic_helper_is_right():
    K, E = elliptic_ke(0.0)
    assert K == pytest.approx(math.pi / 2, rel=1e-15) and E == pytest.approx(math.pi / 2, rel=1e-15)
    K, E = elliptic_ke(math.sin(math.pi / 4))  # tabulated: K = 1.854074677, E = 1.350643881
    assert K == pytest.approx(1.8540746773013719, rel=1e-14)
    assert E == pytest.approx(1.3506438810476755, rel=1e-14)


@pytest.mark.parametrize("eps", [0.1, 0.5, 0.9, 0.999, 1.001, 1.5, 3.0, 7.0])
def test_uniform_pressure_matches_contensou_closed_forms(eps):
    """theory.md section 3: F_par/(f N) and |Mz|/(f N R) for uniform pressure."""
    patch = patches()["uniform"]
    R, fN = patch.radius_m, patch.friction * patch.normal_load
    if eps <= 1:
        K, E = elliptic_ke(eps)
        fpar = 4 / (3 * math.pi) * ((1 + eps**2) * E - (1 - eps**2) * K) / eps
        mz = 4 / (9 * math.pi) * ((4 - 2 * eps**2) * E - (1 - eps**2) * K)
    else:
        K, E = elliptic_ke(1 / eps)
        fpar = 4 / (3 * math.pi) * ((1 + eps**2) * E - (eps**2 - 1) * K)
        mz = 4 / (9 * math.pi) * (2 * eps * (2 - eps**2) * E + (2 * eps**2 - 3) * (eps**2 - 1) * K / eps)
    omega = 10.0
    # The same sliding speed along x and along y (both signs of spin): one broadcast call.
    v = eps * omega * R
    r = c.exact_resultants(patch, np.array([v, 0.0]), np.array([0.0, v]), np.array([[omega], [-omega]]))
    F = r.resultants  # (2 spins, 2 directions, 3)
    assert F.shape == (2, 2, 3)
    np.testing.assert_allclose(-F[:, 0, 0], fpar * fN, rtol=0, atol=1e-9 * fN)
    np.testing.assert_allclose(-F[:, 1, 1], fpar * fN, rtol=0, atol=1e-9 * fN)
    np.testing.assert_allclose(np.abs(F[..., 2]), mz * fN * R, rtol=0, atol=1e-9 * fN * R)
    assert (np.sign(F[0, :, 2]) == -1).all() and (np.sign(F[1, :, 2]) == 1).all()


def test_fractional_law_is_seed_equation_5_for_sliding_along_x():
    """F_par = F0 v / sqrt(v^2 + a u^2), Fy = -kx M0 u / (2R sqrt(u^2 + m v^2/4)),
    Mz = -M0 u / sqrt(u^2 + m v^2), written out here; kappa scales the lateral force."""
    law = c.FractionalLaw(F0=1200.0, M0=60.0, a=1.1, m=6.0, kx=0.12, radius=0.09,
                          regularization_speed=1e-12)
    vx = np.geomspace(1e-3, 10.0, 25)
    omega = 7.0
    u = omega * law.radius
    F = c.fractional_resultants(law, vx, 0.0, omega)
    np.testing.assert_allclose(F[:, 0], -law.F0 * vx / np.sqrt(vx**2 + law.a * u**2), rtol=1e-12)
    np.testing.assert_allclose(
        F[:, 1], -law.kx * law.M0 * u / (2 * law.radius * np.sqrt(u**2 + law.m * vx**2 / 4)), rtol=1e-12)
    np.testing.assert_allclose(F[:, 2], -law.M0 * u / np.sqrt(u**2 + law.m * vx**2), rtol=1e-12)
    law.kx, law.kappa = 0.0, 0.7
    G = c.fractional_resultants(law, 0.0, vx, omega)
    np.testing.assert_allclose(G[:, 1], -law.F0 * law.kappa * vx / np.sqrt(vx**2 + law.a * u**2), rtol=1e-12)
    np.testing.assert_allclose(G[:, 2], -law.M0 * (1 + law.kappa) / 2 * u / np.sqrt(u**2 + law.m * vx**2),
                               rtol=1e-12)


def test_jacobian_matches_central_differences():
    patch = patches()["hertz_shifted"]
    law = c.fractional_law_from_patch(patch)
    rng = np.random.default_rng(7)
    k = rng.uniform(-1, 1, size=(50, 3)) * [1.0, 1.0, 20.0]
    F, J = c.fractional_resultants(law, k[:, 0], k[:, 1], k[:, 2], jacobian=True)
    numeric = np.empty_like(J)
    for j in range(3):
        h = 1e-6 * np.maximum(1.0, np.abs(k[:, j]))
        up, down = k.copy(), k.copy()
        up[:, j] += h
        down[:, j] -= h
        Fu = c.fractional_resultants(law, up[:, 0], up[:, 1], up[:, 2])
        Fd = c.fractional_resultants(law, down[:, 0], down[:, 1], down[:, 2])
        numeric[:, :, j] = (Fu - Fd) / (2 * h[:, None])
    np.testing.assert_allclose(J, numeric, rtol=1e-5, atol=1e-5 * law.F0)


def test_broadcasting_and_shapes():
    patch = patches()["seed_tire"]
    model = c.ExactModel(patch)
    law = c.fractional_law_from_patch(patch)
    vx = np.linspace(-1, 1, 4).reshape(4, 1, 1)
    vy = np.array([0.0, 0.3])[None, :, None]
    omega = np.array([-5.0, 0.0, 12.0])
    r = c.exact_resultants(model, vx, vy, omega, tolerance=1e-8)
    assert r.resultants.shape == (4, 2, 3, 3)
    assert r.error.shape == (4, 2, 3, 3) and r.converged.shape == (4, 2, 3)
    F, J = c.fractional_resultants(law, vx, vy, omega, jacobian=True)
    assert F.shape == (4, 2, 3, 3) and J.shape == (4, 2, 3, 3, 3)
    # Each element is the single-point call at those kinematics.
    for i, j, k in [(0, 0, 0), (3, 1, 2), (2, 0, 1), (1, 1, 0)]:
        one = c.exact_resultants(model, vx[i, 0, 0], vy[0, j, 0], omega[k], tolerance=1e-8)
        assert one.resultants.shape == (3,)
        np.testing.assert_array_equal(r.resultants[i, j, k], one.resultants)
        f1, j1 = c.fractional_resultants(law, vx[i, 0, 0], vy[0, j, 0], omega[k], jacobian=True)
        assert j1.shape == (3, 3)
        np.testing.assert_array_equal(F[i, j, k], f1)
        np.testing.assert_array_equal(J[i, j, k], j1)
    # Lists, ints, non-contiguous views and empty inputs.
    grid = np.arange(12.0).reshape(3, 4)
    assert c.fractional_resultants(law, grid[:, ::2], 0, 1).shape == (3, 2, 3)
    np.testing.assert_array_equal(c.fractional_resultants(law, grid[:, ::2], 0, 1),
                                  c.fractional_resultants(law, grid[:, ::2].copy(), 0.0, 1.0))
    assert c.fractional_resultants(law, [1, 2], [0], 3).shape == (2, 3)
    assert c.exact_resultants(model, np.empty((0, 5)), 0.0, 1.0).resultants.shape == (0, 5, 3)


def test_threads_give_the_same_numbers():
    model = c.ExactModel(patches()["cosine_series"])
    rng = np.random.default_rng(3)
    k = rng.normal(size=(3, 401))
    one = c.exact_resultants(model, *k, threads=1)
    for threads in (2, 3, 0):
        many = c.exact_resultants(model, *k, threads=threads)
        np.testing.assert_array_equal(many.resultants, one.resultants)
        np.testing.assert_array_equal(many.error, one.error)


def test_bad_input_raises_value_error_with_the_library_message(tmp_path):
    patch = patches()["uniform"]
    law = c.fractional_law_from_patch(patch)
    with pytest.raises(ValueError, match=r"^vx = nan: must be finite \(point 2 of the flattened input\)$"):
        c.exact_resultants(patch, [0.1, 0.2, np.nan, np.nan], 0.0, 1.0, threads=2)
    with pytest.raises(ValueError, match=r"^omega = inf: must be finite"):
        c.fractional_resultants(law, 0.1, 0.0, [1.0, np.inf])
    with pytest.raises(ValueError, match=r"^radius_m = -0.1: must be positive and finite$"):
        c.ContactPatch(radius_m=-0.1)  # refused where it is made
    with pytest.raises(ValueError, match=r"^tolerance = 2: must lie in \(0, 1\)"):
        c.exact_resultants(patch, 0.1, 0.0, 1.0, tolerance=2.0)
    with pytest.raises(ValueError, match=r"^kappa = -1: must be positive and finite$"):
        bad = c.fractional_law_from_patch(patch)
        bad.kappa = -1.0
        c.fractional_resultants(bad, 0.1, 0.0, 1.0)
    with pytest.raises(ValueError, match="do not broadcast"):
        c.exact_resultants(patch, np.zeros(3), np.zeros(4), 1.0)
    for threads in (-1, 100000, 1.5):
        with pytest.raises(ValueError, match="threads"):
            c.exact_resultants(patch, 0.1, 0.0, 1.0, threads=threads)
    with pytest.raises(ValueError, match=r"rho = 1.5: must lie in \[0, 1\]"):
        c.shape_values(c.hertz_profile(), [0.5, 1.5])
    with pytest.raises(ValueError, match="rho"):
        c.tabulated_profile([0.0, 0.6, 0.5, 1.0], [1, 1, 1, 1])
    csv = tmp_path / "profile.csv"
    csv.write_text("rho,pressure_Pa\n0,2e5\n0.5,abc\n1,0\n")
    with pytest.raises(ValueError, match=r"profile\.csv:3: .*not a number: 'abc'"):
        c.read_profile_csv(str(csv))
    # A negative pressure is refused by the exact model unless clipped or kept.
    neg = c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.4,
                         profile=c.cosine_series_profile(1.0, [0.2, 1.0]))
    with pytest.raises(ValueError, match="negative"):
        c.ExactModel(neg)


def test_profiles_and_moments(tmp_path):
    rho = np.linspace(0, 1, 11)
    np.testing.assert_array_equal(c.shape_values(c.uniform_profile(), rho), np.ones(11))
    np.testing.assert_allclose(c.shape_values(c.hertz_profile(), rho), np.sqrt(1 - rho**2), rtol=1e-15)
    cos = c.cosine_series_profile(0.848, [0.5, 0.3, -0.1])
    expected = sum(a * np.cos(np.pi * k * 0.848 * rho) for k, a in enumerate([0.5, 0.3, -0.1]))
    np.testing.assert_allclose(c.shape_values(cos, rho.reshape(11, 1)), expected.reshape(11, 1), rtol=1e-14)
    knots, values = [0.0, 0.3, 0.7, 1.0], [1.0, 0.9, 0.6, 0.1]
    table = c.tabulated_profile(knots, values)
    np.testing.assert_allclose(c.shape_values(table, knots), values, rtol=1e-14)
    for n in range(4):  # uniform: 1/(n+1); Hertz: integral sqrt(1-r^2) r^n dr
        assert c.uniform_profile().moment(n) == pytest.approx(1 / (n + 1), rel=1e-14)
    hertz = [math.pi / 4, 1 / 3, math.pi / 16, 2 / 15]
    for n, value in enumerate(hertz):
        assert c.hertz_profile().moment(n) == pytest.approx(value, rel=1e-13)
    seed = c.seed_tire_profile()
    assert seed.kind == "cosine_series" and seed.keep_negative
    (lo, hi), = seed.negative_intervals()
    assert lo == pytest.approx(0.9936, abs=1e-4) and hi == 1.0
    csv = tmp_path / "p.csv"
    csv.write_text("rho,pressure_Pa\n0,3e5\n0.5,2.5e5\n1,0\n")
    prof, p_ref = c.read_profile_csv(str(csv))
    assert prof.kind == "tabulated"
    # The reference pressure is the mean pressure: 2 A^1 = 1.
    assert 2 * prof.moment(1) == pytest.approx(1.0, rel=1e-12)
    np.testing.assert_allclose(c.shape_values(prof, [0, 0.5, 1]) * p_ref, [3e5, 2.5e5, 0], rtol=1e-12)


def test_cpp_loop_baseline_runs():
    """The benchmark's C++ baseline (bench/bench_python.py) is callable; no timing asserted."""
    patch = patches()["seed_tire"]
    x = np.linspace(0, 1, 100)
    assert c._core._cpp_loop_exact(c.ExactModel(patch), x, np.zeros(1), np.full(1, 10.0), 1e-10) > 0
    assert c._core._cpp_loop_fractional(c.fractional_law_from_patch(patch), x, np.zeros(1),
                                        np.full(1, 10.0), True) >= 0
