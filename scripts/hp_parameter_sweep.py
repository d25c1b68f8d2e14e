#!/usr/bin/python3
"""The hp loop's parameters against its accuracy: DOF and the true pressure error per step.

    scripts/hp_parameter_sweep.py [--hpcontact build/hpcontact] [--case examples/hertz/hp.yaml]
                                  [--factors 0.1,0.15,...] [--min-degrees 1,2,3] [--steps 7]

runs the hp loop of the case for every factor × min_degree (fixed steps, no tolerance) and prints
a Markdown table: per run the DOF and the relative L2 error of the method's pressure against
the case's reference (summary.json adapt.history[].multiplier.e_L2_reference_percent) at each
step, then the fewest DOF that reached 1e-3 and 1e-4. examples/hertz/CONVERGENCE.md quotes it.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def run(hpcontact, case, out, factor, min_degree, steps):
    cmd = [hpcontact, "run", str(case), "--out", str(out), "-q", "--set", f"adapt.factor={factor}",
           "--set", f"adapt.min_degree={min_degree}", "--set", f"adapt.steps={steps}",
           "--set", "output.vtu=false"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed: {r.stderr.strip()}")
    s = json.loads((out / "summary.json").read_text())
    return [(h["dofs"], h["multiplier"]["e_L2_reference_percent"] / 100)
            for h in s["adapt"]["history"]]


def first_below(points, tol):
    return min((n for n, e in points if e <= tol), default=None)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=str(ROOT / "build" / "hpcontact"),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--case", default=str(ROOT / "examples" / "hertz" / "hp.yaml"),
                    help="an hp problem file with a reference curve (default %(default)s)")
    ap.add_argument("--factors", default="0.1,0.15,0.2,0.25,0.35,0.5",
                    help="adapt.factor values, comma-separated (default %(default)s)")
    ap.add_argument("--min-degrees", default="1,2,3",
                    help="adapt.min_degree values, comma-separated (default %(default)s)")
    ap.add_argument("--steps", type=int, default=7,
                    help="hp steps of every run (default %(default)s)")
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for f in args.factors.split(","):
            for m in args.min_degrees.split(","):
                pts = run(args.hpcontact, args.case, pathlib.Path(tmp) / f"f{f}m{m}", f, m, args.steps)
                rows.append((f, m, pts))
    print("| factor | min_degree | DOF: error per step (step 1 on) | DOF to 1e-3 | DOF to 1e-4 |")
    print("|---|---|---|---|---|")
    for f, m, pts in rows:
        steps = " ".join(f"{n}: {e:.1e}" for n, e in pts[1:])
        print(f"| {f} | {m} | {steps} | {first_below(pts[1:], 1e-3) or '–'} | "
              f"{first_below(pts[1:], 1e-4) or '–'} |")


if __name__ == "__main__":
    main()
