#!/usr/bin/env python3
"""Fit the bundled diagrams and draw a small stability map, from Python (issue 13).

    .venv/bin/python examples/python/fit_and_map.py [--out out/python] [--dask]

1. contensou.identify on data/seed_tire_diagrams.csv read with pandas (the closed loop with
   the seed tire's profile, as scripts/setup.sh runs contensou-identify), then measured
   against fitted with matplotlib: fit.png.
2. A 8 x 6 stability map of the coupled contact model over forward speed and torsional
   damping (one landing per cell; --dask runs the cells on a local Dask cluster of two
   workers): map.png.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

import contensou  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def plot_fit(result: contensou.IdentificationResult, path: Path) -> None:
    psi = result.psi
    order = np.argsort(psi)
    fig, axes = plt.subplots(2, 3, figsize=(13, 6.5), sharex=True,
                             gridspec_kw={"height_ratios": [3, 1]})
    labels = [("Fx", "N"), ("Fy", "N"), ("Mz", "N m")]
    for k, (name, unit) in enumerate(labels):
        top, bottom = axes[0, k], axes[1, k]
        top.plot(psi[order], result.measured[order, k], "o", ms=4, color="#1f77b4", label="measured")
        top.plot(psi[order], result.base_prediction[order, k], "-", color="#999999",
                 label="fractional law (base)")
        top.plot(psi[order], result.prediction[order, k], "-", lw=2, color="#d62728",
                 label=f"final ({result.model})")
        top.set_ylabel(f"{name} [{unit}]")
        top.grid(True, which="both", alpha=0.3)
        bottom.axhline(0.0, color="black", lw=0.8)
        bottom.plot(psi[order], result.base_residuals[order, k], "o", ms=3, color="#999999")
        bottom.plot(psi[order], result.residuals[order, k], "o", ms=3, color="#d62728")
        bottom.set_xscale("log")
        bottom.set_xlabel("psi = v / (omega R)")
        bottom.set_ylabel("residual")
        bottom.grid(True, which="both", alpha=0.3)
    axes[0, 0].legend(loc="best", fontsize=8)
    f = result.parameters["f"]
    lo, hi = f.ci95 if f.ci95 is not None else (float("nan"), float("nan"))
    fig.suptitle(f"seed tire diagrams: f = {f.value:.4f} [{lo:.4f}, {hi:.4f}], "
                 f"kx = {result.parameters['kx'].value:.4f}; accepted: "
                 f"{', '.join(result.accepted_effects) or 'none'}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_map(m: contensou.StabilityMapResult, path: Path) -> None:
    fig, ax = plt.subplots(figsize=(7, 5))
    g = np.where(m.valid, m.growth_rate_per_s, np.nan)
    lim = max(1e-3, float(np.nanmax(np.abs(g)))) if np.isfinite(g).any() else 1.0
    mesh = ax.pcolormesh(m.x_values, m.y_values, g, cmap="RdBu_r", vmin=-lim, vmax=lim,
                         shading="nearest")
    fig.colorbar(mesh, ax=ax, label="torsional growth rate [1/s]")
    ys, xs = np.nonzero(m.shimmy)
    ax.plot(m.x_values[xs], m.y_values[ys], "kx", label="shimmy")
    ax.set_xlabel(m.x.parameter)
    ax.set_ylabel(m.y.parameter)
    ax.set_title(f"{m.model} contact: stability map")
    if len(xs):
        ax.legend(loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "python")
    ap.add_argument("--dask", action="store_true", help="run the map on a local Dask cluster")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)

    data = pd.read_csv(ROOT / "data" / "seed_tire_diagrams.csv", comment="#")
    result = contensou.identify(data, radius=0.087, profile="seed-tire", pressure=2.1e5,
                                source="data/seed_tire_diagrams.csv")
    print(f"contensou {contensou.__version__}: {len(data)} points, final model {result.model}, "
          f"accepted effects: {', '.join(result.accepted_effects) or 'none'}")
    for p in result.parameters.values():
        ci = f"[{p.ci95[0]:.6g}, {p.ci95[1]:.6g}]" if p.ci95 else "(no interval)"
        print(f"  {p.name:6s} {p.value:12.6g} {ci:28s} {p.unit}")
    print(f"  error before {result.error_before:.4f}, after {result.error_after:.4f}")
    plot_fit(result, args.out / "fit.png")
    (args.out / "report.json").write_text(result.to_json())

    config = contensou.LandingConfig.default()
    axes = (("scenario.forward_speed_mps", 30.0, 90.0, 8),
            ("structure.torsional_damping_nms_per_rad", 0.0, 250.0, 6))
    progress = sys.stderr.isatty()
    if args.dask:
        from distributed import Client, LocalCluster

        with LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            m = contensou.stability_map(config, axes, client=client, progress=progress)
    else:
        m = contensou.stability_map(config, axes, progress=progress)
    failed = int((m.error != "").sum())
    print(f"stability map {m.x.points} x {m.y.points}: {int(m.shimmy.sum())} shimmy cells, "
          f"{failed} failed")
    plot_map(m, args.out / "map.png")
    print(f"wrote {args.out}/fit.png, {args.out}/map.png, {args.out}/report.json")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
