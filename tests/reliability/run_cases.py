#!/usr/bin/env python3
"""Runs the hostile cases of the case tables against the apps (ctest reliability.cases).

    run_cases.py DATA_DIR NAME=PATH... CASES...

NAME=PATH names a tool the commands call as {NAME} (identify, shimmy, engines, model_error, ...);
CASES are case tables or folders of them (every *.txt inside, in name order).

Each case runs in a fresh temporary folder with a 120 s limit; a case fails when its exit status
is not the expected class, its output does not match, its `then` test fails, or anything looks
like a crash (a signal, "terminate called", a sanitizer report). Prints one line a case and
exits 1 if any failed."""
import os
import re
import shlex
import subprocess
import sys
import tempfile

CRASH = re.compile(r"terminate called|Aborted|AddressSanitizer|runtime error:|Segmentation fault|"
                   r"core dumped|Check failed")


def parse(path):
    cases = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.rstrip("\n")
            if not line.strip() or line.lstrip().startswith("#"):
                continue
            fields = [x.strip() for x in line.split(" ¦ ")]
            if len(fields) not in (4, 5) or fields[1] not in ("refused", "accepted"):
                sys.exit(f"{path}:{number}: expected 'name ¦ refused|accepted ¦ pattern ¦ command"
                         f" [¦ then]', got {line!r}")
            cases.append((number, *fields, *([None] if len(fields) == 4 else [])))
    return cases


def substitute(text, tools):
    """{identify} and the like replaced; other braces (JSON) left alone."""
    for key, value in tools.items():
        text = text.replace("{" + key + "}", value)
    return text


def run_case(case, tools):
    number, name, expect, pattern, command, then = case
    command = substitute(command, tools)
    with tempfile.TemporaryDirectory(prefix="contensou-reliability-") as work:
        try:
            p = subprocess.run(["bash", "-c", command], cwd=work, capture_output=True, text=True,
                               errors="replace", timeout=120)
        except subprocess.TimeoutExpired:
            return "did not end within 120 s"
        out = p.stdout + p.stderr
        if CRASH.search(out) or p.returncode < 0 or p.returncode > 125:
            return f"crashed (status {p.returncode}): {out[-600:]}"
        if expect == "refused" and p.returncode == 0:
            return f"accepted, expected an error matching {pattern!r}: {out[-400:]}"
        if expect == "accepted" and p.returncode != 0:
            return f"refused (status {p.returncode}): {out[-400:]}"
        where = p.stderr if expect == "refused" else out
        if not re.search(pattern, where):
            return f"output does not match {pattern!r}: {where[-400:]!r}"
        if then:
            t = subprocess.run(["bash", "-c", substitute(then, tools)], cwd=work, capture_output=True,
                               text=True, timeout=60)
            if t.returncode != 0:
                return f"afterwards, `{then}` failed: {t.stdout + t.stderr}"
    return None


def case_files(paths):
    files = []
    for p in paths:
        if os.path.isdir(p):
            files += sorted(os.path.join(p, f) for f in os.listdir(p) if f.endswith(".txt"))
        else:
            files.append(p)
    return files


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    data_dir = os.path.abspath(sys.argv[1])
    tools, tables = {}, []
    for arg in sys.argv[2:]:
        name, eq, path = arg.partition("=")
        if eq and re.fullmatch(r"[a-z_]+", name):
            tools[name] = shlex.quote(os.path.abspath(path))
        else:
            tables.append(os.path.abspath(arg))
    data = os.path.join(data_dir, "seed_tire_diagrams.csv")
    tools.update({"data": shlex.quote(data), "fit": f"{shlex.quote(data)} --radius 0.087 --no-loop"})
    cases = [(f, c) for f in case_files(tables) for c in parse(f)]
    failed = 0
    for path, case in cases:
        problem = run_case(case, tools)
        print(f"{'FAIL' if problem else 'ok  '} {case[1]} ({os.path.basename(path)}:{case[0]})"
              + (f": {problem}" if problem else ""), flush=True)
        failed += problem is not None
    print(f"{failed} of {len(cases)} cases failed" if failed else f"all {len(cases)} cases hold")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
