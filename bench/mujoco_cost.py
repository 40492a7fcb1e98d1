#!/usr/bin/env python3
"""The plugin's cost per contact pair against the number of pairs: n disks (R = 0.1 m, f = 0.5,
uniform pressure) sliding and spinning on one plane, each its own pair "disk<i> floor" of one
plugin instance, for n = 1, 10, 100, 200 and each law.

The plugin's two costs per disk (per configured pair; MuJoCo makes 3 contacts per
cylinder-plane pair here), each the difference to the same model without the plugin (condim 1,
the same contacts, no friction), divided by n, on a frozen state after mj_forward (every call
sees the same contacts and twists):
  wrench:  mj_passive, the stage where the plugin computes and applies the wrench;
  normal:  mj_Euler, whose mj_advance runs the plugin's `advance`: the pair's normal forces
           (mj_contactForce) stored for the next step (qpos, qvel and time restored each call).
And, for scale, MuJoCo's whole step (mj_step) in microseconds with and without the plugin (the
kinematics restored every 20 steps, so the disks keep sliding and spinning): the difference is
more than the plugin's cost, as MuJoCo's constraint solver works harder once friction tilts
the disks on their soft contacts (the frictionless baseline's disks slide flat).
Each disk slides at 1 m/s in its own direction with v / (omega R) from 0.2 to 5 (the exact
law's cost depends on it; fixed seed). Times are the thread's CPU time (time.thread_time), so
that other processes on a shared machine count less; each number is the median of --repeats
runs, the spread (smallest to largest run) follows it in brackets.

Usage: .venv/bin/python bench/mujoco_cost.py [--disks 1 10 100 200] [--laws exact fractional]
       [--repeats 5] [--json out.json]
       (CONTENSOU_MUJOCO_PLUGIN=path/to/libcontensou_mujoco.so measures another build)
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mujoco  # noqa: E402

from mujoco_common import load_plugin, plugin_path  # noqa: E402

RADIUS, HALF_HEIGHT, FRICTION, SPACING = 0.1, 0.005, 0.5, 0.3
LAWS = {"exact": '<config key="law" value="exact"/>',
        "fractional": '<config key="law" value="fractional"/>',
        "set-valued": '<config key="law" value="set-valued"/>'}


def disks_mjcf(n: int, law: str | None, dt: float = 1e-3) -> str:
    """n disks on a square grid (SPACING apart) on a plane; law None: no plugin."""
    side = math.ceil(math.sqrt(n))
    bodies = "".join(
        f'<body name="disk{i}" pos="{SPACING * (i % side)} {SPACING * (i // side)} {HALF_HEIGHT}">'
        f'<freejoint/><geom name="disk{i}" type="cylinder" size="{RADIUS} {HALF_HEIGHT}" '
        'density="1000" condim="1" contype="1" conaffinity="2"/></body>'
        for i in range(n))
    ext = ""
    if law is not None:
        pairs = "; ".join(f"disk{i} floor" for i in range(n))
        ext = ('<extension><plugin plugin="contensou.friction"><instance name="patch">'
               f'<config key="pairs" value="{pairs}"/><config key="friction" value="{FRICTION}"/>'
               f'<config key="radius" value="{RADIUS}"/>{LAWS[law]}'
               '</instance></plugin></extension>')
    return (f'<mujoco><option timestep="{dt}"/>{ext}<worldbody>'
            '<geom name="floor" type="plane" size="100 100 .1" condim="1" contype="2" '
            f'conaffinity="1"/>{bodies}</worldbody></mujoco>')


def throw(d, n: int) -> None:
    """Each disk at 1 m/s in its own direction, spin omega = v / (psi R), psi in [0.2, 5]."""
    rng = np.random.default_rng(0)
    angle = rng.uniform(0.0, 2.0 * math.pi, n)
    psi = np.exp(rng.uniform(math.log(0.2), math.log(5.0), n))
    for i in range(n):
        d.qvel[6 * i:6 * i + 6] = [math.cos(angle[i]), math.sin(angle[i]), 0.0, 0.0, 0.0,
                                   1.0 / (psi[i] * RADIUS)]


def settled(n: int, law: str | None):
    m = mujoco.MjModel.from_xml_string(disks_mjcf(n, law))
    d = mujoco.MjData(m)
    for _ in range(50):  # 0.05 s: resting contacts, the normal forces stored
        mujoco.mj_step(m, d)
    throw(d, n)
    mujoco.mj_forward(m, d)
    return m, d


def time_passive(m, d, calls: int) -> float:
    """Seconds per mj_passive call on a frozen state."""
    t0 = time.thread_time()
    for _ in range(calls):
        mujoco.mj_passive(m, d)
    return (time.thread_time() - t0) / calls


def time_euler(m, d, calls: int) -> float:
    """Seconds per mj_Euler call (the plugin's `advance` inside), from the same state each call
    (qpos, qvel, time restored outside the timing)."""
    spec = (mujoco.mjtState.mjSTATE_QPOS | mujoco.mjtState.mjSTATE_QVEL
            | mujoco.mjtState.mjSTATE_TIME)
    state = np.empty(mujoco.mj_stateSize(m, spec))
    mujoco.mj_getState(m, d, state, spec)
    total = 0.0
    for _ in range(calls):
        mujoco.mj_setState(m, d, state, spec)
        t0 = time.thread_time()
        mujoco.mj_Euler(m, d)
        total += time.thread_time() - t0
    mujoco.mj_setState(m, d, state, spec)
    return total / calls


def time_step(m, d, steps: int, chunk: int = 20) -> float:
    """Seconds per mj_step, restarting from the same state every `chunk` steps."""
    spec = mujoco.mjtState.mjSTATE_INTEGRATION
    state = np.empty(mujoco.mj_stateSize(m, spec))
    mujoco.mj_getState(m, d, state, spec)
    total = 0.0
    for _ in range(max(1, steps // chunk)):
        mujoco.mj_setState(m, d, state, spec)
        t0 = time.thread_time()
        mujoco.mj_step(m, d, chunk)
        total += time.thread_time() - t0
    mujoco.mj_setState(m, d, state, spec)
    return total / (max(1, steps // chunk) * chunk)


def measure(n: int, law: str, repeats: int) -> dict:
    """The plugin's wrench and normal-force costs per disk [ns] over the baseline's, and the
    step with and without the plugin [us]; each the median and spread of `repeats` runs."""
    with_plugin, without = settled(n, law), settled(n, None)
    calls = max(200, 40000 // n)
    steps = max(200, 20000 // n)
    runs = {"wrench": [], "normal": [], "step": [], "step_without": []}
    for _ in range(repeats):
        runs["wrench"].append(1e9 / n * (time_passive(*with_plugin, calls)
                                         - time_passive(*without, calls)))
        runs["normal"].append(1e9 / n * (time_euler(*with_plugin, calls // 4)
                                         - time_euler(*without, calls // 4)))
        runs["step"].append(1e6 * time_step(*with_plugin, steps))
        runs["step_without"].append(1e6 * time_step(*without, steps))
    row = {"disks": n, "law": law, "contacts": int(with_plugin[1].ncon)}
    for name, xs in runs.items():
        row[name] = {"median": statistics.median(xs), "min": min(xs), "max": max(xs)}
    return row


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--disks", type=int, nargs="+", default=[1, 10, 100, 200])
    ap.add_argument("--laws", nargs="+", default=["exact", "fractional"], choices=list(LAWS))
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--json", default=None)
    args = ap.parse_args()
    if min(args.disks) < 1 or args.repeats < 1:
        ap.error(f"--disks {args.disks}, --repeats {args.repeats}: must be at least 1")
    load_plugin(mujoco)
    print(f"plugin {plugin_path()}, MuJoCo {mujoco.__version__}; median [min - max] of "
          f"{args.repeats} runs; wrench, normal: the plugin's CPU time per disk [ns] over the same "
          "model without it; step: MuJoCo's whole step [us], without the plugin -> with it")
    print(f"{'law':12} {'disks':>5} {'contacts':>8} {'wrench [ns/disk]':>23} "
          f"{'normal [ns/disk]':>23} {'step [us]':>25}")
    rows = []
    for law in args.laws:
        for n in args.disks:
            r = measure(n, law, args.repeats)
            cells = "".join(
                f" {r[k]['median']:7.0f} [{r[k]['min']:5.0f} - {r[k]['max']:5.0f}]"
                for k in ("wrench", "normal"))
            step = f"{r['step_without']['median']:9.1f} -> {r['step']['median']:7.1f}"
            print(f"{law:12} {n:5d} {r['contacts']:8d}{cells}      {step}")
            rows.append(r)
    if args.json:
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
        Path(args.json).write_text(json.dumps(rows, indent=1))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
