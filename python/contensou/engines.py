"""Coefficients for other engines' spin friction from a contact patch, with their error against
the exact integrals (the same numbers as the C++ app ``contensou-engine-coefficients``).

Every engine below models spin friction as a torque proportional to the normal force, with a
coefficient of its own. Each coefficient is matched to the patch at one point and its worst
error over psi = v / (omega R) in [1e-3, 1e3] is measured against the exact resultants
(theory.md sections 2-4), relative to F0 = f N (forces) and M0 = f N R A^2/A^1 (torque; the
exact pure-spin torque, theory.md section 4: M0 = 2 pi f R^3 p* A^2, N = 2 pi R^2 p* A^1).

- MuJoCo, condim 4, elliptic cone: ``friction="f mu_t 0"``; mu_t [m] is a length (torque
  bound mu_t N). Read as maximum dissipation on the ellipse (F/fN)^2 + (M/mu_t N)^2 <= 1:
  F = F0 psi / sqrt(psi^2 + c^2), M = mu_t N c / sqrt(psi^2 + c^2), c = mu_t / (f R).
  "pure spin": mu_t = M0 / N (2/3 R f for uniform pressure; Zhuravlev 1998, theory.md section 3);
  "least squares": c minimises the squared errors of F/F0 and M/M0 at log-spaced psi.
- Chrono (spinning friction coefficient, a length) and Bullet (spinningFriction, a length):
  torque bound mu_s N independent of sliding (F = F0 whenever sliding); pure spin mu_s = M0/N.
- Gazebo/ODE torsional friction: torque (3 pi / 16) mu a N (a Hertz patch of radius a;
  3 pi/16 = A^2/A^1 of p = sqrt(1 - rho^2)), independent of sliding; with mu = f the matching
  patch radius is a = (M0 / N) / (3 pi f / 16).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import _args
from ._core import ContactPatch, ExactModel, hertz_profile, seed_tire_profile, uniform_profile
from .friction import ExactLaw, exact_law_resultants, exact_resultants

PROFILES = ("uniform", "hertz", "seed-tire")
PSI_MIN, PSI_MAX, PSI_POINTS = 1e-3, 1e3, 121


@dataclass(frozen=True)
class EngineCoefficient:
    engine: str
    parameter: str
    value: float
    unit: str
    definition: str
    worst_force_error: float  # max |F - F_exact| / F0 over psi
    worst_torque_error: float  # max |M - M_exact| / M0 over psi
    snippet: str


def _profile(name: str):
    if not isinstance(name, str):
        _args.wrong_type("--profile", name, "a built-in profile's name (" + ", ".join(PROFILES) + ")")
    if name == "uniform":
        return uniform_profile()
    if name == "hertz":
        return hertz_profile()
    if name == "seed-tire":
        return seed_tire_profile()
    raise ValueError(f"--profile '{name}': use one of {', '.join(PROFILES)}")


def _positive(option: str, value: float) -> float:
    x = _args.number(option, value)
    if not math.isfinite(x) or x <= 0:
        raise ValueError(f"{option} = {value!r}: must be a positive finite number")
    return x


def exact_curves(profile: str, radius: float, friction: float, psi: np.ndarray):
    """F_par / F0 and |Mz| / M0 of the exact integrals at psi (unit load), and M0 / N."""
    # The unit load: p* = 1 / (2 pi R^2 A^1) (theory.md section 4).
    patch = ContactPatch(radius_m=radius, normal_load=1.0, friction=friction,
                         profile=_profile(profile))
    m0 = friction * radius * patch.profile.moment(2) / patch.profile.moment(1)
    omega = 1.0 / radius
    # The exact law (contensou/friction/exact_law.hpp): the exact resultants from tables built
    # once, within a certified bound of the integrals (relative to f N and f N R), the
    # integrator's tolerance here; a build that misses it leaves the points to the integrator.
    model = ExactModel(patch)
    law = ExactLaw(model, tolerance=1e-9)
    if law.reached:
        r = exact_law_resultants(law, psi * radius * omega, 0.0, omega)
    else:
        r = exact_resultants(model, psi * radius * omega, 0.0, omega, tolerance=1e-9).resultants
    return -r[:, 0] / friction, -r[:, 2] / m0, m0


def engine_coefficients(profile: str, radius: float, friction: float) -> list[EngineCoefficient]:
    """The table of ``contensou-engine-coefficients``; ValueError naming a bad option."""
    if profile not in PROFILES:
        _profile(profile)
    radius = _positive("--radius", radius)
    friction = _positive("--friction", friction)
    psi = np.geomspace(PSI_MIN, PSI_MAX, PSI_POINTS)
    fx, mz, m0 = exact_curves(profile, radius, friction, psi)

    def elliptic(c: float):
        s = np.sqrt(psi**2 + c**2)
        mu_t = c * friction * radius
        return psi / s, mu_t * c / s / m0  # F/F0, M/M0

    def errors(f_model, m_model):
        return float(np.max(np.abs(f_model - fx))), float(np.max(np.abs(m_model - mz)))

    rows = []
    c_spin = m0 / (friction * radius)
    grid = np.geomspace(c_spin / 4, c_spin * 4, 2001)
    cost = [np.sum((elliptic(c)[0] - fx) ** 2 + (elliptic(c)[1] - mz) ** 2) for c in grid]
    c_ls = float(grid[int(np.argmin(cost))])
    for label, c in (("pure spin: mu_t N = M0", c_spin), ("least squares over psi", c_ls)):
        mu_t = c * friction * radius
        ef, em = errors(*elliptic(c))
        rows.append(EngineCoefficient(
            "MuJoCo (condim 4, elliptic cone)", "friction[1] (torsional)", mu_t, "m", label,
            ef, em,
            f'<geom condim="4" friction="{friction:.6g} {mu_t:.6g} 0"/>  '
            '<option cone="elliptic"/>'))
    mu_s = m0
    one = np.ones_like(psi)
    ef, em = errors(one, one)
    rows.append(EngineCoefficient(
        "Chrono", "spinning friction coefficient", mu_s, "m", "pure spin: mu_s N = M0", ef, em,
        f"material->SetFriction({friction:.6g}); "
        f"material->SetSpinningFriction({mu_s:.6g});"))
    rows.append(EngineCoefficient(
        "Bullet", "spinningFriction", mu_s, "m", "pure spin: spinningFriction N = M0", ef, em,
        f'<contact><lateral_friction value="{friction:.6g}"/>'
        f'<spinning_friction value="{mu_s:.6g}"/></contact>  (URDF)'))
    a = m0 / (3 * math.pi / 16 * friction)
    rows.append(EngineCoefficient(
        "Gazebo (ODE)", "torsional patch_radius", a, "m",
        "pure spin: (3 pi/16) f a N = M0", ef, em,
        f"<friction><torsional><coefficient>{friction:.6g}</coefficient>"
        f"<use_patch_radius>true</use_patch_radius><patch_radius>{a:.6g}</patch_radius>"
        "</torsional><ode><mu>" f"{friction:.6g}</mu></ode></friction>  (SDF)"))
    return rows


def format_table(rows: list[EngineCoefficient]) -> str:
    lines = [f"{'engine':34} {'parameter':30} {'value':>12}  {'worst F err':>11} "
             f"{'worst M err':>11}  definition"]
    for r in rows:
        lines.append(f"{r.engine:34} {r.parameter:30} {r.value:12.6g}  {r.worst_force_error:11.4f} "
                     f"{r.worst_torque_error:11.4f}  {r.definition}")
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    """``python -m contensou.engines --profile uniform --radius 0.1 --friction 0.5``"""
    import argparse
    import sys

    ap = argparse.ArgumentParser(prog="python -m contensou.engines", description=__doc__.splitlines()[0])
    ap.add_argument("--profile", default="uniform", help="uniform, hertz or seed-tire")
    ap.add_argument("--radius", type=float, required=True, help="patch radius R [m]")
    ap.add_argument("--friction", type=float, required=True, help="friction coefficient f")
    args = ap.parse_args(argv)
    try:
        rows = engine_coefficients(args.profile, args.radius, args.friction)
    except ValueError as e:
        print(f"python -m contensou.engines: {e}", file=sys.stderr)
        return 2
    print(format_table(rows))
    print("\nsnippets:")
    for r in rows:
        print(f"  {r.engine}: {r.snippet}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
