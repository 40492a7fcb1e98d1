#!/usr/bin/env python3
"""Draws docs/validation.md's pictures from the CSV files that tests/friction/test_validation
writes when CONTENSOU_VALIDATION_CSV is set: the terminal ratio against the annulus' inner
radius (Weidman & Malhotra), the free disk's ratio as it stops (Farkas et al.), and the static
force against the applied torque (Dahmen et al.). Columns are selected by name.

Usage: .venv/bin/python scripts/validation_plots.py [--build build] [--csv DIR] [--out docs/images]
(without --csv it runs BUILD/tests/friction/test_validation into a temporary folder first).
"""

from __future__ import annotations

import argparse
import csv
import os
import subprocess
import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path: Path) -> dict[str, list[float | None]]:
    """The columns of a CSV by name; an empty cell is None."""
    with path.open(newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"validation_plots: {path} has no rows")
    return {k: [float(r[k]) if r[k] != "" else None for r in rows] for k in rows[0]}


def terminal_ratio(data: dict, out: Path) -> None:
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    eta, cf, lib = data["eta"], data["ratio_closed_form"], data["ratio_library"]
    ax.plot(eta, cf, "-", color="0.3", label="closed forms, uniform disks superposed")
    pts = [(e, v) for e, v in zip(eta, lib) if v is not None]
    ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", mfc="none", color="C0",
            label="contensou exact integrals (annulus table)")
    ax.plot([0.0, 1.0], [0.653, 1.0], "s", color="C3", ms=8,
            label="published: disk 0.653, ring 1 (Weidman & Malhotra)")
    ax.set_xlabel(r"inner radius / outer radius $\eta$ [-]")
    ax.set_ylabel(r"terminal ratio $v/(\omega R)$ [-]")
    ax.set_xlim(-0.02, 1.02)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=8)
    ax.set_title("Sliding-spinning annular disk: terminal ratio", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def trajectories(data: dict, out: Path) -> None:
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    keys = sorted({(e, s) for e, s in zip(data["eta"], data["start_ratio"])})
    for i, (eta, start) in enumerate(keys):
        idx = [j for j, (e, s) in enumerate(zip(data["eta"], data["start_ratio"]))
               if (e, s) == (eta, start)]
        x = [data["remaining"][j] for j in idx]
        y = [data["v_mps"][j] / data["omegaR_mps"][j] for j in idx]
        ax.semilogx(x, y, "-" if eta == 0 else "--", color=f"C{i % 3}",
                    label=fr"$\eta$ = {eta:g}, start {start:g}")
    ax.axhline(0.653, color="C3", lw=0.8, label="published disk value 0.653")
    ax.invert_xaxis()
    ax.set_xlabel(r"remaining speed $(v+\omega R)/(v_0+\omega_0 R)$ [-]")
    ax.set_ylabel(r"$v/(\omega R)$ [-]")
    ax.set_ylim(0, 5.2)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=7, ncol=2)
    ax.set_title("Free disk, exact law: both motions stop together", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def static_force(path: Path, out: Path) -> None:
    with path.open(newline="") as f:
        rows = list(csv.DictReader(f))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    labels = {"uniform": "uniform pressure (Coulomb limit surface)", "Hertz": "Hertz pressure",
              "seed tire": "seed tire (Table 1)",
              "ellipsoid (uniform)": "engines' ellipsoid fitted to uniform"}
    for (name, label), style in zip(labels.items(), ["-", "--", "-.", ":"]):
        sel = [r for r in rows if r["patch"] == name]
        if not sel:
            raise SystemExit(f"validation_plots: no rows for {name} in {path}")
        ax.plot([float(r["torque_ratio"]) for r in sel], [float(r["force_ratio"]) for r in sel],
                style, label=label)
    ax.set_xlabel(r"applied torque $M/(f N R)$ [-]")
    ax.set_ylabel(r"static force $F_s/(f N)$ [-]")
    ax.set_xlim(0, 0.7)
    ax.set_ylim(0, 1.05)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    ax.set_title("Static force held under a torque (Dahmen et al. 2005)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", default="build")
    ap.add_argument("--csv", default=None, help="folder with the CSV files (else run the test)")
    ap.add_argument("--out", default="docs/images")
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(args.csv) if args.csv else Path(tmp)
        if not args.csv:
            exe = Path(args.build) / "tests/friction/test_validation"
            if not exe.exists():
                raise SystemExit(f"validation_plots: {exe} not built")
            env = dict(os.environ, CONTENSOU_VALIDATION_CSV=str(folder))
            subprocess.run([str(exe), "--gtest_filter=Validation.*:-*PageNumbers*"], env=env,
                           check=True, stdout=subprocess.DEVNULL)
        out = Path(args.out)
        out.mkdir(parents=True, exist_ok=True)
        terminal_ratio(read(folder / "validation_terminal_ratio.csv"),
                       out / "validation-terminal-ratio.png")
        trajectories(read(folder / "validation_trajectories.csv"),
                     out / "validation-trajectories.png")
        static_force(folder / "validation_static_force.csv",
                     out / "validation-static-force.png")
    print(f"wrote {out}/validation-*.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
