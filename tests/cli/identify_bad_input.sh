#!/usr/bin/env bash
# contensou-identify on bad input: a one-line error on stderr naming the problem, a non-zero
# exit, and no report file. Usage: identify_bad_input.sh PATH/TO/contensou-identify
set -u
app="$1"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fails=0
good="$dir/good.csv"
"$app" simulate --out "$good" --points 12 --noise-level 0.01 > /dev/null || { echo "simulate failed"; exit 1; }

# expect NAME EXPECTED_STDERR_FRAGMENT ARGS...
expect() {
  local name="$1" fragment="$2"
  shift 2
  rm -f "$dir/report.json"
  "$@" > "$dir/out" 2> "$dir/err"
  local rc=$?
  local lines
  lines=$(wc -l < "$dir/err")
  if [ "$rc" -eq 0 ] || ! grep -qF -- "$fragment" "$dir/err" || [ "$lines" -ne 1 ] || [ -e "$dir/report.json" ]; then
    echo "FAIL $name: rc=$rc, stderr ($lines lines): $(cat "$dir/err")"
    fails=$((fails + 1))
  else
    echo "ok   $name: $(cat "$dir/err")"
  fi
}

printf 'vx_mps,vy_mps,omega_radps,Fx_N\n1,0,10,-5\n1,0,abc,-5\n' > "$dir/malformed.csv"
expect "malformed cell" "malformed.csv:3: column 'omega_radps' (3): not a number: 'abc'" \
  "$app" "$dir/malformed.csv" --radius 0.1 --json "$dir/report.json"
printf 'vx_mps,omega_radps,Fx_N\n1,10,-5\n' > "$dir/missing.csv"
expect "missing column" "missing required column 'vy_mps'" \
  "$app" "$dir/missing.csv" --radius 0.1 --json "$dir/report.json"
printf 'vx_mps,vy_mps,omega_radps,Fx_N\n1,0,10,-5\n1,0,10,inf\n' > "$dir/nonfinite.csv"
expect "non-finite value" "nonfinite.csv:3: column 'Fx_N' (4): non-finite value 'inf'" \
  "$app" "$dir/nonfinite.csv" --radius 0.1 --json "$dir/report.json"
printf 'vx_mps,vy_mps,omega_radps,Fx_N\n1,0,10,-5\n2,0,10,-6\n' > "$dir/few.csv"
expect "fewer points than parameters" \
  "data = 2 measured values: too little data: the fit needs at least 7 (5 free parameters + 1 estimated noise scales + 1)" \
  "$app" "$dir/few.csv" --radius 0.1 --json "$dir/report.json"
printf 'vx_mps,vy_mps,omega_radps,Fx_N\n1,0,10,-5\n2,0,10,-6\n3,0,10,-7\n4,0,10,-7\n5,0,10,-7\n6,0,10,-7\n' > "$dir/six.csv"
expect "one value short" "too little data: the fit needs at least 7" \
  "$app" "$dir/six.csv" --radius 0.1 --json "$dir/report.json"
expect "failed evaluation, law" \
  "fit of the fractional law (free: F0_N, a, M0_Nm, m, kx) failed: Residual and Jacobian evaluation failed" \
  "$app" "$good" --radius 0.087 --no-loop --test-failing-point 3 --json "$dir/report.json"
expect "failed evaluation, loop" "failed: Residual and Jacobian evaluation failed" \
  "$app" "$good" --radius 0.087 --test-failing-point 0 --json "$dir/report.json"
printf 'vx_mps,vy_mps,omega_hz,Fx_N\n1,0,10,-5\n' > "$dir/unit.csv"
expect "other unit" "column 'omega_hz' (3): unit 'hz' of omega is not one this reader converts (omega: rad/s, deg/s, rpm)" \
  "$app" "$dir/unit.csv" --radius 0.1 --json "$dir/report.json"
printf 'vx_mps,vy_mps,omega_radps,Fxx_N\n1,0,10,-5\n' > "$dir/case.csv"
expect "misspelt channel" "column 'Fxx_N' (4) is not a column this reader knows: did you mean 'Fx_N'?" \
  "$app" "$dir/case.csv" --radius 0.1 --json "$dir/report.json"
{ echo 'vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm'; for i in 1 2 3 4 5 6 7 8; do echo '0,0,0,0.1,-0.2,0'; done; } > "$dir/rest.csv"
expect "every row at rest" "every row is at rest (v = omega = 0)" \
  "$app" "$dir/rest.csv" --radius 0.1 --json "$dir/report.json"
{ echo 'vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm'; for i in 1 2 3 4 5 6 7 8; do echo "1e200,0,$i,-1000,0,-1"; done; } > "$dir/units.csv"
expect "speeds beyond any rig" "units.csv:2, vx = 1e+200 m/s" \
  "$app" "$dir/units.csv" --radius 0.087 --no-loop --json "$dir/report.json"
printf 'rho,pressure_Pa\n0,1e5\n0.5,-3e4\n1,1e5\n' > "$dir/dip.csv"
expect "negative profile" "add --profile-clip to clip it at zero" \
  "$app" "$good" --radius 0.087 --profile "$dir/dip.csv" --json "$dir/report.json"
expect "smoothing with too many terms" "--profile-smoothing 6 (" \
  "$app" "$good" --radius 0.087 --profile "$dir/dip.csv" --profile-smoothing 6 --json "$dir/report.json"
printf '1,0,10,-5\n2,0,10,-6\n' > "$dir/noheader.csv"
expect "no header" "the first row holds numbers, not column names" \
  "$app" "$dir/noheader.csv" --radius 0.1 --json "$dir/report.json"
expect "zero radius" "--radius = 0: must be positive" "$app" "$good" --radius 0 --json "$dir/report.json"
expect "no radius" "--radius is required" "$app" "$good" --json "$dir/report.json"
expect "negative radius" "radius = -0.1:" "$app" "$good" --radius -0.1 --json "$dir/report.json"
expect "negative load" "normal-load = -4000" \
  "$app" "$good" --radius 0.087 --normal-load -4000 --json "$dir/report.json"
expect "unreadable profile" "no such file" \
  "$app" "$good" --radius 0.087 --profile "$dir/nope.csv" --json "$dir/report.json"
printf 'rho,pressure_Pa\n0,1\n0.5,x\n1,1\n' > "$dir/badprofile.csv"
expect "malformed profile" "badprofile.csv:3: column 'pressure_Pa' (2): not a number: 'x'" \
  "$app" "$good" --radius 0.087 --profile "$dir/badprofile.csv" --json "$dir/report.json"
expect "missing data file" "cannot open file" \
  "$app" "$dir/absent.csv" --radius 0.087 --json "$dir/report.json"
expect "bad --fix" "expected NAME=VALUE" \
  "$app" "$good" --radius 0.087 --fix a --json "$dir/report.json"
expect "unknown --fix" "--fix bogus: no such parameter" \
  "$app" "$good" --radius 0.087 --fix bogus=1 --json "$dir/report.json"

# And the good file gives a complete report.
if "$app" "$good" --radius 0.087 --normal-load 4535 --json "$dir/report.json" > /dev/null &&
   grep -q '"accepted_effects"' "$dir/report.json" && grep -q '"F0_N"' "$dir/report.json"; then
  echo "ok   good input writes the report"
else
  echo "FAIL good input"
  fails=$((fails + 1))
fi
echo "$((23 - fails)) passed, $fails failed"
[ "$fails" -eq 0 ]
