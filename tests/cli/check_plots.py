#!/usr/bin/env python3
"""Checks the gnuplot scripts an app wrote against the CSV files they read.

Usage: check_plots.py DIR [DIR ...]

For every DIR/*.gp: each column a plot names ("name" or column("name")) is in the header of the
CSV it reads; the axis labels carry the unit that the plotted columns' names end in (t_s -> [s],
Mz_nm -> [N m], ...; a pure number -> [-]), and a label that names a force or moment channel
(Fx, Fy, Mz, ...) names the one its column holds; where the script fixes a y range, every finite value
of the plotted columns lies inside it (the range in force at that plot: the last `set yrange`, or
`set y2range` for a clause on axes x1y2, since the last `set autoscale` of that axis). Columns chosen by number (using 1:3) are refused: they
silently pick another quantity when a column is added. Exit status 1 with one line per problem.
"""
import csv
import glob
import math
import os
import re
import sys

# Unit suffixes of the column and configuration names (independent of the apps' own tables).
UNITS = [("_nms_per_rad", "N m s/rad"), ("_nm_per_rad", "N m/rad"), ("_nm2_per_rad", "N m^2/rad"),
         ("_ns_per_m", "N s/m"), ("_n_per_m", "N/m"), ("_kgm2", "kg m^2"), ("_radps", "rad/s"),
         ("_mps", "m/s"), ("_nm", "N m"), ("_kg", "kg"), ("_pa", "Pa"), ("_rad", "rad"),
         ("_n", "N"), ("_m", "m"), ("_s", "s"), ("_per_s", "1/s"), ("_hz", "Hz")]


def unit_of(name):
    low = name.lower()
    for suffix, unit in sorted(UNITS, key=lambda u: -len(u[0])):
        if low.endswith(suffix):
            return unit
    return "-"


def header(path):
    with open(path, newline="") as f:
        return next(csv.reader(f))


def column_values(path, name):
    out = []
    with open(path, newline="") as f:
        rows = csv.reader(f)
        i = next(rows).index(name)
        for row in rows:
            if len(row) > i:
                try:
                    v = float(row[i])
                except ValueError:
                    continue
                if math.isfinite(v):
                    out.append(v)
    return out


def label(script, axis):
    """The axis label in force at the end of `script` (the last one set before a plot)."""
    m = re.findall(r"set %slabel '([^']*)'" % axis, script)
    return m[-1] if m else None


def range_in_force(before, axis):
    """(lo, hi) of the last numeric `set <axis>range [lo:hi]` in `before` that no later
    `set autoscale <axis>` undid; None where the axis autoscales."""
    last = None
    for m in re.finditer(r"set (%s)range \[([^:\]]+):([^\]]+)\]|set autoscale (%s)\b" % (axis, axis),
                         before):
        last = (float(m.group(2)), float(m.group(3))) if m.group(1) else None
    return last


def check_script(gp):
    problems = []
    folder = os.path.dirname(gp)
    script = open(gp).read()
    lines = script.splitlines()
    for number, line in enumerate(lines):
        if not line.startswith("plot "):
            continue
        before = "\n".join(lines[:number])
        current = None
        for clause in re.split(r",\s*(?=')", line[5:]):
            f = re.match(r"'([^']*)'", clause)
            if f and f.group(1):
                current = f.group(1)
            using = re.search(r"using\s+(\S+)", clause)
            if not using or current is None:
                continue
            spec = using.group(1)
            names = re.findall(r'"([^"]+)"', spec)
            if not current.endswith("_boundary.csv") and re.match(r"^\$?\d+:", spec):
                problems.append(f"{gp}: columns chosen by number: using {spec}")
            csv_path = os.path.join(folder, current)
            if not os.path.exists(csv_path):
                problems.append(f"{gp}: reads {current}, which is not there")
                continue
            have = header(csv_path)
            for n in names:
                if n not in have:
                    problems.append(f"{gp}: column '{n}' not in the header of {current}")
            if not names:
                continue
            plotted = [n for n in re.findall(r'^"([^"]+)":"([^"]+)"', spec)]
            # One sweep's rows: "x":(column("sweep")==K?column("y"):NaN).
            plotted += re.findall(r'^"([^"]+)":\(column\("sweep"\)==\d+\?column\("([^"]+)"\):NaN\)$',
                                  spec)
            if not plotted:
                continue
            x, y = plotted[0]
            for axis, col in (("x", x), ("y", y)):
                text = label(before, axis)
                want = "[" + unit_of(col) + "]"
                if text is None or not text.endswith(want):
                    problems.append(f"{gp}: {axis} label '{text}' does not end in {want} ({col})")
                # A label that names a force or moment channel names the one plotted (not Fy
                # under 'Mz [N]'); a generic label ('friction force [N]') may hold several.
                named = re.findall(r"\b(F[xyz]|M[xyz])\b", text or "")
                for channel in re.findall(r"(?:^|_)(F[xyz]|M[xyz])(?=_|$)", col):
                    if named and channel not in named:
                        problems.append(f"{gp}: {axis} label '{text}' does not name {channel} "
                                        f"({col})")
            fixed = range_in_force(before, "y2" if "axes x1y2" in clause else "y")
            if fixed and y in have:
                lo, hi = fixed
                vals = column_values(csv_path, y)
                if vals and (min(vals) < lo or max(vals) > hi):
                    problems.append(f"{gp}: {y} of {current} spans [{min(vals)}, {max(vals)}] "
                                    f"outside the y range [{lo}, {hi}]")
    return problems


def main(dirs):
    problems, scripts = [], 0
    for d in dirs:
        for gp in sorted(glob.glob(os.path.join(d, "*.gp"))):
            scripts += 1
            problems += check_script(gp)
    for p in problems:
        print("FAIL " + p)
    if scripts == 0:
        print("FAIL no gnuplot scripts in " + " ".join(dirs))
        return 1
    print(f"checked {scripts} plot scripts: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
