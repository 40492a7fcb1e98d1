#!/usr/bin/env bash
# Fails if a function in the library, the apps, the plugin or the bindings is longer than 80
# lines, has a cyclomatic complexity over 25 or takes more than 8 parameters (lizard, from
# python/requirements.txt; the limits of docs/architecture.md). Prints the offenders.
# Usage: scripts/check-complexity.sh [lizard executable]   (default: .venv/bin/lizard)
set -euo pipefail
cd "$(dirname "$0")/.."
lizard=${1:-.venv/bin/lizard}
[ -x "$lizard" ] || { echo "complexity: $lizard not found (scripts/setup.sh installs it)" >&2; exit 1; }
dirs=(include src apps plugins python/src)
if ! "$lizard" --CCN 25 --length 80 --arguments 8 --warnings_only "${dirs[@]}"; then
  echo "complexity: the functions above exceed 80 lines, complexity 25 or 8 parameters" >&2
  exit 1
fi
count=$("$lizard" --CCN 25 --length 80 --arguments 8 "${dirs[@]}" |
  awk '/^Total nloc/ {getline; getline; print $5}')
echo "complexity: ${count:-all} functions within 80 lines, complexity 25, 8 parameters"
