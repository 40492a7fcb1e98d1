"""Vectorised friction: exact resultants, the exact law and the fractional law on numpy arrays.

Two forms of input:

- three arrays ``vx, vy, omega`` [m/s, m/s, rad/s] that broadcast against each other (numpy
  rules); results have the broadcast shape with a last axis of 3 (Fx, Fy, Mz), Jacobians a
  last two axes of 3 x 3 (rows Fx, Fy, Mz; columns vx, vy, omega);
- one table of columns, a pandas DataFrame or any mapping of column name to 1-D array, with
  the columns ``vx_mps``, ``vy_mps`` and ``omega_radps`` (the names of contensou-identify's
  files, theory.md section 6; the same quantities in another unit, as ``omega [rpm]`` or
  ``vx_kmh``, are converted as in data files; other columns are ignored); the result is a
  ``FrictionTable`` labelled ``Fx_N``, ``Fy_N``, ``Mz_Nm``, whose ``to_frame()`` is a DataFrame on the input's
  index.

The loop over points runs in C++ with the GIL released, on ``threads`` threads (1 by default;
0 for one per core).
"""

from __future__ import annotations

from typing import Any, Literal, NamedTuple, Optional, Protocol, Union, overload

import numpy as np
import numpy.typing as npt

from . import _args, _core
from ._core import ContactPatch, ExactModel, FractionalLaw, PressureProfile

ArrayLike = npt.ArrayLike

#: The columns a table of kinematics must have (SI units in the names, as in the CSV files).
KINEMATIC_COLUMNS = ("vx_mps", "vy_mps", "omega_radps")
#: The labels of the resultants (``FrictionTable``, ``to_frame()``).
RESULTANT_COLUMNS = ("Fx_N", "Fy_N", "Mz_Nm")
_ERROR_COLUMNS = ("Fx_error_N", "Fy_error_N", "Mz_error_Nm")


class ColumnTable(Protocol):
    """A table of columns: a pandas DataFrame or a mapping of column name to 1-D array."""

    def keys(self) -> Any: ...

    def __getitem__(self, key: str, /) -> Any: ...


def _frame(columns: dict[str, np.ndarray], index: Any = None) -> Any:
    try:
        import pandas as pd  # type: ignore[import-untyped]  # optional
    except ImportError:
        raise ImportError("to_frame() needs pandas (pip install pandas)") from None
    return pd.DataFrame(columns, index=index)


class ExactResults(NamedTuple):
    """Exact resultants on a grid of kinematics. ``error`` is one estimate per component (not
    one number): ``error.max(axis=-1)`` is the largest at each point."""

    resultants: np.ndarray  # (..., 3): Fx, Fy [N], Mz [N m], friction on the tire
    error: np.ndarray  # (..., 3): estimated absolute error of each component [N, N, N m]
    converged: np.ndarray  # (...): True where every component of `error` meets the tolerance

    def to_frame(self) -> Any:
        """A pandas DataFrame, a row per point (flattened in C order): Fx_N, Fy_N, Mz_Nm,
        Fx_error_N, Fy_error_N, Mz_error_Nm, converged."""
        F = self.resultants.reshape(-1, 3)
        E = self.error.reshape(-1, 3)
        cols = {name: F[:, k] for k, name in enumerate(RESULTANT_COLUMNS)}
        cols.update({name: E[:, k] for k, name in enumerate(_ERROR_COLUMNS)})
        cols["converged"] = self.converged.reshape(-1)
        return _frame(cols)


class FrictionTable:
    """Resultants of a table of kinematics, a row per input row, labelled by column.

    ``Fx_N``, ``Fy_N`` [N] and ``Mz_Nm`` [N m] (friction on the tire), ``resultants`` the same
    as (n, 3); ``jacobian`` (n, 3, 3) when asked for; ``error`` (n, 3, per component) and
    ``converged`` (n,) from the exact integrals; ``index`` the input DataFrame's index (None for
    a mapping). ``to_frame()`` gives a pandas DataFrame on that index."""

    def __init__(self, resultants: np.ndarray, index: Any = None, *,
                 jacobian: Optional[np.ndarray] = None, error: Optional[np.ndarray] = None,
                 converged: Optional[np.ndarray] = None) -> None:
        self.resultants = resultants
        self.jacobian = jacobian
        self.error = error
        self.converged = converged
        self.index = index

    @property
    def Fx_N(self) -> np.ndarray:
        return self.resultants[:, 0]

    @property
    def Fy_N(self) -> np.ndarray:
        return self.resultants[:, 1]

    @property
    def Mz_Nm(self) -> np.ndarray:
        return self.resultants[:, 2]

    def __len__(self) -> int:
        return int(self.resultants.shape[0])

    def __repr__(self) -> str:
        extra = "".join(f", {n}" for n in ("jacobian", "error") if getattr(self, n) is not None)
        return f"<FrictionTable of {len(self)} rows: Fx_N, Fy_N, Mz_Nm{extra}>"

    def to_frame(self) -> Any:
        """A pandas DataFrame: Fx_N, Fy_N, Mz_Nm (and Fx_error_N, Fy_error_N, Mz_error_Nm,
        converged from the exact integrals), on the input's index."""
        cols = {name: self.resultants[:, k] for k, name in enumerate(RESULTANT_COLUMNS)}
        if self.error is not None:
            cols.update({name: self.error[:, k] for k, name in enumerate(_ERROR_COLUMNS)})
        if self.converged is not None:
            cols["converged"] = self.converged
        return _frame(cols, self.index)


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


def _is_table(a: Any) -> bool:
    return not isinstance(a, np.ndarray) and hasattr(a, "keys") and hasattr(a, "__getitem__")


_KINEMATIC_DIMENSIONS = {"vx_mps": ("vx", "speed"), "vy_mps": ("vy", "speed"),
                         "omega_radps": ("omega", "angular rate")}


def _find_kinematic_column(names: list[str], si_name: str) -> tuple[Optional[str], float]:
    """The column holding a kinematic quantity and its factor to SI: the SI name itself, else a
    name with a unit the readers convert ('omega [rpm]', 'vx_kmh', 'vy (mm/s)'), as in data
    files (one unit table for both). (None, 1) when there is none; ValueError for two."""
    if si_name in names:
        return si_name, 1.0
    stem, dimension = _KINEMATIC_DIMENSIONS[si_name]
    found = []
    for n in names:
        name, unit = _core._split_name_and_unit(n)
        if name.lower() != stem or not unit:
            continue
        u = _core._unit(unit)
        if u is None or u[0] != dimension:
            raise ValueError(f"column '{n}': '{unit}' is not a unit of {dimension} "
                             f"({_core._units_of(dimension)})")
        found.append((n, u[1]))
    if len(found) > 1:
        raise ValueError(f"columns {', '.join(repr(f[0]) for f in found)}: two columns for "
                         f"{si_name}; keep one")
    return found[0] if found else (None, 1.0)


def _table_kinematics(data: Any) -> tuple[list[np.ndarray], Any]:
    """The columns vx_mps, vy_mps, omega_radps of a DataFrame or mapping (or the same quantities
    in other units, 'omega [rpm]', converted), as float64 arrays of one length, and the
    DataFrame's index (None for a mapping)."""
    names = [str(k) for k in data.keys()]
    found = {c: _find_kinematic_column(names, c) for c in KINEMATIC_COLUMNS}
    missing = [c for c in KINEMATIC_COLUMNS if found[c][0] is None]
    if missing:
        shown = ", ".join(names[:10]) + (", ..." if len(names) > 10 else "")
        raise ValueError(
            f"columns: missing {', '.join(repr(m) for m in missing)}: the kinematics are the "
            f"columns vx_mps, vy_mps [m/s] and omega_radps [rad/s] (or in another unit, as "
            f"'omega [rpm]'); found {shown or 'none'}")
    arrays = []
    for si_name in KINEMATIC_COLUMNS:
        name, to_si = found[si_name]
        col = data[name]
        if hasattr(col, "to_numpy") and not np.iscomplexobj(col):
            try:  # pandas: missing values (None, pd.NA) become NaN, refused as not finite
                col = col.to_numpy(dtype=np.float64, na_value=np.nan)
            except (TypeError, ValueError) as e:
                raise ValueError(f"column '{name}': not numbers ({e})") from None
        a = _real_array(f"column '{name}'", col)
        if a.ndim != 1:
            raise ValueError(f"column '{name}': expected one dimension, got shape {a.shape}")
        arrays.append(np.ascontiguousarray(a * to_si if to_si != 1.0 else a))
    if len({a.size for a in arrays}) > 1:
        raise ValueError("columns vx_mps, vy_mps, omega_radps: different lengths "
                         + ", ".join(str(a.size) for a in arrays))
    return arrays, getattr(data, "index", None)


def _kinematics(vx: Any, vy: Any, omega: Any) -> tuple[tuple[int, ...], list, Any, bool]:
    """(shape, three flat arrays, index, from a table) for either form of input."""
    if _is_table(vx):
        if vy is not None or omega is not None:
            raise TypeError("give a table of columns (vx_mps, vy_mps, omega_radps) alone, or "
                            "three arrays vx, vy, omega")
        arrays, index = _table_kinematics(vx)
        return (arrays[0].size,), arrays, index, True
    if vy is None or omega is None:
        raise TypeError("give three arrays vx, vy, omega, or one DataFrame or mapping with the "
                        "columns vx_mps, vy_mps, omega_radps")
    shape, flat = _flatten(vx, vy, omega)
    return shape, flat, None, False


@overload
def exact_resultants(
    model: Union[ExactModel, ContactPatch], vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    tolerance: float = 1e-10, threads: int = 1,
) -> ExactResults: ...


@overload
def exact_resultants(
    model: Union[ExactModel, ContactPatch], columns: ColumnTable, /, *,
    tolerance: float = 1e-10, threads: int = 1,
) -> FrictionTable: ...


def exact_resultants(
    model: Union[ExactModel, ContactPatch],
    vx: Any,
    vy: Optional[ArrayLike] = None,
    omega: Optional[ArrayLike] = None,
    *,
    tolerance: float = 1e-10,
    threads: int = 1,
) -> Union[ExactResults, FrictionTable]:
    """Exact resultants of the patch at every (vx, vy, omega) (broadcast), or at every row of
    a table with the columns vx_mps, vy_mps, omega_radps (a ``FrictionTable``).

    ``model`` is an ``ExactModel`` (build it once from a ``ContactPatch``) or a patch (the
    model is built for this call). ``tolerance`` is relative to f N (forces) and f N R (torque).
    The error is estimated per component.
    """
    if isinstance(model, ContactPatch):
        model = ExactModel(model)
    _args.instance("model", model, (ExactModel,), "an ExactModel or a ContactPatch")
    shape, (x, y, w), index, table = _kinematics(vx, vy, omega)
    n = int(np.prod(shape, dtype=np.int64))
    force = np.empty((n, 3))
    error = np.empty((n, 3))
    converged = np.empty(n, dtype=bool)
    _core._exact_loop(model, (x, y, w), force, error, converged, _args.number("tolerance", tolerance),
                      _check_threads(threads))
    if table:
        return FrictionTable(force, index, error=error, converged=converged)
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
        super().__init__(model, _args.number("tolerance", tolerance), _check_threads(threads))


def _law_on_arrays(loop: Any, law: Any, vx: Any, vy: Any, omega: Any, jacobian: bool,
                   threads: int) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray], FrictionTable]:
    """A compiled law loop over broadcast (vx, vy, omega): (..., 3) and the (..., 3, 3)
    Jacobian; or over a table's rows: a FrictionTable."""
    shape, (x, y, w), index, table = _kinematics(vx, vy, omega)
    n = int(np.prod(shape, dtype=np.int64))
    force = np.empty((n, 3))
    jac = np.empty((n, 3, 3)) if jacobian else None
    loop(law, x, y, w, force, jac, _check_threads(threads))
    if table:
        return FrictionTable(force, index, jacobian=jac)
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
    law: ExactLaw, columns: ColumnTable, /, *, jacobian: bool = False, threads: int = 1,
) -> FrictionTable: ...


@overload
def exact_law_resultants(
    law: ExactLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: bool, threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray]]: ...


def exact_law_resultants(
    law: ExactLaw,
    vx: Any,
    vy: Optional[ArrayLike] = None,
    omega: Optional[ArrayLike] = None,
    *,
    jacobian: bool = False,
    threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray], FrictionTable]:
    """The exact law at every (vx, vy, omega) (broadcast): (..., 3), and with ``jacobian=True``
    also d(Fx, Fy, Mz)/d(vx, vy, omega) as (..., 3, 3) (the exact derivative of the law; at
    v = 0 and omega = 0 its limits). Zero at rest. Given a table with the columns vx_mps,
    vy_mps, omega_radps instead: a ``FrictionTable`` (its ``jacobian`` when asked for)."""
    return _law_on_arrays(_core._exact_law_loop, law, vx, vy, omega, jacobian, threads)


@overload
def fractional_resultants(
    law: FractionalLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: Literal[False] = False, threads: int = 1,
) -> np.ndarray: ...


@overload
def fractional_resultants(
    law: FractionalLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: Literal[True], threads: int = 1,
) -> tuple[np.ndarray, np.ndarray]: ...


@overload
def fractional_resultants(
    law: FractionalLaw, columns: ColumnTable, /, *, jacobian: bool = False, threads: int = 1,
) -> FrictionTable: ...


@overload
def fractional_resultants(
    law: FractionalLaw, vx: ArrayLike, vy: ArrayLike, omega: ArrayLike, *,
    jacobian: bool, threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray]]: ...


def fractional_resultants(
    law: FractionalLaw,
    vx: Any,
    vy: Optional[ArrayLike] = None,
    omega: Optional[ArrayLike] = None,
    *,
    jacobian: bool = False,
    threads: int = 1,
) -> Union[np.ndarray, tuple[np.ndarray, np.ndarray], FrictionTable]:
    """The fractional law at every (vx, vy, omega) (broadcast): (..., 3), and with
    ``jacobian=True`` also d(Fx, Fy, Mz)/d(vx, vy, omega) as (..., 3, 3) (analytic). Given a
    table with the columns vx_mps, vy_mps, omega_radps instead: a ``FrictionTable``."""
    return _law_on_arrays(_core._fractional_loop, law, vx, vy, omega, jacobian, threads)


def shape_values(profile: Union[PressureProfile, str], rho: ArrayLike) -> np.ndarray:
    """The dimensionless shape p(rho) for rho in [0, 1] (after clipping if set; no shift) of a
    profile or a built-in profile's name ("uniform", "hertz", "seed-tire")."""
    shape = _args.profile("profile", profile)
    r = _real_array("rho", rho)
    flat = np.ascontiguousarray(r).reshape(-1)
    out = np.empty((flat.size, 1))
    shape._shape_values(flat, out)
    return out.reshape(r.shape)
