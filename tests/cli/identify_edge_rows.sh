#!/usr/bin/env bash
# contensou-identify on diagrams with the rows a rig produces (issue 10): pure spin, pure
# sliding, v = omega = 0, negative omega. The fit and its closed loop must run to a report
# with finite intervals (they used to end in a segfault in the covariance step).
# Usage: identify_edge_rows.sh PATH/TO/contensou-identify PATH/TO/tests/data
set -u
app="$1"
data="$2/seed_tire_edge_rows.csv"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$app" "$data" --radius 0.087 --profile seed-tire --pressure 2.1e5 --json "$dir/report.json" \
  > "$dir/out" 2> "$dir/err"
rc=$?
if [ "$rc" -ne 0 ] || [ ! -s "$dir/report.json" ]; then
  echo "FAIL: rc=$rc"; cat "$dir/err"; exit 1
fi
if grep -qiE 'nan|inf' "$dir/report.json"; then
  echo "FAIL: non-finite value in the report"; grep -iE 'nan|inf' "$dir/report.json" | head; exit 1
fi
grep -q "kx" "$dir/out" || { echo "FAIL: no kx in the table"; cat "$dir/out"; exit 1; }
# The data come from the exact integrals of the seed tire: the loop must end with white
# residuals and name the shape (the model is right once the exact integrals replace the law).
grep -q '"residual_white": true' <(python3 -c "import json,sys; print(json.dumps(json.load(open(sys.argv[1]))['final']))" "$dir/report.json") ||
  { echo "FAIL: final residuals not white"; exit 1; }
grep -q '"structure_remains": false' "$dir/report.json" || { echo "FAIL: structure remains"; exit 1; }
# The fractional law alone (no closed loop) on the same rows.
"$app" "$data" --radius 0.087 --profile seed-tire --pressure 2.1e5 --no-loop > "$dir/out2" 2> "$dir/err2" \
  || { echo "FAIL: --no-loop rc=$?"; cat "$dir/err2"; exit 1; }
echo "ok: edge rows fitted; $(grep -c . "$dir/out") lines of report"
