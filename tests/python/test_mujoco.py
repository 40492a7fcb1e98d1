"""The MuJoCo plugin (plugins/mujoco) driven by the `mujoco` Python module, and the engine
coefficient converter. Oracles: the library's own resultants at the plugin's state (through the
Python package), MuJoCo's mj_applyFT for the mapping to generalised forces, the closed forms of
theory.md section 3 (the sliding disk's fixed point 0.6530, integrated by RK4 for the stopping
time), and (2/3) f N R at pure spin.

Skipped, with the reason shown, only if `mujoco` cannot be imported; a missing plugin library
is an error.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys

import numpy as np
import pytest

from conftest import BUILD, ROOT, program

mujoco = pytest.importorskip(
    "mujoco", reason="MuJoCo is not installed in this Python (pip install mujoco): plugin tests skipped"
)
sys.path.insert(0, str(ROOT / "bench"))
import mujoco_common as mc  # noqa: E402

import contensou  # noqa: E402
from contensou.engines import engine_coefficients  # noqa: E402


@pytest.fixture(scope="module", autouse=True)
def plugin():
    path = mc.plugin_path()
    assert path.exists(), f"{path} is missing: scripts/setup.sh builds it when MuJoCo is found"
    mc.load_plugin(mujoco)


def settled_disk(variant: str, disk: mc.Disk, regularization: float = 1e-4, **patch):
    m = mujoco.MjModel.from_xml_string(mc.disk_mjcf(disk, variant, regularization, **patch))
    d = mujoco.MjData(m)
    for _ in range(200):
        mujoco.mj_step(m, d)
    return m, d


@pytest.mark.parametrize("variant,profile,stiffness", [
    ("fractional", "uniform", None), ("exact", "uniform", None),
    ("fractional", "hertz", 7.25 / 0.05**3), ("exact", "hertz", 7.25 / 0.05**3)])
def test_plugin_wrench_equals_library_at_a_frozen_state(variant, profile, stiffness):
    disk = mc.Disk(timestep=1e-3)
    m, d = settled_disk(variant, disk, regularization=1e-3, profile=profile, stiffness=stiffness)
    d.qvel[:] = [0.31, -0.12, 0.0, 0.0, 0.0, 4.0]  # vx, vy (world), spin about z
    N = 7.25
    d.plugin_state[0] = N  # the normal force of the "previous step"
    mujoco.mj_forward(m, d)
    s = d.plugin_state
    # R given, or R = (N / k)^(1/3) from the stiffness k: 0.05 m here.
    radius = disk.radius if stiffness is None else 0.05
    assert s[1] == N and s[2] == pytest.approx(radius, rel=1e-12)

    # Independent kinematics: the patch centre is the disk's centre projected onto the contact
    # plane (through the mean of the contact points; the floor's normal is z); the disk is flat,
    # so the body-frame spin is the world spin.
    con = d.contact[0]
    n, t1 = con.frame[:3], con.frame[3:6]
    assert n @ [0, 0, 1] == pytest.approx(1.0)
    ey = np.cross(n, t1)
    plane_z = np.mean([c.pos[2] for c in d.contact[: d.ncon]])
    centre = np.array([d.xpos[1][0], d.xpos[1][1], plane_z])
    w = d.qvel[3:6]
    v = d.qvel[:3] + np.cross(w, centre - d.xpos[1])
    vx, vy, omega = v @ t1, v @ ey, w[2]
    assert s[3:6] == pytest.approx([vx, vy, omega], abs=1e-9)

    # The library at that state: the patch carrying N; N = 2 pi R^2 p* A^1 (theory.md section 4)
    # with A^1 = 1/2 (uniform) or 1/3 (Hertz, integral of rho sqrt(1 - rho^2)).
    patch = contensou.ContactPatch()
    patch.radius_m = radius
    patch.friction = disk.friction
    patch.profile = contensou.uniform_profile() if profile == "uniform" else contensou.hertz_profile()
    a1 = 0.5 if profile == "uniform" else 1 / 3
    patch.reference_pressure_pa = N / (2 * math.pi * radius**2 * a1)
    if variant == "exact":
        want = contensou.exact_resultants(patch, vx, vy, omega, tolerance=1e-12).resultants
    else:
        law = contensou.fractional_law_from_patch(patch)
        law.regularization_speed = 1e-3
        want = contensou.fractional_resultants(law, vx, vy, omega)
    assert s[6:9] == pytest.approx(want, rel=1e-6, abs=1e-9 * N)

    # The generalised force: the wrench at the centre through MuJoCo's own mj_applyFT.
    qfrc = np.zeros(m.nv)
    force = want[0] * t1 + want[1] * ey
    mujoco.mj_applyFT(m, d, force, want[2] * n, centre, 1, qfrc)
    assert d.qfrc_passive == pytest.approx(qfrc, rel=1e-6, abs=1e-9)


def test_plugin_rejects_bad_configuration_with_a_clear_error():
    disk = mc.Disk()
    bad = mc.disk_mjcf(disk, "fractional").replace('value="uniform"', 'value="cone"')
    with pytest.raises(Exception, match="profile.*cone"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(bad))
    condim = mc.disk_mjcf(disk, "exact").replace('condim="1"', 'condim="3"', 1)
    with pytest.raises(Exception, match="condim"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(condim))


def test_disk_with_the_exact_law_stops_at_the_farkas_ratio():
    """Farkas et al. 2003: v/(omega R) -> 0.6530, both motions stop together."""
    disk = mc.Disk(timestep=2e-5)
    tr = mc.run_disk(mujoco, disk, "exact", 1.0, 1.0, 0.35)
    fixed_point = mc.farkas_ratio()
    assert fixed_point == pytest.approx(0.6530, abs=5e-5)
    assert tr.ratio_at(1e-3) == pytest.approx(fixed_point, rel=0.01)
    ref = mc.closed_form_disk(1.0, 1.0, disk.friction)
    # Stop together (1 % of the start of each) and at the closed form's time.
    assert tr.time_below("v", 0.01) == pytest.approx(tr.time_below("u", 0.01), rel=0.01)
    assert tr.time_at(1e-3) == pytest.approx(ref.time_at(1e-3), rel=0.01)


def test_mujoco_torsional_coefficient_from_the_converter_matches_the_plugin_at_pure_spin():
    """A sphere spinning on a plane (one contact point): MuJoCo's torsional torque per unit of
    its normal force with the converter's mu_t, and the plugin's, both equal (2/3) f R."""
    f, radius = 0.5, 0.01
    mu_t = engine_coefficients("uniform", radius, f)[0].value

    def sphere(contact: str, ext: str = "") -> str:
        return (f'<mujoco><option timestep="1e-4" cone="elliptic"/>{ext}<worldbody>'
                f'<geom name="floor" type="plane" size="1 1 .1" {contact}/>'
                '<body pos="0 0 0.05"><freejoint/>'
                f'<geom name="ball" type="sphere" size="0.05" density="1000" {contact}/></body>'
                "</worldbody></mujoco>")

    def spin(xml: str):
        m = mujoco.MjModel.from_xml_string(xml)
        d = mujoco.MjData(m)
        for _ in range(2000):
            mujoco.mj_step(m, d)
        d.qvel[:] = 0.0
        d.qvel[5] = 10.0
        for _ in range(100):
            mujoco.mj_step(m, d)
        return m, d

    m, d = spin(sphere(f'condim="4" friction="{f} {mu_t} 0"'))
    assert d.ncon == 1
    r = np.zeros(6)
    mujoco.mj_contactForce(m, d, 0, r)
    mujoco_ratio = abs(r[3]) / r[0]
    ext = ('<extension><plugin plugin="contensou.friction"><instance name="p">'
           '<config key="pairs" value="ball floor"/>'
           f'<config key="friction" value="{f}"/><config key="radius" value="{radius}"/>'
           '<config key="law" value="exact"/></instance></plugin></extension>')
    m, d = spin(sphere('condim="1"', ext))
    plugin_ratio = abs(d.plugin_state[8]) / d.plugin_state[1]
    assert mujoco_ratio == pytest.approx(2 / 3 * f * radius, rel=1e-3)
    assert plugin_ratio == pytest.approx(2 / 3 * f * radius, rel=1e-6)


def test_converter_round_trip_python_cpp_and_mjcf():
    """The Python converter gives the C++ app's numbers, and its MJCF snippet compiles in MuJoCo
    to the same coefficients."""
    app = program("apps/contensou-engine-coefficients")
    for profile in ("uniform", "hertz"):
        out = subprocess.run([str(app), "--profile", profile, "--radius", "0.05", "--friction",
                              "0.6", "--json"], check=True, capture_output=True, text=True).stdout
        cpp = json.loads(out)["rows"]
        py = engine_coefficients(profile, 0.05, 0.6)
        assert [r["engine"] for r in cpp] == [r.engine for r in py]
        for c, p in zip(cpp, py):
            assert p.value == pytest.approx(c["value"], rel=1e-9)
            assert p.worst_force_error == pytest.approx(c["worst_force_error"], abs=1e-6)
            assert p.worst_torque_error == pytest.approx(c["worst_torque_error"], abs=1e-6)
        geom = py[0].snippet.split("  ")[0].replace("<geom ", '<geom name="g" type="sphere" size="1" ')
        m = mujoco.MjModel.from_xml_string(f"<mujoco><worldbody>{geom}</worldbody></mujoco>")
        assert m.geom_condim[0] == 4
        assert m.geom_friction[0][:2] == pytest.approx([0.6, py[0].value], rel=1e-5)
    bad = subprocess.run([str(app), "--profile", "uniform", "--radius", "-1", "--friction", "0.5"],
                         capture_output=True, text=True)
    assert bad.returncode != 0 and "--radius = -1" in bad.stderr
    with pytest.raises(ValueError, match="--friction"):
        engine_coefficients("uniform", 0.1, float("nan"))
    with pytest.raises(ValueError, match="--profile 'cone'"):
        engine_coefficients("cone", 0.1, 0.5)


def test_copied_data_steps_identically_and_reset_clears_the_state():
    """mj_copyData goes through the plugin's copy: a copy steps bit for bit like the original."""
    import copy

    m, d = settled_disk("exact", mc.Disk(timestep=1e-3))
    d.qvel[0], d.qvel[5] = 0.5, 3.0
    twin = copy.copy(d)
    for _ in range(100):
        mujoco.mj_step(m, d)
        mujoco.mj_step(m, twin)
    assert np.array_equal(d.qpos, twin.qpos) and np.array_equal(d.plugin_state, twin.plugin_state)
    mujoco.mj_resetData(m, d)
    assert not d.plugin_state.any()
