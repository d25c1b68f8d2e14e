#!/usr/bin/python3
"""Runs the plate with a hole (examples/plate-hole) for a range of degrees and measures the
convergence of the strain energy.

The relative energy-norm error of degree p is e_p = sqrt(|U_ref - U_p| / U_ref) (seed eq. 4.3),
U_ref the energy of the same model at a high degree (--reference-degree), or of another model
(--reference-case, e.g. roller.yaml). Writes OUT/convergence.csv (degree, dofs, strain_energy,
energy_rel_error_percent) and OUT/convergence.png (error against DOF, log-log), prints the
table and the least-squares slopes of ln e against p and against sqrt(DOF) over --fit.

    scripts/plate_hole_study.py --hpcontact build/hpcontact --out results/plate-hole
    scripts/plate_hole_study.py --case examples/plate-hole/roller.yaml --out results/plate-hole-roller
"""
import argparse
import csv
import json
import math
import pathlib
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent


def degree_list(text):
    """'1-12' or '2,3,4' -> [1, ..., 12] or [2, 3, 4]."""
    if "-" in text:
        first, last = (int(v) for v in text.split("-"))
        return list(range(first, last + 1))
    return [int(v) for v in text.split(",")]


def solve(hpcontact, case, degree, out):
    """One run at the given degree; returns its summary.json (exits on failure)."""
    r = subprocess.run([hpcontact, "run", str(case), "--out", str(out), "-q",
                        "--set", f"discretization.degree={degree}"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{case} at p = {degree} failed:\n{r.stderr.strip()}")
    s = json.loads((out / "summary.json").read_text())
    if not s["converged"]:
        sys.exit(f"{case} at p = {degree} did not converge")
    return s


def fit_slope(xs, ys):
    """Least-squares slope of ys against xs."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=str(ROOT / "build" / "hpcontact"),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--case", default=str(ROOT / "examples" / "plate-hole" / "contact.yaml"),
                    help="problem file swept over the degrees (default %(default)s)")
    ap.add_argument("--degrees", type=degree_list, default=list(range(1, 13)),
                    help="degrees to run, '1-12' or '2,3,4' (default 1-12)")
    ap.add_argument("--reference-degree", type=int, default=14,
                    help="degree of the reference run (default 14)")
    ap.add_argument("--reference-case", default=None,
                    help="problem file of the reference run (default: --case)")
    ap.add_argument("--fit", type=degree_list, default=list(range(2, 7)),
                    help="degrees of the slope fits (default 2-6)")
    ap.add_argument("--out", default=str(ROOT / "results" / "plate-hole"),
                    help="output folder (default %(default)s)")
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    reference_case = args.reference_case or args.case

    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        ref = solve(args.hpcontact, reference_case, args.reference_degree, tmp / "reference")
        u_ref = ref["strain_energy"]
        rows = []
        for p in args.degrees:
            s = solve(args.hpcontact, args.case, p, tmp / f"p{p}")
            u = s["strain_energy"]
            rows.append((p, s["dofs"], u, 100 * math.sqrt(abs(u_ref - u) / u_ref)))

    with open(out / "convergence.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["degree", "dofs", "strain_energy", "energy_rel_error_percent"])
        for p, n, u, e in rows:
            w.writerow([p, n, repr(u), f"{e:.6e}"])

    print(f"{pathlib.Path(args.case).name}: reference {pathlib.Path(reference_case).name} "
          f"at p = {args.reference_degree}, {ref['dofs']} DOF, U_ref = {u_ref:.12g}")
    print(f"{'p':>3} {'DOF':>6} {'U':>20} {'e %':>12}")
    for p, n, u, e in rows:
        print(f"{p:>3} {n:>6} {u:>20.12f} {e:>12.4e}")

    fitted = [(p, n, e) for p, n, _, e in rows if p in args.fit and e > 0]
    if len(fitted) >= 2:
        slope_p = fit_slope([p for p, _, _ in fitted], [math.log(e) for _, _, e in fitted])
        slope_sqrt = fit_slope([math.sqrt(n) for _, n, _ in fitted],
                               [math.log(e) for _, _, e in fitted])
        print(f"p = {fitted[0][0]}..{fitted[-1][0]}: ln e against p, slope {slope_p:.3f} "
              f"(e falls by {math.exp(-slope_p):.2f} per degree); against sqrt(DOF), "
              f"slope {slope_sqrt:.3f}")
        print("log-log slopes between successive degrees (algebraic convergence: constant):")
        for (p0, n0, e0), (p1, n1, e1) in zip(fitted, fitted[1:]):
            print(f"  p = {p0}->{p1}: {math.log(e1 / e0) / math.log(n1 / n0):.3f}")

    fig, ax = plt.subplots(figsize=(6, 4.5))
    shown = [(n, e) for _, n, _, e in rows if e > 0]
    ax.loglog([n for n, _ in shown], [e for _, e in shown], "o-", label=pathlib.Path(args.case).name)
    for p, n, _, e in rows:
        if e > 0:
            ax.annotate(f"p={p}", (n, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("relative error in energy norm [%]")
    ax.set_title(f"plate with a hole, 4 p-elements; reference: p = {args.reference_degree}",
                 fontsize=10)
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=9)
    fig.tight_layout()
    fig.savefig(out / "convergence.png", dpi=120)
    print(f"wrote {out / 'convergence.csv'} and {out / 'convergence.png'}")


if __name__ == "__main__":
    main()
