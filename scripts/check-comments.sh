#!/usr/bin/env bash
# Code comments state what the code does and why, not its history: no issue numbers ("issue 12",
# "#12"), no dates (2024-05), no benchmark history (timings such as "12.9 s for 10^5 knots",
# "took", "previously", "speed-up", "was 3e-15 before"). The history belongs in git and
# CHANGELOG.md, the figures in docs/speed.md and docs/accuracy.md.
# Usage: scripts/check-comments.sh [PATH...]   (default: include src apps plugins python/src)
# Prints file:line: text for every hit and fails if there is one.
set -euo pipefail
cd "$(dirname "$0")/.."
paths=("$@")
((${#paths[@]})) || paths=(include src apps plugins python/src)

# The comment part of a line: from the first // that does not follow a ':' (a URL), or a line of
# a /* ... */ block that starts with '*'.
comment='(?:(?<!:)//|^\s*/?\*)'
patterns=(
  'issue\s*[0-9]'                                         # issue numbers
  '(?<![\w&])#[0-9]+'                                     # #12
  '\b20[0-9]{2}-[0-9]{2}\b'                               # dates
  '\b[0-9]+(?:\.[0-9]+)?\s?(?:s|ms|us|min)\s+(?:for|on)\b'  # timings: "0.3 s for 10^4 knots"
  '\b(?:took|previously|formerly|used to be|speed-?ups?|faster than|slower than)\b'
  '\b(?:was|were)\s+(?:[0-9]|O\()'                        # "was 3e-15", "was O(n log n)"
  '\bbefore\s+(?:that|them|were|was)\b'                   # "the knot terms before that"
)
joined=$(IFS='|'; echo "${patterns[*]}")
status=0
while IFS= read -r -d '' file; do
  if grep -nP -i "${comment}.*(?:${joined})" "$file" >/tmp/check-comments.$$ 2>/dev/null; then
    sed "s|^|$file:|" /tmp/check-comments.$$
    status=1
  fi
done < <(find "${paths[@]}" -type f \( -name '*.hpp' -o -name '*.cpp' -o -name '*.h' -o -name '*.inc' \) -print0 | sort -z)
rm -f /tmp/check-comments.$$
if ((status)); then
  echo "check-comments: issue numbers, dates or benchmark history in code comments (above)" >&2
fi
exit $status
