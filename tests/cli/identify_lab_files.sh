#!/usr/bin/env bash
# contensou-identify on files written the way labs write them (issue 10, item 4): the same
# diagrams (with pure-spin, pure-slide and rest rows) as Excel writes them (UTF-8 BOM, CRLF,
# quoted header, trailing empty columns), as a European Excel writes them (';' and decimal
# comma), and with a tabulated pressure profile that has a kink, from a BOM+CRLF file.
# Each must give the same report as the plain file. Usage: identify_lab_files.sh APP DATA_DIR
set -u
app="$1"
plain="$2/seed_tire_edge_rows.csv"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fails=0
run() {  # run NAME DATA [ARGS...]: report in $dir/NAME.json, without the data path
  local name="$1" data="$2"
  shift 2
  if ! "$app" "$data" --radius 0.087 --profile seed-tire --pressure 2.1e5 --no-loop \
    --json "$dir/$name.json" "$@" > "$dir/$name.out" 2> "$dir/$name.err"; then
    echo "FAIL $name: $(cat "$dir/$name.err")"
    fails=$((fails + 1))
    return 1
  fi
  grep -v "$data" "$dir/$name.json" > "$dir/$name.cmp"
}
run plain "$plain"

# Excel: BOM, CRLF, quoted header names, two trailing empty columns, a blank row of separators.
excel="$dir/excel.csv"
{
  printf '\357\273\277'
  grep -v '^#' "$plain" | awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) $i = "\"" $i "\"" }
    { OFS = ","; $1 = $1; printf "%s,,\r\n", $0 } END { printf ",,,,,,,,\r\n" }'
} > "$excel"
# European Excel: ';' between cells, decimal comma, cells padded with spaces.
euro="$dir/euro.csv"
grep -v '^#' "$plain" | sed -e 's/,/ ; /g' -e 's/\./,/g' > "$euro"
for v in excel euro; do
  if run "$v" "$dir/$v.csv"; then
    if cmp -s "$dir/plain.cmp" "$dir/$v.cmp"; then
      echo "ok   $v: same report as the plain file"
    else
      echo "FAIL $v: report differs from the plain file"
      diff "$dir/plain.cmp" "$dir/$v.cmp" | head -5
      fails=$((fails + 1))
    fi
  fi
done

# A tabulated profile with a kink at rho = 0.8 (as a finite-element table arrives), BOM + CRLF,
# through the closed loop: a report, no non-finite number.
{
  printf '\357\273\277rho,pressure_Pa\r\n'
  awk 'BEGIN { for (i = 0; i <= 40; ++i) { r = i / 40;
    p = r < 0.8 ? 2.1e5 * (1 - 0.5 * r * r) : 2.1e5 * (0.68 - 2 * (r - 0.8));
    printf "%.4f,%.6g\r\n", r, p } }'
} > "$dir/profile.csv"
if "$app" "$plain" --radius 0.087 --profile "$dir/profile.csv" --json "$dir/tab.json" \
  > "$dir/tab.out" 2> "$dir/tab.err" && ! grep -qiE 'nan|inf' "$dir/tab.json"; then
  echo "ok   tabulated profile with a kink: report written, all numbers finite"
else
  echo "FAIL tabulated profile: $(cat "$dir/tab.err")"
  fails=$((fails + 1))
fi
# Noisy film data (the same table with 3 % scatter) through --profile-smoothing: a smooth
# Chebyshev series in rho^2, its residual in the report, and a refusal without a profile CSV.
awk -F, 'NR == 1 { print; next } { srand(NR); print $1 "," $2 * (1 + 0.03 * (rand() - 0.5) * 3.46) }' \
  "$dir/profile.csv" | tr -d '\r' | sed '1s/^\xEF\xBB\xBF//' > "$dir/film.csv"
if "$app" "$plain" --radius 0.087 --profile "$dir/film.csv" --profile-smoothing 6 \
  --json "$dir/film.json" > "$dir/film.out" 2> "$dir/film.err" &&
  grep -q '"profile_fit_rms_residual_Pa"' "$dir/film.json" &&
  grep -q "^profile: .*Chebyshev series in rho^2 (6 terms) fitted to 41 points (fit residual: rms" "$dir/film.out"; then
  echo "ok   noisy film data smoothed: $(grep -m1 '^profile:' "$dir/film.out")"
else
  echo "FAIL --profile-smoothing: $(cat "$dir/film.err")"
  fails=$((fails + 1))
fi
if "$app" "$plain" --radius 0.087 --profile seed-tire --profile-smoothing 6 > /dev/null 2> "$dir/s.err" ||
  ! grep -q "needs --profile with a CSV file" "$dir/s.err"; then
  echo "FAIL --profile-smoothing without a CSV: $(cat "$dir/s.err")"
  fails=$((fails + 1))
else
  echo "ok   --profile-smoothing without a CSV is refused"
fi

# The same diagrams with units a lab uses: km/h, rpm, kN and kN m in brackets; a units row
# under bare names; other names mapped with --columns. The fit must be the plain file's (to the
# print precision of the converted values), and the report must name every conversion.
lab() {  # lab NAME HEADER UNITS_ROW: the plain data as a lab writes them, in $dir/NAME.csv
  python3 - "$plain" "$dir/$1.csv" "$2" "$3" <<'PY'
import math, sys
src, out, header, units = sys.argv[1:]
to_si = {"km/h": 1 / 3.6, "rpm": 2 * math.pi / 60, "kN": 1e3, "kN m": 1e3, "m/s": 1, "rad/s": 1,
         "N": 1, "N m": 1, "s": 1, "deg/s": math.pi / 180}
names = header.split(",")
cell_units = units.split(",") if units else [n[n.index("[") + 1:-1] for n in names]
rows = [l.strip().split(",") for l in open(src) if not l.startswith("#")][1:]
with open(out, "w") as f:
    f.write(header + "\n" + (units + "\n" if units else ""))
    for r in rows:
        f.write(",".join("" if c == "" else repr(float(c) / to_si[u]) for c, u in zip(r, cell_units)) + "\n")
PY
}
same_fit() {  # same_fit NAME: base parameters within 1e-7 of the plain file's, conversions named
  python3 - "$dir/plain.json" "$dir/$1.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
pa = {k: p["value"] for k, p in a["base"]["params"].items()}
pb = {k: p["value"] for k, p in b["base"]["params"].items()}
bad = [k for k in pa if abs(pa[k] - pb[k]) > 1e-7 * (1 + abs(pa[k]))]
if bad or not b["input"].get("columns_converted"):
    sys.exit(f"parameters differ: {bad}" if bad else "no columns_converted in the report")
PY
}
lab brackets "vx [km/h],vy [km/h],omega [rpm],Fx [kN],Fy [kN],Mz [kN m],t [s]" ""
lab units_row "vx,vy,omega,Fx,Fy,Mz,t" "km/h,m/s,deg/s,N,kN,N m,s"
lab renamed "Speed [km/h],Lateral [km/h],Wheel rate [rpm],Long. force [kN],Side force [kN],Torque [kN m],Time [s]" ""
renames="vx=Speed,vy=Lateral,omega=Wheel rate,Fx=Long. force,Fy=Side force,Mz=Torque,t=Time"
for v in brackets units_row renamed; do
  extra=()
  [ "$v" = renamed ] && extra=(--columns "$renames")
  if run "$v" "$dir/$v.csv" "${extra[@]}" && msg=$(same_fit "$v" 2>&1) &&
    grep -q "^column: omega_radps from" "$dir/$v.out"; then
    echo "ok   $v: same fit as the plain file, $(grep -c '^column:' "$dir/$v.out") conversions named"
  else
    echo "FAIL $v: ${msg:-no 'column:' line in the report}"
    fails=$((fails + 1))
  fi
done
echo "$fails failed"
[ "$fails" -eq 0 ]
