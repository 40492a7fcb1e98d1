#!/usr/bin/env bash
# Regenerates the shimmy demo's pictures in docs/images from the app's own output, writes
# docs/images/shimmy-sources.json (for each picture the command and file it comes from, and the
# numbers of the default run it shows: tests/cli/doc_images.sh checks them against a fresh run)
# and docs/shimmy-results.md, every number the shimmy docs quote, with the commit, the machine
# and its load (scripts/shimmy_results.py; with --bench also bench/bench_shimmy's times).
# Usage: scripts/make-doc-images.sh [BUILD_DIR] [--bench]   (default ./build; a few minutes)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
bench="${2:-}"
shimmy="$build/apps/contensou-shimmy"
identify="$build/apps/contensou-identify"
images=docs/images
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sources="$tmp/sources.tsv"  # picture <TAB> command <TAB> file it is copied from
: > "$sources"

# copy_picture PICTURE FROM COMMAND
copy_picture() {
  [ -s "$2" ] || { echo "make-doc-images: $3 did not write $2" >&2; exit 1; }
  cp "$2" "$tmp/$1"
  printf '%s\t%s\t%s\n' "$1" "$3" "${2#"$tmp"/}" >> "$sources"
}

# The default run (the three scenarios) with its eigenvalue maps and overlays.
cmd="contensou-shimmy --map"
"$shimmy" --out "$tmp/default" --map > "$tmp/default.txt"
for picture in torsion torque spin forces energy; do
  copy_picture "shimmy_$picture.png" "$tmp/default/large-offset/$picture.png" "$cmd"
done
copy_picture shimmy_touchdown_torsion.png "$tmp/default/touchdown/torsion.png" "$cmd"

# Bifurcation diagrams of the large offset's braked slide: speed, offset, torsional damping.
cmd="contensou-shimmy --bifurcation --set structure.offset_m=0.45 --set scenario.forward_speed_mps=58"
"$shimmy" --out "$tmp/sweeps" --bifurcation --set structure.offset_m=0.45 \
  --set scenario.forward_speed_mps=58 > "$tmp/sweeps.txt"
for png in "$tmp"/sweeps/bifurcation_*.png; do
  copy_picture "$(basename "$png")" "$png" "$cmd"
done
for png in "$tmp"/default/map_*.png "$tmp"/default/overlay_*.png; do
  copy_picture "$(basename "$png")" "$png" "$cmd"
done

# Twin-wheel gear: speed x wheel spacing, braked slide.
twin_map='[{"x": {"parameter": "scenario.forward_speed_mps", "from": 30, "to": 90, "points": 50},
  "y": {"parameter": "structure.wheel_spacing_m", "from": 0, "to": 1.2, "points": 50}}]'
cmd="contensou-shimmy --map --set maps=<speed x structure.wheel_spacing_m>"
"$shimmy" --out "$tmp/twin" --map --set "maps=$twin_map" > /dev/null
for m in coupled von_schlippe; do
  copy_picture "map_forward_speed_mps_wheel_spacing_m_braked_slide_$m.png" \
    "$tmp/twin/map_forward_speed_mps_wheel_spacing_m_braked_slide_$m.png" "$cmd"
done

# Carcass compliance: the offset map with the estimated carcass stiffnesses.
offset_map='[{"x": {"parameter": "scenario.forward_speed_mps", "from": 30, "to": 90, "points": 50},
  "y": {"parameter": "structure.offset_m", "from": 0, "to": 0.5, "points": 50}}]'
carcass=(--set structure.carcass_lateral_stiffness_n_per_m=8.5e5
  --set structure.carcass_torsional_stiffness_nm_per_rad=7.8e4)
cmd="contensou-shimmy --map ${carcass[*]} --set maps=<speed x structure.offset_m>"
"$shimmy" --out "$tmp/carcass" --map "${carcass[@]}" --set "maps=$offset_map" > /dev/null
for m in coupled decoupled; do
  copy_picture "map_forward_speed_mps_offset_m_braked_slide_${m}_carcass.png" \
    "$tmp/carcass/map_forward_speed_mps_offset_m_braked_slide_$m.png" "$cmd"
done

# Fore-aft bending at 13 Hz: gear walk in the braked slide.
cmd="contensou-shimmy --scenario braked-slide --set structure.fore_aft_stiffness_n_per_m=2e6"
"$shimmy" --out "$tmp/fore_aft" --scenario braked-slide \
  --set structure.fore_aft_stiffness_n_per_m=2e6 > /dev/null
copy_picture shimmy_fore_aft_gear_walk.png "$tmp/fore_aft/braked-slide/fore_aft.png" "$cmd"

# A rig's file: three loads, two sliding directions, 10^4 rows; the fit drawn per sweep.
rig=(--radius 0.087 --profile seed-tire --pressure 2.1e5 --kx 0.14 --points 1667
  --directions 0,1.5708 --normal-load 3000,4500,6000 --noise additive-gaussian --noise-level 0.01)
"$identify" simulate --out "$tmp/rig.csv" "${rig[@]}" > /dev/null
"$identify" "$tmp/rig.csv" --radius 0.087 --profile seed-tire --plots "$tmp/rig" > /dev/null
cmd="contensou-identify <simulate ${rig[*]}> --radius 0.087 --profile seed-tire --plots"
copy_picture fit_rig_Mz_Nm.png "$tmp/rig/fit_Mz_Nm.png" "$cmd"

# The seed tire's identified law as the tire: probability of shimmy over the offset map.
"$identify" data/seed_tire_diagrams.csv --radius 0.087 --normal-load 4480 --no-loop \
  --json "$tmp/report.json" > /dev/null
cmd="contensou-shimmy --tire <contensou-identify data/seed_tire_diagrams.csv --radius 0.087 --normal-load 4480 --no-loop --json> --map --set maps=<speed x structure.offset_m>"
"$shimmy" --out "$tmp/tire" --tire "$tmp/report.json" --map --set "maps=$offset_map" > /dev/null
copy_picture prob_forward_speed_mps_offset_m_braked_slide_coupled.png \
  "$tmp/tire/prob_forward_speed_mps_offset_m_braked_slide_coupled.png" "$cmd"

# The manifest: every picture's source, and the default run's numbers the pictures show.
python3 - "$sources" "$tmp/default/summary.json" "$tmp/manifest.json" <<'PY'
import json, sys
pictures = {}
for line in open(sys.argv[1]):
    name, command, source = line.rstrip("\n").split("\t")
    pictures[name] = {"command": command, "from": source}
summary = json.load(open(sys.argv[2]))
numbers = {}
for name, s in summary["scenarios"].items():
    for model, run in s["summary"]["models"].items():
        numbers[f"{name}/{model}"] = {
            "shimmy": run["shimmy"],
            "growth_rate_per_s": run["growth_rate_per_s"],
            "eigenvalue_growth_rate_per_s": run["stability"][s["phase"]]["growth_rate_per_s"]}
maps = {m["png"]: {"shimmy_cells": m["shimmy_cells"], "not_computed_cells": m["not_computed_cells"]}
        for m in summary.get("maps", [])}
json.dump({"generated_by": "scripts/make-doc-images.sh", "pictures": pictures,
           "default_run": numbers, "maps": maps}, open(sys.argv[3], "w"), indent=1)
PY
# The numbers of the docs, from these runs (and the benchmark when asked for).
if [ "$bench" = "--bench" ]; then
  "$build/bench/bench_shimmy" --benchmark_repetitions=3 --benchmark_format=json \
    > "$tmp/bench.json"
fi
python3 scripts/shimmy_results.py "$tmp/shimmy-results.md" "$tmp/default" "$tmp/sweeps" \
  "$tmp/tire" ${bench:+"$tmp/bench.json"}
# Replace the pictures only when every one was made.
while IFS=$'\t' read -r name _ _; do mv "$tmp/$name" "$images/$name"; done < "$sources"
mv "$tmp/manifest.json" "$images/shimmy-sources.json"
mv "$tmp/shimmy-results.md" docs/shimmy-results.md
echo "make-doc-images: $(wc -l < "$sources") pictures and $images/shimmy-sources.json"
