#!/usr/bin/python3
"""Plots one column of a study's table against another (study.csv of `hpcontact study`).

usage: plot_study.py STUDY_DIR --x COLUMN --y COLUMN [--y COLUMN ...] [--group COLUMN]
                     [--log | --logx | --logy] [--out FILE.png] [--title TEXT]

STUDY_DIR is the --out folder of `hpcontact study` (or of scripts/study_table.py); its
study.csv has a row per run and a column per measure (docs/study.md): dofs, wall_time_s,
strain_energy, newton_iterations, contact.half_width, contact.e_L2_hertz_percent, ..., the
study's `columns` and its seed_* values. Every --y column is drawn against --x, one marker per
converged run with a value in both (the legend says how many runs were left out and why);
--group draws one curve per value of a column (case, a seed_* value, or a summary key the study
file lists in `columns`, e.g. method). Axis labels carry the column's unit where it is known (a
length or stress in the input's own units, a percentage, seconds, a count).
Writes FILE.png (default STUDY_DIR/<y>-vs-<x>.png) and prints its name. Exit status 1 with a
message naming the file and column when a column is not in study.csv or has no numbers.
"""
import csv
import json
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import script_parser, unit_text, units_of  # noqa: E402

# Units of study.csv's columns, by the end of their name.
UNITS = [(r"_percent$", "[%]"), (r"(^|\.)(wall_time_s|seconds)$", "[s]"),
         (r"(^|\.)(dofs|load_steps|newton_iterations|iterations)$", "[count]"),
         (r"(^|\.)(half_width|max_penetration|width)$", "length"),
         (r"(^|\.)(p_max|peak_pressure)$", "pressure"),
         (r"(^|\.)strain_energy$", "energy per thickness")]


def column_label(name, units):
    for pattern, unit in UNITS:
        if re.search(pattern, name):
            return f"{name} {unit if unit.startswith('[') else unit_text(unit, units)}"
    return name


def number(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("study_dir", help="folder with study.csv (hpcontact study --out)")
    ap.add_argument("--x", required=True, help="column along x, e.g. dofs")
    ap.add_argument("--y", required=True, action="append",
                    help="column along y, e.g. contact.e_L2_hertz_percent (repeatable)")
    ap.add_argument("--group", help="one curve per value of this column (e.g. case)")
    scale = ap.add_mutually_exclusive_group()
    scale.add_argument("--log", action="store_true", help="logarithmic x and y axes")
    scale.add_argument("--logx", action="store_true", help="logarithmic x axis")
    scale.add_argument("--logy", action="store_true", help="logarithmic y axis")
    ap.add_argument("--out", help="the PNG to write (default STUDY_DIR/<y>-vs-<x>.png)")
    ap.add_argument("--title", help="title (default: the study's title or name)")
    args = ap.parse_args(argv)

    table = os.path.join(args.study_dir, "study.csv")
    try:
        with open(table, newline="") as f:
            reader = csv.DictReader(f)
            rows, columns = list(reader), reader.fieldnames or []
    except OSError as e:
        print(f"plot_study: {table}: {e.strerror}", file=sys.stderr)
        return 1
    for name in [args.x, *args.y] + ([args.group] if args.group else []):
        if name not in columns:
            print(f"plot_study: {table}: no column '{name}' (columns: {', '.join(columns)})",
                  file=sys.stderr)
            return 1
    study, units = {}, None
    try:
        with open(os.path.join(args.study_dir, "study.json")) as f:
            study = json.load(f)
        units = next((units_of(r.get("summary")) for r in study.get("runs", [])
                      if units_of(r.get("summary"))), None)
    except (OSError, ValueError):
        pass  # the table alone is enough; the title and units then say less

    fig, ax = plt.subplots(figsize=(6.8, 4.6))
    notes, drawn = [], 0
    groups = sorted({r[args.group] for r in rows}) if args.group else [None]
    for yi, y in enumerate(args.y):
        for gi, g in enumerate(groups):
            pts, left_out = [], 0
            for r in rows:
                if g is not None and r[args.group] != g:
                    continue
                xv, yv = number(r[args.x]), number(r[y])
                ok = r.get("converged", "true") == "true" and xv is not None and yv is not None
                if ok and (args.log or args.logx) and xv <= 0 or ok and (args.log or args.logy) and yv <= 0:
                    ok = False
                if ok:
                    pts.append((xv, yv))
                else:
                    left_out += 1
            if not pts:
                notes.append(f"{y}{'' if g is None else f' ({g})'}: no value")
                continue
            pts.sort()
            label = y if len(args.y) > 1 or g is None else f"{args.group} = {g}"
            if len(args.y) > 1 and g is not None:
                label = f"{y}, {args.group} = {g}"
            if left_out:
                label += f" ({left_out} run(s) without a value{' > 0' if args.log else ''} left out)"
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", ms=4, lw=1.2,
                    color=f"C{(yi * len(groups) + gi) % 10}", label=label)
            drawn += len(pts)
    if drawn == 0:
        print(f"plot_study: {table}: no converged run has numbers in '{args.x}' and "
              f"'{', '.join(args.y)}'", file=sys.stderr)
        plt.close(fig)
        return 1
    if args.log or args.logx:
        ax.set_xscale("log")
    if args.log or args.logy:
        ax.set_yscale("log")
    ax.set_xlabel(column_label(args.x, units))
    ax.set_ylabel(column_label(args.y[0], units) if len(args.y) == 1 else
                  ", ".join(column_label(y, units) for y in args.y))
    ax.grid(alpha=0.3, which="both")
    for note in notes:
        ax.plot([], [], " ", label=note)
    ax.legend(fontsize=8)
    ax.set_title(args.title or study.get("title") or study.get("study") or table, fontsize=10)
    fig.tight_layout()
    slug = re.sub(r"[^A-Za-z0-9_.-]+", "_", f"{args.y[0]}-vs-{args.x}")
    out = args.out or os.path.join(args.study_dir, slug + ".png")
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
