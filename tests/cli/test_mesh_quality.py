"""Mesh quality from the command line: `check` and `run` warn about needle elements along a
contact edge (naming the element and its ratio), and `run` about a contact zone far smaller than
the element edges that carry it; summary.json lists the warnings."""
import json
import os

BLOCK = """case: needle-block
bodies:
  - name: block
    material: {E: 1000, nu: 0.3, plane: strain}
    nodes: {1: [-5, 0], 2: [0, 0], 3: [5, 0], 4: [-5, DEPTH], 5: [0, DEPTH], 6: [5, DEPTH],
            7: [-5, 5], 8: [0, 5], 9: [5, 5]}
    elements: {1: [1, 2, 5, 4], 2: [2, 3, 6, 5], 3: [4, 5, 8, 7], 4: [5, 6, 9, 8]}
    edge_sets: {bottom: [[1, 2], [2, 3]], top: [[7, 8], [8, 9]]}
    constraints:
      - {edges: [top], ux: 0, uy: -0.01}
contact:
  - body: block
    edges: [bottom]
    obstacle: {type: plane, point: [0, 0], normal: [0, 1]}
discretization: {method: p, degree: 3}
"""


def test_check_warns_about_needles_along_a_contact_edge(hpcontact, tmp_path):
    """A bottom layer 5 wide and 0.05 deep on the contact edge: ratio 100, named; 1 deep: none."""
    case = tmp_path / "needle.yaml"
    case.write_text(BLOCK.replace("DEPTH", "0.05"))
    r = hpcontact("check", case)
    assert r.returncode == 0, r.stderr
    assert "needle.yaml: bodies[0] (block): 2 element(s) on a contact edge with the edge's length " \
           "over the element's depth above 10; the worst, element " in r.stdout, r.stdout
    assert ", has 100:" in r.stdout
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q")
    assert r.returncode == 0, r.stderr
    assert "hpcontact: warning: " in r.stderr and "on a contact edge" in r.stderr
    s = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert any("on a contact edge" in w for w in s["warnings"])
    case.write_text(BLOCK.replace("DEPTH", "1"))
    r = hpcontact("check", case)
    assert r.returncode == 0 and "warning" not in r.stdout, r.stdout


def test_a_contact_zone_within_one_coarse_edge_is_warned(hpcontact, root, tmp_path):
    """The ball on a flat on its 2×2 mesh without hp: the zone (a = 0.2) lies on one contact edge
    2.5 long. With hp the mesh is graded towards it: no warning."""
    ball = os.path.join(root, "examples", "hertz", "ball-on-flat.yaml")
    r = hpcontact("run", ball, "--out", tmp_path / "coarse", "-q", "--set", "adapt.method=none")
    assert r.returncode == 0, r.stderr
    assert "contact[0]: the contact zone (" in r.stderr and "lies on 1 contact edge(s) of body 'ball'" in r.stderr
    s = json.loads((tmp_path / "coarse" / "summary.json").read_text())
    assert any("lies on 1 contact edge(s)" in w for w in s["warnings"])
    r = hpcontact("run", ball, "--out", tmp_path / "hp", "-q", "--set", "adapt.tolerance=1e-2")
    assert r.returncode == 0, r.stderr
    assert "warning" not in r.stderr, r.stderr
