#!/usr/bin/env python3
"""Runs the hostile cases of cases.txt against the apps (ctest reliability.cases).

    run_cases.py CASES IDENTIFY SHIMMY ENGINES DATA_DIR

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


def main():
    if len(sys.argv) != 6:
        sys.exit(__doc__)
    cases_path, identify, shimmy, engines, data_dir = map(os.path.abspath, sys.argv[1:])
    data = os.path.join(data_dir, "seed_tire_diagrams.csv")
    tools = {"identify": shlex.quote(identify), "shimmy": shlex.quote(shimmy),
             "engines": shlex.quote(engines), "data": shlex.quote(data),
             "fit": f"{shlex.quote(data)} --radius 0.087 --no-loop"}
    failed = 0
    for case in parse(cases_path):
        problem = run_case(case, tools)
        print(f"{'FAIL' if problem else 'ok  '} {case[1]} (line {case[0]})"
              + (f": {problem}" if problem else ""), flush=True)
        failed += problem is not None
    print(f"{failed} of {len(parse(cases_path))} cases failed" if failed else "all cases hold")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
