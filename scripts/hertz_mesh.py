#!/usr/bin/python3
"""Quarter-cylinder meshes for the Hertz benchmark (seed §5.2.2), written as hpcontact YAML.

The quarter x in [0, R], lower half of the circle of radius R centred at (0, R), is a
structured grid by transfinite (Coons) interpolation of its four sides: the arc from the bottom
point (0, 0) to a corner C (45 degrees) carries the contact, the arc from C to (R, R), the
centre plane y = R (uniform vertical displacement, force control to F/2) and the symmetry line
x = 0 (ux = 0). Arc edges are exact circles; the h-version uses them as isoparametric nodes.

Node positions along the contact arc are given by their x coordinates; presets make
quasi-uniform meshes (uniform: equal arcs, equal layers), meshes refined towards the contact
(refined: equal elements on x in [0, --zone], a fraction --fine of those along the arc, layers
of that size down to the depth --zone, growing geometrically beyond), and meshes graded
geometrically towards a point (graded: the end of the contact zone Γ*).

The one patch has a fourth corner at C on the smooth arc: the element there has an angle of
nearly 180° at C (far from the contact; not inverted, but the worst element of every mesh).

    hertz_mesh.py uniform --cells 18 18 --method h --element Q4 > mesh.yaml
    hertz_mesh.py refined --cells 15 21 --method h --element Q9 > refined.yaml
    hertz_mesh.py graded --at 1.93 --factor 0.5 --layers 4 --degree 10 > reference.yaml
    hertz_mesh.py uniform --cells 6 6 --radius 25 --E 70000 --nu 0.33 --force 2000 > alu.yaml

The cylinder (--radius, --E, --nu) and the load (--force on the whole cylinder) are arguments;
the defaults are the dissertation's case, and the points that depend on the zone (--at, --zone,
--contact-extent) default to multiples of Hertz's half width b of the case given.
"""
import argparse
import math
import sys

R = 10.0
CORNER_ANGLE = math.radians(45.0)  # C, measured from the bottom point around the centre


def arc_point(theta):
    """Point of the circle at angle theta from the bottom point (0, 0), counter-clockwise."""
    return (R * math.sin(theta), R - R * math.cos(theta))


def angle_of_x(x):
    return math.asin(x / R)


def build(bottom_x, left_y, right_n, right_t=None):
    """Nodes (dict id -> (x, y)) and quads of the Coons grid.

    bottom_x: x of the nodes on the contact arc from 0 to C; left_y: y of the nodes on the
    symmetry line from 0 to R (as many as right_n + 1); right_t: fractions in [0, 1] of the
    arc from C to (R, R) at which its nodes lie (default: those of the symmetry line, y / R).
    With its own right_t, node (i, j) uses the blended parameter t_j + s_i (t'_j - t_j), so the
    grid lines run from node j of the symmetry line to node j of the right arc (discrete
    transfinite interpolation); without, the grid is the same as before that option existed.
    """
    nx, ny = len(bottom_x) - 1, len(left_y) - 1
    assert right_n == ny
    xc = bottom_x[-1]
    th_c = angle_of_x(xc)
    bottom = [arc_point(angle_of_x(x)) for x in bottom_x]
    s = [x / xc for x in bottom_x]                 # parameter along bottom and top
    t = [y / R for y in left_y]                     # parameter along left and right
    left = [(0.0, y) for y in left_y]
    tr = t if right_t is None else list(right_t)
    assert len(tr) == ny + 1 and tr[0] == 0.0 and tr[-1] == 1.0
    right = [arc_point(th_c + (math.pi / 2 - th_c) * tj) for tj in tr]
    top = [(R * si, R) for si in s]
    p00, p10, p01, p11 = bottom[0], bottom[-1], top[0], top[-1]
    nodes = {}
    nid = lambda i, j: j * (nx + 1) + i + 1
    for j in range(ny + 1):
        for i in range(nx + 1):
            if j == 0:
                p = bottom[i]
            elif j == ny:
                p = top[i]
            elif i == 0:
                p = left[j]
            elif i == nx:
                p = right[j]
            else:
                si = s[i]
                tj = t[j] + si * (tr[j] - t[j])
                p = tuple((1 - tj) * bottom[i][k] + tj * top[i][k] + (1 - si) * left[j][k]
                          + si * right[j][k]
                          - ((1 - si) * (1 - tj) * p00[k] + si * (1 - tj) * p10[k]
                             + (1 - si) * tj * p01[k] + si * tj * p11[k]) for k in range(2))
            nodes[nid(i, j)] = p
    quads = {}
    for j in range(ny):
        for i in range(nx):
            quads[j * nx + i + 1] = (nid(i, j), nid(i + 1, j), nid(i + 1, j + 1), nid(i, j + 1))
    bottom_edges = [(nid(i, 0), nid(i + 1, 0)) for i in range(nx)]
    right_edges = [(nid(nx, j), nid(nx, j + 1)) for j in range(ny)]
    left_edges = [(nid(0, j), nid(0, j + 1)) for j in range(ny)]
    top_edges = [(nid(i, ny), nid(i + 1, ny)) for i in range(nx)]
    return nodes, quads, bottom_edges, right_edges, left_edges, top_edges


def mesh_lines(nodes, quads, arcs):
    """The `nodes`, `elements` and `curves` keys of a body in a problem file, as YAML lines
    indented for bodies[0] (after its "    nodes:" line): `arcs` are edges on the circle of
    radius R about (0, R)."""
    fmt = lambda v: repr(round(v, 15))  # noqa: E731
    out = [f"      {k}: [{fmt(x)}, {fmt(y)}]" for k, (x, y) in nodes.items()]
    out.append("    elements:")
    out += [f"      {k}: [{a}, {b}, {c}, {d}]" for k, (a, b, c, d) in quads.items()]
    out.append("    curves:")
    out += [f"      - {{nodes: [{a}, {b}], arc: {{center: [0, {fmt(R)}], radius: {fmt(R)}}}}}"
            for a, b in arcs]
    return out


def num(v):
    """v as the problem files write it: 10 rather than 10.0, 0.3 rather than 0.30000000000000004."""
    v = float(v)
    return str(int(v)) if v == int(v) and abs(v) < 1e15 else repr(round(v, 12))


def hertz_half_width(args):
    """b of Hertz's cylinder on a rigid plane, plane strain: √(4 F R (1 − ν²) / (π E))."""
    return math.sqrt(4 * args.force * R * (1 - args.nu ** 2) / (math.pi * args.E))


def yaml_text(args, bottom_x, left_y, comment, right_t=None):
    nodes, quads, bottom, right, left, top = build(bottom_x, left_y, len(left_y) - 1, right_t)
    contact = [e for e, x in zip(bottom, bottom_x) if x < args.contact_extent - 1e-12]
    out = [f"# {line}" for line in comment]
    out += [f"# Generated by scripts/hertz_mesh.py {' '.join(sys.argv[1:])}",
            f"case: {args.case}",
            f"description: Hertz contact, quarter cylinder R = {num(R)} mm, {len(quads)} elements, "
            f"{args.method}-version, F = {num(args.force)} N.",
            "", "bodies:", "  - name: cylinder",
            f"    material: {{E: {num(args.E)}, nu: {num(args.nu)}, plane: strain}}", "    nodes:"]
    out += mesh_lines(nodes, quads, bottom + right)
    es = lambda edges: ", ".join(f"[{a}, {b}]" for a, b in edges)
    out += ["    edge_sets:", f"      symmetry: [{es(left)}]", f"      centre: [{es(top)}]",
            f"      contact: [{es(contact)}]",
            "    constraints:", "      - {edges: [symmetry], ux: 0}",
            f"      - {{edges: [centre], uy: {num(-args.displacement)}}}", "",
            "contact:", "  - body: cylinder", "    edges: [contact]",
            "    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}",
            *(["    enforcement: penalty", f"    penalty: {args.penalty:.6g}".replace("e+0", "e")]
              if args.enforcement == "penalty" else []),
            "    quadrature: 50",
            f"    compare: {{radius: {num(R)}, force: {num(args.force)}" +
            (f", reference: {args.reference}" if args.reference else "") + "}", "",
            "discretization:", f"  method: {args.method}"]
    if args.method == "p":
        out += [f"  degree: {args.degree}", "  condense: true"]
    else:
        out += [f"  element: {args.element}"]
    out += ["", "solver:", f"  target_resultant: {{value: {num(args.force / 2)}, component: y}}"]
    return "\n".join(out) + "\n"


def uniform_points(a, b, n):
    return [a + (b - a) * k / n for k in range(n + 1)]


def growing(length, n, h0):
    """n sizes h0·q, h0·q², ..., h0·qⁿ adding up to length, q >= 1 (equal if n·h0 >= length)."""
    if n * h0 >= length:
        return [length / n] * n
    lo, hi = 1.0, 2.0
    while sum(h0 * hi ** k for k in range(1, n + 1)) < length:
        hi *= 2
    for _ in range(200):
        q = 0.5 * (lo + hi)
        lo, hi = (q, hi) if sum(h0 * q ** k for k in range(1, n + 1)) < length else (lo, q)
    sizes = [h0 * q ** k for k in range(1, n + 1)]
    return [h * length / sum(sizes) for h in sizes]


def refined(nx, ny, zone, fine):
    """Refined towards the contact zone: the arc x in [0, zone] in equal elements of size h0
    (round(fine·nx) of the nx elements along the arc), the symmetry line in layers of h0 down
    to the depth `zone`, both growing geometrically beyond (to C and to the centre plane). The
    right arc C -> (R, R) is divided uniformly (graded from C if the arc's last element is
    finer than that). Returns bottom x, left y, right fractions and the header comment."""
    lb = R * CORNER_ANGLE                      # arc length from the bottom point to C
    n1 = max(1, min(nx - 1, round(fine * nx)))
    a1 = R * angle_of_x(zone)
    h0 = a1 / n1
    arcs = [h0 * k for k in range(n1 + 1)]
    for h in growing(lb - a1, nx - n1, h0):
        arcs.append(arcs[-1] + h)
    bottom = [R * math.sin(a / R) for a in arcs[:-1]] + [R * math.sin(CORNER_ANGLE)]
    m1 = max(1, min(ny - 1, math.ceil(zone / h0 - 1e-9)))
    left = [h0 * k for k in range(m1 + 1)]
    depth = left[-1]
    for h in growing(R - depth, ny - m1, h0):
        left.append(left[-1] + h)
    left[-1] = R
    lr = R * (math.pi / 2 - CORNER_ANGLE)     # arc length from C to (R, R)
    first = arcs[-1] - arcs[-2]
    sizes = growing(lr, ny, first) if first < lr / ny else [lr / ny] * ny
    right_t = [0.0]
    for h in sizes:
        right_t.append(right_t[-1] + h / lr)
    right_t[-1] = 1.0
    comment = [f"{nx} x {ny} grid refined towards the contact zone: x in [0, {zone}] in {n1} "
               f"equal elements of {h0:.3f} along the arc,",
               f"layers of that size down to y = {depth:.3f}, growing geometrically beyond."]
    return bottom, left, right_t, comment


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("kind", choices=["uniform", "refined", "graded"],
                    help="uniform: equal arcs and layers; refined: fine towards the contact; "
                         "graded: geometric towards --at")
    ap.add_argument("--cells", type=int, nargs=2, default=[18, 18], metavar=("NX", "NY"),
                    help="elements along the contact arc and along the symmetry line")
    ap.add_argument("--radius", type=float, default=10.0, help="the cylinder's radius R (default %(default)s)")
    ap.add_argument("--E", type=float, default=210000.0, help="Young's modulus (default %(default)s)")
    ap.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio (default %(default)s)")
    ap.add_argument("--force", type=float, default=70000.0,
                    help="F on the whole cylinder per unit length; the quarter carries F/2 "
                         "(solver.target_resultant) (default %(default)s)")
    ap.add_argument("--displacement", type=float,
                    help="the centre plane's prescribed displacement the force control scales "
                         "(default 0.02 for the defaults, scaled by F/E)")
    ap.add_argument("--penalty", type=float,
                    help="--enforcement penalty: eps_N (default 1000 E, the dissertation's)")
    ap.add_argument("--at", type=float,
                    help="graded: the point graded towards (Γ*; default 0.982 b, b Hertz's half "
                         "width: 1.93 for the defaults)")
    ap.add_argument("--factor", type=float, default=0.5, help="graded: size ratio per layer")
    ap.add_argument("--layers", type=int, default=4, help="graded: layers on each side of --at")
    ap.add_argument("--zone", type=float,
                    help="refined: extent in x of the finely meshed contact zone (default 1.22 b: "
                         "2.4 for the defaults, b = 1.965)")
    ap.add_argument("--fine", type=float, default=0.6,
                    help="refined: fraction of the elements along the arc inside the zone")
    ap.add_argument("--method", choices=["p", "h"], default="p",
                    help="discretization.method of the file (default %(default)s)")
    ap.add_argument("--degree", type=int, default=8, help="p-version degree (default %(default)s)")
    ap.add_argument("--element", default="Q8", choices=["Q4", "Q8", "Q9"],
                    help="h-version element (default %(default)s)")
    ap.add_argument("--case", default="hertz-mesh", help="the file's case name (default %(default)s)")
    ap.add_argument("--enforcement", choices=["augmented-lagrangian", "penalty"],
                    default="augmented-lagrangian",
                    help="the contact's enforcement: exact (the program's default, no penalty "
                         "written) or the dissertation's penalty eps_N = 2.1e8 = 1000 E")
    ap.add_argument("--reference", help="compare.reference CSV to name in the file")
    ap.add_argument("--contact-extent", type=float,
                    help="arc edges starting below this x are contact edges (default 2.04 b: 4.0 "
                         "for the defaults)")
    args = ap.parse_args()
    global R
    if not (args.radius > 0 and args.E > 0 and -1 < args.nu < 0.5 and args.force > 0):
        ap.error("needs --radius > 0, --E > 0, -1 < --nu < 0.5 and --force > 0")
    R = args.radius
    b = hertz_half_width(args)
    # Defaults of the dissertation's case (R = 10, E = 210000, nu = 0.3, F = 70000, b = 1.965)
    # kept as they were; other cases scale them with b (and F/E for the displacement).
    default_case = (R, args.E, args.nu, args.force) == (10.0, 210000.0, 0.3, 70000.0)
    if args.at is None:
        args.at = 1.93 if default_case else 0.982 * b
    if args.zone is None:
        args.zone = 2.4 if default_case else 1.22 * b
    if args.contact_extent is None:
        args.contact_extent = 4.0 if default_case else 2.04 * b
    if args.displacement is None:
        args.displacement = 0.02 * (args.force / 70000.0) * (210000.0 / args.E)
    if args.penalty is None:
        args.penalty = 1000 * args.E
    if not 0 < args.at < R * math.sin(CORNER_ANGLE) / 2:
        ap.error(f"--at must lie in (0, {R * math.sin(CORNER_ANGLE) / 2:.4g}) (half way to the "
                 "45° corner of the contact arc)")
    xc = arc_point(CORNER_ANGLE)[0]
    nx, ny = args.cells
    right_t = None
    if args.kind == "uniform":
        bottom = [R * math.sin(CORNER_ANGLE * k / nx) for k in range(nx + 1)]
        left = uniform_points(0, R, ny)
        comment = [f"Quasi-uniform {nx} x {ny} grid."]
    elif args.kind == "refined":
        if not 0 < args.zone < 0.8 * xc or not 0 < args.fine < 1 or min(nx, ny) < 2:
            ap.error(f"refined needs 0 < --zone < {0.8 * xc:.2f}, 0 < --fine < 1, cells >= 2")
        bottom, left, right_t, comment = refined(nx, ny, args.zone, args.fine)
    else:
        a, f, L = args.at, args.factor, args.layers
        # Distances a·f^k from a on both sides: element sizes shrink by f towards a.
        bottom = [a - a * f ** k for k in range(L + 1)] + [a] + [a + a * f ** k for k in range(L, -1, -1)]
        bottom += uniform_points(2 * a, xc, 2)[1:]
        left = [0.0] + [a * f ** k for k in range(L, -1, -1)] + uniform_points(a, R, 3)[1:]
        left[-1] = R  # exactly, whatever the rounding of a + (R - a)
        comment = [f"Graded geometrically (factor {f}, {L} layers) towards x = {a} on the contact arc."]
    sys.stdout.write(yaml_text(args, bottom, left, comment, right_t))


if __name__ == "__main__":
    main()
