"""The planar-pushing reference models of scripts/real_data (limit_surfaces.py, and the scoring of
benchmark.py) on synthetic data made here: an exact ellipsoid is recovered, an exact convex
quartic predicts its own normals, force from motion and motion from force invert each other, the
fitted quartic is convex, nearest neighbour returns a training point's own answer, bad input is a
ValueError. Sign convention: the data hold the friction w; the surfaces hold W = -w."""

from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts" / "real_data"))

import numpy as np  # noqa: E402
import pytest  # noqa: E402

import benchmark as bm  # noqa: E402
import limit_surfaces as ls  # noqa: E402

A_TRUE = np.array([[0.12, 0.01, 0.02], [0.01, 0.10, 0.04], [0.02, 0.04, 0.55]])  # 1/N^2


def quartic_truth() -> ls.QuarticLimitSurface:
    """A convex quartic that is no ellipsoid: B_1 SPD, B_2 rank 2, B_3 rank 1 = (c . W)^4."""
    c = np.array([0.3, -0.2, 0.5])
    B2 = np.array([[0.08, 0.02, 0.0], [0.02, 0.03, 0.0], [0.0, 0.0, 0.0]])
    return ls.QuarticLimitSurface.from_matrices([0.6 * A_TRUE, B2, np.outer(c, c)])


def surface_pairs(model, n: int, seed: int):
    """n twists and FRICTION wrenches drawn exactly from a model: W on H(W) = 1 in random
    directions, t = speed * ∇H(W)/|∇H(W)| with random speeds, w = -W."""
    rng = np.random.default_rng(seed)
    W = model.project(rng.normal(size=(n, 3)))
    g = model.gradient(W)
    speeds = rng.uniform(1e-3, 1e-2, size=n)
    return speeds[:, None] * g / np.linalg.norm(g, axis=1)[:, None], -W


def angle_deg(a, b):
    return bm.angles_deg(np.asarray(a), np.asarray(b))


def test_exact_ellipsoid_data_recover_its_matrix():
    truth = ls.EllipsoidLimitSurface.from_matrix(A_TRUE)
    t, w = surface_pairs(truth, 60, seed=1)
    assert np.all(np.sum(t * -w, axis=1) > 0)  # applied power W . t > 0: the sign is right
    fit = ls.EllipsoidLimitSurface().fit(t, w)
    assert np.linalg.norm(fit.A - A_TRUE) / np.linalg.norm(A_TRUE) < 1e-6
    np.testing.assert_allclose(fit.A, fit.A.T, atol=0)
    t_new, w_new = surface_pairs(truth, 40, seed=2)
    assert angle_deg(fit.motion_from_force(w_new), t_new).max() < 1e-5
    np.testing.assert_allclose(fit.force_from_motion(t_new), w_new, rtol=1e-6, atol=1e-6)


def test_exact_quartic_data_predict_their_own_normals():
    truth = quartic_truth()
    t, w = surface_pairs(truth, 150, seed=3)
    fit = ls.QuarticLimitSurface().fit(t, w)
    t_new, w_new = surface_pairs(truth, 60, seed=4)
    assert angle_deg(fit.motion_from_force(w_new), t_new).max() < 1e-6
    rel = np.linalg.norm(fit.force_from_motion(t_new) - w_new, axis=1) / np.linalg.norm(w_new,
                                                                                     axis=1)
    assert rel.max() < 1e-8
    # A quartic that is no ellipsoid: the best ellipsoid misses its normals by degrees.
    ell = ls.EllipsoidLimitSurface().fit(t, w)
    assert np.median(angle_deg(ell.motion_from_force(w_new), t_new)) > 0.5


@pytest.mark.parametrize("model", [ls.EllipsoidLimitSurface.from_matrix(A_TRUE), quartic_truth()],
                         ids=["ellipsoid", "quartic"])
def test_force_from_motion_and_motion_from_force_are_inverse(model):
    rng = np.random.default_rng(5)
    t = rng.normal(size=(200, 3)) * [1e-2, 1e-2, 3e-3]
    w = model.force_from_motion(t)
    np.testing.assert_allclose(model.value(-w), 1.0, rtol=1e-10)
    assert angle_deg(model.motion_from_force(w), t).max() < 1e-7
    # The other way: a wrench inside or outside maps to its radial projection on the surface.
    w_any = rng.normal(size=(200, 3)) * 2.0
    back = model.force_from_motion(model.motion_from_force(w_any))
    np.testing.assert_allclose(back, -model.project(-w_any), rtol=1e-8, atol=1e-10)
    # Support point: no point of the surface has more power along t.
    probe = model.project(rng.normal(size=(20000, 3)))
    t_unit = t / np.linalg.norm(t, axis=1)[:, None]
    assert np.all(np.sum(-w * t_unit, axis=1) >= (t_unit @ probe.T).max(axis=1) - 1e-12)


def test_quartic_support_is_finite_for_hard_directions_and_through_the_fallback(monkeypatch):
    model = quartic_truth()
    hard = np.vstack([np.eye(3), -np.eye(3), [[1e-12, 0.0, 1.0], [1.0, 1e-9, -1e-9]],
                      [[3e-3, -4e-3, 1e-6]]])
    w = model.force_from_motion(hard)
    assert np.all(np.isfinite(w))
    assert angle_deg(model.motion_from_force(w), hard).max() < 1e-6
    # Newton reports failure on every row: scipy's trust-exact gives the same support points.
    monkeypatch.setattr(model, "_newton", lambda t, u: (u, np.zeros(len(t), dtype=bool)))
    np.testing.assert_allclose(model.force_from_motion(hard), w, rtol=1e-6, atol=1e-9)


def test_fitted_quartic_is_convex():
    rng = np.random.default_rng(6)
    t, w = surface_pairs(quartic_truth(), 200, seed=7)
    t_noisy = t + rng.normal(scale=2e-3, size=t.shape)  # rows no quartic fits exactly
    w_noisy = w * rng.uniform(0.7, 1.3, size=(len(w), 1))
    fit = ls.QuarticLimitSurface().fit(t_noisy, w_noisy)
    points = rng.normal(size=(2000, 3)) * rng.uniform(1e-3, 10.0, size=(2000, 1))
    eig = np.linalg.eigvalsh(fit.hessian(points))
    assert np.all(eig[:, 0] >= -1e-12 * eig[:, -1])
    assert np.all(eig[:, -1] > 0)
    for B in fit.B:
        assert np.linalg.eigvalsh(B)[0] >= -1e-12 * np.trace(B)
    # The surface is closed: H > 0 off the origin.
    assert np.all(fit.value(points) > 0)


@pytest.mark.parametrize("model", [ls.NearestNeighbour(), ls.NearestNeighbour(1, "uniform")],
                         ids=["default", "k1-uniform"])
def test_nearest_neighbour_returns_a_training_points_own_answer(model):
    rng = np.random.default_rng(8)
    t = rng.normal(size=(80, 3)) * 1e-2
    w = rng.normal(size=(80, 3))
    model.fit(t, w)
    np.testing.assert_allclose(model.motion_from_force(w),
                               t / np.linalg.norm(t, axis=1)[:, None], atol=1e-12)
    np.testing.assert_allclose(model.force_from_motion(t), w, atol=1e-12)
    # Scale does not matter: only directions are compared.
    np.testing.assert_allclose(model.force_from_motion(3.0 * t), w, atol=1e-12)


def test_nearest_neighbour_uniform_averages_its_k_neighbours():
    t = np.array([[1.0, 0, 0], [0.99, 0.1, 0], [0.98, -0.1, 0], [-1, 0, 0]])
    w = np.array([[-1.0, 0, 0], [-2.0, 0, 0], [-3.0, 0, 0], [9.0, 0, 0]])
    model = ls.NearestNeighbour(3, "uniform").fit(t, w)
    np.testing.assert_allclose(model.force_from_motion([[1.0, 0.0, 0.0]]), [[-2.0, 0, 0]])


MODELS = [ls.EllipsoidLimitSurface, ls.QuarticLimitSurface, ls.NearestNeighbour]


@pytest.mark.parametrize("make", MODELS, ids=lambda m: m.__name__)
def test_bad_input_is_a_clear_value_error(make):
    t, w = surface_pairs(ls.EllipsoidLimitSurface.from_matrix(A_TRUE), 40, seed=9)
    bad = w.copy()
    bad[7, 1] = np.nan
    with pytest.raises(ValueError, match="row 7 is not finite"):
        make().fit(t, bad)
    zero = t.copy()
    zero[3] = 0.0
    with pytest.raises(ValueError, match="row 3 is zero"):
        make().fit(zero, w)
    with pytest.raises(ValueError, match="cannot fit"):
        make().fit(t[:make().n_params - 1], w[:make().n_params - 1])
    with pytest.raises(ValueError, match="twists but"):
        make().fit(t, w[:-1])
    with pytest.raises(ValueError, match="N x 3"):
        make().fit(t[:, :2], w[:, :2])
    model = make().fit(t, w)
    with pytest.raises(ValueError, match="row 0 is zero"):
        model.force_from_motion(np.zeros((2, 3)))
    with pytest.raises(ValueError, match="not finite"):
        model.motion_from_force([[np.nan, 1.0, 0.0]])


def test_matrices_given_by_hand_are_checked():
    with pytest.raises(ValueError, match="positive definite"):
        ls.EllipsoidLimitSurface.from_matrix(np.diag([1.0, 1.0, 0.0]))
    with pytest.raises(ValueError, match="semidefinite"):
        ls.QuarticLimitSurface.from_matrices([np.eye(3), np.diag([1.0, -1.0, 0.0])])
    with pytest.raises(ValueError, match="symmetric"):
        ls.EllipsoidLimitSurface.from_matrix(np.array([[1.0, 0.5, 0], [0, 1, 0], [0, 0, 1]]))


def synthetic_diagram(tmp_path: Path, model, n: int = 30) -> bm.Diagram:
    """A diagram file in the measured format (omega and Mz unscaled by R), read back."""
    t, w = surface_pairs(model, n, seed=10)
    R = bm.RADIUS_M
    path = tmp_path / "diagram_synthetic.csv"
    rows = [",".join(f"{v:.17g}" for v in (*ti[:2], ti[2] / R, *wi[:2], wi[2] * R))
            for ti, wi in zip(t, w)]
    path.write_text("# synthetic\nvx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm\n"
                    + "\n".join(rows) + "\n")
    d = bm.load_diagram(path)
    np.testing.assert_allclose(d.twists, t, rtol=1e-12)
    np.testing.assert_allclose(d.wrenches, w, rtol=1e-12)
    return d


def test_score_of_exact_and_external_predictions(tmp_path):
    truth = ls.EllipsoidLimitSurface.from_matrix(A_TRUE)
    d = synthetic_diagram(tmp_path, truth)
    s = bm.score(truth.motion_from_force(d.wrenches), truth.force_from_motion(d.twists), d)
    assert s["n"] == 30 and s["motion_angle_deg_median"] < 1e-6
    assert s["force_rel_err_mean"] < 1e-10 and s["force_angle_deg_mean"] < 1e-6
    # An external file: forces as friction in the data's units (Mz in N m), one failed row.
    pw = 1.1 * d.wrenches
    pw[4] = np.nan
    lines = ["# data: diagram_synthetic.csv", "pred_Fx_N,pred_Fy_N,pred_Mz_Nm"]
    lines += [f"{a:.17g},{b:.17g},{c * bm.RADIUS_M:.17g}" for a, b, c in pw]
    csv = tmp_path / "pred.csv"
    csv.write_text("\n".join(lines) + "\n")
    rows = bm.external_protocol([f"other={csv}"], {"synthetic": d}, bm.RADIUS_M)
    assert rows[0]["invalid_wrench"] == 1 and "motion_angle_deg_median" not in rows[0]
    assert rows[0]["force_rel_err_median"] == pytest.approx(0.1, rel=1e-9)
    assert rows[0]["force_angle_deg_mean"] < 1e-6
    with pytest.raises(ValueError, match="NAME"):
        bm.parse_external("no-equals-sign")


def test_json_is_written_atomically(tmp_path):
    out = tmp_path / "sub" / "bench.json"
    bm.write_json_atomically(out, {"a": 1.5})
    bm.write_json_atomically(out, {"a": 2.5})
    assert out.read_text().strip().endswith("}") and '"a": 2.5' in out.read_text()
    assert [p.name for p in out.parent.iterdir()] == ["bench.json"]
    with pytest.raises(ValueError):
        bm.write_json_atomically(out, {"a": float("nan")})
    assert '"a": 2.5' in out.read_text() and len(list(out.parent.iterdir())) == 1
