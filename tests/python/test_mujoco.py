"""The MuJoCo plugin (plugins/mujoco) of the installed package (contensou.mujoco.load_plugin();
$CONTENSOU_MUJOCO_PLUGIN loads another build's) driven by the `mujoco` Python module, and the
engine coefficient converter. Oracles: the library's own resultants at the plugin's state
(through the Python package; for the exact law the adaptive integrator, within the law's tolerance),
MuJoCo's mj_applyFT for the mapping to generalised forces, the closed forms of theory.md
section 3 (the sliding disk's fixed point 0.6530, integrated by RK4 for the stopping time),
(2/3) f N R at pure spin, and for the set-valued law MuJoCo's dense mass matrix and Jacobian
(the Delassus matrix), a loaded disk's displacement and the direction of a force.

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

# The state of a pair (plugins/mujoco/contensou_plugin.cpp, header comment).
STICK, ITERATIONS, HISTORY, STATE = 9, 10, 33, 34  # STATE: numbers a pair


@pytest.fixture(scope="module", autouse=True)
def plugin():
    path = mc.plugin_path()
    assert path.exists(), f"{path} is missing: pip install builds it when MuJoCo is found"
    mc.load_plugin(mujoco)


def patch_x_axis(m, d, n, geom: str = "disk"):
    """The patch frame's x: the tire geom's x axis projected onto the contact plane."""
    g = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, geom)
    x = d.geom_xmat[g].reshape(3, 3)[:, 0]
    x = x - (x @ n) * n
    return x / np.linalg.norm(x)


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
    n, t1 = con.frame[:3], patch_x_axis(m, d, con.frame[:3])
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
    shape = contensou.uniform_profile() if profile == "uniform" else contensou.hertz_profile()
    a1 = 0.5 if profile == "uniform" else 1 / 3
    patch = contensou.ContactPatch(radius_m=radius, friction=disk.friction, profile=shape,
                                   reference_pressure_pa=N / (2 * math.pi * radius**2 * a1))
    # The same patch made from the load itself.
    by_load = contensou.ContactPatch(radius_m=radius, friction=disk.friction, profile=shape,
                                     normal_load=N)
    assert by_load.reference_pressure_pa == pytest.approx(patch.reference_pressure_pa, rel=1e-14)
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


def multi_pair_mjcf(profile: str = "uniform", kappa: float = 1.0, tolerance: str = "1e-6",
                    pairs: str = "disk0 floor; disk1 floor; ball block; disk2 floor",
                    law: str = "exact", second_instance: str = "") -> str:
    """Three disks (R = 0.1 m) on a plane, a ball (r = 0.1 m: a patch is no wider than its tire)
    on a box (MuJoCo orders that contact (ball, block): tire first) and a fourth disk that no
    pair names (condim 1: no friction at all); one plugin instance for `pairs`, R = 0.1 m,
    f = 0.5."""
    tol = f'<config key="tolerance" value="{tolerance}"/>' if tolerance else ""
    disks = "".join(
        f'<body pos="{0.4 * i} 0 0.005"><freejoint/><geom name="disk{i}" type="cylinder" '
        'size="0.1 0.005" density="1000" condim="1"/></body>' for i in range(4))
    return f"""<mujoco><option timestep="1e-3"/>
      <extension><plugin plugin="contensou.friction"><instance name="patch">
        <config key="pairs" value="{pairs}"/><config key="friction" value="0.5"/>
        <config key="radius" value="0.1"/><config key="profile" value="{profile}"/>
        <config key="kappa" value="{kappa}"/><config key="law" value="{law}"/>{tol}
      </instance>{second_instance}</plugin></extension>
      <worldbody><geom name="floor" type="plane" size="5 5 .1" condim="1"/>
        <geom name="block" type="box" pos="3 0 0.1" size="0.3 0.3 0.1" condim="1"/>
        <body pos="3 0 0.3"><freejoint/>
          <geom name="ball" type="sphere" size="0.1" density="1000" condim="1"/></body>
        {disks}</worldbody></mujoco>"""


def reference_patch(profile: str, kappa: float, N: float, radius: float = 0.1):
    """The patch of the plugin's configuration carrying the normal force N."""
    shape = {"uniform": contensou.uniform_profile, "hertz": contensou.hertz_profile,
             "seed-tire": contensou.seed_tire_profile}[profile]()
    return contensou.ContactPatch(radius_m=radius, normal_load=N, friction=0.5, kappa=kappa,
                                  profile=shape)


@pytest.mark.parametrize("profile,kappa", [("uniform", 1.0), ("hertz", 0.6), ("seed-tire", 1.0)])
def test_exact_law_wrench_is_the_integrators_within_the_law_tolerance_for_every_pair(profile,
                                                                                       kappa):
    """Four pairs at four twists (pure spin, sliding and spinning, pure sliding, the ball's
    contact in MuJoCo's (tire, road) order), each with its own normal force, at a frozen state:
    each pair's twist is its own tire's (velocity at its patch centre, in its patch frame) and
    its wrench is the adaptive integrator's (exact_resultants, 1e-12) for the same patch within
    the law's tolerance 1e-6 of f N and f N R; the disk that no pair names gets no force."""
    m = mujoco.MjModel.from_xml_string(multi_pair_mjcf(profile, kappa))
    d = mujoco.MjData(m)
    for _ in range(200):
        mujoco.mj_step(m, d)
    geoms = ["disk0", "disk1", "ball", "disk2"]
    qvel = {"disk0": [0, 0, 0, 0, 0, 7.0], "disk1": [0.3, -0.2, 0, 0, 0, 3.0],
            "disk2": [-0.4, 0.1, 0, 0, 0, 0], "ball": [0.05, 0.2, 0, 0, 0, -2.5],
            "disk3": [0.5, 0, 0, 0, 0, 3.0]}
    loads = [2.0, 5.0, 3.0, 7.0]
    for name, v in qvel.items():
        body = m.geom_bodyid[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, name)]
        d.qvel[m.body_dofadr[body]:m.body_dofadr[body] + 6] = v
    for k, N in enumerate(loads):
        d.plugin_state[STATE * k] = N
    mujoco.mj_forward(m, d)
    for k, (name, N) in enumerate(zip(geoms, loads)):
        s = d.plugin_state[STATE * k:STATE * (k + 1)]
        g = mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, name)
        body = m.geom_bodyid[g]
        mine = [c for c in d.contact[: d.ncon] if g in c.geom]
        sign = 1.0 if mine[0].geom[1] == g else -1.0  # MuJoCo's normal: geom[0] into geom[1]
        n = sign * mine[0].frame[:3]
        assert n @ [0, 0, 1] == pytest.approx(1.0)
        point = np.mean([c.pos for c in mine], axis=0)
        centre = d.geom_xpos[g] - ((d.geom_xpos[g] - point) @ n) * n
        w = d.xmat[body].reshape(3, 3) @ d.qvel[m.body_dofadr[body] + 3:m.body_dofadr[body] + 6]
        v = d.qvel[m.body_dofadr[body]:m.body_dofadr[body] + 3] + np.cross(w, centre - d.xpos[body])
        ex = patch_x_axis(m, d, n, name)
        twist = [v @ ex, v @ np.cross(n, ex), w @ n]
        assert s[1] == N and s[3:6] == pytest.approx(twist, abs=1e-9), name
        want = contensou.exact_resultants(reference_patch(profile, kappa, N), *s[3:6],
                                          tolerance=1e-12).resultants
        f_n, f_n_r = 0.5 * N, 0.5 * N * 0.1
        assert abs(s[6:8] - want[:2]).max() <= 1e-6 * f_n, name
        assert abs(s[8] - want[2]) <= 1e-6 * f_n_r, name
        assert abs(s[8]) > 1e-3 * f_n_r or name == "disk2", name  # not trivially zero
    free = m.body_dofadr[m.geom_bodyid[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "disk3")]]
    assert not d.qfrc_passive[free:free + 6].any()


@pytest.mark.parametrize("pairs,message", [
    ("disk0 floor; disk0 floor", "'disk0 floor' and 'disk0 floor' are the same geom pair"),
    ("ball block; disk0 floor; block ball", "'block ball' and 'ball block' are the same geom pair"),
    ("floor disk0", "'floor disk0'.*tire \\(first\\) geom is a plane"),
    ("disk0 disk0", "'disk0 disk0' never touch: a geom has no contact with itself"),
    ("disk0 disk1", "'disk0 disk1' never touch: their contype and conaffinity do not match"),
])
def test_a_pair_whose_friction_would_be_doubled_or_lost_is_an_error(pairs, message):
    """The same geom pair twice (in either order) would get its friction twice; a plane as the
    tire puts the patch at the plane's centre; a geom with itself, or two geoms whose contype and
    conaffinity exclude each other, never touch: errors at init naming the pair."""
    xml = multi_pair_mjcf(pairs=pairs)
    if "disk1" in pairs:
        xml = xml.replace('name="disk1" type="cylinder"',
                          'name="disk1" type="cylinder" contype="2" conaffinity="2"')
    with pytest.raises(Exception, match=message):
        mujoco.MjData(mujoco.MjModel.from_xml_string(xml))
    # Two instances naming one pair (in either order) would also apply it twice.
    other = ('<instance name="again"><config key="pairs" value="block ball"/>'
             '<config key="friction" value="0.5"/><config key="radius" value="0.1"/></instance>')
    with pytest.raises(Exception, match="'block ball' is also a pair of plugin instance 'again'"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(multi_pair_mjcf(second_instance=other)))


@pytest.mark.parametrize("law,value,message", [
    ("exact", "0.1", "'tolerance' = '0.1' is outside \\(1e-14, 1e-2\\) for law 'exact'"),
    ("exact", "1e-15", "'tolerance' = '1e-15' is outside \\(1e-14, 1e-2\\) for law 'exact'"),
    ("exact", "0.01", "'tolerance' = '0.01' is outside \\(1e-14, 1e-2\\)"),
    ("exact", "tight", "'tolerance' = 'tight' is not a positive number"),
    ("exact", "-1e-8", "'tolerance' = '-1e-8' is not a positive number"),
    ("set-valued", "1e-4",
     "'tolerance' = '1e-4' is outside \\[1e-14, 1e-6\\] for law 'set-valued'"),
    ("fractional", "1e-8", "'tolerance' = '1e-8' applies to laws 'exact' and 'set-valued' only"),
])
def test_bad_tolerance_is_an_error_naming_the_key_and_value(law, value, message):
    """The exact law's tolerance lies in (1e-14, 1e-2), the limit surface's in [1e-14, 1e-6]; the
    fractional law has none: anything else is an error at init naming the key and the value."""
    with pytest.raises(Exception, match=message):
        mujoco.MjData(mujoco.MjModel.from_xml_string(multi_pair_mjcf(law=law, tolerance=value)))


def test_plugin_rejects_bad_configuration_with_a_clear_error():
    disk = mc.Disk()
    bad = mc.disk_mjcf(disk, "fractional").replace('value="uniform"', 'value="cone"')
    with pytest.raises(Exception, match="profile.*cone"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(bad))
    condim = mc.disk_mjcf(disk, "exact").replace('condim="1"', 'condim="3"', 1)
    with pytest.raises(Exception, match="condim"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(condim))


def test_plugin_rejects_bad_set_valued_configuration():
    disk = mc.Disk()
    law = '<config key="law" value="exact"/>'
    bad = {
        "surface.*needs law 'set-valued'": mc.disk_mjcf(disk, "exact").replace(
            law, law + '<config key="surface" value="ellipsoid"/>'),
        "surface.*'cone'.*exact or ellipsoid": mc.disk_mjcf(disk, "set-valued-ellipsoid").replace(
            'value="ellipsoid"', 'value="cone"'),
        "law.*'set valued'.*set-valued": mc.disk_mjcf(disk, "exact").replace(
            'value="exact"', 'value="set valued"'),
    }
    for message, xml in bad.items():
        with pytest.raises(Exception, match=message):
            mujoco.MjData(mujoco.MjModel.from_xml_string(xml))
    # A key of another law is an error, not silently ignored; kappa must be positive.
    law = '<config key="law" value="set-valued"/>'
    with pytest.raises(Exception, match="regularization.*'fractional' only.*set-valued"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(mc.disk_mjcf(disk, "set-valued").replace(
            law, law + '<config key="regularization" value="1e-3"/>')))
    with pytest.raises(Exception, match="kappa.*'-0.5'.*positive"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(mc.disk_mjcf(disk, "exact", kappa=-0.5)))


def disk_with(key: str, value: str, law: str = "exact") -> str:
    """The disk of mc.disk_mjcf (R = 0.1 m, f = 0.5) with one configuration value replaced or
    added (radius for stiffness, regularization with the fractional law)."""
    xml = mc.disk_mjcf(mc.Disk(timestep=1e-3), law)
    if key == "stiffness":
        return xml.replace('<config key="radius" value="0.1"/>',
                           f'<config key="stiffness" value="{value}"/>')
    if f'key="{key}"' in xml:
        start = xml.index(f'<config key="{key}" value="')
        end = xml.index("/>", start) + 2
        return xml[:start] + f'<config key="{key}" value="{value}"/>' + xml[end:]
    return xml.replace("</instance>", f'<config key="{key}" value="{value}"/></instance>')


# The numeric keys and their ranges (docs/mujoco.md, "Valid values"): a value outside is an
# error naming the key, the value as written and the range, when the model is compiled (the
# ranges of the doubles and of MuJoCo's own numbers) or when its data is made (those of the tire
# geom: its bounding radius, 0.100125 m for the disk, and the weight it carries, 3.08 N).
@pytest.mark.parametrize("key,value,law,message", [
    ("radius", "1e308", "exact", r"'radius' = '1e308' is outside \[1e-15, 1e\+10\] m"),
    ("radius", "1e-310", "exact", r"'radius' = '1e-310' is outside \[1e-15, 1e\+10\] m"),
    ("radius", "0.5", "exact",
     r"'radius' = '0.5' is outside \[1e-15, 0.100125\] m: .*bounding radius \(pair 'disk floor'\)"),
    ("radius", "0.10013", "exact", r"'radius' = '0.10013' is outside \[1e-15, 0.100125\] m"),
    ("stiffness", "1e-300", "exact", r"'stiffness' = '1e-300' is outside \[1e-45, 1e\+55\] N/m\^3"),
    ("stiffness", "1e-5", "exact",
     r"'stiffness' = '1e-5' is outside \[3\d\d\d\.\d*, .*\] N/m\^3: the patch \(W / k\)\^\(1/3\) "
     r"under the weight W = 3\.08\d* N"),
    ("stiffness", "1e50", "exact", r"'stiffness' = '1e50' is outside \[3\d\d\d"),
    ("kappa", "1e300", "exact", r"'kappa' = '1e300' is outside \[0\.001, 1000\]"),
    ("kappa", "1e-300", "set-valued", r"'kappa' = '1e-300' is outside \[0\.001, 1000\]"),
    ("friction", "1e300", "fractional", r"'friction' = '1e300' is outside \[1e-06, 100\]"),
    ("friction", "1e-310", "exact", r"'friction' = '1e-310' is outside \[1e-06, 100\]"),
    ("regularization", "1e300", "fractional",
     r"'regularization' = '1e300' is outside \[1e-15, 1e\+10\] m/s"),
    ("regularization", "1e-310", "fractional",
     r"'regularization' = '1e-310' is outside \[1e-15, 1e\+10\] m/s"),
    ("radius", "1e400", "exact", r"'radius' = '1e400' is not a positive number"),
    ("friction", "0.5 ", "exact", r"'friction' = '0.5 ' is not a positive number"),
])
def test_numeric_keys_outside_their_range_are_errors_naming_key_value_and_range(key, value, law,
                                                                                 message):
    with pytest.raises(Exception, match=message):
        mujoco.MjData(mujoco.MjModel.from_xml_string(disk_with(key, value, law)))


@pytest.mark.parametrize("key,value,law", [
    ("radius", "0.100125", "exact"), ("radius", "1e-15", "exact"), ("kappa", "1e3", "set-valued"),
    ("kappa", "1e-3", "exact"), ("kappa", "1e-3", "set-valued"), ("friction", "100", "set-valued"),
    ("friction", "10", "exact"), ("friction", "1e-6", "fractional"),
    ("regularization", "1e-15", "fractional"), ("regularization", "1e10", "fractional"),
    ("stiffness", "3070.38", "exact"), ("stiffness", "3e45", "fractional"),
])
def test_values_at_the_ends_of_their_ranges_step_to_finite_states(key, value, law):
    """At the ends of each range (as the messages show them) the law builds (the exact law also
    at kappa = 1e3, test below) and a sliding, spinning disk steps 200 times to a finite state,
    without MuJoCo's reset (|qacc| below mjMAXVAL). The explicit laws (fractional, exact) are
    run at f max(1, kappa) <= 10: at dt = 1e-3 from about 50 on (f = 100, or kappa = 1e3 with
    f = 0.5) they blew this disk up, as a disk with f above R / h = 20 would tip over anyway;
    the set-valued law stayed put at f = 100 and kappa = 1e3."""
    m = mujoco.MjModel.from_xml_string(disk_with(key, value, law))
    d = mujoco.MjData(m)
    for _ in range(20):
        mujoco.mj_step(m, d)
    d.qvel[0], d.qvel[5] = 0.5, 5.0
    for _ in range(200):
        mujoco.mj_step(m, d)
    assert np.isfinite(d.qpos).all() and np.isfinite(d.qvel).all()
    assert np.isfinite(d.plugin_state).all()
    assert d.warning[int(mujoco.mjtWarning.mjWARN_BADQACC)].number == 0


def test_the_exact_law_builds_across_the_range_of_kappa_and_names_kappa_when_it_cannot():
    """kappa = 1e3 and 1e-3 reach the default tolerance 1e-8; the law's error relative to f N
    grows with kappa (1.6e-10 at 1e3), so a tolerance of 1e-11 there is an error naming kappa."""
    for kappa in ("1e3", "1e-3"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(disk_with("kappa", kappa)))
    xml = disk_with("kappa", "1e3").replace(
        "</instance>", '<config key="tolerance" value="1e-11"/></instance>')
    with pytest.raises(Exception, match=r"'tolerance' = 1e-11: the exact law reached .* grows "
                                        r"with kappa = 1000"):
        mujoco.MjData(mujoco.MjModel.from_xml_string(xml))


def test_a_patch_from_the_stiffness_stays_within_the_tire():
    """R = (N / k)^(1/3) is kept within [1e-15 m, the tire geom's bounding radius]: at a normal
    force that would make it wider (an impact) it is the bounding radius, and the wrench is the
    library's for that patch; at a tiny force it is (N / k)^(1/3) itself."""
    disk = mc.Disk(timestep=1e-3)
    m, d = settled_disk("exact", disk, stiffness=3100.0)  # k_min = W / widest^3 = 3070.38
    widest = float(m.geom_rbound[mujoco.mj_name2id(m, mujoco.mjtObj.mjOBJ_GEOM, "disk")])
    d.qvel[:] = [0.3, 0.0, 0.0, 0.0, 0.0, 2.0]
    for N, R in ((1e4, widest), (1e-6, (1e-6 / 3100.0) ** (1 / 3))):
        d.plugin_state[0] = N
        mujoco.mj_forward(m, d)
        s = d.plugin_state
        assert s[2] == pytest.approx(R, rel=1e-12)
        patch = contensou.ContactPatch(radius_m=R, normal_load=N, friction=disk.friction)
        want = contensou.exact_resultants(patch, *s[3:6], tolerance=1e-12).resultants
        assert s[6:9] == pytest.approx(want, rel=1e-6, abs=1e-7 * disk.friction * N)


def test_an_empty_value_is_refused_before_compiling():
    """MuJoCo compiles value="" as a key left out (the plugin sees the default); the package's
    model_from_xml (check_config) refuses it naming the instance and the key, and gives the same
    model as MuJoCo's compiler otherwise."""
    import contensou.mujoco as cm

    for key in ("law", "profile", "surface", "kappa"):
        xml = disk_with(key, "") if key != "surface" else disk_with("surface", "", "set-valued")
        with pytest.raises(ValueError, match=f"instance 'patch': config '{key}' is empty: an "
                                             "empty value is not a choice"):
            cm.model_from_xml(xml)
        mujoco.MjModel.from_xml_string(xml)  # MuJoCo's own compiler cannot tell: the default
    good = mc.disk_mjcf(mc.Disk(timestep=1e-3), "exact")
    a, b = cm.model_from_xml(good), mujoco.MjModel.from_xml_string(good)
    assert bytes(a.plugin_attr) == bytes(b.plugin_attr) and a.nplugin == b.nplugin == 1
    assert np.array_equal(a.geom_rbound, b.geom_rbound)


@pytest.mark.parametrize("variant", ["fractional", "exact", "set-valued", "set-valued-ellipsoid"])
def test_kappa_scales_the_lateral_friction_along_the_tire_axes(variant):
    """kappa = 0.6 and the disk turned by 30 degrees about z: fast pure sliding along the disk's
    x axis gives f N against the slip, along its y axis kappa f N (theory.md section 2: the limit
    of pure sliding is F = -f N (cos phi, kappa sin phi) in the tire's axes), for every law."""
    disk = mc.Disk(timestep=1e-3)
    m, d = settled_disk(variant, disk, kappa=0.6)
    yaw = math.radians(30)
    d.qpos[3:7] = [math.cos(yaw / 2), 0, 0, math.sin(yaw / 2)]
    N = 3.0
    ex = np.array([math.cos(yaw), math.sin(yaw), 0.0])
    ey = np.array([-math.sin(yaw), math.cos(yaw), 0.0])
    for axis, limit in ((ex, 1.0), (ey, 0.6)):
        d.qvel[:] = 0.0
        d.qvel[:3] = 5.0 * axis  # 5 m/s: far outside any stick, and eps << |v|
        d.plugin_state[0] = N
        if variant.startswith("set-valued"):
            d.plugin_state[HISTORY] = 0.0  # no history: s_free = s
        mujoco.mj_forward(m, d)
        mujoco.mj_forward(m, d)  # the patch frame follows the turned geom
        s = d.plugin_state
        fx, fy = s[6], s[7]  # in the patch frame (the disk's axes)
        world = fx * ex + fy * ey
        assert world @ axis == pytest.approx(-limit * disk.friction * N, rel=1e-6)
        assert abs(np.cross(world, axis)[2]) < 1e-6 * N
        assert abs(s[8]) < 1e-6 * N * disk.radius



@pytest.mark.parametrize("variant", ["set-valued", "set-valued-ellipsoid"])
def test_set_valued_wrench_at_a_frozen_state_is_the_projection_with_mujocos_delassus(variant):
    """One mj_forward without history (s_free = s). Inside: w = -A^-1 s with A = h J M^-1 J^T
    built here from MuJoCo's dense M (mj_fullM) and mj_jac at the patch centre. Outside (fast
    pure sliding): the support point in the sliding direction, f N against the slip, Mz = 0."""
    disk = mc.Disk(timestep=1e-3)
    m, d = settled_disk(variant, disk)
    N = 3.0
    con = d.contact[0]
    n, t1 = con.frame[:3], patch_x_axis(m, d, con.frame[:3])
    ey = np.cross(n, t1)
    for qvel, inside in (([2e-6, -1e-6, 0, 0, 0, 1e-4], True), ([3.0, 0, 0, 0, 0, 0], False)):
        d.qvel[:] = qvel
        d.plugin_state[0], d.plugin_state[HISTORY] = N, 0.0
        mujoco.mj_forward(m, d)
        s = d.plugin_state
        plane_z = np.mean([c.pos[2] for c in d.contact[: d.ncon]])
        centre = np.array([d.xpos[1][0], d.xpos[1][1], plane_z])
        jp, jr = np.zeros((3, m.nv)), np.zeros((3, m.nv))
        mujoco.mj_jac(m, d, jp, jr, centre, 1)
        J = np.vstack([t1 @ jp, ey @ jp, n @ jr])
        M = np.zeros((m.nv, m.nv))
        mujoco.mj_fullM(m, d, M)
        A = disk.timestep * J @ np.linalg.solve(M, J.T)
        twist = J @ d.qvel
        assert s[3:6] == pytest.approx(twist, rel=1e-12, abs=1e-15)
        assert s[STICK] == (1.0 if inside else 0.0) and s[ITERATIONS] >= 1
        if inside:
            assert s[6:9] == pytest.approx(-np.linalg.solve(A, twist), rel=1e-9)
        else:
            slide = -disk.friction * N * twist[:2] / np.hypot(*twist[:2])  # in (t1, n x t1)
            assert s[6:9] == pytest.approx([*slide, 0.0], abs=1e-7 * N)


def loaded_disk(variant: str, force: float, torque: float, angle: float, seconds: float,
                dt: float = 1e-3):
    """The disk of bench/mujoco_creep.py (R = 0.1 m, f = 0.5) settled for 0.2 s, then loaded at
    its centre of mass by a horizontal force `force` f N at `angle` from x and a torque `torque`
    M0 about z (M0 = (2/3) f N R), for `seconds`. Returns (m, d, x0, qpos at 0.5 s of load,
    stick flags)."""
    disk = mc.Disk(timestep=dt)
    m, d = settled_disk(variant, disk)
    for _ in range(int(round(0.2 / dt)) - 200):
        mujoco.mj_step(m, d)
    N = float(m.body_mass[1]) * mc.GRAVITY
    f0, m0 = disk.friction * N, 2 / 3 * disk.friction * N * disk.radius
    d.xfrc_applied[1, :2] = force * f0 * np.array([math.cos(angle), math.sin(angle)])
    d.xfrc_applied[1, 5] = torque * m0
    x0, half, stick = d.qpos.copy(), None, []
    for i in range(int(round(seconds / dt))):
        mujoco.mj_step(m, d)
        stick.append(d.plugin_state[STICK])
        if i + 1 == int(round(0.5 / dt)):
            half = d.qpos.copy()
    return m, d, x0, half, np.array(stick)


@pytest.mark.parametrize("variant", ["set-valued", "set-valued-ellipsoid"])
def test_set_valued_law_keeps_a_disk_loaded_inside_the_limit_at_rest(variant):
    """0.3 f N and 0.3 M0 (inside the limit) for 1.5 s at dt = 1e-3: the trial is inside at every
    step and the disk does not move from 0.5 s on, once its elastic tilt on MuJoCo's soft normal
    contact has settled (the first 0.5 s move the centre of mass by 1.1e-7 m, mostly that tilt).
    Measured from 0.5 s to 1.5 s: 1.5e-14 m and 2e-15 rad at dt = 1e-3 (6.5e-13 m at dt = 1e-4),
    so the bound 1e-9 m (1e-9 rad) is round-off with a margin of 1000; the fractional law
    (eps = 1e-4 m/s) creeps 0.74 mm in the same second."""
    m, d, x0, half, stick = loaded_disk(variant, 0.3, 0.3, 0.0, 1.5)
    assert stick.min() == 1.0
    drift = np.hypot(*(d.qpos[:2] - half[:2]))
    assert drift < 1e-9
    assert np.hypot(*(half[:2] - x0[:2])) < 1e-6
    yaw = lambda q: 2 * math.atan2(q[6], q[3])  # the disk stays flat: rotation about z
    assert abs(yaw(d.qpos) - yaw(half)) < 1e-9
    m, d, x0, half, _ = loaded_disk("fractional", 0.3, 0.3, 0.0, 1.5)
    assert np.hypot(*(d.qpos[:2] - half[:2])) > 1e-4


def box_on_incline(angle_deg: float, law: str, seconds: float, dt: float = 1e-3):
    """A 0.1 m cube (f = 0.5) on a plane tilted by angle_deg (gravity tilted instead), settled
    for 0.5 s; returns the displacement over `seconds` after that and the final velocity along
    the slope. The load is gravity, not an applied force: the set-valued law's free twist gets
    it from the previous step's accelerations alone."""
    a = math.radians(angle_deg)
    surface = '<config key="surface" value="exact"/>' if law == "set-valued" else ""
    xml = f"""<mujoco><option timestep="{dt}" gravity="{-mc.GRAVITY * math.sin(a)} 0
      {-mc.GRAVITY * math.cos(a)}"/>
      <extension><plugin plugin="contensou.friction"><instance name="p">
        <config key="pairs" value="box floor"/><config key="friction" value="0.5"/>
        <config key="radius" value="0.05"/><config key="law" value="{law}"/>{surface}
      </instance></plugin></extension>
      <worldbody><geom name="floor" type="plane" size="5 5 .1" condim="1"/>
        <body pos="0 0 0.05"><freejoint/>
          <geom name="box" type="box" size=".05 .05 .05" condim="1" density="500"/></body>
      </worldbody></mujoco>"""
    m = mujoco.MjModel.from_xml_string(xml)
    d = mujoco.MjData(m)
    for _ in range(int(round(0.5 / dt))):
        mujoco.mj_step(m, d)
    x0 = d.qpos[:2].copy()
    for _ in range(int(round(seconds / dt))):
        mujoco.mj_step(m, d)
    return float(np.hypot(*(d.qpos[:2] - x0))), float(-d.qvel[0])


def test_set_valued_law_holds_a_box_on_an_incline_below_the_friction_angle():
    """Friction angle atan(0.5) = 26.57 degrees. At 20 and 25 degrees the box stays (measured
    1e-12 m over 2 s, the bound 1e-9 m is round-off with a margin), where the fractional law
    creeps (6-10 mm); at 30 degrees it slides with g (sin a - f cos a) = 0.657 m/s^2 (the speed
    2 s after release: 0.5 s of settling plus 1.5 s)."""
    for angle in (20.0, 25.0):
        drift, _ = box_on_incline(angle, "set-valued", 2.0)
        assert drift < 1e-9, angle
        creep, _ = box_on_incline(angle, "fractional", 2.0)
        assert creep > 1e-3, angle
    _, v = box_on_incline(30.0, "set-valued", 1.5)
    a = mc.GRAVITY * (math.sin(math.radians(30)) - 0.5 * math.cos(math.radians(30)))
    assert v / 2.0 == pytest.approx(a, rel=0.01)


@pytest.mark.parametrize("variant", ["set-valued", "set-valued-ellipsoid"])
def test_set_valued_law_slides_along_a_force_outside_the_limit(variant):
    """1.2 f N at 30 degrees from x, no torque: the trial is outside at every step and the disk
    slides along the force without spin; the friction is f N against the slip (pure sliding),
    so the acceleration is (1.2 - 1) f g = 0.981 m/s^2 (measured 0.983: N lags one step)."""
    angle = math.radians(30)
    m, d, x0, _, stick = loaded_disk(variant, 1.2, 0.0, angle, 0.5)
    assert stick.max() == 0.0
    dx = d.qpos[:2] - x0[:2]
    assert math.atan2(dx[1], dx[0]) == pytest.approx(angle, abs=1e-9)
    assert math.atan2(d.qvel[1], d.qvel[0]) == pytest.approx(angle, abs=1e-9)
    assert math.hypot(*d.qvel[:2]) / 0.5 == pytest.approx(0.2 * 0.5 * mc.GRAVITY, rel=0.01)
    assert abs(d.qvel[5]) < 1e-9


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
