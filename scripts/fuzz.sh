#!/usr/bin/env bash
# Runs the libFuzzer targets of tests/fuzz (clang 14, ASan+UBSan; built in ./build-asan by
# scripts/test.sh --sanitize, which this script calls first: a no-op when the build is current)
# for SECONDS each (default 60), starting from the seed corpus in tests/fuzz/corpus/<target>
# (read only: new inputs go to build-asan/fuzz-run/). Exits non-zero on a finding and names the
# saved input; skips with exit 0 if clang++-14 or its fuzzer runtime is missing.
#   scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
targets=(fuzz_measured_csv fuzz_profile_csv fuzz_shimmy_config)
bin=build-asan/tests/fuzz

scripts/test.sh --sanitize --build-only
for t in "${targets[@]}"; do
  [ -x "$bin/$t" ] || {
    echo "fuzz: skipped, no $bin/$t: clang++-14 or its libFuzzer runtime is missing" \
      "(scripts/setup.sh installs clang-14 and libclang-rt-14-dev)"
    exit 0
  }
done

export UBSAN_OPTIONS=print_stacktrace=1
failed=()
# All targets at once (libFuzzer is single-threaded): the wall time is SECONDS, not 3 x SECONDS.
pids=()
for t in "${targets[@]}"; do
  run=build-asan/fuzz-run/$t
  rm -rf "$run"
  mkdir -p "$run/corpus" "$run/artifacts"
  "$bin/$t" -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$run/artifacts/" \
    "$run/corpus" "tests/fuzz/corpus/$t" >"$run/log" 2>&1 &
  pids+=($!)
done
echo "fuzz: ${#targets[@]} targets, ${seconds} s each, in parallel"
for i in "${!targets[@]}"; do
  t=${targets[$i]}
  run=build-asan/fuzz-run/$t
  rc=0
  wait "${pids[$i]}" || rc=$?
  echo "== $t"
  # The last status line: executions, coverage (cov: edges, ft: features), exec/s.
  grep -E '^#[0-9]+' "$run/log" | tail -n 1 || true
  grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' "$run/log" || true
  if ((rc != 0)); then
    failed+=("$t")
    echo "fuzz: $t FAILED (exit $rc); log $run/log, last lines:"
    tail -n 40 "$run/log"
    for f in "$run"/artifacts/*; do
      [ -e "$f" ] && echo "fuzz: crashing input $f (reproduce: $bin/$t $f)"
    done
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: findings in ${failed[*]}"
  exit 1
fi
echo "fuzz: ${#targets[@]} targets ran ${seconds} s each without a finding"
