"""Hostile but realistic input to the Python API: refused with a ValueError naming the problem,
never a crash, a silent drop or a silent change of the numbers."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

import contensou as c

from conftest import DATA


@pytest.fixture(scope="module")
def frame():
    return pd.read_csv(DATA, comment="#")


def test_every_parameter_fixed_is_an_error_not_a_crash(frame):
    fix = {"F0_N": 1375.0, "a": 0.6, "M0_Nm": 75.0, "m": 6.5, "kx": 0.13}
    with pytest.raises(ValueError, match="every parameter is fixed"):
        c.identify(frame, radius=0.087, fix=fix, loop=False)


def test_a_misspelt_column_is_refused_not_dropped(frame):
    # A near miss of a known column is refused, naming the column it may be.
    with pytest.raises(ValueError, match=r"column 'Fxx_N' \(4\) is not a column this reader knows: did you mean 'Fx_N'"):
        c.identify(frame.rename(columns={"Fx_N": "Fxx_N"}), radius=0.087, loop=False)
    # The quantity with its unit in another case is read, and the report says so.
    r = c.identify(frame.rename(columns={"Fx_N": "Fx_n"}), radius=0.087, loop=False)
    assert r.parameters["F0_N"].value == pytest.approx(
        c.identify(frame, radius=0.087, loop=False).parameters["F0_N"].value, rel=1e-12)
    assert any("'Fx_n'" in note for note in r.report["input"]["columns_converted"])
    # An unrelated extra column is no near miss: ignored, as in the CSV reader.
    extra = frame.assign(run_id=1)
    assert c.identify(extra, radius=0.087, loop=False).parameters["F0_N"].value > 0


def test_complex_input_is_refused_not_truncated(frame):
    law = c.fractional_law_from_patch(c.seed_tire_patch())
    with pytest.raises(ValueError, match="vx: complex values"):
        c.fractional_resultants(law, np.array([1.0 + 2.0j]), 0.0, 10.0)
    with pytest.raises(ValueError, match="complex values"):
        c.identify(frame.astype({"Fx_N": complex}), radius=0.087, loop=False)
    with pytest.raises(ValueError, match="complex values"):
        c.identify(frame.to_numpy().astype(complex), radius=0.087, loop=False)


def test_finite_input_gives_finite_output_or_an_error():
    law = c.fractional_law_from_patch(c.seed_tire_patch())
    law.F0 = law.M0 = 1e308
    with pytest.raises(ValueError, match="overflow a double"):
        c.fractional_resultants(law, 1.0, 0.0, 1.0)
    patch = c.seed_tire_patch()
    patch.radius_m = 1e308
    with pytest.raises(ValueError, match="radius_m, reference_pressure_pa"):
        c.ExactModel(patch)
