"""contensou.LimitSurface from Python against closed forms (theory.md section 3: uniform disk,
pure slide f N, pure spin (2/3) f N R), the exact resultants (normality: a boundary point is the
friction of its normal's kinematics), the ellipsoid's closed-form gauge, and bad input."""

from __future__ import annotations

import math

import numpy as np
import pytest

import contensou as c


def uniform() -> c.ContactPatch:
    return c.ContactPatch(radius_m=0.1, reference_pressure_pa=1e5, friction=0.5,
                          profile=c.uniform_profile())


def test_support_matches_the_closed_forms_of_the_uniform_disk():
    p = uniform()
    s = c.LimitSurface(p)
    fN, R = s.force_scale, s.radius
    assert fN == pytest.approx(0.5 * 1e5 * math.pi * 0.1**2, rel=1e-12)
    assert s.support([1.0, 0.0, 0.0]) == pytest.approx(fN, rel=1e-10)
    assert s.support([0.0, 0.0, 2.0]) == pytest.approx(4 / 3 * fN * R, rel=1e-10)
    d = s.dissipation_with_derivatives(np.array([0.3, -0.4, 2.0]))
    assert d.hessian.shape == (3, 3)
    np.testing.assert_allclose(d.hessian, d.hessian.T, atol=1e-6 * fN)
    np.testing.assert_allclose(d.hessian @ np.array([0.3, -0.4, 2.0]), 0.0, atol=1e-6 * fN)


def test_surface_point_is_minus_the_exact_resultant_of_its_normal():
    p = c.seed_tire_patch()
    p.profile.kx = 0.14
    s = c.LimitSurface(p)
    n = np.array([0.2, -0.1, 5.0])
    w = s.surface_point(n)
    r = c.exact_resultants(c.ExactModel(p), n[0], n[1], n[2], tolerance=1e-12).resultants
    np.testing.assert_allclose(w, -r, atol=1e-9 * s.force_scale)
    g = s.gauge(w)
    assert g.value == pytest.approx(1.0, abs=1e-8)


def test_projection_sticks_inside_and_lands_on_the_boundary_outside():
    s = c.LimitSurface(uniform())
    fN, R = s.force_scale, s.radius
    G = np.diag([1.0, 1.0, 1.0 / R**2])
    inside = s.project([0.3 * fN, 0.0, 0.2 * fN * R], G)
    assert inside.inside and np.all(inside.twist == 0.0)
    out = s.project([2.0 * fN, 0.5 * fN, 0.3 * fN * R], G)
    assert not out.inside and out.converged
    assert s.gauge(out.wrench).value == pytest.approx(1.0, abs=1e-8)
    # Normality: the returned twist's friction is the returned wrench.
    np.testing.assert_allclose(s.surface_point(-out.twist), out.wrench, atol=1e-7 * fN)


def test_moreau_jean_step_keeps_a_loaded_body_at_rest_and_the_ellipsoid_agrees():
    s = c.LimitSurface(uniform())
    fN, R = s.force_scale, s.radius
    twist = np.zeros(3)
    for _ in range(1000):
        st = s.moreau_jean_step(300.0, 1.5, twist, [0.5 * fN, 0.0, 0.2 * fN * R], 1e-3)
        assert st.stick
        twist = st.twist
    assert np.all(twist == 0.0)
    e = s.fit_ellipsoid()
    assert e.force_limit == pytest.approx(fN, rel=1e-10)
    assert e.torsional_length == pytest.approx(2 / 3 * R, rel=1e-10)
    assert e.kappa == pytest.approx(1.0, rel=1e-12)
    assert "EllipsoidalLimitSurface F=" in repr(e)
    # The ellipsoid's gauge in closed form.
    w = np.array([0.3 * fN, 0.4 * fN, 0.2 * fN * e.torsional_length])
    assert e.gauge(w).value == pytest.approx(math.sqrt(0.09 + 0.16 + 0.04), rel=1e-12)
    err = s.ellipsoid_error(e, 12, 12)
    assert 0.03 < err.max_radial_error < 0.08  # 6.9 % on the fine grid (docs/accuracy.md)


def test_orthotropic_surface_has_kappa_times_the_force_across():
    p = uniform()
    p.kappa = 0.6
    s = c.LimitSurface(p)
    assert s.support([0.0, 1.0, 0.0]) == pytest.approx(0.6 * s.force_scale, rel=1e-10)
    assert s.fit_ellipsoid().kappa == pytest.approx(0.6, rel=1e-10)


def test_bad_input_raises_value_error_naming_the_problem():
    s = c.LimitSurface(uniform())
    with pytest.raises(ValueError, match="metric"):
        s.project([1.0, 0.0, 0.0], np.diag([1.0, -1.0, 1.0]))
    with pytest.raises(ValueError, match="trial"):
        s.project([math.nan, 0.0, 0.0], np.eye(3))
    with pytest.raises(ValueError, match=r"direction = 2 components: must have 3"):
        s.support([1.0, 0.0])
    with pytest.raises(ValueError, match=r"metric = 2 rows: must be 3 x 3"):
        s.project([1.0, 0.0, 0.0], np.eye(2))
    with pytest.raises(ValueError, match="step"):
        s.moreau_jean_step(1.0, 1.0, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], 0.0)
    with pytest.raises(ValueError, match="kappa"):
        c.EllipsoidalLimitSurface(1.0, 0.1, 0.1, kappa=-1.0).support([1.0, 0.0, 0.0])
    p = uniform()
    p.slip_speed_friction = c.SlipSpeedFriction(0.6, 0.4, 1.0, 1.0)
    with pytest.raises(ValueError, match="slip_speed_friction"):
        c.LimitSurface(p)
