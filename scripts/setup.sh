#!/usr/bin/env bash
# Installs every dependency from Debian 12's packages, builds contensou in ./build and runs the
# main job on the built-in data. Usage: scripts/setup.sh   (CONTENSOU_WERROR=ON for CI)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
  libeigen3-dev libceres-dev libsundials-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcubature-dev libcli11-dev nlohmann-json3-dev gnuplot-nox clang-format
  clang-14 libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCONTENSOU_WERROR="${CONTENSOU_WERROR:-OFF}"
cmake --build build --parallel
echo
./build/examples/contensou-model-error
echo
# Identification and the closed loop on the bundled diagrams: tables on stdout, pictures and
# the JSON report in out/identify.
./build/apps/contensou-identify data/seed_tire_diagrams.csv --radius 0.087 \
  --profile seed-tire --pressure 2.1e5 --plots out/identify --json out/identify/report.json
echo
# The landing-gear shimmy demo: three contact models, CSV, PNG and summary.json in out/shimmy.
./build/apps/contensou-shimmy --out out/shimmy
