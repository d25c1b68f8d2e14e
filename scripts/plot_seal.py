#!/usr/bin/python3
"""Draws an O-ring seal's curves from a study over the system pressure (examples/o-ring/
o-ring-seal-study.yaml, run by `hpcontact study`): the force–squeeze curve of the squeeze stage,
the peak contact pressure on each sealing face against the system pressure (the seal holds while
it exceeds the system pressure: the line p = p_s), and the plate zone's deformed end nearest the
sealed side against the groove wall's x (the extrusion onset: the zone reaching past the wall's
edge into the gap).

usage: plot_seal.py STUDY_DIR [--plate K] [--groove K] [--units LENGTH,FORCE] [--out FILE.png]

Each run folder STUDY_DIR/runs/NN-label/ gives one system pressure: bodies[0].loads[0].pressure
of its input.yaml. The plate is contact[--plate] (default 1), a plane; the groove contact[--groove]
(default 0), a profile whose lowest points are the groove's bottom: the wall on the sealed side is
the rightmost of them (a pressure from the left). The force–squeeze curve is the first run's
contact_history.csv rows with load factor 0, against the plate's displacement times the factor.
Prints a table (p_s, the two peaks, the plate zone's end, leaks) and the onset, interpolated
linearly between the last run whose zone end lies inside the wall and the first beyond it, or
that no run reaches it. Writes FILE.png (default STUDY_DIR/seal.png) and prints its name.
"""
import csv
import glob
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import script_parser  # noqa: E402
from plot_runs import chosen_units, read_problem, unit_of  # noqa: E402


def sealed_side_wall(problem, groove):
    """The x of the groove wall on the sealed side: the rightmost of the profile's lowest points."""
    points = problem["contact"][groove]["obstacle"]["points"]
    bottom = min(y for _, y in points)
    return max(x for x, y in points if abs(y - bottom) < 1e-12)


def read_run(folder, plate, groove):
    """One run's figures: system pressure, peaks, the plate zone's rightmost deformed end, leaks."""
    summary = json.load(open(os.path.join(folder, "summary.json")))
    problem = read_problem(folder)
    pairs = summary["contact_pairs"]
    return {"p_s": float(problem["bodies"][0]["loads"][0]["pressure"]),
            "peak_groove": pairs[groove]["pressure_max"],
            "peak_plate": pairs[plate]["pressure_max"],
            "plate_zone_end": max(x for x, _ in pairs[plate]["gamma_star_deformed"]),
            "leaks": any(p["leaks"] for p in summary.get("penetration", [])),
            "summary": summary, "problem": problem, "folder": folder}


def onset(rows, wall):
    """The system pressure at which the plate zone's end reaches the wall (linear between the
    runs that bracket it), or None."""
    for below, above in zip(rows, rows[1:]):
        if below["plate_zone_end"] <= wall < above["plate_zone_end"]:
            t = (wall - below["plate_zone_end"]) / (above["plate_zone_end"] - below["plate_zone_end"])
            return below["p_s"] + t * (above["p_s"] - below["p_s"])
    return None


def squeeze_curve(row, plate):
    """Squeeze and plate force of the squeeze stage (load factor 0) of one run."""
    dy = abs(row["problem"]["contact"][plate]["obstacle"]["displacement"][1])
    squeeze, force = [0.0], [0.0]
    with open(os.path.join(row["folder"], "contact_history.csv")) as f:
        for r in csv.DictReader(f):
            if int(r["pair"]) == plate and float(r["load_factor"]) == 0.0:
                squeeze.append(float(r["displacement_factor"]) * dy)
                force.append(float(r["normal_force"]))
    return squeeze, force


def draw(rows, wall, plate, units, out):
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(14, 4.2))
    squeeze, force = squeeze_curve(rows[0], plate)
    a.plot(squeeze, force, "o-")
    a.set_xlabel(f"squeeze (plate displacement) {unit_of('length', units)}")
    a.set_ylabel(f"plate force {unit_of('force per thickness', units)}")
    a.set_title("squeeze stage")
    ps = [r["p_s"] for r in rows]
    b.plot(ps, [r["peak_plate"] for r in rows], "o-", label="plate face (contact[%d])" % plate)
    b.plot(ps, [r["peak_groove"] for r in rows], "s-", label="groove faces")
    b.plot([0, max(ps)], [0, max(ps)], "k--", label="system pressure")
    for r in rows:
        if r["leaks"]:
            b.plot([r["p_s"]], [r["peak_plate"]], "rx", ms=10)
    b.set_xlabel(f"system pressure {unit_of('pressure', units)}")
    b.set_ylabel(f"peak contact pressure {unit_of('pressure', units)}")
    b.set_title("seal: peak above the system pressure")
    b.legend(fontsize=8)
    c.plot(ps, [r["plate_zone_end"] for r in rows], "o-", label="plate zone end (deformed)")
    c.axhline(wall, color="k", ls="--", label=f"groove wall x = {wall:g}")
    c.set_xlabel(f"system pressure {unit_of('pressure', units)}")
    c.set_ylabel(f"x {unit_of('length', units)}")
    c.set_title("extrusion: zone end against the wall")
    c.legend(fontsize=8)
    for ax in (a, b, c):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=80)


def main():
    ap = script_parser(__doc__)
    ap.add_argument("study_dir", metavar="STUDY_DIR",
                    help="the output folder of `hpcontact study` (its runs/NN-label/ folders)")
    ap.add_argument("--plate", type=int, default=1, help="the plate's contact pair (default 1)")
    ap.add_argument("--groove", type=int, default=0, help="the groove's contact pair (default 0)")
    ap.add_argument("--units", help="LENGTH,FORCE written into the labels, e.g. mm,N")
    ap.add_argument("--out", help="PNG to write (default STUDY_DIR/seal.png)")
    args = ap.parse_args()
    folders = sorted(d for d in glob.glob(os.path.join(args.study_dir, "runs", "*"))
                     if os.path.isfile(os.path.join(d, "summary.json")))
    if not folders:
        sys.exit(f"plot_seal.py: {args.study_dir}: no run folder with a summary.json under runs/")
    rows = sorted((read_run(d, args.plate, args.groove) for d in folders), key=lambda r: r["p_s"])
    wall = sealed_side_wall(rows[0]["problem"], args.groove)
    try:
        units = chosen_units(args, rows[0]["summary"])
    except ValueError as e:
        sys.exit(f"plot_seal.py: {e}")
    print("p_s,peak_plate,peak_groove,plate_zone_end,leaks")
    for r in rows:
        print(f"{r['p_s']:g},{r['peak_plate']:.4f},{r['peak_groove']:.4f},"
              f"{r['plate_zone_end']:.4f},{str(r['leaks']).lower()}")
    p = onset(rows, wall)
    print(f"extrusion onset: p_s = {p:.4g}" if p is not None else
          f"extrusion onset: not reached (plate zone end below the wall x = {wall:g} in every run)")
    out = args.out or os.path.join(args.study_dir, "seal.png")
    draw(rows, wall, args.plate, units, out)
    print(out)


if __name__ == "__main__":
    main()
