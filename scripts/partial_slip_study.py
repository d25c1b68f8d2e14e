#!/usr/bin/python3
"""Convergence of the partial-slip example in p: for each degree (and grading), write the
problem with scripts/partial_slip_mesh.py, run it, measure it with scripts/partial_slip_compare.py,
and write study.csv and study.md (a Markdown table) into --out.

    partial_slip_study.py --hpcontact build/hpcontact --out out/partial-slip --degrees 2 3 4 5 6
    partial_slip_study.py --out out/ps-c --degrees 2 4 6 --mesh-args "--grade-at a c"
"""
import argparse
import csv
import os
import shlex
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import partial_slip_compare  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
COLUMNS = ["p", "dofs", "P", "Q", "c_over_a", "shear_rel_L2", "pressure_rel_L2", "c_fe", "c",
           "c_rel_error", "slip_tv_ratio", "coulomb_ratio_max", "wall_time_s"]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=os.path.join(HERE, "..", "build", "hpcontact"),
                    help="the program (default build/hpcontact)")
    ap.add_argument("--out", required=True, help="folder for the problem files, runs and tables")
    ap.add_argument("--degrees", type=int, nargs="+", default=[2, 3, 4, 5, 6],
                    help="the degrees p to run (default %(default)s)")
    ap.add_argument("--mesh-args", default="", help="further arguments of partial_slip_mesh.py, one string")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = []
    for p in args.degrees:
        case = os.path.join(args.out, f"p{p}.yaml")
        cmd = [sys.executable, os.path.join(HERE, "partial_slip_mesh.py"), "--degree", str(p),
               *shlex.split(args.mesh_args)]
        with open(case, "w") as f:
            subprocess.run(cmd, stdout=f, check=True)
        run = os.path.join(args.out, f"p{p}")
        t0 = time.time()
        r = subprocess.run([args.hpcontact, "run", case, "--out", run, "-q"], capture_output=True, text=True)
        if r.returncode != 0:
            sys.exit(f"p = {p}: {r.stderr}")
        m, data = partial_slip_compare.measure(run)
        m["p"], m["wall_time_s"] = p, time.time() - t0
        partial_slip_compare.plot(data, os.path.join(args.out, f"p{p}.png"), f"p = {p}, {m['dofs']} DOF")
        rows.append(m)
        print(" ".join(f"{k}={m[k]:.4g}" if isinstance(m[k], float) else f"{k}={m[k]}" for k in COLUMNS), flush=True)
    with open(os.path.join(args.out, "study.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(COLUMNS)
        w.writerows([[m[k] for k in COLUMNS] for m in rows])
    with open(os.path.join(args.out, "study.md"), "w") as f:
        f.write("| p | DOF | shear e_L2 % | pressure e_L2 % | c_FE / a | c / a | TV slip FE / exact | wall s |\n")
        f.write("|---|---|---|---|---|---|---|---|\n")
        for m in rows:
            f.write(f"| {m['p']} | {m['dofs']} | {100 * m['shear_rel_L2']:.3g} | {100 * m['pressure_rel_L2']:.3g} "
                    f"| {m['c_fe'] / m['a']:.4f} | {m['c_over_a']:.4f} | {m['slip_tv_ratio']:.4f} | {m['wall_time_s']:.0f} |\n")


if __name__ == "__main__":
    main()
