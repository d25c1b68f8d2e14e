#!/usr/bin/python3
"""A rigid sphere of exact spherical profile pressed into an elastic half-space (frictionless,
linear elasticity): the closed form (Segedin 1957; Sneddon 1965's relations for a punch of any
axisymmetric profile; Johnson, Contact Mechanics §5.2), Hertz beside it, an hpcontact problem
file of the same problem on a large cylinder, and a run's figures against both.

The profile is f(r) = R - sqrt(R^2 - r^2) (not Hertz's r^2 / (2 R)); E* = E / (1 - nu^2). A
punch of contact radius a is built from flat punches of radius c = 0 .. a (Mossakovskii), each
adding dp = E* d(delta) / (pi sqrt(c^2 - r^2)) and dF = 2 E* c d(delta), with the approach at
contact radius c (bounded pressure at r = c)

    delta(c) = c int_0^c f'(t) / sqrt(c^2 - t^2) dt = c atanh(c / R),

so that

    F(a)    = E* [(a^2 + R^2) atanh(a / R) - a R],
    p(r)    = (E* / pi) int_r^a delta'(c) / sqrt(c^2 - r^2) dc,
              delta'(c) = atanh(c / R) + c R / (R^2 - c^2),
    p(0)    = (E* / pi) [chi_2(a / R) + atanh(a / R)],  chi_2(x) = sum_k x^(2k+1) / (2k+1)^2.

With atanh x = x + x^3/3 + ... these are Hertz's a^3 = 3 F R / (4 E*), delta = a^2 / R,
p0 = 2 E* a / (pi R) to O((a/R)^2). All positions are those of the undeformed surface (linear
theory: the gap is u_z(r) - delta + f(r) at the undeformed radius r, the radial displacement
plays no part).

  sphere_indentation.py solution --a-over-R 0.2               # a, delta, F, p(0) and Hertz's
  sphere_indentation.py solution --force 5000 --pressure-csv p.csv
  sphere_indentation.py mesh --a-over-R 0.2 > sphere.yaml      # the hpcontact problem file
  sphere_indentation.py mesh --a-over-R 0.2 --nu 0.4999 --size 100 > incompressible.yaml
  sphere_indentation.py compare results/sphere                 # a run against both closed forms
  sphere_indentation.py explain results/sphere                 # ... and against the geometry's effects
"""
import argparse
import csv
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from flat_punch_mesh import Mesh  # noqa: E402  (nodes by position, quads counter-clockwise)


# ---------------------------------------------------------------------------------------------
# The closed forms


def e_star(E, nu):
    """The contact modulus of an elastic half-space against a rigid indenter."""
    return E / (1 - nu * nu)


def chi2(x):
    """Legendre's chi function chi_2(x) = sum_k x^(2k+1) / (2k+1)^2 = int_0^x atanh(t) / t dt
    (|x| < 1)."""
    total, k, term = 0.0, 0, x
    while True:
        add = term / (2 * k + 1) ** 2
        total += add
        if abs(add) < 1e-17 * abs(total):
            return total
        k += 1
        term *= x * x


def approach(a, R):
    """The approach delta of the exact sphere at contact radius a."""
    return a * math.atanh(a / R)


def force(a, R, Es):
    """The total force F of the exact sphere at contact radius a."""
    return Es * ((a * a + R * R) * math.atanh(a / R) - a * R)


def pressure_centre(a, R, Es):
    """p(0) of the exact sphere at contact radius a."""
    x = a / R
    return Es / math.pi * (chi2(x) + math.atanh(x))


def pressure(r, a, R, Es, points=64):
    """p(r) of the exact sphere at contact radius a (0 for r >= a): with c^2 = r^2 + s^2 the
    integral int_0^sqrt(a^2 - r^2) delta'(c) / c ds, whose integrand is smooth, by Gauss-Legendre."""
    r = np.atleast_1d(np.asarray(r, dtype=float))
    xg, wg = np.polynomial.legendre.leggauss(points)
    out = np.zeros_like(r)
    for i, ri in enumerate(r):
        if ri >= a:
            continue
        S = math.sqrt(a * a - ri * ri)
        s = 0.5 * S * (xg + 1)
        c = np.sqrt(ri * ri + s * s)
        d = np.arctanh(c / R) + c * R / (R * R - c * c)
        out[i] = Es / math.pi * 0.5 * S * np.sum(wg * d / c)
    return out


def contact_radius(F, R, Es):
    """The contact radius a of the exact sphere under the force F (bisection on F(a), which
    rises monotonically on 0 < a < R)."""
    lo, hi = 0.0, R * (1 - 1e-15)
    if force(hi, R, Es) < F:
        raise ValueError(f"F = {F} needs a contact radius beyond R = {R}")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if force(mid, R, Es) < F:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def hertz(F, R, Es):
    """Hertz's sphere on a half-space under the force F: a, delta, p0."""
    a = (3 * F * R / (4 * Es)) ** (1 / 3)
    return {"a": a, "delta": a * a / R, "p0": 3 * F / (2 * math.pi * a * a)}


def exact(F, R, Es):
    """The exact sphere under the force F: a, delta, p0."""
    a = contact_radius(F, R, Es)
    return {"a": a, "delta": approach(a, R), "p0": pressure_centre(a, R, Es)}


def _wallis(k):
    """int_0^(pi/2) sin^(2k-1) phi d phi."""
    v = 1.0
    for j in range(1, k):
        v *= 2 * j / (2 * j + 1)
    return v


def polynomial_profile(coef, F, Es, a_max):
    """A rigid punch of profile f(r) = sum_k coef[k-1] r^(2k) on the half-space under the force F
    (Sneddon's relations, term by term: delta(c) = sum c_k 2k J_k c^(2k), J_k the Wallis
    integral): its contact radius a (bisection on (0, a_max), where F(a) rises) and p(0)."""
    def Fa(a):
        return 2 * Es * sum(c * 2 * k * _wallis(k) * 2 * k * a ** (2 * k + 1) / (2 * k + 1)
                            for k, c in enumerate(coef, 1))
    lo, hi = 0.0, a_max
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if Fa(mid) < F else (lo, mid)
    a = 0.5 * (lo + hi)
    p0 = Es / math.pi * sum(c * 2 * k * _wallis(k) * 2 * k * a ** (2 * k - 1) / (2 * k - 1)
                            for k, c in enumerate(coef, 1))
    return a, p0


def even_fit(r, f, terms=5):
    """Least-squares coefficients of f(r) - f(0) in r^2, r^4, ..., r^(2 terms)."""
    A = np.array([[ri ** (2 * k) for k in range(1, terms + 1)] for ri in r])
    return np.linalg.lstsq(A, np.asarray(f) - f[0], rcond=None)[0]


def radial_traction_lift(X, x, traction, a, R, E, nu):
    """The surface's normal displacement (positive into the body) at the undeformed radii X of a
    half-space under the radial component of a traction along the sphere's normal,
    q = traction x / R outwards (x the deformed radius): u_z(r) = -(1 - 2 nu)(1 + nu) / E
    int_r^a q d rho (Johnson §3.5 by reciprocity with a ring of normal load). Zero at nu = 1/2."""
    rr = np.linspace(0, a, 20001)
    q = np.interp(rr, X, traction) * np.interp(rr, X, x) / R
    cum = np.concatenate([[0], np.cumsum(0.5 * (q[1:] + q[:-1]) * np.diff(rr))])
    return -(1 - 2 * nu) * (1 + nu) / E * np.interp(X, rr, cum[-1] - cum)


# ---------------------------------------------------------------------------------------------
# The problem file


def build_mesh(box, cells, size, ratio):
    """The meridian section [0, W] x [-W, 0] (W >= size): a box [0, box] x [-box, 0] of
    cells x cells squares at the contact, then L-shaped rings, each a copy of the box's boundary
    scaled by `ratio` about the origin (the contact's centre), until the box reaches `size`. The
    rings' elements are trapezoids between two rays from the origin (no needles)."""
    m = Mesh()
    h = box / cells
    for j in range(cells):
        for i in range(cells):
            m.quad((i * h, -j * h), ((i + 1) * h, -j * h), ((i + 1) * h, -(j + 1) * h), (i * h, -(j + 1) * h))
    # the box's boundary from the top surface (box, 0) round the corner to the axis (0, -box)
    boundary = [(box, -j * h) for j in range(cells)] + [(box - i * h, -box) for i in range(cells + 1)]
    L = box
    while L < size * (1 - 1e-12):
        g = min(ratio, size / L)
        for p, q in zip(boundary, boundary[1:]):
            m.quad(p, q, (g * q[0], g * q[1]), (g * p[0], g * p[1]))
        boundary = [(g * x, g * y) for x, y in boundary]
        L *= g
    W = L
    xs = sorted({x for (x, y) in m.nodes if abs(y) < 1e-12})
    top = [[m.node(x0, 0.0), m.node(x1, 0.0)] for x0, x1 in zip(xs, xs[1:])]
    ys = sorted({y for (x, y) in m.nodes if abs(x) < 1e-12}, reverse=True)
    axis = [[m.node(0.0, y0), m.node(0.0, y1)] for y0, y1 in zip(ys, ys[1:])]
    xb = sorted({x for (x, y) in m.nodes if abs(y + W) < 1e-9 * W})
    bottom = [[m.node(x0, -W), m.node(x1, -W)] for x0, x1 in zip(xb, xb[1:])]
    return m, W, top, axis, bottom


def problem_file(args):
    Es = e_star(args.E, args.nu)
    R = args.radius
    a = args.a_over_R * R
    F = force(a, R, Es)
    m, W, top, axis, bottom = build_mesh(args.box * a, args.cells, args.size * a, args.ratio)
    pairs = lambda edges: "[" + ", ".join(f"[{p}, {q}]" for p, q in edges) + "]"
    lines = [
        f"# Generated by scripts/sphere_indentation.py {' '.join(sys.argv[2:])}".rstrip(),
        "# A rigid sphere of exact profile (obstacle circle R, centred on the axis, touching at the",
        f"# origin) pressed into an elastic cylinder of radius and height {W:.6g} = {W / a:.4g} a",
        "# (axisymmetric: x = r, y = z), the bottom held (uy = 0), u_r = 0 on the axis, frictionless,",
        "# exact contact, force control to the exact-sphere force of the contact radius a:",
        f"# a/R = {args.a_over_R}, a = {a:.6g}, F = {F:.8g} (exact sphere on a half-space,",
        f"# p(0) = {pressure_centre(a, R, Es):.8g}; Hertz at that F: a = {hertz(F, R, Es)['a']:.6g},",
        f"# p0 = {hertz(F, R, Es)['p0']:.8g}).",
        f"case: sphere-indentation-{args.a_over_R:g}",
        f"description: Rigid sphere R = {R:g} on an elastic cylinder, a/R = {args.a_over_R:g}, nu = {args.nu:g}.",
        "bodies:",
        "  - name: cylinder",
        f"    material: {{E: {args.E:g}, nu: {args.nu:g}, plane: axisymmetric}}",
        "    nodes:",
    ]
    for (x, y), k in sorted(m.nodes.items(), key=lambda kv: kv[1]):
        lines.append(f"      {k}: [{x:.12g}, {y:.12g}]")
    lines.append("    elements:")
    for k, e in enumerate(m.elements, 1):
        lines.append(f"      {k}: [{', '.join(map(str, e))}]")
    lines += [
        "    edge_sets:",
        f"      top: {pairs(top)}",
        f"      axis: {pairs(axis)}",
        f"      bottom: {pairs(bottom)}",
        "    constraints:",
        "      - {edges: [axis], ux: 0}",
        "      - {edges: [bottom], uy: 0}",
        "contact:",
        "  - body: cylinder",
        "    edges: [top]",
        f"    obstacle: {{type: circle, center: [0, {R:.12g}], radius: {R:.12g}, "
        f"displacement: [0, {-1.5 * approach(a, R):.12g}]}}",
        "discretization:",
        "  method: p",
        f"  degree: {args.degree}",
        "  condense: true",
        "solver:",
        f"  target_resultant: {{value: {F:.12g}, component: y}}",
    ]
    if args.tolerance > 0:
        lines.append(f"adapt: {{method: hp, tolerance: {args.tolerance:g}}}")
    return "\n".join(lines) + "\n"


# ---------------------------------------------------------------------------------------------
# A run against the closed forms


def compare_run(out):
    """A run's force, p(0) and contact radius (undeformed and deformed) against the exact
    sphere and Hertz at the run's force, E and nu of its input."""
    import yaml  # Debian's python3-yaml
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(out, "input.yaml")) as f:
        inp = yaml.safe_load(f)
    mat = inp["bodies"][0]["material"]
    obstacle = inp["contact"][0]["obstacle"]
    Es, R = e_star(mat["E"], mat["nu"]), obstacle["radius"]
    c = s["contact"]
    with open(os.path.join(out, "contact.csv"), newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    centre = min(rows, key=lambda r: float(r["X"]))
    F = abs(c["resultant"][1])
    ex, hz = exact(F, R, Es), hertz(F, R, Es)
    end = max(c["gamma_star"], key=lambda p: p[0])
    end_deformed = max(c["gamma_star_deformed"], key=lambda p: p[0])
    run = {"F": F, "p0": float(centre["traction"]), "p0_pressure": float(centre["pressure"]),
           "p0_from_stress": float(centre["minus_sigma_nn"]), "pressure_max": c["pressure_max"],
           "a": end[0], "a_deformed": end_deformed[0], "dofs": s.get("dofs")}
    return {"run": run, "exact": ex, "hertz": hz,
            "p0_vs_exact_percent": 100 * (run["p0"] / ex["p0"] - 1),
            "p0_from_stress_vs_exact_percent": 100 * (run["p0_from_stress"] / ex["p0"] - 1),
            "p0_vs_hertz_percent": 100 * (run["p0"] / hz["p0"] - 1),
            "a_vs_exact_percent": 100 * (run["a"] / ex["a"] - 1),
            "a_deformed_vs_exact_percent": 100 * (run["a_deformed"] / ex["a"] - 1),
            "a_over_R": ex["a"] / R, "nu": mat["nu"]}


def explain_run(out):
    """The run's p(0) and contact radius against the half-space theory of three profiles, each
    the exact sphere with one more of the run's geometric effects (its own u_r and traction):
    the sphere met at the deformed radius, f(X + u_r); the surface lifted by the radial component
    of the traction along the sphere's normal (zero at nu = 1/2); both. The run's force F_y."""
    import yaml
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    with open(os.path.join(out, "input.yaml")) as f:
        inp = yaml.safe_load(f)
    mat = inp["bodies"][0]["material"]
    E, nu = mat["E"], mat["nu"]
    Es, R = e_star(E, nu), inp["contact"][0]["obstacle"]["radius"]
    c = s["contact"]
    F = abs(c["resultant"][1])
    with open(os.path.join(out, "contact.csv"), newline="") as f:
        rows = sorted(csv.DictReader(f), key=lambda r: float(r["X"]))
    X = np.array([float(r["X"]) for r in rows])
    x = np.array([float(r["x"]) for r in rows])
    lam = np.array([float(r["traction"]) for r in rows])
    a_run = max(p[0] for p in c["gamma_star"])
    inside = X < 1.05 * a_run
    sphere = lambda r: R - np.sqrt(np.clip(R * R - r * r, 0, None))
    lift = radial_traction_lift(X, x, lam, a_run, R, E, nu)
    ex = exact(F, R, Es)
    result = {"F": F, "nu": nu, "a_over_R": ex["a"] / R, "run": {"p0": lam[0], "a": a_run},
              "exact": {"p0": ex["p0"], "a": ex["a"]},
              "u_r_over_r_axis": (x[1] - X[1]) / X[1],
              "u_r_over_r_end": float(np.interp(a_run, X, (x - X) / np.maximum(X, 1e-300)))}
    for name, profile in (("deformed_radius", sphere(x)), ("radial_traction", sphere(X) + lift),
                          ("both", sphere(x) + lift)):
        a, p0 = polynomial_profile(even_fit(X[inside], profile[inside]), F, Es, 1.5 * a_run)
        result[name] = {"p0": p0, "a": a, "p0_vs_exact_percent": 100 * (p0 / ex["p0"] - 1),
                        "run_p0_vs_it_percent": 100 * (lam[0] / p0 - 1),
                        "run_a_vs_it_percent": 100 * (a_run / a - 1)}
    result["run_p0_vs_exact_percent"] = 100 * (lam[0] / ex["p0"] - 1)
    return result


# ---------------------------------------------------------------------------------------------


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True, help="what to do (each has its own --help)")

    def material(p):
        p.add_argument("--radius", type=float, default=10.0, help="sphere radius R (default 10)")
        p.add_argument("--E", type=float, default=210000.0, help="Young's modulus (default 210000)")
        p.add_argument("--nu", type=float, default=0.3, help="Poisson's ratio (default 0.3)")

    s = sub.add_parser("solution", help="the exact sphere and Hertz at one load")
    material(s)
    load = s.add_mutually_exclusive_group(required=True)
    load.add_argument("--force", type=float, help="the total force F")
    load.add_argument("--a-over-R", type=float, help="the exact sphere's contact radius over R")
    s.add_argument("--pressure-csv", help="write r, the exact sphere's p(r) and Hertz's at its force")

    m = sub.add_parser("mesh", help="the hpcontact problem file (stdout)")
    material(m)
    m.add_argument("--a-over-R", type=float, default=0.2, help="contact radius over R of the "
                   "exact sphere whose force the run is driven to (default 0.2)")
    m.add_argument("--size", type=float, default=50.0, help="cylinder radius and height over a (default 50)")
    m.add_argument("--box", type=float, default=2.0, help="the fine box's side over a (default 2)")
    m.add_argument("--cells", type=int, default=4, help="elements along the box's side (default 4)")
    m.add_argument("--ratio", type=float, default=2.0, help="growth of the rings outside the box (default 2)")
    m.add_argument("--degree", type=int, default=4, help="polynomial degree (default 4)")
    m.add_argument("--tolerance", type=float, default=1e-3,
                   help="adapt: {method: hp, tolerance} (default 1e-3; 0: no adaptation)")

    c = sub.add_parser("compare", help="a run's p(0), a and force against both closed forms")
    c.add_argument("out", help="the run's output folder (summary.json, contact.csv, input.yaml)")
    x = sub.add_parser("explain", help="a run's p(0) against the half-space theory with the run's "
                       "own radial displacement and traction direction put in, one at a time")
    x.add_argument("out", help="the run's output folder")

    args = ap.parse_args()
    if args.command == "solution":
        Es = e_star(args.E, args.nu)
        R = args.radius
        F = args.force if args.force is not None else force(args.a_over_R * R, R, Es)
        ex, hz = exact(F, R, Es), hertz(F, R, Es)
        print(f"F = {F:.10g}, E* = {Es:.10g}, R = {R:g}")
        print(f"exact sphere: a = {ex['a']:.10g} (a/R = {ex['a'] / R:.6g}), delta = {ex['delta']:.10g}, "
              f"p(0) = {ex['p0']:.10g}")
        print(f"Hertz:        a = {hz['a']:.10g} (a/R = {hz['a'] / R:.6g}), delta = {hz['delta']:.10g}, "
              f"p0 = {hz['p0']:.10g}")
        print(f"exact / Hertz - 1: a {100 * (ex['a'] / hz['a'] - 1):+.4f} %, delta "
              f"{100 * (ex['delta'] / hz['delta'] - 1):+.4f} %, p(0) {100 * (ex['p0'] / hz['p0'] - 1):+.4f} %")
        if args.pressure_csv:
            r = np.linspace(0, ex["a"], 201)
            p = pressure(r, ex["a"], R, Es)
            ph = hz["p0"] * np.sqrt(np.clip(1 - (r / hz["a"]) ** 2, 0, None))
            with open(args.pressure_csv, "w") as f:
                f.write("r,exact,hertz\n")
                for row in zip(r, p, ph):
                    f.write(",".join(f"{v:.12g}" for v in row) + "\n")
    elif args.command == "mesh":
        sys.stdout.write(problem_file(args))
    elif args.command == "compare":
        print(json.dumps(compare_run(args.out), indent=1))
    else:
        print(json.dumps(explain_run(args.out), indent=1, default=float))


if __name__ == "__main__":
    main()
