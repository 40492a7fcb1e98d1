#!/usr/bin/env bash
# Installs every dependency from Debian 12's packages, builds contensou in ./build, creates the
# Python virtual environment .venv with the package `contensou` installed in it (pip install .,
# python/requirements.txt, which includes `mujoco` for the MuJoCo plugin in plugins/mujoco), and
# runs the main job on the built-in data.
# Usage: scripts/setup.sh   (CONTENSOU_WERROR=ON for CI)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config
  libeigen3-dev libceres-dev libboost-dev libsundials-dev libgtest-dev libgmock-dev libbenchmark-dev
  libcubature-dev libcli11-dev nlohmann-json3-dev gnuplot-nox clang-format doxygen
  clang-14 libclang-rt-14-dev libomp-14-dev python3-venv python3-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# The Python environment: python/requirements.txt pins the build requirements, the packages the
# tests and the example use, and `mujoco`, whose wheels ship MuJoCo's headers and libmujoco.so;
# CMake finds them there (cmake/FindMuJoCo.cmake) and builds plugins/mujoco.
python_env() {
  [ -x .venv/bin/python ] || python3 -m venv .venv
  .venv/bin/python -m pip install --quiet --disable-pip-version-check -r python/requirements.txt
}
python_job=""
if ((${#missing[@]})); then
  # When this machine's Python can make a virtual environment without Debian's python3-venv, the
  # Python packages download while apt installs the others.
  if python3 -c 'import ensurepip, venv' 2>/dev/null; then
    python_env &
    python_job=$!
  fi
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ -n "$python_job" ]; then
  wait "$python_job" || { echo "setup: installing python/requirements.txt into .venv failed" >&2; exit 1; }
else
  python_env
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCONTENSOU_WERROR="${CONTENSOU_WERROR:-OFF}"
cmake --build build --parallel

# The Python package in .venv: the extension (scikit-build-core, nanobind; warnings as errors
# with CONTENSOU_WERROR=ON) and the MuJoCo plugin (against .venv's mujoco), linked against the
# libraries just built (installed into build/prefix) rather than compiling them a second time,
# in build/python, kept between runs (a plain pip install builds in a temporary folder).
cmake --install build --prefix build/prefix >/dev/null
CONTENSOU_WERROR="${CONTENSOU_WERROR:-OFF}" .venv/bin/python -m pip install --quiet \
  --disable-pip-version-check --no-build-isolation --config-settings=build-dir=build/python \
  --config-settings=cmake.define.CONTENSOU_PREBUILT_PREFIX="$PWD/build/prefix" .
.venv/bin/python -c "import contensou; print('python: contensou', contensou.__version__, 'in .venv')"
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
