"""contensou.identify against contensou-identify: the same report JSON, byte for byte, from a
CSV path, a DataFrame and plain arrays; the result's arrays against the report; bad input."""

from __future__ import annotations

import json
import re
import subprocess

import numpy as np
import pandas as pd
import pytest

import contensou as c

from conftest import DATA

SOURCE = "data/seed_tire_diagrams.csv"  # the name the app is given (it runs from the root)
PROFILE = dict(profile="seed-tire", pressure=2.1e5)


def app_report(identify_app, tmp_path, *args: str) -> str:
    out = tmp_path / "report.json"
    subprocess.run([str(identify_app), SOURCE, "--radius", "0.087", *args, "--json", str(out)],
                   check=True, capture_output=True, cwd=DATA.parents[1])
    return out.read_text()


@pytest.fixture(scope="module")
def loop_app_json(identify_app, tmp_path_factory):
    return app_report(identify_app, tmp_path_factory.mktemp("app"), "--profile", "seed-tire",
                      "--pressure", "2.1e5")


@pytest.fixture(scope="module")
def loop_result():
    return c.identify(str(DATA), radius=0.087, source=SOURCE, **PROFILE)


def test_loop_report_is_the_apps_byte_for_byte(loop_result, loop_app_json):
    assert loop_result.to_json() == loop_app_json
    assert loop_result.model == "exact" and loop_result.accepted_effects == ["shape"]


def test_fit_only_and_no_profile_reports_are_the_apps(identify_app, tmp_path):
    assert (c.identify(DATA, radius=0.087, loop=False, source=SOURCE, **PROFILE).to_json()
            == app_report(identify_app, tmp_path, "--profile", "seed-tire", "--pressure", "2.1e5",
                          "--no-loop"))
    assert (c.identify(DATA, radius=0.087, loop=False, fix={"a": 1.03}, loss="huber",
                       normal_load=4500.0, source=SOURCE).to_json()
            == app_report(identify_app, tmp_path, "--no-loop", "--fix", "a=1.03", "--loss", "huber",
                          "--normal-load", "4500"))


def test_dataframe_and_arrays_give_the_same_report(loop_app_json):
    df = pd.read_csv(DATA, comment="#")
    # pandas' parser and the library's agree to the last bit on this file: equal reports.
    from_df = c.identify(df, radius=0.087, source=SOURCE, **PROFILE)
    assert from_df.to_json() == loop_app_json
    arrays = {name: df[name].to_numpy() for name in df.columns}
    assert c.identify(arrays, radius=0.087, source=SOURCE, **PROFILE).to_json() == loop_app_json
    # Without the time column a drift is looked for along the row order: the same report as the
    # DataFrame without it.
    columns = ["vx_mps", "vy_mps", "omega_radps", "Fx_N", "Fy_N", "Mz_Nm"]
    plain = df[columns].to_numpy()
    assert (c.identify(plain, radius=0.087, source=SOURCE, **PROFILE).to_json()
            == c.identify(df[columns], radius=0.087, source=SOURCE, **PROFILE).to_json())
    assert json.loads(c.identify(df, radius=0.087, **PROFILE).to_json())["input"]["file"] == "<DataFrame>"


def test_missing_values_are_not_measured():
    df = pd.read_csv(DATA, comment="#")
    df.loc[::2, "Mz_Nm"] = np.nan
    df = df.drop(columns=["Fy_N"])
    r = c.identify(df, radius=0.087, loop=False, **PROFILE)
    assert r.report["input"]["values"] == 40 + 20
    assert np.isnan(r.residuals[::2, 2]).all() and np.isnan(r.residuals[:, 1]).all()
    assert np.isfinite(r.residuals[1::2, 2]).all()


def test_result_arrays_agree_with_the_report(loop_result):
    r = loop_result
    df = pd.read_csv(DATA, comment="#")
    np.testing.assert_array_equal(r.measured, df[["Fx_N", "Fy_N", "Mz_Nm"]].to_numpy())
    np.testing.assert_array_equal(r.kinematics, df[["vx_mps", "vy_mps", "omega_radps"]].to_numpy())
    assert r.residuals.shape == r.prediction.shape == (40, 3)
    # Channel rms of the residual arrays, computed here, against the C++ report's.
    rms = np.sqrt(np.mean(r.residuals**2, axis=0))
    for k, ch in enumerate(["Fx_N", "Fy_N", "Mz_Nm"]):
        assert rms[k] == pytest.approx(r.report["final"]["rms"][ch], rel=1e-12)
        assert np.sqrt(np.mean(r.base_residuals[:, k] ** 2)) == pytest.approx(
            r.report["base"]["rms"][ch], rel=1e-12)
    # The shape step's residuals: before it is the base model, after it the final one.
    shape_step = r.steps[0]
    assert shape_step.effect == "shape" and shape_step.accepted
    np.testing.assert_array_equal(shape_step.prediction_before, r.base_prediction)
    np.testing.assert_array_equal(shape_step.prediction_after, r.prediction)
    assert [s.effect for s in r.steps] == [s["chosen"] for s in r.report["steps"]]
    # Intervals and standard errors as in the report; covariance diagonal = std_error^2.
    final = r.report["final"]["params"]
    for name, p in r.parameters.items():
        assert p.value == final[name]["value"]
        assert p.ci95 == (None if final[name]["ci95"] is None else tuple(final[name]["ci95"]))
    assert r.covariance_names == ["F0_N", "kx"]
    assert r.covariance.shape == (2, 2)
    np.testing.assert_allclose(np.sqrt(np.diag(r.covariance)),
                               [final[n]["std_error"] for n in r.covariance_names], rtol=1e-12)
    np.testing.assert_allclose(r.covariance, r.covariance.T, rtol=1e-12)
    corr = np.array(r.report["final"]["correlation"]["matrix"])
    d = np.sqrt(np.diag(r.covariance))
    np.testing.assert_allclose(r.covariance / np.outer(d, d), corr, rtol=1e-12, atol=1e-15)
    ci = r.ci95
    assert ci.shape == (len(r.parameters), 2)
    assert np.isnan(ci[r.names.index("a")]).all()  # derived from the profile: no interval


def test_bad_input_is_a_value_error_with_the_message(tmp_path):
    df = pd.read_csv(DATA, comment="#")
    with pytest.raises(ValueError, match=r"^radius = -1: must be positive and finite$"):
        c.identify(df, radius=-1.0)
    with pytest.raises(ValueError, match="missing required column.*omega_radps"):
        c.identify(df.drop(columns=["omega_radps"]), radius=0.087)
    bad = df.copy()
    bad.loc[4, "vx_mps"] = np.inf
    with pytest.raises(ValueError,
                       match=r"<DataFrame>: row 5 \(index 4\): column 'vx_mps' \(1\): non-finite"):
        c.identify(bad, radius=0.087)
    with pytest.raises(ValueError, match="no measured channel"):
        c.identify(df[["vx_mps", "vy_mps", "omega_radps"]], radius=0.087)
    with pytest.raises(ValueError, match="^profile = nowhere.csv: no such file"):
        c.identify(df, radius=0.087, profile="nowhere.csv")
    with pytest.raises(ValueError, match="unknown"):
        c.identify(df, radius=0.087, fix={"zeta": 1.0}, loop=False)
    broken = tmp_path / "broken.csv"
    broken.write_text("vx_mps,vy_mps,omega_radps,Fx_N\n0.1,0,10,-5\n0.2,0,ten,-6\n")
    with pytest.raises(ValueError, match=r"broken\.csv:3: column 'omega_radps' \(3\): not a number"):
        c.identify(str(broken), radius=0.087)
    words = df.astype({"Fx_N": object})
    words.loc[2, "Fx_N"] = "high"
    with pytest.raises(ValueError, match=r"row 3 \(index 2\): column 'Fx_N' \(4\): not a number: 'high'"):
        c.identify(words, radius=0.087)
    with pytest.raises(ValueError, match="loss"):
        c.identify(df, radius=0.087, loss="square")


def test_units_in_names_and_renamed_columns_are_read_as_the_app_reads_them():
    """A DataFrame in lab units (km/h, rpm, kN, a torque under another name) gives the SI
    frame's parameters, and the report names every conversion."""
    df = pd.read_csv(DATA, comment="#")
    lab = pd.DataFrame({
        "vx [km/h]": df["vx_mps"] * 3.6,
        "vy_mps": df["vy_mps"],
        "omega_rpm": df["omega_radps"] * 60.0 / (2.0 * np.pi),
        "Fx [kN]": df["Fx_N"] / 1000.0,
        "Fy_N": df["Fy_N"],
        "Torque (N m)": df["Mz_Nm"],
        "operator": ["A"] * len(df),  # text in a column nobody reads is fine
    })
    si = c.identify(df, radius=0.087, loop=False, **PROFILE)
    r = c.identify(lab, radius=0.087, loop=False, columns={"Mz": "Torque (N m)"}, **PROFILE)
    for name, p in si.parameters.items():
        assert r.parameters[name].value == pytest.approx(p.value, rel=1e-7), name
    notes = " | ".join(r.report["input"]["columns_converted"])
    for expected in ("vx [km/h]", "omega_rpm", "Fx [kN]", "Torque (N m)"):
        assert expected in notes
    with pytest.raises(ValueError, match="Mz"):  # the torque column unmapped: no channel named
        c.identify(lab.drop(columns=["Fx [kN]", "Fy_N"]), radius=0.087, loop=False)
    with pytest.raises(ValueError, match=r"row 2 \(index 1\): column 'operator'|operator"):
        c.identify(lab.drop(columns=["Torque (N m)"]), radius=0.087, loop=False,
                   columns="Mz=operator")
    with pytest.raises(ValueError, match=r"'Torque \(N m\)' \(6\): holds a moment"):
        c.identify(lab, radius=0.087, loop=False, columns="Mz=operator")  # the torque unread


def test_column_errors_name_the_keyword_as_python_writes_it():
    """Messages about columns point at ``columns=``, never at the app's ``--columns``; a header
    cell with a comma or an equals sign is mapped as written."""
    df = pd.read_csv(DATA, comment="#")
    with pytest.raises(ValueError, match=r"or give its name: columns=\{'omega': 'NAME'\}"):
        c.identify(df.rename(columns={"omega_radps": "Rate"}), radius=0.087, loop=False)
    with pytest.raises(ValueError, match=r"columns=\{'vx': 'Speed'\}: the header has no column"):
        c.identify(df, radius=0.087, loop=False, columns={"vx": "Speed"})
    with pytest.raises(ValueError, match=r"'speed' is not a quantity"):
        c.identify(df, radius=0.087, loop=False, columns={"speed": "vx_mps"})
    with pytest.raises(TypeError, match="columns: expected a mapping"):
        c.identify(df, radius=0.087, loop=False, columns=["vx", "Speed"])
    odd = df.rename(columns={"Mz_Nm": "Torque, N=m"})
    r = c.identify(odd, radius=0.087, loop=False, columns={"Mz": "Torque, N=m"}, **PROFILE)
    si = c.identify(df, radius=0.087, loop=False, **PROFILE)
    assert r.parameters["M0_Nm"].value == pytest.approx(si.parameters["M0_Nm"].value, rel=1e-9)


def test_a_column_that_looks_like_a_channel_is_never_dropped_unread():
    """A DataFrame column no channel reads but that looks like one (a misspelt name, a force
    unit) is an error naming it, as in the app; declared, it is mapped, kept or left out; every
    other numeric column is recorded in SI and listed in the report."""
    df = pd.read_csv(DATA, comment="#")
    kn = df.assign(Fx_N=df["Fx_N"] / 1000.0)
    for header in ("Fxx [kN]", "Force X [kN]", "Fx [kN]x"):
        with pytest.raises(ValueError, match=re.escape(f"column '{header}' (4)")):
            c.identify(kn.rename(columns={"Fx_N": header}), radius=0.087, loop=False)
    si = c.identify(df, radius=0.087, loop=False)
    mapped = c.identify(kn.rename(columns={"Fx_N": "Force X [kN]"}), radius=0.087, loop=False,
                        columns={"Fx": "Force X [kN]"})
    assert mapped.parameters["F0_N"].value == pytest.approx(si.parameters["F0_N"].value, rel=1e-9)
    warm = df.assign(**{"T [degC]": np.linspace(20.0, 40.0, len(df)), "note": "ok"})
    r = json.loads(c.identify(warm, radius=0.087, loop=False).to_json())
    (t,) = r["input"]["recorded_columns"]
    assert (t["header"], t["kind"], t["si_unit"]) == ("T [degC]", "temperature", "K")
    assert (t["min"], t["max"]) == pytest.approx((293.15, 313.15))
    assert r["input"]["columns_not_read"] == ["'note' (column 9): text"]
    assert r["final"]["params"]["F0_N"]["value"] == pytest.approx(
        si.parameters["F0_N"].value, rel=1e-12)  # a recorded column changes nothing of the fit
    kept = json.loads(c.identify(kn.rename(columns={"Fx_N": "Fxx"}), radius=0.087, loop=False,
                                 columns={"extra": ["Fxx"]}).to_json())
    assert [x["header"] for x in kept["input"]["recorded_columns"]] == ["Fxx"]


def test_a_second_column_of_a_channel_must_repeat_it_and_missing_spellings_are_counted():
    """A DataFrame with the channel again beside its SI column is read as the app reads the
    file: kept only when every row repeats it (to the digits written), refused naming the row
    when it holds another channel; 'n/a', 'NA' and '-' are missing cell by cell and counted; the
    same column name twice is refused by name."""
    df = pd.read_csv(DATA, comment="#")
    si = c.identify(df, radius=0.087, loop=False)
    same = c.identify(df.assign(**{"Fx [kN]": (df["Fx_N"] / 1000.0).round(4)}), radius=0.087,
                      loop=False)
    assert same.parameters["F0_N"].value == si.parameters["F0_N"].value
    with pytest.raises(ValueError, match=re.escape("is a second Fx beside 'Fx_N'")):
        c.identify(df.assign(**{"Fx [N]": df["Fy_N"]}), radius=0.087, loop=False)
    with pytest.raises(ValueError, match=re.escape("column 'Fx_raw' (8): is a second Fx")):
        c.identify(df.assign(Fx_raw=1.01 * df["Fx_N"]), radius=0.087, loop=False)
    text = df.astype({"Fy_N": object})
    text.loc[[3, 5], "Fy_N"] = "n/a"
    text.loc[8, "Fy_N"] = "NA"
    r = c.identify(text, radius=0.087, loop=False)
    assert np.isnan(r.measured[3, 1]) and np.isnan(r.measured[8, 1])
    assert json.loads(r.to_json())["input"]["missing_values"] == [
        f"'Fy_N' (column 5): 3 of {len(df)} rows (NA 1, n/a 2)"]
    twice = pd.concat([df, df[["Fx_N"]]], axis=1)
    with pytest.raises(ValueError, match=re.escape("duplicate column 'Fx_N' (columns 4 and 8)")):
        c.identify(twice, radius=0.087, loop=False)


def test_gross_errors_are_named_and_left_out_as_the_app_does(identify_app, tmp_path):
    """Glitched rows (a sign flip, a spike) are found by Python as by the app: the same report
    byte for byte, the values left out are NaN in ``measured``, and ``text`` is what the app
    prints."""
    df = pd.read_csv(DATA, comment="#")
    bad = df.copy()
    bad.loc[20, "Fy_N"] = -bad.loc[20, "Fy_N"] + 300.0
    bad.loc[30, "Mz_Nm"] = bad.loc[30, "Mz_Nm"] + 40.0
    path = tmp_path / "glitched.csv"
    bad.to_csv(path, index=False, float_format="%.17g")
    out = tmp_path / "r.json"
    printed = subprocess.run([str(identify_app), str(path), "--radius", "0.087", "--no-loop",
                              "--json", str(out)], check=True, capture_output=True, text=True).stdout
    r = c.identify(str(path), radius=0.087, loop=False)
    assert r.to_json() == out.read_text()
    named = sorted((o["line"], o["channel"]) for o in r.outliers)
    assert named == [(22, "Fy_N"), (32, "Mz_Nm")]  # header on line 1, row i on line i + 2
    assert r.text in printed and "Fy_N" in r.text
    assert np.isnan(r.measured[20, 1]) and np.isnan(r.measured[30, 2])
    np.testing.assert_array_equal(r.rows, np.arange(len(df)))
    # The same from the DataFrame (rows numbered from 1), and none without the search.
    from_df = c.identify(bad, radius=0.087, loop=False)
    assert sorted((o["line"], o["channel"]) for o in from_df.outliers) == [(21, "Fy_N"),
                                                                          (31, "Mz_Nm")]
    assert c.identify(bad, radius=0.087, loop=False, outliers=False).outliers == []


def test_the_keys_are_documented_from_the_librarys_table():
    doc = c.identify.__doc__ or ""
    for key in ("radius", "normal_load", "profile", "pressure", "alpha", "outliers"):
        assert f"``{key}``" in doc


def test_noise_models_are_the_apps(loop_result, identify_app, tmp_path):
    # auto, the default: the loop tests a noise scale growing with the value and, on this white
    # constant noise, keeps one constant scale per channel.
    steps = {s.effect: s for s in loop_result.steps}
    assert "noise_growth" in steps and not steps["noise_growth"].accepted
    assert steps["noise_growth"].report["lr_dof"] == 3
    assert loop_result.report["noise_model"] == "additive"
    # affine (sigma = a + b |y| per channel), asked for: as the app's --noise-model affine.
    affine = c.identify(DATA, radius=0.087, loop=False, noise_model="affine", source=SOURCE,
                        **PROFILE)
    assert affine.to_json() == app_report(identify_app, tmp_path, "--profile", "seed-tire",
                                          "--pressure", "2.1e5", "--no-loop", "--noise-model",
                                          "affine")
    assert affine.report["base"]["noise_model"] == "affine"
    assert set(affine.report["base"]["noise_slope"]) == {"Fx_N", "Fy_N", "Mz_Nm"}
    with pytest.raises(ValueError, match="noise_scale gives constant scales"):
        c.identify(DATA, radius=0.087, noise_model="affine", noise_scale=(1.0, 1.0, 1.0))


def _heating_rig_file(seed=7):
    """A programme as a rig records it: a Hertz tire (R = 0.09 m) at 2, 4 and 6 kN, sweeps in
    three directions of 120 points each plus pure spin and pure sliding, friction falling with
    the load and with a tread temperature that rises over the run, load-cell noise (3 N plus
    0.5 % of the value), six Fx sign flips, rows shuffled. Returns the frame (rows numbered from
    1 in the data given) and the glitched rows."""
    rng = np.random.default_rng(seed)
    R = 0.09
    rows = []
    for N in (2000.0, 4000.0, 6000.0):
        for d in (0.0, np.pi / 2, np.pi / 4):
            for psi in np.geomspace(0.02, 50, 120):
                rows.append((N, psi * np.cos(d), psi * np.sin(d), 1.0 / R))
        rows += [(N, 0.0, 0.0, 10.0), (N, 1.0, 0.0, 0.0), (N, 0.3, 0.0, 0.0)]
    N, vx, vy, om = np.array(rows).T
    t = 0.5 * np.arange(len(N))
    temp = 25 + 30 * t / t.max() + rng.normal(0, 0.3, len(t))
    f = 0.9 * (1 - 0.04 * (N - 4000) / 1000) * (1 - 0.004 * (temp - 40))
    F = np.zeros((len(N), 3))
    for load in (2000.0, 4000.0, 6000.0):
        at = N == load
        patch = c.ContactPatch(radius_m=R, normal_load=load, friction=1.0,
                               profile=c.hertz_profile())
        r = c.exact_resultants(c.ExactModel(patch), vx[at], vy[at], om[at], tolerance=1e-10)
        F[at] = np.asarray(r.resultants).reshape(-1, 3)
    F *= f[:, None]
    F += (0.005 * np.abs(F) + np.array([3.0, 3.0, 0.1])) * rng.normal(size=F.shape)
    glitched = rng.choice(len(N), 6, replace=False)
    F[glitched, 0] *= -1
    df = pd.DataFrame({"t_s": t, "Fz_N": N, "vx_mps": vx, "vy_mps": vy, "omega_radps": om,
                       "Fx_N": F[:, 0], "Fy_N": F[:, 1], "Mz_Nm": F[:, 2], "T_tread": temp})
    order = rng.permutation(len(df))
    return df.iloc[order].reset_index(drop=True), set(int(np.where(order == g)[0][0]) + 1
                                                      for g in glitched), R


def test_good_rows_the_final_model_fits_are_put_back():
    """The robust judge fit knows neither the load nor the temperature dependence; on this file
    it takes two good rows at the end of the 6 kN sweep for glitches (11 and 10 robust sigma).
    The final model (friction following Fz_N and T_tread) fits them within 2 sigma: they are put
    back, and the named outliers are glitches only (the two sign flips of |Fx| < 3 N, inside the
    noise, go unnamed)."""
    df, glitched, R = _heating_rig_file()
    r = c.identify(df, radius=R, profile="hertz")
    named = {o["line"] for o in r.outliers}
    put_back = {o["line"] for o in r.outliers_put_back}
    assert named <= glitched, (named - glitched)
    assert len(named) == 4
    assert put_back and not put_back & glitched
    assert all(abs(o["residual_sigma"]) <= 4.0 for o in r.outliers_put_back)
    assert "put back: 2 values" in r.text
    assert r.accepted_effects.count("friction_dependence") == 2
    assert "friction follows the load (Fz_N)" in r.text and "friction follows T_tread" in r.text


def test_predict_both_ways_matches_the_app_and_keeps_rows_without_forces(
        loop_result, identify_app, tmp_path):
    """result.predict(df): the final model at any rows (forces optional), the same numbers as
    `contensou-identify predict --model REPORT.json`; on the fitted rows the forces are the
    fit's own predictions (an independent path: the report's model rebuilt from its JSON)."""
    df = pd.read_csv(DATA, comment="#")
    pred = loop_result.predict(df)
    assert list(pred.columns[:6]) == ["pred_Fx_N", "pred_Fy_N", "pred_Mz_Nm", "pred_twist_vx",
                                      "pred_twist_vy", "pred_twist_omegaR"]
    assert len(pred) == len(df) and (pred.index == df.index).all()
    fitted = pred[["pred_Fx_N", "pred_Fy_N", "pred_Mz_Nm"]].to_numpy()[loop_result.rows]
    np.testing.assert_allclose(fitted, loop_result.prediction, rtol=1e-9, atol=1e-9)
    unit = pred[["pred_twist_vx", "pred_twist_vy", "pred_twist_omegaR"]].to_numpy()
    np.testing.assert_allclose(np.linalg.norm(unit, axis=1)[np.isfinite(unit[:, 0])], 1.0,
                               rtol=1e-12)
    scores = pred.attrs["scores"]
    assert scores["rows"] > 0 and np.isfinite(scores["median_motion_angle_deg"])
    # Rows without forces: predicted, not dropped; no motion is predicted for them.
    bare = df[["vx_mps", "vy_mps", "omega_radps"]]
    no_forces = loop_result.predict(bare)
    np.testing.assert_allclose(no_forces[["pred_Fx_N", "pred_Fy_N", "pred_Mz_Nm"]].to_numpy(),
                               pred[["pred_Fx_N", "pred_Fy_N", "pred_Mz_Nm"]].to_numpy())
    assert no_forces["pred_twist_vx"].isna().all() and no_forces.attrs["scores"]["rows"] == 0
    # The app's predict from the report file gives the same numbers.
    report = tmp_path / "report.json"
    report.write_text(loop_result.to_json())
    out = tmp_path / "pred.csv"
    subprocess.run([str(identify_app), "predict", "--model", str(report), str(DATA), "--out",
                    str(out)], check=True, capture_output=True)
    app = pd.read_csv(out)
    for col in ["pred_Fx_N", "pred_Mz_Nm", "pred_twist_omegaR"]:
        np.testing.assert_allclose(app[col].to_numpy(), pred[col].to_numpy(), rtol=1e-8,
                                   atol=1e-12)
