#!/usr/bin/env bash
# Kills and races, bounded (ctest reliability.kill_and_race): what an unlucky operator does.
#   kill_and_race.sh IDENTIFY SHIMMY DATA_CSV [ROUNDS]
# 1. `identify simulate` killed (SIGKILL) at random moments: the CSV is the previous one or a
#    whole new one, never a partial one.
# 2. Two fits writing --json to one path at once, ROUNDS times: each time the file is whole JSON.
# 3. Two shimmy runs into one --out folder: the second is refused while the first runs.
# 4. shimmy killed while it draws: every PNG present is whole (ends with the IEND chunk).
# 5. Two shimmy runs one after the other into one folder: the second removes the first's files
#    it did not rewrite (a scenario folder); a file the user put there makes the next run refuse
#    the folder, the file untouched; a third run killed half-way removes nothing, and the run
#    after it cleans the killed run's temporary files.
# 6. A file another process writes into the folder during a run is not the run's: the next run
#    refuses the folder, naming it, and removes nothing (identify --plots).
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
"$shimmy" --scenario braked-slide --out seq >second.log 2>&1 && fail "a folder with the user's notes.txt was taken"
grep -q "holds files no contensou run wrote ('notes.txt')" second.log || fail "refused without naming notes.txt: $(cat second.log)"
[ "$(cat seq/notes.txt)" = mine ] || fail "the user's seq/notes.txt was touched"
[ -d seq/touchdown ] || fail "a refused run removed the previous run's files"
rm seq/notes.txt
"$shimmy" --scenario braked-slide --out seq >second.log 2>&1 || fail "second run: $(cat second.log)"
[ -e seq/touchdown ] && fail "the first run's seq/touchdown is still there after the second run"
grep -q "removed .* file(s) an earlier run had written" second.log || fail "no word on removed files"
"$shimmy" --scenario touchdown --out seq >/dev/null 2>&1 &
pid=$!
sleep 1.5
kill -9 "$pid" 2>/dev/null || true
wait "$pid" 2>/dev/null || true
[ -d seq/braked-slide ] || fail "a killed run removed the previous run's files"
"$shimmy" --scenario touchdown --out seq >third.log 2>&1 || fail "the run after a killed one: $(cat third.log)"
leftover=$(find seq -name '.*.contensou-tmp-*' | head -3)
[ -z "$leftover" ] || fail "temporary files of the killed run left: $leftover"
[ -e seq/braked-slide ] && fail "the braked-slide folder of an earlier run is still there"

echo "== 6. a file another process writes during a run"
"$identify" "$data" --radius 0.087 --plots mf >/dev/null 2>&1 &
pid=$!
sleep 0.5
mkdir -p mf/other && echo x >mf/other/n.txt
wait "$pid" || fail "the fit with --plots mf failed"
"$identify" "$data" --radius 0.087 --no-loop --plots mf >sixth.log 2>&1 && fail "mf with another process's file was taken"
grep -q "other/n.txt" sixth.log || fail "refused without naming other/n.txt: $(cat sixth.log)"
[ "$(cat mf/other/n.txt)" = x ] || fail "another process's mf/other/n.txt was touched"
echo "kill_and_race: every output whole or absent, the second run refused, stale files removed, no file of another removed"
