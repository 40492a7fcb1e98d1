#!/usr/bin/env bash
# The API reference (docs/Doxyfile, Doxygen) of the installed headers' public names, into
# build/api/html. Every public name of the checked modules must carry a doc comment: an
# undocumented name or a broken comment is a warning, and a warning fails the run.
# Usage: scripts/api-reference.sh [MODULE...]   (default: friction; "all": every module)
#   MODULE: friction, identification, gear, fmu. --count: report the warnings of each module and
#   do not fail (the state of the modules not yet documented).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v doxygen >/dev/null || { echo "api-reference: doxygen is not installed (scripts/setup.sh)" >&2; exit 1; }
count=0
modules=()
for a in "$@"; do
  case "$a" in
    --count) count=1 ;;
    all) modules+=(friction identification gear fmu) ;;
    friction | identification | gear | fmu) modules+=("$a") ;;
    *) echo "api-reference: unknown module '$a' (friction, identification, gear, fmu, all)" >&2; exit 2 ;;
  esac
done
((${#modules[@]})) || modules=(friction)

run() {  # run OUTPUT WARN_AS_ERROR INPUT...
  local out=$1 warn=$2
  shift 2
  mkdir -p "$out"
  CONTENSOU_API_OUTPUT="$out" CONTENSOU_API_WARN_AS_ERROR="$warn" CONTENSOU_API_STRIP="$PWD/include" \
    CONTENSOU_API_INPUT="$*" doxygen docs/Doxyfile
}

if ((count)); then
  for m in "${modules[@]}"; do
    inputs=("include/contensou/$m")
    [ -f "include/contensou/$m.hpp" ] && inputs+=("include/contensou/$m.hpp")
    run "build/api-$m" NO "${inputs[@]}" >/dev/null 2>&1 || true
    echo "$m: $(grep -c . "build/api-$m/warnings.log" || true) warnings (build/api-$m/warnings.log)"
  done
  exit 0
fi

inputs=()
for m in "${modules[@]}"; do
  inputs+=("include/contensou/$m")
  [ -f "include/contensou/$m.hpp" ] && inputs+=("include/contensou/$m.hpp")
done
if ! run build/api FAIL_ON_WARNINGS "${inputs[@]}"; then
  cat build/api/warnings.log >&2
  echo "api-reference: the warnings above (build/api/warnings.log)" >&2
  exit 1
fi
if [ -s build/api/warnings.log ]; then
  cat build/api/warnings.log >&2
  echo "api-reference: the warnings above (build/api/warnings.log)" >&2
  exit 1
fi
echo "api-reference: build/api/html/index.html (${modules[*]})"
