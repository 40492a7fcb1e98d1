"""The FMUs as a real FMI importer sees them (docs/fmu.md): FMPy (pinned in
python/requirements.txt) validates the archives contensou-fmu writes, and simulates them against
the library:
  - the law FMU of a patch the test draws at random (radius, load, profile, friction, kappa,
    shift), in Model Exchange and Co-Simulation, to 1e-9 of f N against the exact integrals, its
    directional derivatives against the exact law's Jacobian;
  - the fractional law's FMU against the library's fractional law;
  - the gear FMU stepped by FMPy with the demo's brake and speed as inputs: the torsion's growth
    rate and frequency within 1 % of the native demo's (contensou.simulate_landing).
"""

from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

fmpy = pytest.importorskip("fmpy", reason="fmpy is in python/requirements.txt")
from fmpy import read_model_description, simulate_fmu  # noqa: E402
from fmpy.fmi2 import FMU2Slave  # noqa: E402
from fmpy.fmi3 import FMU3Slave  # noqa: E402
from fmpy.validation import validate_fmu  # noqa: E402

import contensou as c  # noqa: E402
import contensou.fmu  # noqa: E402,F401
from conftest import BUILD, program  # noqa: E402

# The contensou-fmu under test: the build's (contensou.fmu.command() reads $CONTENSOU_FMU).
os.environ.setdefault("CONTENSOU_FMU", str(BUILD / "apps" / "contensou-fmu"))


@pytest.fixture(scope="module")
def fmu_app() -> Path:
    return program("apps/contensou-fmu")


@pytest.fixture(scope="module")
def folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fmu")


def unseen_patch(seed: int) -> c.ContactPatch:
    """A patch drawn at random: radius, load, a smooth profile, friction, kappa and shift."""
    rng = np.random.default_rng(seed)
    profile = [c.uniform_profile, c.hertz_profile,
               lambda: c.cosine_series_profile(0.9, [1.0, 0.3 * rng.uniform(), -0.1])][seed % 3]()
    profile.kx = float(rng.uniform(-0.2, 0.2))
    profile.ky = float(rng.uniform(-0.1, 0.1))
    return c.ContactPatch(radius_m=float(rng.uniform(0.02, 0.2)), normal_load=float(rng.uniform(100, 1e4)),
                          friction=float(rng.uniform(0.2, 1.0)), kappa=float(rng.uniform(0.6, 1.0)),
                          profile=profile)


def kinematics(n: int, seed: int, radius: float) -> np.ndarray:
    """(n, 3) vx, vy, omega over every regime: sliding, spinning, both, near the kinks."""
    rng = np.random.default_rng(seed)
    v = 10.0 ** rng.uniform(-3, 1, n)
    angle = rng.uniform(0, 2 * np.pi, n)
    omega = rng.choice([-1.0, 1.0], n) * v / radius * 10.0 ** rng.uniform(-2, 2, n)
    k = np.column_stack([v * np.cos(angle), v * np.sin(angle), omega])
    k[: n // 10, :2] = 0.0  # pure spin
    k[n // 10 : n // 5, 2] = 0.0  # pure sliding
    return k


def test_archives_validate_and_are_laid_out_as_the_standard_says(folder: Path) -> None:
    law = c.fmu.export(c.seed_tire_patch(), folder / "law.fmu")
    gear = c.fmu.export_gear(folder / "gear.fmu")
    for path in (law, gear):
        assert validate_fmu(str(path)) == [], path
        out = subprocess.run([sys.executable, "-m", "fmpy", "validate", str(path)],
                             capture_output=True, text=True)
        assert out.returncode == 0 and out.stdout.strip() == "No problems found.", out
    assert sorted(zipfile.ZipFile(law).namelist()) == [
        "binaries/linux64/contensou_law.so", "modelDescription.xml", "resources/law.txt"]
    assert sorted(zipfile.ZipFile(gear).namelist()) == [
        "binaries/linux64/contensou_gear.so", "modelDescription.xml"]
    md = read_model_description(str(law))
    assert md.modelExchange and md.coSimulation and md.coSimulation.providesDirectionalDerivative
    assert "R = 0.087 m" in md.description and "exact law" in md.description
    names = [v.name for v in md.modelVariables]
    assert names[:7] == ["vx", "vy", "omega", "N", "Fx", "Fy", "Mz"]


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_law_fmu_of_an_unseen_patch_matches_the_exact_integrals(folder: Path, seed: int) -> None:
    patch = unseen_patch(seed)
    path = c.fmu.export(patch, folder / f"unseen{seed}.fmu", tolerance=1e-10)
    assert validate_fmu(str(path)) == []
    k = kinematics(200, seed, patch.radius_m)
    load = patch.normal_load * np.linspace(0.5, 1.5, len(k))
    t = np.arange(len(k), dtype=float)
    signals = np.array(list(zip(t, k[:, 0], k[:, 1], k[:, 2], load)),
                       dtype=[("time", float), ("vx", float), ("vy", float), ("omega", float), ("N", float)])
    # Model Exchange: the outputs at each time are the law at that time's inputs.
    me = simulate_fmu(str(path), fmi_type="ModelExchange", input=signals, output=["Fx", "Fy", "Mz"],
                      start_time=0.0, stop_time=t[-1], output_interval=1.0, solver="Euler", step_size=1.0)
    got = np.column_stack([me["Fx"], me["Fy"], me["Mz"]])
    # The exact integrals at the patch's own load, scaled to each sample's (the law is linear in N).
    exact = c.exact_resultants(c.ExactModel(patch), k[:, 0], k[:, 1], k[:, 2], tolerance=1e-12)
    want = np.asarray(exact.resultants) * (load / patch.normal_load)[:, None]
    fN = patch.friction * load
    scale = np.column_stack([fN, fN, fN * patch.radius_m])
    error = np.abs(got - want) / scale
    assert error.max() <= 1e-9, (error.max(), np.unravel_index(error.argmax(), error.shape))
    # The model description names the profile, not the temporary table it was handed over in.
    description = zipfile.ZipFile(path).read("modelDescription.xml").decode()
    assert "contensou-fmu-" not in description
    if seed % 3 == 2:
        assert "cosine_series profile of the patch exported, sampled at 4097 points" in description


def test_law_fmu_co_simulation_and_directional_derivatives(folder: Path) -> None:
    patch = c.seed_tire_patch()
    patch.profile.kx = 0.14
    patch.slip_speed_friction = c.SlipSpeedFriction(0.8, 0.45, 10.0, 2.0)
    path = c.fmu.export(patch, folder / "slip.fmu")
    assert validate_fmu(str(path)) == []
    law = c.ExactLaw(patch)
    md = read_model_description(str(path))
    slave = FMU2Slave(guid=md.guid, unzipDirectory=fmpy.extract(str(path)),
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName="law")
    slave.instantiate()
    slave.setupExperiment(startTime=0.0)
    slave.enterInitializationMode()
    slave.exitInitializationMode()
    k = kinematics(100, 9, patch.radius_m)
    N = patch.normal_load
    E, J = c.exact_law_resultants(law, k[:, 0], k[:, 1], k[:, 2], jacobian=True)
    for i, (vx, vy, omega) in enumerate(k):
        slave.setReal([0, 1, 2, 3], [vx, vy, omega, N])
        slave.doStep(currentCommunicationPoint=float(i), communicationStepSize=1.0)
        out = np.array(slave.getReal([4, 5, 6]))
        np.testing.assert_allclose(out, E[i], rtol=1e-12, atol=1e-12 * 0.8 * N)
        for j in range(3):
            d = np.array(slave.getDirectionalDerivative([4, 5, 6], [j], [1.0]))
            np.testing.assert_allclose(d, J[i][:, j], rtol=1e-12, atol=1e-9 * np.abs(J[i]).max())
        dN = np.array(slave.getDirectionalDerivative([4, 5, 6], [3], [1.0]))
        np.testing.assert_allclose(dN * N, out, rtol=1e-12, atol=1e-12 * N)
    slave.terminate()
    slave.freeInstance()


def test_fmi3_archives_validate_and_give_the_fmi2_numbers(folder: Path) -> None:
    patch = unseen_patch(7)
    two = c.fmu.export(patch, folder / "two.fmu")
    three = c.fmu.export(patch, folder / "three.fmu", fmi_version=3)
    gear3 = c.fmu.export_gear(folder / "gear3.fmu", fmi_version=3)
    for path in (three, gear3):
        assert validate_fmu(str(path)) == [], path
    assert "binaries/x86_64-linux/contensou_law.so" in zipfile.ZipFile(three).namelist()
    assert read_model_description(str(three)).fmiVersion == "3.0"
    k = kinematics(60, 7, patch.radius_m)
    t = np.arange(len(k), dtype=float)
    signals = np.array(list(zip(t, k[:, 0], k[:, 1], k[:, 2], np.full(len(k), patch.normal_load))),
                       dtype=[("time", float), ("vx", float), ("vy", float), ("omega", float), ("N", float)])
    runs = {}
    for name, path in (("2", two), ("3", three)):
        for kind in ("ModelExchange", "CoSimulation"):
            r = simulate_fmu(str(path), fmi_type=kind, input=signals, output=["Fx", "Fy", "Mz"],
                             stop_time=t[-1], output_interval=1.0, solver="Euler", step_size=1.0)
            runs[name, kind] = np.column_stack([r["Fx"], r["Fy"], r["Mz"]])
    for kind in ("ModelExchange", "CoSimulation"):
        assert np.array_equal(runs["2", kind], runs["3", kind]), kind
    # Directional and adjoint derivatives: the same Jacobian as the library's exact law.
    md = read_model_description(str(three))
    slave = FMU3Slave(guid=md.guid, unzipDirectory=fmpy.extract(str(three)),
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName="law3")
    slave.instantiate()
    slave.enterInitializationMode(startTime=0.0)
    slave.exitInitializationMode()
    vx, vy, omega = k[30]
    slave.setFloat64([0, 1, 2, 3], [vx, vy, omega, patch.normal_load])
    _, J = c.exact_law_resultants(c.ExactLaw(patch), vx, vy, omega, jacobian=True)
    J = np.asarray(J).reshape(3, 3)
    for j in range(3):
        d = slave.getDirectionalDerivative([4, 5, 6], [j], [1.0])
        np.testing.assert_allclose(d, J[:, j], rtol=1e-12, atol=1e-9 * np.abs(J).max())
    a = slave.getAdjointDerivative([4, 5, 6], [0, 1, 2], [1.0, 0.0, 0.0], nSensitivity=3)
    np.testing.assert_allclose(a, J[0, :], rtol=1e-12, atol=1e-9 * np.abs(J).max())
    slave.terminate()
    slave.freeInstance()
    # The gear in FMI 3.0: the same landing as in FMI 2.0.
    gear2 = folder / "gear.fmu"
    if not gear2.exists():
        c.fmu.export_gear(gear2)
    out = [simulate_fmu(str(g), fmi_type="CoSimulation", stop_time=0.2, output_interval=5e-4,
                        output=["psi_rad"])["psi_rad"] for g in (gear2, gear3)]
    assert np.array_equal(out[0], out[1]) and np.abs(out[0]).max() > 0


def test_fractional_law_fmu_matches_the_library(folder: Path) -> None:
    patch = unseen_patch(4)  # a Hertz profile: passed by name, the same patch as the library's
    path = c.fmu.export(patch, folder / "fractional.fmu", law="fractional")
    assert validate_fmu(str(path)) == []
    k = kinematics(50, 5, patch.radius_m)
    t = np.arange(len(k), dtype=float)
    signals = np.array(list(zip(t, k[:, 0], k[:, 1], k[:, 2], np.full(len(k), patch.normal_load))),
                       dtype=[("time", float), ("vx", float), ("vy", float), ("omega", float), ("N", float)])
    me = simulate_fmu(str(path), fmi_type="ModelExchange", input=signals, output=["Fx", "Fy", "Mz"],
                      stop_time=t[-1], output_interval=1.0, solver="Euler", step_size=1.0)
    got = np.column_stack([me["Fx"], me["Fy"], me["Mz"]])
    want = np.asarray(c.fractional_resultants(c.fractional_law_from_patch(patch), k[:, 0], k[:, 1], k[:, 2]))
    np.testing.assert_allclose(got, want.reshape(got.shape), rtol=1e-12,
                               atol=1e-13 * patch.friction * patch.normal_load)


def test_bad_export_options_are_refused(folder: Path) -> None:
    patch = c.seed_tire_patch()
    patch.slip_speed_friction = c.SlipSpeedFriction(0.8, 0.45, 10.0, 2.0)
    with pytest.raises(ValueError, match="slip-speed law f\\(w\\) needs the exact law"):
        c.fmu.export(patch, folder / "bad.fmu", law="fractional")
    with pytest.raises(ValueError, match="tolerance"):
        c.fmu.export(c.seed_tire_patch(), folder / "bad.fmu", tolerance=1.0)
    # Names no XML reader accepts: refused by name, not written into modelDescription.xml.
    for name in ("tire\abell", "a\x01b\x1bc"):
        with pytest.raises(ValueError, match="model_name .*control character"):
            c.fmu.export(c.seed_tire_patch(), folder / "bad.fmu", model_name=name)
    # Arguments of the wrong kind: a clear TypeError or ValueError naming them, nothing written.
    with pytest.raises(TypeError, match="patch: a ContactPatch .* is required, not str"):
        c.fmu.export("seed-tire", folder / "bad.fmu")  # type: ignore[arg-type]
    for version in ("3", True, 2.0):
        with pytest.raises(TypeError, match="fmi_version: the integer 2 or 3 is required"):
            c.fmu.export(c.seed_tire_patch(), folder / "bad.fmu", fmi_version=version)
        with pytest.raises(TypeError, match="fmi_version: the integer 2 or 3 is required"):
            c.fmu.export_gear(folder / "bad.fmu", fmi_version=version)
    with pytest.raises(ValueError, match="fmi_version = 4: must be 2"):
        c.fmu.export_gear(folder / "bad.fmu", fmi_version=4)
    assert not (folder / "bad.fmu").exists()


def test_gear_fmu_names_a_tolerance_cvode_cannot_meet(folder: Path) -> None:
    """A relative tolerance of 1e-300 set on the gear FMU is refused naming the parameter and its
    range (it failed with CVODE's bare flag)."""
    path = folder / "gear_tolerance.fmu"
    c.fmu.export_gear(path)
    messages: list[str] = []

    def log(env: object, name: object, status: object, category: object, message: object) -> None:
        messages.append(message.decode() if isinstance(message, bytes) else str(message))

    with pytest.raises(Exception):
        simulate_fmu(str(path), fmi_type="CoSimulation", stop_time=0.1, logger=log,
                     start_values={"solver.relative_tolerance": 1e-300})
    assert any("solver.relative_tolerance = 1e-300: must lie in [1e-1" in m for m in messages), messages


def oscillation(t: np.ndarray, rate: np.ndarray, position: np.ndarray) -> tuple[float, float]:
    """Frequency and growth rate of the torsion as the library measures them
    (src/gear/oscillation.cpp): the rate's zero crossings, and the slope of ln|rate peak|."""
    s = rate < 0.0
    idx = np.nonzero((s[1:] != s[:-1]) & (rate[1:] != rate[:-1]))[0] + 1
    w = rate[idx - 1] / (rate[idx - 1] - rate[idx])
    tc = t[idx - 1] + w * (t[idx] - t[idx - 1])
    frequency = (len(tc) - 1) / (2.0 * (tc[-1] - tc[0]))
    peaks = [a + int(np.argmax(np.abs(rate[a:b]))) for a, b in zip(idx[:-1], idx[1:])]
    growth = np.polyfit(t[peaks], np.log(np.abs(rate[peaks])), 1)[0]
    return float(frequency), float(growth)


@pytest.mark.parametrize("model", ["coupled", "decoupled", "von_schlippe"])
def test_gear_fmu_reproduces_the_demo(folder: Path, model: str) -> None:
    config = c.LandingConfig.default()
    native = c.simulate_landing(config, model)
    s = config.to_dict()["scenario"]
    dt = config.to_dict()["solver"]["output_interval_s"]
    path = folder / "gear.fmu"
    if not path.exists():
        c.fmu.export_gear(path)
    # The demo's scenario as inputs: the speed, and the brake command between brake on and off.
    times = [0.0, s["brake_on_s"], s["brake_on_s"], s["brake_off_s"], s["brake_off_s"], s["end_time_s"]]
    torque = [0.0, 0.0, s["brake_max_torque_nm"], s["brake_max_torque_nm"], 0.0, 0.0]
    signals = np.array([(t, s["forward_speed_mps"], b) for t, b in zip(times, torque)],
                       dtype=[("time", float), ("forward_speed_mps", float), ("brake_torque_command_nm", float)])
    result = simulate_fmu(str(path), fmi_type="CoSimulation", input=signals, start_time=0.0,
                          stop_time=s["end_time_s"], output_interval=dt, start_values={"contact_model": model},
                          output=["psi_rad", "psidot_radps", "torque_link_nm", "Fx_n", "wheel_spin_radps"])
    start, end = s["brake_on_s"] + 0.1, s["brake_off_s"]
    window = (result["time"] >= start - 1e-9) & (result["time"] <= end + 1e-9)
    f_fmu, g_fmu = oscillation(result["time"][window], result["psidot_radps"][window], result["psi_rad"][window])
    m = native.metrics
    # The same analysis on the native samples gives the library's own numbers.
    nt = native.t
    nw = (nt >= start - 1e-9) & (nt <= end + 1e-9)
    f_nat, g_nat = oscillation(nt[nw], native["psidot_radps"][nw], native["psi_rad"][nw])
    assert f_nat == pytest.approx(m["frequency_hz"], rel=1e-9)
    assert g_nat == pytest.approx(m["growth_rate_per_s"], rel=1e-6, abs=1e-9)
    assert f_fmu == pytest.approx(m["frequency_hz"], rel=0.01), (f_fmu, m)
    assert g_fmu == pytest.approx(m["growth_rate_per_s"], rel=0.01, abs=0.01 * 2 * np.pi * m["frequency_hz"] * 0.01), (g_fmu, m)
    assert np.all(np.isfinite(result["torque_link_nm"]))
