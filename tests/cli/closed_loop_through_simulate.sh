#!/usr/bin/env bash
# The closed loop through the app: simulate the seed tire from the exact integrals (two
# sweeps: longitudinal, then lateral sliding) with one effect injected, run contensou-identify,
# and check that the JSON report names exactly shape and that effect.
set -u
app="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fails=0
common=(--radius 0.087 --profile seed-tire --pressure 2.1e5 --friction 0.3 --kx 0.14
        --points 20 --noise-level 0.01 --seed 7 --time-step 0.5 --directions 0,1.5707963)
check() {
  local name="$1" expected="$2"
  shift 2
  "$app" simulate --out "$dir/$name.csv" "${common[@]}" "$@" > /dev/null || { echo "FAIL $name: simulate"; fails=$((fails + 1)); return; }
  "$app" "$dir/$name.csv" --radius 0.087 --profile seed-tire --pressure 2.1e5 \
    --json "$dir/$name.json" > /dev/null 2> "$dir/$name.err" || { echo "FAIL $name: identify"; fails=$((fails + 1)); return; }
  local got
  got=$(python3 -c "import json,sys; print(' '.join(sorted(json.load(open(sys.argv[1]))['accepted_effects'])))" "$dir/$name.json")
  if [ "$got" = "$expected" ]; then echo "ok   $name: $got"; else echo "FAIL $name: got '$got', expected '$expected'"; fails=$((fails + 1)); fi
}
check anisotropy "anisotropy shape" --kappa 0.8
check shift_y "pressure_shift_y shape" --ky 0.1
check speed "shape speed_dependence" --speed-drop 0.3 --speed-ref 5
check offset "channel_offset shape" --offset 0,15,0
check crosstalk "channel_crosstalk shape" --crosstalk 'Mz_Nm<-Fx_N=0.002'
# Longitudinal sliding only, anisotropy injected: anisotropy and a crosstalk into Mz explain
# the residual equally. The report must accept anisotropy or name it in "ambiguous_with" of the
# accepted step, and say so in the closing lines.
"$app" simulate --out "$dir/ambiguous.csv" --radius 0.087 --profile seed-tire --pressure 2.1e5 \
  --kappa 0.8 --points 60 --noise-level 0.01 --seed 3 > /dev/null
if "$app" "$dir/ambiguous.csv" --radius 0.087 --profile seed-tire --pressure 2.1e5 \
  --json "$dir/ambiguous.json" > "$dir/ambiguous.out" 2> "$dir/ambiguous.err" &&
  python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
ok = 'anisotropy' in r['accepted_effects'] or any(
    'anisotropy' in s['ambiguous_with'] for s in r['steps'] if s['accepted'])
sys.exit(0 if ok else 1)" "$dir/ambiguous.json" &&
  { grep -q "anisotropy" <(grep -E "^accepted effects" "$dir/ambiguous.out") ||
    grep -q "^AMBIGUOUS: .*anisotropy.*lateral sweep" "$dir/ambiguous.out"; }; then
  echo "ok   ambiguous: $(grep -E '^(accepted effects|AMBIGUOUS)' "$dir/ambiguous.out" | tr '\n' ' ')"
else
  echo "FAIL ambiguous: anisotropy neither accepted nor named"; fails=$((fails + 1))
fi
# Load-cell noise (sigma = 0.2 % of the peak + 2 % of |y|, simulate --noise load-cell): the loop
# keeps its effects and weights the final fit by the growing scale (noise_model affine).
"$app" simulate --out "$dir/load_cell.csv" --radius 0.087 --profile seed-tire --pressure 2.1e5 \
  --friction 0.3 --kx 0.14 --points 20 --seed 7 --time-step 0.5 --directions 0,1.5707963 \
  --noise load-cell --noise-level 0.002 --noise-growth 0.02 > /dev/null
if "$app" "$dir/load_cell.csv" --radius 0.087 --profile seed-tire --pressure 2.1e5 \
  --json "$dir/load_cell.json" > /dev/null 2> "$dir/load_cell.err" &&
  python3 -c "
import json, sys
r = json.load(open(sys.argv[1]))
sys.exit(0 if r['noise_model'] == 'affine' and r['accepted_effects'] == ['shape'] else 1)" \
    "$dir/load_cell.json"; then
  echo "ok   load_cell: shape, noise a + b|y|"
else
  echo "FAIL load_cell: the growing noise scale not chosen, or other effects"; fails=$((fails + 1))
fi
echo "$((7 - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
