"""Follower pressure and pressure penetration from the command line (issue 43, item 3): the
O-ring example squeezed then pressurised reports where the pressure stops, a pressure above the
seal's contact pressure is reported as a leak, and bad penetration input is refused naming the
file, the key and the cause."""
import json
import os

from conftest import expect_refused


def example(root):
    return os.path.join(root, "examples", "o-ring", "o-ring-pressurised.yaml")


def test_the_pressurised_ring_reports_where_the_pressure_stops(hpcontact, root, tmp_path):
    """The pressure enters from the right end of the ring's outline (x = 22 on the mid-plane) and
    stops at the contact with the top plate: a point on the outline (radius 2 about (20, 0))
    between the right end and the plate's first contact (x < 22, y > 0), less than the outline's
    length from the start to the top (π R / 2 = 3.14) wetted, no leak, no warning."""
    r = hpcontact("run", example(root), "--out", tmp_path, "-q")
    assert r.returncode == 0, r.stderr
    s = json.load(open(tmp_path / "summary.json"))
    (p,) = s["penetration"]
    assert p["contact"] == 0 and p["from"] == "start" and p["leaks"] is False
    assert "bodies[0].loads[0]" in p["load"]
    x, y = p["stop"]
    assert abs((x - 20) ** 2 + y ** 2 - 4) < 1e-9
    assert 20 < x < 22 and 0 < y < 2
    assert 0 < p["wetted_length"] < 3.1416
    assert not s.get("warnings")


def test_an_hp_run_reports_where_the_pressure_stops_on_its_mesh(hpcontact, root, tmp_path):
    """hp's result, a solve on its last mesh, reports the penetration as a plain run does: the
    stop on the outline, within 0.1 of the plain run's (the wetted lengths 2.28 and 2.27
    measured: the stop is a node of each mesh) — before, an hp run wrote no `penetration`."""
    plain = hpcontact("run", example(root), "--out", tmp_path / "plain", "-q")
    assert plain.returncode == 0, plain.stderr
    r = hpcontact("run", example(root), "--out", tmp_path / "hp", "-q",
                  "--set", "adapt.method=hp", "--set", "adapt.steps=1")
    assert r.returncode == 0, r.stderr
    (p,) = json.load(open(tmp_path / "hp" / "summary.json"))["penetration"]
    (q,) = json.load(open(tmp_path / "plain" / "summary.json"))["penetration"]
    assert p["leaks"] is False and p["contact"] == 0
    x, y = p["stop"]
    assert abs((x - 20) ** 2 + y ** 2 - 4) < 1e-9
    assert abs(p["wetted_length"] - q["wetted_length"]) < 0.1


def test_a_pressure_above_the_contact_pressure_leaks(hpcontact, root, tmp_path):
    """The top plate pressed only 5 % of the cord (a peak contact pressure of some 2 N/mm²) and a
    pressure of 40 N/mm²: it passes the whole contact, and the run says so (summary.json and a
    warning naming the load and the pair)."""
    r = hpcontact("run", example(root), "--out", tmp_path, "-q",
                  "--set", "bodies[0].loads[0].pressure=40",
                  "--set", "contact[0].obstacle.displacement=[0, -0.1]")
    assert r.returncode == 0, r.stderr
    s = json.load(open(tmp_path / "summary.json"))
    (p,) = s["penetration"]
    assert p["leaks"] is True
    assert any("bodies[0].loads[0].penetration" in w and "contact[0]" in w and "leaks" in w
               for w in s["warnings"])


def test_penetration_without_follower_is_refused(hpcontact, root, tmp_path):
    expect_refused(hpcontact, example(root), tmp_path, ["bodies[0].loads[0].follower=false"],
                   "bodies[0].loads[0].penetration: pressure penetration moves with the contact zone "
                   "on the deformed boundary: it needs follower: true (got follower: false)", 1)


def test_an_unknown_pair_is_refused(hpcontact, root, tmp_path):
    expect_refused(hpcontact, example(root), tmp_path, ["bodies[0].loads[0].penetration.contact=5"],
                   "bodies[0].loads[0].penetration.contact (from --set): no such contact pair "
                   "(the problem has 2) (got 5)", 2)


def test_a_pair_without_the_loads_edges_is_refused(hpcontact, root, tmp_path):
    expect_refused(hpcontact, example(root), tmp_path, ["contact[0].edges=[left]"],
                   "bodies[0].loads[0].penetration.contact: contact[0] has none of the load's edges "
                   "on body 'ring'", 1)


def test_a_follower_traction_is_refused(hpcontact, root, tmp_path):
    expect_refused(hpcontact, example(root), tmp_path,
                   ["bodies[0].loads[0]={edges: [right], traction: [1, 0], follower: true}"],
                   "bodies[0].loads[0].follower (from --set): a follower load is a pressure", 2)


def test_penetrating_edges_that_are_not_one_chain_are_refused(hpcontact, root, tmp_path):
    """The right end and the left end of the outline (contact[1], the wall, has the left one):
    two chains, no single path for the pressure to run along."""
    expect_refused(hpcontact, example(root), tmp_path,
                   ["bodies[0].loads[0].edges=[right, left]", "bodies[0].loads[0].penetration.contact=1"],
                   "bodies[0].loads[0].penetration: the loaded edges must form one open chain", 1)


def test_from_end_of_the_reversed_chain_is_the_same_load(hpcontact, root, tmp_path):
    """The loaded edges listed from the top ([upper, right]: the chain starts at the upper end)
    and pressurised `from: end` are the example's load: the same stop, wetted length and strain
    energy to round-off (1e-12 relative)."""
    runs = {}
    for name, settings in (("start", []),
                           ("end", ["bodies[0].loads[0]={edges: [upper, right], pressure: 1.5, "
                                    "follower: true, penetration: {contact: 0, from: end}}"])):
        args = ["run", example(root), "--out", tmp_path / name, "-q"]
        for s in settings:
            args += ["--set", s]
        r = hpcontact(*args)
        assert r.returncode == 0, r.stderr
        runs[name] = json.load(open(tmp_path / name / "summary.json"))
    a, b = runs["start"], runs["end"]
    assert b["penetration"][0]["from"] == "end"
    for i in range(2):
        assert abs(a["penetration"][0]["stop"][i] - b["penetration"][0]["stop"][i]) < 1e-12 * 20
    assert abs(a["penetration"][0]["wetted_length"] - b["penetration"][0]["wetted_length"]) < 1e-12 * 3
    assert abs(a["strain_energy"] - b["strain_energy"]) < 1e-12 * a["strain_energy"]
