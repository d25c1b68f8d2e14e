#!/usr/bin/python3
"""The load path of the ring on the rigid foundation (examples/ring-foundation): runs the example
with every load step written, and tabulates and plots, against the applied load, the strip's
top displacement, the contact reaction and the gap at the symmetry axis (lift-off > 0).

usage: ring_foundation_study.py [--hpcontact PATH] --out DIR [--set key=value ...]

Writes DIR/run/ (the run, with output.steps), DIR/path.csv (per converged arc-length step:
load [N, whole ring], top displacement [mm], reaction [N, whole ring], gap at the axis [mm],
contact zone ends [mm]) and DIR/path.png. Exit status 1 if the run fails.
"""
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from hpc_run import default_hpcontact, read_columns, read_vtu, script_parser  # noqa: E402

CASE = os.path.join(ROOT, "examples", "ring-foundation", "ring.yaml")
HALF_LOAD = 1035.0  # N on the half model (the case's traction resultant)


def zone_ends(x, gap):
    """x where the gap changes sign between neighbouring points (linear interpolation)."""
    ends = []
    for i in range(len(x) - 1):
        if (gap[i] > 0) != (gap[i + 1] > 0):
            ends.append(x[i] - gap[i] * (x[i + 1] - x[i]) / (gap[i + 1] - gap[i]))
    return ends


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("--hpcontact", default=default_hpcontact(),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--out", required=True, metavar="DIR", help="output folder")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="an input override of the run (repeatable)")
    args = ap.parse_args(argv)
    run_dir = os.path.join(args.out, "run")
    cmd = [args.hpcontact, "run", CASE, "--out", run_dir, "-q", "--set", "output.steps=true"]
    for s in args.set:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        return 1
    steps = read_columns(os.path.join(run_dir, "path.csv"))
    rows = []
    for k in range(len(steps["step"])):
        X, _, c, _ = read_vtu(os.path.join(run_dir, "steps", f"contact-{k + 1:04d}.vtu"))
        order = np.argsort(X[:, 0])
        x, gap = X[order, 0], c["gap"][order]
        ends = zone_ends(x, gap)
        rows.append({"load_N": 2 * HALF_LOAD * steps["load_factor"][k],
                     "top_displacement_mm": -steps["monitor_uy"][k],
                     "reaction_N": 2 * steps["resultant_y"][k],
                     "gap_at_axis_mm": gap[0],
                     "zone_ends_mm": " ".join(f"{e:.6g}" for e in ends)})
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "path.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    load = np.array([r["load_N"] for r in rows])
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    axes[0].plot(load, [r["top_displacement_mm"] for r in rows], "o-", ms=3)
    axes[0].set_ylabel("top displacement [mm]")
    axes[1].plot(load, [r["reaction_N"] for r in rows], "o-", ms=3, label="contact reaction")
    axes[1].plot(load, load, "k:", label="applied load")
    axes[1].set_ylabel("reaction [N]")
    axes[1].legend(fontsize=8)
    axes[2].plot(load, [1e3 * r["gap_at_axis_mm"] for r in rows], "o-", ms=3)
    axes[2].axhline(0, color="0.5", lw=0.8)
    axes[2].set_ylabel("gap at the symmetry axis [µm] (> 0: lift-off)")
    for ax in axes:
        ax.set_xlabel("applied load [N] (whole ring)")
        ax.grid(alpha=0.3)
    fig.suptitle("Composite ring on a rigid foundation, arc-length path (examples/ring-foundation)",
                 fontsize=10)
    fig.tight_layout()
    png = os.path.join(args.out, "path.png")
    fig.savefig(png, dpi=100)
    last = rows[-1]
    print(f"{len(rows)} arc-length steps to {last['load_N']:.6g} N: top displacement "
          f"{last['top_displacement_mm']:.4g} mm, reaction {last['reaction_N']:.6g} N, gap at "
          f"the axis {last['gap_at_axis_mm']:.3g} mm; wrote {args.out}/path.csv, {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
