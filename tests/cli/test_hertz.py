"""The Hertz examples end to end: the p-version on four elements against the closed forms and
against our own overkill reference (examples/hertz/reference.yaml)."""
import csv
import json
import os

import pytest

HERTZ = "examples/hertz"


def run(hpcontact, root, name, out):
    r = hpcontact("run", os.path.join(root, HERTZ, name), "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


def read_curve(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r["x"]) for r in rows], [float(r["pressure_from_stress"]) for r in rows]


@pytest.fixture(scope="module")
def reference_run(hpcontact, root, tmp_path_factory):
    """One run of reference.yaml (12448 DOF, a few seconds) shared by the tests below."""
    out = tmp_path_factory.mktemp("reference")
    return out, run(hpcontact, root, "reference.yaml", out)


def test_reference_reproduces_its_curve(reference_run, root):
    """reference.yaml, run again, gives the committed reference-pressure.csv, and its node on the
    end of the contact zone is where the solution puts Γ* (the mesh was made that way).
    The CSV is a snapshot: 62c9a39 (this program's output, by scripts/make_hertz_reference.py);
    the independent check beside it is test_reference_against_closed_forms."""
    tmp_path, s = reference_run
    x_new, p_new = read_curve(tmp_path / "pressure.csv")
    x_ref, p_ref = read_curve(os.path.join(root, HERTZ, "reference-pressure.csv"))
    assert len(x_new) == len(x_ref)
    p0 = s["contact"]["hertz_peak_pressure"]
    # same points; pressures equal to round-off of a 12448-DOF solve (1e-6 of the peak)
    assert max(abs(a - b) for a, b in zip(x_new, x_ref)) < 1e-9
    assert max(abs(a - b) for a, b in zip(p_new, p_ref)) < 1e-6 * p0
    (end,) = s["contact"]["gamma_star"]
    with open(os.path.join(root, HERTZ, "reference.yaml")) as f:
        nodes_x = [float(line.split("[")[1].split(",")[0]) for line in f
                   if line.strip()[:1].isdigit() and "[" in line and line.count(",") == 1]
    assert min(abs(x - end[0]) for x in nodes_x) < 1e-6


def test_reference_against_closed_forms(reference_run):
    """The converged finite cylinder lies between the half-space solutions' spread: its half
    width within 0.5 % of Shtayerman's (1.951), its peak within 1 % of Hertz's p0, and in the
    seed's squared measure closer to Shtayerman (exact circle) than to Hertz (parabola)."""
    c = reference_run[1]["contact"]
    assert abs(c["half_width"] / c["shtayerman_half_width"] - 1) < 5e-3
    assert abs(c["p_max"] / c["hertz_peak_pressure"] - 1) < 1e-2
    assert c["e_seed_shtayerman_percent"] < c["e_seed_hertz_percent"] < 0.1
    assert abs(c["resultant"][1] - 35000) < 35


def test_p_examples_converge_to_the_reference(hpcontact, root, tmp_path):
    """p5, p8, p15 as they are: the seed's DOF (tensor space on the 2x2 mesh), the resultant
    F/2 within 0.1 %, and the pressure error against the reference falling with p."""
    dofs = {5: 220, 8: 544, 15: 1860}
    errors = []
    for p in (5, 8, 15):
        s = run(hpcontact, root, f"p{p}.yaml", tmp_path / f"p{p}")
        c = s["contact"]
        assert s["converged"] and s["dofs"] == dofs[p]
        assert abs(c["resultant"][1] - 35000) <= 35
        assert c["reference"] == "reference-pressure.csv"
        errors.append(c["e_L2_reference_percent"])
    assert errors[0] > errors[1] > errors[2], errors
    assert errors[2] < 3.0  # measured 2.48 %


def test_bilateral_equals_unilateral(hpcontact, root, tmp_path):
    """Two equal cylinders (bilateral.yaml: both sides' Gauss points against the other's deformed
    boundary, half weight each, half the penalty on the gap between the bodies) give the
    unilateral p8.yaml result: the pressure from stresses within 1e-6 of p0 everywhere on
    [0, 1.5 b] (measured 8.6e-7), the same energy per cylinder and the same load factor."""
    uni = run(hpcontact, root, "p8.yaml", tmp_path / "uni")
    bil = run(hpcontact, root, "bilateral.yaml", tmp_path / "bil")
    assert bil["converged"] and bil["dofs"] == 2 * uni["dofs"]
    _, pu = read_curve(tmp_path / "uni" / "pressure.csv")
    _, pb = read_curve(tmp_path / "bil" / "pressure.csv")
    p0 = uni["contact"]["hertz_peak_pressure"]
    assert len(pu) == len(pb)
    assert max(abs(a - b) for a, b in zip(pu, pb)) < 1e-6 * p0
    assert abs(bil["strain_energy"] - 2 * uni["strain_energy"]) < 1e-8 * bil["strain_energy"]
    assert abs(bil["load_factor"] / uni["load_factor"] - 1) < 1e-8
    assert abs(bil["contact"]["resultant"][1] - 35000) < 35


def test_bilateral_rp_moves_a_node_of_each_body_and_equals_rp8(hpcontact, root, tmp_path):
    """rp between two bodies (bilateral-rp.yaml): the zone end on each body gets its own node
    (node 2 of the upper and of the lower cylinder), the two ends are mirror images, and the
    result equals the unilateral rp8.yaml: zone end within 1e-6 mm (measured 3.8e-7), pressure
    from stresses within 1e-4 of p0 (measured 6e-6; the meshes differ by the 1e-8 tolerance)."""
    uni = run(hpcontact, root, "rp8.yaml", tmp_path / "uni")
    bil = run(hpcontact, root, "bilateral-rp.yaml", tmp_path / "bil")
    assert bil["converged"] and bil["adapt"]["converged"]
    last = bil["adapt"]["history"][-1]["nodes"]
    assert sorted((n["body"], n["node"]) for n in last) == [(0, 2), (1, 2)]
    upper, lower = bil["contact"]["gamma_star"], bil["contact"]["gamma_star_other"]
    assert len(upper) == len(lower) == 1
    assert abs(upper[0][0] - lower[0][0]) < 1e-7 and abs(upper[0][1] + lower[0][1]) < 1e-7
    assert abs(upper[0][0] - uni["contact"]["gamma_star"][0][0]) < 1e-6
    _, pu = read_curve(tmp_path / "uni" / "pressure.csv")
    _, pb = read_curve(tmp_path / "bil" / "pressure.csv")
    p0 = uni["contact"]["hertz_peak_pressure"]
    assert len(pu) == len(pb)
    assert max(abs(a - b) for a, b in zip(pu, pb)) < 1e-4 * p0


def test_obstacle_the_body_starts_inside_is_refused(hpcontact, root, tmp_path):
    """A plane whose normal points away from the body (the body starts inside the obstacle) is
    an input error naming the key and the cause, before any solving; no summary is written."""
    out = tmp_path / "out"
    r = hpcontact("run", os.path.join(root, HERTZ, "p8.yaml"), "--out", out, "-q",
                  "--set", "contact[0].obstacle.normal=[0,-1]")
    assert r.returncode == 1, r.stderr
    assert "p8.yaml:" in r.stderr and "contact[0].obstacle" in r.stderr
    assert "inside" in r.stderr and "normal" in r.stderr
    assert not (out / "summary.json").exists()
