"""Two identical cylinders (R = 10, steel, plane strain, p = 4; scripts/partial_slip_mesh.py
without an overlap, the lower body the upper one's mirror image node for node) pressed together
with Coulomb friction (mu = 0.3) and no tangential load: for elastically similar bodies the
normal and tangential problems uncouple and the exact shear is zero everywhere (Dundurs'
beta = 0), so every tangential traction the run reports is an error of the method.

The default normal of a frictional pair between two bodies is the mean of both boundaries'
normals (contact[].normal: auto): mirror-image bodies then receive mirror-image forces and the
discrete shear vanishes to Newton's round-off (measured 4.7e-9 mu p0 in one load step). The
one-sided normal (the other body's) measures the approach of the two curved surfaces partly
along the tangent of a discrete surface that is not quite flat, and sticking nodes hold that:
2.7e-2 mu p0, alternating in sign from node to node."""
import os

import pytest
import yaml

from conftest import csv_rows, load_script, partial_slip_generator

compare = load_script("partial_slip_compare")

MU = 0.3


def pressed(hpcontact, root, out, steps, normal=None):
    """The pair pressed by the approach of P = 700 N/mm in `steps` load steps, the upper cut's
    centre node held in x (the bodies touch at one point: the upper one is otherwise free in x
    before friction holds it; by symmetry the node carries no force): contact.csv's rows of the
    points and nodes in contact, and p0."""
    gen = partial_slip_generator(root, "--force", "700", "--overlap", "0", "--degree", "4")
    assert gen.returncode == 0, gen.stderr
    spec = yaml.safe_load(gen.stdout)
    upper, lower = spec["bodies"]
    centre = next(c for c in lower["constraints"] if "nodes" in c)  # the lower cut's centre: ux = 0
    upper["constraints"].append({"nodes": centre["nodes"], "ux": 0})
    upper["loads"] = []
    lower["loads"] = []
    spec["solver"]["stages"] = [{"displacements": 1, "loads": 0, "steps": steps}]
    if normal:
        spec["contact"][0]["normal"] = normal
    case = out / "pressed.yaml"
    case.write_text(yaml.safe_dump(spec))
    r = hpcontact("run", case, "--out", out / "run", "-q")
    assert r.returncode == 0, r.stderr
    rows = [row for row in csv_rows(out / "run" / "contact.csv") if row["state"] != "open"]
    p0 = max(float(row["pressure"]) for row in rows)
    return rows, p0


def largest_shear(rows, p0):
    return max(abs(float(row["tangential_traction"])) for row in rows) / (MU * p0)


def test_no_shear_between_mirror_images(hpcontact, root, tmp_path):
    """One load step: |t_T| <= 1e-8 mu p0 at every node and point in contact, none slips, no
    slip accumulated; p0 is Hertz's (2 P / (pi a), a = 0.1965) to 1 % (a press, not an open
    pair)."""
    rows, p0 = pressed(hpcontact, root, tmp_path, steps=1)
    assert p0 == pytest.approx(2 * 700 / (3.14159265 * 0.196524), rel=0.01)
    assert len(rows) > 100
    assert largest_shear(rows, p0) <= 1e-8
    assert not any(row["state"] == "slip" for row in rows)
    assert max(abs(float(row["slip"])) for row in rows) <= 1e-10  # 6.8e-12 measured, a = 0.197


def test_pressing_in_steps_keeps_the_shear_negligible(hpcontact, root, tmp_path):
    """Four load steps: points that close during a step are measured from where they were at its
    start, along feet that are closest points (second order off the mirror image): 2.1e-6 mu p0
    measured; <= 1e-5, and no slip."""
    rows, p0 = pressed(hpcontact, root, tmp_path, steps=4)
    assert largest_shear(rows, p0) <= 1e-5
    assert not any(row["state"] == "slip" for row in rows)


def test_the_one_sided_normal_would_shear(hpcontact, root, tmp_path):
    """What the default avoids, on the same model: with normal: other the sticking nodes hold a
    shear of 2.7e-2 mu p0 (at least 1e-3)."""
    rows, p0 = pressed(hpcontact, root, tmp_path, steps=1, normal="other")
    assert largest_shear(rows, p0) > 1e-3


def test_sheared_by_moving_the_cuts_without_an_overlap(hpcontact, root, tmp_path):
    """The pair pressed and then sheared by moving the cuts (--shear-displacement 0.0042: the
    upper cut by +0.0021 in x, the lower by -0.0021, both held in x from the start), no overlap
    in the input and no pinned node: Q = 0.5 mu P to 1 % (0.5006 measured), the shear within
    2.5 % of Cattaneo–Mindlin's for the Q it carries in L2 (1.97 % measured at p = 4) and the
    stick zone's end within 2 % of c (0.39 %)."""
    gen = partial_slip_generator(root, "--force", "700", "--degree", "4", "--shear-displacement", "0.0042")
    assert gen.returncode == 0, gen.stderr
    spec = yaml.safe_load(gen.stdout)
    upper, lower = spec["bodies"]
    assert min(y for _, y in upper["nodes"].values()) == 0.0 == max(y for _, y in lower["nodes"].values())
    assert "loads" not in upper and all("nodes" not in c for c in upper["constraints"] + lower["constraints"])
    case = tmp_path / "sheared.yaml"
    case.write_text(gen.stdout)
    r = hpcontact("run", case, "--out", tmp_path / "run", "-q")
    assert r.returncode == 0, r.stderr
    m, _ = compare.measure(str(tmp_path / "run"))
    assert m["Q"] / (MU * m["P"]) == pytest.approx(0.5, rel=0.01)
    assert m["shear_rel_L2"] < 0.025
    assert abs(m["c_rel_error"]) < 0.02


def test_touching_at_one_point_friction_holds_the_body_from_the_start(hpcontact, root, tmp_path):
    """The example's model without its overlap and without a pinned node (the upper cylinder
    only touches the lower one at (0, 0), its cut held in y alone): the node touching at its own
    point starts active and sticks, so friction holds the upper body in x from the first Newton
    iteration (before, the tangent was singular: "held only by contact against translation in
    x"). Pressed, then sheared by the traction Q = mu P / 2: Q carried (the load's resultant),
    shear within 3.5 % of Cattaneo–Mindlin in L2 (2.47 % measured), pressure within 0.5 % of
    Hertz (0.25 %), the stick zone's end within 3 % of c (1.56 %)."""
    gen = partial_slip_generator(root, "--force", "700", "--overlap", "0", "--degree", "4")
    assert gen.returncode == 0, gen.stderr
    spec = yaml.safe_load(gen.stdout)
    assert all("nodes" not in c for c in spec["bodies"][0]["constraints"])  # upper: held in y only
    case = tmp_path / "touching.yaml"
    case.write_text(gen.stdout)
    r = hpcontact("run", case, "--out", tmp_path / "run", "-q")
    assert r.returncode == 0, r.stderr
    m, _ = compare.measure(str(tmp_path / "run"))
    assert m["Q"] / (MU * m["P"]) == pytest.approx(0.5, rel=1e-3)
    assert m["shear_rel_L2"] < 0.035 and m["pressure_rel_L2"] < 0.005
    assert abs(m["c_rel_error"]) < 0.03


def test_touching_between_two_nodes_friction_holds_the_body_from_the_start(hpcontact, root, tmp_path):
    """As above, with the upper cylinder moved by dx = 0.05 (a third of its contact edge at the
    touching point) and down until it touches again: the bodies touch at a point no node of
    either lies on, as after hp moved the node that did. The two nodes of the upper body's edge
    around the point start active and stick, so the run converges from the first Newton
    iteration (before, only a node touching at its own point started active: the tangent was
    singular, "held only by contact against translation in x"); Q is carried."""
    gen = partial_slip_generator(root, "--force", "700", "--overlap", "0", "--degree", "4")
    assert gen.returncode == 0, gen.stderr
    spec = yaml.safe_load(gen.stdout)
    upper = spec["bodies"][0]
    dx = 0.05
    dy = -(20 - (400 - dx * dx) ** 0.5)  # the centres 2 R apart again
    upper["nodes"] = {k: [x + dx, y + dy] for k, (x, y) in upper["nodes"].items()}
    for c in upper["curves"]:
        cx, cy = c["arc"]["center"]
        c["arc"]["center"] = [cx + dx, cy + dy]
    case = tmp_path / "between.yaml"
    case.write_text(yaml.safe_dump(spec))
    r = hpcontact("run", case, "--out", tmp_path / "run", "-q")
    assert r.returncode == 0, r.stderr
    m, _ = compare.measure(str(tmp_path / "run"))
    assert m["Q"] / (MU * m["P"]) == pytest.approx(0.5, rel=1e-3)
