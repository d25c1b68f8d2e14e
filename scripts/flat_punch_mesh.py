#!/usr/bin/python3
"""A rigid flat punch with sharp corners pressed onto a large elastic block (plane strain,
frictionless, exact contact), written as an hpcontact problem file: Sadowsky's problem.

Half model (x >= 0, ux = 0 on x = 0). The block is [0, W] x [-H, 0] (W = H = --size), held at
y = -H (uy = 0); its top edges from x = 0 to the punch's corner x = a are the contact edges,
against a plane obstacle y = 0 (normal (0, -1)) pushed down by force control until the half
model carries --force / 2.

The mesh is graded towards the corner C = (a, 0): rings of 4 elements about C (sectors of 45
degrees, straight edges) at radii a/2 ratio^k, k = 0 .. --layers, two elements at C itself; the
half disc of radius a/2 sits in the box [0, 2a] x [-a, 0] (four elements between them); the rest
of the block is a grid whose lines at x = a, 2a and y = -a grow geometrically to W and H
(--outer-layers), so that no element is a needle.

  flat_punch_mesh.py > punch.yaml                       # a = 1, W = H = 100, P = 100
  flat_punch_mesh.py --layers 6 --degree 10 > fine.yaml
  flat_punch_mesh.py --elastic-punch > elastic.yaml      # a steel punch on the block

Sadowsky's pressure on an elastic half-plane: p(x) = P / (pi sqrt(a^2 - x^2)), singular at the
corner as K d^(-1/2) with K = P / (pi sqrt(2 a)), d = a - x.
"""
import argparse
import math


class Mesh:
    def __init__(self):
        self.nodes, self.elements = {}, []

    def node(self, x, y):
        key = (round(x, 12), round(y, 12))
        if key not in self.nodes:
            self.nodes[key] = len(self.nodes) + 1
        return self.nodes[key]

    def quad(self, *points):
        """An element through the points in either order: stored counter-clockwise."""
        area = sum(p[0] * q[1] - q[0] * p[1] for p, q in zip(points, points[1:] + points[:1]))
        ids = [self.node(*p) for p in points]
        self.elements.append(ids if area > 0 else ids[::-1])


def geometric(start, end, steps):
    """start, start g, ..., end (steps intervals)."""
    g = (end / start) ** (1 / steps)
    return [start * g ** j for j in range(steps)] + [end]


def build(a, size, ratio, layers, outer_layers):
    m = Mesh()
    cx = a
    angles = [0, -45, -90, -135, -180]
    ring = lambda r, t: (cx + r * math.cos(math.radians(t)), r * math.sin(math.radians(t)))
    radii = [a / 2 * ratio ** k for k in range(layers + 1)]
    for r_out, r_in in zip(radii, radii[1:]):  # the rings about the corner
        for t0, t1 in zip(angles, angles[1:]):
            m.quad(ring(r_in, t0), ring(r_out, t0), ring(r_out, t1), ring(r_in, t1))
    r = radii[-1]
    m.quad((cx, 0.0), ring(r, 0), ring(r, -45), ring(r, -90))  # the two at the corner
    m.quad((cx, 0.0), ring(r, -90), ring(r, -135), ring(r, -180))
    box = [(2 * a, 0.0), (2 * a, -a), (a, -a), (0.0, -a), (0.0, 0.0)]  # the box about the half disc
    for i in range(4):
        m.quad(ring(radii[0], angles[i]), ring(radii[0], angles[i + 1]), box[i + 1], box[i])
    xs = [0.0, a] + geometric(2 * a, size, outer_layers)  # the grid outside the box
    ys = [0.0] + [-y for y in geometric(a, size, outer_layers)]
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            if j == 0 and i < 2:
                continue  # the box
            m.quad((xs[i], ys[j]), (xs[i + 1], ys[j]), (xs[i + 1], ys[j + 1]), (xs[i], ys[j + 1]))
    face_x = [0.0] + [a - rr for rr in radii] + [a]
    face = [[m.node(x0, 0.0), m.node(x1, 0.0)] for x0, x1 in zip(face_x, face_x[1:])]
    beyond = [a + rr for rr in reversed(radii)] + [2 * a]  # the top on to x = 2a
    top = face + [[m.node(x0, 0.0), m.node(x1, 0.0)] for x0, x1 in zip([a] + beyond, beyond)]
    symmetry = [[m.node(0.0, y0), m.node(0.0, y1)] for y0, y1 in zip(ys, ys[1:])]
    bottom = [[m.node(x0, -size), m.node(x1, -size)] for x0, x1 in zip(xs, xs[1:])]
    return m, face, top, symmetry, bottom


def rounded_punch(a, radius):
    """The points of a flat punch face y = 0 (from x = -a/2 to a) rounded beyond x = a by an arc
    of `radius` to 60 degrees, from the arc's end to the flat's (the block, below, on the left)."""
    arc = [(a + radius * math.sin(math.radians(t)), radius * (1 - math.cos(math.radians(t))))
           for t in range(60, 0, -5)]
    flat = [(a * (1 - k / 4), 0.0) for k in range(7)]
    return [[float(f"{x:.12g}"), float(f"{y:.12g}") + 0.0] for x, y in arc + flat]


def print_punch(a, ratio, E, nu):
    """The elastic punch [0, a] x [0, a]: a 4 x 4 grid graded towards its corner (a, 0), ux = 0 on
    x = 0, its top pushed down (force control finds how far)."""
    xs = [0.0, a / 2, a * (1 - ratio), a * (1 - ratio ** 2), a]
    ys = [0.0, a * ratio ** 2, a * ratio, a / 2, a]
    node = lambda i, j: 1 + j * len(xs) + i
    print("  - name: punch")
    print(f"    material: {{E: {E:g}, nu: {nu:g}, plane: strain}}")
    print("    nodes:")
    for j, y in enumerate(ys):
        for i, x in enumerate(xs):
            print(f"      {node(i, j)}: [{x:.17g}, {y:.17g}]")
    print("    elements:")
    eid = 1
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            print(f"      {eid}: [{node(i, j)}, {node(i + 1, j)}, {node(i + 1, j + 1)}, {node(i, j + 1)}]")
            eid += 1
    n = len(xs) - 1
    print(f"    edge_sets:")
    print(f"      bottom: {[[node(i, 0), node(i + 1, 0)] for i in range(n)]}")
    print(f"      axis: {[[node(0, j), node(0, j + 1)] for j in range(n)]}")
    print(f"      top: {[[node(i, n), node(i + 1, n)] for i in range(n)]}")
    print("    constraints:")
    print("      - {edges: [axis], ux: 0}")
    print("      - {edges: [top], uy: -0.001}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--half-width", type=float, default=1.0, help="a, the punch's half width")
    ap.add_argument("--size", type=float, default=100.0, help="W = H, the block's half width and depth")
    ap.add_argument("--force", type=float, default=100.0, help="P on the whole punch per unit thickness")
    ap.add_argument("--ratio", type=float, default=0.15, help="geometric grading ratio towards the corner")
    ap.add_argument("--layers", type=int, default=4, help="rings of elements about the corner")
    ap.add_argument("--outer-layers", type=int, default=4, help="grid lines from 2a to the block's edge")
    ap.add_argument("--degree", type=int, default=8, help="the polynomial degree p of every element")
    ap.add_argument("--E", type=float, default=210000.0, help="the block's Young's modulus")
    ap.add_argument("--nu", type=float, default=0.3, help="the block's Poisson's ratio")
    ap.add_argument("--rounded", type=float,
                    help="a rigid punch whose corners are rounded with this radius: a curve obstacle "
                         "(flat to x = a, then the arc to 60 degrees) against the block's top to x = 2a")
    ap.add_argument("--elastic-punch", action="store_true",
                    help="the punch an elastic body [0, a] x [0, a] of the block's material (a tensor "
                         "grid graded towards its corner, pushed down on its top), not a rigid plane")
    args = ap.parse_args()
    a = args.half_width
    m, face, top, symmetry, bottom = build(a, args.size, args.ratio, args.layers, args.outer_layers)
    print("# Generated by scripts/flat_punch_mesh.py " + " ".join(
        f"--{k.replace('_', '-')}" + ("" if v is True else f" {v}")
        for k, v in vars(args).items() if v is not False and v is not None))
    print("case: flat-punch")
    print(f"description: Rigid flat punch (half width {a:g}) on an elastic block, Sadowsky's problem, half model.")
    print("bodies:")
    print("  - name: block")
    print(f"    material: {{E: {args.E:g}, nu: {args.nu:g}, plane: strain}}")
    print("    nodes:")
    for (x, y), nid in sorted(m.nodes.items(), key=lambda kv: kv[1]):
        print(f"      {nid}: [{x + 0.0:.17g}, {y + 0.0:.17g}]")
    print("    elements:")
    for eid, ids in enumerate(m.elements, 1):
        print(f"      {eid}: {ids}")
    print("    edge_sets:")
    if args.rounded:  # the top on to 2a (no edge set ends at x = a: hp may move the node there)
        print(f"      top: {top}")
    else:
        print(f"      face: {face}")
    print(f"      symmetry: {symmetry}")
    print(f"      bottom: {bottom}")
    print("    constraints:")
    print("      - {edges: [symmetry], ux: 0}")
    print("      - {edges: [bottom], uy: 0}")
    if args.rounded:
        print("contact:")
        print("  - body: block")
        print("    edges: [top]")
        print(f"    obstacle: {{type: curve, points: {rounded_punch(a, args.rounded)}, displacement: [0, -0.001]}}")
    elif args.elastic_punch:
        print_punch(a, args.ratio, args.E, args.nu)
        print("contact:")
        print("  - body: punch")
        print("    edges: [bottom]")
        print("    obstacle: {type: body, body: block, edges: [face]}")
    else:
        print("contact:")
        print("  - body: block")
        print("    edges: [face]")
        print("    obstacle: {type: plane, point: [0, 0], normal: [0, -1], displacement: [0, -0.001]}")
    print(f"discretization: {{degree: {args.degree}}}")
    print(f"solver: {{target_resultant: {{value: {args.force / 2:g}, component: y}}}}")


if __name__ == "__main__":
    main()
