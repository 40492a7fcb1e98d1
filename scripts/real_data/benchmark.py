#!/usr/bin/env python3
"""Benchmark of the planar-pushing reference models (limit_surfaces.py) on measured diagrams.

Usage (from the repository's root):
  .venv/bin/python scripts/real_data/benchmark.py [DATA_DIR] [--splits 35] [--jobs 2]
      [--json PATH] [--external NAME[@DATA]=CSV ...]

DATA_DIR (default ../shared/real/pushing-disk, next to the repository) holds diagram_<set>.csv:
'#' comment lines, then vx_mps,vy_mps,omega_radps,Fx_N,Fy_N,Mz_Nm (Fx, Fy, Mz the friction on
the body). With R = 0.0525 m (--radius) the twist is t = (vx, vy, omega R) [m/s] and the friction
wrench w = (Fx, Fy, Mz / R) [N]; the models fit their surfaces to the applied W = -w.

Metrics (`score`), on each test row:
  motion from force   angle [deg] between the predicted and the measured twist
  force from motion   |w_pred - w| / |w| and the angle [deg] between w_pred and w
each summarised by its median and mean over the rows.
Protocols:
  random   80/20 splits of each file (seeds 0..splits-1: numpy default_rng(seed).permutation,
           the first 20 % test); the table gives the mean over the splits of each split's median
           and mean, and "mean of files" the mean of that over the files.
  speed    fit on all of abs_v10, predict all of abs_v50, and the reverse.
  external another model's predictions, read from a CSV aligned row by row with a data file
           (`--external NAME@abs_v50=pred.csv`, or `NAME=pred.csv` with a '# data: <file>' comment
           line in it), scored on all its rows: columns pred_Fx_N, pred_Fy_N, pred_Mz_Nm (friction
           on the body, as the data) and/or pred_twist_vx, pred_twist_vy, pred_twist_omegaR
           (m/s; any scale). A NaN row counts as a failed prediction (reported, not scored).
           Other scripts may call `load_diagram` and `score` directly.
Prints a Markdown table (and the seeds, the commit, the machine) and writes --json atomically.
"""

from __future__ import annotations

import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    # One BLAS thread: the fits do many tiny solves, which threads only slow down.
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import csv  # noqa: E402
import json  # noqa: E402
import platform  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from concurrent.futures import ProcessPoolExecutor  # noqa: E402
from dataclasses import dataclass  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import limit_surfaces as ls  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DEFAULT_DATA = ROOT.parent / "shared" / "real" / "pushing-disk"
RADIUS_M = 0.0525
SETS = ("abs_v10", "abs_v50", "plywood_v10")
SPEED_PAIRS = (("abs_v10", "abs_v50"), ("abs_v50", "abs_v10"))
TEST_FRACTION = 0.2
DATA_COLUMNS = ("vx_mps", "vy_mps", "omega_radps", "Fx_N", "Fy_N", "Mz_Nm")
WRENCH_COLUMNS = ("pred_Fx_N", "pred_Fy_N", "pred_Mz_Nm")
TWIST_COLUMNS = ("pred_twist_vx", "pred_twist_vy", "pred_twist_omegaR")
METRICS = ("motion_angle_deg_median", "motion_angle_deg_mean", "force_rel_err_median",
           "force_rel_err_mean", "force_angle_deg_median", "force_angle_deg_mean")


def make_model(name: str):
    """A fresh, unfitted model of the benchmark by name."""
    if name == "ellipsoid":
        return ls.EllipsoidLimitSurface()
    if name == "quartic":
        return ls.QuarticLimitSurface()
    if name == "nearest":
        return ls.NearestNeighbour()
    if name == "nearest-uniform":
        return ls.NearestNeighbour(weights="uniform")
    raise ValueError(f"unknown model {name}")


MODELS = ("ellipsoid", "quartic", "nearest", "nearest-uniform")
MODEL_NOTES = {
    "ellipsoid": "H = W^T A W, A = L L^T SPD (Howe & Cutkosky)",
    "quartic": "H = sum_{k=1..3} (W^T B_k W)^2, B_k = L_k L_k^T PSD, B_1 + 1e-6 I SPD "
               "(convex homogeneous quartic, Zhou et al. ICRA 2016)",
    "nearest": f"k = {ls.NN_K} nearest in unit-direction space, inverse-distance weights",
    "nearest-uniform": f"k = {ls.NN_K} nearest in unit-direction space, plain mean",
}


@dataclass
class Diagram:
    """One measured file: twists t = (vx, vy, omega R) [m/s] and friction wrenches
    w = (Fx, Fy, Mz / R) [N], N x 3 each."""

    name: str
    path: Path
    twists: np.ndarray
    wrenches: np.ndarray


def _read_table(path: Path) -> tuple[list[str], list[str], list[list[str]]]:
    """Comment lines (without '#'), the header and the rows of a CSV with '#' comments."""
    with open(path, newline="") as f:
        lines = f.read().splitlines()
    comments = [ln.lstrip("#").strip() for ln in lines if ln.startswith("#")]
    body = [ln for ln in lines if ln.strip() and not ln.startswith("#")]
    if not body:
        raise ValueError(f"{path}: no header line")
    rows = list(csv.reader(body))
    return comments, [c.strip() for c in rows[0]], rows[1:]


def _columns(path: Path, header: list[str], rows: list[list[str]], names) -> np.ndarray:
    """The named columns as floats (N x len(names)); a missing column is a ValueError."""
    missing = [n for n in names if n not in header]
    if missing:
        raise ValueError(f"{path}: no column {', '.join(missing)} (header: {','.join(header)})")
    idx = [header.index(n) for n in names]
    try:
        return np.array([[float(r[i]) for i in idx] for r in rows], dtype=float).reshape(-1, len(idx))
    except (ValueError, IndexError) as e:
        raise ValueError(f"{path}: unreadable row ({e})") from e


def load_diagram(path, radius: float = RADIUS_M, name: str | None = None) -> Diagram:
    """Reads a measured diagram (DATA_COLUMNS) into SI twists and friction wrenches."""
    path = Path(path)
    _, header, rows = _read_table(path)
    a = _columns(path, header, rows, DATA_COLUMNS)
    twists = np.column_stack([a[:, 0], a[:, 1], a[:, 2] * radius])
    wrenches = np.column_stack([a[:, 3], a[:, 4], a[:, 5] / radius])
    ls.as_rows(twists, f"{path.name} twists")
    ls.as_rows(wrenches, f"{path.name} wrenches")
    stem = name or path.stem.removeprefix("diagram_")
    return Diagram(stem, path, twists, wrenches)


def angles_deg(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Row-wise angle between a and b [deg], atan2(|a x b|, a . b): accurate near 0 and 180."""
    return np.degrees(np.arctan2(np.linalg.norm(np.cross(a, b), axis=1), np.sum(a * b, axis=1)))


def _valid(pred: np.ndarray) -> np.ndarray:
    """Rows of a prediction that can be scored: finite and nonzero."""
    return np.all(np.isfinite(pred), axis=1) & (np.linalg.norm(np.nan_to_num(pred), axis=1) > 0)


def _summary(prefix: str, values: np.ndarray) -> dict:
    if values.size == 0:
        return {f"{prefix}_median": None, f"{prefix}_mean": None}
    return {f"{prefix}_median": float(np.median(values)), f"{prefix}_mean": float(np.mean(values))}


def score(pred_twist, pred_wrench, data: Diagram, rows=None) -> dict:
    """Scores predictions against `data` (rows: the indices they are for; default all rows).

    pred_twist (N x 3, any scale, (vx, vy, omega R)) is scored by its angle to the measured twist;
    pred_wrench (N x 3, friction (Fx, Fy, Mz / R) [N], the data's convention) by
    |w_pred - w| / |w| and its angle to w. Either may be None (not predicted). Rows with a NaN or
    zero prediction are failures: counted in invalid_twist / invalid_wrench, not scored."""
    rows = np.arange(len(data.twists)) if rows is None else np.asarray(rows)
    t, w = data.twists[rows], data.wrenches[rows]
    out: dict = {"n": int(len(rows))}
    for key, pred, shape_of in (("twist", pred_twist, t), ("wrench", pred_wrench, w)):
        if pred is not None and np.shape(pred) != shape_of.shape:
            raise ValueError(f"pred_{key}: shape {np.shape(pred)}, expected {shape_of.shape}")
    if pred_twist is not None:
        ok = _valid(np.asarray(pred_twist, dtype=float))
        out["invalid_twist"] = int((~ok).sum())
        out.update(_summary("motion_angle_deg", angles_deg(np.asarray(pred_twist)[ok], t[ok])))
    if pred_wrench is not None:
        pw = np.asarray(pred_wrench, dtype=float)
        ok = _valid(pw)
        out["invalid_wrench"] = int((~ok).sum())
        rel = np.linalg.norm(pw[ok] - w[ok], axis=1) / np.linalg.norm(w[ok], axis=1)
        out.update(_summary("force_rel_err", rel))
        out.update(_summary("force_angle_deg", angles_deg(pw[ok], w[ok])))
    return out


def fit_and_score(model_name: str, train: Diagram, train_rows, test: Diagram, test_rows) -> dict:
    """Fits a model on train's rows and scores both predictions on test's rows."""
    model = make_model(model_name).fit(train.twists[train_rows], train.wrenches[train_rows])
    s = score(model.motion_from_force(test.wrenches[test_rows]),
              model.force_from_motion(test.twists[test_rows]), test, test_rows)
    res = getattr(model, "fit_result", None)
    if res is not None:
        s["fit_nfev"], s["fit_status"] = int(res.nfev), int(res.status)
    return s


def split(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """Train and test rows of one random 80/20 split: default_rng(seed).permutation(n), the
    first round(0.2 n) test."""
    perm = np.random.default_rng(seed).permutation(n)
    n_test = int(round(TEST_FRACTION * n))
    return np.sort(perm[n_test:]), np.sort(perm[:n_test])


def _split_task(args) -> dict:
    """One (file, seed) of the random protocol, every model (a worker process's job)."""
    data, seed, models = args
    train, test = split(len(data.twists), seed)
    return {m: fit_and_score(m, data, train, data, test) for m in models}


def _aggregate(per_split: list[dict]) -> dict:
    """Mean over splits of each metric (each split's median or mean), the spread of the
    medians, and the fits' worst evaluation count and budget hits."""
    out: dict = {"splits": len(per_split), "n_test": per_split[0]["n"]}
    for key in METRICS:
        vals = [s[key] for s in per_split if s.get(key) is not None]
        out[key] = float(np.mean(vals)) if vals else None
        if key.endswith("median") and vals:
            out[key + "_std_over_splits"] = float(np.std(vals))
    for key in ("invalid_twist", "invalid_wrench"):
        out[key] = int(sum(s.get(key, 0) for s in per_split))
    if "fit_nfev" in per_split[0]:
        out["fit_nfev_max"] = max(s["fit_nfev"] for s in per_split)
        out["fits_out_of_budget"] = sum(s["fit_status"] == 0 for s in per_split)
    out["per_split_medians"] = {k: [s.get(k) for s in per_split] for k in METRICS
                                if k.endswith("median")}
    return out


def random_protocol(diagrams: dict, seeds: list[int], models, jobs: int) -> list[dict]:
    """Protocol (a): the random splits of every file, in `jobs` worker processes."""
    tasks = [(diagrams[name], seed, tuple(models)) for name in diagrams for seed in seeds]
    if jobs > 1:
        with ProcessPoolExecutor(max_workers=jobs) as pool:
            results = list(pool.map(_split_task, tasks, chunksize=max(1, len(seeds) // 4)))
    else:
        results = [_split_task(t) for t in tasks]
    rows = []
    for i, name in enumerate(diagrams):
        chunk = results[i * len(seeds):(i + 1) * len(seeds)]
        for m in models:
            rows.append({"protocol": "random", "train": name, "test": name, "model": m,
                         **_aggregate([r[m] for r in chunk])})
    rows += _mean_of_files(rows, models)
    return rows


def _mean_of_files(rows: list[dict], models) -> list[dict]:
    """One row a model: the mean over the files of the random protocol's metrics."""
    out = []
    for m in models:
        mine = [r for r in rows if r["model"] == m]
        mean = {k: float(np.mean([r[k] for r in mine])) for k in METRICS
                if all(r.get(k) is not None for r in mine)}
        out.append({"protocol": "random", "train": "mean of files", "test": "mean of files",
                    "model": m, **mean})
    return out


def speed_protocol(diagrams: dict, models) -> list[dict]:
    """Protocol (b): fit on all of one speed's file, predict all of the other's."""
    rows = []
    for a, b in SPEED_PAIRS:
        if a not in diagrams or b not in diagrams:
            continue
        da, db = diagrams[a], diagrams[b]
        for m in models:
            s = fit_and_score(m, da, np.arange(len(da.twists)), db, np.arange(len(db.twists)))
            rows.append({"protocol": "speed", "train": a, "test": b, "model": m, **s})
    return rows


def parse_external(spec: str) -> tuple[str, str | None, Path]:
    """NAME[@DATA]=CSV -> (NAME, DATA or None, CSV path)."""
    if "=" not in spec:
        raise ValueError(f"--external {spec}: expected NAME[@DATA]=CSV")
    left, path = spec.split("=", 1)
    name, _, data = left.partition("@")
    if not name or not path:
        raise ValueError(f"--external {spec}: expected NAME[@DATA]=CSV")
    return name, (data or None), Path(path)


def read_predictions(path, n_rows: int, radius: float = RADIUS_M):
    """Predicted twists and friction wrenches (either None when its columns are absent) of an
    external CSV, and the data file named by a '# data: <file>' comment (or None)."""
    path = Path(path)
    comments, header, rows = _read_table(path)
    if len(rows) != n_rows:
        raise ValueError(f"{path}: {len(rows)} rows, the data file has {n_rows}")
    twist = wrench = None
    if any(c in header for c in TWIST_COLUMNS):
        twist = _columns(path, header, rows, TWIST_COLUMNS)
    if any(c in header for c in WRENCH_COLUMNS):
        wrench = _columns(path, header, rows, WRENCH_COLUMNS) * np.array([1.0, 1.0, 1.0 / radius])
    if twist is None and wrench is None:
        raise ValueError(f"{path}: none of the columns {TWIST_COLUMNS + WRENCH_COLUMNS}")
    named = [c.split(":", 1)[1].strip() for c in comments if c.lower().startswith("data:")]
    return twist, wrench, (named[0] if named else None)


def external_protocol(specs, diagrams: dict, radius: float) -> list[dict]:
    """Scores every --external prediction file on all rows of its data file."""
    rows = []
    for spec in specs:
        name, data, path = parse_external(spec)
        probe = data
        if probe is None:
            probe = read_predictions(path, _count_rows(path), radius)[2]
        key = Path(probe).stem.removeprefix("diagram_") if probe else None
        if key not in diagrams:
            raise ValueError(f"--external {spec}: data file {probe!r} is not among "
                             f"{sorted(diagrams)} (say NAME@DATA=CSV or add '# data: <file>')")
        d = diagrams[key]
        twist, wrench, _ = read_predictions(path, len(d.twists), radius)
        rows.append({"protocol": "external", "train": "(external)", "test": key, "model": name,
                     "file": str(path), **score(twist, wrench, d)})
    return rows


def _count_rows(path: Path) -> int:
    return len(_read_table(path)[2])


def _fmt(v, digits: int) -> str:
    return "–" if v is None else f"{v:.{digits}f}"


def markdown(rows: list[dict]) -> str:
    """The results as a Markdown table: medians / means of each metric."""
    lines = ["| protocol | train → test | model | motion angle [deg] median / mean "
             "| force rel. error median / mean | force angle [deg] median / mean |",
             "| --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        where = r["test"] if r["train"] == r["test"] else f"{r['train']} → {r['test']}"
        cells = [f"{_fmt(r.get(a), d)} / {_fmt(r.get(b), d)}" for a, b, d in (
            ("motion_angle_deg_median", "motion_angle_deg_mean", 1),
            ("force_rel_err_median", "force_rel_err_mean", 3),
            ("force_angle_deg_median", "force_angle_deg_mean", 1))]
        lines.append(f"| {r['protocol']} | {where} | {r['model']} | " + " | ".join(cells) + " |")
    return "\n".join(lines)


def provenance() -> dict:
    """The commit (git rev-parse --short HEAD; whether tracked files differ from it) and the
    machine (platform, Python, usable processors)."""
    def git(*args):
        return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True)

    head = git("rev-parse", "--short", "HEAD")
    commit = head.stdout.strip() if head.returncode == 0 else "unknown"
    modified = git("diff", "--quiet", "HEAD", "--").returncode == 1
    nproc = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    return {"commit": commit, "tracked_files_modified": modified,
            "machine": {"platform": platform.platform(), "python": platform.python_version(),
                        "processor": platform.processor() or platform.machine(),
                        "nproc": nproc}}


def write_json_atomically(path, payload: dict) -> None:
    """Writes JSON to a unique temporary file in path's folder, then os.replace()s it."""
    write_text_atomically(path, json.dumps(payload, indent=1, allow_nan=False) + "\n")


def write_text_atomically(path, text: str) -> None:
    """Writes text to a unique temporary file in path's folder, then os.replace()s it."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o644)  # mkstemp makes it 0600; an ordinary file is what a reader expects
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def data_notes(diagrams: dict) -> dict:
    """Per file: rows, and rows whose applied power W . t = -w . t is not positive (a twist
    pointing into the limit surface: measurement noise, or a sign error if many)."""
    out = {}
    for name, d in diagrams.items():
        power = -np.sum(d.wrenches * d.twists, axis=1)
        out[name] = {"rows": int(len(power)), "rows_with_applied_power_le_0":
                     int(np.sum(power <= 0.0)), "file": str(d.path)}
    return out


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("data_dir", nargs="?", default=str(DEFAULT_DATA),
                    help="folder of diagram_<set>.csv (default ../shared/real/pushing-disk)")
    ap.add_argument("--splits", type=int, default=35, help="random 80/20 splits (seeds 0..n-1)")
    ap.add_argument("--sets", default=",".join(SETS), help="comma-separated data sets")
    ap.add_argument("--models", default=",".join(MODELS), help="comma-separated models")
    ap.add_argument("--radius", type=float, default=RADIUS_M, help="R [m] (default 0.0525)")
    ap.add_argument("--jobs", type=int, default=min(2, os.cpu_count() or 1),
                    help="worker processes of the random protocol (default 2)")
    ap.add_argument("--json", help="write the results to this JSON file (atomically)")
    ap.add_argument("--external", action="append", default=[], metavar="NAME[@DATA]=CSV",
                    help="score another model's predictions (see the module docstring)")
    args = ap.parse_args(argv)
    if args.splits < 1:
        ap.error("--splits must be at least 1")
    for m in args.models.split(","):
        if m not in MODELS:
            ap.error(f"unknown model {m} (known: {', '.join(MODELS)})")
    return args


def main(argv=None) -> int:
    args = parse_args(argv)
    start = time.perf_counter()
    folder = Path(args.data_dir)
    diagrams = {s: load_diagram(folder / f"diagram_{s}.csv", args.radius)
                for s in args.sets.split(",")}
    models, seeds = args.models.split(","), list(range(args.splits))
    rows = random_protocol(diagrams, seeds, models, args.jobs)
    rows += speed_protocol(diagrams, models)
    rows += external_protocol(args.external, diagrams, args.radius)
    elapsed = time.perf_counter() - start
    prov = provenance()
    print(f"commit {prov['commit']}" + (" (tracked files modified)"
                                        if prov["tracked_files_modified"] else ""))
    m = prov["machine"]
    print(f"machine {m['platform']}, {m['processor']}, nproc {m['nproc']}, "
          f"Python {m['python']}; {args.jobs} worker process(es)")
    print(f"data {folder.resolve()}; R = {args.radius} m; seeds {seeds[0]}..{seeds[-1]} "
          f"({len(seeds)} random 80/20 splits a file)")
    for name, model in MODEL_NOTES.items():
        if name in models:
            print(f"  {name}: {model}")
    print()
    print(markdown(rows))
    print(f"\nruntime {elapsed:.1f} s")
    if args.json:
        write_json_atomically(args.json, {
            **prov, "data_dir": str(folder.resolve()), "radius_m": args.radius, "seeds": seeds,
            "test_fraction": TEST_FRACTION, "models": {k: MODEL_NOTES[k] for k in models},
            "align_weight": ls.ALIGN_WEIGHT, "data_notes": data_notes(diagrams),
            "runtime_s": elapsed, "results": rows})
    return 0


if __name__ == "__main__":
    sys.exit(main())
