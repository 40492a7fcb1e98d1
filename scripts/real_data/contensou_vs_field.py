#!/usr/bin/env python3
"""contensou-identify on the measured pushing-disk sets, against the planar-pushing field's models.

Usage (from the repository's root, after scripts/setup.sh):
  .venv/bin/python scripts/real_data/contensou_vs_field.py [DATA_DIR] [--splits 5]
      [--out docs/real-data-results.md] [--images docs/images] [--work out/real-data]

For each set of DATA_DIR (default ../shared/real/pushing-disk): the closed loop on the whole file
as a user runs it (its report's first lines, accepted and unstable effects, summary); then, on
random 80/20 splits (benchmark.split, seeds 0..splits-1) and across speeds (abs_v10 -> abs_v50 and
back), the loop fitted on the training rows (`contensou-identify TRAIN.csv --json`) and its model
predicting the test rows both ways (`contensou-identify predict --model`), scored with
benchmark.score beside the ellipsoidal and convex quartic limit surfaces and the nearest-neighbour
reference (limit_surfaces.py) fitted on the same rows. Writes a Markdown page of the numbers with
the commit and the machine, its JSON beside it, and two pictures: the measured and identified
limit surface (|F| against |Mz| / R), and predicted against measured motion across speeds. Every
file is written to a temporary name and renamed.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import benchmark as bm  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
APP = ROOT / "build" / "apps" / "contensou-identify"
LOAD_N = 8.8  # the disk's weight (the data's README): f = F0 / N
FIELD = ("ellipsoid", "quartic", "nearest")
# contensou as shipped, and with its law held to what some patch produces (--admissible-law).
VARIANTS = {"contensou": [], "contensou --admissible-law": ["--admissible-law"]}


def write_rows(path: Path, data: bm.Diagram, rows) -> None:
    """Rows of a diagram as the measured-diagram CSV (SI names; Mz = (Mz / R) R)."""
    t, w = data.twists[rows], data.wrenches[rows]
    r = bm.RADIUS_M
    lines = [",".join(bm.DATA_COLUMNS)] + [
        f"{a[0]:.12g},{a[1]:.12g},{a[2] / r:.12g},{b[0]:.12g},{b[1]:.12g},{b[2] * r:.12g}"
        for a, b in zip(t, w)]
    bm.write_text_atomically(path, "\n".join(lines) + "\n")


def identify(train_csv: Path, report: Path, options=()) -> str:
    """The loop as a user runs it on a file; its text report."""
    out = subprocess.run([str(APP), str(train_csv), "--radius", str(bm.RADIUS_M), "--normal-load",
                          str(LOAD_N), "--json", str(report), *options], capture_output=True,
                         text=True)
    if out.returncode != 0:
        raise RuntimeError(f"contensou-identify {train_csv}: {out.stderr.strip()}")
    return out.stdout


def predict(report: Path, test_csv: Path, pred_csv: Path) -> tuple[np.ndarray, np.ndarray]:
    """Both predictions of a report's model at the rows of a CSV: unit twists and wrenches
    (Fx, Fy, Mz / R), N x 3 each."""
    out = subprocess.run([str(APP), "predict", "--model", str(report), str(test_csv), "--out",
                          str(pred_csv)], capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"contensou-identify predict: {out.stderr.strip()}")
    _, header, rows = bm._read_table(pred_csv)
    twist = bm._columns(pred_csv, header, rows, bm.TWIST_COLUMNS)
    wrench = bm._columns(pred_csv, header, rows, bm.WRENCH_COLUMNS)
    wrench[:, 2] /= bm.RADIUS_M
    return twist, wrench


def contensou_scores(train: bm.Diagram, train_rows, test: bm.Diagram, test_rows, work: Path,
                     options=()):
    """The loop fitted on the training rows, scored on the test rows, and its predictions."""
    work.mkdir(parents=True, exist_ok=True)
    write_rows(work / "train.csv", train, train_rows)
    write_rows(work / "test.csv", test, test_rows)
    identify(work / "train.csv", work / "report.json", options)
    twist, wrench = predict(work / "report.json", work / "test.csv", work / "pred.csv")
    return bm.score(twist, wrench, test, test_rows), twist, wrench


def one_case(train, train_rows, test, test_rows, work: Path) -> dict:
    """contensou and the field's models on one train/test case."""
    scores = {name: contensou_scores(train, train_rows, test, test_rows,
                                     work if not options else work / "admissible", options)[0]
              for name, options in VARIANTS.items()}
    for name in FIELD:
        scores[name] = bm.fit_and_score(name, train, train_rows, test, test_rows)
    return scores


def mean_of(cases: list[dict]) -> dict:
    """The mean over cases of each model's median metrics."""
    out: dict = {}
    for model in cases[0]:
        out[model] = {m: float(np.mean([c[model][m] for c in cases]))
                      for m in ("motion_angle_deg_median", "force_rel_err_median",
                                "force_angle_deg_median")}
    return out


def whole_file_runs(diagrams: dict, work: Path) -> dict:
    """The loop on each whole file: the report's text and JSON."""
    runs = {}
    work.mkdir(parents=True, exist_ok=True)
    for name, d in diagrams.items():
        report = work / f"{name}.json"
        text = identify(d.path, report)
        bm.write_text_atomically(work / f"{name}.txt", text)
        j = json.loads(report.read_text())
        runs[name] = {"text": text, "accepted": j["accepted_effects"],
                      "stability": j.get("stability", []), "summary": j.get("summary", ""),
                      "cautions": j["final"]["cautions"], "checks": j["data_checks"]}
    return runs


def table(title: str, results: dict) -> str:
    """One Markdown table: a row a case and model."""
    s = f"\n### {title}\n\n| case | model | motion angle, median [deg] | force error, median | " \
        "force angle, median [deg] |\n|---|---|---|---|---|\n"
    for case, models in results.items():
        for model, m in models.items():
            s += (f"| {case} | {model} | {m['motion_angle_deg_median']:.1f} | "
                  f"{m['force_rel_err_median']:.3f} | {m['force_angle_deg_median']:.1f} |\n")
    return s


def write_atomically(path: Path, text: str) -> None:
    bm.write_text_atomically(path, text)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("data", nargs="?", default=str(bm.DEFAULT_DATA))
    p.add_argument("--splits", type=int, default=5)
    p.add_argument("--out", default=str(ROOT / "docs" / "real-data-results.md"))
    p.add_argument("--images", default=str(ROOT / "docs" / "images"))
    p.add_argument("--work", default=str(ROOT / "out" / "real-data"))
    a = p.parse_args(argv)
    if not APP.exists():
        raise SystemExit(f"{APP}: not built (run scripts/setup.sh)")
    start = time.time()
    work = Path(a.work)
    diagrams = {s: bm.load_diagram(Path(a.data) / f"diagram_{s}.csv") for s in bm.SETS}
    runs = whole_file_runs(diagrams, work / "whole")
    random = {}
    for name, d in diagrams.items():
        cases = []
        for seed in range(a.splits):
            tr, te = bm.split(len(d.twists), seed)
            cases.append(one_case(d, tr, d, te, work / f"{name}-split{seed}"))
            print(f"{name} split {seed}: {time.time() - start:.0f} s", file=sys.stderr)
        random[name] = mean_of(cases)
    speed, shown = {}, {}
    for src, dst in bm.SPEED_PAIRS:
        s, t = diagrams[src], diagrams[dst]
        all_s, all_t = np.arange(len(s.twists)), np.arange(len(t.twists))
        case = one_case(s, all_s, t, all_t, work / f"{src}-to-{dst}")
        speed[f"{src} -> {dst}"] = {m: {k: v for k, v in x.items()} for m, x in case.items()}
        if (src, dst) == bm.SPEED_PAIRS[0]:
            shown = {"train": s, "test": t, "work": work / f"{src}-to-{dst}"}
    import plots  # noqa: PLC0415 (matplotlib only when drawing)
    images = plots.draw(shown, diagrams, runs, Path(a.images))
    prov = bm.provenance()
    m = prov["machine"]
    machine = f"{m['platform']}, {m['nproc']} processors, Python {m['python']}"
    page = (f"# Real measurements: the numbers\n\nGenerated by `scripts/real_data/contensou_vs_field.py` "
            f"(commit {prov['commit']}{' with local changes' if prov['tracked_files_modified'] else ''}"
            f", {machine}; {time.time() - start:.0f} s). "
            f"Random splits: the mean over {a.splits} splits (seeds 0..{a.splits - 1}) of each "
            f"split's median; across speeds: all rows of one file fitted, all of the other "
            f"predicted. contensou: the closed loop as `contensou-identify` runs it by default "
            f"(resamples 5), and with `--admissible-law`, its final model predicting both ways. "
            f"Explained in "
            f"[real-data.md](real-data.md).\n")
    page += table("Random 80/20 splits", random) + table("Across speeds", speed)
    page += "\n### The loop on each whole file\n"
    for name, r in runs.items():
        page += f"\n**{name}**: accepted {r['accepted'] or 'nothing'}; "
        page += "; ".join(f"{s['effect']} {s['accepted_in']}/{s['resamples']}"
                          f"{'' if s['stable'] else ' (unstable)'}" for s in r["stability"])
        page += "\n\n" + "".join(f"- {c}\n" for c in r["cautions"] + r["checks"]["findings"])
        page += f"\n> {r['summary']}\n"
    page += "\n" + "".join(f"![{k}](images/{Path(v).name})\n\n" for k, v in images.items())
    write_atomically(Path(a.out), page)
    write_atomically(Path(a.out).with_suffix(".json"), json.dumps(
        {"random": random, "speed": speed, "provenance": prov, "splits": a.splits,
         "whole": {k: {x: v[x] for x in v if x != "text"} for k, v in runs.items()}}, indent=1))
    print(page)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
