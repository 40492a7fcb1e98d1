#!/usr/bin/env python3
"""Writes docs/shimmy-results.md, every number the shimmy docs quote, from the app's own runs.

Usage: shimmy_results.py OUT.md DEFAULT_DIR SWEEP_DIR TIRE_DIR [BENCH.json]

DEFAULT_DIR holds `contensou-shimmy --map` (summary.json, the map CSVs), SWEEP_DIR
`contensou-shimmy --bifurcation` at the large offset, TIRE_DIR `contensou-shimmy --tire`; BENCH.json
is bench_shimmy's --benchmark_format=json output (optional). The commit, the machine and its load
are stated at the top. Called by scripts/make-doc-images.sh; nothing here is typed by hand.
"""
import csv
import json
import math
import os
import platform
import subprocess
import sys


def fmt(v, digits=3):
    if v is None or (isinstance(v, float) and not math.isfinite(v)):
        return "–"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, (int,)) and not isinstance(v, bool):
        return str(v)
    a = abs(v)
    if a != 0 and (a < 1e-3 or a >= 1e5):
        return f"{v:.{digits}g}"
    return f"{v:.{digits}g}" if a >= 1 else f"{v:.{digits}f}".rstrip("0").rstrip(".") or "0"


def signed(v, digits=2):
    if v is None or not math.isfinite(v):
        return "–"
    return f"{v:+.{digits}f}"


def machine():
    cpu = "unknown CPU"
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    load = os.getloadavg() if hasattr(os, "getloadavg") else (float("nan"),) * 3
    return f"{cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}", load


def commit():
    try:
        rev = subprocess.run(["git", "rev-parse", "--short=12", "HEAD"], capture_output=True,
                             text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
        return rev + (" (with uncommitted changes)" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def scenario_tables(s, out):
    out.append("## Scenarios (`contensou-shimmy`): landings, eigenvalues, limit cycles\n")
    out.append("| scenario | model | simulated growth [1/s] | eigenvalue growth [1/s] (phase) | "
               "frequency [Hz] | end of the window | amplitude [rad] | torque link [N m] | "
               "steps |")
    out.append("|---|---|---|---|---|---|---|---|---|")
    for name, sc in s["scenarios"].items():
        phase = sc["phase"]
        for model, run in sc["summary"]["models"].items():
            st = run["stability"][phase]
            lc = run["limit_cycle"]
            out.append(f"| {name} | {model} | {signed(run['growth_rate_per_s'])} | "
                       f"{signed(st['growth_rate_per_s'])} ({phase}) | {fmt(run['frequency_Hz'])} | "
                       f"{lc['state'].replace('_', ' ')} by {fmt(lc['run_end_s'])} s | "
                       f"{fmt(lc['amplitude_rad'])} | {fmt(lc['torque_link_amplitude_nm'])} | "
                       f"{run['steps']} |")
    out.append("")
    out.append("Both phases by eigenvalues (default gear: the `braked-slide` scenario's "
               "configuration):\n")
    out.append("| model | phase | growth [1/s] | frequency [Hz] | torsional mode [1/s] | "
               "−dMz/dψ′ [N m s/rad] | f | verdict |")
    out.append("|---|---|---|---|---|---|---|---|")
    for model, run in s["scenarios"]["braked-slide"]["summary"]["models"].items():
        for phase in ("touchdown", "braked_slide"):
            st = run["stability"][phase]
            out.append(f"| {model} | {phase} | {signed(st['growth_rate_per_s'])} | "
                       f"{fmt(st['frequency_Hz'])} | {signed(st['torsion_growth_rate_per_s'])} | "
                       f"{fmt(st['spin_torque_damping_nms_per_rad'])} | {fmt(st['friction'])} | "
                       f"{st['verdict']} |")
    out.append("")
    out.append("Energy per cycle of the dominant mode [mJ at 1 mrad of torsion or 1 mm of "
               "deflection], each scenario's phase (> 0 feeds the mode):\n")
    keys = ["offset_drag", "spin_torque", "trail_lateral_force", "lateral_friction",
            "torsional_damping", "lateral_damping", "of_which_fall_of_friction", "total"]
    out.append("| scenario | model | mode | " + " | ".join(k.replace("_", " ") for k in keys) + " |")
    out.append("|---|---|---|" + "---|" * len(keys))
    for name, sc in s["scenarios"].items():
        for model, run in sc["summary"]["models"].items():
            st = run["stability"][sc["phase"]]
            e = st["energy_per_cycle_J"]
            out.append(f"| {name} | {model} | {st['mode']} | " +
                       " | ".join(f"{1e3 * e[k]:+.1f}" for k in keys) + " |")
    out.append("")


def sensitivity_table(s, out):
    rows = s.get("classical_sensitivity")
    if not rows:
        return
    out.append("## The classical verdict against the classical tire's assumed numbers\n")
    out.append("One change at a time from the default gear (eigenvalues; the offset boundary is "
               "the lowest over 45, 58 and 70 m/s):\n")
    out.append("| model | change | touchdown critical damping [N m s/rad] | braked slide growth "
               "[1/s] | lowest unstable offset, braked [m] |")
    out.append("|---|---|---|---|---|")
    for r in rows:
        b = r["lowest_unstable_offset_m"]
        where = f"{b:.3f} (at {r['at_forward_speed_mps']:.0f} m/s)" if b is not None else "none up to 1 m"
        out.append(f"| {r['model']} | {r['change']} | "
                   f"{fmt(r['touchdown_critical_damping_nms_per_rad'], 4)} | "
                   f"{signed(r['braked_slide_growth_rate_per_s'])} | {where} |")
    out.append("")


def lowest_unstable(csv_path, xname, yname):
    """Per x, the lowest y with growth > 0 (linear interpolation between rows); the lowest of
    them and its x."""
    rows = [r for r in csv.DictReader(l for l in open(csv_path) if l.strip())]
    by_x = {}
    for r in rows:
        if r["valid"] in ("1", "true"):
            by_x.setdefault(float(r[xname]), []).append((float(r[yname]), float(r["growth_rate_per_s"])))
    best = None
    for x, col in by_x.items():
        col.sort()
        for (y0, g0), (y1, g1) in zip(col, col[1:]):
            if g0 <= 0 < g1:
                y = y0 + (y1 - y0) * (-g0) / (g1 - g0)
                if best is None or y < best[0]:
                    best = (y, x)
                break
    return best


def map_table(s, folder, out):
    maps = s.get("maps")
    if not maps:
        return
    out.append("## Maps (`contensou-shimmy --map`, eigenvalues)\n")
    out.append("| x × y | phase | model | cells | unstable cells | unstable lobes | not computed | "
               "lowest y where the growth turns positive going up y (at x) |")
    out.append("|---|---|---|---|---|---|---|---|")
    for m in maps:
        low = lowest_unstable(os.path.join(folder, m["csv"]), m["x"], m["y"])
        where = f"{low[0]:.4g} (at {low[1]:.3g})" if low else "–"
        out.append(f"| {m['x'].split('.')[-1]} × {m['y'].split('.')[-1]} | {m['phase']} | "
                   f"{m['model']} | {m['points'][0]} × {m['points'][1]} | {m['shimmy_cells']} | "
                   f"{m.get('unstable_lobes', '–')} | {m['not_computed_cells']} | {where} |")
    out.append("")


def sweep_table(s, out):
    sweeps = s.get("bifurcation")
    if not sweeps:
        return
    cfg = s["configuration"]
    out.append("## Bifurcation sweeps (`contensou-shimmy --bifurcation`, braked slide)\n")
    out.append(f"At offset {cfg['structure']['offset_m']} m and {cfg['scenario']['forward_speed_mps']} "
               "m/s (the `large-offset` scenario), each parameter swept up from a small kick and "
               "down from a large swing:\n")
    out.append("| model | parameter | linear boundaries | settled cycle, up | settled cycle, down | "
               "largest amplitude [rad] (torque link [N m]) | shortest onset [s] |")
    out.append("|---|---|---|---|---|---|---|")
    for sw in sweeps:
        pts = [p for p in sw["up"] + sw["down"] if p["state"] == "limit_cycle"]
        big = max(pts, key=lambda p: p["amplitude_rad"]) if pts else None
        onsets = [p["onset_s"] for p in sw["up"] if p["onset_s"] is not None]
        rng = lambda r: f"{fmt(r[0])} … {fmt(r[1])}" if r else "none"
        out.append(f"| {sw['model']} | {sw['parameter'].split('.')[-1]} | "
                   f"{', '.join(fmt(b, 4) for b in sw['linear_boundaries']) or 'none'} | "
                   f"{rng(sw['limit_cycle_range_up'])} | {rng(sw['limit_cycle_range_down'])} | "
                   + (f"{fmt(big['amplitude_rad'])} ({fmt(big['torque_link_nm'])})" if big else "–")
                   + f" | {fmt(min(onsets)) if onsets else '–'} |")
    out.append("")


def tire_table(s, out):
    t = None
    for sc in s.get("scenarios", {}).values():
        t = sc["summary"].get("tire_uncertainty") or t
    t = t or s.get("tire_uncertainty")
    if not t:
        return
    law = t["mean_law"]
    out.append("## The seed tire's identified law as the tire (`--tire`)\n")
    out.append(f"The report's {t['report_model']} model: a = {fmt(law['a'])}, m = {fmt(law['m'])}, "
               f"kx = {fmt(law['kx'])}, M0/(F0 R) = {fmt(law['spin_ratio'])}; {t['draws']} draws "
               f"({t['redrawn']} redrawn). {t['note']}\n")
    out.append("| phase | median growth [1/s] | 95 % band [1/s] | P(shimmy) |")
    out.append("|---|---|---|---|")
    for phase in ("touchdown", "braked_slide"):
        b = t[phase]
        out.append(f"| {phase} | {signed(b['median_growth_rate_per_s'])} | "
                   f"[{signed(b['band95_per_s'][0])}, {signed(b['band95_per_s'][1])}] | "
                   f"{b['shimmy_probability']:.3f} |")
    out.append("")


def bench_table(path, out):
    if not path or not os.path.exists(path):
        return
    b = json.load(open(path))
    out.append("## Speed (`bench/bench_shimmy`, CPU time)\n")
    ctx = b.get("context", {})
    out.append(f"Run at load average {', '.join(f'{v:.1f}' for v in ctx.get('load_avg', []))} "
               f"on {ctx.get('num_cpus', '?')} CPUs.\n")
    out.append("| benchmark | CPU time | real-time factor | steps | RHS evaluations | "
               "off the 1e-10 landing: growth [1/s], frequency |")
    out.append("|---|---|---|---|---|---|")
    rows = b["benchmarks"]
    medians = [r for r in rows if r.get("run_type") == "aggregate" and r.get("aggregate_name") == "median"]
    for r in medians or rows:
        unit = r.get("time_unit", "ns")
        wall = "real_time" in r["name"]  # the maps: wall time on their threads
        t = r["real_time"] if wall else r["cpu_time"]
        rt = r.get("realtime_factor")
        name = r["name"].replace("_median", "").replace("/iterations:1/real_time", " (wall)")
        off = (f"{r['growth_diff_per_s']:.2g}, {r['freq_rel_diff']:.2g}"
               if "growth_diff_per_s" in r else "–")
        out.append(f"| {name} | {t:.3g} {unit} | "
                   f"{fmt(rt, 4) + '×' if rt else '–'} | {fmt(r.get('steps'), 4)} | "
                   f"{fmt(r.get('rhs'), 4)} | {off} |")
    out.append("")
    reps = sum(1 for r in rows if r.get("run_type") == "iteration") // max(len(medians), 1)
    out.append(f"Medians of {reps} repetitions (the machine is shared: times move with its load). "
               "BM_Rhs and BM_Jacobian: one right-hand side and one structured Jacobian at the "
               "braked slide's quasi-steady state; a landing's time less its RHS evaluations × "
               "BM_Rhs is CVODE's own work per step (error test, Nordsieck update, LU solves). "
               "BM_LandingTolerance/k: the default coupled landing at relative tolerance 1e-k, "
               "its window's fitted growth rate and frequency against the same landing at 1e-10.")
    out.append("")


def main(argv):
    out_path, default_dir, sweep_dir, tire_dir = argv[1:5]
    bench = argv[5] if len(argv) > 5 else None
    what, load = machine()
    out = ["# The shimmy demo's numbers, generated",
           "",
           "<!-- generated by scripts/make-doc-images.sh (scripts/shimmy_results.py): do not edit -->",
           "",
           f"Every number below comes from the runs of `scripts/make-doc-images.sh` at commit "
           f"{commit()}, on {what}, load average {load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} "
           "(1 / 5 / 15 min) when written. [shimmy.md](shimmy.md) and "
           "[shimmy-demo.md](shimmy-demo.md) explain them.",
           ""]
    default = json.load(open(os.path.join(default_dir, "summary.json")))
    scenario_tables(default, out)
    sensitivity_table(default, out)
    map_table(default, default_dir, out)
    sweep_table(json.load(open(os.path.join(sweep_dir, "summary.json"))), out)
    tire_table(json.load(open(os.path.join(tire_dir, "summary.json"))), out)
    bench_table(bench, out)
    open(out_path, "w").write("\n".join(out).rstrip() + "\n")


if __name__ == "__main__":
    main(sys.argv)
