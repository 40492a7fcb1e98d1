"""Shared fixtures of the Python tests: the repository, the C++ build made by scripts/setup.sh
(its apps and the reference program are the oracles), and the bundled data.

The build directory is ./build unless CONTENSOU_BUILD_DIR says otherwise. A missing program is
an error, not a skip: these tests exist to compare the package with the C++ results.
"""

from __future__ import annotations

import csv
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(os.environ.get("CONTENSOU_BUILD_DIR", ROOT / "build"))
DATA = ROOT / "data" / "seed_tire_diagrams.csv"


def program(relative: str) -> Path:
    path = BUILD / relative
    if not path.exists():
        raise FileNotFoundError(
            f"{path} is missing: build the C++ project first (scripts/setup.sh), or set "
            "CONTENSOU_BUILD_DIR"
        )
    return path


@pytest.fixture(scope="session")
def identify_app() -> Path:
    return program("apps/contensou-identify")


@pytest.fixture(scope="session")
def shimmy_app() -> Path:
    return program("apps/contensou-shimmy")


@pytest.fixture(scope="session")
def reference_rows() -> list[dict[str, str]]:
    """Rows printed by tests/python/reference_values.cpp."""
    out = subprocess.run(
        [str(program("tests/python/contensou-python-reference"))],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    rows = list(csv.DictReader(out.splitlines()))
    assert len(rows) > 100
    return rows
