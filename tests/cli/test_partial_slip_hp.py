"""hp to a tolerance with friction (issue 22): examples/partial-slip/hp-tolerance.yaml (two
cylinders at b/R = 0.002 meshed in rings about the contact point, pressed, then sheared by
Q = mu P / 2) asked for 1.5 % instead of the example's 0.1 %. The tolerance holds the shear as well as the pressure: the loop goes on while
the shear's estimate is above it though the pressure's is below, and the result's shear is
within the tolerance of Cattaneo–Mindlin's closed form (the half-space is the model's answer
here to 0.086 % in the shear, 0.020 % in the pressure: examples/partial-slip/README.md), and the
estimate is the error against a finer run of the same model.

Measured: step 0 estimates the pressure at 0.82 % and the shear at 1.75 %; step 2 (2541 DOF)
0.37 % and 1.04 %, and its shear is 0.91 % from the closed form, the pressure 0.27 %."""
import json
import os
import re

import pytest
import yaml

from conftest import assert_hp_degree_rules, csv_rows, load_script, partial_slip_generator

compare = load_script("partial_slip_compare")
CASE = os.path.join("examples", "partial-slip", "hp-tolerance.yaml")
TOLERANCE = 1.5e-2


@pytest.fixture(scope="module")
def run(hpcontact, root, tmp_path_factory):
    out = tmp_path_factory.mktemp("partial-slip-hp")
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q",
                  "--set", f"adapt.tolerance={TOLERANCE}")
    assert r.returncode == 0, r.stderr
    assert_hp_degree_rules(out)
    return out, json.load(open(out / "summary.json"))


def larger(estimate):
    return max(estimate["pressure_rel_L2"], estimate["shear_rel_L2"])


def test_the_shear_is_held_to_the_tolerance(run):
    """Every step estimates the shear; the loop stops at the first step whose larger estimate is
    below the tolerance, and an earlier step had the pressure's below it and the shear's above
    (without the shear in the stopping test the loop would have ended there)."""
    _, s = run
    a = s["adapt"]
    assert a["converged"] and a["stopped"] == "tolerance reached"
    history = a["history"]
    assert all("shear_rel_L2" in h["estimated_error"] for h in history)
    assert larger(history[-1]["estimated_error"]) <= TOLERANCE
    assert all(larger(h["estimated_error"]) > TOLERANCE for h in history[:-1])
    assert any(h["estimated_error"]["pressure_rel_L2"] <= TOLERANCE < h["estimated_error"]["shear_rel_L2"]
               for h in history[:-1])
    assert a["estimated_error"] == history[-1]["estimated_error"]
    assert s["shape_space"] == "tensor"  # the default with friction


def test_the_comparison_reads_the_adapted_meshs_edges(run):
    """scripts/partial_slip_compare.py on the hp result (edges of different degrees): the
    own-points figures weigh the multiplier nodes edge by edge as the node-based ones do, and are
    the same numbers (before, the script stopped: "not blocks of p + 1")."""
    out, _ = run
    measured, _ = compare.measure(str(out))
    errors = compare.uniform_errors(str(out))
    assert errors["shear_rel_L2_own_points"] == pytest.approx(measured["shear_rel_L2"], rel=1e-12)
    assert errors["pressure_rel_L2_own_points"] == pytest.approx(measured["pressure_rel_L2"], rel=1e-12)


def test_the_result_is_within_the_tolerance_of_cattaneo_mindlin(run):
    """The shear and the pressure of the result against the closed forms: each within the
    tolerance (0.91 % and 0.27 % measured), the stick zone's half width within 2 % of c (0.7 %), the
    slip zones without oscillation, the Coulomb bound at every node."""
    out, s = run
    m, _ = compare.measure(str(out))
    assert m["dofs"] == s["dofs"]
    assert m["shear_rel_L2"] <= TOLERANCE
    assert m["pressure_rel_L2"] <= TOLERANCE
    assert abs(m["c_rel_error"]) < 0.02
    assert 0.95 < m["slip_tv_ratio"] < 1.05
    assert m["coulomb_ratio_max"] <= 1 + 1e-9


@pytest.fixture(scope="module")
def finer(hpcontact, root, tmp_path_factory):
    """The same loop taken to 3e-3 (4693 DOF, its shear estimated at 0.17 %)."""
    out = tmp_path_factory.mktemp("partial-slip-hp-finer")
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q", "--set", "adapt.tolerance=3e-3")
    assert r.returncode == 0, r.stderr
    assert_hp_degree_rules(out)
    return out


def test_the_estimate_is_the_error_against_a_finer_run_of_the_same_model(run, finer):
    """The loop's estimate (one degree more on the same mesh) against the error measured from the
    model's own answer: the result's shear and pressure against those of the same loop taken to
    3e-3 (partial_slip_compare --reference), whose own error is a fifth of the tested one's.
    Measured: shear 1.04 % estimated, 0.999 % against it; pressure 0.371 % and 0.324 %. (Against
    the loop to 3e-4 the estimates of every step from 2541 DOF on are within 7 % of the errors:
    examples/partial-slip/README.md, "Against the model's own answer".)"""
    out, s = run
    errors = compare.against_reference(compare.discrete_tractions(str(out)),
                                       compare.discrete_tractions(str(finer)))
    estimate = s["adapt"]["estimated_error"]
    assert json.load(open(finer / "summary.json"))["adapt"]["estimated_error"]["shear_rel_L2"] < 0.25 * estimate["shear_rel_L2"]
    assert 0.85 < estimate["shear_rel_L2"] / errors["shear_rel_L2_reference"] < 1.25, (estimate, errors)
    assert 0.85 < estimate["pressure_rel_L2"] / errors["pressure_rel_L2_reference"] < 1.4, (estimate, errors)


def test_facing_contact_edges_have_equal_degrees(finer):
    """On the loop's meshes the two cylinders' facing contact edges (the lower body is the upper
    one's mirror image, and hp refines both about the same points) have equal degrees: the
    goal-oriented corrections, learnt per element, gave them 8 and 6 side by side (at ±0.3 a and
    ±0.65 a from 4621 DOF on), which made the stick zone's shear oscillate once the degrees were
    raised further (0.84 % off, equal degrees 0.015 %). Every contact edge of the upper body
    faces one of the lower's here."""
    mesh = yaml.safe_load(open(finer / "mesh.yaml"))

    def contact_elements(body):
        b = mesh[body]
        out = []
        for edge in b["edge_sets"]["contact"]:
            element = next(e for e, nodes in b["elements"].items() if set(edge) <= set(nodes))
            x0, x1 = b["nodes"][edge[0]][0], b["nodes"][edge[1]][0]
            degree = b["degrees"][element]
            out.append((min(x0, x1), max(x0, x1), degree[0] if isinstance(degree, list) else degree))
        return out
    upper, lower = contact_elements("upper"), contact_elements("lower")
    assert len(upper) >= 30
    for x0, x1, p in upper:
        facing = [q for y0, y1, q in lower if min(x1, y1) - max(x0, y0) > 0.5 * min(x1 - x0, y1 - y0)]
        assert len(facing) == 1 and facing[0] == p, (x0, x1, p, facing)


def test_under_force_control_every_step_has_goal_oriented_weights(hpcontact, root, tmp_path):
    """Pressed by a force through the stages (solver.target_resultant), the loop's adjoint is
    bordered with the force held; each step that learns degrees says which weights its indicators
    had. Until stop 37 its solve failed at every step here and the summary did not say so (the
    energy surplus alone ranked the elements: 13295 DOF for 0.136 % at the example's 0.1 %)."""
    out = tmp_path / "force"
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q",
                  "--set", "solver.target_resultant={value: 7}", "--set", f"adapt.tolerance={TOLERANCE}")
    assert r.returncode == 0, r.stderr
    assert_hp_degree_rules(out)
    a = json.load(open(out / "summary.json"))["adapt"]
    assert a["converged"]
    learnt = [h["degrees"] for h in a["history"] if "degrees" in h]
    assert learnt and all(d["weights"] == "goal-oriented" for d in learnt), learnt


def test_a_shear_above_the_friction_capacity_is_said(hpcontact, root, tmp_path):
    """Q = 2.2 on the cylinders pressed to 7 with mu = 0.3 (capacity 2.1): every point slips at
    the last load steps and the upper body is held by nothing in x; the run fails saying so, the
    capacity named, and writes no summary."""
    out = tmp_path / "gross"
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q", "--set", "adapt.method=none",
                  "--set", "bodies[0].loads[0].resultant=2.2", "--set", "bodies[1].loads[0].resultant=2.2")
    assert r.returncode == 1, r.stderr
    assert "body 'upper' is held only by contact against translation in x" in r.stderr, r.stderr
    assert "a tangential load above the friction's capacity, mu times the normal force" in r.stderr
    assert not (out / "summary.json").exists()


def test_pressed_only_the_tolerance_holds_the_pressure(hpcontact, root, tmp_path):
    """The same cylinders pressed and not sheared carry almost no shear (none in the linear
    theory: equal bodies), a numerical rest whose error relative to its own size stays between
    0.7 and 3 at every step (measured at 1e-3: 0.68, 1.0, 2.0, 1.1, 0.94, 1.9, 2.9 in six steps, the
    pressure's 2.3e-5 at the last, and no end); below 1 % of the friction's capacity μ‖p‖ its
    error counts against the pressure's size, and the loop ends at the tolerance with the pressure
    within it of Hertz's."""
    tolerance = 3e-3
    out = tmp_path / "pressed"
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q",
                  "--set", "solver.stages=[{displacements: 1, loads: 0, steps: 1}]",
                  "--set", f"adapt.tolerance={tolerance}")
    assert r.returncode == 0, r.stderr
    assert_hp_degree_rules(out)
    a = json.load(open(out / "summary.json"))["adapt"]
    assert a["converged"] and a["stopped"] == "tolerance reached"
    assert larger(a["estimated_error"]) <= tolerance
    rows = [row for row in csv_rows(out / "contact.csv") if float(row["pressure"]) > 0]
    shear = sum(float(row["tangential_traction"]) ** 2 for row in rows) ** 0.5
    capacity = sum((0.3 * float(row["pressure"])) ** 2 for row in rows) ** 0.5
    assert shear < 0.01 * capacity  # incidental: what the rule is for
    m, _ = compare.measure(str(out))
    assert m["pressure_rel_L2"] <= tolerance, m["pressure_rel_L2"]


def test_a_solve_that_fails_inside_the_loop_is_named_and_the_best_step_kept(hpcontact, root,
                                                                              tmp_path):
    """Newton held to 10 iterations without cuts: a later step's solve (here step 4's; at 14
    iterations step 3's estimate failed until each step of a finer solve started from the
    coarser solve's state at that step) does not converge. The message names the step and which of its solves
    failed, after the problem file, and the step whose result last-good/ holds (hp calls them
    steps, not iterations); last-good's summary says the same step."""
    out = tmp_path / "r"
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q", "--set",
                  "solver.max_iterations=10", "--set", "solver.max_cuts=0")
    assert r.returncode == 1
    m = re.search(r"hp-tolerance\.yaml: hp step (\d+)(, its estimate \(one degree more\))?: the "
                  r"solver stopped: .*; the last good result \(step (\d+)\) is in", r.stderr)
    assert m, r.stderr
    failed, kept = int(m.group(1)), int(m.group(3))
    assert 0 < failed and kept <= failed
    a = json.load(open(out / "last-good" / "summary.json"))["adapt"]
    assert a["stopped"] == "error" and a["result_step"] == kept
    assert f"hp-tolerance.yaml: hp step {failed}" in a["message"]


def test_the_example_is_what_the_generator_writes(root):
    """The example's header names the command that made it; that command writes it again."""
    text = open(os.path.join(root, CASE)).read()
    args = text.splitlines()[0].split("partial_slip_mesh.py ", 1)[1].split()
    r = partial_slip_generator(root, *args)
    assert r.returncode == 0, r.stderr
    assert r.stdout == text


def test_rings_too_large_for_the_contact_zone_are_refused(root):
    """At the seed's load (a = 0.2 R) a second ring at 3a lies beyond R/2: one ring only, and its
    contact edges would end at a, where the zone ends (an hp run from it failed at its first
    step). Refused naming the option and the largest ratio; a ratio within it gives contact
    edges that reach beyond a."""
    r = partial_slip_generator(root, "--force", "70000", "--mesh", "polar")
    assert r.returncode == 2
    assert "--ring-ratio" in r.stderr and "2.54" in r.stderr and "R/2" in r.stderr
    r = partial_slip_generator(root, "--force", "70000", "--mesh", "polar", "--ring-ratio", "2.5")
    assert r.returncode == 0, r.stderr
    upper = yaml.safe_load(r.stdout)["bodies"][0]
    xs = [upper["nodes"][n][0] for e in upper["edge_sets"]["contact"] for n in e]
    assert max(xs) > 2 * 1.965 and min(xs) < -2 * 1.965
