"""The fenced code blocks of README.md and docs/*.md, for the tests that run them.

A block is a fence of three or more backticks at the start of a line, with an optional language
tag. It is a *fragment* when the last non-blank line before it is an HTML comment that starts
with `<!-- fragment` (a synopsis, a part of a program, a command CI runs elsewhere): fragments
are not run. `text` blocks are program output or diagrams, not code. Indented (four-space)
blocks are formulas and are not looked at.

Who runs what:
- ```python: tests/python/test_readme.py, every block of one file in order in one namespace,
  from the repository root;
- ```cpp with `int main` in README.md: the ctest readme.cpp_quick_start (tests/CMakeLists.txt);
- ```sh and ```bash: the ctest docs.shell_blocks (tests/cli/doc_shell_blocks.py), with the
  apps in place of build/apps/.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

FENCE = re.compile(r"^(`{3,})([\w+-]*)\s*$")
RUN = {"python", "cpp", "sh", "bash"}  # languages a test runs
OUTPUT = {"text"}  # printed output and diagrams


@dataclass
class Block:
    path: Path
    line: int  # 1-based line of the opening fence
    lang: str
    code: str
    fragment: bool


def documents(root: Path) -> list[Path]:
    """README.md and the pages under docs/, in a stable order."""
    return [root / "README.md"] + sorted((root / "docs").glob("*.md"))


def blocks(path: Path) -> list[Block]:
    """The fenced blocks of one file; an unclosed fence is an error."""
    lines = path.read_text(encoding="utf-8").split("\n")
    found: list[Block] = []
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        ticks, lang = m.group(1), m.group(2)
        j = i - 1
        while j >= 0 and not lines[j].strip():
            j -= 1
        fragment = j >= 0 and lines[j].strip().startswith("<!-- fragment")
        k = i + 1
        while k < len(lines) and not re.match(r"^" + ticks + r"`*\s*$", lines[k]):
            k += 1
        if k == len(lines):
            raise ValueError(f"{path}:{i + 1}: code fence never closed")
        found.append(Block(path, i + 1, lang, "\n".join(lines[i + 1 : k]) + "\n", fragment))
        i = k + 1
    return found
