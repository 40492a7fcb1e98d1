"""The documentation runs as written: every ```python block of README.md and docs/*.md (from the
repository root, the blocks of one file in order in one namespace; what they print must appear
in the page), every code block is run by some test or marked as a fragment, fences are closed,
and the links between the pages resolve. Which test runs which block: tests/python/doc_blocks.py.
"""

from __future__ import annotations

import os
import re
import unicodedata
from pathlib import Path

import pytest

from conftest import BUILD, ROOT
from doc_blocks import OUTPUT, RUN, blocks, documents

DOCS = documents(ROOT)
WITH_PYTHON = [d for d in DOCS if any(b.lang == "python" and not b.fragment for b in blocks(d))]


def _source(code: str) -> str:
    """The block as a user runs it from the root; with CONTENSOU_BUILD_DIR set, its build."""
    if BUILD.resolve() != (ROOT / "build").resolve():
        code = code.replace('"build/', f'"{BUILD}/')
    return code


@pytest.mark.parametrize("doc", WITH_PYTHON, ids=[d.name for d in WITH_PYTHON])
def test_python_blocks_run(doc: Path, monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    namespace: dict = {"__name__": "__doc_block__"}
    for b in blocks(doc):
        if b.lang != "python" or b.fragment:
            continue
        if re.search(r"^import mujoco$", b.code, flags=re.M):
            pytest.importorskip("mujoco", reason="MuJoCo is not installed in this Python")
        # Line numbers in a traceback are the file's.
        exec(compile("\n" * b.line + _source(b.code), str(doc), "exec"), namespace)
    printed = [line for line in capsys.readouterr().out.splitlines() if line.strip()]
    text = doc.read_text(encoding="utf-8")
    missing = [line for line in printed if line not in text]
    assert not missing, f"{doc.name} does not show what its blocks print: {missing}"
    if doc.name == "README.md":  # the Python quick start's shapes, as its comments say
        assert namespace["r"].resultants.shape == (201, 2, 3)
        assert namespace["E"].shape == (201, 2, 3) and namespace["dE"].shape == (201, 2, 3, 3)
        assert namespace["m"].shimmy.shape == (6, 8)
        assert list(namespace["frame"].columns) == ["Fx_N", "Fy_N", "Mz_Nm"]
    assert os.getcwd() == str(ROOT)


def test_readme_has_the_quick_starts():
    langs = [b.lang for b in blocks(ROOT / "README.md") if not b.fragment]
    assert langs.count("python") >= 2, "the Python and MuJoCo quick starts"
    assert any(b.lang == "cpp" and "int main" in b.code for b in blocks(ROOT / "README.md"))
    assert langs.count("sh") >= 2, "the two apps"


def test_every_code_block_is_run_or_a_fragment():
    loose = []
    for doc in DOCS:
        for b in blocks(doc):  # raises on an unclosed fence
            if b.fragment or b.lang in OUTPUT:
                continue
            quick_start = doc.name == "README.md" and "int main" in b.code
            runs = b.lang in RUN and (b.lang != "cpp" or quick_start)
            if not runs:
                loose.append(f"{doc.relative_to(ROOT)}:{b.line}: ```{b.lang or '(no language)'}")
    assert not loose, (
        "code blocks that no test runs: mark them <!-- fragment --> on the line before, tag output "
        "as ```text, or make them runnable:\n" + "\n".join(loose)
    )


def _slug(heading: str) -> str:
    """GitHub's anchor of a heading."""
    text = re.sub(r"`|\*\*|\*|_(?=\W)|\[([^\]]*)\]\([^)]*\)", r"\1", heading.strip()).lower()
    text = "".join(ch for ch in text if ch in " -_" or unicodedata.category(ch)[0] in "LN")
    return text.replace(" ", "-")


def _anchors(path: Path) -> set[str]:
    fenced = {n for b in blocks(path) for n in range(b.line, b.line + b.code.count("\n") + 1)}
    seen: dict[str, int] = {}
    out = set()
    for n, line in enumerate(path.read_text(encoding="utf-8").split("\n"), start=1):
        m = re.match(r"^#{1,6}\s+(.*?)\s*#*\s*$", line)
        if m and n not in fenced:
            s = _slug(m.group(1))
            out.add(s if s not in seen else f"{s}-{seen[s]}")
            seen[s] = seen.get(s, 0) + 1
    return out


def test_links_between_pages_resolve():
    broken = []
    for doc in DOCS:
        text = doc.read_text(encoding="utf-8")
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):
                continue  # http(s), mailto
            file, _, anchor = target.partition("#")
            path = (doc.parent / file).resolve() if file else doc
            if not path.exists():
                broken.append(f"{doc.relative_to(ROOT)}: {target}: no such file")
            elif anchor and path.suffix == ".md" and anchor not in _anchors(path):
                broken.append(f"{doc.relative_to(ROOT)}: {target}: no heading with that anchor")
    assert not broken, "\n".join(broken)
