#!/usr/bin/env python3
"""Runs every ```sh and ```bash block of README.md and docs/*.md that is not marked as a fragment
(tests/python/doc_blocks.py says how), as a user would from the repository root: in a fresh
folder holding `data/` (the repository's) and `build/apps/` (the apps under test), with
`bash -eu -o pipefail`. A block that calls anything else fails here, so it must be a fragment.
A ```text block right after a run block (at most two lines between them) is the output the
docs claim: each of its lines (but "..." elisions) must be a line the run printed.
Usage: doc_shell_blocks.py SOURCE_DIR APP...  (contensou-identify, -shimmy, -engine-coefficients,
-fmu)
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

root = Path(sys.argv[1]).resolve()
apps = [Path(a).resolve() for a in sys.argv[2:]]
sys.path.insert(0, str(root / "tests" / "python"))
from doc_blocks import blocks, documents  # noqa: E402

failures, ran = [], 0
def claimed_output(found, k):
    """The ```text block right after found[k] (the printed output the docs show), or None."""
    if k + 1 >= len(found) or found[k + 1].lang != "text" or found[k + 1].fragment:
        return None
    end = found[k].line + found[k].code.count("\n") + 1  # the closing fence's line
    return found[k + 1] if found[k + 1].line - end <= 3 else None


for doc in documents(root):
    found = blocks(doc)
    for k, b in enumerate(found):
        if b.lang not in ("sh", "bash") or b.fragment:
            continue
        where = f"{doc.relative_to(root)}:{b.line}"
        with tempfile.TemporaryDirectory() as tmp:
            os.symlink(root / "data", Path(tmp) / "data")
            (Path(tmp) / "build" / "apps").mkdir(parents=True)
            for app in apps:
                os.symlink(app, Path(tmp) / "build" / "apps" / app.name)
            start = time.monotonic()
            r = subprocess.run(["bash", "-eu", "-o", "pipefail", "-c", b.code], cwd=tmp,
                               capture_output=True, text=True, timeout=300)
            ran += 1
            print(f"{where}: exit {r.returncode} in {time.monotonic() - start:.1f} s")
            if r.returncode != 0:
                tail = r.stdout[-2000:] + r.stderr[-2000:]
                failures.append(f"{where}: exit {r.returncode}\n{b.code}{tail}")
                continue
            shown = claimed_output(found, k)
            if shown is not None:
                printed = {line.rstrip() for line in (r.stdout + r.stderr).split("\n")}
                for n, line in enumerate(shown.code.split("\n")):
                    line = line.rstrip()
                    if line and line.strip() not in ("...", "…") and line not in printed:
                        failures.append(f"{doc.relative_to(root)}:{shown.line + 1 + n}: the "
                                        f"output shown is not what the run printed: {line}")
if ran == 0:
    failures.append("no shell block found: the README's app quick starts are missing")
for f in failures:
    print("FAIL", f)
sys.exit(1 if failures else 0)
