#!/usr/bin/env bash
# Runs the whole test suite on the build made by scripts/setup.sh.
#   scripts/test.sh             the Release build in ./build (ctest), then the Python package in
#                               .venv (pytest tests/python) and its example
#   scripts/test.sh --sanitize  builds ./build-asan with ASan+UBSan (and the fuzz targets of
#                               tests/fuzz, for scripts/fuzz.sh) and runs the C++ tests there
#   scripts/test.sh --sanitize --build-only   only builds ./build-asan
set -euo pipefail
cd "$(dirname "$0")/.."
dir=build
skip=()
if [ "${1:-}" = "--sanitize" ]; then
  dir=build-asan
  # -O1 -g1 (line tables for the reports): half the compile time of -O2 -g, same findings.
  # clang 14 when present (scripts/setup.sh installs it): under ASan+UBSan it compiles this tree
  # in about half the time GCC 12 takes, its warnings are a second opinion, and with its
  # libFuzzer runtime the same build holds the fuzz targets.
  compilers=() fuzz=OFF
  if command -v clang++-14 >/dev/null; then
    compilers=(-DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14)
    probe=$(mktemp -d)
    printf '%s\n' '#include <cstddef>' '#include <cstdint>' \
      'extern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }' >"$probe/p.cpp"
    clang++-14 -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" 2>/dev/null && fuzz=ON
    rm -rf "$probe"
  fi
  cmake -S . -B "$dir" -G Ninja "${compilers[@]}" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" \
    -DCONTENSOU_SANITIZE=ON -DCONTENSOU_FUZZ="$fuzz" -DCONTENSOU_WERROR=ON \
    -DCONTENSOU_BUILD_BENCHMARKS=OFF -DCONTENSOU_BUILD_EXAMPLES=OFF
  cmake --build "$dir" --parallel
  [ "${2:-}" = "--build-only" ] && exit 0
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1
  # The long end-to-end repeats of app code that shorter tests already run under the sanitizers
  # (tests/CMakeLists.txt: label end_to_end_repeat) run in the Release build only.
  # So does the loop on fractional-law data (70 s under ASan, every path of it also in the
  # shorter ClosedLoop tests).
  skip=(-LE end_to_end_repeat -E '^ClosedLoop[.]NoEffectOnFractionalLawData$')
fi
[ -d "$dir" ] || { echo "test: no $dir; run scripts/setup.sh first" >&2; exit 1; }
ctest --test-dir "$dir" --output-on-failure --parallel 2 "${skip[@]}"
[ "$dir" = build ] || exit 0

# The Python package (scripts/setup.sh installed it into .venv); its tests compare with the
# apps and a reference program of ./build; -rs prints the reason of a skip (the MuJoCo tests skip
# only when `mujoco` cannot be imported).
[ -x .venv/bin/python ] || { echo "test: no .venv; run scripts/setup.sh first" >&2; exit 1; }
status=0
CONTENSOU_BUILD_DIR="$PWD/build" .venv/bin/python -m pytest tests/python -q -rs -p no:cacheprovider \
  || status=$?
if [ "$status" -eq 5 ]; then
  echo "test: pytest collected no tests in tests/python" >&2
  exit 1
fi
[ "$status" -eq 0 ] || exit "$status"
.venv/bin/python examples/python/fit_and_map.py --out out/python
