#!/usr/bin/python3
"""Why the axisymmetric O-ring differs from its plane-strain section without friction: runs
examples/o-ring/o-ring-axisymmetric.yaml and o-ring-plane-strain.yaml with Coulomb friction (as
given) and frictionless, and tabulates per run the plate force (the ring's per unit length of
its mid-circle, 2 pi 20 mm), the plates' radial force, the hoop force of the half section, the
radial shift of the cord's centre and the tilt of its vertical radius.

usage: o_ring_hoop.py [--hpcontact PATH] [--out DIR] [--set key=value ...]

The hoop force is N = ∫ sigma_zz da over the deformed half section (solution.vtu's sigma_zz:
the hoop stress sigma_theta of the ring; of the plane section the stress normal to its plane),
each sample cell's area times the mean of its corners' values. A
half ring cut along a meridian is held by the hoop forces on its two cuts and the radial
tractions on it: N = F_r / (2 pi), F_r the radial total of the plate's tractions (summary.json
contact.resultant[0]). Frictionless plates push only axially, so the ring's hoop force is zero;
the plane section has no such balance and carries the compressive sigma_zz that its
out-of-plane strain, held at zero, demands. The frictionless plane section is held in x at
the cord's centre (node 7; symmetry puts no force there).
The shift is u_r of the cord's centre (r = 20, z = 0), its hoop strain shift / 20; the tilt
the angle the radius from the cord's centre to the top (r = 20, z = 2) turns through,
positive outwards (the half model's mid-plane, held in z, cannot turn).
--set goes to every run (e.g. solver.load_steps=4). Exit status 1 if a run fails.
"""
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from hpc_run import default_hpcontact, read_vtu, run_case, script_parser  # noqa: E402

RING_RADIUS = 20.0  # the cord's centre, mm
CORD_RADIUS = 2.0
EXAMPLES = os.path.join(ROOT, "examples", "o-ring")
FRICTIONLESS = "contact[0].friction.law=none"
HELD_AT_CENTRE = "bodies[0].constraints=[{edges: [mid-plane], uy: 0}, {nodes: [7], ux: 0}]"
RUNS = {  # name: (problem file, --set of the run, axisymmetric)
    "axisymmetric, mu = 0.3": ("o-ring-axisymmetric.yaml", [], True),
    "axisymmetric, frictionless": ("o-ring-axisymmetric.yaml", [FRICTIONLESS], True),
    "plane strain, mu = 0.3": ("o-ring-plane-strain.yaml", [], False),
    "plane strain, frictionless": ("o-ring-plane-strain.yaml", [FRICTIONLESS, HELD_AT_CENTRE], False),
}


def section_integral(points, cells, displacement, values):
    """∫ values da over the deformed section: per sample cell its (shoelace) area times the mean
    of its corners' values."""
    total = 0.0
    for cell in cells:
        x = [(points[i][0] + displacement[i][0], points[i][1] + displacement[i][1]) for i in cell]
        area = 0.5 * sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(x, x[1:] + x[:1]))
        total += area * sum(values[i] for i in cell) / len(cell)
    return total


def displacement_at(points, displacement, where):
    """The displacement at the sample point at `where` (a vertex of the mesh; ValueError if no
    sample is there)."""
    best = min(range(len(points)), key=lambda i: math.dist(points[i], where))
    if math.dist(points[best], where) > 1e-9:
        raise ValueError(f"no sample point at {where} (nearest {tuple(points[best])})")
    return displacement[best]


def ring_figures(folder, summary, axisymmetric):
    """The table's figures of one run's results folder (solution.vtu) and summary.json."""
    points, cells, fields, _ = read_vtu(os.path.join(folder, "solution.vtu"))
    u = fields["displacement"]
    per_length = 2 * math.pi * RING_RADIUS if axisymmetric else 1.0
    centre = displacement_at(points, u, (RING_RADIUS, 0.0))
    top = displacement_at(points, u, (RING_RADIUS, CORD_RADIUS))
    contact = summary["contact"]
    return {"force_per_length": contact["normal_force"] / per_length,
            "radial_force": contact["resultant"][0],
            "hoop_force": section_integral(points, cells, u, fields["sigma_zz"]),
            "centre_shift": float(centre[0]),
            "tilt_degrees": math.degrees(math.atan2(top[0] - centre[0], CORD_RADIUS + top[1])),
            "converged": summary["converged"]}


def run_all(hpcontact, out, sets=()):
    """Every run of RUNS into out/<index>: {name: figures}; SystemExit naming a failed run."""
    table = {}
    for k, (name, (case, run_sets, axisymmetric)) in enumerate(RUNS.items()):
        folder = os.path.join(out, str(k))
        summary, error = run_case(hpcontact, os.path.join(EXAMPLES, case), folder,
                                  list(run_sets) + list(sets), vtu=True)
        if summary is None:
            sys.exit(f"o_ring_hoop.py: {name}: {error}")
        table[name] = ring_figures(folder, summary, axisymmetric)
    return table


def main(argv=None):
    parser = script_parser(__doc__)
    parser.add_argument("--hpcontact", default=default_hpcontact(),
                        help="the hpcontact program (default: %(default)s)")
    parser.add_argument("--out", default=os.path.join("results", "o-ring-hoop"),
                        help="folder of the four runs, out/0 ... out/3 (default: %(default)s)")
    parser.add_argument("--set", action="append", default=[], dest="sets", metavar="KEY=VALUE",
                        help="an input override given to every run (repeatable)")
    args = parser.parse_args(argv)
    table = run_all(args.hpcontact, args.out, args.sets)
    plane = table["plane strain, frictionless"]["force_per_length"]
    print(f"{'run':28} {'F/length':>9} {'vs plane':>8} {'F_r':>9} {'F_r/2pi':>8} {'N hoop':>8} "
          f"{'shift':>7} {'tilt':>6}")
    for name, f in table.items():
        print(f"{name:28} {f['force_per_length']:9.4f} {f['force_per_length'] / plane - 1:+8.2%} "
              f"{f['radial_force']:9.4f} {f['radial_force'] / (2 * math.pi):8.4f} "
              f"{f['hoop_force']:8.4f} {f['centre_shift']:7.4f} {f['tilt_degrees']:6.2f}")
    print("F/length: plate force per unit length of the mid-circle (plane: per unit thickness), "
          "N/mm; F_r: the plate's radial force (axisymmetric: total, N); N hoop: ∫ sigma_zz da "
          "over the half section, N; shift: u_r of the cord's centre, mm; tilt: degrees")


if __name__ == "__main__":
    main()
