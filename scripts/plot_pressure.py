#!/usr/bin/python3
"""Plots the contact pressure of a run (its pressure.csv) against Hertz and Shtayerman.

usage: plot_pressure.py RESULTS_DIR [OUT.png]

Reads RESULTS_DIR/pressure.csv and RESULTS_DIR/summary.json of a run whose contact pair has a
`compare` section (contact[].compare) and writes OUT.png (default RESULTS_DIR/pressure.png):
p/p0 over x/b, b and p0 being Hertz's half width and peak pressure (the axis labels give their
values and units), like the dissertation's Fig. 5.11-5.14: the pressure from the stresses, the
penalty traction, Hertz and Shtayerman. The view is p/p0 in [-0.1, 1.3]; a curve that leaves it
is clipped, and the legend says so with the curve's extreme value (also printed after the PNG's
name). Exit status 1 with a message for a run without `compare`.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_columns, script_parser, unit_text, units_of  # noqa: E402

LOW, HIGH = -0.1, 1.3


def clipped(label, values):
    """The legend label of a curve (values in units of p0), saying where the view clips it."""
    notes = []
    if max(values) > HIGH:
        notes.append(f"max {max(values):.3g} p0")
    if min(values) < LOW:
        notes.append(f"min {min(values):.3g} p0")
    return label + (f" (clipped: {', '.join(notes)})" if notes else "")


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("folder", metavar="RESULTS_DIR", help="the --out folder of `hpcontact run`")
    ap.add_argument("out", nargs="?", metavar="OUT.png",
                    help="the PNG to write (default RESULTS_DIR/pressure.png)")
    args = ap.parse_args(argv)
    folder = args.folder
    out = args.out or os.path.join(folder, "pressure.png")
    try:
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
    except OSError as e:
        print(f"plot_pressure: {os.path.join(folder, 'summary.json')}: {e.strerror}", file=sys.stderr)
        return 1
    contact = summary.get("contact", {})
    if "hertz_half_width" not in contact:
        print(f"plot_pressure: {folder}/summary.json has no pressure comparison (contact[].compare)",
              file=sys.stderr)
        return 1
    units = units_of(summary)
    b, p0 = contact["hertz_half_width"], contact["hertz_peak_pressure"]
    cols = read_columns(os.path.join(folder, "pressure.csv"))
    xb = [x / b for x in cols["x"]]
    inside = [i for i, v in enumerate(xb) if 0 <= v <= 1.5]
    fig, ax = plt.subplots(figsize=(7, 4.7))
    notes = []
    for column, label, style in (("hertz", "Hertz", dict(color="k", ls="--", lw=1.2)),
                                 ("shtayerman", "Shtayerman", dict(color="k", ls=":", lw=1.5)),
                                 ("pressure_multiplier", "FE, multiplier", dict(color="0.55", lw=0.9)),
                                 ("pressure_penalty", "FE, penalty traction", dict(color="0.7", lw=0.8)),
                                 ("pressure_from_stress", "FE, from stresses", dict(color="C0", lw=1.8))):
        if column not in cols:
            continue
        p = [v / p0 for v in cols[column]]
        legend = clipped(label, [p[i] for i in inside])
        if legend != label:
            notes.append(legend)
        ax.plot(xb, p, label=legend, **style)
    ax.set_xlabel(f"x / b  (b = {b:.4g} {unit_text('length', units)}: Hertz half width; "
                  "x undeformed, along the obstacle)", fontsize=9)
    ax.set_ylabel(f"p / p0  (p0 = {p0:.5g} {unit_text('pressure', units)})", fontsize=9)
    ax.set_xlim(0, 1.5)
    ax.set_ylim(LOW, HIGH)
    ax.grid(alpha=0.3)
    ax.set_title(f"{summary['case']}: {summary['method']}-version, {summary['dofs']} DOF, "
                 f"e_L2 vs Shtayerman {contact['e_L2_shtayerman_percent']:.2f} %", fontsize=10)
    ax.legend(loc="lower left", fontsize=8.5)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"wrote {out}" + "".join(f"; {n}" for n in notes))
    return 0


if __name__ == "__main__":
    sys.exit(main())
