"""Vectorised friction: exact resultants, the exact law and the fractional law on numpy arrays.

vx, vy and omega broadcast against each other (numpy rules); results have the broadcast
shape with a last axis of 3 (Fx, Fy, Mz), Jacobians a last two axes of 3 x 3 (rows Fx, Fy,
Mz; columns vx, vy, omega). The loop over points runs in C++ with the GIL released, on
``threads`` threads (1 by default; 0 for one per core).
"""

from __future__ import annotations

from typing import Literal, NamedTuple, Union, overload

import numpy as np
import numpy.typing as npt

from . import _core
from ._core import ContactPatch, ExactModel, FractionalLaw, PressureProfile

ArrayLike = npt.ArrayLike


class ExactResults(NamedTuple):
    """Exact resultants on a grid of kinematics."""

    resultants: np.ndarray  # (..., 3): Fx, Fy [N], Mz [N m], friction on the tire
    error: np.ndarray  # (..., 3): estimated absolute error [N, N, N m]
    converged: np.ndarray  # (...): True where every component of `error` meets the tolerance


MAX_THREADS = 256


def _check_threads(threads: int) -> int:
    if (isinstance(threads, bool) or not isinstance(threads, (int, np.integer))
            or not 0 <= threads <= MAX_THREADS):
        raise ValueError(
            f"threads = {threads!r}: must be an integer in 0..{MAX_THREADS} (0: one per core)")
    return int(threads)


def _real_array(name: str, a: ArrayLike) -> np.ndarray:
    """``a`` as float64, refusing what the conversion would silently change: complex values
    (numpy drops the imaginary part with only a warning) and non-numbers."""
    if np.iscomplexobj(a) or (not isinstance(a, np.ndarray) and isinstance(a, complex)):
        raise ValueError(f"{name}: complex values; give real numbers (the imaginary part would "
                         "be lost)")
    try:
        out = np.asarray(a, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"{name}: not convertible to an array of floats ({e})") from None
    return out


def _flatten(vx: ArrayLike, vy: ArrayLike, omega: ArrayLike) -> tuple[tuple[int, ...], list]:
    """The broadcast shape and three flat float64 arrays of that many points, or of one."""
    arrays = [_real_array(name, a) for name, a in (("vx", vx), ("vy", vy), ("omega", omega))]
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays))
    except ValueError:
        raise ValueError(
            "vx, vy and omega do not broadcast together: shapes "
            + ", ".join(str(a.shape) for a in arrays)
        ) from None
    flat = []
    for a in arrays:
        if a.size == 1:
            flat.append(np.ascontiguousarray(a.reshape(1)))
        elif a.shape == shape:
            flat.append(np.ascontiguousarray(a).reshape(-1))
        else:
            flat.append(np.ascontiguousarray(np.broadcast_to(a, shape)).reshape(-1))
    return shape, flat


def exact_resultants(
    model: Union[ExactModel, ContactPatch],
    vx: ArrayLike,
    vy: ArrayLike,
    omega: ArrayLike,
    *,
    tolerance: float = 1e-10,
    threads: int = 1,
) -> ExactResults:
    """Exact resultants of the patch at every (vx, vy, omega) (broadcast).

    ``model`` is an ``ExactModel`` (build it once from a ``ContactPatch``) or a patch (the
    model is built for this call). ``tolerance`` is relative to f N (forces) and f N R (torque).
    """
    if isinstance(model, ContactPatch):
        model = ExactModel(model)
    shape, (x, y, w) = _flatten(vx, vy, omega)
    n = int(np.prod(shape, dtype=np.int64))
    force = np.empty((n, 3))
    error = np.empty((n, 3))
    converged = np.empty(n, dtype=bool)
    _core._exact_loop(model, x, y, w, force, error, converged, float(tolerance), _check_threads(threads))
    return ExactResults(
        force.reshape(shape + (3,)), error.reshape(shape + (3,)), converged.reshape(shape)
    )


class ExactLaw(_core._ExactLaw):
    """The exact resultants of a patch from tables built once (contensou/friction/exact_law.hpp).

    ``model`` is an ``ExactModel`` or a ``ContactPatch`` (its model is built here). The build
    takes tens of milliseconds for constant friction and about a second or more with slip-speed
    friction f(w), on ``threads`` threads (0: one per core; the law is the same for any number).
    Evaluate it with ``exact_law_resultants``: the cost of a closed-form law, within
    ``achieved`` (a certified bound, relative to f N for forces and f N R for the torque) of
    ``exact_resultants``. ``tolerance`` is the requested bound, in (1e-14, 1e-2); ``reached``
    tells whether ``achieved`` is within it.
    """

    def __init__(
        self, model: Union[ExactModel, ContactPatch], tolerance: float = 1e-8, threads: int = 0
    ) -> None:
        if isinstance(model, ContactPatch):
            model = ExactModel(model)
        if not isinstance(model, ExactModel):
            raise TypeError(
                f"model: expected an ExactModel or a ContactPatch, not {type(model).__name__}")
        try:
            tol = float(tolerance)
        except (TypeError, ValueError):
            raise ValueError(f"tolerance = {tolerance!r}: must be a number") from None
        super().__init__(model, tol, _check_threads(threads))


def _law_on_arrays(loop, law, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, jacobian: bool,
                   threads: int) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """A compiled law loop over broadcast (vx, vy, omega): (..., 3) and the (..., 3, 3) Jacobian."""
    shape, (x, y, w) = _flatten(vx, vy, omega)
    n = int(np.prod(shape, dtype=np.int64))
    force = np.empty((n, 3))
    jac = np.empty((n, 3, 3)) if jacobian else None
    loop(law, x, y, w, force, jac, _check_threads(threads))
    if jac is None:
        return force.reshape(shape + (3,))
    return force.reshape(shape + (3,)), jac.reshape(shape + (3, 3))


@overload
def exact_law_resultants(
    law: ExactLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: Literal[False] = False, threads: int = 1,
) -> np.ndarray: ...


@overload
def exact_law_resultants(
    law: ExactLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: Literal[True], threads: int = 1,
) -> tuple[np.ndarray, np.ndarray]: ...


@overload
def exact_law_resultants(
    law: ExactLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: bool, threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray]]: ...


def exact_law_resultants(
    law: ExactLaw,
    vx: ArrayLike,
    vy: ArrayLike,
    omega: ArrayLike,
    *,
    jacobian: bool = False,
    threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The exact law at every (vx, vy, omega) (broadcast): (..., 3), and with ``jacobian=True``
    also d(Fx, Fy, Mz)/d(vx, vy, omega) as (..., 3, 3) (the exact derivative of the law; at
    v = 0 and omega = 0 its limits). Zero at rest."""
    return _law_on_arrays(_core._exact_law_loop, law, vx, vy, omega, jacobian, threads)


def fractional_resultants(
    law: FractionalLaw,
    vx: ArrayLike,
    vy: ArrayLike,
    omega: ArrayLike,
    *,
    jacobian: bool = False,
    threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The fractional law at every (vx, vy, omega) (broadcast): (..., 3), and with
    ``jacobian=True`` also d(Fx, Fy, Mz)/d(vx, vy, omega) as (..., 3, 3) (analytic)."""
    return _law_on_arrays(_core._fractional_loop, law, vx, vy, omega, jacobian, threads)


def shape_values(profile: PressureProfile, rho: ArrayLike) -> np.ndarray:
    """The dimensionless shape p(rho) for rho in [0, 1] (after clipping if set; no shift)."""
    r = _real_array("rho", rho)
    flat = np.ascontiguousarray(r).reshape(-1)
    out = np.empty((flat.size, 1))
    profile._shape_values(flat, out)
    return out.reshape(r.shape)
