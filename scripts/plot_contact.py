#!/usr/bin/python3
"""Plots the contact pressure and the gap along the contact boundary from a run's contact.csv
(any case; scripts/plot_pressure.py needs a contact[].compare section, this does not).

usage: plot_contact.py RESULTS_DIR [RESULTS_DIR ...] [--along X|Y|s] [--out FILE.png] [--xlim A B]

One curve per folder: the pressure from the stresses (-n.sigma.n, solid) and the column
`pressure` (thin: the multiplier at the multiplier nodes; with enforcement: penalty the penalty
traction eps_N <-g_N> at the Gauss points), over the undeformed coordinate X (or Y, or s = the arc length
along the contact points in file order); below them the gap g_N. Rows of every pair are used in
file order. --xlim limits the view along the boundary (the gap axis then fits the points inside
it); a pressure curve that leaves the pressure axis (set by --ylim) is clipped, and the legend
says so. Axis labels carry units: those summary.json names ("units"), else input units.
Writes FILE.png (default: RESULTS_DIR/contact.png of the first folder) and prints its name.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import axis_label, read_run_csv, script_parser, units_of  # noqa: E402


def pressure_name(folder):
    """What contact.csv's `pressure` is: the penalty traction if the run's effective input
    (input.yaml) enforces contact by the penalty, else the multiplier."""
    try:
        with open(os.path.join(folder, "input.yaml")) as f:
            penalty = any(line.split("#")[0].split() == ["enforcement:", "penalty"] for line in f)
    except OSError:
        return "pressure"
    return "penalty traction" if penalty else "multiplier"


def read(folder):
    """contact.csv's columns and summary.json (or {}) of a results folder; exits naming the
    file if there is no contact.csv with rows."""
    return read_run_csv(folder, "contact.csv", "plot_contact", "a run without contact pairs?")


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("folders", nargs="+", metavar="RESULTS_DIR",
                    help="--out folders of `hpcontact run` (one curve each)")
    ap.add_argument("--along", default="X", choices=["X", "Y", "s"],
                    help="abscissa: undeformed X or Y, or s, the length along the contact "
                         "points (default %(default)s)")
    ap.add_argument("--out", help="PNG to write (default RESULTS_DIR/contact.png of the first)")
    ap.add_argument("--xlim", type=float, nargs=2, metavar=("A", "B"), help="range of the abscissa")
    ap.add_argument("--ylim", type=float, nargs=2, metavar=("A", "B"),
                    help="range of the pressure axis (default: all values)")
    args = ap.parse_args(argv)
    fig, (ax, ag) = plt.subplots(2, 1, figsize=(7, 6), sharex=True,
                                 gridspec_kw={"height_ratios": [2, 1]})
    gaps, units = [], None
    for i, folder in enumerate(args.folders):
        c, summary = read(folder)
        units = units or units_of(summary)
        if args.along == "s":
            t, s = [0.0], 0.0
            for k in range(1, len(c["X"])):
                s += math.hypot(c["X"][k] - c["X"][k - 1], c["Y"][k] - c["Y"][k - 1])
                t.append(s)
        else:
            t = c[args.along]
        name = os.path.basename(os.path.normpath(folder))
        seen = [k for k, x in enumerate(t) if not args.xlim or args.xlim[0] <= x <= args.xlim[1]]
        for column, what, style in (("pressure_from_stress", "from stresses", dict(lw=1.8)),
                                    ("pressure", pressure_name(folder), dict(lw=0.7, alpha=0.6))):
            label = f"{name}: {what}"
            if args.ylim and seen:
                shown = [c[column][k] for k in seen]
                out_of = [v for v in shown if v < args.ylim[0] or v > args.ylim[1]]
                if out_of:
                    label += f" (clipped: {min(shown):.4g} to {max(shown):.4g})"
            ax.plot(t, c[column], f"C{i}", label=label, **style)
        ag.plot(t, c["gap"], f"C{i}", lw=1.2)
        gaps += [g for g, x in zip(c["gap"], t) if not args.xlim or args.xlim[0] <= x <= args.xlim[1]]
    ax.set_ylabel(axis_label("contact pressure", "pressure", units))
    if args.ylim:
        ax.set_ylim(*args.ylim)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ag.axhline(0, color="k", lw=0.6)
    ag.set_ylabel(axis_label("gap g_N", "length", units))
    ag.set_xlabel(axis_label({"X": "undeformed X", "Y": "undeformed Y",
                              "s": "s along the contact points"}[args.along], "length", units))
    ag.grid(alpha=0.3)
    if args.xlim:
        ag.set_xlim(*args.xlim)
        lo, hi = min(gaps), max(gaps)
        ag.set_ylim(lo - 0.05 * (hi - lo), hi + 0.05 * (hi - lo))
    fig.tight_layout()
    out = args.out or os.path.join(args.folders[0], "contact.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
