#!/usr/bin/python3
"""Plots the contact pressure of every iteration of an rp or hp run (seed Fig. 5.15-5.18).

usage: plot_adapt.py RESULTS_DIR [OUT.png] [--column pressure_from_stress|pressure_penalty]

Reads RESULTS_DIR/summary.json (its adapt section) and RESULTS_DIR/rp/pressure-N.csv or
RESULTS_DIR/hp/pressure-N.csv (written by `hpcontact run` for a case with adapt.method rp or hp
and contact[].compare); writes RESULTS_DIR/adapt-pressure.png: p/p0 over x/b for every
iteration against Hertz and Shtayerman, the whole range and zoomed on the end of the zone.
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_columns  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("folder")
    ap.add_argument("out", nargs="?")
    ap.add_argument("--column", default="pressure_from_stress",
                    choices=["pressure_from_stress", "pressure_penalty"])
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
    closed = None
    for i, h in enumerate(history):
        path = os.path.join(folder, method, f"pressure-{h[key]}.csv")
        if not os.path.exists(path):
            print(f"{path}: missing", file=sys.stderr)
            return 1
        c = read_columns(path)
        closed = closed or c
        xb = [x / b for x in c["x"]]
        colour = cmap(i / max(1, len(history) - 1))
        label = f"{key} {h[key]} ({h['dofs']} DOF)"
        for a in (ax, az):
            a.plot(xb, [p / p0 for p in c[args.column]], color=colour, lw=1.2, label=label)
    xb = [x / b for x in closed["x"]]
    for a in (ax, az):
        a.plot(xb, [p / p0 for p in closed["hertz"]], "k--", lw=1, label="Hertz")
        a.plot(xb, [p / p0 for p in closed["shtayerman"]], "k:", lw=1.5, label="Shtayerman")
        a.grid(alpha=0.3)
        a.set_xlabel("x / b (Hertz)")
    ax.set_xlim(0, 1.5)
    ax.set_ylim(-0.15, 1.3)
    az.set_xlim(0.85, 1.1)
    az.set_ylim(-0.1, 0.6)
    ax.set_ylabel("p / p0 (Hertz)")
    what = "from stresses" if args.column == "pressure_from_stress" else "penalty traction"
    ax.set_title(f"{summary['case']}: {method} iterations, pressure {what}", fontsize=10)
    az.set_title("end of the contact zone", fontsize=10)
    ax.legend(fontsize=7, loc="lower left", ncol=2)
    fig.tight_layout()
    out = args.out or os.path.join(folder, "adapt-pressure.png")
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
