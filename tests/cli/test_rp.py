"""The rp-version on the Hertz examples (seed §4.8, Table 5.1 rp rows): node A moves along the
exact arc onto the end of the contact zone until the two coincide; what it buys is measured
against the p-version on the same mesh and our overkill reference."""
import json
import math
import os

import pytest

HERTZ = "examples/hertz"


def run(hpcontact, root, name, out, *sets):
    args = ["run", os.path.join(root, HERTZ, name), "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    return r, (json.loads((out / "summary.json").read_text())
               if (out / "summary.json").exists() else None)


@pytest.fixture(scope="module")
def rp5(hpcontact, root, tmp_path_factory):
    out = tmp_path_factory.mktemp("rp5")
    r, s = run(hpcontact, root, "rp5.yaml", out)
    assert r.returncode == 0, r.stderr
    return out, s


def test_rp5_reaches_gamma_star(rp5):
    """From node A 26 % beyond b (x = 2.48) to Γ* within the tolerance (1e-10 of the body size)
    in at most the seed's 20 iterations; every iteration recorded; force control still exact."""
    out, s = rp5
    a = s["adapt"]
    assert s["method"] == "rp" and a["converged"] is True
    assert 1 <= a["iterations"] <= 20
    hist = a["history"]
    assert len(hist) == a["iterations"] + 1
    assert hist[0]["nodes"][0]["node"] == 2
    assert hist[0]["nodes"][0]["position"] == pytest.approx([2.48, 10 - math.sqrt(100 - 2.48**2)],
                                                             abs=1e-9)
    assert hist[-1]["distance"] <= 1e-10 < hist[0]["distance"]
    for h in hist:
        assert h["dofs"] == 220 and len(h["gamma_star"]) == 1
    # The node is where the final solve puts Γ*, on the exact circle, and Γ* is the contact's.
    node = hist[-1]["nodes"][0]["position"]
    (end,) = s["contact"]["gamma_star"]
    size = math.hypot(10, 10)
    assert math.dist(node, end) <= 1e-10 * size
    assert math.hypot(node[0], node[1] - 10) == pytest.approx(10, abs=1e-12)
    assert s["contact"]["resultant"][1] == pytest.approx(35000, rel=1e-6)
    # Files: the final mesh's nodes and one pressure curve per iteration.
    assert (out / "mesh.yaml").exists()
    for h in hist:
        assert (out / "rp" / f"pressure-{h['iteration']}.csv").exists()


def test_rp_removes_the_oscillation_of_the_penalty_traction(hpcontact, root, tmp_path):
    """With the seed's penalty and Γ* inside element 1 the penalty traction oscillates (islands
    of opening inside the zone at p = 5); with node A on Γ* it is one zone and close to the
    closed form (seed §4.8)."""
    _, p5 = run(hpcontact, root, "p5.yaml", tmp_path / "p5", "contact[0].enforcement=penalty")
    _, s = run(hpcontact, root, "rp5.yaml", tmp_path / "rp5", "contact[0].enforcement=penalty")
    assert len(p5["contact"]["gamma_star"]) > 1  # several sign changes of the gap
    pen_p, pen_rp = p5["contact"]["penalty_traction"], s["contact"]["penalty_traction"]
    assert pen_rp["e_seed_shtayerman_percent"] < 0.2 < 10 < pen_p["e_seed_shtayerman_percent"]
    assert pen_rp["e_L2_reference_percent"] < p5["contact"]["e_L2_reference_percent"]


def test_rp15_against_p15(hpcontact, root, tmp_path):
    """Issue 4's Must-show at 1860 DOF, with exact contact: e_L2 vs the reference below 0.6 of
    p15's at the same DOF (measured 1.13 % against 2.36 %), and the multiplier (the pressure the
    method carries) within the seed's rp15 figure vs Shtayerman, 0.0207 % (measured 0.0165 %)."""
    r, rp = run(hpcontact, root, "rp15.yaml", tmp_path / "rp15")
    assert r.returncode == 0, r.stderr
    _, p = run(hpcontact, root, "p15.yaml", tmp_path / "p15")
    assert rp["dofs"] == p["dofs"] == 1860
    assert rp["contact"]["e_L2_reference_percent"] < 0.6 * p["contact"]["e_L2_reference_percent"]
    assert rp["contact"]["multiplier"]["e_seed_shtayerman_percent"] <= 0.0207
    assert rp["adapt"]["iterations"] <= 20


def test_rp_that_runs_out_of_iterations_keeps_the_last_good_result(hpcontact, root, tmp_path):
    out = tmp_path / "out"
    r, s = run(hpcontact, root, "rp5.yaml", out, "adapt.max_iterations=2",
               "adapt.update=relocate")
    assert r.returncode != 0
    assert "did not reach the zone ends in 2 relocations" in r.stderr
    assert "last-good" in r.stderr
    assert s is None  # nothing that could pass for the result
    last = json.loads((out / "last-good" / "summary.json").read_text())
    assert last["converged"] is False and last["adapt"]["converged"] is False
    assert len(last["adapt"]["history"]) == 3


def test_rp_without_contact_zone_end_is_an_error(hpcontact, root, tmp_path):
    """The cylinder lifted off the foundation (displacement control, no force target): no Gauss
    point closes, so there is no Γ* to move a node to: a clear message and no summary."""
    import yaml
    with open(os.path.join(root, HERTZ, "rp5.yaml")) as f:
        case = yaml.safe_load(f)
    del case["solver"]["target_resultant"]
    case["bodies"][0]["constraints"][1]["uy"] = 0.01
    del case["contact"][0]["compare"]
    path = tmp_path / "lifted.yaml"
    path.write_text(yaml.safe_dump(case))
    out = tmp_path / "out"
    r = hpcontact("run", path, "--out", out, "-q")
    assert r.returncode != 0 and not (out / "summary.json").exists()
    assert "no end of a contact zone found" in r.stderr, r.stderr


def test_rp_needs_contact(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, "examples/lame/thick-cylinder.yaml"), "--out",
                  tmp_path / "o", "--set", "adapt.method=rp")
    assert r.returncode != 0
    assert "adapt.method" in r.stderr and "no contact" in r.stderr


@pytest.mark.parametrize("example", ["rp5.yaml", "hp.yaml"])
def test_no_node_that_can_move_keeps_the_first_solve(hpcontact, root, tmp_path, example):
    """Edge 2-3 made straight: every node of the contact edges sits where the boundary changes
    from the circle to a straight edge or ends the contact edge set, so no node can slide onto
    Γ* (moving an end would change what the set covers). The loop
    says which nodes and why, exits 1, writes no summary.json in the output folder, and keeps
    the first (successful) solve in last-good/ marked as not converged."""
    text = open(os.path.join(root, HERTZ, example)).read()
    straight = "      - {nodes: [2, 3], arc: {center: [0, 10], radius: 10}}\n"
    assert straight in text
    text = text.replace(straight, "").replace(
        "reference: reference-pressure.csv",
        "reference: " + os.path.join(root, HERTZ, "reference-pressure.csv"))
    path = tmp_path / "straight.yaml"
    path.write_text(text)
    out = tmp_path / "out"
    r = hpcontact("run", path, "--out", out, "-q")
    assert r.returncode == 1
    assert "straight.yaml: no boundary node of body 'cylinder' can move onto the zone end" in r.stderr
    # nodes 1 and 3 end edge sets (symmetry, contact), node 2 sits between the arc and the
    # straight edge
    for node in (1, 3):
        assert r.stderr.count(f"node {node} of body 'cylinder' ends edge set '") == 1
    assert r.stderr.count("node 2 of body 'cylinder' sits where the boundary changes") == 1
    # rp counts iterations, hp steps
    step = "iteration" if example.startswith("rp") else "step"
    assert f"the last good result ({step} 0) is in" in r.stderr
    assert not (out / "summary.json").exists()
    kept = json.loads((out / "last-good" / "summary.json").read_text())
    assert kept["converged"] is False and kept["adapt"]["converged"] is False
    assert len(kept["adapt"]["history"]) == 1
    assert abs(kept["contact"]["resultant"][1] - 35000) < 35


def test_relocation_that_would_invert_an_element_keeps_the_first_solve(hpcontact, root, tmp_path):
    """tests/cli/data/thin-arch-rp.yaml: node 2 of a ring one element thick would slide 2.8 mm
    onto Γ* past its partner on the inner arc; no interior node can follow, so element 2 would
    invert. The loop names the node, the element and the file, exits 1, and keeps the first
    solve in last-good/ (not converged); nothing in the output folder passes for a result."""
    out = tmp_path / "out"
    r = hpcontact("run", os.path.join(root, "tests/cli/data/thin-arch-rp.yaml"), "--out", out, "-q")
    assert r.returncode == 1
    assert "thin-arch-rp.yaml: rp: moving node 2 of body 'arch' to (" in r.stderr, r.stderr
    assert "would invert an element (the node has no interior neighbours" in r.stderr
    assert "element 2 is inverted or degenerate at node 2" in r.stderr
    assert "the last good result (iteration 0) is in" in r.stderr
    assert not (out / "summary.json").exists()
    kept = json.loads((out / "last-good" / "summary.json").read_text())
    assert kept["converged"] is False and kept["adapt"]["converged"] is False
    assert len(kept["adapt"]["history"]) == 1
    # The kept solve is the unmoved mesh: node 2 still at 22.5 degrees on the outer arc.
    mesh = (out / "last-good" / "mesh.yaml").read_text()
    assert "2: [3.8268343236509" in mesh
