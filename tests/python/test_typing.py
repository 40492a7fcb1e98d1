"""The installed package type-checks with its stubs (stubgen's _core.pyi and py.typed in the
wheel): mypy on the package itself and on the example, as an editor or a user's CI would."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import contensou

from conftest import ROOT


def test_wheel_ships_stubs_and_marker():
    package = Path(contensou.__file__).parent
    stub = package / "_core.pyi"
    assert (package / "py.typed").exists()
    text = stub.read_text()
    for name in ("class ContactPatch", "class FractionalLaw", "def _exact_loop", "class _ExactLaw",
                 "def _exact_law_loop", "version: str"):
        assert name in text, name


@pytest.fixture(scope="module")
def mypy(tmp_path_factory):
    """Runs mypy in a folder of its own, with one cache for the module's tests."""
    folder = tmp_path_factory.mktemp("mypy")

    def run(*target: str) -> subprocess.CompletedProcess:
        return subprocess.run([sys.executable, "-m", "mypy", "--cache-dir", str(folder / "cache"),
                               "--no-error-summary", *target], capture_output=True, text=True,
                              cwd=folder)

    return run


def test_mypy_accepts_the_package_and_the_example(mypy):
    for target in (["-p", "contensou"],
                   ["--ignore-missing-imports", str(ROOT / "examples" / "python" / "fit_and_map.py")]):
        run = mypy(*target)
        assert run.returncode == 0, run.stdout + run.stderr


def test_exact_law_results_have_one_type_each(mypy, tmp_path):
    """exact_law_resultants returns an array, or with jacobian=True a pair: no Union to narrow."""
    use = tmp_path / "use_exact_law.py"
    use.write_text(
        "import numpy as np\n"
        "import contensou as c\n"
        "law = c.ExactLaw(c.seed_tire_patch(), tolerance=1e-8)\n"
        "F: np.ndarray = c.exact_law_resultants(law, 0.5, 0.0, 10.0)\n"
        "pair: tuple[np.ndarray, np.ndarray] = c.exact_law_resultants(law, 0.5, 0.0, 10.0,\n"
        "                                                             jacobian=True)\n"
        "G, J = c.exact_law_resultants(law, [0.5], 0.0, 10.0, jacobian=True)\n"
        "bound: float = law.achieved + J.sum()\n"
        "wrong: np.ndarray = c.exact_law_resultants(law, 0.5, 0.0, 10.0, jacobian=True)\n")
    run = mypy(str(use))
    # Only the last line is an error: the pair is not an array.
    errors = [line for line in run.stdout.splitlines() if ": error:" in line]
    assert len(errors) == 1 and "use_exact_law.py:9:" in errors[0], run.stdout + run.stderr


def test_both_input_forms_type_check(mypy, tmp_path):
    """Three arrays give arrays (a pair with jacobian=True), a table of columns gives a
    FrictionTable: each form has one type, so F[:, 0] and table.Fx_N need no narrowing."""
    use = tmp_path / "use_tables.py"
    use.write_text(
        "import numpy as np\n"
        "import contensou as c\n"
        "patch = c.ContactPatch(radius_m=0.087, normal_load=4500.0, friction=0.3)\n"
        "law = c.fractional_law_from_patch(patch)\n"
        "F = c.fractional_resultants(law, [0.5, 1.0], 0.0, 10.0)\n"
        "first: np.ndarray = F[:, 0]\n"
        "G, J = c.fractional_resultants(law, 0.5, 0.0, 10.0, jacobian=True)\n"
        "cols = {'vx_mps': [0.5], 'vy_mps': [0.0], 'omega_radps': [10.0]}\n"
        "t = c.fractional_resultants(law, cols)\n"
        "fx: np.ndarray = t.Fx_N\n"
        "frame = c.exact_resultants(patch, cols).to_frame()\n"
        "e: np.ndarray = c.exact_resultants(patch, 0.5, 0.0, 10.0).error\n"
        "wrong: np.ndarray = c.fractional_resultants(law, cols)\n")
    run = mypy(str(use))
    # Only the last line is an error: a table's result is a FrictionTable, not an array.
    errors = [line for line in run.stdout.splitlines() if ": error:" in line]
    assert len(errors) == 1 and "use_tables.py:13:" in errors[0], run.stdout + run.stderr
