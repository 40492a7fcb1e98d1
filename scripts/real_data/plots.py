"""The pictures of docs/real-data.md (contensou_vs_field.py): the measured and identified limit
surface, and predicted against measured motion across speeds. Data are selected by column name
(the predictions' CSV), axes carry units, and each file is written to a temporary name and
renamed."""

from __future__ import annotations

import os
import subprocess
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from scipy.special import ellipe, ellipk  # noqa: E402

import benchmark as bm  # noqa: E402


def ring(s: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """P(s) = |F| / (f W) and Q(s) = |Mz| / (f W R) of a ring of pressure at the rim, s = |v| /
    (|omega| R) (coulomb_envelope.hpp: closed forms with J(k) = (E - (1 - k^2) K) / k^2, modulus
    k; scipy's ellipk/ellipe take m = k^2)."""
    def J(k):
        m = k * k
        # (1 - m) K(m) -> 0 at m = 1, where K is infinite: J(1) = 1.
        tail = np.where(m < 1, (1 - m) * ellipk(np.minimum(m, 1 - 1e-16)), 0.0)
        return np.where(k > 1e-6, (ellipe(m) - tail) / np.maximum(m, 1e-300), np.pi / 4)
    small = s <= 1
    k = np.where(small, s, 1 / np.maximum(s, 1e-300))
    P = np.where(small, 2 / np.pi * s * J(k), 2 / np.pi * ellipe(k * k))
    Q = np.where(small, 2 / np.pi * ellipe(k * k), 2 / np.pi * J(k) / np.maximum(s, 1e-300))
    return P, Q


def meridian(report: Path, work: Path, direction_deg: float,
             speed: float) -> tuple[np.ndarray, np.ndarray]:
    """The model's |F| and |Mz| / R [N] along twists of size `speed` [m/s] from pure sliding to
    pure spin in one sliding direction (the app's predict at those motions)."""
    theta = np.radians(np.linspace(0.5, 89.5, 90))
    phi = np.radians(direction_deg)
    rows = work / f"meridian_{direction_deg:.0f}.csv"
    lines = ["vx_mps,vy_mps,omega_radps"] + [
        f"{speed * np.cos(t) * np.cos(phi):.12g},{speed * np.cos(t) * np.sin(phi):.12g},"
        f"{speed * np.sin(t) / bm.RADIUS_M:.12g}" for t in theta]
    bm.write_text_atomically(rows, "\n".join(lines) + "\n")
    out = work / f"meridian_{direction_deg:.0f}_pred.csv"
    subprocess.run([str(bm.ROOT / "build" / "apps" / "contensou-identify"), "predict", "--model",
                    str(report), str(rows), "--out", str(out)], check=True, capture_output=True)
    _, header, cells = bm._read_table(out)
    w = bm._columns(out, header, cells, ("pred_Fx_N", "pred_Fy_N", "pred_Mz_Nm"))
    return np.hypot(w[:, 0], w[:, 1]), np.abs(w[:, 2]) / bm.RADIUS_M


def patch_meridian(report: Path, direction_deg: float,
                   speed: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The rigid patch of the motion (the report's model.motion_patch; None without one): its |F|
    and |Mz| / R [N] along the meridian of meridian(), from its exact integrals (the Python
    package: p = rho^n as the exact Chebyshev series in rho^2 that power_profile holds)."""
    import json

    import contensou as c

    patch = json.loads(report.read_text()).get("model", {}).get("motion_patch")
    if not patch:
        return None
    n = int(patch["exponent"])
    rho = np.sqrt(np.linspace(0.0, 1.0, 2 * n + 8))
    profile = c.smoothed_profile(list(rho), list(rho ** n), n // 2 + 1)[0]
    profile.kx, profile.ky = patch["kx"], patch["ky"]
    a = patch["contact_radius_ratio"] * patch["radius_m"]
    surface = c.LimitSurface(c.ContactPatch.from_normal_load(a, patch["force_scale_N"], profile,
                                                             1.0), 1e-8)
    theta = np.radians(np.linspace(0.5, 89.5, 90))
    phi = np.radians(direction_deg)
    w = np.array([-np.asarray(surface.dissipation_with_derivatives(
        [speed * np.cos(t) * np.cos(phi), speed * np.cos(t) * np.sin(phi),
         speed * np.sin(t) / bm.RADIUS_M]).gradient) for t in theta])
    return np.hypot(w[:, 0], w[:, 1]), np.abs(w[:, 2]) / bm.RADIUS_M


def save(fig, path: Path) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.stem}.", suffix=".png")
    os.close(fd)
    os.chmod(tmp, 0o644)
    fig.savefig(tmp, dpi=110, bbox_inches="tight")
    plt.close(fig)
    os.replace(tmp, path)
    return path


def limit_surfaces(diagrams: dict, work: Path, path: Path) -> Path:
    """Each set: measured (|F|, |Mz| / R), the identified law's meridians in four sliding
    directions, the rigid patch's that gives the motion from the force, and the limit surface of a ring of pressure at the rim scaled to the model's own
    sliding force (its meridian's end at pure sliding): the support function of a centred
    patch, a mixture of rings of radius up to R, is at most the rim ring's, so every centred
    patch with that sliding force lies inside the dashed curve."""
    fig, axes = plt.subplots(1, len(diagrams), figsize=(5 * len(diagrams), 4.4), squeeze=False)
    s = np.logspace(-3, 3, 400)
    P, Q = ring(s)
    for ax, (name, d) in zip(axes[0], diagrams.items()):
        F = np.hypot(d.wrenches[:, 0], d.wrenches[:, 1])
        ax.scatter(F, np.abs(d.wrenches[:, 2]), s=6, color="0.55", label="measured")
        report = work / "whole" / f"{name}.json"
        sliding = []
        speed = float(np.median(np.linalg.norm(d.twists, axis=1)))
        for k, direction in enumerate((0, 90, 180, 270)):
            f, m = meridian(report, work / "whole", direction, speed)
            sliding.append(f[0])
            ax.plot(f, m, color="C0", lw=1.4, label="identified law (4 directions)" if k == 0 else None)
            pm = patch_meridian(report, direction, speed)
            if pm is not None:
                ax.plot(pm[0], pm[1], color="C2", lw=1.2,
                        label="rigid patch of the motion" if k == 0 else None)
        scale = float(np.mean(sliding))
        ax.plot(scale * P, scale * Q, color="C3", ls="--", lw=1.2,
                label="rim ring, same sliding force")
        ax.set_title(f"{name}: limit surface (force and torque)")
        ax.set_xlabel("|F| = |(Fx, Fy)| [N]")
        ax.set_ylabel("|Mz| / R [N]")
        ax.set_ylim(0, 1.15 * max(scale, float(np.max(np.abs(d.wrenches[:, 2])))))
        ax.legend(fontsize=7, loc="upper right", framealpha=0.9)
    return save(fig, path)


def motion(shown: dict, path: Path) -> Path:
    """Across speeds: the twist's elevation atan2(omega R, |v|), predicted against measured, for
    contensou (the predictions' CSV) and the ellipsoid fitted on the same rows."""
    train, test, work = shown["train"], shown["test"], shown["work"]
    pred = work / "pred.csv"
    _, header, cells = bm._read_table(pred)
    t_c = bm._columns(pred, header, cells, bm.TWIST_COLUMNS)
    ell = bm.make_model("ellipsoid").fit(train.twists, train.wrenches)
    t_e = ell.motion_from_force(test.wrenches)

    def elevation(t):
        return np.degrees(np.arctan2(t[:, 2], np.hypot(t[:, 0], t[:, 1])))

    measured = elevation(test.twists)
    fig, ax = plt.subplots(figsize=(5.6, 5.2))
    ax.plot([-90, 90], [-90, 90], color="0.3", lw=0.8, label="predicted = measured")
    ax.scatter(measured, elevation(t_e), s=7, color="C1", alpha=0.6, label="ellipsoid")
    ax.scatter(measured, elevation(t_c), s=7, color="C0", alpha=0.6, label="contensou")
    ax.set_xlim(-90, 90)
    ax.set_ylim(-90, 90)
    ax.set_xlabel("measured twist elevation atan2(omega R, |v|) [deg]")
    ax.set_ylabel("predicted twist elevation [deg]")
    ax.set_title(f"motion from force: {train.name} fitted, {test.name} predicted")
    ax.legend(fontsize=8, loc="upper left")
    return save(fig, path)


def draw(shown: dict, diagrams: dict, runs: dict, images: Path) -> dict:
    """Both pictures; their paths by caption."""
    del runs
    work = shown["work"].parent
    return {"measured and identified limit surfaces": limit_surfaces(
                diagrams, work, images / "real_limit_surface.png"),
            "predicted against measured motion across speeds": motion(
                shown, images / "real_motion.png")}
