#!/usr/bin/python3
"""Plots the contact pressure of runs (their pressure.csv) against Hertz and Shtayerman.

usage: plot_pressure.py RESULTS_DIR [RESULTS_DIR ...] [OUT.png] [--label TEXT ...] [--units LENGTH,FORCE] [--out OUT.png]

Reads each RESULTS_DIR/pressure.csv and summary.json of a run whose contact pair has a `compare`
section (contact[].compare; pressure.csv is the curve of the first pair that has one, the panel's
title names it) and writes OUT.png (default: the first RESULTS_DIR/pressure.png): p/p0 over x/b,
b and p0 being Hertz's half width and peak pressure of each run (the axis labels give the first
run's values and units), like the dissertation's Fig. 5.11-5.14: the pressure from the stresses
(thick), the multiplier or penalty traction (thin), Hertz (dashed) and Shtayerman (dotted; of
the first run). Several runs (a p-study, two methods) get one colour and one legend entry each,
labelled by folder name or --label (once per folder, in order). The view is p/p0 in [-0.1, 1.3];
a curve that leaves it is clipped, and the legend says so with the curve's extreme value (also
printed after the PNG's name). Exit status 1 with a message for a run without `compare`.
hpcontact has no units: --units mm,N names them in the labels, else those summary.json names.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from matplotlib.lines import Line2D  # noqa: E402

from hpc_run import read_columns, script_parser, unit_text, units_of  # noqa: E402
from plot_runs import legend_below, pair_title, parse_units, read_problem, run_labels  # noqa: E402

LOW, HIGH = -0.1, 1.3


def clipped(label, values):
    """The legend label of a curve (values in units of p0), saying where the view clips it."""
    notes = []
    if max(values) > HIGH:
        notes.append(f"max {max(values):.3g} p0")
    if min(values) < LOW:
        notes.append(f"min {min(values):.3g} p0")
    return label + (f" (clipped: {', '.join(notes)})" if notes else "")


def read_run(folder):
    """summary.json and pressure.csv of a run with a comparison, or exits with status 1 naming
    what is missing."""
    try:
        with open(os.path.join(folder, "summary.json")) as f:
            summary = json.load(f)
    except OSError as e:
        print(f"plot_pressure: {os.path.join(folder, 'summary.json')}: {e.strerror}", file=sys.stderr)
        sys.exit(1)
    if "hertz_half_width" not in summary.get("contact", {}):
        print(f"plot_pressure: {folder}/summary.json has no pressure comparison (contact[].compare)",
              file=sys.stderr)
        sys.exit(1)
    return summary, read_columns(os.path.join(folder, "pressure.csv"))


# The curves of pressure.csv: column, legend words, style (FE curves take the run's colour).
CLOSED_FORMS = (("hertz", "Hertz", dict(color="k", ls="--", lw=1.2)),
                ("shtayerman", "Shtayerman", dict(color="k", ls=":", lw=1.5)))
FE_CURVES = (("pressure_multiplier", "multiplier", dict(lw=0.9, alpha=0.7)),
             ("pressure_penalty", "penalty traction", dict(lw=0.8, alpha=0.7)),
             ("pressure_from_stress", "from stresses", dict(lw=1.8)))


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("folders", nargs="+", metavar="RESULTS_DIR",
                    help="the --out folder(s) of `hpcontact run` (a last argument ending in .png "
                         "is OUT.png, the PNG to write)")
    ap.add_argument("--out", metavar="OUT.png", help="the PNG to write (default "
                    "RESULTS_DIR/pressure.png of the first)")
    ap.add_argument("--label", action="append", metavar="TEXT",
                    help="the legend label of a run, once per RESULTS_DIR (default: folder name)")
    ap.add_argument("--units", metavar="LENGTH,FORCE",
                    help="the units of the input's numbers, e.g. mm,N (default: see below)")
    args = ap.parse_args(argv)
    folders = list(args.folders)
    out = args.out
    if len(folders) > 1 and folders[-1].endswith(".png"):
        out = out or folders.pop()
    try:
        labels = run_labels(folders, args.label)
        runs = [read_run(folder) for folder in folders]
        units = parse_units(args.units) if args.units else units_of(runs[0][0])
    except ValueError as e:
        ap.error(str(e))
    out = out or os.path.join(folders[0], "pressure.png")
    fig, ax = plt.subplots(figsize=(7, 5.4 + 0.2 * len(runs)))
    notes, handles = [], []
    for i, (label, (summary, cols)) in enumerate(zip(labels, runs)):
        contact = summary["contact"]
        b, p0 = contact["hertz_half_width"], contact["hertz_peak_pressure"]
        xb = [x / b for x in cols["x"]]
        inside = [k for k, v in enumerate(xb) if 0 <= v <= 1.5]
        curves = (CLOSED_FORMS if i == 0 else ()) + FE_CURVES
        for column, words, style in curves:
            if column not in cols:
                continue
            p = [v / p0 for v in cols[column]]
            name = words if column in ("hertz", "shtayerman") else f"{label}: {words}"
            legend = clipped(name, [p[k] for k in inside])
            if legend != name:
                notes.append(legend)
            colour = {} if "color" in style else {"color": f"C{i}"}
            ax.plot(xb, p, **style, **colour)
            if column in ("hertz", "shtayerman"):
                handles.append((Line2D([], [], **style), words))
        handles.append((Line2D([], [], color=f"C{i}", lw=1.8), label))
    handles += [(Line2D([], [], color="0.4", lw=1.8), "from stresses (thick)"),
                (Line2D([], [], color="0.4", lw=0.9), "multiplier or penalty traction (thin)")]
    handles += [(Line2D([], [], color="none"), n) for n in notes]
    summary = runs[0][0]
    c = summary["contact"]
    b, p0 = c["hertz_half_width"], c["hertz_peak_pressure"]
    ax.set_xlabel(f"x / b  (b = {b:.4g} {unit_text('length', units)}: Hertz half width; "
                  "x undeformed, along the obstacle)", fontsize=9)
    ax.set_ylabel(f"p / p0  (p0 = {p0:.5g} {unit_text('pressure', units)})", fontsize=9)
    ax.set_xlim(0, 1.5)
    ax.set_ylim(LOW, HIGH)
    ax.grid(alpha=0.3)
    pair = c.get("pair", 0)
    title = pair_title(pair, read_problem(folders[0]), summary).replace("\n", " ")
    errors = "\n".join(f"{label}: {s['method']}-version, {s['dofs']} DOF, e_L2 vs Shtayerman "
                       f"{s['contact']['e_L2_shtayerman_percent']:.2f} %"
                       for label, (s, _) in zip(labels, runs))
    ax.set_title(f"{summary['case']}, {title}\n{errors}", fontsize=9 if len(runs) == 1 else 8)
    bottom = legend_below(fig, [h for h, _ in handles], [t for _, t in handles],
                          ncol=1 if notes else 2)
    fig.tight_layout(rect=(0, bottom, 1, 1))
    fig.savefig(out, dpi=120)
    plt.close(fig)
    print(f"wrote {out}" + "".join(f"; {n}" for n in notes))
    return 0


if __name__ == "__main__":
    sys.exit(main())
