#!/usr/bin/env bash
# Kills and races, bounded (ctest reliability.kill_and_race): what an unlucky operator does.
#   kill_and_race.sh IDENTIFY SHIMMY DATA_CSV [ROUNDS]
# 1. `identify simulate` killed (SIGKILL) at random moments: the CSV is the previous one or a
#    whole new one, never a partial one.
# 2. Two fits writing --json to one path at once, ROUNDS times: each time the file is whole JSON.
# 3. Two shimmy runs into one --out folder: the second is refused while the first runs.
# 4. shimmy killed while it draws: every PNG present is whole (ends with the IEND chunk).
# 5. Two shimmy runs one after the other into one folder: the second removes the first's files
#    it did not rewrite (a scenario folder), keeps a file the user put there, and a third run
#    killed half-way removes nothing.
set -euo pipefail
identify=$(realpath "$1") shimmy=$(realpath "$2") data=$(realpath "$3") rounds=${4:-8}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

echo "== 1. simulate killed at random moments ($rounds rounds)"
"$identify" simulate --out sim.csv --points 20000 --radius 0.087 >/dev/null
whole=$(wc -l <sim.csv)
for ((i = 0; i < rounds; i++)); do
  "$identify" simulate --out sim.csv --points 20000 --radius 0.087 --seed $((i + 2)) >/dev/null &
  pid=$!
  sleep "0.0$((RANDOM % 9 + 1))"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  lines=$(wc -l <sim.csv)
  [ "$lines" -eq "$whole" ] || fail "sim.csv has $lines lines after a kill, a whole file has $whole"
  [ "$(tail -c 1 sim.csv | od -An -c | tr -d ' ')" = '\n' ] || fail "sim.csv ends mid-line"
done
rm -f .sim.csv.*  # the temporary files of killed runs (hidden, never the real name)

echo "== 2. two fits into one --json path ($rounds rounds)"
for ((i = 0; i < rounds; i++)); do
  "$identify" "$data" --radius 0.087 --no-loop --json r.json >/dev/null &
  a=$!
  "$identify" "$data" --radius 0.087 --no-loop --json r.json >/dev/null &
  b=$!
  wait "$a" || fail "first fit failed"
  wait "$b" || fail "second fit failed"
  python3 -c "import json; json.load(open('r.json'))" || fail "r.json is not whole JSON"
done

echo "== 3. two shimmy runs into one folder"
"$shimmy" --scenario touchdown --out twice >first.log 2>&1 &
first=$!
sleep 0.5
if "$shimmy" --scenario touchdown --out twice >second.log 2>&1; then
  kill -0 "$first" 2>/dev/null && fail "a second run wrote into a folder the first was writing"
else
  grep -q "another run is writing into this output folder" second.log ||
    fail "second run failed without naming the lock: $(cat second.log)"
fi
wait "$first" || fail "the first shimmy run failed: $(tail -3 first.log)"
python3 -c "import json; json.load(open('twice/summary.json'))" || fail "summary.json not whole"

echo "== 4. shimmy killed while it draws"
for ((i = 0; i < 3; i++)); do
  "$shimmy" --scenario touchdown --out killed >/dev/null 2>&1 &
  pid=$!
  sleep "$((i + 1)).$((RANDOM % 9))"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  for png in killed/*/*.png killed/*.png; do
    [ -e "$png" ] || continue
    [ "$(tail -c 8 "$png" | od -An -tx1 | tr -d ' \n')" = "49454e44ae426082" ] ||
      fail "$png is truncated after a kill"
  done
done
echo "== 5. runs one after the other into one folder"
"$shimmy" --scenario touchdown --out seq >/dev/null 2>&1 || fail "shimmy --scenario touchdown failed"
[ -d seq/touchdown ] || fail "no seq/touchdown after the first run"
echo "mine" >seq/notes.txt
"$shimmy" --scenario braked-slide --out seq >second.log 2>&1 || fail "second run: $(cat second.log)"
[ -e seq/touchdown ] && fail "the first run's seq/touchdown is still there after the second run"
grep -q "removed .* file(s) an earlier run had written" second.log || fail "no word on removed files"
[ "$(cat seq/notes.txt)" = mine ] || fail "the user's seq/notes.txt was touched"
"$shimmy" --scenario touchdown --out seq >/dev/null 2>&1 &
pid=$!
sleep 0.3
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
[ -d seq/braked-slide ] || fail "a killed run removed the previous run's files"
echo "kill_and_race: every output whole or absent, the second run refused, stale files removed"
