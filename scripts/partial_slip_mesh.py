#!/usr/bin/python3
"""Two equal cylinders pressed together and then sheared (Cattaneo–Mindlin partial slip),
written as an hpcontact problem file.

Half models: the lower half of the upper cylinder (centre (0, R)) and the upper half of the
lower one (centre (0, -R)), touching at the origin, each a structured grid of two mirrored
quarters (the Coons grid of scripts/hertz_mesh.py) with exact arcs, graded geometrically
along the contact arc towards the Hertz half width a (and, with --grade-at a c, towards the
stick-zone half width c = a sqrt(1 - Q / (mu P)) too), the lower body the upper one's mirror
image in y = 0 (the meshes match node for node). Plane strain, exact contact between the
bodies (the upper one carries the multipliers), Coulomb friction.

Load path (solver.stages): stage 1 presses the upper body's cut (its diameter y = R) down by
--displacement (uy; the lower cut held, uy = 0), stage 2 applies the tangential force Q as a
uniform shear traction on the upper cut (+x) and on the lower cut (-x), uy still held: the
problem is symmetric under the half turn about the origin, and one node of the lower cut
(its centre, ux = 0) removes the pair's free sliding; it carries no force. Q is the stage's
resultant exactly; P is what the pressing gives (summary.json's normal_force); --displacement
defaults to an estimate of the approach for --force.

    partial_slip_mesh.py --force 700 > small-load.yaml           # b/R = 0.02
    partial_slip_mesh.py --force 70000 > seed-load.yaml          # the seed's P, b/R = 0.2
    partial_slip_mesh.py --force 700 --grade-at a c --degree 6   # a node at the stick-slip point
"""
import argparse
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hertz_mesh  # noqa: E402  (the quarter's Coons grid, the number format)

CORNER_ANGLE = hertz_mesh.CORNER_ANGLE


def hertz_half_width(radius, force, E, nu):
    """a of two equal cylinders, plane strain: sqrt(4 P R* / (pi E*)), R* = R/2, E* = E'/2."""
    return math.sqrt(4 * force * radius * (1 - nu ** 2) / (math.pi * E))


def approach(radius, force, E, nu, a):
    """An estimate of the cut's displacement for P (the 2-D approach depends on the bodies'
    size): each half disc shortens by about (1 - nu²) P / (pi E) (2 ln(4R/a) - 1), half of the
    diametral compression of a disc between two Hertz contacts (Johnson §5.6)."""
    return 2 * (1 - nu ** 2) * force / (math.pi * E) * (2 * math.log(4 * radius / a) - 1)


def growing(length, h0, ratio):
    """Sizes growing from h0 by about `ratio` per element adding up to length (at least two):
    hertz_mesh.growing with the count that ratio needs."""
    n = max(2, math.ceil(math.log(length / h0 * (ratio - 1) + 1) / math.log(ratio) - 0.3))
    return hertz_mesh.growing(length, n, h0)


def graded_points(targets, factor, layers, end):
    """Points on [0, 2 t_max] graded geometrically (ratio factor, `layers` layers) towards each
    target from both sides (between two targets each gets half the distance), then growing
    sizes (ratio about 1/factor) up to end."""
    ext = [0.0] + sorted(targets) + [2 * max(targets)]
    pts = {0.0, ext[-1]}
    for i in range(1, len(ext) - 1):
        t = ext[i]
        hl = (t - ext[i - 1]) / (2 if i > 1 else 1)
        hr = (ext[i + 1] - t) / (2 if i < len(ext) - 2 else 1)
        pts.add(t)
        for k in range(layers + 1):
            pts.add(t - hl * factor ** k)
            pts.add(t + hr * factor ** k)
    pts = sorted(round(p, 14) for p in pts)
    h_last = pts[-1] - pts[-2]
    for h in growing(end - pts[-1], h_last, 1 / factor):
        pts.append(pts[-1] + h)
    pts[-1] = end
    return pts


def depth_points(first, factor, layers, radius):
    """y of the nodes on x = 0: layers from first·factor^layers growing by 1/factor up to
    first, then growing sizes (ratio about 1/factor) to the cut y = R."""
    ys = [0.0] + [first * factor ** k for k in range(layers, -1, -1)]
    for h in growing(radius - ys[-1], ys[-1] - ys[-2], 1 / factor):
        ys.append(ys[-1] + h)
    ys[-1] = radius
    return ys


def half_disc(radius, bottom_x, left_y):
    """Nodes, counter-clockwise quads, contact-arc edges (with the x of their ends), other arc
    edges and cut edges of the lower half of the disc about (0, R): the quarter x >= 0 of
    hertz_mesh.build and its mirror image in x = 0, sharing the nodes on x = 0."""
    hertz_mesh.R = radius
    ny = len(left_y) - 1
    # the right arc (C to (R, R)) in equal parts: the grading stays at the contact
    right_t = [k / ny for k in range(ny + 1)]
    nodes, quads, bottom, right, left, top = hertz_mesh.build(bottom_x, left_y, ny, right_t)
    on_axis = {n for e in left for n in e}
    offset = max(nodes)
    mirror = {n: (n if n in on_axis else n + offset) for n in nodes}
    all_nodes = dict(nodes)
    for n, (x, y) in nodes.items():
        if n not in on_axis:
            all_nodes[mirror[n]] = (-x, y)
    all_quads = dict(quads)
    qoff = max(quads)
    for k, (a, b, c, d) in quads.items():
        # counter-clockwise from the bottom left: edge 1 (vertices 1 -> 2) is the one towards
        # the contact in every element, parametrised in +x (see body_lines)
        all_quads[k + qoff] = (mirror[b], mirror[a], mirror[d], mirror[c])
    m = lambda edges: [(mirror[b], mirror[a]) for a, b in edges]  # noqa: E731
    contact = list(reversed(m(bottom))) + bottom       # from -C to C along the arc
    arcs = right + m(right)
    cut = list(reversed(m(top))) + top
    # Number the nodes row by row from x = -C to C: the program orients an edge from its lower
    # node index to the higher, and so the contact tangent (see examples/partial-slip/README.md);
    # mirrored ids would turn it round at x = 0.
    nx = len(bottom_x) - 1
    row = lambda n: (n - 1) // (nx + 1)  # noqa: E731  (hertz_mesh.build's nid(i, j))
    order = sorted(all_nodes, key=lambda n: (row(n if n <= offset else n - offset), all_nodes[n][0]))
    new = {n: k + 1 for k, n in enumerate(order)}
    all_nodes = {new[n]: all_nodes[n] for n in order}
    all_quads = {k: tuple(new[n] for n in q) for k, q in sorted(all_quads.items())}
    r = lambda edges: [(new[a], new[b]) for a, b in edges]  # noqa: E731
    return all_nodes, all_quads, r(contact), r(arcs), r(cut)


def polar_half_disc(radius, first, ratio, sectors, outer, inner=()):
    """Nodes, counter-clockwise quads, contact-arc edges, other arc edges and cut edges of the
    lower half of the disc about (0, R), meshed in rings about the contact point (the origin):
    rings at the `inner` radii (each below `first`: e.g. the stick zone's c), then radii
    first · ratio^k up to `outer` · R, each ring cut into `sectors` (even) elements between its
    two points on the arc; a core of three elements inside the first ring, and one layer from
    the last ring to the cut (the cut in `sectors` equal parts). Elements keep their shape (no
    slivers) from the contact zone to the cut, unlike the structured grid. Every boundary edge
    on the circle is an exact arc; the contact edges are the core's two, the inner rings' and
    the ring beyond `first`. Each element's first edge is its edge on the circle, if it has one,
    in +x; the circle's nodes are numbered first, in x, as in half_disc. ValueError when the
    ring after `first` would lie beyond `outer` · R (contact edges ending at `first`)."""
    R = radius
    if any(not 0 < r < first for r in inner):
        raise ValueError(f"inner rings {list(inner)} must lie between 0 and a = {first:.4g}")
    radii = sorted(inner) + [first]
    while radii[-1] * ratio <= outer * R:
        radii.append(radii[-1] * ratio)
    if len(radii) < len(inner) + 2:
        # one ring: the contact edges (the core's) would end at `first`, where the zone ends
        raise ValueError(f"the second ring, --ring-ratio × a = {first * ratio:.4g}, lies beyond "
                         f"R/2 = {outer * R:.4g}, and the contact edges would end at a = "
                         f"{first:.4g}, where the contact zone ends; a smaller --ring-ratio (at "
                         f"most {outer * R / first:.3g}) or --mesh structured")

    def ring(r):
        y = r * r / (2 * R)           # where the ring meets the circle x² + (y - R)² = R²
        tb = math.atan2(y, math.sqrt(r * r - y * y))
        return [(r * math.cos(f), r * math.sin(f))
                for f in (math.pi - tb - (math.pi - 2 * tb) * j / sectors for j in range(sectors + 1))]

    pts = [ring(r) for r in radii]
    K, m = len(radii) - 1, sectors
    nodes, ids = {}, {}

    def nid(key, xy):
        if key not in ids:
            ids[key] = len(nodes) + 1
            nodes[ids[key]] = xy
        return ids[key]

    # the circle's nodes first, in x: the left ring ends outwards-in, the origin, the right ones
    on_circle = [("P", k, 0) for k in range(K, -1, -1)] + [("O",)] + [("P", k, m) for k in range(K + 1)]
    circle = [nid(key, (0.0, 0.0) if key == ("O",) else pts[key[1]][key[2]]) for key in on_circle]
    P = lambda k, j: nid(("P", k, j), pts[k][j])  # noqa: E731
    O = nid(("O",), (0.0, 0.0))
    C = nid(("C",), (0.0, radii[0] / 2))
    Q = lambda j: nid(("Q", j), (-R + 2 * R * j / m if 2 * j != m else 0.0, R))  # noqa: E731
    quads = {}

    def quad(*v):
        quads[len(quads) + 1] = v

    # the core: the two elements on the circle, [P0, O, C, P1] and [O, Pm, Pm-1, C], and the
    # polygon C, Pm-1, ..., P1 left between them cut into quads [C, Pj+2, Pj+1, Pj] (m even)
    quad(P(0, 0), O, C, P(0, 1))
    quad(O, P(0, m), P(0, m - 1), C)
    for j in range(m - 3, 0, -2):
        quad(C, P(0, j + 2), P(0, j + 1), P(0, j))
    for k in range(K):
        for j in range(m):
            if j == 0:
                quad(P(k + 1, 0), P(k, 0), P(k, 1), P(k + 1, 1))
            elif j == m - 1:
                quad(P(k, m), P(k + 1, m), P(k + 1, m - 1), P(k, m - 1))
            else:
                quad(P(k, j), P(k, j + 1), P(k + 1, j + 1), P(k + 1, j))
    for j in range(m):
        if j == 0:
            quad(Q(0), P(K, 0), P(K, 1), Q(1))
        elif j == m - 1:
            quad(P(K, m), Q(m), Q(m - 1), P(K, m - 1))
        else:
            quad(P(K, j), P(K, j + 1), Q(j + 1), Q(j))
    edges = list(zip(circle, circle[1:]))
    contact = edges[K - 1 - len(inner):K + 3 + len(inner)]
    arcs = [e for e in edges if e not in contact] + [(Q(0), circle[0]), (circle[-1], Q(m))]
    cut = [(Q(j), Q(j + 1)) for j in range(m)]
    return nodes, quads, contact, arcs, cut


def body_lines(name, radius, E, nu, nodes, quads, contact_edges, arcs, cut, sign, constraints,
               loads, shift=0.0):
    """The body's YAML lines; sign = +1 for the upper body (as meshed), -1 for its mirror image
    in y = 0 (y negated, the quads' orientation restored).

    Every element's first edge (vertex 1 -> 2) faces the contact, so the contact edges share
    one direction of their reference parameter: between two bodies the program takes the
    friction tangent from the other body's edge parametrisation (contact/point_gap.cpp), and
    edges of opposite parameter directions turn it round from one edge to the next (the
    tangential multiplier of the node between them then acts against itself)."""
    num = hertz_mesh.num
    fmt = lambda v: repr(round(v, 15) + 0.0)  # noqa: E731
    out = [f"  - name: {name}", f"    material: {{E: {num(E)}, nu: {num(nu)}, plane: strain}}",
           "    nodes:"]
    out += [f"      {k}: [{fmt(x)}, {fmt(sign * y + shift)}]" for k, (x, y) in nodes.items()]
    out.append("    elements:")
    for k, (a, b, c, d) in quads.items():
        # the mirror image counter-clockwise from the top right: edge 1 still towards the contact
        q = (a, b, c, d) if sign > 0 else (b, a, d, c)
        out.append(f"      {k}: [{', '.join(map(str, q))}]")
    out.append("    curves:")
    out += [f"      - {{nodes: [{a}, {b}], arc: {{center: [0, {num(sign * radius + shift)}], "
            f"radius: {num(radius)}}}}}" for a, b in contact_edges + arcs]
    es = lambda edges: ", ".join(f"[{a}, {b}]" for a, b in edges)  # noqa: E731
    out += ["    edge_sets:", f"      contact: [{es(contact_edges)}]", f"      cut: [{es(cut)}]",
            "    constraints:", *constraints, *(["    loads:", *loads] if loads else [])]
    return out


def carried_zone(ap, run, radius, E, nu, mu):
    """(a, c) of Cattaneo–Mindlin for the normal and tangential force pair 0 of the run in
    folder `run` carried (its summary.json); ap.error naming the file when it has none or when
    the shear is beyond mu P."""
    path = os.path.join(run, "summary.json")
    try:
        with open(path) as f:
            pair = json.load(f)["contact_pairs"][0]
        P, Q = float(pair["normal_force"]), abs(float(pair["tangential_force"]))
    except (OSError, ValueError, KeyError, IndexError, TypeError) as e:
        ap.error(f"--carried: {path}: no normal_force and tangential_force of pair 0 ({e})")
    if not (P > 0 and Q < mu * P):
        ap.error(f"--carried: {path}: P = {P:.6g}, Q = {Q:.6g}: needs P > 0 and Q < mu P = {mu * P:.6g}")
    a = hertz_half_width(radius, P, E, nu)
    return a, a * math.sqrt(1 - Q / (mu * P))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--radius", type=float, default=10.0, help="R of both cylinders (default %(default)s)")
    ap.add_argument("--E", type=float, default=210000.0, help="Young's modulus (default %(default)s)")
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio (default %(default)s)")
    ap.add_argument("--force", type=float, default=700.0,
                    help="normal force P per unit length the pressing aims at (default %(default)s: b/R = 0.02)")
    ap.add_argument("--displacement", type=float,
                    help="the upper cut's prescribed uy (downwards); default: the estimate for --force")
    ap.add_argument("--overlap", type=float,
                    help="start with the upper body moved down by this much, a part of the approach "
                         "(default: 1/20 of it): contact at one point leaves the upper body free "
                         "in x in the first iteration (the program refuses a singular tangent)")
    ap.add_argument("--mu", type=float, default=0.3, help="Coulomb friction coefficient (default %(default)s)")
    ap.add_argument("--ratio", type=float, default=0.5,
                    help="Q / (mu P) of the tangential force, P = --force (default %(default)s)")
    ap.add_argument("--grade-at", nargs="+", choices=["a", "c"], default=["a"],
                    help="grade the contact arc towards a (Hertz) and/or c (stick-slip point, "
                         "for --ratio); polar: c adds a ring at c (default: a)")
    ap.add_argument("--carried", metavar="RUN",
                    help="place a and c where Cattaneo-Mindlin puts them for the forces a run of "
                         "this problem carried (RUN/summary.json: normal_force and "
                         "tangential_force of pair 0) instead of --force and --ratio's; the "
                         "displacements stay those --force and --shear-displacement give")
    ap.add_argument("--factor", type=float, default=0.3, help="size ratio per layer (default %(default)s)")
    ap.add_argument("--layers", type=int, default=2, help="layers on each side of a grading point (default %(default)s)")
    ap.add_argument("--degree", type=int, default=4, help="p-version degree (default %(default)s)")
    ap.add_argument("--steps", type=int, default=2, help="load steps of the shearing stage (default %(default)s)")
    ap.add_argument("--shear-displacement", type=float,
                    help="shear by moving the cuts instead of a traction: the upper cut by +D/2 in x, the "
                         "lower by -D/2 (each held in x from the start, so neither an overlap nor a pinned "
                         "node is needed: --overlap defaults to 0); Q is then what the run carries "
                         "(summary.json tangential_force)")
    ap.add_argument("--case", default="partial-slip", help="the file's case name (default %(default)s)")
    ap.add_argument("--mesh", choices=["structured", "polar"], default="structured",
                    help="structured: the Coons grid graded along the arc (--grade-at, --factor, "
                         "--layers); polar: rings about the contact point (--ring-ratio, --sectors), "
                         "a start for hp (default %(default)s)")
    ap.add_argument("--ring-ratio", type=float, default=3.0,
                    help="polar: ratio of consecutive ring radii, the first at a (default %(default)s)")
    ap.add_argument("--sectors", type=int, default=4,
                    help="polar: elements per ring, even, at least 4 (default %(default)s)")
    ap.add_argument("--hp-tolerance", type=float,
                    help="add adapt: {method: hp, tolerance: T}: hp to this relative L2 error of the "
                         "contact traction (pressure and shear)")
    ap.add_argument("--hp-steps", type=int,
                    help="add adapt: {method: hp, steps: N}: N hp steps (with --hp-tolerance the most)")
    args = ap.parse_args()
    if not (args.radius > 0 and args.E > 0 and -1 < args.nu < 0.5 and args.force > 0
            and args.mu > 0 and 0 < args.ratio < 1 and 0 < args.factor < 1 and args.layers >= 0):
        ap.error("needs --radius, --E, --force, --mu > 0, -1 < --nu < 0.5, 0 < --ratio < 1, "
                 "0 < --factor < 1, --layers >= 0")
    R = args.radius
    a = hertz_half_width(R, args.force, args.E, args.nu)
    c = a * math.sqrt(1 - args.ratio)
    a_mesh, c_mesh = (a, c) if args.carried is None else carried_zone(ap, args.carried, R, args.E, args.nu, args.mu)
    xc = R * math.sin(CORNER_ANGLE)
    if not 2 * a < 0.8 * xc:
        ap.error(f"--force too large: 2a = {2 * a:.3g} must stay below {0.8 * xc:.3g}")
    delta = args.displacement if args.displacement is not None else approach(R, args.force, args.E, args.nu, a)
    if args.overlap is None:
        args.overlap = delta / 20 if args.shear_displacement is None else 0.0
    Q = args.ratio * args.mu * args.force
    if args.mesh == "polar":
        if not (args.ring_ratio > 1 and args.sectors >= 4 and args.sectors % 2 == 0):
            ap.error("--ring-ratio must be > 1 and --sectors even and at least 4")
        try:
            nodes, quads, contact, arcs, cut = polar_half_disc(R, a_mesh, args.ring_ratio, args.sectors, 0.5,
                                                              [c_mesh] if "c" in args.grade_at else [])
        except ValueError as e:
            ap.error(f"--mesh polar at this load: {e}")
        grading = (f"rings about the contact point {'at c, ' if 'c' in args.grade_at else ''}from a, "
                   f"ratio {hertz_mesh.num(args.ring_ratio)}, {args.sectors} sectors")
    else:
        targets = sorted({"a": a_mesh, "c": c_mesh}[g] for g in set(args.grade_at))
        bottom_x = graded_points(targets, args.factor, args.layers, xc)
        left_y = depth_points(min(targets), args.factor, args.layers, R)
        nodes, quads, contact, arcs, cut = half_disc(R, bottom_x, left_y)
        # the contact edges within 2a; the arc's other edges stay exact arcs
        near = [e for e in contact if max(abs(nodes[e[0]][0]), abs(nodes[e[1]][0])) <= 2 * a_mesh + 1e-12]
        arcs = arcs + [e for e in contact if e not in near]
        contact = near
        grading = f"graded towards {', '.join(args.grade_at)}"

    centre = next(n for n, (x, y) in nodes.items() if x == 0.0 and y == R)
    num = hertz_mesh.num
    shear = lambda s: f"      - {{edges: [cut], traction: [{s}, 0], resultant: {num(Q)}}}"  # noqa: E731
    out = [f"# Generated by scripts/partial_slip_mesh.py {' '.join(sys.argv[1:])}",
           f"# Hertz a = {a:.6g} (b/R = {a / R:.3g}), stick zone c = {c:.6g} for Q = {num(Q)} "
           f"= {num(args.ratio)} mu P at P = {num(args.force)}; {grading}.",
           *([] if args.carried is None else
             [f"# The mesh's a = {a_mesh:.6g}, c = {c_mesh:.6g}: Cattaneo-Mindlin's for the forces {args.carried} carried."]),
           f"case: {args.case}",
           f"description: Partial slip of two equal cylinders R = {num(R)} mm, P = {num(args.force)} N/mm "
           f"then Q = {num(Q)} N/mm, mu = {num(args.mu)}, p = {args.degree}.",
           "", "bodies:"]
    if args.shear_displacement is None:
        upper_held = [f"      - {{edges: [cut], uy: {num(-(delta - args.overlap))}}}"]
        lower_held = ["      - {edges: [cut], uy: 0}", f"      - {{nodes: [{centre}], ux: 0}}"]
        upper_loads, lower_loads = [shear(1)], [shear(-1)]
        stages = ["    - {displacements: 1, loads: 0, steps: 1}",
                  f"    - {{displacements: 1, loads: 1, steps: {args.steps}}}"]
    else:
        half = num(args.shear_displacement / 2)
        upper_held = [f"      - {{edges: [cut], ux: {half}, uy: {num(-(delta - args.overlap))}}}"]
        lower_held = [f"      - {{edges: [cut], ux: -{half}, uy: 0}}"]
        upper_loads, lower_loads = [], []
        stages = ["    - {displacements_x: 0, displacements_y: 1, loads: 0, steps: 1}",
                  f"    - {{displacements_x: 1, displacements_y: 1, loads: 0, steps: {args.steps}}}"]
    out += body_lines("upper", R, args.E, args.nu, nodes, quads, contact, arcs, cut, +1,
                      upper_held, upper_loads, -args.overlap)
    out += body_lines("lower", R, args.E, args.nu, nodes, quads, contact, arcs, cut, -1,
                      lower_held, lower_loads)
    out += ["", "contact:", "  - body: upper", "    edges: [contact]",
            "    obstacle: {type: body, body: lower, edges: [contact]}",
            f"    friction: {{law: coulomb, mu: {num(args.mu)}}}", "",
            "discretization:", "  method: p", f"  degree: {args.degree}", "  condense: true", "",
            "solver:", "  stages:", *stages]
    if args.hp_tolerance is not None or args.hp_steps is not None:
        out += ["", "adapt:", "  method: hp"]
    if args.hp_tolerance is not None:
        if not 0 < args.hp_tolerance < 1:
            ap.error("--hp-tolerance must lie in (0, 1)")
        out += [f"  tolerance: {num(args.hp_tolerance)}"]
    if args.hp_steps is not None:
        if args.hp_steps < 1:
            ap.error("--hp-steps must be at least 1")
        out += [f"  steps: {args.hp_steps}"]
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
