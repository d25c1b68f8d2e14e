#!/usr/bin/python3
"""The tutorial's p-convergence study: runs punch.yaml at several degrees (p-version, and the
rp-version with --rp), one `hpcontact run --set discretization.degree=N` each, and tabulates
their summary.json figures.

usage: p_study.py [--hpcontact build/hpcontact] [--out results/tutorial-study]
                  [--degrees 2 3 ... 12] [--rp 4 6 8 10 12]

Writes OUT/<method>-p<N>/ (each run's results), OUT/study.csv, OUT/study.md and OUT/study.png
(the relative L2 error of the contact pressure against reference-pressure.csv over DOF).
"""
import argparse
import csv
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CASE = os.path.join(HERE, "punch.yaml")
COLUMNS = ["method", "p", "dofs", "strain_energy", "half_width", "p_max", "e_L2_reference_percent",
           "e_L2_reference_multiplier_percent", "e_L2_shtayerman_percent", "rp_iterations",
           "newton_iterations", "wall_time_s"]


def run(hpcontact, out, p, rp):
    args = [hpcontact, "run", CASE, "--out", out, "-q",
            "--set", f"discretization.degree={p}",
            "--set", "contact[0].compare.reference=reference-pressure.csv"]
    if rp:
        args += ["--set", "adapt.method=rp"]
    subprocess.run(args, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    c = s["contact"]
    return {"method": "rp" if rp else "p", "p": p, "dofs": s["dofs"],
            "strain_energy": s["strain_energy"], "half_width": c["half_width"], "p_max": c["p_max"],
            "e_L2_reference_percent": c["e_L2_reference_percent"],
            "e_L2_reference_multiplier_percent": c.get("penalty_traction", c.get("multiplier"))["e_L2_reference_percent"],
            "e_L2_shtayerman_percent": c["e_L2_shtayerman_percent"],
            "rp_iterations": s["adapt"]["iterations"] if rp else "",
            "newton_iterations": s["newton_iterations"], "wall_time_s": s["wall_time_s"]}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("--hpcontact", default="build/hpcontact",
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--out", default="results/tutorial-study", help="output folder (default %(default)s)")
    ap.add_argument("--degrees", type=int, nargs="+", default=list(range(2, 13)),
                    help="degrees of the p-version runs (default 2 ... 12)")
    ap.add_argument("--rp", type=int, nargs="*", default=[4, 6, 8, 10, 12],
                    help="degrees of the rp-version runs (default 4 6 8 10 12; none: no rp runs)")
    args = ap.parse_args(argv)
    rows = []
    for rp, degrees in ((False, args.degrees), (True, args.rp)):
        for p in degrees:
            name = f"{'rp' if rp else 'p'}-p{p}"
            rows.append(run(args.hpcontact, os.path.join(args.out, name), p, rp))
            print(f"{name}: {rows[-1]['dofs']} DOF, e_L2 vs reference "
                  f"{rows[-1]['e_L2_reference_percent']:.3f} %")
    with open(os.path.join(args.out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(args.out, "study.md"), "w") as f:
        f.write("| method | p | DOF | U | half width | p_max | e_L2 vs ref., stresses [%] "
                "| e_L2 vs ref., multiplier [%] | rp relocations |\n")
        f.write("|---|---:|---:|---:|---:|---:|---:|---:|---:|\n")
        for r in rows:
            f.write(f"| {r['method']} | {r['p']} | {r['dofs']} | {r['strain_energy']:.4f} | "
                    f"{r['half_width']:.4f} | {r['p_max']:.0f} | {r['e_L2_reference_percent']:.3f} | "
                    f"{r['e_L2_reference_multiplier_percent']:.2f} | {r['rp_iterations']} |\n")
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for method, colour in (("p", "C0"), ("rp", "C1")):
        rs = [r for r in rows if r["method"] == method]
        if not rs:
            continue
        n = [r["dofs"] for r in rs]
        ax.loglog(n, [r["e_L2_reference_percent"] for r in rs], "o-", color=colour,
                  label=f"{method}-version, pressure from stresses")
        ax.loglog(n, [r["e_L2_reference_multiplier_percent"] for r in rs], "s--", color=colour,
                  mfc="none", lw=0.8, label=f"{method}-version, multiplier")
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("e_L2 of the pressure vs reference [%]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    ax.set_title("punch.yaml: p = 2...12 on four elements", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "study.png"), dpi=100)
    print(f"wrote {os.path.join(args.out, 'study.md')} and study.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
