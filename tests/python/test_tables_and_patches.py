"""The patch made from its normal load and checked where it is made; the friction functions on
a DataFrame or mapping of columns, with labelled results; signatures visible to inspect; the
progress bar only on a terminal."""

from __future__ import annotations

import inspect
import math

import numpy as np
import pandas as pd
import pytest

import contensou as c
from contensou import gear


def test_patch_from_the_normal_load():
    # p* = N / (2 pi R^2 A^1) (theory.md section 4): A^1 = 1/2 uniform, 1/3 Hertz.
    u = c.ContactPatch(radius_m=0.05, normal_load=800.0, friction=0.4)
    assert u.reference_pressure_pa == pytest.approx(800.0 / (math.pi * 0.05**2), rel=1e-14)
    assert u.normal_load == pytest.approx(800.0, rel=1e-14)
    h = c.ContactPatch(radius_m=0.05, normal_load=800.0, friction=0.4, profile=c.hertz_profile())
    assert h.reference_pressure_pa == pytest.approx(3 * 800.0 / (2 * math.pi * 0.05**2), rel=1e-14)
    same = c.ContactPatch.from_normal_load(0.05, 800.0, c.hertz_profile(), 0.4)
    assert same.reference_pressure_pa == h.reference_pressure_pa
    seed = c.ContactPatch.seed_tire()
    assert (seed.radius_m, seed.reference_pressure_pa, seed.friction) == (0.087, 2.1e5, 0.3)
    # Same resultants as the patch given by its pressure.
    by_p = c.ContactPatch(radius_m=0.05, reference_pressure_pa=u.reference_pressure_pa, friction=0.4)
    np.testing.assert_array_equal(c.exact_resultants(u, 0.3, 0.0, 5.0).resultants,
                                  c.exact_resultants(by_p, 0.3, 0.0, 5.0).resultants)


@pytest.mark.parametrize("kwargs,message", [
    (dict(radius_m=-0.1), r"^radius_m = -0.1: must be positive and finite$"),
    (dict(), r"^radius_m = missing: needed: ContactPatch\(radius_m="),
    (dict(radius_m=0.1, normal_load=100.0), r"^friction = missing"),
    (dict(radius_m=0.1, friction=0.3), r"neither given: give one"),
    (dict(radius_m=0.1, friction=0.3, normal_load=1.0, reference_pressure_pa=1e5), r"both given"),
    (dict(radius_m=0.1, friction=0.3, normal_load=-5.0), r"^normal_load = -5: must be positive"),
    (dict(radius_m=0.1, friction=-0.3, normal_load=5.0), r"^friction = -0.3: must be"),
    (dict(radius_m=0.1, friction=0.3, normal_load=5.0, kappa=0.0), r"^kappa = 0: must be positive"),
])
def test_patch_constructor_checks_its_arguments(kwargs, message):
    with pytest.raises(ValueError, match=message):
        c.ContactPatch(**kwargs)


def kinematics_frame() -> pd.DataFrame:
    rng = np.random.default_rng(3)
    n = 7
    return pd.DataFrame({"t_s": np.arange(n) * 0.1, "vx_mps": rng.uniform(-1, 1, n),
                         "vy_mps": rng.uniform(-1, 1, n), "omega_radps": rng.uniform(-20, 20, n)},
                        index=pd.Index([10, 11, 12, 13, 14, 15, 16], name="row"))


def test_functions_take_a_dataframe_and_label_their_results():
    df = kinematics_frame()
    vx, vy, w = (df[k].to_numpy() for k in ("vx_mps", "vy_mps", "omega_radps"))
    patch = c.seed_tire_patch()
    law = c.fractional_law_from_patch(patch)
    exact = c.ExactLaw(patch, tolerance=1e-8)

    table = c.fractional_resultants(law, df)
    assert isinstance(table, c.FrictionTable) and len(table) == 7
    np.testing.assert_array_equal(table.resultants, c.fractional_resultants(law, vx, vy, w))
    np.testing.assert_array_equal(table.Mz_Nm, table.resultants[:, 2])
    frame = table.to_frame()
    assert list(frame.columns) == ["Fx_N", "Fy_N", "Mz_Nm"]
    assert list(frame.index) == list(df.index) and frame.index.name == "row"

    with_j = c.fractional_resultants(law, df, jacobian=True)
    np.testing.assert_array_equal(with_j.jacobian,
                                  c.fractional_resultants(law, vx, vy, w, jacobian=True)[1])
    np.testing.assert_array_equal(c.exact_law_resultants(exact, df).resultants,
                                  c.exact_law_resultants(exact, vx, vy, w))

    r = c.exact_resultants(patch, df, tolerance=1e-9)
    arrays = c.exact_resultants(patch, vx, vy, w, tolerance=1e-9)
    np.testing.assert_array_equal(r.resultants, arrays.resultants)
    np.testing.assert_array_equal(r.error, arrays.error)
    out = r.to_frame()
    assert list(out.columns) == ["Fx_N", "Fy_N", "Mz_Nm", "Fx_error_N", "Fy_error_N",
                                 "Mz_error_Nm", "converged"]
    assert out["converged"].all()
    flat = arrays.to_frame()  # the array form's frame: a row per point
    np.testing.assert_array_equal(flat["Fy_N"].to_numpy(), arrays.resultants[:, 1])


def test_a_mapping_of_columns_works_without_pandas_types():
    cols = {"vx_mps": [0.1, 0.5], "vy_mps": (0.0, 0.2), "omega_radps": np.array([5.0, -3.0])}
    law = c.fractional_law_from_patch(c.seed_tire_patch())
    table = c.fractional_resultants(law, cols)
    assert table.index is None
    np.testing.assert_array_equal(table.resultants,
                                  c.fractional_resultants(law, [0.1, 0.5], [0.0, 0.2], [5.0, -3.0]))


def test_kinematic_columns_in_other_units_are_converted_as_in_data_files():
    law = c.fractional_law_from_patch(c.seed_tire_patch())
    si = {"vx_mps": [0.5, 1.0], "vy_mps": [0.0, 0.25], "omega_radps": [10.0, -20.0]}
    other = {"vx [km/h]": [1.8, 3.6], "vy_mm/s": [0.0, 250.0],
             "omega (rpm)": [10.0 * 60 / (2 * math.pi), -20.0 * 60 / (2 * math.pi)]}
    np.testing.assert_allclose(c.fractional_resultants(law, pd.DataFrame(other)).resultants,
                               c.fractional_resultants(law, si).resultants, rtol=1e-13)
    with pytest.raises(ValueError, match=r"column 'omega \[N\]': 'N' is not a unit of angular rate"):
        c.fractional_resultants(law, {"vx_mps": [1.0], "vy_mps": [0.0], "omega [N]": [1.0]})
    with pytest.raises(ValueError, match="two columns for omega_radps"):
        c.fractional_resultants(law, {"vx_mps": [1.0], "vy_mps": [0.0], "omega [rpm]": [1.0],
                                      "omega_deg/s": [1.0]})


def test_table_errors_name_the_columns():
    law = c.fractional_law_from_patch(c.seed_tire_patch())
    with pytest.raises(ValueError, match=r"missing 'omega_radps'.*vx_mps, vy_mps \[m/s\] and omega_radps"):
        c.fractional_resultants(law, {"vx_mps": [1.0], "vy_mps": [0.0], "omega": [1.0]})
    with pytest.raises(ValueError, match="different lengths"):
        c.fractional_resultants(law, {"vx_mps": [1.0, 2.0], "vy_mps": [0.0], "omega_radps": [1.0]})
    with pytest.raises(ValueError, match=r"^omega = nan: must be finite"):
        c.fractional_resultants(law, pd.DataFrame({"vx_mps": [1.0], "vy_mps": [0.0],
                                                   "omega_radps": [None]}))
    with pytest.raises(TypeError, match="alone"):
        c.fractional_resultants(law, kinematics_frame(), 0.0, 1.0)  # type: ignore[call-overload]
    with pytest.raises(TypeError, match="three arrays"):
        c.fractional_resultants(law, [1.0, 2.0])  # type: ignore[call-overload]


def test_signatures_are_visible_to_inspect():
    sig = inspect.signature(c.ContactPatch)
    assert list(sig.parameters)[:3] == ["radius_m", "reference_pressure_pa", "friction"]
    assert sig.parameters["normal_load"].kind is inspect.Parameter.KEYWORD_ONLY
    assert list(inspect.signature(c.ExactModel).parameters) == ["patch", "representation_tolerance"]
    assert inspect.signature(c.ExactModel).parameters["representation_tolerance"].default == 1e-15
    assert list(inspect.signature(c.LimitSurface).parameters) == ["patch", "tolerance"]
    assert "tolerance" in inspect.signature(c.ExactLaw).parameters


def test_progress_bar_only_on_a_terminal_or_when_asked(monkeypatch):
    class Stream:
        def __init__(self, tty: bool) -> None:
            self.tty = tty

        def isatty(self) -> bool:
            return self.tty

        def write(self, s: str) -> int:
            return len(s)

        def flush(self) -> None:
            pass

    monkeypatch.setattr("sys.stderr", Stream(False))
    assert type(gear._progress(3, None, "x")).__name__ == "_Silent"
    assert type(gear._progress(3, False, "x")).__name__ == "_Silent"
    bar = gear._progress(3, True, "x")  # asked for: shown even off a terminal
    assert type(bar).__name__ != "_Silent"
    bar.close()
    monkeypatch.setattr("sys.stderr", Stream(True))
    bar = gear._progress(3, None, "x")
    assert type(bar).__name__ != "_Silent"
    bar.close()
