"""A profile obstacle's points from a Gmsh file (contact[].obstacle.gmsh): the line elements of a
1D physical group chained end to end (tests/cli/data/groove-housing.geo, its .msh made by gmsh)."""
import json
import os

import pytest

GROOVE = "examples/o-ring/o-ring-profile-groove.yaml"
POINTS = "      points: [[-14, 20], [-11.3, 20], [-10.3, 19], [-10.3, 0], [10.3, 0], [10.3, 19], [11.3, 20], [14, 20]]"
FILLET = "      fillet: [0, 0, 0.4, 0.4, 0, 0]"


def groove_from(root, tmp_path, gmsh, fillet=None, name="case.yaml"):
    """The example with its housing's points replaced by `gmsh` (a flow map's inside)."""
    text = open(os.path.join(root, GROOVE)).read()
    assert text.count(POINTS) == 1 and text.count(FILLET) == 1
    msh = os.path.join(root, "tests", "cli", "data", "groove-housing.msh")
    text = text.replace(POINTS, "      gmsh: {file: '" + msh + "', " + gmsh + "}")
    if fillet is not None:
        text = text.replace(FILLET, "      fillet: " + fillet)
    path = tmp_path / name
    path.write_text(text)
    return path


def numbers(tree, prefix=""):
    """Every number of a summary.json, by its key path."""
    if isinstance(tree, dict):
        for k, v in tree.items():
            yield from numbers(v, prefix + "." + k)
    elif isinstance(tree, list):
        for i, v in enumerate(tree):
            yield from numbers(v, f"{prefix}[{i}]")
    elif isinstance(tree, (int, float)) and not isinstance(tree, bool):
        yield prefix, tree


def test_the_groove_from_gmsh_is_the_groove_from_points(hpcontact, root, tmp_path):
    """38 line elements (lines of at most 2 mm; the bottom two lines, one drawn right to left)
    chain into the example's 8 points — the 31 where the chain goes straight on left out — and
    the run equals the example's bit for bit: every number of summary.json but the times."""
    r = hpcontact("run", groove_from(root, tmp_path, "curve: housing"), "--out", tmp_path / "gmsh", "-q")
    assert r.returncode == 0, r.stderr
    r = hpcontact("run", os.path.join(root, GROOVE), "--out", tmp_path / "points", "-q")
    assert r.returncode == 0, r.stderr
    effective = (tmp_path / "gmsh" / "input.yaml").read_text()
    assert "curve 'housing': 8 points from 38 lines (31 where it goes straight on left out)" in effective
    assert POINTS in effective and "gmsh:" not in effective
    a = dict(numbers(json.load(open(tmp_path / "gmsh" / "summary.json"))))
    b = dict(numbers(json.load(open(tmp_path / "points" / "summary.json"))))
    timing = {k for k in a if "time" in k or k.endswith("_s")}
    assert a.keys() == b.keys()
    assert len(a) - len(timing) > 100
    assert {k: v for k, v in a.items() if k not in timing} == {k: v for k, v in b.items() if k not in timing}


def test_reverse_walks_the_chain_the_other_way_and_a_loop_is_closed(hpcontact, root, tmp_path):
    """Walked the other way, the housing has the ring on its right, inside the housing's
    material, which the input check says; a closed loop makes a closed profile."""
    r = hpcontact("check", groove_from(root, tmp_path, "curve: housing, reverse: true"))
    assert r.returncode == 1
    assert "inside profile(8 points from (14,20) to (-14,20))" in r.stderr, r.stderr
    # Drawn from right to left, the same points walk the other way by themselves.
    r = hpcontact("check", groove_from(root, tmp_path, "curve: drawn back", name="back.yaml"))
    assert r.returncode == 1
    assert "inside profile(8 points from (14,20) to (-14,20))" in r.stderr, r.stderr
    r = hpcontact("check", groove_from(root, tmp_path, "curve: drawn back, reverse: true", name="fore.yaml"))
    assert r.returncode == 0, r.stderr
    assert "against profile(8 points from (-14,20) to (14,20))" in r.stdout, r.stdout
    # The square loop (counter-clockwise: the ring inside it) is a closed profile of 4 corners.
    r = hpcontact("check", groove_from(root, tmp_path, "curve: box", fillet="0", name="box.yaml"))
    assert r.returncode == 0, r.stderr
    assert "against profile(closed, 4 points from (-30,-30) to (-30,30))" in r.stdout, r.stdout


@pytest.mark.parametrize("gmsh, fillet, where, message", [
    ("curve: branched", None, "contact[0].obstacle.gmsh.curve",
     "the lines of 'branched' in {msh} branch: 3 of them meet at node 5 at (0, 0) (an obstacle's "
     "boundary is one chain)"),
    ("curve: walls", None, "contact[0].obstacle.gmsh.curve",
     "the lines of 'walls' in {msh} are not one chain: they fall into pieces"),
    ("curve: grove", None, "contact[0].obstacle.gmsh.curve",
     "no line elements of a 1D physical group 'grove' in {msh} (defined: housing, walls, box, branched, drawn back)"),
    ("curve: box", "0\n      closed: false", "contact[0].obstacle.closed",
     "the lines of 'box' in {msh} close on themselves: leave closed out (it follows the chain)"),
    ("file: missing.msh, curve: housing", None, "contact[0].obstacle.gmsh.file", "missing.msh"),
])
def test_bad_gmsh_obstacles_are_refused_naming_the_key(hpcontact, root, tmp_path, gmsh, fillet, where, message):
    msh = os.path.join(root, "tests", "cli", "data", "groove-housing.msh")
    case = groove_from(root, tmp_path, gmsh, fillet)
    if gmsh.startswith("file: missing"):
        text = case.read_text().replace("file: '" + msh + "', file: missing.msh", "file: missing.msh")
        case.write_text(text)
    r = hpcontact("check", case)
    assert r.returncode != 0
    assert f"case.yaml:" in r.stderr and where in r.stderr, r.stderr
    assert message.format(msh=msh) in r.stderr, r.stderr


def test_gmsh_points_only_for_a_profile_or_curve_and_not_beside_points(hpcontact, root, tmp_path):
    msh = os.path.join(root, "tests", "cli", "data", "groove-housing.msh")
    case = groove_from(root, tmp_path, "curve: housing")
    text = case.read_text()
    plane = text.replace("      type: profile", "      type: plane", 1)
    (tmp_path / "plane.yaml").write_text(plane)
    r = hpcontact("check", tmp_path / "plane.yaml")
    assert r.returncode == 1
    assert "contact[0].obstacle.gmsh: gives the points of a profile or curve obstacle (got type: plane)" \
        in r.stderr, r.stderr
    both = text.replace("      gmsh: {", POINTS + "\n      gmsh: {", 1)
    (tmp_path / "both.yaml").write_text(both)
    r = hpcontact("check", tmp_path / "both.yaml")
    assert r.returncode == 1
    assert "contact[0].obstacle.points: give either gmsh or points, not both" in r.stderr, r.stderr


def test_a_second_gmsh_key_is_refused_not_dropped(hpcontact, root, tmp_path):
    """Two gmsh keys in one obstacle: only one could be expanded and the other would vanish
    unseen (the duplicate-key check runs after the expansion): refused naming the second's line."""
    case = groove_from(root, tmp_path, "curve: housing")
    text = case.read_text()
    line = next(ln for ln in text.splitlines() if ln.startswith("      gmsh: {"))
    (tmp_path / "two.yaml").write_text(text.replace(line, line + "\n" + line.replace("housing", "box"), 1))
    r = hpcontact("check", tmp_path / "two.yaml")
    assert r.returncode == 1
    second = text.splitlines().index(line) + 2
    assert f"two.yaml:{second}:7: contact[0].obstacle.gmsh: duplicate key" in r.stderr, r.stderr
