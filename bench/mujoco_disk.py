#!/usr/bin/env python3
"""The sliding-spinning disk in MuJoCo (Farkas et al., PRL 90, 248302, 2003), six ways:
(a) MuJoCo's elliptic cone with torsional friction mu_t = (2/3) R f (the converter's pure-spin
value for uniform pressure), (b) its pyramidal cone with the same coefficients, (c) the contensou
plugin with the exact law, (d) the plugin with the fractional law, (e) the plugin's set-valued
law on the exact limit surface, (f) on its fitted ellipsoid. Prints the stopping ratio
v / (omega R) as v + omega R falls to 1 %, 0.3 % and 0.1 % of its start, the times at which v
and omega R fall below 1 % of their start, against the closed form (theory.md section 3,
integrated by RK4; the exact fixed point 0.6530), the cost of the normal force's one-step lag,
and draws the (v, omega R) trajectories into a PNG.

Usage: .venv/bin/python bench/mujoco_disk.py [--png docs/images/mujoco_disk.png] [--json out.json]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mujoco  # noqa: E402

from mujoco_common import Disk, closed_form_disk, farkas_ratio, run_disk  # noqa: E402

VARIANTS = {
    "elliptic": "(a) MuJoCo elliptic cone, mu_t = 2/3 R f",
    "pyramidal": "(b) MuJoCo pyramidal cone, mu_t = 2/3 R f",
    "exact": "(c) contensou plugin, exact law",
    "fractional": "(d) contensou plugin, fractional law",
    "set-valued": "(e) contensou plugin, set-valued (exact)",
    "set-valued-ellipsoid": "(f) contensou plugin, set-valued (ellipsoid)",
}
LEVELS = (0.01, 0.003, 0.001)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--png", default="docs/images/mujoco_disk.png")
    ap.add_argument("--json", default=None)
    ap.add_argument("--dt", type=float, default=2e-5, help="time step [s]")
    args = ap.parse_args()
    if not (args.dt > 0):
        ap.error(f"--dt = {args.dt}: must be positive")

    v0 = u0 = 1.0
    disk = Disk(timestep=args.dt)
    ref = closed_form_disk(v0, u0, disk.friction)
    runs = {k: run_disk(mujoco, disk, k, v0, u0, 0.45) for k in VARIANTS}
    print(f"disk R = {disk.radius} m, f = {disk.friction}, v0 = omega0 R = 1 m/s, dt = {args.dt} s, "
          f"MuJoCo {mujoco.__version__}")
    print(f"exact fixed point of v/(omega R): {farkas_ratio():.4f}; fractional law (a = 1, "
          f"m = 64/9): sqrt(7/48) = {math.sqrt(7 / 48):.4f}")
    head = "".join(f"  ratio@{lv:g}" for lv in LEVELS)
    print(f"{'variant':44}{head}   t_v(1%)  t_wR(1%)  t_stop(0.1%)")
    rows = {}
    for name, tr in [("closed form (theory.md 3, RK4)", ref)] + [(VARIANTS[k], runs[k]) for k in runs]:
        ratios = [tr.ratio_at(lv) for lv in LEVELS]
        tv, tw, ts = tr.time_below("v", 0.01), tr.time_below("u", 0.01), tr.time_at(0.001)
        print(f"{name:44}" + "".join(f"  {r:10.4f}" for r in ratios) + f"  {tv:8.4f}  {tw:8.4f}  {ts:8.4f}")
        rows[name] = {"ratios": dict(zip(map(str, LEVELS), ratios)), "t_v": tv, "t_wR": tw,
                      "t_stop": ts}

    # The normal force's lag: the plugin uses the previous step's contact solution.
    # max |dN|/N: largest step-to-step change of N relative to its mean; impulse err: sum of
    # |N_used - N_now| over sum of N_now (the friction impulse's relative error from the lag).
    print("\nnormal-force lag (plugin, exact law): N used (previous step) vs this step's N")
    print(f"{'case':16} {'dt [s]':>8}  {'max |dN|/N':>11}  {'impulse err':>11}  {'ratio@0.001':>11}  "
          f"{'t_stop':>8}")
    lag = []
    for case, drop in (("thrown flat", 0.0), ("dropped 5 mm", 5e-3)):
        for dt in (4e-4, 1e-4, 2e-5):
            tr = run_disk(mujoco, Disk(timestep=dt), "exact", v0, u0, 0.5, drop=drop)
            nu, nn = tr.extra["n_used"], tr.extra["n_now"]
            w = nn > 0
            rel = float(abs(nu[w] - nn[w]).max() / nn[w].mean())
            imp = float(abs(nu[w] - nn[w]).sum() / nn[w].sum())
            print(f"{case:16} {dt:8.0e}  {rel:11.2e}  {imp:11.2e}  {tr.ratio_at(0.001):11.4f}  "
                  f"{tr.time_at(0.001):8.4f}")
            lag.append({"case": case, "dt": dt, "max_rel": rel, "impulse_rel": imp,
                        "ratio": tr.ratio_at(0.001), "t_stop": tr.time_at(0.001)})

    # Pure spin (v0 = 0): the spin torque from the deceleration, I domega/dt = Mz, I = M R^2/2,
    # between 0.02 s and 0.08 s; exact: (2/3) f N R (theory.md section 3).
    print("\npure spin, omega0 R = 1 m/s: |Mz| / (f N R) from the deceleration (exact 2/3)")
    spin = {}
    for k in VARIANTS:
        tr = run_disk(mujoco, disk, k, 0.0, 1.0, 0.1)
        i, j = (int(round(t / disk.timestep)) for t in (0.02, 0.08))
        dudt = (tr.u[j] - tr.u[i]) / (tr.t[j] - tr.t[i])
        spin[k] = -dudt / (2 * disk.friction * 9.81)  # du/dt = 2 Mz / (M R)
        print(f"{VARIANTS[k]:44}  {spin[k]:.4f}")

    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps({"rows": rows, "lag": lag, "pure_spin": spin}, indent=1))
    if args.png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(6.4, 5.2))
        ax.plot(ref.u, ref.v, "k-", lw=3, alpha=0.3, label="closed form (exact law)")
        for k, tr in runs.items():
            ax.plot(tr.u, tr.v, lw=1.3, label=VARIANTS[k])
        s = farkas_ratio()
        ax.plot([0, 1], [0, s], "k:", lw=0.8, label=f"v = {s:.4f} omega R")
        ax.set_xlabel("omega R [m/s]")
        ax.set_ylabel("v [m/s]")
        ax.set_xlim(0, 1.02)
        ax.set_ylim(0, 1.02)
        ax.set_title("Sliding-spinning disk in MuJoCo: v0 = omega0 R = 1 m/s, f = 0.5")
        ax.legend(fontsize=8, loc="upper left")
        fig.tight_layout()
        Path(args.png).parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(args.png, dpi=110)
        print(f"\nwrote {args.png}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
