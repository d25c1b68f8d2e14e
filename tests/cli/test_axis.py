"""An axisymmetric body against its axis r = 0: contact edges on it refused, a radial motion
prescribed on it refused, a pair of an axisymmetric and a plane body refused, nodes put off it
by round-off taken as on it, an axis left free to move radially and a section whose deformed
shape crosses the axis warned about (check, run's stderr and summary.json)."""
import json
import os

import pytest

from conftest import expect_refused


@pytest.fixture
def ball(root):
    return os.path.join(root, "examples", "hertz", "ball-on-flat.yaml")


@pytest.fixture
def sphere(root):
    return os.path.join(root, "examples", "lame", "thick-sphere.yaml")


def test_a_contact_edge_on_the_axis_is_refused(hpcontact, ball, tmp_path):
    """The ball's axis edges as its contact edges: a line of the solid, no area to press on
    (accepted before, with pressures up to 1e16)."""
    expect_refused(hpcontact, ball, tmp_path, ["contact[0].edges=[symmetry]"],
                   "contact[0].edges: edge 1-4 of body 'ball' lies on the axis r = 0", 1)


def test_a_radial_motion_of_the_axis_is_refused(hpcontact, ball, tmp_path):
    expect_refused(hpcontact, ball, tmp_path, ["bodies[0].constraints[0].ux=0.1"],
                   "bodies[0].constraints[0].ux: prescribes u_r = 0.1 at node 1 of body 'ball' on "
                   "the axis r = 0", 1)


def test_an_axisymmetric_body_against_a_plane_one_is_refused(hpcontact, root, tmp_path):
    case = os.path.join(root, "examples", "lame", "shrink-fit.yaml")
    expect_refused(hpcontact, case, tmp_path, ["bodies[1].material.plane=strain"],
                   "contact[0].obstacle.body: body 'shaft' is axisymmetric and body 'hub' is a "
                   "plane section", 1)


def test_nodes_off_the_axis_by_round_off_are_on_it(hpcontact, sphere, tmp_path):
    """The sphere's axis nodes given at r = ±4e-16 (what fitting a node onto an arc leaves) and a
    point force along the axis on one of them: the same solution as at r = 0 exactly (refused
    before as 'x = r < 0' and as a ring load)."""
    force = ["bodies[0].nodal_forces=[{node: 6, force: [0, 500]}]"]
    runs = {}
    for name, sets in {"exact": force,
                       "rounded": force + ["bodies[0].nodes.5=[-4e-16, 10]",
                                           "bodies[0].nodes.6=[4e-16, 20]"]}.items():
        args = ["run", sphere, "--out", tmp_path / name, "-q"]
        for s in sets:
            args += ["--set", s]
        r = hpcontact(*args)
        assert r.returncode == 0, r.stderr
        runs[name] = json.loads((tmp_path / name / "summary.json").read_text())
    assert runs["rounded"]["strain_energy"] == pytest.approx(runs["exact"]["strain_energy"], rel=1e-12)
    assert runs["exact"]["strain_energy"] != pytest.approx(40 * 3.141592653589793, rel=1e-6)


def test_an_axis_free_to_move_radially_is_warned(hpcontact, ball, tmp_path):
    """Without u_r = 0 on the axis the hoop strain u_r / r is unbounded there: check and run say
    so, naming the body and the nodes; summary.json lists the warning; the run still succeeds."""
    free = ["--set", "bodies[0].constraints=[{edges: [centre], uy: -0.02}]", "--set", "adapt.method=none"]
    r = hpcontact("check", ball, *free)
    assert r.returncode == 0, r.stderr
    assert "warning: " in r.stdout and "ball-on-flat.yaml: bodies[0] (ball): 3 node(s) on the axis r = 0 (1, 4, 7) may move radially" in r.stdout
    r = hpcontact("run", ball, "--out", tmp_path / "free", "-q", *free)
    assert r.returncode == 0, r.stderr
    assert "hpcontact: warning: " in r.stderr and "(1, 4, 7) may move radially" in r.stderr
    s = json.loads((tmp_path / "free" / "summary.json").read_text())
    assert sum("(1, 4, 7) may move radially" in w for w in s["warnings"]) == 1
    # held on the axis: no warning about it (the coarse mesh's contact zone is another's)
    r = hpcontact("run", ball, "--out", tmp_path / "held", "-q", "--set", "adapt.method=none")
    assert r.returncode == 0 and "may move radially" not in r.stderr, r.stderr
    s = json.loads((tmp_path / "held" / "summary.json").read_text())
    assert not any("may move radially" in w for w in s.get("warnings", []))


def test_a_section_pulled_across_the_axis_is_warned(hpcontact, sphere, tmp_path):
    """A suction of 5e6 on the sphere's bore pulls its inner nodes (r = 7.07, 10) 200 mm inwards in
    linear elasticity: across the axis. The run says that this is beyond linear elasticity."""
    r = hpcontact("run", sphere, "--out", tmp_path, "-q", "--set", "bodies[0].loads[0].pressure=-5e6")
    assert r.returncode == 0, r.stderr
    assert "the deformed section crosses the axis r = 0 (node " in r.stderr
    s = json.loads((tmp_path / "summary.json").read_text())
    assert any("beyond linear elasticity" in w for w in s["warnings"])
