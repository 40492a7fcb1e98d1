#!/usr/bin/env bash
# docs/shimmy.md's table of configuration keys is the app's key table (apps/shimmy/config_keys.cpp):
# the lines between its markers are what `contensou-shimmy --print-keys` prints, so that the
# documentation cannot drift from the keys the app reads, their units, ranges and defaults.
# Usage: shimmy_keys_doc.sh PATH/TO/contensou-shimmy PATH/TO/docs/shimmy.md
set -u
app="$1"
doc="$2"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
"$app" --print-keys > "$dir/app.md" || { echo "FAIL --print-keys"; exit 1; }
sed -n '/^<!-- keys: begin/,/^<!-- keys: end/p' "$doc" | sed '1d;$d' > "$dir/doc.md"
[ -s "$dir/doc.md" ] || { echo "FAIL no key table between the markers in $doc"; exit 1; }
if ! diff -u "$dir/doc.md" "$dir/app.md"; then
  echo "FAIL $doc's key table differs from contensou-shimmy --print-keys (above: - doc, + app);"
  echo "     paste the app's table between the markers"
  exit 1
fi
echo "ok   $doc's key table is the app's ($(wc -l < "$dir/app.md") lines)"
