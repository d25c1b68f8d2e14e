#!/usr/bin/python3
"""Plots the contact pressure and the gap along the contact boundary from a run's contact.csv
(any case; scripts/plot_pressure.py needs a contact[].compare section, this does not).

usage: plot_contact.py RESULTS_DIR [RESULTS_DIR ...] [--along X|Y|s] [--out FILE.png] [--xlim A B]

One curve per folder: the pressure from the stresses (-n.sigma.n, solid) and the penalty
traction eps_N <-g_N> (thin), over the undeformed coordinate X (or Y, or s = the arc length
along the contact points in file order); below them the gap g_N. Rows of every pair are used in
file order. Writes FILE.png (default: RESULTS_DIR/contact.png of the first folder).
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_columns  # noqa: E402


def read(folder):
    cols = read_columns(os.path.join(folder, "contact.csv"))
    if not cols:
        sys.exit(f"{folder}/contact.csv: no rows")
    return cols


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folders", nargs="+")
    ap.add_argument("--along", default="X", choices=["X", "Y", "s"])
    ap.add_argument("--out")
    ap.add_argument("--xlim", type=float, nargs=2)
    args = ap.parse_args(argv)
    fig, (ax, ag) = plt.subplots(2, 1, figsize=(7, 6), sharex=True,
                                 gridspec_kw={"height_ratios": [2, 1]})
    gaps = []
    for i, folder in enumerate(args.folders):
        c = read(folder)
        if args.along == "s":
            t, s = [0.0], 0.0
            for k in range(1, len(c["X"])):
                s += math.hypot(c["X"][k] - c["X"][k - 1], c["Y"][k] - c["Y"][k - 1])
                t.append(s)
        else:
            t = c[args.along]
        name = os.path.basename(os.path.normpath(folder))
        ax.plot(t, c["pressure_from_stress"], f"C{i}", lw=1.8, label=f"{name}: from stresses")
        ax.plot(t, c["pressure"], f"C{i}", lw=0.7, alpha=0.6, label=f"{name}: penalty traction")
        ag.plot(t, c["gap"], f"C{i}", lw=1.2)
        gaps += [g for g, x in zip(c["gap"], t) if not args.xlim or args.xlim[0] <= x <= args.xlim[1]]
    ax.set_ylabel("contact pressure")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ag.axhline(0, color="k", lw=0.6)
    ag.set_ylabel("gap g_N")
    ag.set_xlabel({"X": "X (undeformed)", "Y": "Y (undeformed)", "s": "s along the contact edges"}[args.along])
    ag.grid(alpha=0.3)
    if args.xlim:
        ag.set_xlim(*args.xlim)
        lo, hi = min(gaps), max(gaps)
        ag.set_ylim(lo - 0.05 * (hi - lo), hi + 0.05 * (hi - lo))
    fig.tight_layout()
    out = args.out or os.path.join(args.folders[0], "contact.png")
    fig.savefig(out, dpi=100)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
