#!/usr/bin/python3
"""Plots runs' contact histories (contact_history.csv: one row per converged load step and
contact pair) — what each pair carries against the load path, as seal, press-fit and friction
work reads it: one panel per pair, one colour and one legend entry per run.

usage: plot_contact_history.py RESULTS_DIR [RESULTS_DIR ...] [--label TEXT ...] [--x Q] [--y Q[,Q...]]
                               [--units LENGTH,FORCE] [--per-circumference R] [--out FILE.png]

Quantities (--x, the abscissa; --y, the ordinates, several separated by commas):
  step, load_factor, displacement_factor      of the load step (the factors of path.csv)
  squeeze, squeeze:NAME                       how far a prescribed displacement has moved along
                                              its direction: the displacement factor times
                                              contact[K].obstacle.displacement (NAME: contact[K]
                                              or K) or a constraint's (ux, uy) (NAME: the body,
                                              an edge set of the constraint, or BODY/EDGE_SET);
                                              plain squeeze: the run's only one. Computed from
                                              the run's input.yaml and the factors per step.
  normal_force, tangential_force, resultant_x, resultant_y, contact_length, max_penetration,
  pressure_max, traction_max, contact_points, stick_points, slip_points
                                              a column of contact_history.csv: of the panel's
                                              pair, or of pair K with :K (--x normal_force:1)
Defaults: --x squeeze where every run has exactly one prescribed displacement (a plate moved
down), else the factor that changes most over the first run (else step); --y normal_force, with
tangential_force where a run carries one. Quantities of one kind (forces; lengths; pressures;
counts) share a panel's axes — solid the first, then dashed, dotted —, each further kind adds a
row of axes to every panel.

Each panel is titled with its pair as the run's input.yaml names it (contact[K], its body and
edge sets, the obstacle); runs are told apart by colour and labelled by folder name or by
--label (once per folder, in order) in one legend below the panels. Forces are per unit
thickness (plane: "force per unit length"), or for an axisymmetric run the total over the
ring; --per-circumference R divides an axisymmetric run's forces by 2 pi R, the force per unit
length of the circle of radius R, to compare with plane runs (runs of both kinds without it are
refused: their forces have different units). hpcontact has no units: its numbers are in those of
the input; --units mm,N writes them into the labels ("squeeze [mm]", "normal force per unit
length [N/mm]"), else those summary.json names, else "input units". Writes FILE.png (default:
the first RESULTS_DIR/contact-history.png) and prints its name.
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
                       find_prescribed, legend_below, pair_cells, panel_grid, read_problem,
                       run_labels, unit_of)

# A pair's columns of contact_history.csv: their kind (what shares axes) and how a label says them.
PAIR_COLUMNS = {"normal_force": ("force", "normal force"),
                "tangential_force": ("force", "tangential force"),
                "resultant_x": ("force", "resultant x"), "resultant_y": ("force", "resultant y"),
                "contact_length": ("length", "contact length"),
                "max_penetration": ("length", "largest penetration"),
                "pressure_max": ("pressure", "peak pressure"),
                "traction_max": ("pressure", "peak traction"),
                "contact_points": ("count", "contact points"),
                "stick_points": ("count", "stick points"), "slip_points": ("count", "slip points")}
STEP_COLUMNS = {"step": ("step", "load step"), "load_factor": ("factor", "load factor"),
                "displacement_factor": ("factor", "displacement factor")}
STYLES = ("-", "--", ":", "-.")


class Run:
    """One results folder: its contact history, summary.json, input.yaml and label."""

    def __init__(self, folder, label):
        self.folder, self.label = folder, label
        self.cols, self.summary = read_run_csv(
            folder, "contact_history.csv", "plot_contact_history",
            "a run without contact pairs, or an rp/hp run, which writes no history")
        path = os.path.join(folder, "contact_history.csv")
        missing = [c for c in ("step", "pair", "normal_force") if c not in self.cols]
        if missing:
            sys.exit(f"plot_contact_history: {path}: no column {', '.join(missing)}")
        self.problem = read_problem(folder)
        self.pairs = sorted({int(p) for p in self.cols["pair"]})
        units = self.summary.get("units")
        self.axisymmetric = isinstance(units, dict) and "axisymmetric" in units

    def rows(self, pair):
        return [i for i, p in enumerate(self.cols["pair"]) if int(p) == pair]

    def factors(self, rows):
        """The displacement factors (x, y) of these rows: displacement_factor_x and _y where the
        run writes them (stages that differ by direction), else displacement_factor both."""
        c = self.cols
        fx = c.get("displacement_factor_x", c["displacement_factor"])
        fy = c.get("displacement_factor_y", c["displacement_factor"])
        return [(fx[i], fy[i]) for i in rows]


class Quantity:
    """A quantity of --x or --y: `name` (a column, squeeze, with :QUALIFIER), its kind and the
    words of its label."""

    def __init__(self, text):
        self.text = text
        self.name, _, self.qualifier = text.partition(":")
        if self.name == "squeeze":
            self.kind, self.words = "length", "squeeze"
        elif self.name in STEP_COLUMNS and not self.qualifier:
            self.kind, self.words = STEP_COLUMNS[self.name]
        elif self.name in PAIR_COLUMNS:
            self.kind, self.words = PAIR_COLUMNS[self.name]
            if self.qualifier:
                if not self.qualifier.isdigit():
                    raise ValueError(f"'{text}': the pair after ':' is a number, e.g. "
                                     f"{self.name}:1")
                self.words += f" of pair {self.qualifier}"
        else:
            raise ValueError(f"unknown quantity '{text}' (known: {', '.join(STEP_COLUMNS)}, "
                             f"squeeze[:NAME], {', '.join(PAIR_COLUMNS)}[:PAIR])")

    def values(self, run, pair, scale):
        """Its values at the load steps of `pair` in `run` (forces times `scale`); ValueError
        naming the run's file where the run cannot give it."""
        rows = run.rows(pair)
        where = os.path.join(run.folder, "contact_history.csv")
        if self.name == "squeeze":
            if not run.problem:
                raise ValueError(f"{os.path.join(run.folder, 'input.yaml')}: missing: the squeeze "
                                 "is computed from the run's effective input")
            moved = find_prescribed(run.problem, self.qualifier or None,
                                    os.path.join(run.folder, "input.yaml"))
            return [moved.squeeze(fx, fy) for fx, fy in run.factors(rows)]
        if self.name not in run.cols:
            raise ValueError(f"{where}: no column {self.name}")
        column = run.cols[self.name]
        factor = scale if self.kind == "force" else 1.0
        if not self.qualifier:
            return [factor * column[i] for i in rows]
        other = int(self.qualifier)
        if other not in run.pairs:
            raise ValueError(f"{where}: no pair {other} (pairs {', '.join(map(str, run.pairs))})")
        at_step = {run.cols["step"][i]: column[i] for i in run.rows(other)}
        return [factor * at_step.get(run.cols["step"][i], math.nan) for i in rows]


def force_quantity(runs, per_circumference):
    """The unit quantity of forces (unit_text's), the scale of each run's forces, and None or
    why the runs' forces cannot share an axis."""
    axi = [r.axisymmetric for r in runs]
    scales = [1 / (2 * math.pi * per_circumference) if a and per_circumference else 1.0 for a in axi]
    if all(axi) and not per_circumference:
        return "force", scales, None
    if any(axi) and not all(axi) and not per_circumference:
        return None, scales, ("axisymmetric runs (forces: totals over the ring) and plane ones "
                              "(per unit length): give --per-circumference R")
    return "force per thickness", scales, None


def label_of(words, kind, force_unit, units):
    """An axis label: the quantity's words and its unit ("normal force per unit length [N/mm]")."""
    if kind == "step":
        return words
    if kind in ("factor", "count"):
        return f"{words} [-]"
    if kind == "force":
        words += " per unit length" if force_unit == "force per thickness" else ""
        return f"{words} {unit_of(force_unit, units)}"
    return f"{words} {unit_of(kind, units)}"


def row_label(same, force_unit, units):
    """The label of a row of axes: its one quantity's, else the kind's ("force per unit length
    [N/mm]"; the legend tells the quantities apart by line style)."""
    if len(same) == 1:
        return label_of(same[0].words, same[0].kind, force_unit, units)
    kind = same[0].kind
    return label_of({"count": "points"}.get(kind, kind), kind, force_unit, units)


def draw_pair(axes, pair, runs, scales, x, ys, kinds):
    """One pair's panel: each run's curves of the quantities `ys` over `x`, a row of axes per
    kind, one colour per run."""
    axes[0].set_title(common_pair_title(pair, runs), fontsize=9)
    for i, (run, scale) in enumerate(zip(runs, scales)):
        if pair not in run.pairs:
            continue
        xs = x.values(run, pair, scale)
        for row, kind in enumerate(kinds):
            for j, q in enumerate([q for q in ys if q.kind == kind]):
                axes[row].plot(xs, q.values(run, pair, scale), STYLES[j % len(STYLES)],
                               marker="o", ms=3, color=f"C{i}", label=run.label)


def default_x(runs):
    """squeeze where every run has exactly one prescribed displacement, else the factor that
    changes most over the first run (a load stage after a press: the loads), else step."""
    try:
        for r in runs:
            find_prescribed(r.problem, None, r.folder)
        if all(r.problem for r in runs):
            return "squeeze"
    except ValueError:
        pass
    cols = runs[0].cols

    def span(name):
        values = cols.get(name, [])
        return max(values) - min(values) if values else 0.0
    best = max(("displacement_factor", "load_factor"), key=span)
    return best if span(best) > 0 else "step"


def default_y(runs):
    """normal_force, and tangential_force where a run carries one."""
    for r in runs:
        t, n = r.cols.get("tangential_force", []), r.cols["normal_force"]
        if any(abs(v) > 1e-9 * max(max(map(abs, n)), 1e-300) for v in t):
            return "normal_force,tangential_force"
    return "normal_force"


def main(argv=None):
    ap = script_parser(__doc__)
    add_run_arguments(ap, "one colour and legend entry each")
    ap.add_argument("--x", "--against", dest="x", metavar="Q",
                    help="the abscissa (default: see above)")
    ap.add_argument("--y", metavar="Q[,Q...]", help="the ordinates (default: see above)")
    ap.add_argument("--per-circumference", type=float, metavar="R",
                    help="divide an axisymmetric run's forces by 2 pi R")
    ap.add_argument("--out", help="the PNG to write (default RESULTS_DIR/contact-history.png)")
    args = ap.parse_args(argv)
    if args.per_circumference is not None and not args.per_circumference > 0:
        ap.error(f"--per-circumference: must be > 0 (got {args.per_circumference})")
    try:
        labels = run_labels(args.folders, args.label)
        runs = [Run(folder, label) for folder, label in zip(args.folders, labels)]
        units = chosen_units(args, runs[0].summary)
        x = Quantity(args.x or default_x(runs))
        ys = [Quantity(t.strip()) for t in (args.y or default_y(runs)).split(",")]
    except ValueError as e:
        ap.error(str(e))
    force_unit, scales, mixed = force_quantity(runs, args.per_circumference)
    if mixed and any(q.kind == "force" for q in [x] + ys):
        ap.error(mixed)
    kinds = list(dict.fromkeys(q.kind for q in ys))
    pairs = sorted({p for r in runs for p in r.pairs})

    grid_rows, grid_cols = panel_grid(len(pairs))
    fig = plt.figure(figsize=(max(7.0, 4.3 * grid_cols), grid_rows * (0.9 + 2.3 * len(kinds)) + 1.0))
    cells = pair_cells(fig, len(pairs), len(kinds))
    try:
        for pair, axes in zip(pairs, cells):
            draw_pair(axes, pair, runs, scales, x, ys, kinds)
            for row, kind in enumerate(kinds):
                ax = axes[row]
                ax.set_ylabel(row_label([q for q in ys if q.kind == kind], force_unit, units),
                              fontsize=8)
                ax.axhline(0, color="0.8", lw=0.6, zorder=0)
                ax.grid(alpha=0.3)
                ax.tick_params(labelsize=8)
            axes[-1].set_xlabel(label_of(x.words, x.kind, force_unit, units), fontsize=8)
    except ValueError as e:
        ap.error(str(e))
    handles = [Line2D([], [], color=f"C{i}", marker="o", ms=3) for i in range(len(runs))]
    texts = [r.label for r in runs]
    for kind in kinds:
        same = [q for q in ys if q.kind == kind]
        if len(same) > 1:
            handles += [Line2D([], [], color="0.4", ls=STYLES[j % len(STYLES)]) for j in range(len(same))]
            texts += [q.words for q in same]
    bottom = legend_below(fig, handles, texts)
    heading = "contact over the load path"
    if x.name == "squeeze":
        moved = {find_prescribed(r.problem, x.qualifier or None, r.folder).name for r in runs}
        heading += f"\nsqueeze: how far {', '.join(sorted(moved))} has moved"
    if args.per_circumference and any(r.axisymmetric for r in runs):
        heading += f"\naxisymmetric forces per length of the circle r = {args.per_circumference:g}"
    fig.suptitle(heading, fontsize=10)
    fig.tight_layout(rect=(0, bottom, 1, 1))
    out = args.out or os.path.join(args.folders[0], "contact-history.png")
    fig.savefig(out, dpi=100)
    plt.close(fig)
    print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
