"""A steel roller (R = 15) on an aluminium block with Coulomb friction (mu = 0.1), coarse Gmsh
meshes, the roller touching the block at one point in the input (no overlap) and held in x by
nothing but friction: pressed by force control to P = 1000 N/mm, then sheared by Q = 50 N/mm
(tests/cli/data/roller-block-friction/, p = 8).

Before, the first Newton iteration found no multiplier node active — the mortar-weighted gap of
the node touching at (0, 0) is positive where the arc rises from it (2.9e-4 mm) — and the
tangent was singular ("held only by contact against translation in x"). A node touching at its
own point now starts active (ContactSystem::activate_touching)."""
import json
import math
import os

import pytest

CASE = os.path.join("tests", "cli", "data", "roller-block-friction", "roller-block-friction.yaml")
E_STAR = 1 / ((1 - 0.3 ** 2) / 210000 + (1 - 0.33 ** 2) / 70000)
B_HERTZ = math.sqrt(4 * 1000 * 15 / (math.pi * E_STAR))  # two-body Hertz, R* = 15: 0.5709


def run(hpcontact, root, out, *settings):
    args = ["run", os.path.join(root, CASE), "--out", out, "-q"]
    for s in settings:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


def test_pressed_and_sheared_from_a_one_point_touch(hpcontact, root, tmp_path):
    """Both stages converge (11 Newton iterations measured; at most 20), the contact carries
    P = 1000 and Q = 50 to 1e-8, and the shear moves the zone sideways (its ends no longer
    symmetric: 7e-3 b measured, at least 1e-3 b)."""
    s = run(hpcontact, root, tmp_path / "sheared")
    pair = s["contact_pairs"][0]
    assert s["newton_iterations_total"] <= 20
    assert pair["normal_force"] == pytest.approx(1000, rel=1e-8)
    assert abs(pair["tangential_force"]) == pytest.approx(50, rel=1e-8)
    zone = pair["zone"]
    assert abs(zone["from"] + zone["to"]) > 1e-3 * B_HERTZ


def test_pressed_zone_is_symmetric(hpcontact, root, tmp_path):
    """The pressing stage alone: the zone's ends symmetric to 1e-6 of b (1.3e-9 measured). On
    this coarse mesh the zone lies inside one element and its half width is 6.3 % below two-body
    Hertz's b at p = 8 (−2.0 % at p = 6, +13 % at p = 10): within 10 % here; the issue's 1 % needs
    hp (test_the_example_pressed_by_hp_to_1e2: −0.21 %)."""
    s = run(hpcontact, root, tmp_path / "pressed", "solver.stages=[{displacements: 1, loads: 0}]")
    zone = s["contact_pairs"][0]["zone"]
    assert abs(zone["from"] + zone["to"]) <= 1e-6 * B_HERTZ
    assert zone["to"] == pytest.approx(B_HERTZ, rel=0.10)


def test_hp_gives_each_end_of_a_zone_around_one_node_its_own(hpcontact, root, tmp_path):
    """hp, one step, from the default degree (p = 4): the coarse solve's zone (ends at -0.518 / +0.515 on the roller) lies in the
    two elements at the node where the bodies touch, nearest to both ends. Zone resolution
    refines towards that node on both bodies (the contact point, once each), and hp step 1 has
    a refinement centre at both ends of each body. Before, the node served one end (the other
    left in an element 5.7 mm long) and, moved off the contact point, left no node active: hp
    step 1's tangent was singular."""
    s = run(hpcontact, root, tmp_path / "hp", "adapt={method: hp, steps: 1}",
            "discretization={method: p, degree: 4}")
    first, second = s["adapt"]["history"]
    assert first["resolve_rounds"] == 1
    assert len(first["resolved_towards"]) == 2
    assert all(math.hypot(*X) < 1e-9 for X in first["resolved_towards"])
    ends = [X for X in second["centres"] if abs(X[0]) > 0.4]
    assert len(ends) == 4  # both ends, on the roller and on the block
    assert sorted(X[0] > 0 for X in ends) == [False, False, True, True]


EXAMPLE = os.path.join("examples", "roller-block", "friction", "roller-block-friction.yaml")


def run_example(hpcontact, root, out, *settings):
    args = ["run", os.path.join(root, EXAMPLE), "--out", out, "-q"]
    for s in settings:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


def test_the_example_pressed_by_hp_to_1e2(hpcontact, root, tmp_path):
    """The example (coarse Gmsh meshes, no overlap, defaults) pressed alone, hp to 1e-2 by
    itself: the zone's ends symmetric to 1e-3 of b (6e-9 measured) and within 1 % of two-body
    Hertz (−0.21 % measured, hp step 4, 4195 DOF, 8 s)."""
    s = run_example(hpcontact, root, tmp_path / "pressed", "solver.stages=[{displacements: 1, loads: 0}]")
    assert s["adapt"]["stopped"] == "tolerance reached"
    zone = s["contact_pairs"][0]["zone"]
    assert abs(zone["from"] + zone["to"]) <= 1e-3 * B_HERTZ
    assert zone["to"] == pytest.approx(B_HERTZ, rel=0.01)
    assert -zone["from"] == pytest.approx(B_HERTZ, rel=0.01)


@pytest.mark.slow
def test_the_example_pressed_and_sheared_by_hp_to_1e2(hpcontact, root, tmp_path):
    """The whole example, pressed then sheared by half the capacity: hp reaches 1e-2 by itself
    (hp step 5, 7635 DOF: pressure 0.17 %, shear 0.53 % estimated; 88 s CPU idle, 2026-12-07).
    Each step of a finer solve starts from the coarser solve's state at that step
    (StartState::path); before, the loop never got below 2 % (shear 2.8 %) and failed at step 4."""
    s = run_example(hpcontact, root, tmp_path / "sheared")
    a = s["adapt"]
    assert a["stopped"] == "tolerance reached"
    e = a["history"][a["result_step"]]["estimated_error"]
    assert max(e["pressure_rel_L2"], e["shear_rel_L2"]) <= 1e-2
    pair = s["contact_pairs"][0]
    assert pair["normal_force"] == pytest.approx(1000, rel=1e-8)
    assert abs(pair["tangential_force"]) == pytest.approx(50, rel=1e-8)
