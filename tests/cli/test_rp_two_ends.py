"""rp with two zone ends at once (issue 4: "several Γ* at once"): the whole lower half of the
Hertz cylinder, the p5 quarter and its mirror image, pressed onto the plane. Its contact zone
has two ends, each served by its own node (A and its mirror); by symmetry the result must be
the quarter model's (rp5.yaml) with the load doubled."""
import json
import os

import pytest
import yaml


def half_cylinder(root, path):
    with open(os.path.join(root, "examples/hertz/rp5.yaml")) as f:
        case = yaml.safe_load(f)
    body = case["bodies"][0]
    mirror = {n: (n if abs(xy[0]) < 1e-12 else n + 10) for n, xy in body["nodes"].items()}
    for n, (x, y) in list(body["nodes"].items()):
        if mirror[n] != n:
            body["nodes"][mirror[n]] = [-x, y]
    for e, nodes in list(body["elements"].items()):
        a, b, c, d = (mirror[n] for n in nodes)
        body["elements"][e + 10] = [b, a, d, c]  # mirrored: reverse to stay counter-clockwise
    for cv in list(body["curves"]):
        a, b = cv["nodes"]
        body["curves"].append({"nodes": [mirror[a], mirror[b]], "arc": cv["arc"]})
    sets = body["edge_sets"]
    sets["contact"] += [[mirror[a], mirror[b]] for a, b in sets["contact"]]
    sets["centre"] += [[mirror[a], mirror[b]] for a, b in sets["centre"]]
    del sets["symmetry"]
    body["constraints"] = [{"edges": ["centre"], "uy": -0.02}, {"nodes": [7], "ux": 0}]
    case["case"] = "hertz-half-rp5"
    case["solver"]["target_resultant"]["value"] = 70000
    del case["contact"][0]["compare"]
    path.write_text(yaml.safe_dump(case))


def test_two_zone_ends_each_get_a_node(hpcontact, root, tmp_path):
    half_cylinder(root, tmp_path / "half.yaml")
    r = hpcontact("run", tmp_path / "half.yaml", "--out", tmp_path / "half", "-q")
    assert r.returncode == 0, r.stderr
    s = json.loads((tmp_path / "half" / "summary.json").read_text())
    a = s["adapt"]
    assert a["converged"] is True and a["iterations"] <= 20
    last = a["history"][-1]
    nodes = {n["node"]: n["position"] for n in last["nodes"]}
    assert sorted(nodes) == [2, 12]
    (x2, y2), (x12, y12) = nodes[2], nodes[12]
    assert x2 == pytest.approx(-x12, abs=1e-8) and y2 == pytest.approx(y12, abs=1e-8)
    assert last["distance"] <= 1e-10
    # The quarter model with half the load: the same zone end.
    r = hpcontact("run", os.path.join(root, "examples/hertz/rp5.yaml"), "--out", tmp_path / "q", "-q")
    assert r.returncode == 0, r.stderr
    q = json.loads((tmp_path / "q" / "summary.json").read_text())
    (xq, yq), = q["contact"]["gamma_star"]
    assert x2 == pytest.approx(xq, abs=1e-7)
    assert s["strain_energy"] == pytest.approx(2 * q["strain_energy"], rel=1e-7)
