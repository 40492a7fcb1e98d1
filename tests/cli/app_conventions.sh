#!/usr/bin/env bash
# The conventions every app keeps (apps/common/cli.hpp): --version prints "NAME VERSION" (the
# CMake project's), --help documents the exit statuses, and the statuses are 0 on success,
# 2 on a usage error (the nearest option named) and 1 on a failure (a missing input file too).
# Usage: app_conventions.sh VERSION IDENTIFY SHIMMY ENGINE_COEFFICIENTS
set -u
version=$1
identify=$2
shimmy=$3
engines=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failed=0

# expect STATUS DESCRIPTION COMMAND...: runs the command, checks its exit status.
expect() {
  local want=$1 what=$2
  shift 2
  "$@" > out.txt 2> err.txt
  local rc=$?
  if [ "$rc" -ne "$want" ]; then
    echo "FAIL: $what: exit status $rc, expected $want"
    sed 's/^/  | /' err.txt | head -5
    failed=1
  fi
}

for pair in "contensou-identify:$identify" "contensou-shimmy:$shimmy" \
            "contensou-engine-coefficients:$engines"; do
  name=${pair%%:*}
  app=${pair#*:}
  expect 0 "$name --version" "$app" --version
  if [ "$(cat out.txt)" != "$name $version" ]; then
    echo "FAIL: $name --version printed '$(cat out.txt)', expected '$name $version'"
    failed=1
  fi
  expect 0 "$name --help" "$app" --help
  grep -q "Exit status: 0 success, 1 failure" out.txt ||
    { echo "FAIL: $name --help does not document the exit statuses"; failed=1; }
  required=()  # CLI11 reports a missing required option before an unknown one
  [ "$name" = contensou-engine-coefficients ] && required=(--radius 0.05 --friction 0.5)
  expect 2 "$name with an unknown option" "$app" "${required[@]}" --no-such-option
  grep -q "no-such-option" err.txt ||
    { echo "FAIL: $name: the usage error does not name the option"; failed=1; }
done
expect 2 "contensou-identify --radius without a value" "$identify" data.csv --radius
expect 2 "contensou-engine-coefficients without --radius" "$engines" --friction 0.5
expect 1 "contensou-identify on a missing file" "$identify" no-such-file.csv --radius 0.087
expect 1 "contensou-engine-coefficients with a negative radius" "$engines" --radius -1 --friction 0.5
echo '{"scenario": ' > broken.json
expect 1 "contensou-shimmy with a broken configuration" "$shimmy" --print-config --config broken.json
expect 1 "contensou-shimmy with a configuration that does not exist" "$shimmy" --config no.json
expect 0 "contensou-engine-coefficients on a valid patch" "$engines" --radius 0.05 --friction 0.5
# A typo is named with the nearest option, before any missing required option.
expect 2 "contensou-engine-coefficients with a misspelt option" "$engines" --radiuss 0.1
grep -q "unknown option --radiuss (did you mean --radius?)" err.txt ||
  { echo "FAIL: the typo --radiuss is not named with --radius: $(cat err.txt)"; failed=1; }
expect 2 "contensou-identify with a word not among the allowed ones" "$identify" data.csv \
  --radius 0.087 --loss hubber
grep -q "none, huber, cauchy" err.txt ||
  { echo "FAIL: --loss hubber does not name the allowed values: $(cat err.txt)"; failed=1; }
exit $failed
