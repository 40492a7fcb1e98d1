#!/usr/bin/env bash
# contensou-identify judged on rows no fit used and predicting both ways, as a user runs it:
# --holdout and --validate give one held-out block each in the JSON, with finite errors and a
# step list; `predict --model REPORT.json` writes one line a row, rows without forces included
# (no motion predicted for them), and its forces at the fitted file's rows are the report's own
# model's; a damaged model file and a missing one are refused by name with a non-zero exit.
# Usage: identify_held_out_and_predict.sh PATH/TO/contensou-identify
set -u
app="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }
"$app" simulate --out "$dir/a.csv" --model exact --profile hertz --radius 0.05 --pressure 2e4 \
  --directions 0,1,2,3,4,5 --points 30 --spin-speed 0.02 --seed 3 >/dev/null || fail simulate a
"$app" simulate --out "$dir/b.csv" --model exact --profile hertz --radius 0.05 --pressure 2e4 \
  --directions 0.5,2.5 --points 30 --spin-speed 0.05 --seed 4 >/dev/null || fail simulate b
"$app" "$dir/a.csv" --radius 0.05 --holdout 0.2 --validate "$dir/b.csv" --resamples 2 \
  --json "$dir/r.json" >"$dir/out" 2>"$dir/err" || { cat "$dir/err"; fail "the fit failed"; }
grep -q "^held out: 20 % of the rows" "$dir/out" || fail "no held-out block in the report"
grep -q "^validation file .*b.csv: 60 rows no fit used" "$dir/out" || fail "no validation block"
python3 - "$dir/r.json" <<'PY' || fail "JSON held_out"
import json, math, sys
r = json.load(open(sys.argv[1]))
h = r["held_out"]
assert len(h) == 2, h
assert h[1]["rows"] == 60, h[1]["rows"]
for x in h:
    assert math.isfinite(x["base_error"]) and math.isfinite(x["final_error"]), x
    assert x["final"]["rows"] == x["rows"], x["final"]
assert r["model"]["format"] == "contensou-model 1"
PY
# Predictions: the fitted file's rows, and the same rows without their forces.
"$app" predict --model "$dir/r.json" "$dir/a.csv" --out "$dir/p.csv" >"$dir/pout" ||
  fail "predict failed"
[ "$(wc -l <"$dir/p.csv")" -eq 181 ] || fail "predict wrote $(wc -l <"$dir/p.csv") lines, not 181"
grep -q "motion from the force: median angle" "$dir/pout" || fail "no scores printed"
grep -v '^#' "$dir/a.csv" | cut -d, -f1-3 >"$dir/bare.csv"
"$app" predict --model "$dir/r.json" "$dir/bare.csv" --out "$dir/pb.csv" >/dev/null ||
  fail "predict refused rows without forces"
python3 - "$dir/p.csv" "$dir/pb.csv" <<'PY' || fail "predictions without forces"
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(b) == 180
for x, y in zip(a, b):
    assert x["pred_Fx_N"] == y["pred_Fx_N"] and x["pred_Mz_Nm"] == y["pred_Mz_Nm"]
    assert y["pred_twist_vx"] == "" and x["pred_twist_vx"] != ""
PY
# Bad model files: named, non-zero exit, nothing written.
echo '{"format": "contensou-model 1"}' >"$dir/bad.json"
"$app" predict --model "$dir/bad.json" "$dir/a.csv" --out "$dir/x.csv" 2>"$dir/e1" &&
  fail "a model without members was accepted"
grep -qE "bad.json: [A-Za-z_]+ = missing: the model file needs it" "$dir/e1" || { cat "$dir/e1"; fail "the missing member is not named"; }
"$app" predict --model "$dir/none.json" "$dir/a.csv" --out "$dir/x.csv" 2>"$dir/e2" &&
  fail "a missing model file was accepted"
grep -q "none.json" "$dir/e2" || { cat "$dir/e2"; fail "the missing file is not named"; }
[ ! -e "$dir/x.csv" ] || fail "a refused prediction wrote its output"
echo "held-out, validation and predictions both ways: ok"
