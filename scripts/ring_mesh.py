#!/usr/bin/python3
"""Half-ring meshes (x >= 0) for the stiff axle in an elastic ring (seed §5.4, docs/cases.md §6).

The ring r_in <= r <= r_out around the origin is cut at theta = -90° and 90° (the symmetry line
x = 0); elements are annular sectors with exact arcs. `angles` are the element boundaries in
degrees from -90 to 90, `radii` the radial ones. Prints the bodies[0] mesh keys of a problem file:
nodes, elements, curves and the edge sets symmetry (x = 0), inner (r = r_in), outer (r = r_out).

  scripts/ring_mesh.py --angles -90 0 90 --radii 0.7 2.0
"""
import argparse
import math


def ring_mesh(angles, radii):
    nodes = {}
    ids = {}
    for j, r in enumerate(radii):
        for i, a in enumerate(angles):
            nid = 1 + j * len(angles) + i
            t = math.radians(a)
            x, y = r * math.cos(t), r * math.sin(t)
            nodes[nid] = (0.0 if abs(x) < 1e-15 else x, y)
            ids[(i, j)] = nid
    elements, curves = {}, []
    for j in range(len(radii) - 1):
        for i in range(len(angles) - 1):
            eid = 1 + j * (len(angles) - 1) + i
            elements[eid] = (ids[(i, j)], ids[(i, j + 1)], ids[(i + 1, j + 1)], ids[(i + 1, j)])  # counter-clockwise
    for j in (0, len(radii) - 1):
        for i in range(len(angles) - 1):
            curves.append((ids[(i, j)], ids[(i + 1, j)], radii[j]))
    for j in range(1, len(radii) - 1):
        for i in range(len(angles) - 1):
            curves.append((ids[(i, j)], ids[(i + 1, j)], radii[j]))
    last = len(angles) - 1
    symmetry = [(ids[(0, j)], ids[(0, j + 1)]) for j in range(len(radii) - 1)]
    symmetry += [(ids[(last, j)], ids[(last, j + 1)]) for j in range(len(radii) - 1)]
    inner = [(ids[(i, 0)], ids[(i + 1, 0)]) for i in range(len(angles) - 1)]
    outer = [(ids[(i, len(radii) - 1)], ids[(i + 1, len(radii) - 1)]) for i in range(len(angles) - 1)]
    return nodes, elements, curves, {"symmetry": symmetry, "inner": inner, "outer": outer}


def yaml_text(angles, radii, indent="    "):
    nodes, elements, curves, sets = ring_mesh(angles, radii)
    out = [f"{indent}nodes:"]
    out += [f"{indent}  {k}: [{x!r}, {y!r}]" for k, (x, y) in nodes.items()]
    out.append(f"{indent}elements:")
    out += [f"{indent}  {k}: [{a}, {b}, {c}, {d}]" for k, (a, b, c, d) in elements.items()]
    out.append(f"{indent}curves:")
    out += [f"{indent}  - {{nodes: [{a}, {b}], arc: {{center: [0, 0], radius: {r:g}}}}}"
            for a, b, r in curves]
    out.append(f"{indent}edge_sets:")
    for name, edges in sets.items():
        out.append(f"{indent}  {name}: [" + ", ".join(f"[{a}, {b}]" for a, b in edges) + "]")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--angles", type=float, nargs="+", required=True, help="element boundaries [deg], -90 .. 90")
    ap.add_argument("--radii", type=float, nargs="+", required=True, help="radial element boundaries")
    a = ap.parse_args()
    if a.angles[0] != -90 or a.angles[-1] != 90 or sorted(a.angles) != a.angles:
        ap.error("--angles must rise from -90 to 90")
    if sorted(a.radii) != a.radii or len(a.radii) < 2:
        ap.error("--radii must rise and have at least two values")
    print(yaml_text(a.angles, a.radii))


if __name__ == "__main__":
    main()
