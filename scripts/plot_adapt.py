#!/usr/bin/python3
"""Plots the contact pressure of every iteration of an rp or hp run (seed Fig. 5.15-5.18).

usage: plot_adapt.py RESULTS_DIR [OUT.png] [--column pressure_from_stress|pressure_penalty]

Reads RESULTS_DIR/summary.json (its adapt section) and RESULTS_DIR/rp/pressure-N.csv or
RESULTS_DIR/hp/pressure-N.csv (written by `hpcontact run` for a case with adapt.method rp or hp
and contact[].compare); writes RESULTS_DIR/adapt-pressure.png: p/p0 over x/b for every
iteration against Hertz and Shtayerman, the whole range and zoomed on the end of the zone
(b and p0: Hertz's half width and peak pressure, their values and units in the axis labels).
The views are p/p0 in [-0.15, 1.3] and [-0.1, 0.6]; the legend says which iterations' curves
leave them (clipped), with their extreme values. Prints the name of the PNG.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_columns, script_parser, unit_text, units_of  # noqa: E402

VIEW, ZOOM = (-0.15, 1.3), (-0.1, 0.6)


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("folder", metavar="RESULTS_DIR", help="--out folder of an rp or hp run")
    ap.add_argument("out", nargs="?", metavar="OUT.png",
                    help="PNG to write (default RESULTS_DIR/adapt-pressure.png)")
    ap.add_argument("--column", default="pressure_from_stress",
                    choices=["pressure_from_stress", "pressure_penalty"],
                    help="which pressure of pressure-N.csv (default %(default)s)")
    args = ap.parse_args(argv)
    folder = args.folder
    summary_path = os.path.join(folder, "summary.json")
    if not os.path.exists(summary_path) and os.path.exists(os.path.join(folder, "last-good")):
        print(f"{folder}: the run failed; plotting its last good result (last-good/)", file=sys.stderr)
        summary_path = os.path.join(folder, "last-good", "summary.json")
    with open(summary_path) as f:
        summary = json.load(f)
    adapt = summary.get("adapt")
    contact = summary.get("contact", {})
    if not adapt or "hertz_half_width" not in contact:
        print(f"{folder}: not an rp/hp run with a pressure comparison (adapt, contact[].compare)",
              file=sys.stderr)
        return 1
    method = adapt["method"]
    b, p0 = contact["hertz_half_width"], contact["hertz_peak_pressure"]
    fig, (ax, az) = plt.subplots(1, 2, figsize=(13, 5), gridspec_kw={"width_ratios": [1.5, 1]})
    key = "iteration" if method == "rp" else "step"
    history = adapt["history"]
    cmap = plt.get_cmap("viridis")
    closed, zoom_clipped = None, False
    for i, h in enumerate(history):
        path = os.path.join(folder, method, f"pressure-{h[key]}.csv")
        if not os.path.exists(path):
            print(f"{path}: missing", file=sys.stderr)
            return 1
        c = read_columns(path)
        closed = closed or c
        xb = [x / b for x in c["x"]]
        pb = [p / p0 for p in c[args.column]]
        colour = cmap(i / max(1, len(history) - 1))
        label = f"{key} {h[key]} ({h['dofs']} DOF)"
        seen = [p for x, p in zip(xb, pb) if 0 <= x <= 1.5]
        if seen and (max(seen) > VIEW[1] or min(seen) < VIEW[0]):
            label += f" (clipped: {min(seen):.3g} to {max(seen):.3g} p0)"
        zoomed = [p for x, p in zip(xb, pb) if 0.85 <= x <= 1.1]
        zoom_clipped = zoom_clipped or any(p < ZOOM[0] or p > ZOOM[1] for p in zoomed)
        for a in (ax, az):
            a.plot(xb, pb, color=colour, lw=1.2, label=label)
    xb = [x / b for x in closed["x"]]
    for a in (ax, az):
        a.plot(xb, [p / p0 for p in closed["hertz"]], "k--", lw=1, label="Hertz")
        a.plot(xb, [p / p0 for p in closed["shtayerman"]], "k:", lw=1.5, label="Shtayerman")
        a.grid(alpha=0.3)
        a.set_xlabel(f"x / b  (b = {b:.4g} {unit_text('length', units_of(summary))}, Hertz)",
                     fontsize=9)
    ax.set_xlim(0, 1.5)
    ax.set_ylim(*VIEW)
    az.set_xlim(0.85, 1.1)
    az.set_ylim(*ZOOM)
    ax.set_ylabel(f"p / p0  (p0 = {p0:.5g} {unit_text('pressure', units_of(summary))}, Hertz)",
                  fontsize=9)
    what = "from stresses" if args.column == "pressure_from_stress" else "penalty traction"
    ax.set_title(f"{summary['case']}: {method} iterations, pressure {what}", fontsize=10)
    az.set_title("end of the contact zone", fontsize=10)
    ax.legend(fontsize=7, loc="lower left", ncol=2)
    if zoom_clipped:
        az.plot([], [], " ", label=f"curves clipped to {ZOOM[0]} ≤ p/p0 ≤ {ZOOM[1]}")
        az.legend(fontsize=7, loc="upper right")
    fig.tight_layout()
    out = args.out or os.path.join(folder, "adapt-pressure.png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
