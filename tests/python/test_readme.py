"""The README's Python quick start runs as written (from the repository root)."""

from __future__ import annotations

import os
import re

from conftest import ROOT


def test_readme_quick_start_runs(monkeypatch):
    text = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, flags=re.S)
    assert blocks, "no Python block in the README"
    monkeypatch.chdir(ROOT)
    namespace: dict = {}
    exec(compile(blocks[0], "README.md", "exec"), namespace)
    assert namespace["r"].resultants.shape == (201, 2, 3)
    assert namespace["E"].shape == (201, 2, 3) and namespace["dE"].shape == (201, 2, 3, 3)
    assert namespace["m"].shimmy.shape == (6, 8)
    assert list(namespace["frame"].columns) == ["Fx_N", "Fy_N", "Mz_Nm"]
    assert os.getcwd() == str(ROOT)
