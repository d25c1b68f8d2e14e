#!/usr/bin/python3
"""Plots the contact pressure and the gap along the contact boundary from runs' contact.csv
(any case; scripts/plot_pressure.py needs a contact[].compare section, this does not): one
panel per contact pair, one colour and one legend entry per run.

usage: plot_contact.py RESULTS_DIR [RESULTS_DIR ...] [--label TEXT ...] [--pair K ...]
                       [--along auto|X|Y|s] [--units LENGTH,FORCE] [--out FILE.png] [--xlim A B] [--ylim A B]

Each pair's panel (titled with the pair as the run's input.yaml names it: contact[K], its body
and edge sets, the obstacle) has the pressure above and the gap g_N below: the pressure from the
stresses (-n.sigma.n, thick) and the column `pressure` (thin: the multiplier at the multiplier
nodes; with enforcement: penalty the penalty traction eps_N <-g_N> at the Gauss points), over
the undeformed coordinate X or Y (auto, the default: the one the pair's points spread along
more — X along a plate, Y along a wall), or s = the arc length along the pair's points in file
order (the program writes them along the boundary). A pair between two bodies lists the points
of both: the other body's are drawn dotted. Runs are told apart by colour and labelled by folder
name or by --label (once per folder, in order) in one legend below the panels; --pair draws only
the pairs named. --xlim limits the view along the boundary (the gap axes then fit the points
inside it). The pressure axis shows every run's `pressure` and the pressure from the stresses
where the points touch (state contact): the stresses at an open point can be far off (at the
end of a coarse edge set); a curve that leaves the axis (or the range of --ylim) is clipped,
and the legend says so with its range. hpcontact has no units: its numbers are in those of the input; --units mm,N
writes them into the labels ([mm], [N/mm²]), else those summary.json names, else "input units".
Writes FILE.png (default: RESULTS_DIR/contact.png of the first folder) and prints its name.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_run_csv, script_parser  # noqa: E402
from plot_runs import (add_run_arguments, chosen_units, common_pair_title,  # noqa: E402
                       legend_below, pair_cells, panel_grid, read_problem, run_labels, unit_of)

ALONG = {"X": "undeformed X", "Y": "undeformed Y", "s": "s along the contact points"}


def pressure_name(problem):
    """What contact.csv's `pressure` is: the penalty traction if the run's effective input
    enforces contact by the penalty, else the multiplier."""
    pairs = problem.get("contact") or []
    if any((p or {}).get("enforcement") == "penalty" for p in pairs):
        return "penalty traction"
    return "multiplier" if pairs else "pressure"


class Run:
    """One results folder: contact.csv's columns, summary.json, input.yaml and its label."""

    def __init__(self, folder, label):
        self.folder, self.label = folder, label
        self.cols, self.summary = read_run_csv(folder, "contact.csv", "plot_contact",
                                               "a run without contact pairs?")
        self.problem = read_problem(folder)
        n = len(self.cols["X"])
        self.cols.setdefault("pair", [0.0] * n)
        self.pairs = sorted({int(p) for p in self.cols["pair"]})

    def groups(self, pair):
        """The rows of `pair` by body, the pair's own body first (the one contact[K] names)."""
        rows = [i for i, p in enumerate(self.cols["pair"]) if int(p) == pair]
        bodies = self.cols.get("body") or [""] * len(self.cols["X"])
        names = list(dict.fromkeys(bodies[i] for i in rows))
        pairs = self.problem.get("contact") or []
        own = (pairs[pair] or {}).get("body") if pair < len(pairs) else None
        names.sort(key=lambda b: b != own)
        return [[i for i in rows if bodies[i] == b] for b in names]


def abscissa(cols, rows, along):
    """The coordinate along the pair of these rows, and its name (auto: X or Y, the one that
    spans more)."""
    if along == "auto":
        span = {c: max(cols[c][i] for i in rows) - min(cols[c][i] for i in rows) for c in "XY"}
        along = "Y" if span["Y"] > span["X"] else "X"
    if along != "s":
        return [cols[along][i] for i in rows], along
    t, s = [0.0], 0.0
    for a, b in zip(rows, rows[1:]):
        s += math.hypot(cols["X"][b] - cols["X"][a], cols["Y"][b] - cols["Y"][a])
        t.append(s)
    return t, along


def finite(values):
    """Values for a plot: an open point's infinite gap (no surface facing it) left out."""
    return [v if isinstance(v, float) and math.isfinite(v) else math.nan for v in values]


def pressure_view(runs, pair):
    """The pressure axis's default range for a pair: every run's `pressure` and its pressure
    from the stresses where the points touch (state contact), with 0 — or None (all values)
    when the stresses at open points stay within 1.5 times that. An open point's stresses at
    the end of a contact edge set can be far off (a coarse element's corner), and would
    flatten the curves to a line."""
    inside, every = [0.0], [0.0]
    for run in runs:
        c = run.cols
        rows = [i for i, p in enumerate(c["pair"]) if int(p) == pair]
        state = c.get("state") or ["contact"] * len(c["X"])
        inside += finite([c["pressure"][i] for i in rows])
        inside += finite([c["pressure_from_stress"][i] for i in rows if state[i] == "contact"])
        every += finite([c["pressure_from_stress"][i] for i in rows])
    inside = [v for v in inside if math.isfinite(v)]
    every = [v for v in every if math.isfinite(v)]
    lo, hi = min(inside), max(inside)
    span = hi - lo or 1.0
    if min(every) >= lo - 0.5 * span and max(every) <= hi + 0.5 * span:
        return None
    return lo - 0.08 * span, hi + 0.08 * span


def draw_pair(ax, ag, pair, runs, args, view):
    """One pair's panel: pressure (ax, within `view` or all) and gap (ag) of every run; returns
    the name of its abscissa, the gaps in view and the clipping notes."""
    gaps, notes, along = [], [], args.along
    for i, run in enumerate(runs):
        if pair not in run.pairs:
            continue
        c = run.cols
        groups = run.groups(pair)
        t0, along = abscissa(c, groups[0], args.along)
        for g, rows in enumerate(groups):
            t = t0 if g == 0 else abscissa(c, rows, along)[0]
            seen = [k for k, x in enumerate(t) if not args.xlim or args.xlim[0] <= x <= args.xlim[1]]
            columns = [("pressure_from_stress", dict(lw=1.8))]
            if g == 0:
                columns.append(("pressure", dict(lw=0.7, alpha=0.6)))
            for column, style in columns:
                p = finite([c[column][k] for k in rows])
                shown = [p[k] for k in seen if math.isfinite(p[k])]
                if view and shown and (min(shown) < view[0] or max(shown) > view[1]):
                    notes.append(f"{run.label}, pair {pair}, {column}: clipped, "
                                 f"{min(shown):.4g} to {max(shown):.4g}")
                ax.plot(t, p, color=f"C{i}", ls="-" if g == 0 else ":", **style)
            gap = finite([c["gap"][k] for k in rows])
            ag.plot(t, gap, color=f"C{i}", lw=1.2, ls="-" if g == 0 else ":")
            gaps += [gap[k] for k in seen if math.isfinite(gap[k])]
    return along, gaps, notes


def main(argv=None):
    ap = script_parser(__doc__)
    add_run_arguments(ap, "one colour and legend entry each")
    ap.add_argument("--pair", type=int, action="append", metavar="K",
                    help="draw pair K only (contact[K]; repeat for several; default: all)")
    ap.add_argument("--along", default="auto", choices=["auto", "X", "Y", "s"],
                    help="abscissa: undeformed X or Y, auto: the one a pair spreads along "
                         "more, or s, the length along the contact points (default %(default)s)")
    ap.add_argument("--out", help="PNG to write (default RESULTS_DIR/contact.png of the first)")
    ap.add_argument("--xlim", type=float, nargs=2, metavar=("A", "B"), help="range of the abscissa")
    ap.add_argument("--ylim", type=float, nargs=2, metavar=("A", "B"),
                    help="range of the pressure axes (default: all values)")
    args = ap.parse_args(argv)
    try:
        labels = run_labels(args.folders, args.label)
        runs = [Run(folder, label) for folder, label in zip(args.folders, labels)]
        units = chosen_units(args, runs[0].summary)
    except ValueError as e:
        ap.error(str(e))
    pairs = sorted({p for r in runs for p in r.pairs})
    if args.pair:
        missing = sorted(set(args.pair) - set(pairs))
        if missing:
            ap.error(f"--pair: no pair {', '.join(map(str, missing))} in the runs "
                     f"(pairs {', '.join(map(str, pairs))})")
        pairs = sorted(set(args.pair))
    rows, cols = panel_grid(len(pairs))
    fig = plt.figure(figsize=(4.6 * cols if cols > 1 else 7, 5.2 * rows + 0.6))
    cells = pair_cells(fig, len(pairs), 2, height_ratios=[2, 1])
    notes = []
    for pair, (ax, ag) in zip(pairs, cells):
        view = tuple(args.ylim) if args.ylim else pressure_view(runs, pair)
        along, gaps, clipped = draw_pair(ax, ag, pair, runs, args, view)
        notes += clipped
        ax.set_title(common_pair_title(pair, runs), fontsize=9)
        ax.set_ylabel(f"contact pressure {unit_of('pressure', units)}", fontsize=8)
        ag.set_ylabel(f"gap g_N {unit_of('length', units)}", fontsize=8)
        ag.set_xlabel(f"{ALONG[along]} {unit_of('length', units)}", fontsize=8)
        ag.axhline(0, color="k", lw=0.6)
        for a in (ax, ag):
            a.grid(alpha=0.3)
            a.tick_params(labelsize=8)
        if view:
            ax.set_ylim(*view)
        if args.xlim:
            ag.set_xlim(*args.xlim)
            if gaps:
                lo, hi = min(gaps), max(gaps)
                pad = 0.05 * (hi - lo) or 1e-12
                ag.set_ylim(lo - pad, hi + pad)
    handles = [Line2D([], [], color=f"C{i}", lw=1.8) for i in range(len(runs))]
    texts = [r.label for r in runs]
    handles += [Line2D([], [], color="0.4", lw=1.8), Line2D([], [], color="0.4", lw=0.7)]
    texts += ["from stresses (thick)", f"{pressure_name(runs[0].problem)} (thin)"]
    if any(len(r.groups(p)) > 1 for r in runs for p in pairs if p in r.pairs):
        handles.append(Line2D([], [], color="0.4", ls=":"))
        texts.append("the other body's points")
    handles += [Line2D([], [], color="none")] * len(notes)
    texts += notes
    bottom = legend_below(fig, handles, texts, ncol=1 if notes else None)
    fig.tight_layout(rect=(0, bottom, 1, 1))
    out = args.out or os.path.join(args.folders[0], "contact.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
