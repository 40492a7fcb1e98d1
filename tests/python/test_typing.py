"""The installed package type-checks with its stubs (stubgen's _core.pyi and py.typed in the
wheel): mypy on the package itself and on the example, as an editor or a user's CI would."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import contensou

from conftest import ROOT


def test_wheel_ships_stubs_and_marker():
    package = Path(contensou.__file__).parent
    stub = package / "_core.pyi"
    assert (package / "py.typed").exists()
    text = stub.read_text()
    for name in ("class ContactPatch", "class FractionalLaw", "def _exact_loop", "version: str"):
        assert name in text, name


def test_mypy_accepts_the_package_and_the_example(tmp_path):
    for target in (["-p", "contensou"],
                   ["--ignore-missing-imports", str(ROOT / "examples" / "python" / "fit_and_map.py")]):
        run = subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(tmp_path / "cache"),
                              "--no-error-summary", *target], capture_output=True, text=True,
                             cwd=tmp_path)
        assert run.returncode == 0, run.stdout + run.stderr
