"""The landing gear from Python: configuration, landings and stability maps.

A ``LandingConfig`` is the JSON configuration of ``contensou-shimmy`` (``--print-config`` /
``--config``): it is read and validated by the app's own reader, so a file works in both. Its
values are reached by dotted name (``cfg["structure.offset_m"]``) or as attributes
(``cfg.structure.offset_m``). ``simulate_landing`` returns the time histories as arrays;
``stability_map`` runs one landing per cell, in-process by default or on a
``dask.distributed`` client, each cell computed exactly as the C++ map computes it.
"""

from __future__ import annotations

import copy
import json
import os
import re
import sys
from dataclasses import dataclass
from typing import Any, Iterator, Mapping, NamedTuple, Optional, Sequence, Union

import numpy as np

from . import _args, _core, _parts
from .friction import _check_threads

_parts.require("gear")  # ImportError naming SUNDIALS when the build left it out

MODELS = ("coupled", "decoupled", "von_schlippe")
#: Other names of the models that contensou-shimmy takes too (its --set models=..., its
#: configuration's "models"); the results name the model as in MODELS.
MODEL_ALIASES = {"nonholonomic": "von_schlippe"}


def _non_finite(node: Any, prefix: str = "") -> Optional[tuple[str, float]]:
    """The dotted name and value of the first NaN or infinity in a configuration, or None."""
    if isinstance(node, Mapping):
        for key, value in node.items():
            found = _non_finite(value, f"{prefix}.{key}" if prefix else str(key))
            if found:
                return found
    elif isinstance(node, (list, tuple)):
        for i, value in enumerate(node):
            found = _non_finite(value, f"{prefix}[{i}]")
            if found:
                return found
    elif isinstance(node, (float, np.floating)) and not np.isfinite(node):
        return prefix, float(node)
    return None


def _normalise(data: Mapping[str, Any]) -> dict[str, Any]:
    """Every key, defaults for those left out; ValueError naming a bad key or value (the
    reader's line and column refer to no file here, so they are left out). A NaN or infinity
    is named as such (JSON has no such numbers: the reader would see invalid JSON)."""
    bad = _non_finite(data)
    if bad:
        raise ValueError(f"{bad[0]} = {bad[1]}: NaN and infinities are not allowed (a finite "
                         "number is needed)")
    try:
        return json.loads(_core._normalise_config(json.dumps(data), "<configuration>"))
    except ValueError as e:
        raise ValueError(re.sub(r"^<configuration>:\d+:(\d+:)? ", "", str(e))) from None


class _Section:
    """Attribute view of a nested part of a configuration (cfg.structure.offset_m)."""

    def __init__(self, config: "LandingConfig", prefix: str):
        object.__setattr__(self, "_config", config)
        object.__setattr__(self, "_prefix", prefix)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self._config[f"{self._prefix}.{name}"]
        except KeyError:
            raise AttributeError(f"{self._prefix}.{name}") from None

    def __setattr__(self, name: str, value: Any) -> None:
        self._config[f"{self._prefix}.{name}"] = value

    def __dir__(self) -> list[str]:
        return list(self._config._node(self._prefix))

    def __repr__(self) -> str:
        return f"{self._prefix}: {json.dumps(self._config._node(self._prefix), sort_keys=True)}"


class LandingConfig:
    """The shimmy app's configuration: gear structure, sliding and rolling tire, landing
    scenario, solver, shimmy criterion, models and maps (docs/shimmy.md)."""

    def __init__(self, data: Optional[Mapping[str, Any]] = None):
        self._data: dict[str, Any] = _normalise(data or {})

    # -- construction and export -------------------------------------------------------------
    @classmethod
    def default(cls) -> "LandingConfig":
        return cls()

    @classmethod
    def from_json(cls, source: Union[str, os.PathLike]) -> "LandingConfig":
        """From a JSON file (a path) or JSON text; keys left out keep their defaults."""
        text, name = os.fspath(source), "<text>"
        if not text.lstrip().startswith("{"):
            name = text
            try:
                with open(text, encoding="utf-8") as f:
                    text = f.read()
            except OSError as e:
                raise ValueError(f"{name}: cannot open the configuration file ({e.strerror})") from None
        cfg = cls.__new__(cls)
        cfg._data = json.loads(_core._normalise_config(text, name))
        return cfg

    def to_dict(self) -> dict[str, Any]:
        return copy.deepcopy(self._data)

    def to_json(self, path: Optional[Union[str, os.PathLike]] = None, indent: int = 2) -> str:
        """The configuration as JSON text (every key), written to ``path`` if given; the app
        reads it with ``--config``."""
        text = json.dumps(self._data, indent=indent, sort_keys=True) + "\n"
        if path is not None:
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
        return text

    def _text(self) -> str:
        return json.dumps(self._data)

    # -- access by dotted name ---------------------------------------------------------------
    @staticmethod
    def parameter_names() -> list[str]:
        """The numeric gear parameters (the names a map axis takes)."""
        return list(_core._gear_parameter_names())

    @staticmethod
    def keys() -> list[dict[str, Any]]:
        """Every configuration key, from the app's key table (``contensou-shimmy --print-keys``,
        docs/shimmy.md): ``name``, ``type``, ``unit``, ``values`` (the valid values in words),
        ``default`` and ``help``."""
        out = []
        for k in _core._config_keys():
            k = dict(k)
            k["default"] = json.loads(k["default"])
            out.append(k)
        return out

    def _node(self, dotted: str) -> Any:
        node: Any = self._data
        for part in dotted.split("."):
            if not isinstance(node, dict) or part not in node:
                raise KeyError(dotted)
            node = node[part]
        return node

    def __getitem__(self, dotted: str) -> Any:
        node = self._node(dotted)
        return copy.deepcopy(node) if isinstance(node, (dict, list)) else node

    def __setitem__(self, dotted: str, value: Any) -> None:
        self._node(dotted)  # KeyError for an unknown key
        data = copy.deepcopy(self._data)
        node = data
        parts = dotted.split(".")
        for part in parts[:-1]:
            node = node[part]
        node[parts[-1]] = value.item() if isinstance(value, np.generic) else value
        self._data = _normalise(data)  # validated as the app validates: ValueError if bad

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        data = self.__dict__.get("_data", {})
        if name not in data:
            raise AttributeError(name)
        return _Section(self, name) if isinstance(data[name], dict) else copy.deepcopy(data[name])

    def replace(self, **changes: Any) -> "LandingConfig":
        """A copy with values changed, by dotted name with '__' for '.':
        ``cfg.replace(structure__offset_m=0.3)``."""
        out = copy.deepcopy(self)
        for key, value in changes.items():
            out[key.replace("__", ".")] = value
        return out

    def __eq__(self, other: object) -> bool:
        return isinstance(other, LandingConfig) and self._data == other._data

    def __repr__(self) -> str:
        return f"LandingConfig({json.dumps(self._data, sort_keys=True)})"


def _config(config: Union[LandingConfig, Mapping[str, Any], None]) -> LandingConfig:
    if config is None:
        return LandingConfig()
    return config if isinstance(config, LandingConfig) else LandingConfig(config)


def _model(model: str) -> str:
    """The model's name (MODELS) for any name contensou-shimmy takes (MODEL_ALIASES too)."""
    if not isinstance(model, str):
        _args.wrong_type("model", model, f"a model's name ({', '.join(MODELS)})")
    try:
        return str(_core._contact_model(model))
    except ValueError:
        aliases = ", ".join(f"{a} for {m}" for a, m in MODEL_ALIASES.items())
        raise ValueError(f"model = {model!r}: must be one of {', '.join(MODELS)} (also "
                         f"{aliases})") from None


@dataclass
class LandingResult:
    """A simulated landing: time histories (``t``, ``history[:, k]`` or ``result["psi_rad"]``;
    the columns of contensou-shimmy's CSV), events and shimmy metrics."""

    contact: str
    columns: list[str]
    history: np.ndarray  # (samples, len(columns))
    events: list[tuple[float, str]]
    metrics: dict[str, Any]

    @property
    def t(self) -> np.ndarray:
        return self.history[:, 0]

    def __getitem__(self, column: str) -> np.ndarray:
        try:
            return self.history[:, self.columns.index(column)]
        except ValueError:
            raise KeyError(f"{column} (columns: {', '.join(self.columns)})") from None

    @property
    def shimmy(self) -> bool:
        return bool(self.metrics["shimmy"])

    def to_frame(self) -> Any:
        """The history as a pandas DataFrame, one column per name in ``columns`` (SI units)."""
        import pandas as pd  # type: ignore[import-untyped]  # optional

        return pd.DataFrame(self.history, columns=self.columns)

    def to_dataframe(self) -> Any:
        """The same as ``to_frame()`` (the name of the friction results), kept for old code."""
        return self.to_frame()


def simulate_landing(
    config: Union[LandingConfig, Mapping[str, Any], None] = None,
    model: str = "coupled",
    *,
    record: bool = True,
) -> LandingResult:
    """One landing with the configuration's solver and shimmy criterion (CVODE, events)."""
    raw = _core._simulate_landing(_config(config)._text(), _model(model), bool(record))
    return LandingResult(
        contact=raw["contact"],
        columns=list(raw["columns"]),
        history=np.asarray(raw["history"]),
        events=[(float(t), str(w)) for t, w in raw["events"]],
        metrics=dict(raw["metrics"]),
    )


class MapAxis(NamedTuple):
    """An axis of a map: a gear parameter by dotted name, from, to and number of points."""

    parameter: str
    start: float
    stop: float
    points: int

    def values(self) -> np.ndarray:
        # The same doubles as the C++ MapAxis::value(i).
        if self.points == 1:
            return np.array([self.start])
        return np.array(
            [self.start + (self.stop - self.start) * i / (self.points - 1) for i in range(self.points)]
        )


AxisLike = Union[MapAxis, Sequence[Any], Mapping[str, Any]]


def _axis(a: AxisLike) -> MapAxis:
    if isinstance(a, Mapping):
        keys = ("parameter", "from", "to", "points")
        missing = [k for k in keys if k not in a]
        unknown = [str(k) for k in a if k not in keys]
        if missing or unknown:
            raise ValueError(f"axis {dict(a)!r}: " + (f"missing {', '.join(missing)}" if missing
                             else f"unknown key {', '.join(unknown)}")
                             + " (an axis is {parameter, from, to, points})")
        a = (a["parameter"], a["from"], a["to"], a["points"])
    try:
        parameter, start, stop, points = a
    except (TypeError, ValueError):
        raise ValueError(f"axis {a!r}: expected (parameter, from, to, points)") from None
    if not isinstance(parameter, str):
        _args.wrong_type("axis parameter", parameter, "a gear parameter's dotted name")
    start = _args.number(f"axis {parameter}: from", start)
    stop = _args.number(f"axis {parameter}: to", stop)
    n = _args.number(f"axis {parameter}: points", points)
    if not n.is_integer() or not 1 <= n <= 10000:
        raise ValueError(f"axis {parameter}: points = {points!r}: must be an integer in 1..10000")
    return MapAxis(parameter, start, stop, int(n))


def _is_one_axis(a: Any) -> bool:
    """An axis itself (not a pair of them): a MapAxis, a mapping, or (parameter, ...)."""
    return (isinstance(a, (MapAxis, Mapping))
            or (isinstance(a, Sequence) and not isinstance(a, str) and len(a) > 0
                and isinstance(a[0], str)))


def _axes(cfg: "LandingConfig", axes: Any) -> tuple[MapAxis, MapAxis]:
    """(x, y) from two axes; from one axis (alone or in a sequence of one), a 1-D sweep: y is a
    1-point axis of another gear parameter at its configured value, so it changes nothing (the
    C++ map is a grid of two axes; a 1-point axis is its 1-D form)."""
    if _is_one_axis(axes):
        axes = (axes,)
    if isinstance(axes, str) or not isinstance(axes, Sequence) or not 1 <= len(axes) <= 2:
        raise ValueError(f"axes = {axes!r}: give (x, y), two axes (parameter, from, to, points), "
                         "or one axis for a 1-D sweep")
    x = _axis(axes[0])
    if len(axes) == 2:
        return x, _axis(axes[1])
    for other in _core._gear_parameter_names():
        try:
            value = cfg[other]
        except KeyError:
            continue
        if other != x.parameter and isinstance(value, (int, float)) and not isinstance(value, bool):
            return x, MapAxis(other, float(value), float(value), 1)
    raise ValueError(f"axes: no other gear parameter to hold fixed for a 1-D sweep over {x.parameter}")


@dataclass
class StabilityMapResult:
    """Cells on a grid: arrays (y.points, x.points), row j at y value j, column i at x value i
    (the row-major order of the C++ map)."""

    x: MapAxis
    y: MapAxis
    model: str
    growth_rate_per_s: np.ndarray
    frequency_hz: np.ndarray
    last_amplitude_rad: np.ndarray
    shimmy: np.ndarray  # bool
    valid: np.ndarray  # bool: enough oscillation to estimate a growth rate
    error: np.ndarray  # str, "" where the landing integrated

    @property
    def x_values(self) -> np.ndarray:
        return self.x.values()

    @property
    def y_values(self) -> np.ndarray:
        return self.y.values()

    @classmethod
    def _from_cells(cls, x: MapAxis, y: MapAxis, model: str, cells: Sequence[tuple]) -> "StabilityMapResult":
        shape = (y.points, x.points)

        def column(k: int, dtype: Any) -> np.ndarray:
            return np.array([c[k] for c in cells], dtype=dtype).reshape(shape)

        return cls(x, y, model, column(2, float), column(3, float), column(4, float),
                   column(5, bool), column(6, bool), column(7, object))

    def cells(self) -> Iterator[dict[str, Any]]:
        xs, ys = self.x_values, self.y_values
        for j in range(self.y.points):
            for i in range(self.x.points):
                yield {
                    self.x.parameter: xs[i],
                    self.y.parameter: ys[j],
                    "growth_rate_per_s": self.growth_rate_per_s[j, i],
                    "frequency_hz": self.frequency_hz[j, i],
                    "final_amplitude_rad": self.last_amplitude_rad[j, i],
                    "shimmy": bool(self.shimmy[j, i]),
                    "valid": bool(self.valid[j, i]),
                    "error": self.error[j, i],
                }


def _cell_task(k: int, config: str, model: str, x: tuple, y: tuple) -> tuple:
    """One cell (k in row-major order): picklable plain data in and out, for Dask workers."""
    return tuple(_core._map_cell(config, model, x, y, k % x[3], k // x[3]))


def _progress(total: int, enabled: Optional[bool], label: str) -> Any:
    """A tqdm bar when asked for (True), or by default (None) only when standard error is a
    terminal: no bar in logs, CI output or a notebook's captured stream."""
    if enabled is None:
        enabled = sys.stderr is not None and sys.stderr.isatty()
    if enabled:
        try:
            from tqdm.auto import tqdm  # type: ignore[import-untyped]

            return tqdm(total=total, desc=label, unit="cell")
        except ImportError:
            pass

    class _Silent:
        def update(self, n: int = 1) -> None:
            pass

        def close(self) -> None:
            pass

    return _Silent()


def stability_map(
    config: Union[LandingConfig, Mapping[str, Any], None],
    axes: Union[AxisLike, Sequence[AxisLike]],
    client: Any = None,
    *,
    model: str = "coupled",
    progress: Optional[bool] = None,
) -> StabilityMapResult:
    """A stability map over two gear parameters: one landing per cell.

    ``axes`` = (x, y), each (parameter, from, to, points), a ``MapAxis`` or a dict as in the
    app's configuration; or one axis alone for a 1-D sweep (one row: y is then a 1-point axis
    of another parameter at its configured value, which changes nothing). Cells run in this
    process one after another by default, or as tasks on ``client`` (a
    ``dask.distributed.Client``). A tqdm progress bar counts cells when
    ``progress`` is True, or by default when standard error is a terminal."""
    cfg = _config(config)
    x, y = _axes(cfg, axes)
    if x.parameter == y.parameter:
        raise ValueError(f"axes: x and y are both {x.parameter}: give two different parameters "
                         "(or one axis for a 1-D sweep)")
    model = _model(model)
    text = cfg._text()
    names = set(_core._gear_parameter_names())
    for a in (x, y):
        if a.parameter not in names:
            raise ValueError(f"map parameter = {a.parameter}: is not a gear parameter")
    total = x.points * y.points
    bar = _progress(total, progress, f"{model} {x.parameter.split('.')[-1]} x {y.parameter.split('.')[-1]}")
    cells: list[Any] = [None] * total
    try:
        if client is None:
            for k in range(total):
                cells[k] = _cell_task(k, text, model, x, y)
                bar.update(1)
        else:
            from distributed import as_completed  # optional: only with a client

            futures = client.map(
                _cell_task, range(total), config=text, model=model, x=tuple(x), y=tuple(y),
                pure=False,
            )
            index = {f.key: k for k, f in enumerate(futures)}
            for future in as_completed(futures):
                cells[index[future.key]] = future.result()
                bar.update(1)
    finally:
        bar.close()
    return StabilityMapResult._from_cells(x, y, model, cells)


def stability_map_native(
    config: Union[LandingConfig, Mapping[str, Any], None],
    axes: Union[AxisLike, Sequence[AxisLike]],
    *,
    model: str = "coupled",
    threads: int = 0,
) -> StabilityMapResult:
    """The same map by the C++ ``stability_map`` on threads (0: one per core), as
    contensou-shimmy --map runs it."""
    cfg = _config(config)
    x, y = _axes(cfg, axes)
    if x.parameter == y.parameter:
        raise ValueError(f"axes: x and y are both {x.parameter}: give two different parameters "
                         "(or one axis for a 1-D sweep)")
    model = _model(model)
    cells = _core._stability_map_cpp(cfg._text(), model, x, y, _check_threads(threads))
    return StabilityMapResult._from_cells(x, y, model, cells)


_SWEEP_COLUMNS = [
    "direction", "value", "state", "amplitude_rad", "torque_link_nm", "trend_per_s",
    "frequency_hz", "eigen_growth_rate_per_s", "eigen_frequency_hz", "onset_s", "run_s", "valid",
    "error",
]


def bifurcation_sweep(
    config: Union[LandingConfig, Mapping[str, Any], None],
    axis: AxisLike,
    *,
    model: str = "coupled",
    threads: int = 0,
) -> Any:
    """The braked slide's bifurcation diagram over one gear parameter, as contensou-shimmy
    --bifurcation computes it: the torsional limit cycle by continuation, swept up from a small
    kick and down from a large swing (``direction`` "up" or "down"), each point with its settled
    amplitude, torque-link load, amplitude trend, simulated frequency, the linearisation's growth
    rate and frequency, and the time to onset (up sweep, where it settles on a cycle or still
    grows: from a kick at the quasi-steady state until a swing first reaches the threshold).
    Returns a pandas DataFrame; ``df.attrs["linear_boundary"]`` is the parameter where the
    eigenvalue growth first changes sign (NaN if it does not). Both directions run on threads
    (0: one per core)."""
    import pandas as pd

    cfg = _config(config)
    a = _axis(axis)
    rows, boundary = _core._bifurcation_sweep(cfg._text(), _model(model), a, _check_threads(threads))
    df = pd.DataFrame([tuple(r) for r in rows], columns=_SWEEP_COLUMNS)
    df = df.rename(columns={"value": a.parameter})
    df.attrs["linear_boundary"] = boundary
    df.attrs["parameter"] = a.parameter
    df.attrs["model"] = _model(model)
    return df
