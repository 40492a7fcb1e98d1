"""The friction law of a contact patch and the landing gear as Functional Mock-up Units (FMI 2.0
or 3.0) for Modelica tools, Simulink's FMU Import block, FMPy and any other FMI importer
(docs/fmu.md).

``export(patch, path)`` writes the law's FMU (inputs vx, vy, omega, N; outputs Fx, Fy, Mz; Model
Exchange and Co-Simulation, directional derivatives), ``export_gear(path)`` the shimmy demo's
landing gear (Co-Simulation, CVODE inside). Both run the ``contensou-fmu`` command, which the
wheel installs beside the Python interpreter (``command()`` says where it is found).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Union

import numpy as np

from . import _args
from ._core import ContactPatch, seed_tire_profile
from .friction import shape_values

PathLike = Union[str, "os.PathLike[str]"]

# A profile other than uniform, Hertz or the seed's is handed over as a table of this many points,
# uniform in t = rho^2 (the exact model's variable), which the FMU interpolates by monotone cubics:
# for a smooth profile its resultants are those of the profile to about 1e-12 of f N.
TABLE_POINTS = 4097


def command() -> Path:
    """The contensou-fmu program: $CONTENSOU_FMU, else the one beside this Python (the wheel's
    command), else the first on PATH. Raises FileNotFoundError naming where it looked."""
    given = os.environ.get("CONTENSOU_FMU")
    if given:
        return Path(given)
    here = Path(sys.executable).parent / "contensou-fmu"
    if here.exists():
        return here
    found = shutil.which("contensou-fmu")
    if found:
        return Path(found)
    raise FileNotFoundError(
        f"contensou-fmu not found: not in $CONTENSOU_FMU, {here.parent} or PATH (the wheel installs "
        "it; a build from source has it in build/apps)"
    )


def _run(arguments: list[str]) -> str:
    result = subprocess.run([str(command()), *arguments], capture_output=True, text=True)
    if result.returncode != 0:
        message = result.stderr.strip().removeprefix("contensou-fmu: ")
        raise ValueError(message or f"contensou-fmu failed with status {result.returncode}")
    return result.stdout


def _same_shape(a: object, b: object) -> bool:
    rho = np.linspace(0.0, 1.0, 257)
    return bool(np.array_equal(shape_values(a, rho), shape_values(b, rho)))  # type: ignore[arg-type]


def _profile_arguments(patch: ContactPatch, folder: Path) -> list[str]:
    """The profile as contensou-fmu takes it: by name, or as a table file written into folder."""
    profile = patch.profile
    flags = []
    if profile.clip_negative:
        flags.append("--clip-negative")
    if profile.keep_negative:
        flags.append("--keep-negative")
    pressure = ["--pressure", repr(patch.reference_pressure_pa)]
    if profile.kind in ("uniform", "hertz"):
        return ["--profile", profile.kind, *pressure, *flags]
    seed = seed_tire_profile()
    if profile.kind == "cosine_series" and _same_shape(profile, seed):
        return ["--profile", "seed-tire", *pressure, *flags]
    rho = np.sqrt(np.linspace(0.0, 1.0, TABLE_POINTS))
    p = shape_values(profile, rho).reshape(-1) * patch.reference_pressure_pa
    table = folder / "profile.csv"
    lines = ["# the pressure profile of the patch, sampled by contensou.fmu.export", "rho,pressure_Pa"]
    lines += [f"{r!r},{v!r}" for r, v in zip(rho.tolist(), p.tolist())]
    table.write_text("\n".join(lines) + "\n")
    # The file's mean pressure becomes p* and the table p / p*: the same pressure sigma.
    name = f"the {profile.kind} profile of the patch exported, sampled at {TABLE_POINTS} points in rho^2"
    return ["--profile", str(table), "--profile-name", name, *flags]


def _fmi(version: object) -> str:
    """The FMI version as contensou-fmu takes it: 2 or 3 (an int; "3" or True are refused)."""
    if isinstance(version, bool) or not isinstance(version, (int, np.integer)):
        _args.wrong_type("fmi_version", version, "the integer 2 or 3")
    if version not in (2, 3):
        raise ValueError(f"fmi_version = {version!r}: must be 2 (FMI 2.0) or 3 (FMI 3.0)")
    return str(int(version))  # type: ignore[call-overload]


def export(
    patch: ContactPatch,
    path: PathLike,
    *,
    law: str = "exact",
    tolerance: float = 1e-8,
    model_name: str = "contensou_law",
    fmi_version: int = 2,
) -> Path:
    """Writes the law FMU of ``patch`` to ``path`` (.fmu) and returns the path.

    ``law``: "exact" (the exact law's tables, built here to ``tolerance`` relative to f N and
    f N R, shipped in resources/law.txt) or "fractional"; ``fmi_version`` 2 (FMI 2.0) or 3
    (FMI 3.0). Raises ValueError with contensou-fmu's
    message for a bad patch or option, FileNotFoundError when contensou-fmu is not found.
    """
    _args.instance("patch", patch, (ContactPatch,),
                   "a ContactPatch (e.g. contensou.ContactPatch.from_normal_load(R, N, "
                   "contensou.seed_tire_profile(), f))")
    _args.instance("model_name", model_name, (str,), "a string")
    _args.instance("law", law, (str,), '"exact" or "fractional"')
    fmi = _fmi(fmi_version)
    patch.validate()
    with tempfile.TemporaryDirectory(prefix="contensou-fmu-") as folder:
        arguments = ["law", "--out", os.fspath(path), "--radius", repr(patch.radius_m)]
        arguments += _profile_arguments(patch, Path(folder))
        slip = patch.slip_speed_friction
        if slip is not None:
            values = (slip.static_coefficient, slip.kinetic_coefficient, slip.reference_speed, slip.exponent)
            arguments += ["--slip-speed-friction", ",".join(repr(v) for v in values)]
        else:
            arguments += ["--friction", repr(patch.friction)]
        arguments += ["--kappa", repr(patch.kappa), "--kx", repr(patch.profile.kx)]
        arguments += ["--ky", repr(patch.profile.ky), "--law", law, "--tolerance", repr(tolerance)]
        arguments += ["--model-name", model_name, "--fmi", fmi]
        _run(arguments)
    return Path(path)


def export_gear(path: PathLike, *, fmi_version: int = 2) -> Path:
    """Writes the landing-gear FMU (Co-Simulation; parameters the shimmy demo's configuration
    keys; FMI 2.0, or 3.0 with ``fmi_version=3``) to ``path`` and returns the path."""
    _run(["gear", "--out", os.fspath(path), "--fmi", _fmi(fmi_version)])
    return Path(path)


__all__ = ["TABLE_POINTS", "command", "export", "export_gear"]
