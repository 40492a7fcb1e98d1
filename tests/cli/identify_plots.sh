#!/usr/bin/env bash
# The identification's pictures show what they claim: every plot selects its columns by name,
# its axis labels carry the units of those columns (check_plots.py), and fit.csv holds the
# measured values of the data file, channel by channel, at their own psi = |v| / (|omega| R).
# Usage: identify_plots.sh APP DATA_CSV
set -euo pipefail
app="$1" data="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$app" "$data" --radius 0.087 --profile seed-tire --pressure 2.1e5 --plots "$dir/plots" >/dev/null
python3 "$(dirname "$0")/check_plots.py" "$dir/plots"
for png in fit_Fx_N fit_Fy_N fit_Mz_Nm loop_step_1; do
  [ "$(head -c 4 "$dir/plots/$png.png" | od -An -c | tr -d ' ')" = '211PNG' ] ||
    { echo "FAIL $png.png is not a PNG"; exit 1; }
done
python3 - "$data" "$dir/plots/fit.csv" "$dir/plots/sweeps.csv" <<'PY'
import csv, math, sys
data, shown, sweeps = sys.argv[1:]
# The data file's rows by their line number (1-based, comments and header counted).
by_line, header = {}, None
for number, text in enumerate(open(data), start=1):
    if text.startswith("#") or not text.strip():
        continue
    cells = next(csv.reader([text]))
    if header is None:
        header = cells
        continue
    by_line[number] = dict(zip(header, cells))
out = list(csv.DictReader(open(shown)))
assert len(out) == len(by_line), f"{len(out)} rows shown, the data have {len(by_line)}"
assert len({int(o["line"]) for o in out}) == len(out), "a line shown twice"
keys = {}
for o in out:
    r = by_line[int(o["line"])]
    v = math.hypot(float(r["vx_mps"]), float(r["vy_mps"]))
    u = abs(float(r["omega_radps"])) * 0.087
    psi = v / u if u > 0 else (math.inf if v > 0 else 0.0)
    assert math.isclose(float(o["psi"]), psi, rel_tol=1e-8, abs_tol=1e-12), f"psi at line {o['line']}"
    for ch in ("Fx_N", "Fy_N", "Mz_Nm"):
        got, fit, res = (float(o[k + ch]) for k in ("measured_", "fit_", "residual_"))
        want = float(r[ch]) if r.get(ch, "") != "" else math.nan
        assert (math.isnan(got) and math.isnan(want)) or abs(got - want) <= 1e-9 * (1 + abs(want)), \
            f"measured_{ch} = {got} at line {o['line']} is not the data's {want}"
        if not math.isnan(res):
            assert abs(res - (got - fit)) <= 1e-6 * (1 + abs(got)), f"residual_{ch} at line {o['line']}"
    # One sweep: one sliding direction and one spin speed.
    d = round(math.degrees(math.atan2(float(r["vy_mps"]), float(r["vx_mps"])))) if v > 0 else None
    keys.setdefault(o["sweep"], set()).add((d, round(u, 6)))
for s, k in keys.items():
    assert len(k) == 1, f"sweep {s} mixes directions or spin speeds: {sorted(k, key=str)}"
table = list(csv.DictReader(open(sweeps)))
assert sum(int(t["rows"]) for t in table) == len(out), "sweeps.csv does not count every row"
print(f"fit.csv: {len(out)} rows in {len(table)} sweeps, each channel the data's own values")
PY
# A title that says "one colour a sweep" has one measured clause a sweep, each its own colour.
python3 - "$dir/plots/fit.gp" "$dir/plots/sweeps.csv" <<'PY'
import csv, re, sys
gp, sweeps = open(sys.argv[1]).read(), list(csv.DictReader(open(sys.argv[2])))
for block in gp.split("set output ")[1:]:
    if "one colour a sweep" not in block:
        continue
    measured = re.findall(r'column\("sweep"\)==(\d+)\?column\("measured_[^"]+"\):NaN\) with points pt \d+ ps [\d.]+ lc (rgb \S+|\d+)', block)
    assert len(measured) == len(sweeps), f"{len(measured)} measured clauses for {len(sweeps)} sweeps"
    assert len({c for _, c in measured}) == len(sweeps), "two sweeps share a colour"
print("fit.gp: one colour a sweep, as its titles say")
PY
