#!/usr/bin/env python3
"""Creep: the disk of bench/mujoco_disk.py (R = 0.1 m, f = 0.5, uniform pressure) rests on the
plane and is loaded below the friction limit by a horizontal force of 0.3 f N and a torque of
0.3 M0 about the normal (M0 = (2/3) f N R, the pure-spin torque; the pair lies inside the exact
limit curve, checked below with the closed forms of theory.md section 3), held for 10 s of
simulated time. A Coulomb contact would not move; the table prints the drift (horizontal
displacement and rotation about the normal) of MuJoCo's own friction (elliptic and pyramidal
cones, torsional coefficient (2/3) R f) and of the plugin (fractional law, regularised, at
several regularisation speeds eps; the exact law; the set-valued law on the exact limit surface
and on its fitted ellipsoid). "After 1 s": the displacement from 1 s to the end, i.e. the creep
without the first second's elastic settling (the disk tilts on MuJoCo's soft normal contact
under the load's moment about the patch, which moves its centre of mass by about 1e-4 mm).

Usage: .venv/bin/python bench/mujoco_creep.py [--dt 1e-3] [--seconds 10] [--json out.json]
       [--png docs/images/mujoco_creep.png]   (drift against time, log scale, every model)
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mujoco  # noqa: E402

from mujoco_common import (  # noqa: E402
    GRAVITY, PLUGIN_VARIANTS, Disk, disk_mjcf, load_plugin, uniform_closed_form)

LOAD = 0.3  # fraction of f N and of M0


def inside_limit_curve(load: float) -> bool:
    """(load F0, load M0) inside the exact limit curve {(F_par, |Mz|)(eps)} (convex): the point is
    inside iff it is below the curve where the curve's F_par equals load F0."""
    eps = np.geomspace(1e-4, 1e4, 4001)
    fm = np.array([uniform_closed_form(e) for e in eps])
    f, m = fm[:, 0], fm[:, 1] / (2 / 3)
    return bool(np.interp(load, f, m) > load)


def run(variant: str, dt: float, seconds: float, eps: float = 1e-4,
        history: list[tuple[float, float, float]] | None = None) -> tuple[float, float, float]:
    """Drift [m] and rotation [rad] over `seconds`, and the drift from 1 s to the end [m];
    `history` (if given) receives (time, dx, dy) of the centre of mass every 10 ms."""
    disk = Disk(timestep=dt)
    if variant in PLUGIN_VARIANTS:
        load_plugin(mujoco)
    m = mujoco.MjModel.from_xml_string(disk_mjcf(disk, variant, eps))
    d = mujoco.MjData(m)
    for _ in range(int(round(0.2 / dt))):  # settle
        mujoco.mj_step(m, d)
    N = float(m.body_mass[1]) * GRAVITY
    F0, M0 = disk.friction * N, 2 / 3 * disk.friction * N * disk.radius
    x0, yaw0 = d.qpos[:3].copy(), 0.0
    d.xfrc_applied[1, 0] = LOAD * F0  # force along x at the centre of mass
    d.xfrc_applied[1, 5] = LOAD * M0  # torque about z
    yaw = 0.0
    x1 = x0
    one = int(round(min(1.0, seconds) / dt))
    every = max(1, int(round(0.01 / dt)))
    for i in range(int(round(seconds / dt))):
        mujoco.mj_step(m, d)
        yaw += d.qvel[5] * dt  # body-frame spin = world spin while flat
        if i + 1 == one:
            x1 = d.qpos[:3].copy()
        if history is not None and (i + 1) % every == 0:
            dx, dy = d.qpos[:2] - x0[:2]
            history.append(((i + 1) * dt, float(dx), float(dy)))
    drift = float(np.hypot(*(d.qpos[:2] - x0[:2])))
    return drift, yaw - yaw0, float(np.hypot(*(d.qpos[:2] - x1[:2])))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dt", type=float, default=1e-3)
    ap.add_argument("--seconds", type=float, default=10.0)
    ap.add_argument("--json", default=None)
    ap.add_argument("--png", default=None, help="draw drift against time into this PNG")
    args = ap.parse_args()
    for name in ("dt", "seconds"):
        if not (getattr(args, name) > 0):
            ap.error(f"--{name} = {getattr(args, name)}: must be positive")
    print(f"creep: disk R = 0.1 m, f = 0.5, load {LOAD} f N and {LOAD} M0 "
          f"(inside the exact limit curve: {inside_limit_curve(LOAD)}), {args.seconds} s, "
          f"dt = {args.dt} s, MuJoCo {mujoco.__version__}")
    cases = [("MuJoCo elliptic cone, mu_t = 2/3 R f", "elliptic", None),
             ("MuJoCo pyramidal cone, mu_t = 2/3 R f", "pyramidal", None)]
    cases += [(f"plugin fractional, eps = {e:g} m/s", "fractional", e) for e in (1e-2, 1e-3, 1e-4)]
    cases += [("plugin exact law", "exact", None),
              ("plugin set-valued (exact surface)", "set-valued", None),
              ("plugin set-valued (ellipsoid)", "set-valued-ellipsoid", None)]
    print(f"{'model':42} {'drift [mm]':>12} {'rotation [mrad]':>16} {'after 1 s [mm]':>15}")
    rows = []
    histories: dict[str, list[tuple[float, float, float]]] = {}
    for label, variant, eps in cases:
        histories[label] = []
        drift, rot, late = run(variant, args.dt, args.seconds, eps or 1e-4, histories[label])
        print(f"{label:42} {drift * 1e3:12.4g} {rot * 1e3:16.4g} {late * 1e3:15.4g}")
        rows.append({"model": label, "drift_m": drift, "rotation_rad": rot, "drift_after_1s_m": late})
    print("(fractional law, steady creep where F0 v / sqrt(v^2 + eps^2) = 0.3 F0: "
          f"v = {LOAD / math.sqrt(1 - LOAD**2):.3f} eps)")
    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps(rows, indent=1))
    if args.png:
        draw(histories, args)
    return 0


def draw(histories: dict[str, list[tuple[float, float, float]]], args: argparse.Namespace) -> None:
    """Drift of the centre of mass against time, log scale: from the load's onset (left) and from
    1 s on (right, without the first second's elastic settling); zero drawn at the floor."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    floor = 1e-16
    fig, axes = plt.subplots(1, 2, figsize=(10.0, 4.8), sharey=True)
    for label, h in histories.items():
        if not h:
            continue
        t, dx, dy = np.array(h).T
        style = "--" if "set-valued (ellipsoid)" in label else "-"
        axes[0].semilogy(t, np.maximum(np.hypot(dx, dy), floor), style, lw=1.4, label=label)
        late = t >= 1.0 - 1e-9
        if late.sum() > 1:
            i1 = int(np.argmax(late))
            moved = np.hypot(dx[late] - dx[i1], dy[late] - dy[i1])
            axes[1].semilogy(t[late], np.maximum(moved, floor), style, lw=1.4)
    axes[0].set_title("drift since the load came on")
    axes[1].set_title("drift since t = 1 s (after the settling)")
    for ax in axes:
        ax.set_xlabel("time under load [s]")
        ax.set_ylim(floor / 2, 1.0)
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylabel("drift of the centre of mass [m]")
    fig.suptitle(f"MuJoCo disk at 0.3 of the friction limit (force and torque), dt = {args.dt:g} s")
    fig.legend(loc="lower center", ncol=3, fontsize=8, frameon=False)
    fig.tight_layout(rect=(0, 0.14, 1, 1))
    Path(args.png).parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(args.png, dpi=110)
    print(f"wrote {args.png}")


if __name__ == "__main__":
    raise SystemExit(main())
