"""Driving a frictional problem: stages with factors per direction (a displacement-driven
tangential stage with the press held), the load path friction remembers, and force control with
friction (force-controlled load steps, the factor an unknown of each). Every figure is checked
against an exact state: the homogeneous one of a block on a plane, or full slip at mu P."""
import json
import os

import numpy as np
import pytest

from conftest import csv_rows, expect_refused, partial_slip_generator

DATA = os.path.join(os.path.dirname(__file__), "data")
PATCH = os.path.join(DATA, "block-shear-patch.yaml")
PRESS_PUSH = os.path.join(DATA, "block-press-push.yaml")


def run(hpcontact, case, out, *settings):
    args = ["run", case, "--out", out, "-q"]
    for s in settings:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.load(open(os.path.join(out, "summary.json")))


@pytest.mark.parametrize("degree", [1, 3, 6])
def test_tangential_stage_reproduces_the_homogeneous_state(hpcontact, tmp_path, degree):
    """Pressed, then sheared by a displacement-driven stage: pressure E eps = 10, |t_T| = G gamma
    = 2 below mu p (stick), no point moved along the plane; the path's factors per direction."""
    s = run(hpcontact, PATCH, tmp_path, f"discretization.degree={degree}")
    points = csv_rows(tmp_path / "contact.csv")
    assert len(points) > 2
    for p in points:
        assert float(p["pressure"]) == pytest.approx(10, rel=1e-10)
        assert float(p["pressure_from_stress"]) == pytest.approx(10, rel=1e-9)
        assert abs(float(p["tangential_traction"])) == pytest.approx(2, rel=1e-10)
        assert float(p["x"]) == pytest.approx(float(p["X"]), abs=1e-12)
        assert p["state"] == "stick"
    # the force on the block: the plane pushes up by p W, and back against the push by tau W
    assert s["contact"]["resultant"] == pytest.approx([-4, 20], rel=1e-10)
    path = csv_rows(tmp_path / "path.csv")
    assert [float(r["displacement_factor_x"]) for r in path] == [0, 0, 0.5, 1]
    assert [float(r["displacement_factor_y"]) for r in path] == [0.5, 1, 1, 1]
    # pressed, not yet pushed: no tangential force
    assert float(path[1]["resultant_x"]) == pytest.approx(0, abs=1e-12)
    assert float(path[1]["resultant_y"]) == pytest.approx(20, rel=1e-10)


def test_the_load_path_matters(hpcontact, tmp_path):
    """Press then push: the base slides with |t_T| = mu p, the friction force -mu P. Push first
    (nothing presses, the block slides freely), then press: no tangential force at all."""
    s = run(hpcontact, PRESS_PUSH, tmp_path / "press-push")
    assert s["contact"]["normal_force"] == pytest.approx(20, rel=1e-10)
    assert s["contact"]["resultant"][0] == pytest.approx(-0.3 * 20, rel=1e-10)
    for p in csv_rows(tmp_path / "press-push" / "contact.csv"):
        assert p["state"] == "slip"
        assert abs(float(p["tangential_traction"])) == pytest.approx(0.3 * float(p["pressure"]), rel=1e-9)
    s = run(hpcontact, PRESS_PUSH, tmp_path / "push-press",
            "solver.stages[0].displacements_x=1", "solver.stages[0].displacements_y=0")
    assert s["contact"]["normal_force"] == pytest.approx(20, rel=1e-10)
    assert s["contact"]["resultant"][0] == pytest.approx(0, abs=1e-9)


def test_slip_is_the_path_total(hpcontact, tmp_path):
    """contact.csv's `slip` of exact friction: the nodes' slips of every step added up, against
    the homogeneous sliding state. The shear patch block is pressed (p = 10), then its top is
    pushed to u = 0.006 with its sides carrying the shear mu p = 3 (the base sticks, on the
    cone), then on to u = 0.01 in three steps with the shear held: the block slides, sheared by
    gamma = 3 / G = 0.006, so its base slid 0.004 along the plane's tangent (+x) at every node,
    0.004 / 3 in the last step (`tangential_gap`)."""
    text = open(PATCH).read()
    for old, new in (("ux: 0.004", "ux: 0.01"), ("traction: [0, -2]", "traction: [0, -3]"),
                     ("traction: [0, 2]", "traction: [0, 3]"),
                     ("    - {displacements: 1, loads: 1, steps: 2}",
                      "    - {displacements_x: 0.6, displacements_y: 1, loads: 1, steps: 1}\n"
                      "    - {displacements: 1, loads: 1, steps: 3}")):
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    case = tmp_path / "slide.yaml"
    case.write_text(text)
    run(hpcontact, str(case), tmp_path / "slide")
    points = csv_rows(tmp_path / "slide" / "contact.csv")
    assert len(points) >= 7
    for p in points:
        assert p["state"] == "slip" and float(p["tangent_x"]) == 1
        assert float(p["pressure"]) == pytest.approx(10, rel=1e-9)
        assert abs(float(p["tangential_traction"])) == pytest.approx(3, rel=1e-9)
        assert float(p["slip"]) == pytest.approx(0.004, rel=1e-9)
        assert float(p["tangential_gap"]) == pytest.approx(0.004 / 3, rel=1e-9)


def undeformed_at(points, x):
    """The undeformed X of a body's boundary where it is deformed to x, interpolated between its
    contact.csv points (the bodies' deformation is nearly affine here)."""
    points = sorted(points, key=lambda p: float(p["x"]))
    return float(np.interp(x, [float(p["x"]) for p in points], [float(p["X"]) for p in points]))


def test_the_other_bodys_rows_slip_as_the_pair_does(hpcontact, tmp_path):
    """contact.csv's slips of an exact pair's other body (read at each point's foot between the
    pair's nodes) against the motion itself: the shear patch block slid by 0.004 along an elastic
    foundation (tests/cli/data/block-on-foundation-slide.yaml; the foundation ends with the block,
    so the state is homogeneous only away from the ends: pressure 9.8-10.3). A point slid, over
    the path, by the distance between the material points of the two bodies that now face each
    other: slip = X_foundation - X_block (both undeformed) at a common deformed position. Both
    bodies' rows hold this to 2e-5 (measured 2.2e-6 on the block's, 1.9e-5 on the foundation's
    next to the overhang's corner, where they were 0), the last of the three equal steps a third
    of it, both along t_T."""
    run(hpcontact, os.path.join(DATA, "block-on-foundation-slide.yaml"), tmp_path)
    points = csv_rows(tmp_path / "contact.csv")
    block = [p for p in points if p["body"] == "block"]
    foundation = [p for p in points if p["body"] == "foundation"]
    assert len(block) == 7 and len(foundation) > 50
    assert all(p["state"] == "slip" for p in block)
    lo = max(min(float(p["x"]) for p in side) for side in (block, foundation))
    hi = min(max(float(p["x"]) for p in side) for side in (block, foundation))
    checked = 0
    for own, other, sign in ((block, foundation, 1), (foundation, block, -1)):
        for p in own:
            x = float(p["x"])
            if not lo <= x <= hi:
                continue
            # the block's end overhangs the foundation's by 0.005 (its points there measured
            # against the foundation's end, DeformableBoundary::free_end): the rows within 0.01
            # of it, at the corner's singular point, are left out (slip and motion 2.0e-5 apart),
            # and within 0.3 of it the overhang bends both bodies (slid up to 0.0044)
            if x > hi - 0.01:
                continue
            slid = sign * (undeformed_at(other, x) - float(p["X"]))
            if x < hi - 0.3:
                assert slid == pytest.approx(0.004, rel=0.05)
            assert float(p["slip"]) == pytest.approx(slid, abs=2e-5), p
            assert float(p["tangential_gap"]) == pytest.approx(float(p["slip"]) / 3, rel=1e-2)
            assert float(p["tangential_gap"]) * float(p["tangential_traction"]) > 0
            checked += 1
    assert checked > 50


def force_controlled(tmp_path):
    """The press-push block under force control: its top's displacement scaled to P = 20."""
    case = tmp_path / "force.yaml"
    head, _, _ = open(PRESS_PUSH).read().partition("solver:")
    case.write_text(head + "solver:\n  load_steps: 4\n  target_resultant: {value: 20, component: y}\n")
    return case


def test_force_control_with_friction(hpcontact, tmp_path):
    """target_resultant with friction: force-controlled load steps reach the force (5, 10, 15,
    20: each step its share) and the state of the displacement-controlled path to the same
    factor (the slip at mu p, as the path of both components together prescribes it)."""
    settings = ["solver.stages[0].displacements_x=1", "solver.stages[0].steps=4"]
    shown = run(hpcontact, PRESS_PUSH, tmp_path / "displacement", *settings)
    forced = run(hpcontact, force_controlled(tmp_path), tmp_path / "force")
    assert forced["load_factor"] == pytest.approx(1, rel=1e-9)
    assert [float(r["resultant_y"]) for r in csv_rows(tmp_path / "force" / "path.csv")] == \
        pytest.approx([5, 10, 15, 20], rel=1e-9)
    assert forced["contact"]["resultant"] == pytest.approx(shown["contact"]["resultant"], rel=1e-9)
    a = csv_rows(tmp_path / "force" / "contact.csv")
    b = csv_rows(tmp_path / "displacement" / "contact.csv")
    assert len(a) == len(b)
    for p, q in zip(a, b):
        assert float(p["tangential_traction"]) == pytest.approx(float(q["tangential_traction"]), rel=1e-8)
        assert float(p["x"]) == pytest.approx(float(q["x"]), rel=1e-8, abs=1e-12)


def test_friction_on_a_curved_obstacle_from_a_symmetry_line(hpcontact, root, tmp_path):
    """Hertz p5 pressed onto a rigid disc with Coulomb friction under force control (the
    defaults: collocation at the nodes). The first node touching is the one on the symmetry line,
    whose slip along the disc no unknown moves (u_x is held there): its stick row was zero to
    round-off and every step failed as singular. Now its tangential multiplier is the support's,
    pinned to 0; the run converges with the target force, the friction sticks inside and slips
    outside, on the Coulomb bound there and within it everywhere."""
    mu = 0.3
    s = run(hpcontact, os.path.join(root, "examples/hertz/p5.yaml"), tmp_path,
            "contact[0].obstacle={type: circle, center: [0, -50], radius: 50}",
            f"contact[0].friction={{law: coulomb, mu: {mu}}}")
    assert s["converged"] and abs(s["contact"]["resultant"][1] - 35000) < 35
    points = csv_rows(tmp_path / "contact.csv")
    axis = min(points, key=lambda p: abs(float(p["X"])))
    assert float(axis["X"]) < 1e-12 and float(axis["tangential_traction"]) == 0
    # t_T and the normal multiplier `traction` are both per unit undeformed length
    p_max = max(float(p["traction"]) for p in points)
    states = {p["state"] for p in points}
    assert {"stick", "slip", "open"} <= states, states
    for p in points:
        t, pn = abs(float(p["tangential_traction"])), float(p["traction"])
        assert t <= mu * pn * (1 + 1e-9) + 1e-9 * p_max, p
        if p["state"] == "slip":
            assert t == pytest.approx(mu * pn, rel=1e-9)
    assert max(abs(float(p["tangential_traction"])) for p in points) > 0.1 * mu * p_max


@pytest.mark.parametrize("settings, message, code", [
    # given on the command line: a command-line mistake (exit 2)
    (["solver.stages[0].displacements=1"],
     "solver.stages[0].displacements (from --set): displacements_x and displacements_y are both given", 2),
    (["contact[0].enforcement=penalty", "contact[0].friction.penalty=1e6", "contact[0].penalty=1e6"],
     "force control with friction needs the first contact pair enforced exactly", 1),
])
def test_contradicting_load_paths_are_refused(hpcontact, tmp_path, settings, message, code):
    case = PRESS_PUSH if code == 2 else force_controlled(tmp_path)
    expect_refused(hpcontact, str(case), str(tmp_path / "out"), settings, message, code)


def partial_slip_mesh(root, tmp_path, *args):
    """A partial-slip problem file of scripts/partial_slip_mesh.py (two cylinders, R = 10)."""
    case = tmp_path / "partial-slip.yaml"
    r = partial_slip_generator(root, *args)
    assert r.returncode == 0, r.stderr
    case.write_text(r.stdout)
    return case


def test_force_control_through_stages(hpcontact, root, tmp_path):
    """Two cylinders pressed to P = 7 by force control, then sheared by Q = mu P / 2 with P held
    (target_resultant with stages: each stage's displacements the share of P it reaches). Every
    step of the press carries its share of P and every step of the shear P itself, with the
    tangential force growing as the loads do; the state is the displacement-driven path's at the
    factors force control found (stage by stage: the push that gave P at the end of each)."""
    case = partial_slip_mesh(root, tmp_path, "--force", "7", "--mesh", "polar", "--degree", "3")
    stages = ["solver.stages=[{displacements: 0.5, loads: 0, steps: 1}, {displacements: 1, loads: 0, steps: 1},"
              " {displacements: 1, loads: 1, steps: 2}]"]
    forced = run(hpcontact, str(case), tmp_path / "force", "solver.target_resultant={value: 7}", *stages)
    path = csv_rows(tmp_path / "force" / "path.csv")
    assert [float(r["resultant_y"]) for r in path] == pytest.approx([3.5, 7, 7, 7], rel=1e-9)
    assert [float(r["load_factor"]) for r in path] == [0, 0, 0.5, 1]
    assert [float(r["resultant_x"]) for r in path] == pytest.approx([0, 0, -0.525, -1.05], rel=1e-9, abs=1e-9)
    pair = forced["contact_pairs"][0]
    assert pair["normal_force"] == pytest.approx(7, rel=1e-9)
    assert pair["tangential_force"] == pytest.approx(-1.05, rel=1e-9)
    alpha = [float(r["displacement_factor"]) for r in path]
    assert forced["load_factor"] == pytest.approx(alpha[-1], rel=1e-12)
    # the push found differs from the generator's (its P from the half-space) and moves as the
    # shear is applied (the pressure on the tilted interface carries part of Q)
    assert abs(alpha[-1] - 1) > 1e-5 and alpha[-1] != alpha[1]
    # the same path driven by the displacements, stage by stage at the factors found
    shown = run(hpcontact, str(case), tmp_path / "displacement",
                f"solver.stages=[{{displacements: {alpha[0]!r}, loads: 0, steps: 1}},"
                f" {{displacements: {alpha[1]!r}, loads: 0, steps: 1}},"
                f" {{displacements: {alpha[3]!r}, loads: 1, steps: 2}}]")
    assert shown["contact_pairs"][0]["normal_force"] == pytest.approx(7, rel=1e-7)
    a = csv_rows(tmp_path / "force" / "contact.csv")
    b = csv_rows(tmp_path / "displacement" / "contact.csv")
    assert len(a) == len(b) and len(a) > 20
    scale = max(abs(float(p["pressure"])) for p in a)
    for p, q in zip(a, b):
        assert p["state"] == q["state"]
        for key in ("pressure", "tangential_traction"):
            assert float(p[key]) == pytest.approx(float(q[key]), abs=1e-6 * scale), (key, p, q)


@pytest.mark.parametrize("settings, message, code", [
    # force control scales one factor on all the prescribed displacements: no per-direction shares
    ([], "block-press-push.yaml:26:25: solver.stages[0].displacements_x: under solver.target_resultant "
         "a stage's displacements is the share of the target force", 1),
    (["solver.stages=[{displacements: -0.5, steps: 2}, {displacements: 1, steps: 1}]"],
     "solver.stages[0].displacements (from --set): under solver.target_resultant this is the share "
     "of the target force the stage reaches, not negative", 2),
    (["solver.stages=[{displacements: 1, steps: 2}, {displacements: 0.5, steps: 1}]"],
     "solver.stages[1].displacements (from --set): under solver.target_resultant the last stage "
     "reaches the target force", 2),
    (["solver.stages=[{displacements: 1, steps: 2}]", "contact[0].enforcement=penalty",
      "contact[0].friction={law: stick, penalty: 1e6}", "contact[0].penalty=1e6"],
     "force control with friction needs the first contact pair enforced exactly", 1),
    (["solver.stages=[{displacements: 1, steps: 2}]", "contact[0].enforcement=penalty",
      "contact[0].friction={law: none}", "contact[0].penalty=1e6"],
     "target_resultant with stages needs the first contact pair enforced exactly", 1),
])
def test_stages_under_force_control_are_shares_of_the_target(hpcontact, tmp_path, settings, message, code):
    expect_refused(hpcontact, PRESS_PUSH, str(tmp_path / "out"),
                   ["solver.target_resultant={value: 20}", *settings], message, code)


def test_a_shear_at_the_friction_capacity_stops_at_the_shortest_step(hpcontact, root, tmp_path):
    """Pressed to P = 7 by force control, then sheared by Q = mu P exactly: the load cannot be
    carried to its end (at the capacity the bodies may slide). The steps are halved at most
    solver.max_cuts times in all, not in a row (before, the shear crept 0.75, 0.875, ..., 0.9995
    of Q by ever shorter steps); the message says that the load cannot be carried beyond the
    last converged step and how much of the friction's capacity the pair carries there."""
    case = partial_slip_mesh(root, tmp_path, "--force", "7", "--mesh", "polar", "--degree", "3")
    text = case.read_text()
    assert text.count("resultant: 1.05}") == 2  # Q = mu P / 2 on each cut
    case.write_text(text.replace("resultant: 1.05}", "resultant: 2.1}"))
    out = tmp_path / "out"
    r = hpcontact("run", case, "--out", out, "-q", "--set", "solver.target_resultant={value: 7}",
                  "--set", "solver.stages=[{displacements: 0.5, loads: 0, steps: 1},"
                  " {displacements: 1, loads: 0, steps: 1}, {displacements: 1, loads: 1, steps: 2}]")
    assert r.returncode == 1, r.stderr
    assert "the load cannot be carried beyond the last converged step" in r.stderr, r.stderr
    assert "1/32 of a load step (solver.max_cuts = 5 halvings)" in r.stderr, r.stderr
    share = float(r.stderr.split("contact[0] carries ")[1].split(" %")[0])
    assert 90 <= share < 100
    good = json.load(open(out / "last-good" / "summary.json"))
    assert not good["converged"]
    path = csv_rows(out / "last-good" / "path.csv")
    loads = [float(row["load_factor"]) for row in path]
    # the shear's stage in two steps of 1/2, each halved at most 5 times: no step shorter than
    # 1/64 of the shear, so at most 1 - 1/64 reached and a bounded number of steps
    assert 0.9 < loads[-1] <= 1 - 1 / 64 + 1e-12
    assert all(b - a >= 1 / 64 - 1e-12 for a, b in zip(loads[2:], loads[3:]))
    assert len(path) <= 12
    # the share said is the last converged step's: |Q| / (mu P) from its path row
    last = path[-1]
    assert abs(float(last["resultant_x"])) / (0.3 * abs(float(last["resultant_y"]))) == pytest.approx(
        share / 100, rel=1e-3)
