"""Models and oracles shared by the MuJoCo benchmarks (bench/mujoco_disk.py, bench/mujoco_creep.py)
and tests/python/test_mujoco.py.

The sliding-spinning disk (Farkas, Bartels, Unger & Wolf, PRL 90, 248302, 2003): a flat disk of
radius R, uniform pressure, thrown on a plane with speed v0 and spin omega0. Its oracle is the
closed form of the exact resultants for uniform pressure (theory.md section 3, complete elliptic
integrals by the arithmetic-geometric mean) integrated in time by RK4: M dv/dt = -F_par,
I domega/dt = -|Mz|, I = M R^2 / 2.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
GRAVITY = 9.81


def plugin_path() -> Path:
    """The plugin: $CONTENSOU_MUJOCO_PLUGIN (another build's libcontensou_mujoco.so, e.g.
    build/plugins/mujoco/), or the one in the installed package (contensou.mujoco)."""
    if "CONTENSOU_MUJOCO_PLUGIN" in os.environ:
        return Path(os.environ["CONTENSOU_MUJOCO_PLUGIN"])
    import contensou.mujoco

    return contensou.mujoco.plugin_path()


_loaded: set[str] = set()


def load_plugin(mujoco) -> None:
    """Loads plugin_path() once. MuJoCo keeps one plugin per name: one process loads either
    $CONTENSOU_MUJOCO_PLUGIN or the package's, not both."""
    if "CONTENSOU_MUJOCO_PLUGIN" not in os.environ:
        import contensou.mujoco

        contensou.mujoco.load_plugin()
        return
    path = plugin_path()
    if not path.exists():
        raise FileNotFoundError(f"{path} is missing: build it (scripts/setup.sh)")
    if str(path) not in _loaded:
        mujoco.mj_loadPluginLibrary(str(path))
        _loaded.add(str(path))


# --- the closed forms (theory.md section 3) ------------------------------------------------------
def ellipke(k: float) -> tuple[float, float]:
    """Complete elliptic integrals K(k), E(k) (modulus k < 1) by the AGM (Abramowitz & Stegun 17.6)."""
    a, b, c = 1.0, math.sqrt(1.0 - k * k), k
    s, p = 0.5 * c * c, 0.5
    while abs(c) > 1e-16:
        a, b, c = 0.5 * (a + b), math.sqrt(a * b), 0.5 * (a - b)
        p *= 2.0
        s += p * c * c
    K = math.pi / (2.0 * a)
    return K, K * (1.0 - s)


def uniform_closed_form(eps: float) -> tuple[float, float]:
    """F_par / (f N) and |Mz| / (f N R) at eps = v / (omega R) (theory.md section 3)."""
    if eps <= 0.0:
        return 0.0, 2.0 / 3.0
    if eps < 1.0:
        K, E = ellipke(eps)
        fp = 4 / (3 * math.pi) * ((1 + eps**2) * E - (1 - eps**2) * K) / eps
        mz = 4 / (9 * math.pi) * ((4 - 2 * eps**2) * E - (1 - eps**2) * K)
        return fp, mz
    if eps == 1.0:
        return 4 / (3 * math.pi) * 2.0, 4 / (9 * math.pi) * 2.0
    K, E = ellipke(1.0 / eps)
    fp = 4 / (3 * math.pi) * ((1 + eps**2) * E - (eps**2 - 1) * K)
    mz = 4 / (9 * math.pi) * (2 * eps * (2 - eps**2) * E + (2 * eps**2 - 3) * (eps**2 - 1) * K / eps)
    return fp, mz


def farkas_ratio() -> float:
    """The fixed point of v/(omega R): F_par = 2 eps |Mz| (equal relative decay), by bisection."""
    g = lambda e: uniform_closed_form(e)[0] - 2 * e * uniform_closed_form(e)[1]
    lo, hi = 0.3, 0.95
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if g(lo) * g(mid) <= 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


@dataclass
class Trajectory:
    name: str
    t: np.ndarray
    v: np.ndarray  # sliding speed [m/s]
    u: np.ndarray  # omega R [m/s]
    extra: dict = field(default_factory=dict)

    def crossing(self, level: float) -> int:
        """First index where v + u falls below `level` times its start, or -1."""
        s = self.v + self.u
        idx = np.nonzero(s < level * s[0])[0]
        return int(idx[0]) if idx.size else -1

    def ratio_at(self, level: float) -> float:
        i = self.crossing(level)
        return float(self.v[i] / self.u[i]) if i >= 0 and self.u[i] > 0 else math.inf

    def time_at(self, level: float) -> float:
        i = self.crossing(level)
        return float(self.t[i]) if i >= 0 else math.nan

    def time_below(self, which: str, level: float) -> float:
        x = self.v if which == "v" else self.u
        idx = np.nonzero(x < level * x[0])[0]
        return float(self.t[idx[0]]) if idx.size else math.nan


def closed_form_disk(v0: float, u0: float, friction: float, dt: float = 1e-5) -> Trajectory:
    """RK4 on the closed forms until v + u < 1e-6 (v0 + u0); per unit mass, I = R^2 / 2."""
    mg = friction * GRAVITY

    def rhs(y):
        v, u = max(y[0], 0.0), max(y[1], 0.0)
        if u <= 0.0:
            return np.array([-mg if v > 0 else 0.0, 0.0])
        fp, mz = uniform_closed_form(v / u)
        return np.array([-mg * fp, -2.0 * mg * mz])  # du/dt = R * (f N R mz) / (M R^2/2)

    y = np.array([v0, u0], float)
    t, ts, vs, us = 0.0, [0.0], [v0], [u0]
    while y.sum() > 1e-6 * (v0 + u0):
        k1 = rhs(y)
        k2 = rhs(y + 0.5 * dt * k1)
        k3 = rhs(y + 0.5 * dt * k2)
        k4 = rhs(y + dt * k3)
        y = np.maximum(y + dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4), 0.0)
        t += dt
        ts.append(t)
        vs.append(y[0])
        us.append(y[1])
    return Trajectory("closed form (RK4)", np.array(ts), np.array(vs), np.array(us))


# --- MuJoCo models ---------------------------------------------------------------------------------
PLUGIN_VARIANTS = ("exact", "fractional", "set-valued", "set-valued-ellipsoid")


@dataclass
class Disk:
    radius: float = 0.1
    half_height: float = 0.005
    density: float = 1000.0
    friction: float = 0.5
    torsion: float | None = None  # MuJoCo's torsional coefficient; default (2/3) R f
    timestep: float = 1e-4


def disk_mjcf(disk: Disk, variant: str, regularization: float = 1e-4, profile: str = "uniform",
              stiffness: float | None = None, kappa: float | None = None) -> str:
    """variant: elliptic | pyramidal (MuJoCo's own, condim 4) | exact | fractional | set-valued
    (exact limit surface) | set-valued-ellipsoid (plugin, with the patch radius R = disk.radius,
    or from the normal force if a stiffness is given; the regularization only for fractional;
    kappa, if given, is the plugin's lateral/longitudinal friction ratio along the disk's axes)."""
    if variant in PLUGIN_VARIANTS:
        size = (f'<config key="stiffness" value="{stiffness}"/>' if stiffness
                else f'<config key="radius" value="{disk.radius}"/>')
        law = ('<config key="law" value="set-valued"/><config key="surface" value="ellipsoid"/>'
               if variant == "set-valued-ellipsoid" else f'<config key="law" value="{variant}"/>')
        ext = (
            '<extension><plugin plugin="contensou.friction"><instance name="patch">'
            '<config key="pairs" value="disk floor"/>'
            f'<config key="friction" value="{disk.friction}"/>'
            f'{size}<config key="profile" value="{profile}"/>'
            f'{law}'
            + (f'<config key="regularization" value="{regularization}"/>'
               if variant == "fractional" else "")
            + (f'<config key="kappa" value="{kappa}"/>' if kappa is not None else "")
            + "</instance></plugin></extension>"
        )
        contact, cone = 'condim="1"', ""
    elif variant in ("elliptic", "pyramidal"):
        torsion = disk.torsion if disk.torsion is not None else 2 / 3 * disk.radius * disk.friction
        ext = ""
        contact = f'condim="4" friction="{disk.friction} {torsion} 0"'
        cone = f'cone="{variant}"'
    else:
        raise ValueError(f"variant '{variant}': use elliptic, pyramidal or one of {PLUGIN_VARIANTS}")
    return f"""<mujoco model="disk">
  <option timestep="{disk.timestep}" {cone}/>
  {ext}
  <worldbody>
    <geom name="floor" type="plane" size="20 20 0.1" {contact}/>
    <body name="disk" pos="0 0 {disk.half_height}">
      <freejoint/>
      <geom name="disk" type="cylinder" size="{disk.radius} {disk.half_height}"
            density="{disk.density}" {contact}/>
    </body>
  </worldbody>
</mujoco>"""


def run_disk(mujoco, disk: Disk, variant: str, v0: float, u0: float, t_end: float,
             regularization: float = 1e-4, settle: float = 0.05, drop: float = 0.0) -> Trajectory:
    """Settles the disk on the plane for `settle` s, then throws it along x with v0 and spin
    omega0 = u0 / R (from `drop` metres above the plane if drop > 0: a landing); records
    v = |horizontal velocity|, u = |omega_z| R and the normal force."""
    if variant in PLUGIN_VARIANTS:
        load_plugin(mujoco)
    m = mujoco.MjModel.from_xml_string(disk_mjcf(disk, variant, regularization))
    d = mujoco.MjData(m)
    for _ in range(int(round(settle / disk.timestep))):
        mujoco.mj_step(m, d)
    d.qvel[:] = 0.0
    if drop > 0:
        d.qpos[2] += drop
    d.qvel[0] = v0
    d.qvel[5] = u0 / disk.radius
    n = int(round(t_end / disk.timestep))
    t, v, u = np.empty(n + 1), np.empty(n + 1), np.empty(n + 1)
    n_used, n_now = [], []
    t0 = d.time
    for i in range(n + 1):
        t[i] = d.time - t0
        v[i] = math.hypot(d.qvel[0], d.qvel[1])
        u[i] = abs(d.qvel[5]) * disk.radius  # body-frame spin = world spin while the disk is flat
        mujoco.mj_step(m, d)
        if m.npluginstate:
            n_used.append(d.plugin_state[1])  # N of the previous step, used in this step
            n_now.append(d.plugin_state[0])  # N of this step's contact solution
    return Trajectory(variant, t, v, u, {"n_used": np.array(n_used), "n_now": np.array(n_now),
                                         "mass": float(m.body_mass[1])})
