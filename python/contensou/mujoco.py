"""The MuJoCo plugin "contensou.friction", shipped in this package (docs/mujoco.md).

One call registers it with MuJoCo, before the first model that uses it::

    import mujoco
    import contensou.mujoco

    contensou.mujoco.load_plugin()
    model = mujoco.MjModel.from_xml_string(xml)   # <plugin plugin="contensou.friction">...

MuJoCo compiles a configuration key given an empty value (``value=""``) as a key left out, so
the plugin cannot see it; ``model_from_xml(xml)`` (or ``check_config(spec)`` before compiling a
``mujoco.MjSpec``) refuses it, naming the key.

The plugin links the libmujoco of the installed ``mujoco`` package (it is not copied into this
package), so that package must be the MuJoCo version the plugin was built against
(``built_against()``); ``load_plugin()`` checks it.
"""

from __future__ import annotations

import importlib
from pathlib import Path
from types import ModuleType
from typing import Any, Optional

from . import _build

PLUGIN_NAME = "contensou.friction"  # the name in MJCF: <plugin plugin="contensou.friction">

_loaded: Optional[Path] = None


def built_against() -> str:
    """The MuJoCo version whose libmujoco the plugin links (the `mujoco` package of the build)."""
    if _build.MUJOCO_VERSION is None:
        raise ImportError(_no_plugin())
    return _build.MUJOCO_VERSION


def plugin_path() -> Path:
    """The plugin library in the installed package (contensou/libcontensou_mujoco.so)."""
    if _build.MUJOCO_PLUGIN is None:
        raise ImportError(_no_plugin())
    path = Path(__file__).with_name(_build.MUJOCO_PLUGIN)
    if not path.is_file():
        raise FileNotFoundError(f"{path} is missing from the installed package: reinstall contensou")
    return path


def load_plugin() -> Path:
    """Registers the plugin with the installed MuJoCo (once; later calls do nothing) and returns
    its path. ImportError when `mujoco` is not installed or is not the version the plugin was
    built against; RuntimeError when another copy of the plugin is already registered."""
    global _loaded
    path = plugin_path()
    want = built_against()
    try:
        mujoco: ModuleType = importlib.import_module("mujoco")
    except ImportError as e:
        raise ImportError(
            f"contensou's MuJoCo plugin needs the Python package mujoco {want} "
            f'(pip install "mujoco=={want}"): {e}'
        ) from e
    have = mujoco.mj_versionString()
    if have != want:
        raise ImportError(
            f"contensou's MuJoCo plugin was built against MuJoCo {want}, but the installed "
            f'mujoco is {have}: install that version (pip install "mujoco=={want}"), or build '
            "contensou again where your MuJoCo is installed (pip install --no-build-isolation "
            "from the source, with scikit-build-core and nanobind installed)"
        )
    if _loaded is not None:
        return _loaded
    try:
        mujoco.mj_loadPluginLibrary(str(path))
    except mujoco.FatalError as e:
        if "already registered" in str(e):
            raise RuntimeError(
                f"MuJoCo already has a plugin named {PLUGIN_NAME!r} from another library (loaded "
                "with mujoco.mj_loadPluginLibrary, e.g. a C++ build's "
                "plugins/mujoco/libcontensou_mujoco.so): MuJoCo keeps one plugin per name, so "
                f"load only one of them ({path} is the package's)"
            ) from e
        raise ImportError(f"MuJoCo could not load contensou's plugin {path}: {e}") from e
    _loaded = path
    return path


def check_config(spec: Any) -> None:
    """Refuses an empty value of a ``contensou.friction`` configuration key in ``spec`` (a
    ``mujoco.MjSpec``, or MJCF text): MuJoCo compiles ``<config key="law" value=""/>`` exactly as
    a key left out, so the plugin itself would take the default. An empty value is not a
    choice: ValueError naming the instance and the key (leave the key out for its default)."""
    mujoco: Any = importlib.import_module("mujoco")
    if isinstance(spec, str):
        spec = mujoco.MjSpec.from_string(spec)
    for plugin in spec.plugins:
        if plugin.plugin_name != PLUGIN_NAME:
            continue
        for key, value in dict(plugin.config).items():
            if not str(value).strip():
                raise ValueError(
                    f"{PLUGIN_NAME}: instance '{plugin.name}': config '{key}' is empty: an empty "
                    "value is not a choice (leave the key out for its default)")


def model_from_xml(xml: str) -> Any:
    """``mujoco.MjModel`` of MJCF text, after ``check_config``: the same model as
    ``mujoco.MjModel.from_xml_string(xml)``, with empty configuration values refused."""
    mujoco: Any = importlib.import_module("mujoco")
    spec = mujoco.MjSpec.from_string(xml)
    check_config(spec)
    return spec.compile()


def _no_plugin() -> str:
    return (
        "this installation of contensou has no MuJoCo plugin: its build found no MuJoCo (the "
        "Python package mujoco, whose wheel has MuJoCo's headers and libmujoco, was not "
        "installed where it was built). Build it again with mujoco in the build's environment "
        "(pip install from the source does: mujoco-core is a build requirement on Linux with "
        "Python 3.11 and later)"
    )
