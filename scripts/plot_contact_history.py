#!/usr/bin/python3
"""Plots a run's contact history (contact_history.csv: one row per converged load step and
contact pair) — the force each pair carries against the load path, as seal, press-fit and
friction work reads it.

usage: plot_contact_history.py RESULTS_DIR [--against step|displacement_factor|load_factor] [--out FILE.png]

Top: the normal force (solid) and the tangential force (dashed) of every pair, per unit
thickness, against the step or the factor of the prescribed displacements or of the loads
(default: the factor that changes most over the run). Bottom: each pair's contact length and,
with friction, its stick and slip point counts (right axis). Axis labels carry the units
summary.json names, else input units. Writes FILE.png (default RESULTS_DIR/contact-history.png)
and prints its name.
"""
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


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("folder", metavar="RESULTS_DIR", help="the --out folder of `hpcontact run`")
    ap.add_argument("--against", choices=ABSCISSAE, help="the abscissa (default: see above)")
    ap.add_argument("--out", help="the PNG to write (default RESULTS_DIR/contact-history.png)")
    args = ap.parse_args(argv)
    cols, summary = read(args.folder)
    units = units_of(summary)
    x_name = args.against or default_abscissa(cols)
    pairs = sorted({int(p) for p in cols["pair"]})
    friction = any(v > 0 for v in cols.get("stick_points", []) + cols.get("slip_points", []))

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6.5), sharex=True,
                                      gridspec_kw={"height_ratios": [3, 2]})
    counts = bottom.twinx() if friction else None
    for k, pair in enumerate(pairs):
        rows = rows_of_pair(cols, pair)
        x = [cols[x_name][i] for i in rows]
        colour = f"C{k}"
        body = cols["body"][rows[0]] if "body" in cols else ""
        label = f"pair {pair}" + (f" ({body})" if body else "")
        top.plot(x, [cols["normal_force"][i] for i in rows], "-o", ms=3, color=colour,
                 label=f"{label}: normal")
        top.plot(x, [cols["tangential_force"][i] for i in rows], "--s", ms=3, color=colour,
                 label=f"{label}: tangential")
        bottom.plot(x, [cols["contact_length"][i] for i in rows], "-o", ms=3, color=colour,
                    label=f"{label}: contact length")
        if counts:
            counts.step(x, [cols["stick_points"][i] for i in rows], where="post", color=colour,
                        lw=0.8, label=f"{label}: stick points")
            counts.step(x, [cols["slip_points"][i] for i in rows], where="post", color=colour,
                        lw=0.8, ls=":", label=f"{label}: slip points")
    top.set_ylabel(axis_label("force", "force per thickness", units))
    top.axhline(0, color="0.8", lw=0.6)
    top.legend(fontsize=8)
    top.set_title(f"{summary.get('case', os.path.basename(os.path.abspath(args.folder)))}: "
                  "contact forces over the load path", fontsize=10)
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
    out = args.out or os.path.join(args.folder, "contact-history.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    main()
