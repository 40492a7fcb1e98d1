"""The one rule for the arguments of the package's functions and constructors.

- A number is an ``int``, a ``float`` or a numpy scalar (any ``numbers.Real``, a 0-d array of
  one); not a ``bool`` and not a ``str``: ``radius='0.087'`` is a ``TypeError`` naming the
  argument, never converted. Its range is checked by the C++ library (``ValueError`` naming the
  value and the range).
- An integer is a number with an integral value (``3`` or ``3.0``).
- A pressure profile is a ``PressureProfile`` or the name of a built-in one (``"uniform"``,
  ``"hertz"``, ``"seed-tire"``: the names ``identify`` and the apps take).

A wrong type gives a short ``TypeError`` naming the argument and what it accepts.
"""

from __future__ import annotations

import numbers as _numbers
from collections.abc import Iterable, Mapping
from typing import Any, Callable, Optional

import numpy as np

from . import _core

#: The built-in profiles by the name the apps and ``identify(profile=...)`` take.
BUILT_IN_PROFILES: dict[str, Callable[[], Any]] = {
    "uniform": _core.uniform_profile,
    "hertz": _core.hertz_profile,
    "seed-tire": _core.seed_tire_profile,
}


def _shown(value: Any) -> str:
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def number(name: str, value: Any) -> float:
    """``value`` as a float if it is a number (module docstring), else TypeError naming ``name``."""
    if isinstance(value, np.ndarray) and value.ndim == 0 and value.dtype.kind in "iuf":
        value = value[()]
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, _numbers.Real):
        raise TypeError(
            f"{name}: a number is required, not {type(value).__name__} {_shown(value)}")
    return float(value)


def optional_number(name: str, value: Any) -> Optional[float]:
    """None, or ``value`` as a number (``number``)."""
    return None if value is None else number(name, value)


def integer(name: str, value: Any) -> int:
    """``value`` as an int if it is a number with an integral value, else TypeError or
    ValueError naming ``name``."""
    x = number(name, value)
    if not x.is_integer():
        raise ValueError(f"{name} = {_shown(value)}: must be a whole number")
    return int(x)


def numbers(name: str, value: Any) -> list[float]:
    """A sequence (list, tuple, 1-D numpy array, pandas Series) of numbers as a list of floats,
    else TypeError naming ``name``, or the first element that is not a number (``rho[2]``)."""
    if hasattr(value, "to_numpy") and not isinstance(value, np.ndarray):
        value = value.to_numpy()
    if isinstance(value, np.ndarray):
        if value.ndim != 1 or value.dtype.kind not in "iuf":
            wrong_type(name, value, "a sequence of numbers")
        return [float(x) for x in value]
    if (isinstance(value, (str, bytes, Mapping)) or not isinstance(value, Iterable)
            or not hasattr(value, "__len__")):
        wrong_type(name, value, "a sequence of numbers")
    return [number(f"{name}[{i}]", x) for i, x in enumerate(value)]


def profile(name: str, value: Any) -> Any:
    """A ``PressureProfile`` as it is, or the built-in profile of that name; else TypeError
    (or ValueError for an unknown name) naming ``name``."""
    if isinstance(value, _core.PressureProfile):
        return value
    if isinstance(value, str):
        if value in BUILT_IN_PROFILES:
            return BUILT_IN_PROFILES[value]()
        raise ValueError(f"{name} = {value!r}: a built-in profile is one of "
                         f"{', '.join(BUILT_IN_PROFILES)} (or give a PressureProfile)")
    raise TypeError(f"{name}: a PressureProfile or a built-in profile's name "
                    f"({', '.join(BUILT_IN_PROFILES)}) is required, not "
                    f"{type(value).__name__} {_shown(value)}")


def wrong_type(name: str, value: Any, accepted: str) -> None:
    """Raises the short TypeError: ``name`` takes ``accepted``, not ``value``."""
    raise TypeError(f"{name}: {accepted} is required, not {type(value).__name__} {_shown(value)}")


def instance(name: str, value: Any, kinds: tuple[type, ...], accepted: str) -> Any:
    """``value`` if it is one of ``kinds``, else the short TypeError (``wrong_type``)."""
    if not isinstance(value, kinds):
        wrong_type(name, value, accepted)
    return value
