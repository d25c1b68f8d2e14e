#!/usr/bin/python3
"""Plots a run's contact history (contact_history.csv: one row per converged load step and
contact pair) — the force each pair carries against the load path, as seal, press-fit and
friction work reads it.

usage: plot_contact_history.py RESULTS_DIR [RESULTS_DIR ...] [--against step|displacement_factor|load_factor]
                               [--per-circumference R] [--out FILE.png]

Top: the normal force (solid) and the tangential force (dashed) of every pair, per unit
thickness (an axisymmetric run: the total over the ring), against the step or the factor of the
prescribed displacements or of the loads (default: the factor that changes most over the first
run). Bottom: each pair's contact length and, with friction, its stick and slip point counts
(right axis). Several folders draw their curves in one plot, labelled by case, e.g. an
axisymmetric model beside its plane-strain section; --per-circumference R divides the forces of
the axisymmetric runs by 2 pi R, their force per unit length of the circle of radius R, to
compare with the plane runs' force per unit thickness. Axis labels carry the units summary.json
names, else input units. Writes FILE.png (default: the first RESULTS_DIR/contact-history.png)
and prints its name.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import axis_label, read_run_csv, script_parser, units_of  # noqa: E402

ABSCISSAE = ("step", "displacement_factor", "load_factor")


def read(folder):
    """contact_history.csv's columns and summary.json (or {}); exits naming the file when the
    history is missing or empty."""
    cols, summary = read_run_csv(folder, "contact_history.csv", "plot_contact_history",
                                 "a run without contact pairs, or an rp/hp run, which writes no "
                                 "history")
    path = os.path.join(folder, "contact_history.csv")
    missing = [c for c in ("pair", "normal_force", "tangential_force", "contact_length") if c not in cols]
    if missing:
        sys.exit(f"plot_contact_history: {path}: no column {', '.join(missing)}")
    return cols, summary


def default_abscissa(cols):
    """The factor that changes most over the run (a load stage after a press: the loads)."""
    def span(name):
        values = cols.get(name, [])
        return max(values) - min(values) if values else 0.0
    best = max(("displacement_factor", "load_factor"), key=span)
    return best if span(best) > 0 else "step"


def rows_of_pair(cols, pair):
    return [i for i, p in enumerate(cols["pair"]) if int(p) == pair]


def axisymmetric(summary):
    """Whether a run's summary says its integrals are over the solid of revolution."""
    units = summary.get("units")
    return isinstance(units, dict) and "axisymmetric" in units


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("folders", nargs="+", metavar="RESULTS_DIR",
                    help="the --out folder(s) of `hpcontact run`")
    ap.add_argument("--against", choices=ABSCISSAE, help="the abscissa (default: see above)")
    ap.add_argument("--per-circumference", type=float, metavar="R",
                    help="divide an axisymmetric run's forces by 2 pi R")
    ap.add_argument("--out", help="the PNG to write (default RESULTS_DIR/contact-history.png)")
    args = ap.parse_args(argv)
    if args.per_circumference is not None and not args.per_circumference > 0:
        ap.error(f"--per-circumference: must be > 0 (got {args.per_circumference})")
    runs = [read(folder) for folder in args.folders]
    cols, summary = runs[0]
    units = units_of(summary)
    x_name = args.against or default_abscissa(cols)
    friction = any(v > 0 for c, _ in runs for v in c.get("stick_points", []) + c.get("slip_points", []))
    several = len(runs) > 1

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 2]})
    counts = bottom.twinx() if friction else None
    k = 0
    force_kinds = set()
    for folder, (cols, summary) in zip(args.folders, runs):
        case = summary.get("case", os.path.basename(os.path.abspath(folder)))
        scale = 1.0
        if axisymmetric(summary):
            if args.per_circumference:
                scale = 1 / (2 * math.pi * args.per_circumference)
                force_kinds.add(f"axisymmetric: per length of the circle r = {args.per_circumference:g}")
            else:
                force_kinds.add("axisymmetric: total over the ring")
        else:
            force_kinds.add("plane: per unit thickness")
        for pair in sorted({int(p) for p in cols["pair"]}):
            rows = rows_of_pair(cols, pair)
            x = [cols[x_name][i] for i in rows]
            colour = f"C{k}"
            k += 1
            body = cols["body"][rows[0]] if "body" in cols else ""
            label = (f"{case} " if several else "") + f"pair {pair}" + (f" ({body})" if body else "")
            top.plot(x, [scale * cols["normal_force"][i] for i in rows], "-o", ms=3, color=colour,
                     label=f"{label}: normal")
            top.plot(x, [scale * cols["tangential_force"][i] for i in rows], "--s", ms=3,
                     color=colour, label=f"{label}: tangential")
            bottom.plot(x, [cols["contact_length"][i] for i in rows], "-o", ms=3, color=colour,
                        label=f"{label}: contact length")
            if counts and "stick_points" in cols:
                counts.step(x, [cols["stick_points"][i] for i in rows], where="post", color=colour,
                            lw=0.8, label=f"{label}: stick points")
                counts.step(x, [cols["slip_points"][i] for i in rows], where="post", color=colour,
                            lw=0.8, ls=":", label=f"{label}: slip points")
    force_quantity = "force" if force_kinds == {"axisymmetric: total over the ring"} else "force per thickness"
    top.set_ylabel(axis_label("force", force_quantity, units))
    if several or "plane: per unit thickness" not in force_kinds:
        top.text(0.01, 0.98, "; ".join(sorted(force_kinds)), transform=top.transAxes, fontsize=7,
                 va="top")
    top.axhline(0, color="0.8", lw=0.6)
    top.legend(fontsize=7 if several else 8, loc="center left")
    title = (", ".join(s.get("case", os.path.basename(os.path.abspath(f)))
                       for f, (_, s) in zip(args.folders, runs)))
    top.set_title(f"{title}: contact forces over the load path", fontsize=10)
    bottom.set_ylabel(axis_label("contact length", "length", units))
    bottom.set_xlabel(x_name.replace("_", " ") + ("" if x_name == "step" else " [-]"))
    if counts:
        counts.set_ylabel("points [-]")
        lines = bottom.get_legend_handles_labels()
        more = counts.get_legend_handles_labels()
        bottom.legend(lines[0] + more[0], lines[1] + more[1], fontsize=7)
    else:
        bottom.legend(fontsize=8)
    fig.tight_layout()
    out = args.out or os.path.join(args.folders[0], "contact-history.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
