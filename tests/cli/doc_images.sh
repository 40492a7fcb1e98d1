#!/usr/bin/env bash
# The shimmy pictures in docs/images are in sync with the app: each one the README and docs show
# is listed in docs/images/shimmy-sources.json (written by scripts/make-doc-images.sh with the
# command it came from), each listed one is there, and a fresh default run gives the verdicts and
# growth rates the manifest recorded when the pictures were made.
# Usage: doc_images.sh PATH/TO/contensou-shimmy SOURCE_DIR
set -u
app="$1"
root="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$app" --out "$dir/run" > /dev/null 2> "$dir/err" || { echo "FAIL default run: $(cat "$dir/err")"; exit 1; }
python3 - "$root" "$dir/run/summary.json" <<'PY'
import json, os, re, sys
root, fresh = sys.argv[1], json.load(open(sys.argv[2]))
images = os.path.join(root, "docs", "images")
manifest = json.load(open(os.path.join(images, "shimmy-sources.json")))
fails = []
shown = set()
for doc in ["README.md"] + [os.path.join("docs", f) for f in os.listdir(os.path.join(root, "docs"))
                            if f.endswith(".md")]:
    for name in re.findall(r"images/((?:shimmy_|map_|prob_|overlay_|bifurcation_)[^)\s]+\.png)", open(os.path.join(root, doc)).read()):
        shown.add(name)
        if name not in manifest["pictures"]:
            fails.append(f"{doc} shows {name}, which scripts/make-doc-images.sh does not make")
for name in manifest["pictures"]:
    if not os.path.exists(os.path.join(images, name)):
        fails.append(f"{name} is in the manifest but not in docs/images")
for key, want in manifest["default_run"].items():
    scenario, model = key.split("/")
    s = fresh["scenarios"][scenario]
    run = s["summary"]["models"][model]
    got = {"shimmy": run["shimmy"], "growth_rate_per_s": run["growth_rate_per_s"],
           "eigenvalue_growth_rate_per_s": run["stability"][s["phase"]]["growth_rate_per_s"]}
    if got["shimmy"] != want["shimmy"]:
        fails.append(f"{key}: shimmy {got['shimmy']} now, {want['shimmy']} in the pictures")
    for k in ["growth_rate_per_s", "eigenvalue_growth_rate_per_s"]:
        a, b = got[k], want[k]
        if (a is None) != (b is None) or (a is not None and abs(a - b) > 0.02 + 0.02 * abs(b)):
            fails.append(f"{key}: {k} {a} now, {b} in the pictures")
for f in fails:
    print("FAIL " + f)
print(f"{len(shown)} pictures shown, {len(manifest['pictures'])} made by the script, "
      f"{len(manifest['default_run'])} runs compared: {len(fails)} problems")
sys.exit(1 if fails else 0)
PY
