#!/usr/bin/python3
"""The hp loop to a tolerance with goal-oriented degrees: where it stops, and how accurate it is.

    scripts/hp_goal_sweep.py [--hpcontact build/hpcontact] [--case examples/hertz/hp-tolerance.yaml]
                             [--tolerances 1e-3,1e-4] [--factors 0.1,0.15,0.2,0.25]
                             [--spaces trunk,tensor] [--degrees goal,rising]

runs the case's loop to each tolerance for every degree rule × shape space × factor and prints a
Markdown table: the steps taken, the DOF of the result, its estimated error and its true error
(the relative L2 error of the method's pressure against the case's reference, summary.json
contact.multiplier.e_L2_reference_percent), and the estimate against the true error over every
step. examples/hertz/CONVERGENCE.md quotes it.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent


def run(hpcontact, case, out, tolerance, degree, space, factor):
    cmd = [hpcontact, "run", str(case), "--out", str(out), "-q", "--set", f"adapt.tolerance={tolerance}",
           "--set", f"adapt.degree={degree}", "--set", f"discretization.space={space}",
           "--set", f"adapt.factor={factor}", "--set", "output.vtu=false"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    folder = out if r.returncode == 0 else out / "last-good"
    if not (folder / "summary.json").exists():
        sys.exit(f"{' '.join(cmd)} failed: {r.stderr.strip()}")
    s = json.loads((folder / "summary.json").read_text())
    hist = s["adapt"]["history"]
    ratios = [h["estimated_error"]["pressure_rel_L2"] / (h["multiplier"]["e_L2_reference_percent"] / 100)
              for h in hist]
    return {"ok": r.returncode == 0, "steps": s["adapt"]["result_step"], "dofs": s["dofs"],
            "estimate": s["adapt"]["estimated_error"]["pressure_rel_L2"],
            "true": s["contact"]["multiplier"]["e_L2_reference_percent"] / 100,
            "ratio": (min(ratios), max(ratios))}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=str(ROOT / "build" / "hpcontact"),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--case", default=str(ROOT / "examples" / "hertz" / "hp-tolerance.yaml"),
                    help="an hp problem file with a tolerance and a reference curve (default %(default)s)")
    ap.add_argument("--tolerances", default="1e-3,1e-4", help="adapt.tolerance values (default %(default)s)")
    ap.add_argument("--factors", default="0.1,0.15,0.2,0.25", help="adapt.factor values (default %(default)s)")
    ap.add_argument("--spaces", default="trunk,tensor", help="discretization.space values (default %(default)s)")
    ap.add_argument("--degrees", default="goal,rising", help="adapt.degree values (default %(default)s)")
    args = ap.parse_args()
    print("| tolerance | degree | space | factor | steps | DOF | estimated | true | estimate / true, every step |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for t in args.tolerances.split(","):
            for d in args.degrees.split(","):
                for sp in args.spaces.split(","):
                    for f in args.factors.split(","):
                        r = run(args.hpcontact, args.case, pathlib.Path(tmp) / f"{t}{d}{sp}{f}", t, d, sp, f)
                        dofs = f"{r['dofs']}" if r["ok"] else f"{r['dofs']} (not reached)"
                        print(f"| {t} | {d} | {sp} | {f} | {r['steps']} | {dofs} | {r['estimate']:.2g} | "
                              f"{r['true']:.2g} | {r['ratio'][0]:.2f}–{r['ratio'][1]:.2f} |", flush=True)


if __name__ == "__main__":
    main()
