"""contensou.gear against contensou-shimmy: the configuration, a landing's histories and
metrics, and a stability map cell for cell, in-process, on threads and on a Dask cluster."""

from __future__ import annotations

import csv
import json
import subprocess

import distributed
import numpy as np
import pytest

import contensou as c

from conftest import ROOT

AXES = (("scenario.forward_speed_mps", 40.0, 80.0, 3),
        ("structure.torsional_damping_nms_per_rad", 0.0, 200.0, 3))


def print_config(shimmy_app, *args: str) -> dict:
    out = subprocess.run([str(shimmy_app), *args, "--print-config"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


def test_default_configuration_is_the_apps(shimmy_app, tmp_path):
    cfg = c.LandingConfig.default()
    assert cfg.to_dict() == print_config(shimmy_app)
    assert c.LandingConfig.from_json(ROOT / "data" / "shimmy_default.json") == cfg
    # Changed values survive a round trip through the app's --config.
    cfg["structure.offset_m"] = 0.31
    cfg.scenario.forward_speed_mps = 55.5
    assert cfg.structure.offset_m == 0.31 and cfg["scenario.forward_speed_mps"] == 55.5
    path = tmp_path / "cfg.json"
    cfg.to_json(path)
    assert print_config(shimmy_app, "--config", str(path)) == cfg.to_dict()
    assert c.LandingConfig.from_json(path) == cfg
    assert c.LandingConfig.from_json(path.read_text()) == cfg
    trail = cfg["structure.trail_m"]
    assert cfg.replace(structure__trail_m=trail + 0.02)["structure.trail_m"] == trail + 0.02
    assert cfg["structure.trail_m"] == trail  # replace copies
    assert "structure.offset_m" in c.LandingConfig.parameter_names()


def test_keys_are_the_apps_table(shimmy_app):
    """LandingConfig.keys() is the app's key table: every key of the configuration, with its
    default as --print-config prints it."""
    keys = {k["name"]: k for k in c.LandingConfig.keys()}
    printed = print_config(shimmy_app)

    def leaves(node, prefix=""):
        for name, value in node.items():
            dotted = f"{prefix}.{name}" if prefix else name
            if isinstance(value, dict):
                yield from leaves(value, dotted)
            else:
                yield dotted, value

    assert dict(leaves(printed)) == {name: k["default"] for name, k in keys.items()}
    offset = keys["structure.offset_m"]
    assert (offset["type"], offset["unit"], offset["values"]) == ("number", "m", "finite")
    assert keys["structure.freeplay_rad"]["values"] == "[0, 1)"
    assert keys["solver.method"]["values"] == "adams or bdf"
    assert set(c.LandingConfig.parameter_names()) <= set(keys)


def test_bad_configuration_values_are_value_errors(tmp_path):
    cfg = c.LandingConfig()
    mass = cfg["structure.lateral_mass_kg"]
    with pytest.raises(ValueError, match=r"^structure\.lateral_mass_kg = -1: must be positive"):
        cfg["structure.lateral_mass_kg"] = -1.0
    assert cfg["structure.lateral_mass_kg"] == mass  # unchanged after the error
    with pytest.raises(ValueError, match=r"^structure\.offset_m: expected a number"):
        cfg["structure.offset_m"] = "far"
    with pytest.raises(KeyError):
        cfg["structure.no_such_thing"] = 1.0
    with pytest.raises(ValueError, match="unknown key"):
        c.LandingConfig({"structure": {"offset": 0.2}})
    with pytest.raises(ValueError, match="invalid JSON"):
        c.LandingConfig.from_json("{ not json")
    # A file's errors name the file, line and column, as the app's do.
    bad = tmp_path / "bad.json"
    bad.write_text('{\n  "structure": {\n    "offset_m": "far"\n  }\n}\n')
    with pytest.raises(ValueError, match=r"bad\.json:3:5: structure\.offset_m: expected a number"):
        c.LandingConfig.from_json(bad)
    with pytest.raises(ValueError, match="cannot open"):
        c.LandingConfig.from_json(tmp_path / "missing.json")
    with pytest.raises(ValueError, match="model"):
        c.simulate_landing(cfg, "magnetic")
    with pytest.raises(ValueError, match="is not a gear parameter"):
        c.stability_map(cfg, (("structure.wings", 0, 1, 2), AXES[1]), progress=False)
    with pytest.raises(ValueError, match="points"):
        c.stability_map(cfg, (AXES[0], ("structure.offset_m", 0, 1, 0)), progress=False)


@pytest.fixture(scope="module")
def app_run(shimmy_app, tmp_path_factory):
    """contensou-shimmy on a configuration with one 3 x 3 map of the coupled model."""
    out = tmp_path_factory.mktemp("shimmy")
    cfg = c.LandingConfig()
    d = cfg.to_dict()
    d["models"] = ["coupled", "von_schlippe"]
    spec = {k: {"parameter": a[0], "from": a[1], "to": a[2], "points": a[3]} for k, a in zip("xy", AXES)}
    if "method" in (d["maps"] or [{}])[0]:
        spec["method"] = "simulation"  # a configuration that also offers eigenvalue maps
    d["maps"] = [spec]
    cfg = c.LandingConfig(d)
    cfg.to_json(out / "cfg.json")
    run = out / "run"  # an output folder holds only what contensou writes
    subprocess.run([str(shimmy_app), "--config", str(out / "cfg.json"), "--out", str(run),
                    "--map", "--threads", "2"], check=True, capture_output=True)
    return cfg, run


@pytest.mark.parametrize("model", ["coupled", "von_schlippe"])
def test_landing_equals_the_apps_histories_and_metrics(app_run, model):
    cfg, out = app_run
    r = c.simulate_landing(cfg, model)
    with open(out / f"{model}.csv") as f:
        rows = list(csv.reader(f))
    assert rows[0] == r.columns
    app = np.array(rows[1:], dtype=float)
    assert app.shape == r.history.shape
    # The app writes 9 significant digits.
    np.testing.assert_allclose(r.history, app, rtol=6e-9, atol=1e-300)
    np.testing.assert_array_equal(r.t, r["t_s"])
    frame = r.to_frame()  # the friction results' name; to_dataframe() the same
    assert list(frame.columns) == r.columns
    np.testing.assert_array_equal(frame["t_s"].to_numpy(), r["t_s"])
    assert r.to_dataframe().equals(frame)
    summary = json.loads((out / "summary.json").read_text())["models"][model]
    m = r.metrics
    assert m["shimmy"] == summary["shimmy"]
    for key, app_key in [("growth_rate_per_s", "growth_rate_per_s"), ("frequency_hz", "frequency_Hz"),
                         ("peak_torsion_rad", "peak_torsion_rad"), ("peak_lateral_m", "peak_lateral_m"),
                         ("last_amplitude_rad", "final_torsion_amplitude_rad")]:
        assert m[key] == pytest.approx(summary[app_key], rel=1e-12, abs=0), key
    assert m["half_cycles"] == summary["half_cycles"] and m["steps"] == summary["steps"]
    assert [e for _, e in r.events] == [e["event"] for e in summary.get("events", [])]
    np.testing.assert_allclose([t for t, _ in r.events], [e["t_s"] for e in summary.get("events", [])],
                               rtol=1e-12)


def test_solver_method_bdf_gives_the_same_landing_as_adams():
    """solver.method selects CVODE's method (docs/shimmy.md section 5): BDF and the default
    Adams-Moulton agree to the tolerance's level (growth rates ~1e-4 apart at rtol 1e-7) and take
    different numbers of steps; anything else is a ValueError naming the key."""
    cfg = c.LandingConfig.default()
    assert cfg["solver.method"] == "adams"
    adams = c.simulate_landing(cfg, "coupled", record=False).metrics
    cfg["solver.method"] = "bdf"
    bdf = c.simulate_landing(cfg, "coupled", record=False).metrics
    assert bdf["growth_rate_per_s"] == pytest.approx(adams["growth_rate_per_s"], abs=2e-3)
    assert bdf["peak_torsion_rad"] == pytest.approx(adams["peak_torsion_rad"], rel=1e-4)
    assert bdf["steps"] != adams["steps"]
    with pytest.raises(ValueError, match=r"solver\.method: expected adams or bdf"):
        cfg["solver.method"] = "rk4"


@pytest.fixture(scope="module")
def serial_map(app_run):
    return c.stability_map(app_run[0], AXES, progress=False)


def map_arrays(m):
    return [m.growth_rate_per_s, m.frequency_hz, m.last_amplitude_rad, m.shimmy, m.valid, m.error]


def test_map_equals_the_apps_map_csv(app_run, serial_map):
    _, out = app_run
    (path,) = out.glob("map_forward_speed_mps_torsional_damping_nms_per_rad*coupled.csv")
    with open(path) as f:
        rows = [r for r in csv.reader(f) if r][1:]
    m = serial_map
    assert len(rows) == 9 and m.growth_rate_per_s.shape == (3, 3)
    cells = list(m.cells())
    for row, cell in zip(rows, cells):
        x, y, growth, freq, amp = map(float, row[:5])
        assert x == pytest.approx(cell["scenario.forward_speed_mps"], rel=1e-9)
        assert y == pytest.approx(cell["structure.torsional_damping_nms_per_rad"], rel=1e-9, abs=1e-12)
        assert growth == pytest.approx(cell["growth_rate_per_s"], rel=6e-9, abs=1e-300)
        assert freq == pytest.approx(cell["frequency_hz"], rel=6e-9, abs=1e-300)
        assert amp == pytest.approx(cell["final_amplitude_rad"], rel=6e-9, abs=1e-300)
        assert (row[5], row[6], row[7]) == (str(int(cell["shimmy"])), str(int(cell["valid"])), "")


def test_serial_map_equals_the_cpp_map_on_threads(app_run, serial_map):
    native = c.stability_map_native(app_run[0], AXES, threads=2)
    for a, b in zip(map_arrays(serial_map), map_arrays(native)):
        np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(serial_map.x_values, [40.0, 60.0, 80.0])


def test_dask_map_equals_the_serial_map(app_run, serial_map):
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        on_dask = c.stability_map(app_run[0], AXES, client=client, progress=True)
    for a, b in zip(map_arrays(on_dask), map_arrays(serial_map)):
        np.testing.assert_array_equal(a, b)


def test_bifurcation_sweep_arguments_are_checked_before_anything_runs():
    """threads must be an integer (not '4', 2.7 or True), an axis given as a mapping needs all
    four keys: each a clear error naming the argument, before a point is simulated."""
    axis = ("structure.offset_m", 0.3, 0.54, 2)
    for threads in ("4", 2.7, True, -1):
        with pytest.raises((TypeError, ValueError), match=r"threads = .*: must be an integer"):
            c.bifurcation_sweep(None, axis, threads=threads)
    with pytest.raises(ValueError, match=r"missing to \(an axis is \{parameter, from, to, points\}\)"):
        c.bifurcation_sweep(None, {"parameter": "structure.offset_m", "from": 0.3, "points": 2})
    with pytest.raises(ValueError, match="unknown key stop"):
        c.bifurcation_sweep(None, {"parameter": "structure.offset_m", "from": 0.3, "to": 0.5,
                                   "points": 2, "stop": 1})


def test_bifurcation_sweep_equals_the_apps_csv(shimmy_app, tmp_path):
    """contensou.bifurcation_sweep is contensou-shimmy --bifurcation's sweep, row for row, as a
    DataFrame with its linear boundary."""
    d = c.LandingConfig().to_dict()
    d["models"] = ["coupled"]
    d["structure"]["offset_m"] = 0.45
    d["scenario"]["forward_speed_mps"] = 58.0
    d["sweeps"] = [{"parameter": "structure.offset_m", "from": 0.3, "to": 0.54, "points": 4}]
    cfg = c.LandingConfig(d)
    cfg.to_json(tmp_path / "cfg.json")
    subprocess.run([str(shimmy_app), "--config", str(tmp_path / "cfg.json"), "--out",
                    str(tmp_path / "o"), "--bifurcation"], check=True, capture_output=True)
    df = c.bifurcation_sweep(cfg, ("structure.offset_m", 0.3, 0.54, 4), model="coupled")
    assert list(df.columns)[:3] == ["direction", "structure.offset_m", "state"]
    summary = json.loads((tmp_path / "o" / "summary.json").read_text())["bifurcation"][0]
    assert df.attrs["linear_boundary"] == pytest.approx(summary["linear_boundary"], rel=1e-12)
    for direction in ("up", "down"):
        rows = df[df["direction"] == direction]
        with open(tmp_path / "o" / f"bifurcation_offset_m_coupled_{direction}.csv") as f:
            app = list(csv.DictReader(f))
        assert len(rows) == len(app) == 4
        for (_, r), a in zip(rows.iterrows(), app):
            assert r["state"] == a["state"]
            assert r["amplitude_rad"] == pytest.approx(float(a["amplitude_rad"]), rel=1e-8)
            assert r["torque_link_nm"] == pytest.approx(float(a["torque_link_nm"]), rel=1e-8)
