"""The installed package as pip builds it: the parts in it (contensou/_build.py), the ImportError
that names what a part left out needs, and the MuJoCo plugin it carries (contensou.mujoco):
built against the MuJoCo version python/requirements.txt pins, loaded once, with the libmujoco of
the installed `mujoco` package, and clear errors for a wrong or missing MuJoCo or a second copy.
A friction-only build and the self-contained wheel are checked by scripts/wheel-check.sh (CI).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import contensou
import contensou.mujoco
from contensou import _build, _parts

from conftest import ROOT

PACKAGE = Path(contensou.__file__).resolve().parent


def test_this_build_has_every_part():
    """scripts/setup.sh builds on a machine with Ceres and SUNDIALS: nothing is left out."""
    assert _build.PARTS == ("friction", "identification", "gear")
    assert _build.MISSING == {}
    assert callable(contensou.identify) and callable(contensou.stability_map)


def test_names_of_the_optional_parts_are_exported():
    optional = [n for names in contensou._OPTIONAL.values() for n in names]
    assert set(optional) <= set(contensou.__all__)
    assert all(hasattr(contensou, n) for n in contensou.__all__)
    assert len(set(contensou.__all__)) == len(contensou.__all__)


@pytest.mark.parametrize("part,package", [("identification", "libceres-dev"),
                                          ("gear", "libsundials-dev")])
def test_a_part_left_out_raises_import_error_naming_the_package(monkeypatch, part, package):
    monkeypatch.setattr(_build, "PARTS", ("friction",))
    monkeypatch.setitem(_build.MISSING, part, f"X (Debian: {package})")
    with pytest.raises(ImportError, match=rf"contensou\.{part} is not in this installation.*"
                                          rf"did not find X \(Debian: {package}\)"):
        _parts.require(part)
    _parts.require("friction")


def pinned_mujoco() -> str:
    text = (ROOT / "python" / "requirements.txt").read_text()
    return re.search(r"^mujoco==(\S+)$", text, flags=re.M).group(1)


@pytest.fixture
def mujoco():
    """The `mujoco` module; the plugin's tests skip, with the reason shown, only without it."""
    return pytest.importorskip("mujoco", reason="MuJoCo is not installed in this Python "
                                                "(pip install mujoco): plugin tests skipped")


def test_plugin_is_in_the_package_built_against_the_pinned_mujoco(mujoco):
    path = contensou.mujoco.plugin_path()
    assert path.parent == PACKAGE and path.name == "libcontensou_mujoco.so" and path.is_file()
    assert contensou.mujoco.built_against() == pinned_mujoco()


def test_load_plugin_loads_once_and_returns_the_path(mujoco):
    assert mujoco.mj_versionString() == pinned_mujoco()
    path = contensou.mujoco.load_plugin()
    assert path == contensou.mujoco.plugin_path()
    assert contensou.mujoco.load_plugin() == path  # a second call does nothing
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><extension><plugin plugin="contensou.friction"/></extension></mujoco>')
    assert model is not None


def test_another_mujoco_version_is_refused_with_a_clear_error(mujoco, monkeypatch):
    monkeypatch.setattr(_build, "MUJOCO_VERSION", "3.9.9")
    have = mujoco.mj_versionString()
    with pytest.raises(ImportError, match=rf"built against MuJoCo 3\.9\.9, but the installed mujoco "
                                          rf"is {re.escape(have)}: .*pip install \"mujoco==3\.9\.9\""):
        contensou.mujoco.load_plugin()


def test_missing_mujoco_is_an_import_error_naming_the_version(monkeypatch):
    monkeypatch.setitem(sys.modules, "mujoco", None)  # import mujoco raises ImportError
    with pytest.raises(ImportError, match=r"needs the Python package mujoco \d+\.\d+\.\d+ "
                                          r"\(pip install \"mujoco==\d+\.\d+\.\d+\"\)"):
        contensou.mujoco.load_plugin()


def test_a_build_without_mujoco_says_so(monkeypatch):
    monkeypatch.setattr(_build, "MUJOCO_PLUGIN", None)
    monkeypatch.setattr(_build, "MUJOCO_VERSION", None)
    for call in (contensou.mujoco.plugin_path, contensou.mujoco.load_plugin,
                 contensou.mujoco.built_against):
        with pytest.raises(ImportError, match="has no MuJoCo plugin: its build found no MuJoCo"):
            call()


def run_fresh(code: str) -> subprocess.CompletedProcess:
    """`code` in a new interpreter (MuJoCo's plugin table is per process)."""
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=ROOT, timeout=120)


def test_plugin_uses_the_libmujoco_of_the_installed_mujoco(mujoco):
    """In a fresh process: the quick start's one call, then the plugin steps a model; the only
    libmujoco mapped is the `mujoco` package's (the plugin has no copy of its own)."""
    code = """
import mujoco, contensou.mujoco
contensou.mujoco.load_plugin()
m = mujoco.MjModel.from_xml_string('''<mujoco><extension><plugin plugin="contensou.friction">
  <instance name="p"><config key="pairs" value="disk floor"/><config key="friction" value="0.5"/>
  <config key="radius" value="0.1"/></instance></plugin></extension><worldbody>
  <geom name="floor" type="plane" size="1 1 .1" condim="1"/><body pos="0 0 0.005"><freejoint/>
  <geom name="disk" type="cylinder" size="0.1 0.005" condim="1"/></body></worldbody></mujoco>''')
d = mujoco.MjData(m)
mujoco.mj_step(m, d, nstep=100)
d.qvel[0] = 1.0
mujoco.mj_step(m, d, nstep=10)
assert d.plugin_state[1] > 0 and d.plugin_state[6] < 0, d.plugin_state[:9]
print(sorted({l.split()[-1] for l in open('/proc/self/maps') if 'libmujoco' in l}))
print(mujoco.__file__)
"""
    run = run_fresh(code)
    assert run.returncode == 0, run.stderr
    libraries, module = run.stdout.splitlines()
    expected = Path(module).resolve().parent / f"libmujoco.so.{pinned_mujoco()}"
    assert eval(libraries) == [str(expected)]


def test_a_second_copy_of_the_plugin_is_a_clear_error(mujoco, tmp_path):
    """MuJoCo keeps one plugin per name: another library registering "contensou.friction" first
    (here a copy of the package's) makes load_plugin() raise, naming the conflict."""
    copy = tmp_path / "libcontensou_mujoco.so"
    shutil.copy(contensou.mujoco.plugin_path(), copy)
    run = run_fresh(f"""
import mujoco, contensou.mujoco
mujoco.mj_loadPluginLibrary({str(copy)!r})
try:
    contensou.mujoco.load_plugin()
except RuntimeError as e:
    print(e)
""")
    assert run.returncode == 0, run.stderr
    assert "already has a plugin named 'contensou.friction' from another library" in run.stdout
