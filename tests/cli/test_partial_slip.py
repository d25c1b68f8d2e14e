"""Partial slip (examples/partial-slip/small-load.yaml, b/R = 0.02, Q = mu P / 2, p = 4): the
Coulomb friction between two similar cylinders pressed and then sheared reproduces
Cattaneo–Mindlin's stick zone and shear, and carries the applied Q.

Tolerances from the measured p-convergence (examples/partial-slip/README.md: shear e_L2 4.2 %
at p = 3, 2.5 % at p = 4, 1.7 % at p = 5); a friction law off by 10 % in mu in the slip rows
gives 9 % and moves the stick zone by a node."""
import json
import os

import numpy as np
import pytest
import yaml

from conftest import load_script

compare = load_script("partial_slip_compare")
CASE = os.path.join("examples", "partial-slip", "small-load.yaml")


@pytest.fixture(scope="module")
def run(hpcontact, root, tmp_path_factory):
    out = tmp_path_factory.mktemp("partial-slip")
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    measured, _ = compare.measure(str(out))
    spec = yaml.safe_load(open(out / "input.yaml"))
    return out, measured, spec


def test_coulomb_bound_at_every_node(run):
    """|t_T| <= mu t_N (1 + 1e-9) at every multiplier node, and some nodes slip at the bound."""
    out, m, _ = run
    nodes = compare.read_nodes(str(out), "upper")
    bound = m["mu"] * abs(nodes["traction"]) * (1 + 1e-9)
    assert all(abs(nodes["t_t"]) <= bound)
    assert sum(nodes["state"] == "slip") >= 4 and sum(nodes["state"] == "stick") >= 4


def test_friction_carries_the_applied_force(run):
    """The applied Q (the load's resultant) is carried by the shear and by the pressure on the
    deformed interface, tilted by (1 - 2 nu)(1 + nu) q / E (1e-3 of Q); the shear alone, the
    linear theory's Q, within 1 %."""
    _, m, spec = run
    Q = spec["bodies"][0]["loads"][0]["resultant"]
    assert m["x_force"] == pytest.approx(Q, rel=1e-3)
    assert m["shear_integral"] == pytest.approx(Q, rel=1e-2)
    assert m["pressure_integral"] == pytest.approx(m["P"], rel=1e-3)


def test_stick_zone_where_cattaneo_puts_it(run):
    """c = a sqrt(1 - Q / (mu P)) lies between the outermost stick node and the first slip node
    on both sides, and the FE zone's half width (midway between them) is within 3 % of c."""
    _, m, _ = run
    c = m["c"]
    assert m["stick_ends"]["right"][0] < c < m["stick_ends"]["right"][1]
    assert m["stick_ends"]["left"][1] < -c < m["stick_ends"]["left"][0]
    assert abs(m["c_rel_error"]) < 0.03


def test_shear_and_pressure_against_the_closed_forms(run):
    """Shear relative L2 error below 3.5 % (2.5 % measured at p = 4), the pressure's against
    Hertz below 0.5 % (0.25 %), and no oscillation in the slip zones: the shear's total
    variation there within 5 % of the closed form's (0.987 measured)."""
    _, m, _ = run
    assert m["shear_rel_L2"] < 0.035
    assert m["pressure_rel_L2"] < 0.005
    assert 0.95 < m["slip_tv_ratio"] < 1.05


def test_shear_against_the_force_it_carries(run):
    """The shear carries Q and the tilt's part (the pressure on the sheared, tilted interface
    pushes against it: 0.45 % of Q at b/R = 0.02), so its stick zone is Cattaneo's for that
    larger force, narrower. The two errors differ by no more than the two closed forms do
    (triangle inequality in the nodes' weighted L2 norm, the forms compared independently here
    on a fine grid)."""
    _, m, _ = run
    Q, carried = m["Q"], m["shear_integral"]
    assert carried == pytest.approx(Q - m["tilt_force"], rel=1e-3)
    assert 1e-3 < carried / Q - 1 < 1e-2
    assert m["c_carried"] < m["c"]
    # the model's shear is nearer the carried force's form (measured 2.26 % against 2.47 %)
    assert m["shear_rel_L2_carried"] < 0.95 * m["shear_rel_L2"]
    x = np.linspace(-m["a"], m["a"], 400001)
    _, _, _, _, q_applied = compare.closed_form(m["R_star"], m["E_star"], m["mu"], m["P"], Q)
    _, _, _, _, q_carried = compare.closed_form(m["R_star"], m["E_star"], m["mu"], m["P"], carried)
    gap = np.sqrt(np.trapz((q_applied(x) - q_carried(x)) ** 2, x) / np.trapz(q_applied(x) ** 2, x))
    norm_ratio = np.sqrt(np.trapz(q_carried(x) ** 2, x) / np.trapz(q_applied(x) ** 2, x))
    assert gap > 1e-3
    assert abs(m["shear_rel_L2"] - m["shear_rel_L2_carried"] * norm_ratio) <= 1.02 * gap


def test_stick_slip_points_located_between_their_nodes(run):
    """summary.json's stick_slip_points (the root of |λ_T + κ ĝ_T| − μ λ along the edge) lie
    strictly between the outermost stick node and the first slip node, one on each side, and
    are nearer Cattaneo's c than the midway estimate: 0.15 % against 1.6 % measured at p = 4
    (the model's own c, finite cylinders, lies about 0.5 % inside Cattaneo's; the tolerance
    0.5 % keeps that margin and fails a point left at the midpoint or on a node). Their feet
    on the lower body are the same places to 1e-2 a (the interface is nearly flat)."""
    out, m, _ = run
    friction = json.load(open(out / "summary.json"))["contact"]["friction"]
    points = sorted(friction["stick_slip_points"])
    assert len(points) == 2
    left, right = points[0][0], points[1][0]
    assert m["stick_ends"]["left"][1] < left < m["stick_ends"]["left"][0]
    assert m["stick_ends"]["right"][0] < right < m["stick_ends"]["right"][1]
    c = m["c"]
    for x in (-left, right):
        assert abs(x - c) < 0.005 * c
        assert abs(x - c) < abs(m["c_fe"] - c)
    feet = sorted(friction["stick_slip_points_other"])
    for p, f in zip(points, feet):
        assert abs(p[0] - f[0]) < 1e-2 * m["a"]


def gauss_lobatto(p, a, b):
    """The p + 1 Gauss-Lobatto points of [a, b] (the ends and the roots of P_p')."""
    inner = np.polynomial.legendre.Legendre.basis(p).deriv().roots()
    t = np.concatenate([[-1.0], np.sort(inner.real), [1.0]])
    return a + 0.5 * (t + 1) * (b - a)


def test_node_weights_on_edges_of_different_degrees():
    """partial_slip_compare's quadrature on an adapted mesh (hp: every contact edge its own
    degree): blocks between the edges' vertex rows, each integrating the polynomial through its
    nodes exactly. Three edges of degrees 2, 5 and 3: x^k for k up to 2 over the whole line
    (exact on every block), and a degree-5 bump on the degree-5 edge, zero on the others (wrong
    with uniform blocks of 3); uniform blocks of p + 1 = 4 refuse the same nodes."""
    edges = [(-1.0, -0.2, 2), (-0.2, 0.3, 5), (0.3, 1.0, 3)]
    s, vertices = [], [0]
    for a, b, p in edges:
        pts = gauss_lobatto(p, a, b)
        s.extend(pts if not s else pts[1:])   # neighbouring edges share their vertex
        vertices.append(len(s) - 1)
    s = np.array(s)
    assert vertices == [0, 2, 7, 10] and s[7] == pytest.approx(0.3)
    w = compare.edge_weights(s, 2, vertices)
    for k in range(3):
        assert np.sum(w * s ** k) == pytest.approx((1 - (-1) ** (k + 1)) / (k + 1), abs=1e-12)
    # a degree-5 bump on the middle edge, zero on the others: exact only with the right blocks
    bump = np.where((s >= -0.2) & (s <= 0.3), (s + 0.2) * (s - 0.3) * s ** 3, 0.0)
    exact = np.polynomial.Polynomial([0, 0, 0, -0.06, -0.1, 1]).integ()
    assert np.sum(w * bump) == pytest.approx(exact(0.3) - exact(-0.2), rel=1e-12)
    assert np.sum(compare.edge_weights(s, 2) * bump) != pytest.approx(exact(0.3) - exact(-0.2), rel=1e-3)
    with pytest.raises(SystemExit):
        compare.edge_weights(s, 3)


def test_error_against_a_reference_run_of_other_edges():
    """partial_slip_compare --reference: the relative L2 difference of two runs' tractions, each a
    polynomial through its Gauss-Lobatto nodes on each of its own contact edges. The run: degree 2
    on [-1, 0.2], [0.2, 1], values 1 + s²; the reference: degree 3 on [-1, -0.4], [-0.4, 1], values
    1 + s² and 1 + s² + 0.01 (s + 0.4)³ — the difference has its exact L2 norm only if every piece
    between the two meshes' edge ends is integrated apart (the reference's third derivative jumps
    at -0.4, inside the run's first edge)."""
    def traction(edges, f):
        s, vertices = [], [0]
        for a, b, p in edges:
            pts = gauss_lobatto(p, a, b)
            s.extend(pts if not s else pts[1:])
            vertices.append(len(s) - 1)
        s = np.array(s)
        poly, breaks = compare.piecewise_polynomial(s, f(s), vertices)
        return {"shear": poly, "pressure": poly, "breaks": np.array(breaks)}
    run = traction([(-1.0, 0.2, 2), (0.2, 1.0, 2)], lambda s: 1 + s ** 2)
    ref = traction([(-1.0, -0.4, 3), (-0.4, 1.0, 3)],
                   lambda s: 1 + s ** 2 + 0.01 * np.where(s > -0.4, s + 0.4, 0.0) ** 3)
    P = np.polynomial.Polynomial
    base, bump = P([1, 0, 1]), 0.01 * P([0.4, 1]) ** 3
    integral = lambda f, a, b: f.integ()(b) - f.integ()(a)  # noqa: E731
    diff2 = integral(bump ** 2, -0.4, 1)
    norm2 = integral(base ** 2, -1, 1) + integral(2 * base * bump + bump ** 2, -0.4, 1)
    errors = compare.against_reference(run, ref)
    assert errors["shear_rel_L2_reference"] == pytest.approx(np.sqrt(diff2 / norm2), rel=1e-10)
    assert errors["pressure_rel_L2_reference"] == pytest.approx(np.sqrt(diff2 / norm2), rel=1e-10)
    assert compare.against_reference(ref, ref)["shear_rel_L2_reference"] < 1e-14


def test_uniform_metric_closed_form():
    """partial_slip_compare's one metric for both methods: the relative L2 difference on the
    uniform trapezoidal rule over [-1.5 a, 1.5 a]. Against e(x) = sqrt(1 - x²/a²) (zero beyond a,
    ∫ e² = 4a/3): itself gives 0, 1.1 e gives 0.1, e + d (d constant over the whole range,
    ∫ d² = 3 a d²) gives 1.5 d; a measured traction undefined somewhere is refused."""
    a = 0.2
    x, w = compare.uniform_rule(a)
    assert (x[0], x[-1], np.sum(w)) == pytest.approx((-1.5 * a, 1.5 * a, 3 * a), rel=1e-12)
    e = lambda s: np.sqrt(np.clip(1 - (s / a) ** 2, 0, None))  # noqa: E731
    assert compare.relative_l2(x, w, e, e) == 0
    assert compare.relative_l2(x, w, lambda s: 1.1 * e(s), e) == pytest.approx(0.1, rel=1e-12)
    assert compare.relative_l2(x, w, lambda s: e(s) + 0.02, e) == pytest.approx(0.03, rel=1e-5)
    with pytest.raises(SystemExit):
        compare.relative_l2(x, w, lambda s: np.where(s < a, e(s), np.nan), e)


def _synthetic_run(folder, enforcement, s, factor):
    """A run folder of two steel cylinders (R = 10, mu = 0.3; P = 700, Q = mu P / 2) whose pair's
    rows at s carry `factor` times Cattaneo–Mindlin's shear and Hertz's pressure."""
    spec = {"bodies": [{"name": n, "material": {"E": 210000.0, "nu": 0.3, "plane": "strain"},
                        "curves": [{"arc": {"radius": 10.0}}]} for n in ("upper", "lower")],
            "contact": [{"body": "upper", "obstacle": {"type": "body", "body": "lower"},
                         "friction": {"law": "coulomb", "mu": 0.3}}],
            "discretization": {"degree": 4}}
    if enforcement == "penalty":
        spec["contact"][0]["quadrature"] = 50
    os.makedirs(folder)
    with open(os.path.join(folder, "input.yaml"), "w") as f:
        yaml.safe_dump(spec, f)
    with open(os.path.join(folder, "summary.json"), "w") as f:
        json.dump({"dofs": 1, "contact_pairs": [{"enforcement": enforcement, "normal_force": 700.0,
                                                 "tangential_force": -105.0}]}, f)
    mu, R_star, E_star, _, _ = compare.read_case(folder)
    _, _, _, p, q = compare.closed_form(R_star, E_star, mu, 700.0, 105.0)
    with open(os.path.join(folder, "contact.csv"), "w") as f:
        f.write("pair,body,X,Y,x,y,s,pressure,traction,tangential_traction,state\n")
        for si in s:
            pi, qi = factor * p(si), factor * q(si)
            f.write(f"0,upper,{si},0,{si},0,{si},{pi},{pi},{qi},{'slip' if pi > 0 else 'open'}\n")


def test_uniform_metric_reads_both_methods_alike(tmp_path):
    """The same tractions, 10 % above Cattaneo–Mindlin's shear and Hertz's pressure, written at a
    penalty run's points (50 per edge, linear between them) and at an exact run's nodes (degree
    4, Gauss–Lobatto, a polynomial on each edge; edges of a / 16, ending at ±a and ±c), give the
    same figures: 0.1 each to 5e-4 (measured 2.1e-4 and 1.6e-5 off: what interpolating the
    square-root ends costs)."""
    mu, E_star, R_star = 0.3, 210000.0 / (2 * (1 - 0.3 ** 2)), 5.0
    a, c, _, _, _ = compare.closed_form(R_star, E_star, mu, 700.0, 105.0)
    grid = [g for g in np.linspace(-2 * a, 2 * a, 65) if min(abs(abs(g) - a), abs(abs(g) - c)) > 1e-3 * a]
    ends = np.sort(np.concatenate([grid, [-a, -c, c, a]]))
    g, _ = np.polynomial.legendre.leggauss(50)
    penalty = np.concatenate([0.5 * (lo + hi) + 0.5 * (hi - lo) * g for lo, hi in zip(ends, ends[1:])])
    nodes = [ends[0]]
    for lo, hi in zip(ends, ends[1:]):
        nodes.extend(gauss_lobatto(4, lo, hi)[1:])
    for method, s in (("penalty", np.unique(penalty)), ("augmented-lagrangian", np.array(nodes))):
        folder = str(tmp_path / method)
        _synthetic_run(folder, method, s, 1.1)
        errors = compare.uniform_errors(folder)
        assert errors["method"] == method
        assert errors["shear_rel_L2_uniform"] == pytest.approx(0.1, abs=5e-4), method
        assert errors["pressure_rel_L2_uniform"] == pytest.approx(0.1, abs=5e-4), method
        # at the points themselves the factor is all there is
        assert errors["shear_rel_L2_own_points"] == pytest.approx(0.1, rel=1e-12), method
        assert errors["pressure_rel_L2_own_points"] == pytest.approx(0.1, rel=1e-12), method


def test_own_point_weights_integrate_each_methods_polynomials(tmp_path):
    """The own-points metric's quadrature: a penalty run's 50 Gauss points per edge (edges of
    unequal length, the extents found from the points) integrate s^k over the edges (k <= 99;
    checked at 0, 1, 7, 30) exactly; an exact run's Gauss–Lobatto nodes (degree 4) those up to k = 4; points that are
    not one edge's Gauss points are refused."""
    ends = [-1.0, -0.3, 0.1, 1.0]
    g, _ = np.polynomial.legendre.leggauss(50)
    s = np.concatenate([0.5 * (lo + hi) + 0.5 * (hi - lo) * g for lo, hi in zip(ends, ends[1:])])
    folder = str(tmp_path / "penalty")
    _synthetic_run(folder, "penalty", s, 1.0)
    w = compare.own_point_weights(folder, s, "penalty", 4)
    for k in (0, 1, 7, 30):
        assert np.sum(w * s ** k) == pytest.approx((1 - (-1) ** (k + 1)) / (k + 1), abs=1e-13)
    nodes = [ends[0]]
    for lo, hi in zip(ends, ends[1:]):
        nodes.extend(gauss_lobatto(4, lo, hi)[1:])
    nodes = np.array(nodes)
    w = compare.own_point_weights(folder, nodes, "augmented-lagrangian", 4)
    for k in range(5):
        assert np.sum(w * nodes ** k) == pytest.approx((1 - (-1) ** (k + 1)) / (k + 1), abs=1e-13)
    with pytest.raises(SystemExit):
        compare.own_point_weights(folder, np.linspace(-1, 1, 150), "penalty", 4)
