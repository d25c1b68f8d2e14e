#!/usr/bin/python3
"""Convergence of the partial-slip example: in p (for each degree, and grading), or of the hp
loop to a tolerance (for each tolerance, at the first degree): write the problem with
scripts/partial_slip_mesh.py, run it, measure it with scripts/partial_slip_compare.py, and write
study.csv and study.md (a Markdown table, with the rate of the shear's error against DOF from the
row before: log(e1/e0) / log(N1/N0)) into --out. An hp run that does not reach its tolerance
(exit 1) is measured on the result it kept (last-good/) and marked so.

    partial_slip_study.py --hpcontact build/hpcontact --out out/partial-slip --degrees 2 3 4 5 6
    partial_slip_study.py --out out/ps-c --degrees 2 4 6 --mesh-args "--grade-at a c"
    partial_slip_study.py --out out/ps-hp --degrees 4 --tolerances 1e-2 3e-3 1e-3 \
        --mesh-args "--force 7 --layers 0 --factor 0.1"
    partial_slip_study.py --out out/ps-hp-steps --degrees 2 --hp-steps 1 2 3 4 \
        --mesh-args "--force 7 --layers 0 --factor 0.1"              # hp, rising degrees
    partial_slip_study.py ... --set adapt.stick_slip=false     # hp without the stick-slip points
"""
import argparse
import csv
import math
import os
import shlex
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import partial_slip_compare  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
COLUMNS = ["run", "p", "dofs", "P", "Q", "c_over_a", "shear_rel_L2", "pressure_rel_L2", "c_fe", "c",
           "c_rel_error", "slip_tv_ratio", "coulomb_ratio_max", "wall_time_s", "reached", "rate"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=os.path.join(HERE, "..", "build", "hpcontact"),
                    help="the program (default build/hpcontact)")
    ap.add_argument("--out", required=True, help="folder for the problem files, runs and tables")
    ap.add_argument("--degrees", type=int, nargs="+", default=[2, 3, 4, 5, 6],
                    help="the degrees p to run (default %(default)s)")
    ap.add_argument("--mesh-args", default="", help="further arguments of partial_slip_mesh.py, one string")
    ap.add_argument("--tolerances", type=float, nargs="+",
                    help="hp to each of these tolerances (partial_slip_mesh.py --hp-tolerance), at the "
                         "first of --degrees, instead of the p-version")
    ap.add_argument("--hp-steps", type=int, nargs="+",
                    help="hp with each of these numbers of steps (partial_slip_mesh.py --hp-steps; "
                         "rising degrees), at the first of --degrees, instead of the p-version")
    ap.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                    help="passed to every run (hpcontact run --set)")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    if args.tolerances:
        runs = [(f"tol{t:g}", args.degrees[0], ["--hp-tolerance", repr(t)]) for t in args.tolerances]
    elif args.hp_steps:
        runs = [(f"steps{k}", args.degrees[0], ["--hp-steps", str(k)]) for k in args.hp_steps]
    else:
        runs = [(f"p{p}", p, []) for p in args.degrees]
    sets = [a for kv in args.set for a in ("--set", kv)]
    rows = []
    for label, p, extra in runs:
        case = os.path.join(args.out, f"{label}.yaml")
        cmd = [sys.executable, os.path.join(HERE, "partial_slip_mesh.py"), "--degree", str(p),
               *shlex.split(args.mesh_args), *extra]
        with open(case, "w") as f:
            subprocess.run(cmd, stdout=f, check=True)
        run = os.path.join(args.out, label)
        t0 = time.time()
        r = subprocess.run([args.hpcontact, "run", case, "--out", run, "-q", *sets], capture_output=True, text=True)
        reached = r.returncode == 0
        if not reached:
            # an hp loop that stopped short of its tolerance keeps its best step in last-good/
            if not (args.tolerances and r.returncode == 1 and os.path.isdir(os.path.join(run, "last-good"))):
                sys.exit(f"{label}: {r.stderr}")
            run = os.path.join(run, "last-good")
        m, data = partial_slip_compare.measure(run)
        m["run"], m["p"], m["wall_time_s"], m["reached"] = label, p, time.time() - t0, reached
        m["rate"] = (math.log(m["shear_rel_L2"] / rows[-1]["shear_rel_L2"]) / math.log(m["dofs"] / rows[-1]["dofs"])
                     if rows and m["dofs"] != rows[-1]["dofs"] else float("nan"))
        partial_slip_compare.plot(data, os.path.join(args.out, f"{label}.png"), f"{label}, {m['dofs']} DOF")
        rows.append(m)
        print(" ".join(f"{k}={m[k]:.4g}" if isinstance(m[k], float) else f"{k}={m[k]}" for k in COLUMNS), flush=True)
    with open(os.path.join(args.out, "study.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        w.writerows([[m[k] for k in COLUMNS] for m in rows])
    with open(os.path.join(args.out, "study.md"), "w") as f:
        f.write("| run | p | DOF | shear e_L2 % | rate | pressure e_L2 % | c_FE / a | c / a | TV slip FE / exact | wall s |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|\n")
        for m in rows:
            label = m["run"] + ("" if m["reached"] else " (not reached)")
            rate = "" if math.isnan(m["rate"]) else f"{m['rate']:.2f}"
            f.write(f"| {label} | {m['p']} | {m['dofs']} | {100 * m['shear_rel_L2']:.3g} | {rate} "
                    f"| {100 * m['pressure_rel_L2']:.3g} | {m['c_fe'] / m['a']:.4f} | {m['c_over_a']:.4f} "
                    f"| {m['slip_tv_ratio']:.4f} | {m['wall_time_s']:.0f} |\n")


if __name__ == "__main__":
    main()
