"""Contact in axisymmetry (issue 18): the contact patch test of a solid cylinder on a rigid flat,
and a ball on a flat against 3-D Hertz, found by the hp loop to a tolerance from the Hertz
cylinder's coarse mesh (examples/hertz/ball-on-flat.yaml)."""
import csv
import json
import math
import os

import pytest


def run(hpcontact, case, out, *sets):
    args = ["run", str(case), "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


PATCH = """case: axisymmetric-contact-patch
description: A solid cylinder (r <= 2, 0 <= z <= 2) pressed onto a rigid flat, distorted mesh.
bodies:
  - name: cylinder
    material: {E: 1000, nu: 0.25, plane: axisymmetric}
    nodes: {1: [0, 0], 2: [0.9, 0], 3: [2, 0], 4: [0, 1.1], 5: [1.2, 0.75], 6: [2, 0.8],
            7: [0, 2], 8: [1.3, 2], 9: [2, 2]}
    elements: {1: [1, 2, 5, 4], 2: [2, 3, 6, 5], 3: [4, 5, 8, 7], 4: [5, 6, 9, 8]}
    edge_sets:
      axis: [[7, 4], [4, 1]]
      top: [[9, 8], [8, 7]]
      bottom: [[1, 2], [2, 3]]
    constraints:
      - {edges: [axis], ux: 0}
      - {edges: [top], uy: -0.002}
contact:
  - body: cylinder
    edges: [bottom]
    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}
discretization: {method: p, degree: DEGREE}
"""


@pytest.mark.parametrize("degree", [1, 2, 5, 8])
def test_contact_patch_of_a_solid_cylinder(hpcontact, tmp_path, degree):
    """Uniaxial compression of a solid cylinder on a frictionless rigid flat, its top lowered by
    0.002 on a height of 2: σ_zz = −E ε = −1 everywhere (σ_rr = σ_θθ = 0, u_r = ν ε r), so the
    contact pressure is uniform, 1, at every multiplier node (the one on the axis included, by
    its even extension) and the resultant is the total force π r² = 4π, to round-off."""
    case = tmp_path / "patch.yaml"
    case.write_text(PATCH.replace("DEGREE", str(degree)))
    s = run(hpcontact, case, tmp_path / "out")
    with open(tmp_path / "out" / "contact.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) >= 3
    for r in rows:
        assert abs(float(r["pressure"]) - 1) < 1e-9, r
        assert abs(float(r["pressure_from_stress"]) - 1) < 1e-9, r
    assert abs(s["contact"]["resultant"][1] - 4 * math.pi) < 1e-9 * 4 * math.pi


@pytest.fixture(scope="module")
def ball(hpcontact, root, tmp_path_factory):
    out = tmp_path_factory.mktemp("ball") / "b"
    return run(hpcontact, os.path.join(root, "examples/hertz/ball-on-flat.yaml"), out)


def test_ball_on_a_flat_is_3d_hertz(ball):
    """A steel ball (R = 10) on a rigid flat, F = 250 N: a/R = 0.02. The hp loop to 1e-4 from
    the 2x2 mesh: a and p0 within 0.1 % of 3-D Hertz (a = (3FR/4E*)^(1/3) = 0.20104, p0 =
    3F/(2πa²) = 2953.5, computed here), the pressure within 0.1 % in L2 over [0, 1.5 a].
    Measured +0.030 %, −0.076 % and 0.095 % with 2294 DOF (goal-oriented degrees; the tensor
    space, the default for axisymmetric bodies); the finite ball departs from the half space by
    about that much: at tolerance 1e-5 (4503 DOF) +0.030 %, −0.082 % and 0.098 %."""
    s, c = ball, ball["contact"]
    E_star = 210000 / (1 - 0.3 ** 2)
    a = (3 * 250 * 10 / (4 * E_star)) ** (1 / 3)
    p0 = 3 * 250 / (2 * math.pi * a * a)
    assert c["hertz_half_width"] == pytest.approx(a, rel=1e-12)
    assert c["hertz_peak_pressure"] == pytest.approx(p0, rel=1e-12)
    assert s["adapt"]["stopped"] == "tolerance reached"
    assert s["shape_space"] == "tensor"  # goal-oriented degrees keep the tensor space in axisymmetry
    print(f"ball a/R = 0.02: a {c['half_width']:.6g} (Hertz {a:.6g}), p_max {c['pressure_max']:.6g} "
          f"(Hertz {p0:.6g}), L2 {c['multiplier']['e_L2_hertz_percent']:.3g} %, {s['dofs']} DOF")
    assert abs(c["half_width"] / a - 1) < 1e-3
    assert abs(c["pressure_max"] / p0 - 1) < 1e-3
    assert c["multiplier"]["e_L2_hertz_percent"] < 0.1
    assert c["resultant"][1] == pytest.approx(250, rel=1e-9)
    assert c["closed_form"].startswith("Hertz, spheres")


def test_a_large_ball_load_departs_from_the_half_space(hpcontact, root, tmp_path):
    """a/R = 0.2 (F = 246154 N): the finite ball departs from Hertz's half space as the
    cylinder does; reported, and bounded (measured a −0.35 %, p_max −0.03 %, L2 0.72 %)."""
    s = run(hpcontact, os.path.join(root, "examples/hertz/ball-on-flat.yaml"), tmp_path / "big",
            "solver.target_resultant.value=246154", "adapt.tolerance=1e-3")
    c = s["contact"]
    da = c["half_width"] / c["hertz_half_width"] - 1
    dp = c["pressure_max"] / c["hertz_peak_pressure"] - 1
    print(f"ball a/R = 0.2: a {100 * da:+.3f} %, p_max {100 * dp:+.3f} %, "
          f"L2 {c['multiplier']['e_L2_hertz_percent']:.3g} % from Hertz")
    assert s["adapt"]["stopped"] == "tolerance reached"
    assert -2e-2 < da < 0 and -2e-2 < dp < 0


def test_shrink_fit_pressure_is_lames(hpcontact, root, tmp_path):
    """examples/lame/shrink-fit.yaml: a hub of bore a = 9.99 and outer radius b = 20 on a shaft
    of radius c = 10 (E = 210000, ν = 0.3, u_z = 0 on both faces): the interface pressure of
    exact contact, at every multiplier node and from the stresses, within 1e-6 of Lamé's
    (computed here; measured 2e-12). The hub's rows, which read the shaft's multipliers at their
    feet, report the same force per unit area of the hub's own bore, p c / a, as the hub's
    stresses do (measured 1e-12; before, p itself, 1e-3 off)."""
    s = run(hpcontact, os.path.join(root, "examples/lame/shrink-fit.yaml"), tmp_path / "sf")
    E, nu, a, b, c = 210000.0, 0.3, 9.99, 20.0, 10.0
    k = (1 + nu) / E
    hub = k * ((1 - 2 * nu) * a ** 3 + a * b * b) / (b * b - a * a) * c / a  # u_hub(a) per p
    shaft = -k * (1 - 2 * nu) * c                                             # u_shaft(c) per p
    p = (c - a) / (hub - shaft)
    with open(tmp_path / "sf" / "contact.csv") as f:
        rows = [r for r in csv.DictReader(f) if r.get("body", "shaft") == "shaft"]
    assert len(rows) >= 9
    for r in rows:
        assert abs(float(r["pressure"]) / p - 1) < 1e-6, (r["Y"], r["pressure"], p)
        assert abs(float(r["pressure_from_stress"]) / p - 1) < 1e-6
    with open(tmp_path / "sf" / "contact.csv") as f:
        bore = [r for r in csv.DictReader(f) if r["body"] == "hub"]
    assert len(bore) >= 9
    for r in bore:
        assert float(r["pressure"]) == pytest.approx(p * c / a, rel=1e-6), r["Y"]
        assert float(r["pressure_from_stress"]) == pytest.approx(p * c / a, rel=1e-6), r["Y"]
    # the total force on the shaft's face, 2π c h p, h = 4
    assert abs(s["contact"]["normal_force"]) == pytest.approx(2 * math.pi * c * 4 * p, rel=1e-6)
