"""Identification of the friction law from measured diagrams (contensou-identify from Python).

``identify`` takes a pandas DataFrame (or any mapping of column name to array, or a numpy
structured or 2-D array) with the CSV's column names (theory.md section 6: vx_mps, vy_mps,
omega_radps and any of Fx_N, Fy_N, Mz_Nm, optional Fz_N, t_s; NaN = not measured), or the path
of such a CSV, and runs the fit and the closed loop of the app. ``to_json()`` gives the app's
report (``contensou-identify --json``) byte for byte.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Dict, Mapping, Optional, Sequence, Union

import numpy as np

from . import _args, _core, _parts

_parts.require("identification")  # ImportError naming Ceres when the build left it out

COLUMNS = ("vx_mps", "vy_mps", "omega_radps", "Fx_N", "Fy_N", "Mz_Nm", "Fz_N", "t_s")
CHANNELS = ("Fx_N", "Fy_N", "Mz_Nm")


@dataclass(frozen=True)
class Parameter:
    """One parameter of a fitted model."""

    name: str
    value: float
    ci95: Optional[tuple[float, float]]  # None: fixed, derived or not determined by the data
    std_error: Optional[float]
    unit: str
    fixed: bool = False
    determined: bool = True
    derived_from_profile: bool = False


@dataclass
class LoopStep:
    """One fitted candidate of the closed loop (a row of the app's loop table)."""

    step: int
    effect: str
    detail: str
    accepted: bool
    removed_in_backward_pass: bool
    verdict: str
    parameters: dict[str, Parameter]
    lr_p_value: float
    threshold: float
    bic_before: float
    bic_after: float
    error_before: float
    error_after: float
    ambiguous_with: list[str]
    separation: list[str]
    prediction_before: np.ndarray  # (n, 3) model at the data points before the step
    prediction_after: np.ndarray  # (n, 3) after it
    report: dict[str, Any] = field(repr=False)  # the step as in the JSON report


def _parameters(params: Mapping[str, Any]) -> dict[str, Parameter]:
    out = {}
    for name, p in params.items():
        ci = p.get("ci95")
        out[name] = Parameter(
            name=name,
            value=p["value"],
            ci95=None if ci is None else (ci[0], ci[1]),
            std_error=p.get("std_error"),
            unit=p.get("unit", ""),
            fixed=p.get("fixed", False),
            determined=p.get("determined", True),
            derived_from_profile=p.get("derived_from_profile", False),
        )
    return out


class IdentificationResult:
    """The result of ``identify``: the final model's parameters with 95 % intervals and
    covariance, the closed loop's steps, and predictions and residuals as (n, 3) arrays
    (columns Fx, Fy, Mz; NaN where the channel was not measured)."""

    def __init__(self, raw: dict[str, Any]):
        # kinematics, measured and the predictions are (n, 3) over the rows fitted (``rows``);
        # a value left out as a gross error (``outliers``) is NaN in ``measured``.
        self._json: str = raw["json"]
        self.report: dict[str, Any] = json.loads(self._json)
        final = self.report["final"]
        self.model: str = final["name"]  # "fractional" or "exact"
        self.parameters: dict[str, Parameter] = _parameters(final["params"])
        self.base_parameters: dict[str, Parameter] = _parameters(self.report["base"]["params"])
        self.accepted_effects: list[str] = list(self.report["accepted_effects"])
        self.structure_remains: bool = bool(self.report.get("structure_remains", False))
        self.error_before: float = self.report["error_before"]
        self.error_after: float = self.report["error_after"]
        cov = raw["covariance"]
        self.covariance_names: list[str] = list(cov["names"])
        self.covariance: np.ndarray = np.asarray(cov["matrix"])
        self.text: str = raw["text"]  # the report as contensou-identify prints it
        # The rows fitted (their index in the data given) and the gross errors left out.
        self.rows: np.ndarray = np.asarray(raw["rows"]).astype(np.int64)
        self.outliers: list[dict[str, Any]] = list(self.report["input"].get("outliers", []))
        # Values first taken for gross errors that the final model fits (put back in the fit).
        self.outliers_put_back: list[dict[str, Any]] = list(
            self.report["input"].get("outliers_put_back", [])
        )
        self.kinematics: np.ndarray = np.asarray(raw["kinematics"])
        self.measured: np.ndarray = np.asarray(raw["measured"])
        self.prediction: np.ndarray = np.asarray(raw["final_prediction"])
        self.base_prediction: np.ndarray = np.asarray(raw["base_prediction"])
        self.steps: list[LoopStep] = []
        for s, arrays in zip(self.report["steps"], raw.get("steps", [])):
            self.steps.append(
                LoopStep(
                    step=s["step"],
                    effect=s["chosen"],
                    detail=s["detail"],
                    accepted=s["accepted"],
                    removed_in_backward_pass=s["removed_in_backward_pass"],
                    verdict=s["verdict"],
                    parameters=_parameters(s["parameters"]),
                    lr_p_value=s["lr_p_value"],
                    threshold=s["threshold"],
                    bic_before=s["bic_before"],
                    bic_after=s["bic_after"],
                    error_before=s["error_before"],
                    error_after=s["error_after"],
                    ambiguous_with=list(s["ambiguous_with"]),
                    separation=list(s["separation"]),
                    prediction_before=np.asarray(arrays["prediction_before"]),
                    prediction_after=np.asarray(arrays["prediction_after"]),
                    report=s,
                )
            )

    def predict(
        self,
        data: Union[str, os.PathLike, Mapping[str, Any], np.ndarray, Any],
        *,
        columns: Optional[Union[str, Mapping[str, Any]]] = None,
        normal_load: Optional[Union[float, Sequence[float]]] = None,
    ) -> Any:
        """The final model at the rows of ``data`` (read as ``identify`` reads it; rows need
        only their motion), both ways: the friction from the motion (``pred_Fx_N``,
        ``pred_Fy_N``, ``pred_Mz_Nm``) and the direction of motion each row's measured force
        would cause (``pred_twist_vx``, ``pred_twist_vy``, ``pred_twist_omegaR``: the unit vector
        of (vx, vy, omega R) whose model force is parallel to the measured (Fx, Fy, Mz / R), the
        normal of the model's limit surface there; NaN where a channel is not measured), and
        ``wrench_misfit_deg``, the angle the model's force there still differs by.

        Returns a pandas DataFrame (one row a row of ``data``, its index when ``data`` is a
        DataFrame) with the scores in ``.attrs["scores"]`` (median and mean motion angle [deg],
        force relative error and angle; over the rows with all three channels), or a dict of
        arrays with a ``"scores"`` entry when pandas is not installed."""
        model = self.report.get("model")
        if model is None:
            raise ValueError("this report has no model to predict with (made by an older "
                             "contensou: identify again)")
        items, loads = _items_and_loads(data, normal_load, None, scalar_load_per_table=True)
        raw = _core._predict(items, loads, _renames(columns), json.dumps(model))
        out = {"pred_Fx_N": raw["wrench"][:, 0], "pred_Fy_N": raw["wrench"][:, 1],
               "pred_Mz_Nm": raw["wrench"][:, 2], "pred_twist_vx": raw["twist"][:, 0],
               "pred_twist_vy": raw["twist"][:, 1], "pred_twist_omegaR": raw["twist"][:, 2],
               "wrench_misfit_deg": raw["misfit_deg"]}
        try:
            import pandas as pd  # type: ignore[import-untyped]  # optional
        except ImportError:
            return {**out, "scores": dict(raw["scores"])}
        frame_index = getattr(data, "index", None) if hasattr(data, "iloc") else None
        index = frame_index if frame_index is not None and len(frame_index) == len(
            out["pred_Fx_N"]) else None
        frame = pd.DataFrame(out, index=index)
        frame.attrs["scores"] = dict(raw["scores"])
        return frame

    @property
    def names(self) -> list[str]:
        return list(self.parameters)

    @property
    def values(self) -> np.ndarray:
        return np.array([p.value for p in self.parameters.values()])

    @property
    def ci95(self) -> np.ndarray:
        """(p, 2): lower and upper 95 % bounds, NaN where there is no interval."""
        return np.array(
            [p.ci95 if p.ci95 is not None else (np.nan, np.nan) for p in self.parameters.values()]
        ).reshape(-1, 2)

    @property
    def residuals(self) -> np.ndarray:
        """(n, 3): measured minus the final model, NaN where not measured."""
        return self.measured - self.prediction

    @property
    def base_residuals(self) -> np.ndarray:
        """(n, 3): measured minus the base model (the fractional law)."""
        return self.measured - self.base_prediction

    @property
    def psi(self) -> np.ndarray:
        """|v| / |omega R| of each point (inf for pure sliding)."""
        k = self.kinematics
        v = np.hypot(k[:, 0], k[:, 1])
        u = np.abs(k[:, 2]) * self.report["input"]["radius_m"]
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(u > 0, v / np.where(u > 0, u, 1.0), np.inf)

    def to_json(self) -> str:
        """The report exactly as ``contensou-identify --json`` writes it (same schema, same
        bytes for the same input; ends with a newline)."""
        return self._json + "\n"

    def __repr__(self) -> str:
        body = ", ".join(f"{p.name}={p.value:.6g}" for p in self.parameters.values())
        return f"<IdentificationResult {self.model}: {body}; effects {self.accepted_effects}>"


def _cells(data: Any, name: Any) -> Union[np.ndarray, list[str]]:
    """A column as float64 numbers (NaN = empty), or as text when it holds other things: the
    reader refuses text only in a column it reads, naming the row."""
    col = data[name]
    dtype = getattr(col, "dtype", None)
    if (np.issubdtype(dtype, np.complexfloating) if isinstance(dtype, np.dtype)
            else np.iscomplexobj(np.asarray(col))):
        raise ValueError(f"column '{name}': complex values; give real numbers (the imaginary part "
                         "would be lost)")
    try:
        if hasattr(col, "to_numpy"):  # pandas Series: missing values (None, pd.NA) become NaN
            arr = col.to_numpy(dtype=np.float64, na_value=np.nan)
        else:
            arr = np.asarray(col, dtype=np.float64)
    except (TypeError, ValueError):
        values = col.tolist() if hasattr(col, "tolist") else list(col)
        return ["" if v is None or (isinstance(v, float) and np.isnan(v)) else str(v)
                for v in values]
    if arr.ndim != 1:
        raise ValueError(f"column '{name}': expected one dimension, got shape {arr.shape}")
    return np.ascontiguousarray(arr)


def _table_of(data: Any) -> tuple[list[str], list[Any]]:
    """Column names and columns of a DataFrame, mapping, structured or plain 2-D array."""
    if isinstance(data, np.ndarray) and data.dtype.names is None:
        if np.iscomplexobj(data):
            raise ValueError("complex values; give real numbers (the imaginary part would be lost)")
        a = np.asarray(data, dtype=np.float64)
        if a.ndim != 2 or not 4 <= a.shape[1] <= len(COLUMNS):
            raise ValueError(
                f"a plain array must be (n, k) with 4 <= k <= 8 columns in the order "
                f"{', '.join(COLUMNS)}; got shape {a.shape}"
            )
        return list(COLUMNS[: a.shape[1]]), [np.ascontiguousarray(a[:, k]) for k in range(a.shape[1])]
    names = list(data.dtype.names) if isinstance(data, np.ndarray) else list(data.keys())
    text = [str(n) for n in names]
    for j, n in enumerate(text):
        if n in text[:j]:
            raise ValueError(f"duplicate column '{n}' (columns {text.index(n) + 1} and {j + 1}): "
                             "which one holds the data? Rename one")
    return text, [_cells(data, n) for n in names]


def _renames(
    columns: Optional[Union[str, Mapping[str, Any]]]
) -> Optional[Union[str, Dict[str, Any]]]:
    if columns is None or isinstance(columns, str):
        return columns
    if not isinstance(columns, Mapping):
        raise TypeError(
            f"columns: expected a mapping {{quantity: column}} or 'vx=Speed,...', "
            f"got {type(columns).__name__}"
        )
    # {'extra': ['T', 'P']}: several columns kept as recorded variables (or 'ignore': left out)
    return {str(q): [str(x) for x in c] if isinstance(c, (list, tuple)) else str(c)
            for q, c in columns.items()}


def _flag(name: str, value: Any) -> bool:
    """A bool (or numpy bool), else the short TypeError: 'no' or 0.5 is not a choice."""
    if not isinstance(value, (bool, np.bool_)):
        _args.wrong_type(name, value, "True or False")
    return bool(value)


def _text(name: str, value: Any) -> str:
    """A str, else the short TypeError (a number is not a name)."""
    if not isinstance(value, str):
        _args.wrong_type(name, value, "a str")
    return value


def identify(
    data: Union[str, os.PathLike, Mapping[str, Any], np.ndarray, Any],
    *,
    radius: float,
    profile: Optional[Union[str, os.PathLike]] = None,
    pressure: Optional[float] = None,
    normal_load: Optional[Union[float, Sequence[float]]] = None,
    loop: bool = True,
    fix: Optional[Mapping[str, float]] = None,
    loss: str = "none",
    loss_scale: float = 2.0,
    noise_model: str = "auto",
    noise_scale: Optional[tuple[float, float, float]] = None,
    alpha: float = 1e-3,
    speed_inside_integrals: bool = True,
    profile_smoothing: int = 0,
    profile_clip: bool = False,
    outliers: bool = True,
    resamples: int = 5,
    admissible_law: bool = False,
    columns: Optional[Union[str, Mapping[str, Any]]] = None,
    source: Optional[str] = None,
) -> IdentificationResult:
    """Fits the fractional law to measured diagrams and, with ``loop=True`` (the default),
    closes the loop, exactly as ``contensou-identify`` does: the same keys (``normal_load`` is
    ``--normal-load`` there), the same reading of columns and units, the same search for gross
    errors, the same report (``to_json()``, ``text``).

    ``data`` is a CSV path, a DataFrame, a mapping of column name to array, or a structured or
    (n, k) array in the order vx_mps, vy_mps, omega_radps, Fx_N, Fy_N, Mz_Nm, Fz_N, t_s; or a
    list of them, fitted together (each row keeping its table and line), with ``normal_load``
    one load for every table or a list of one a table (for their rows without an Fz value). Rows
    with an Fz value are each fitted at their own load.
    Columns may carry units in their names ('vx [km/h]', omega_rpm, 'Fx [kN]'): they are
    converted to SI. ``columns`` maps other names: ``{"vx": "Speed [km/h]"}`` or
    ``"vx=Speed [km/h],omega=Rate"``; ``{"extra": ["Fx_raw"]}`` keeps a column whose name looks
    like a channel's as a recorded variable, ``{"ignore": [...]}`` leaves columns out. Every
    other numeric column is kept as a recorded variable (listed in the report with its range);
    a column that looks like a misspelt channel, or holds a force no channel reads, is an
    error. ``source`` names the data in the report (default: the
    path, or "<DataFrame>" / "<arrays>"). Errors in in-memory data name the row (1-based) and
    its index.

    The keys:
    """
    # Numbers by the package's one rule (contensou._args: a str is a TypeError, not converted).
    request = _core._IdentifyRequest()
    request.radius = _args.number("radius", radius)
    if profile is not None and not isinstance(profile, (str, os.PathLike)):
        _args.wrong_type("profile", profile, "a built-in profile's name (uniform, hertz, "
                         "seed-tire) or the path of a profile CSV")
    request.profile = "" if profile is None else os.fspath(profile)
    request.pressure = _args.optional_number("pressure", pressure)
    request.profile_smoothing = _args.integer("profile_smoothing", profile_smoothing)
    request.profile_clip = _flag("profile_clip", profile_clip)
    request.fix = {_text("fix", k): _args.number(f"fix[{k!r}]", v) for k, v in (fix or {}).items()}
    request.loss = _text("loss", loss)
    request.loss_scale = _args.number("loss_scale", loss_scale)
    request.noise_model = _text("noise_model", noise_model)
    request.noise_scale = [] if noise_scale is None else [
        _args.number(f"noise_scale[{i}]", x) for i, x in enumerate(noise_scale)]
    request.loop = _flag("loop", loop)
    request.alpha = _args.number("alpha", alpha)
    request.speed_inside_integrals = _flag("speed_inside_integrals", speed_inside_integrals)
    request.outliers = _flag("outliers", outliers)
    request.resamples = _args.integer("resamples", resamples)
    request.admissible_law = _flag("admissible_law", admissible_law)
    renames = _renames(columns)
    if not isinstance(normal_load, (list, tuple)):
        request.normal_load = _args.optional_number("normal_load", normal_load)
    items, loads = _items_and_loads(data, normal_load, source)
    raw = _core._identify(items, loads, renames, request)
    return IdentificationResult(raw)


def _items_and_loads(
    data: Any, normal_load: Any, source: Optional[str], scalar_load_per_table: bool = False
) -> tuple[list[tuple[Optional[str], str, list[str], list[Any]]], list[float]]:
    """The tables of ``data`` as the core reads them, (path or None, source name, column names,
    columns) a table, and the loads given one a table (a single load too with
    ``scalar_load_per_table``; else empty for one load or none)."""
    tables = list(data) if isinstance(data, (list, tuple)) else [data]
    if not tables:
        raise ValueError("data: an empty list; give a table, or several")
    loads: list[float] = []
    if isinstance(normal_load, (list, tuple)):  # one a table: for their rows without Fz
        loads = [_args.number(f"normal_load[{i}]", x) for i, x in enumerate(normal_load)]
        if len(loads) != len(tables):
            raise ValueError(f"normal_load: {len(loads)} values for {len(tables)} tables: give "
                             f"one load, or one a table in their order")
    elif normal_load is not None and scalar_load_per_table:
        loads = [_args.number("normal_load", normal_load)] * len(tables)
    items: list[tuple[Optional[str], str, list[str], list[Any]]] = []
    for k, table in enumerate(tables):
        one = len(tables) == 1
        name = source if one or source is None else f"{source}[{k}]"
        if isinstance(table, (str, os.PathLike)):
            path = os.fspath(table)
            items.append((str(path), str(name or path), [], []))
            continue
        if name is None:
            kind = "DataFrame" if hasattr(table, "iloc") else "arrays"
            name = f"<{kind}>" if one else f"<{kind} {k + 1}>"
        names, cols = _table_of(table)
        items.append((None, name, names, cols))
    return items, loads


# The keys' meaning from the library's table (identify_request.hpp), shared with the app's --help.
identify.__doc__ = (identify.__doc__ or "") + "".join(
    f"\n    - ``{key}``: {text}" for key, text in _core._identify_keys
) + "\n"
