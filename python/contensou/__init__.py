"""contensou: coupled sliding-spinning dry friction over a contact patch, from Python.

numpy in, numpy out: the exact resultants, the exact law (``ExactLaw``: the same resultants
from tables built once, at the cost of a closed-form law, with its Jacobian) and the fractional
law on arrays of any shape (``contensou.friction``), identification of the law from measured
diagrams given as a pandas DataFrame, arrays or a CSV path (``contensou.identify``), and the
landing-gear shimmy model with stability maps in-process or on a ``dask.distributed`` client
(``contensou.gear``), and the patch's limit surface for set-valued (stick without creep)
friction (``LimitSurface``).
The loops run in C++ (the extension ``contensou._core``) with the GIL released.

The friction functions take three arrays vx, vy, omega or one DataFrame (or mapping) with the
columns vx_mps, vy_mps, omega_radps, whose result is labelled Fx_N, Fy_N, Mz_Nm
(``FrictionTable.to_frame()``). Bad input raises ``ValueError`` with the C++ library's message;
an argument of the wrong type a one-line ``TypeError`` naming it (a number is an int, a float or
a numpy scalar, never a str; a profile a ``PressureProfile`` or a built-in profile's name).

The friction part needs nothing but Eigen to build; identification (Ceres) and the gear
(SUNDIALS) are in the package when their libraries were found at build time, and a name of a
part left out raises ``ImportError`` naming what it needs. The MuJoCo plugin:
``contensou.mujoco``.
"""

import typing as _typing

from . import _build, _core, _parts, _signatures
from ._core import (
    ContactPatch,
    ContactStep,
    EllipsoidalLimitSurface,
    ExactModel,
    FractionalLaw,
    LimitSurface,
    PressureProfile,
    Projection,
    SlipSpeedFriction,
    cosine_series_profile,
    fractional_law_fitted,
    fractional_law_from_patch,
    hertz_profile,
    read_profile_csv,
    seed_tire_patch,
    seed_tire_profile,
    smoothed_profile,
    tabulated_profile,
    uniform_profile,
)
from .friction import (
    ExactLaw,
    ExactResults,
    FrictionTable,
    exact_law_resultants,
    exact_resultants,
    fractional_resultants,
    shape_values,
)

__version__: str = _core.version  # the CMake project's version

_signatures.attach(_core)  # inspect.signature(ContactPatch) and the other classes

__all__ = [
    "ContactPatch",
    "ContactStep",
    "EllipsoidalLimitSurface",
    "ExactLaw",
    "ExactModel",
    "ExactResults",
    "FractionalLaw",
    "FrictionTable",
    "LimitSurface",
    "PressureProfile",
    "Projection",
    "SlipSpeedFriction",
    "__version__",
    "cosine_series_profile",
    "exact_law_resultants",
    "exact_resultants",
    "fractional_law_fitted",
    "fractional_law_from_patch",
    "fractional_resultants",
    "hertz_profile",
    "read_profile_csv",
    "seed_tire_patch",
    "seed_tire_profile",
    "shape_values",
    "smoothed_profile",
    "tabulated_profile",
    "uniform_profile",
]

# The names of the optional parts, each from its module (literal lists in __all__ below, for
# type checkers; tests/python/test_package.py checks that the two agree).
_OPTIONAL = {
    "identification": ["IdentificationResult", "LoopStep", "Parameter", "identify"],
    "gear": [
        "LandingConfig",
        "LandingResult",
        "MapAxis",
        "StabilityMapResult",
        "bifurcation_sweep",
        "simulate_landing",
        "stability_map",
        "stability_map_native",
    ],
}
if _typing.TYPE_CHECKING or "identification" in _build.PARTS:
    from .identification import IdentificationResult, LoopStep, Parameter, identify

    __all__ += ["IdentificationResult", "LoopStep", "Parameter", "identify"]
if _typing.TYPE_CHECKING or "gear" in _build.PARTS:
    from .gear import (
        LandingConfig,
        LandingResult,
        MapAxis,
        StabilityMapResult,
        bifurcation_sweep,
        simulate_landing,
        stability_map,
        stability_map_native,
    )

    __all__ += [
        "LandingConfig",
        "LandingResult",
        "MapAxis",
        "StabilityMapResult",
        "bifurcation_sweep",
        "simulate_landing",
        "stability_map",
        "stability_map_native",
    ]

if not _typing.TYPE_CHECKING:  # for the type checker every name above exists

    def __getattr__(name: str) -> _typing.Any:
        """A name of a part the build left out: ImportError naming what that part needs."""
        for part, names in _OPTIONAL.items():
            if name in names:
                raise _parts.missing(part)
        raise AttributeError(f"module 'contensou' has no attribute {name!r}")
