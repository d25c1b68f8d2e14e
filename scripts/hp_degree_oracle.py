#!/usr/bin/python3
"""How few DOF a mesh of the hp loop needs for an accuracy when its degrees are chosen knowing
the true error: a greedy search, the bound goal-oriented degrees are measured against.

    scripts/hp_degree_oracle.py MESH_YAML TOLERANCE [--hpcontact build/hpcontact]
                                [--case examples/hertz/hp.yaml] [--body cylinder] [--space trunk]

MESH_YAML is an adapted mesh an hp run wrote (its mesh.yaml: nodes, elements, curves, edge sets,
degrees). The elements are grouped by degree, by the side of Γ* (the contact zone's side or the
other) and by whether they have a contact edge; the far elements of the input mesh (ids 3 and 4
of the Hertz 2x2 mesh) form a group of their own. Starting from the mesh's degrees, each round
solves the case with every group's degree one higher and one lower (a p-version solve of the
mesh, no adaptivity) and takes the change that buys the most accuracy per DOF while the error is
above TOLERANCE, or saves the most DOF per accuracy lost while it stays below; it stops when no
change is left. The error is the true one: the relative L2 error of the method's pressure
against the case's reference (summary.json contact.multiplier.e_L2_reference_percent). Prints
each round and the final degrees. Each round is ~20 solves of the mesh (a minute or two).
"""
import argparse
import copy
import json
import pathlib
import subprocess
import sys
import tempfile

import yaml

ROOT = pathlib.Path(__file__).resolve().parent.parent


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesh", help="an adapted mesh.yaml")
    ap.add_argument("tolerance", type=float, help="the accuracy asked for (relative L2 of the pressure)")
    ap.add_argument("--hpcontact", default=str(ROOT / "build" / "hpcontact"),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--case", default=str(ROOT / "examples" / "hertz" / "hp.yaml"),
                    help="the problem the mesh was adapted for (default %(default)s)")
    ap.add_argument("--body", default="cylinder", help="the adapted body's name (default %(default)s)")
    ap.add_argument("--far", default="3,4",
                    help="ids of the input's elements beyond the layers, one group (default %(default)s)")
    ap.add_argument("--space", choices=["tensor", "trunk"], help="discretization.space (default: the case's)")
    args = ap.parse_args()

    case = yaml.safe_load(open(args.case))
    mesh = yaml.safe_load(open(args.mesh))[args.body]
    for contact in case["contact"]:
        if "compare" in contact and "reference" in contact["compare"]:
            contact["compare"]["reference"] = str((pathlib.Path(args.case).parent /
                                                   contact["compare"]["reference"]).resolve())
    case.pop("adapt", None)
    if args.space:
        case.setdefault("discretization", {})["space"] = args.space
    far = {int(i) for i in args.far.split(",")}
    elements = {int(k): v for k, v in mesh["elements"].items()}
    on_contact = {n for e in mesh["edge_sets"]["contact"] for n in e}
    start = {int(k): v[0] for k, v in mesh["degrees"].items()}

    def area(e):
        xy = [mesh["nodes"][n] for n in elements[e]]
        return abs(sum(xy[i][0] * xy[i - 1][1] - xy[i - 1][0] * xy[i][1] for i in range(4))) / 2

    # Γ*: the contact node at the corner of the smallest element; the zone lies on its left
    centre = min(on_contact, key=lambda n: min(area(e) for e, ns in elements.items() if n in ns))
    centre_x = mesh["nodes"][centre][0]

    def side(e):
        xs = [mesh["nodes"][n][0] for n in elements[e]]
        return "zone" if sum(xs) / 4 < centre_x else "out"
    groups = {}
    for e in elements:
        key = ("far",) if e in far else (start[e], side(e), sum(n in on_contact for n in elements[e]) >= 2)
        groups.setdefault(key, []).append(e)

    tmp = pathlib.Path(tempfile.mkdtemp())
    cache = {}

    def solve(degrees):
        key = tuple(sorted(degrees.items()))
        if key in cache:
            return cache[key]
        spec = copy.deepcopy(case)
        body = next(b for b in spec["bodies"] if b["name"] == args.body)
        for k in ("nodes", "elements", "curves", "edge_sets"):
            body[k] = mesh[k]
        body["degrees"] = {e: [p, p] for e, p in degrees.items()}
        f = tmp / f"case{len(cache)}.yaml"
        f.write_text(yaml.safe_dump(spec))
        out = tmp / f"out{len(cache)}"
        r = subprocess.run([args.hpcontact, "run", str(f), "--out", str(out), "-q", "--set",
                            "output.vtu=false"], capture_output=True, text=True)
        result = None
        if r.returncode == 0:
            s = json.loads((out / "summary.json").read_text())
            result = (s["dofs"], s["contact"]["multiplier"]["e_L2_reference_percent"] / 100)
        cache[key] = result
        return result

    current = dict(start)
    now = solve(current)
    print(f"start: {now[0]} DOF, error {now[1]:.3g}")
    seen = {tuple(sorted(current.items()))}
    while True:
        options = []
        for es in groups.values():
            for step in (1, -1):
                trial = dict(current)
                if any(not 1 <= trial[e] + step <= 30 for e in es):
                    continue
                for e in es:
                    trial[e] += step
                if tuple(sorted(trial.items())) in seen:
                    continue
                r = solve(trial)
                if r:
                    options.append((step, trial, r))
        if now[1] > args.tolerance:
            better = [o for o in options if o[0] > 0 and o[2][0] > now[0]]
            if not better:
                break
            step, trial, r = max(better, key=lambda o: (now[1] - o[2][1]) / (o[2][0] - now[0]))
        else:
            cheaper = [o for o in options if o[0] < 0 and o[2][1] <= args.tolerance and o[2][0] < now[0]]
            if not cheaper:
                break
            step, trial, r = min(cheaper, key=lambda o: (o[2][1] - now[1]) / (now[0] - o[2][0]))
        current, now = trial, r
        seen.add(tuple(sorted(current.items())))
        print(f"{'+' if step > 0 else '-'}1: {now[0]} DOF, error {now[1]:.3g}", flush=True)
    print(f"final: {now[0]} DOF, error {now[1]:.3g}")
    print("degrees:", dict(sorted(current.items())))


if __name__ == "__main__":
    sys.exit(main())
