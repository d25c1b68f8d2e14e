#!/usr/bin/python3
"""A partial-slip run (examples/partial-slip/) against Cattaneo–Mindlin's closed form.

Reads the run's summary.json (P = normal_force and Q = tangential_force of pair 0) and
contact.csv (the multiplier nodes of the pair's own body), and measures, on force per unit
length along the common tangent (the tangential multiplier times the pressure's dS/ds):

- the shear q against q(x) = mu p0 [sqrt(1 - x²/a²) - (c/a) sqrt(1 - x²/c²)] (stick, |x| < c),
  mu p(x) (slip), c = a sqrt(1 - Q / (mu P)): the relative L2 error over the nodes in [-a, a]
  (the nodes are the contact edges' Gauss–Lobatto points: each edge's nodes integrate the
  polynomial through them in x exactly), and that of the pressure against Hertz's;
- the stick zone's ends from the nodes' states: the outermost stick node on each side and the
  first slip node beyond it, against ±c;
- the total variation of the shear over each slip zone (an oscillation indicator), against the
  closed form's over the same nodes;
- the Coulomb bound |t_T| <= mu t_N at every node (largest ratio), ∫ q dx and ∫ p dx, and
  the part of Q the pressure carries on the deformed, tilted interface (∫ p y' dx);
- the shear against Cattaneo–Mindlin's for the force it carries, ∫ q dx = Q − ∫ p y' dx
  (shear_rel_L2_carried, stick zone c_carried): the error without the tilt's coupling, which
  the linear theory leaves out (it grows with the load: 0.04 % of Q at b/R = 0.002).

- shear_rel_L2_uniform and pressure_rel_L2_uniform: one metric for the exact method and the
  penalty alike (the node-based figures above need multiplier nodes), on the same points for
  every run: the relative L2 error against Cattaneo–Mindlin's (and Hertz's) over
  s in [-1.5 a, 1.5 a], by the trapezoidal rule on 6001 uniform points, of each method's
  traction as its output defines it between its own points (contact.csv, the pair's own body):
  exact, the multipliers' polynomial through the Gauss–Lobatto nodes of each contact edge;
  penalty, linear between its Gauss points (50 per edge: halving them moves the p = 8,
  eps = 1000 E figure by 4e-4, so the full set's interpolation costs about a quarter of that).
  6001 points are within 5e-5 of 96001. Outside [-a, a] the closed forms are zero: a traction
  there counts as error. A penalty run reports P, Q, a, c and these figures.
- shear_rel_L2_own_points and pressure_rel_L2_own_points: each method read only where its
  contact law holds, by its own quadrature: exact, the multipliers at the Gauss–Lobatto nodes
  with the weights that integrate each edge's polynomial in s exactly; penalty, its tractions at
  the Gauss points (contact[].quadrature per edge) with the Gauss–Legendre weights of each edge's
  extent in s (found from its outermost points; s is nearly linear in the edge parameter: the
  points fit to 1e-3 of the extent). No interpolation between points enters.

- with --reference REF (a run of the same case on a much finer discretization: the model's own
  answer, which the half-space's closed forms are not exactly), the shear's and the pressure's
  relative L2 errors against it (shear_rel_L2_reference, pressure_rel_L2_reference): both
  tractions polynomials on their own contact edges, integrated piece by piece between the two
  meshes' edge ends.

    partial_slip_compare.py results/small-load                  # figures as JSON
    partial_slip_compare.py results/small-load --plot shear.png # and the plot
    partial_slip_compare.py results/ps-hp --reference results/ps-hp-3e-4
    partial_slip_compare.py results/ps-penalty                   # a penalty run: the uniform figures

E, nu and R are read from the run's input.yaml (the upper body's material and its contact
arcs' radius), mu from its friction.
"""
import argparse
import csv
import json
import math
import os
import sys

import numpy as np
import yaml


def closed_form(R_star, E_star, mu, P, Q):
    """(a, c, p0, pressure(x), shear(x)) of Cattaneo–Mindlin for two similar cylinders."""
    a = math.sqrt(4 * P * R_star / (math.pi * E_star))
    p0 = 2 * P / (math.pi * a)
    c = a * math.sqrt(max(0.0, 1 - Q / (mu * P)))
    ell = lambda x, w: np.sqrt(np.clip(1 - (np.asarray(x) / w) ** 2, 0, None)) if w > 0 else 0 * np.asarray(x)  # noqa: E731
    return a, c, p0, lambda x: p0 * ell(x, a), lambda x: mu * p0 * (ell(x, a) - c / a * ell(x, c))


def read_case(folder):
    """mu, R*, E*, the pair's body and the degree along the contact of the run (its input.yaml:
    both bodies' materials and contact arcs)."""
    spec = yaml.safe_load(open(os.path.join(folder, "input.yaml")))
    pair = spec["contact"][0]
    bodies = {b["name"]: b for b in spec["bodies"]}
    inv_E, curv = 0.0, 0.0
    for name in (pair["body"], pair["obstacle"]["body"]):
        m = bodies[name]["material"]
        inv_E += (1 - m["nu"] ** 2) / m["E"] if m.get("plane", "strain") == "strain" else 1 / m["E"]
        curv += 1 / bodies[name]["curves"][0]["arc"]["radius"]
    degree = spec["discretization"]["degree"]
    degree = degree[0] if isinstance(degree, list) else degree
    return pair["friction"]["mu"], 1 / curv, 1 / inv_E, pair["body"], degree


def read_nodes(folder, body):
    """The multiplier nodes of pair 0 (the body's own rows of contact.csv), sorted along s."""
    with open(os.path.join(folder, "contact.csv")) as f:
        rows = [r for r in csv.DictReader(f) if r["pair"] == "0" and r["body"] == body]
    rows.sort(key=lambda r: float(r["s"]))
    col = lambda k: np.array([float(r[k]) for r in rows])  # noqa: E731
    return {"s": col("s"), "X": np.column_stack([col("X"), col("Y")]), "x": col("x"), "y": col("y"),
            "pressure": col("pressure"), "traction": col("traction"),
            "t_t": col("tangential_traction"), "state": np.array([r["state"] for r in rows])}


def block_starts(n, degree, vertex_rows=None):
    """The first node of each contact edge's block of Gauss–Lobatto nodes, and the end: blocks of
    degree + 1 nodes sharing their ends, or, on an adapted mesh whose edges have degrees of
    their own, blocks between the rows that are the edges' vertices."""
    if vertex_rows is not None:
        return sorted(set(vertex_rows) | {0, n})
    if n % degree:
        raise SystemExit(f"{n + 1} contact nodes are not blocks of p + 1 = {degree + 1} sharing their ends")
    return list(range(0, n + 1, degree))


def edge_weights(s, degree, vertex_rows=None):
    """Quadrature weights of the nodes along s: the contact edges' Gauss–Lobatto nodes come in
    blocks sharing their ends (block_starts), and each block's weights integrate the
    polynomial through its nodes in s exactly."""
    starts = block_starts(len(s) - 1, degree, vertex_rows)
    w = np.zeros_like(s)
    for k0, k1 in zip(starts, starts[1:]):
        x = s[k0:k1 + 1]
        m, h = 0.5 * (x[0] + x[-1]), 0.5 * (x[-1] - x[0])
        t = (x - m) / h
        V = np.vander(t, len(x), increasing=True).T   # V[j, i] = t_i^j
        moments = np.array([(1 - (-1) ** (j + 1)) / (j + 1) for j in range(len(x))]) * h
        w[k0:k1 + 1] += np.linalg.solve(V, moments)
    return w


def vertex_rows(folder, body, X):
    """The rows (of the body's nodes sorted along s, undeformed positions X) that are vertices of
    its contact edges on the adapted mesh of an rp or hp run (its mesh.yaml); None without one."""
    path = os.path.join(folder, "mesh.yaml")
    if not os.path.exists(path):
        return None
    mesh = yaml.safe_load(open(path))[body]
    vertices = {n for edge in mesh["edge_sets"]["contact"] for n in edge}
    scale = max(1.0, float(np.max(np.abs(X))))
    rows = []
    for v in vertices:
        d = np.hypot(X[:, 0] - mesh["nodes"][v][0], X[:, 1] - mesh["nodes"][v][1])
        k = int(np.argmin(d))
        if d[k] > 1e-9 * scale:
            raise SystemExit(f"{path}: contact vertex {v} of '{body}' is not a node of contact.csv")
        rows.append(k)
    return rows


def piecewise_polynomial(s, v, starts):
    """The function of s that is, on each block of nodes (block_starts), the polynomial through
    the block's values: the discrete traction along the contact edges."""
    blocks = [(s[k0], s[k1], np.polyfit((s[k0:k1 + 1] - 0.5 * (s[k0] + s[k1])) / (0.5 * (s[k1] - s[k0])),
                                         v[k0:k1 + 1], k1 - k0)) for k0, k1 in zip(starts, starts[1:])]

    def evaluate(x):
        x = np.asarray(x, dtype=float)
        out = np.full_like(x, np.nan)
        for lo, hi, coef in blocks:
            k = (x >= lo) & (x <= hi)
            out[k] = np.polyval(coef, (x[k] - 0.5 * (lo + hi)) / (0.5 * (hi - lo)))
        return out
    return evaluate, [b[0] for b in blocks] + [blocks[-1][1]]


def against_reference(run, ref):
    """Relative L2 errors of the run's shear and pressure against a reference run's (the model's
    own answer: the same case on a much finer discretization), each side a polynomial on each of
    its contact edges: Gauss–Legendre on every piece between the two meshes' edge ends, exact
    for the difference of the two piecewise polynomials (p + 1 <= 16 points)."""
    lo, hi = max(run["breaks"][0], ref["breaks"][0]), min(run["breaks"][-1], ref["breaks"][-1])
    cuts = np.unique(np.clip(np.concatenate([run["breaks"], ref["breaks"]]), lo, hi))
    g, gw = np.polynomial.legendre.leggauss(16)
    x = np.concatenate([0.5 * (a + b) + 0.5 * (b - a) * g for a, b in zip(cuts, cuts[1:])])
    w = np.concatenate([0.5 * (b - a) * gw for a, b in zip(cuts, cuts[1:])])
    out = {}
    for key in ("shear", "pressure"):
        fe, ex = run[key](x), ref[key](x)
        out[key + "_rel_L2_reference"] = float(np.sqrt(np.sum(w * (fe - ex) ** 2) / np.sum(w * ex ** 2)))
    return out


def total_variation(v):
    return float(np.sum(np.abs(np.diff(v)))) if len(v) > 1 else 0.0


def shear(n):
    """The shear per unit length along the common tangent at the nodes n (read_nodes): the
    tangential multiplier times dS/ds (the pressure over the normal multiplier), taken positive
    in the direction of its resultant (the multiplier's sign follows the tangent's orientation)."""
    ratio = np.where(n["traction"] > 0, n["pressure"] / np.where(n["traction"] > 0, n["traction"], 1), 1.0)
    return np.sign(np.sum(n["t_t"])) * n["t_t"] * ratio


def discrete_tractions(folder):
    """The run's shear and pressure as functions of s (piecewise_polynomial), and its edge ends."""
    _, _, _, body, degree = read_case(folder)
    n = read_nodes(folder, body)
    starts = block_starts(len(n["s"]) - 1, degree, vertex_rows(folder, body, n["X"]))
    q, breaks = piecewise_polynomial(n["s"], shear(n), starts)
    return {"shear": q, "pressure": piecewise_polynomial(n["s"], n["pressure"], starts)[0],
            "breaks": np.array(breaks)}


UNIFORM_POINTS = 6001  # of the uniform metric over [-1.5 a, 1.5 a]
UNIFORM_EXTENT = 1.5


def point_tractions(folder, body):
    """The shear and pressure of the body's rows of contact.csv (a penalty run: its Gauss points)
    as functions of s, linear between neighbouring points, nan beyond the outermost."""
    n = read_nodes(folder, body)
    s = n["s"]
    line = lambda v: (lambda x: np.interp(x, s, v, left=np.nan, right=np.nan))  # noqa: E731
    return {"shear": line(shear(n)), "pressure": line(n["pressure"]), "breaks": np.array([s[0], s[-1]])}


def uniform_rule(a, n=UNIFORM_POINTS, extent=UNIFORM_EXTENT):
    """Points and trapezoidal weights of n uniform points on [-extent a, extent a]."""
    x = np.linspace(-extent * a, extent * a, n)
    w = np.full(n, x[1] - x[0])
    w[0] = w[-1] = 0.5 * (x[1] - x[0])
    return x, w


def relative_l2(x, w, measured, exact):
    """sqrt(Σ w (measured - exact)² / Σ w exact²) over the points x with weights w, measured and
    exact functions of s; refused where measured is not defined on all of them."""
    m = measured(x)
    if np.any(np.isnan(m)):
        raise SystemExit(f"the run's contact points do not cover [{x[0]:.6g}, {x[-1]:.6g}]")
    e = exact(x)
    return float(np.sqrt(np.sum(w * (m - e) ** 2) / np.sum(w * e ** 2)))


def own_point_weights(folder, s, enforcement, degree, vertices=None):
    """The quadrature weights of a run's own contact points along s (own_point_errors); an exact
    run's nodes by edge_weights (`vertices`: the rows of its edges' ends on an adapted mesh,
    vertex_rows)."""
    if enforcement != "penalty":
        return edge_weights(s, degree, vertices)
    n = yaml.safe_load(open(os.path.join(folder, "input.yaml")))["contact"][0]["quadrature"]
    if len(s) % n:
        raise SystemExit(f"{len(s)} penalty points are not blocks of contact[0].quadrature = {n}")
    g, gw = np.polynomial.legendre.leggauss(n)
    w = np.zeros_like(s)
    for k in range(0, len(s), n):
        x = s[k:k + n]
        h = (x[-1] - x[0]) / (g[-1] - g[0])
        mid = x[0] - g[0] * h
        if not np.allclose(mid + h * g, x, rtol=0, atol=1e-3 * abs(h)):
            raise SystemExit(f"the penalty points {k}..{k + n - 1} are not one edge's Gauss points in s")
        w[k:k + n] = gw * abs(h)
    return w


def own_point_errors(folder, enforcement, degree, body, p_exact, q_exact):
    """The shear's and the pressure's relative L2 errors at the run's own contact points, by
    their own quadrature (the module's docstring)."""
    n = read_nodes(folder, body)
    s = n["s"]
    w = own_point_weights(folder, s, enforcement, degree,
                          None if enforcement == "penalty" else vertex_rows(folder, body, n["X"]))
    rel = lambda fe, ex: float(np.sqrt(np.sum(w * (fe - ex) ** 2) / np.sum(w * ex ** 2)))  # noqa: E731
    return {"shear_rel_L2_own_points": rel(shear(n), q_exact(s)),
            "pressure_rel_L2_own_points": rel(n["pressure"], p_exact(s))}


def uniform_errors(folder):
    """The method's shear and pressure against Cattaneo–Mindlin's and Hertz's by one metric for
    both methods (the module's docstring): shear_rel_L2_uniform, pressure_rel_L2_uniform, with
    P, Q, a, c and the method."""
    summary = json.load(open(os.path.join(folder, "summary.json")))
    pair = summary["contact_pairs"][0]
    mu, R_star, E_star, body, degree = read_case(folder)
    P, Q = pair["normal_force"], abs(pair["tangential_force"])
    a, c, _, p_exact, q_exact = closed_form(R_star, E_star, mu, P, Q)
    penalty = pair["enforcement"] == "penalty"
    t = point_tractions(folder, body) if penalty else discrete_tractions(folder)
    x, w = uniform_rule(a)
    return {"method": pair["enforcement"], "P": P, "Q": Q, "mu": mu, "a": a, "c": c, "dofs": summary["dofs"],
            "shear_rel_L2_uniform": relative_l2(x, w, t["shear"], q_exact),
            "pressure_rel_L2_uniform": relative_l2(x, w, t["pressure"], p_exact),
            "uniform": {"from": float(x[0]), "to": float(x[-1]), "points": len(x)},
            **own_point_errors(folder, pair["enforcement"], degree, body, p_exact, q_exact)}


def measure(folder):
    summary = json.load(open(os.path.join(folder, "summary.json")))
    pair = summary["contact_pairs"][0]
    mu, R_star, E_star, body, degree = read_case(folder)
    n = read_nodes(folder, body)
    P, Q_run = pair["normal_force"], pair["tangential_force"]
    Q = abs(Q_run)
    a, c, p0, p_exact, q_exact = closed_form(R_star, E_star, mu, P, Q)
    s = n["s"]
    q = shear(n)
    w = edge_weights(s, degree, vertex_rows(folder, body, n["X"]))
    rel = lambda fe, ex: float(np.sqrt(np.sum(w * (fe - ex) ** 2) / np.sum(w * ex ** 2)))  # noqa: E731
    out = {"P": P, "Q": Q, "mu": mu, "R_star": R_star, "E_star": E_star, "a": a, "c": c,
           "c_over_a": c / a, "b_over_R": a / (2 * R_star), "dofs": summary["dofs"],
           "nodes_in_contact": int(np.sum(n["state"] != "open")),
           "shear_rel_L2": rel(q, q_exact(s)),
           "pressure_rel_L2": rel(n["pressure"], p_exact(s)),
           "shear_integral": float(np.sum(w * q)), "pressure_integral": float(np.sum(w * n["pressure"]))}
    # The pressure on the deformed interface, tilted by its slope y' (the shear's own
    # (1 - 2 nu)(1 + nu) q / E, absent from the linear theory), carries part of Q as well:
    # Q = ∫ q dx + ∫ p y' dx, y' of the deformed nodes, signed for the push (Q_run, the
    # contact force on the body, opposes it)
    slope = np.gradient(n["y"], n["x"])
    out["tilt_force"] = float(np.sum(w * n["pressure"] * slope)) * (1.0 if Q_run <= 0 else -1.0)
    out["x_force"] = out["shear_integral"] + out["tilt_force"]
    # The linear theory lets the shear carry all of Q; here it carries Q less the tilt's part, and
    # its closed form for that force (the same P) measures the shear without this coupling
    _, out["c_carried"], _, _, q_carried = closed_form(R_star, E_star, mu, P, abs(out["shear_integral"]))
    out["shear_rel_L2_carried"] = rel(q, q_carried(s))
    # Coulomb: the multipliers themselves (per unit undeformed length), every node
    bound = mu * np.abs(n["traction"])
    out["coulomb_ratio_max"] = float(np.max(np.where(bound > 0, np.abs(n["t_t"]) / np.where(bound > 0, bound, 1), 0.0)))
    out["coulomb_excess_max"] = float(np.max(np.abs(n["t_t"]) - bound * (1 + 1e-9)))
    # stick zone ends: outermost stick node on each side, and the next slip node beyond it
    stick = np.where(n["state"] == "stick")[0]
    ends = {}
    if len(stick):
        for side, k, step in (("left", stick[0], -1), ("right", stick[-1], 1)):
            j = k + step
            beyond = float(s[j]) if 0 <= j < len(s) and n["state"][j] == "slip" else float("nan")
            ends[side] = [float(s[k]), beyond]
        mid = lambda e: 0.5 * (e[0] + e[1]) if not math.isnan(e[1]) else e[0]  # noqa: E731
        c_fe = 0.5 * (mid(ends["right"]) - mid(ends["left"]))
        out["stick_ends"] = ends
        out["c_fe"] = c_fe
        out["c_rel_error"] = (c_fe - c) / c
    # oscillation: total variation of q over each slip zone's nodes, FE and closed form
    tv_fe = tv_ex = 0.0
    slip = n["state"] == "slip"
    for zone in (slip & (s < 0), slip & (s > 0)):
        tv_fe += total_variation(q[zone])
        tv_ex += total_variation(q_exact(s[zone]))
    out["slip_tv_fe"], out["slip_tv_exact"] = tv_fe, tv_ex
    out["slip_tv_ratio"] = tv_fe / tv_ex if tv_ex > 0 else float("nan")
    return out, (s, q, n["pressure"], n["state"], mu, a, c, p_exact, q_exact)


def plot(data, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    s, q, p, state, mu, a, c, p_exact, q_exact = data
    x = np.linspace(-1.2 * a, 1.2 * a, 2001)
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.axvspan(-c / a, c / a, color="0.92", label="stick zone, closed form")
    ax.plot(x / a, mu * p_exact(x), "k--", lw=1, label="μ p, Hertz")
    ax.plot(x / a, q_exact(x), "k-", lw=1.2, label="q, Cattaneo–Mindlin")
    ax.plot(s / a, mu * p, "c.", ms=4, label="μ p, FE")
    for st, m, col in (("stick", "o", "tab:blue"), ("slip", "s", "tab:red")):
        k = state == st
        ax.plot(s[k] / a, q[k], m, mfc="none", color=col, ms=4, label=f"q, FE ({st})")
    ax.set_xlim(-1.2, 1.2)
    ax.set_xlabel("x / a")
    ax.set_ylabel("traction per unit length")
    ax.set_title(title)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folder", help="the run's output folder (summary.json, contact.csv, input.yaml)")
    ap.add_argument("--plot", help="PNG of the shear and mu p, FE and closed form")
    ap.add_argument("--reference", help="a run of the same case on a much finer discretization: the "
                    "errors against it as well (shear_rel_L2_reference, pressure_rel_L2_reference)")
    args = ap.parse_args()
    uniform = uniform_errors(args.folder)
    if uniform["method"] == "penalty":  # no multiplier nodes: the uniform figures alone
        json.dump(uniform, sys.stdout, indent=1)
        sys.stdout.write("\n")
        return
    out, data = measure(args.folder)
    out.update({k: uniform[k] for k in ("method", "shear_rel_L2_uniform", "pressure_rel_L2_uniform", "uniform",
                                        "shear_rel_L2_own_points", "pressure_rel_L2_own_points")})
    if args.reference:
        reference, _ = measure(args.reference)
        out.update(against_reference(discrete_tractions(args.folder), discrete_tractions(args.reference)))
        out["reference"] = {"folder": args.reference, "dofs": reference["dofs"],
                            "shear_rel_L2": reference["shear_rel_L2"],
                            "pressure_rel_L2": reference["pressure_rel_L2"]}
    json.dump(out, sys.stdout, indent=1)
    sys.stdout.write("\n")
    if args.plot:
        plot(data, args.plot, f"P = {out['P']:.5g}, Q = {out['Q']:.4g}, c/a = {out['c_over_a']:.3f}, "
                              f"{out['dofs']} DOF")


if __name__ == "__main__":
    main()
