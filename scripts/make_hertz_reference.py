#!/usr/bin/python3
"""Builds the Hertz overkill reference: examples/hertz/reference.yaml and its pressure curve
examples/hertz/reference-pressure.csv.

The mesh is graded geometrically towards the end of the contact zone Γ* from both sides
(scripts/hertz_mesh.py graded), with a node on Γ*: the zone end is found by solving, moving the
grading point to the computed Γ*, and solving again until the two agree to --tol (the rp idea
of seed §4.7, done here by regenerating the mesh). The final run's pressure.csv becomes the
reference the p-, rp- and h-examples are measured against (contact[].compare.reference).

    scripts/make_hertz_reference.py --hpcontact build/hpcontact
"""
import argparse
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent


def source_commit():
    """The commit of the sources the reference is made with (its provenance; '-dirty' when the
    work tree has uncommitted changes, the commit that adds this file then holds them), or
    'unknown'."""
    r = subprocess.run(["git", "describe", "--always", "--dirty", "--abbrev=7"], cwd=HERE,
                       capture_output=True, text=True)
    return r.stdout.strip() if r.returncode == 0 else "unknown"


def mesh(at, degree, layers, factor, path):
    text = subprocess.run(
        [sys.executable, str(HERE / "hertz_mesh.py"), "graded", "--at", repr(at), "--degree",
         str(degree), "--layers", str(layers), "--factor", str(factor), "--case",
         "hertz-reference"], check=True, capture_output=True, text=True).stdout
    header = ("# Hertz overkill reference: the 2x2 problem of p5/p8/p15.yaml (same load and material,\n"
              "# exact contact enforcement) on a mesh graded towards the end of the contact zone, with\n"
              "# a node on it (found by scripts/make_hertz_reference.py). Its pressure.csv is\n"
              "# examples/hertz/reference-pressure.csv.\n"
              f"# Provenance: snapshot: {source_commit()} (this program's output, not an independent value); it is checked\n"
              "# against Hertz's peak pressure and Shtayerman's half width by tests/cli/test_hertz.py.\n")
    path.write_text(header + text)


def solve(hpcontact, case, out):
    subprocess.run([hpcontact, "run", str(case), "--out", str(out), "-q"], check=True)
    return json.loads((out / "summary.json").read_text())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=str(ROOT / "build" / "hpcontact"),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--degree", type=int, default=8, help="degree of every element (default %(default)s)")
    ap.add_argument("--layers", type=int, default=8,
                    help="graded layers on each side of Γ* (default %(default)s)")
    ap.add_argument("--factor", type=float, default=0.35,
                    help="size ratio per graded layer (default %(default)s)")
    ap.add_argument("--start", type=float, default=1.95, help="first guess of Γ*")
    ap.add_argument("--tol", type=float, default=1e-7, help="|Γ* - node| / R to stop")
    ap.add_argument("--max-iterations", type=int, default=20,
                    help="mesh regenerations at most (default %(default)s)")
    ap.add_argument("--out", default=str(ROOT / "examples" / "hertz"),
                    help="folder of reference.yaml and reference-pressure.csv (default %(default)s)")
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        at, prev = args.start, None
        for it in range(1, args.max_iterations + 1):
            case = tmp / "reference.yaml"
            mesh(at, args.degree, args.layers, args.factor, case)
            s = solve(args.hpcontact, case, tmp / "run")
            ends = [g[0] for g in s["contact"]["gamma_star"]]
            if len(ends) != 1:
                sys.exit(f"iteration {it}: expected one end of the contact zone, found {ends}")
            print(f"iteration {it}: node at {at:.10f}, Γ* at {ends[0]:.10f}, "
                  f"{s['dofs']} DOF, U = {s['strain_energy']:.8f}")
            f = ends[0] - at
            if abs(f) < args.tol * 10:
                break
            # secant on f(node) = Γ*(node) - node; the plain fixed point contracts slowly
            nxt = ends[0] if prev is None or prev[1] == f else at - f * (at - prev[0]) / (f - prev[1])
            prev, at = (at, f), nxt
        else:
            sys.exit(f"Γ* did not settle in {args.max_iterations} iterations")
        shutil.copy(case, out / "reference.yaml")
        shutil.copy(tmp / "run" / "pressure.csv", out / "reference-pressure.csv")
    print(f"wrote {out / 'reference.yaml'} and {out / 'reference-pressure.csv'}")


if __name__ == "__main__":
    main()
