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
python3 - "$data" "$dir/plots/fit.csv" <<'PY'
import csv, math, sys
data, shown = sys.argv[1:]
rows = list(csv.DictReader(l for l in open(data) if not l.startswith("#")))
pts = {}
for r in rows:
    v = math.hypot(float(r["vx_mps"]), float(r["vy_mps"]))
    w = abs(float(r["omega_radps"])) * 0.087
    if v > 0 and w > 0:
        pts.setdefault(round(v / w, 6), []).append(r)
out = list(csv.DictReader(open(shown)))
assert len(out) == sum(len(p) for p in pts.values()), f"{len(out)} rows shown, data have {len(pts)}"
for o in out:
    cands = pts[round(float(o["psi"]), 6)]
    for ch in ("Fx_N", "Fy_N", "Mz_Nm"):
        got = float(o["measured_" + ch])
        assert any(abs(got - float(r[ch])) <= 1e-9 * (1 + abs(float(r[ch]))) for r in cands), \
            f"measured_{ch} = {got} at psi {o['psi']} is not the data's"
        res = float(o["residual_" + ch])
        assert abs(res - (got - float(o["fit_" + ch]))) <= 1e-6 * (1 + abs(got)), f"residual_{ch}"
print(f"fit.csv: {len(out)} rows, each channel the data's own values")
PY
