"""Reading a frictional result (issue 22, item 3): contact.csv's tangent columns and the shear
from the stresses, the other body's rows of an exact two-body pair, and summary.json's friction
figures, on blocks in a uniform state whose tractions are known exactly.

The uniform state: blocks of E = 1000, nu = 0 (plane stress) pressed by delta and sheared by a
along the interface through a top with prescribed displacement, the sides loaded with the shear
traction tau0 = G gamma of the uniform state (G = E/2, gamma = a / H) so that they are in
equilibrium with it, stick friction. The displacement is linear, in the FE space of any degree,
so the FE solution is the exact one: sigma_yy = -E delta / H, sigma_xy = tau0 in the frame of
the interface; the contact pressure is p = E delta / H and the friction traction tau0 at every
point. Both meshes hold elements of opposite orientation (the contact edges' local parameters
run both ways), as hp refinement creates."""
import csv
import json
import math

import numpy as np
import pytest

E = 1000.0
G = E / 2  # nu = 0


def rotate(v, theta):
    c, s = math.cos(theta), math.sin(theta)
    return [c * v[0] - s * v[1], s * v[0] + c * v[1]]


def fmt(v):
    return "[" + ", ".join(repr(float(x)) for x in v) + "]"


def block_on_plane(theta, delta=0.01, a=0.004):
    """A 2 x 1 block (two elements, the second listed from its top right corner) on a rigid plane,
    the whole case turned by theta. Exact: p = E delta, t_T = G a along the plane's tangent."""
    tau0 = G * a
    X = {1: [0, 0], 2: [1, 0], 3: [2, 0], 4: [2, 1], 5: [1, 1], 6: [0, 1]}
    nodes = ", ".join(f"{k}: {fmt(rotate(v, theta))}" for k, v in X.items())
    top = rotate([a, -delta], theta)
    return f"""
case: block-on-plane-uniform-shear
bodies:
  - name: block
    material: {{E: {E}, nu: 0, plane: stress}}
    nodes: {{{nodes}}}
    elements: {{1: [1, 2, 5, 6], 2: [4, 5, 2, 3]}}
    edge_sets:
      bottom: [[1, 2], [3, 2]]
      top: [[4, 5], [5, 6]]
      left: [[6, 1]]
      right: [[3, 4]]
    constraints:
      - {{edges: [top], ux: {top[0]!r}, uy: {top[1]!r}}}
    loads:
      - {{edges: [left], traction: {fmt(rotate([0, -tau0], theta))}}}
      - {{edges: [right], traction: {fmt(rotate([0, tau0], theta))}}}
contact:
  - body: block
    edges: [bottom]
    obstacle: {{type: plane, point: [0, 0], normal: {fmt(rotate([0, 1], theta))}}}
    friction: {{law: stick, penalty: 1.0e5}}
discretization: {{method: p, degree: 3}}
""", dict(pressure=E * delta, shear=tau0, length=2.0)


def two_blocks(enforcement, delta=0.02, a=0.01):
    """Two 2 x 1 blocks stacked, the lower one's base fixed, the upper one's top prescribed; in
    each body one element listed the other way round. Exact: p = E delta / 2, t_T = G a / 2.
    Penalty (eps_N = eps_T = 1e7): the interface is a spring in series with the blocks (a uniform
    penetration and micro slip, still in the FE space): p = delta / (2 / E + 1 / eps_N),
    t_T = a / (2 / G + 1 / eps_T)."""
    exact = enforcement == "augmented-lagrangian"
    eps = 1.0e7
    tau0 = G * a / 2 if exact else a / (2 / G + 1 / eps)
    pressure = E * delta / 2 if exact else delta / (2 / E + 1 / eps)
    contact = ("friction: {law: stick, penalty: 1.0e5}" if exact
               else f"enforcement: penalty\n    penalty: {eps}\n"
                    f"    friction: {{law: stick, penalty: {eps}}}")
    sides = f"""    loads:
      - {{edges: [left], traction: [0, {-tau0}]}}
      - {{edges: [right], traction: [0, {tau0}]}}"""
    return f"""
case: two-blocks-uniform-shear
bodies:
  - name: upper
    material: {{E: {E}, nu: 0, plane: stress}}
    nodes: {{1: [0, 0], 2: [1, 0], 3: [2, 0], 4: [2, 1], 5: [1, 1], 6: [0, 1]}}
    elements: {{1: [1, 2, 5, 6], 2: [4, 5, 2, 3]}}
    edge_sets:
      bottom: [[1, 2], [3, 2]]
      top: [[4, 5], [5, 6]]
      left: [[6, 1]]
      right: [[3, 4]]
    constraints:
      - {{edges: [top], ux: {a}, uy: {-delta}}}
{sides}
  - name: lower
    material: {{E: {E}, nu: 0, plane: stress}}
    nodes: {{11: [0, -1], 12: [1, -1], 13: [2, -1], 14: [2, 0], 15: [1, 0], 16: [0, 0]}}
    elements: {{3: [11, 12, 15, 16], 4: [14, 15, 12, 13]}}
    edge_sets:
      top: [[16, 15], [14, 15]]
      base: [[11, 12], [12, 13]]
      left: [[16, 11]]
      right: [[13, 14]]
    constraints:
      - {{edges: [base], ux: 0, uy: 0}}
{sides}
contact:
  - body: upper
    edges: [bottom]
    obstacle: {{type: body, body: lower, edges: [top]}}
    {contact}
discretization: {{method: p, degree: 3}}
""", dict(pressure=pressure, shear=tau0, length=2.0)


def run_case(hpcontact, tmp_path, text):
    case = tmp_path / "case.yaml"
    case.write_text(text)
    out = tmp_path / "out"
    r = hpcontact("run", case, "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    rows = list(csv.DictReader(open(out / "contact.csv")))
    summary = json.load(open(out / "summary.json"))
    return rows, summary["contact_pairs"][0]


def column(rows, key):
    return np.array([float(r[key]) for r in rows])


def in_contact(rows):
    return [r for r in rows if r["state"] != "open"]


@pytest.mark.parametrize("theta", [0.0, 0.5])
def test_block_on_plane_tangent_and_shear(hpcontact, tmp_path, theta):
    """Against a rigid plane the tangent is the plane's, turned with it (exact: (cos, sin) of
    theta); pressure, t_T and both from the stresses are the uniform state's to 1e-8 (measured
    1e-13). Catches: a tangent not turned with the plane's normal, the shear projected on a
    fixed axis or on the normal, a sign flip of either."""
    text, exact = block_on_plane(theta)
    rows, pair = run_case(hpcontact, tmp_path, text)
    rows = in_contact(rows)
    assert len(rows) == 7  # p = 3 on two edges: 7 Lobatto nodes, all in contact
    tangent = np.array([math.cos(theta), math.sin(theta)])
    np.testing.assert_allclose(column(rows, "tangent_x"), tangent[0], atol=1e-12)
    np.testing.assert_allclose(column(rows, "tangent_y"), tangent[1], atol=1e-12)
    tol = 1e-8 * exact["pressure"]
    for key in ("pressure", "pressure_from_stress"):
        np.testing.assert_allclose(column(rows, key), exact["pressure"], atol=tol, err_msg=key)
    for key in ("tangential_traction", "shear_from_stress"):
        np.testing.assert_allclose(column(rows, key), exact["shear"], atol=tol, err_msg=key)
    # the friction on the block, along the pair's tangent: -t_T over the interface
    assert pair["tangential_force"] == pytest.approx(-exact["shear"] * exact["length"], rel=1e-9)


@pytest.mark.parametrize("enforcement", ["augmented-lagrangian", "penalty"])
def test_two_blocks_tangent_one_way_along_each_side(hpcontact, tmp_path, enforcement):
    """Two bodies whose contact edges run both ways: every row of a body has the same tangent
    (the upper body's (1, 0): friction_tangent of the lower body's outward normal (0, 1); the
    lower body's (-1, 0), of the upper's (0, -1)), and t_T and the shear from the stresses are
    the uniform state's on both bodies' rows (action and reaction: the same t_T). Catches: the
    tangent taken from the other body's edge direction dx/dt (exact: the mortar rows of the node
    between the lower edges cancel and the multiplier system is singular; penalty: half the rows
    flip), the other body's rows without tangent or t_T (issue 22, item 4)."""
    text, exact = two_blocks(enforcement)
    rows, pair = run_case(hpcontact, tmp_path, text)
    # penalty: the stresses to 1e-5 (measured 1.5e-6: the Newton tolerance of the penalty solve)
    tol = (1e-8 if enforcement == "augmented-lagrangian" else 1e-5) * exact["pressure"]
    for body, tx in (("upper", 1.0), ("lower", -1.0)):
        side = [r for r in rows if r["body"] == body]
        closed = [r for r in side if float(r["pressure"]) > 0]
        assert len(closed) >= 7, (body, len(closed))
        np.testing.assert_allclose(column(closed, "tangent_x"), tx, atol=1e-12, err_msg=body)
        np.testing.assert_allclose(column(closed, "tangent_y"), 0.0, atol=1e-12, err_msg=body)
        for key in ("pressure", "pressure_from_stress"):
            np.testing.assert_allclose(column(closed, key), exact["pressure"], atol=tol,
                                       err_msg=f"{body} {key}")
        for key in ("tangential_traction", "shear_from_stress"):
            np.testing.assert_allclose(column(closed, key), exact["shear"], atol=tol,
                                       err_msg=f"{body} {key}")
    rel = 1e-9 if enforcement == "augmented-lagrangian" else 1e-5
    assert pair["tangential_force"] == pytest.approx(-exact["shear"] * exact["length"], rel=rel)


def test_transitions_where_the_state_changes_along_the_interface(hpcontact, root, tmp_path):
    """examples/two-bars/coulomb.yaml: the reported stick-slip transitions are exactly the
    midpoints of neighbouring rows of the upper bar (a straight chain along x: its rows in order)
    whose states are stick and slip, counted independently from contact.csv. Catches: counting
    across open or not-anchored points, or between points that are not neighbours."""
    out = tmp_path / "out"
    r = hpcontact("run", f"{root}/examples/two-bars/coulomb.yaml", "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    rows = [r for r in csv.DictReader(open(out / "contact.csv")) if r["body"] == "upper"]
    rows.sort(key=lambda r: float(r["X"]))
    expected = [0.5 * (float(a["X"]) + float(b["X"])) for a, b in zip(rows, rows[1:])
                if {a["state"], b["state"]} == {"stick", "slip"}]
    assert expected, "the example has a stick zone and a slip zone"
    friction = json.load(open(out / "summary.json"))["contact_pairs"][0]["friction"]
    got = [p[0] for p in friction["stick_slip_transitions"]]
    assert got == pytest.approx(expected, abs=1e-9)  # contact.csv has 12 digits


@pytest.mark.parametrize("mu", [0.5, 0.1])
def test_friction_capacity_of_a_uniform_block(hpcontact, tmp_path, mu):
    """The block on the plane under Coulomb friction, p = 10 on a length of 2: capacity mu p L
    exactly. mu = 0.5: the uniform stick state (t_T = 2), ratio t_T / (mu p) = 0.4. mu = 0.1: the
    block slides; with the sides loaded by mu p = 1 the state is uniform again (t_T = mu p, every
    node slipping), ratio 1, no stick-slip transition. Catches: a capacity or ratio from another
    force (the resultant's norm, the applied one). (Exact pairs leave contact.csv's slip at 0:
    the accumulated slip a - H t_T / G = 0.002 is not reported yet.)"""
    text, exact = block_on_plane(0.0)
    shear = exact["shear"] if mu == 0.5 else mu * exact["pressure"]
    text = text.replace("{law: stick, penalty: 1.0e5}", f"{{law: coulomb, mu: {mu}}}")
    text = text.replace("[0.0, -2.0]", f"[0.0, {-shear}]").replace("[0.0, 2.0]", f"[0.0, {shear}]")
    rows, pair = run_case(hpcontact, tmp_path, text)
    rows = in_contact(rows)
    friction = pair["friction"]
    L = exact["length"]
    assert friction["tangential_force_capacity"] == pytest.approx(mu * exact["pressure"] * L, rel=1e-9)
    assert friction["tangential_traction_integral"] == pytest.approx(shear * L, rel=1e-9)
    assert friction["tangential_force_ratio"] == pytest.approx(shear / (mu * exact["pressure"]), rel=1e-9)
    assert pair["tangential_force"] == pytest.approx(-shear * L, rel=1e-9)
    np.testing.assert_allclose(column(rows, "tangential_traction"), shear, rtol=1e-8)
    np.testing.assert_allclose(column(rows, "shear_from_stress"), shear, rtol=1e-8)
    assert {r["state"] for r in rows} == ({"stick"} if mu == 0.5 else {"slip"})
    if mu == 0.1:
        assert friction["stick_slip_transitions"] == []
