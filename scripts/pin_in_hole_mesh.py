#!/usr/bin/python3
"""An elastic pin pressed into a slightly larger hole of an elastic plate (Persson's problem),
written as an hpcontact problem file: plane strain, frictionless, exact contact.

Half model (x >= 0, ux = 0 on x = 0). The pin, a disc of radius R with its centre at
(0, -clearance), touches the hole (radius R + clearance, centre at the origin) at its bottom
(0, -R - clearance) in the unloaded state; a rigid core of radius --core R is pushed down, the
push found by force control so that the contact carries --force per unit thickness on the whole
pin (the half model half of it). The pin is a half annulus from the core to R and the plate one
from R + clearance to --outer, held there (u = 0): --sectors elements around, --pin-layers and
--layers radially (graded geometrically), exact arcs. The pin carries the multipliers; the
contact edges are both bodies' arcs below the centre (the arc can reach 84.8 degrees from the
load line).

  pin_in_hole_mesh.py --force 817.43 > pin.yaml           # about 45 degrees (44.84 with the core)
  pin_in_hole_mesh.py --force 8038.6 --hp-tolerance 1e-3  # 75 degrees, hp to a tolerance

The closed form: src/hpcontact/analytic/pin_in_hole.hpp with pin_core_radius = --core R and
plate_outer_radius = --outer.
"""
import argparse
import math


def half_annulus(inner, outer, sectors, layers, centre_y=0.0):
    """The half annulus x >= 0 from `inner` to `outer` about (0, centre_y), `sectors` elements
    from -90 to 90 degrees and `layers` radially (graded geometrically); ids from 1. Edge sets:
    symmetry (x = 0), inner and outer (the whole arcs), inner_below (the inner arc below the
    centre), outer_below."""
    angles = [-90 + 180 * i / sectors for i in range(sectors + 1)]
    ratio = (outer / inner) ** (1 / layers)
    radii = [inner * ratio ** j for j in range(layers)] + [outer]
    nodes, ids = {}, {}
    for j, r in enumerate(radii):
        for i, a in enumerate(angles):
            nid = 1 + j * len(angles) + i
            t = math.radians(a)
            x = r * math.cos(t)
            nodes[nid] = (0.0 if abs(x) < 1e-12 * r else x, r * math.sin(t) + centre_y)
            ids[(i, j)] = nid
    elements = {}
    for j in range(layers):
        for i in range(sectors):
            elements[1 + j * sectors + i] = (ids[(i, j)], ids[(i, j + 1)], ids[(i + 1, j + 1)], ids[(i + 1, j)])
    curves = [(ids[(i, j)], ids[(i + 1, j)], radii[j]) for j in range(layers + 1) for i in range(sectors)]
    below = [i for i in range(sectors) if angles[i] < 0]
    sets = {"symmetry": [(ids[(0, j)], ids[(0, j + 1)]) for j in range(layers)] +
                        [(ids[(sectors, j)], ids[(sectors, j + 1)]) for j in range(layers)],
            "inner": [(ids[(i, 0)], ids[(i + 1, 0)]) for i in range(sectors)],
            "inner_below": [(ids[(i, 0)], ids[(i + 1, 0)]) for i in below],
            "outer": [(ids[(i, layers)], ids[(i + 1, layers)]) for i in range(sectors)],
            "outer_below": [(ids[(i, layers)], ids[(i + 1, layers)]) for i in below]}
    return nodes, elements, curves, sets


def body_text(name, material, nodes, elements, arcs, sets, constraints, extra=""):
    out = [f"  - name: {name}", f"    material: {material}", "    nodes:"]
    out += [f"      {k}: [{x!r}, {y!r}]" for k, (x, y) in nodes.items()]
    out.append("    elements:")
    out += [f"      {k}: [{a}, {b}, {c}, {d}]" for k, (a, b, c, d) in elements.items()]
    out.append("    curves:")
    out += [f"      - {{nodes: [{a}, {b}], arc: {{center: [{cx!r}, {cy!r}], radius: {r!r}}}}}"
            for a, b, (cx, cy), r in arcs]
    out.append("    edge_sets:")
    for set_name, edges in sets.items():
        out.append(f"      {set_name}: [" + ", ".join(f"[{a}, {b}]" for a, b in edges) + "]")
    out.append("    constraints:")
    out += [f"      - {c}" for c in constraints]
    return "\n".join(out) + extra


def problem(args):
    R, c = args.radius, args.clearance
    pin = half_annulus(args.core * R, R, args.sectors, args.pin_layers, -c)
    plate = half_annulus(R + c, args.outer, args.sectors, args.layers)
    material = f"{{E: {args.E!r}, nu: {args.nu!r}, plane: strain}}"
    pin_text = body_text("pin", material, pin[0], pin[1],
                         [(a, b, (0.0, -c), r) for a, b, r in pin[2]], pin[3],
                         ["{edges: [symmetry], ux: 0}", f"{{edges: [inner], ux: 0, uy: {-c!r}}}"])
    plate_text = body_text("plate", material, plate[0], plate[1],
                           [(a, b, (0.0, 0.0), r) for a, b, r in plate[2]], plate[3],
                           ["{edges: [symmetry], ux: 0}", "{edges: [outer], ux: 0, uy: 0}"])
    head = (f"# Persson's problem: a pin (R = {R:g}) pressed by {args.force:g} N/mm (on the whole pin; the half\n"
            f"# model carries half) through a rigid core of radius {args.core * R:g} into a hole of radius {R + c:g}\n"
            f"# in a plate held at r = {args.outer:g}, steel on steel, plane strain, frictionless, exact contact.\n"
            f"# Written by scripts/pin_in_hole_mesh.py; closed form: src/hpcontact/analytic/pin_in_hole.hpp with\n"
            f"# pin_core_radius {args.core * R:g} and plate_outer_radius {args.outer:g}.\n"
            f"case: {args.case}\n"
            f"description: Pin in a hole, R = {R:g}, clearance {c:g}, P = {args.force:g} N/mm, half model.\n"
            "bodies:\n")
    tail = ["contact:",
            "  - body: pin",
            "    edges: [outer_below]",
            "    obstacle: {type: body, body: plate, edges: [inner_below]}",
            "    normal_direction: [0, 1]          # the load's: normal_force is the pin's load",
            "discretization:",
            "  method: p",
            f"  degree: {args.degree}",
            "solver:",
            f"  load_steps: {args.steps}",
            f"  target_resultant: {{value: {args.force / 2!r}, component: y}}"]
    if args.hp_tolerance:
        tail += ["adapt:", "  method: hp", f"  tolerance: {args.hp_tolerance!r}"]
    return head + pin_text + "\n" + plate_text + "\n" + "\n".join(tail) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--radius", type=float, default=10.0, help="R, the pin's radius (default 10)")
    ap.add_argument("--clearance", type=float, default=0.01, help="the hole's radius minus R (default 0.01)")
    ap.add_argument("--outer", type=float, default=100.0, help="the plate's outer radius, held (default 100)")
    ap.add_argument("--E", type=float, default=210000.0, help="Young's modulus of both (default 210000)")
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio of both (default 0.3)")
    ap.add_argument("--force", type=float, required=True, help="P, the force on the whole pin per unit thickness")
    ap.add_argument("--core", type=float, default=0.2,
                    help="the radius of the pin's rigid core over R, moved by force control (default 0.2)")
    ap.add_argument("--pin-layers", type=int, default=2, help="the pin's elements radially (default 2)")
    ap.add_argument("--sectors", type=int, default=4, help="the plate's elements around (default 4)")
    ap.add_argument("--layers", type=int, default=3, help="the plate's elements radially (default 3)")
    ap.add_argument("--degree", type=int, default=4, help="the polynomial degree (default 4)")
    ap.add_argument("--steps", type=int, default=4, help="load steps (default 4)")
    ap.add_argument("--hp-tolerance", type=float, help="hp to this tolerance (default: no adaptivity)")
    ap.add_argument("--case", default="pin-in-hole", help="the case's name")
    args = ap.parse_args()
    if not (args.radius > 0 and args.clearance > 0 and args.outer > args.radius + args.clearance
            and args.force > 0 and 0 < args.core < 0.7 and args.sectors >= 2 and args.layers >= 1
            and args.pin_layers >= 1 and args.sectors % 2 == 0):
        ap.error("needs --radius, --clearance, --force > 0, --outer > radius + clearance, "
                 "0 < --core < 0.7, an even --sectors >= 2, --layers, --pin-layers >= 1")
    print(problem(args), end="")


if __name__ == "__main__":
    main()
