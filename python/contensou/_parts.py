"""The parts of the package a build may leave out (identification needs Ceres, gear SUNDIALS;
friction needs Eigen only), and the ImportError that names what a missing part needs."""

from __future__ import annotations

from . import _build


def missing(part: str) -> ImportError:
    needs = _build.MISSING.get(part, "its dependencies")
    them = "them" if needs.count("(Debian:") > 1 else "it"
    return ImportError(
        f"contensou.{part} is not in this installation of contensou: its build did not find "
        f"{needs}. Install {them}, then build contensou again from its source (pip install "
        "--force-reinstall <the source>); the friction functions work without it."
    )


def require(part: str) -> None:
    """Raises ImportError naming what `part` needs when the build left it out."""
    if part not in _build.PARTS:
        raise missing(part)
