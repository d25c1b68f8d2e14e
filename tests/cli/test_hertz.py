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
    """One run of reference.yaml (30976 DOF, a few seconds) shared by the tests below."""
    out = tmp_path_factory.mktemp("reference")
    return out, run(hpcontact, root, "reference.yaml", out)


def test_reference_reproduces_its_curve(reference_run, root):
    """reference.yaml, run again, gives the committed reference-pressure.csv, and its node on the
    end of the contact zone is where the solution puts Γ* (the mesh was made that way).
    The CSV is a snapshot (this program's output, by scripts/make_hertz_reference.py, the commit
    named in reference.yaml); the independent checks beside it are
    test_reference_against_closed_forms and test_reference_equals_an_independent_exact_code."""
    tmp_path, s = reference_run
    x_new, p_new = read_curve(tmp_path / "pressure.csv")
    x_ref, p_ref = read_curve(os.path.join(root, HERTZ, "reference-pressure.csv"))
    assert len(x_new) == len(x_ref)
    p0 = s["contact"]["hertz_peak_pressure"]
    # same points; pressures equal to round-off of a 30976-DOF solve (1e-6 of the peak)
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


def test_reference_equals_an_independent_exact_code(reference_run):
    """The converged model with exact contact: strain energy within 2e-6 of 7696.565 N mm and
    the centre plane's displacement within 1e-5 of 0.487397 mm, the values of an independent
    exact-contact (active-set, no penalty) code for this model (issue 15). Measured
    7696.56682 (+2.4e-7) and 0.4873975 (+4.8e-7 mm); the seed's penalty eps_N = 1000 E moved
    them by -1.0e-4 and +1.4e-4."""
    s = reference_run[1]
    assert abs(s["strain_energy"] / 7696.565 - 1) < 2e-6, s["strain_energy"]
    centre = 0.02 * s["load_factor"]  # the prescribed uy = -0.02 of the centre plane, scaled
    assert abs(centre - 0.487397) < 1e-5, centre


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


def rows_by_x(path):
    """pressure.csv's rows keyed by x (to 1e-9): two runs sample [0, 1.5 b] alike but for the
    sample each puts on its own zone end."""
    with open(path) as f:
        return {round(float(r["x"]), 9): r for r in csv.DictReader(f)}


def test_bilateral_equals_unilateral(hpcontact, root, tmp_path):
    """Two equal cylinders (bilateral.yaml: exact contact, the upper cylinder's multiplier nodes
    against the lower one's deformed boundary, collocated, the gap along the mean of the two
    boundaries' normals) against the unilateral p8.yaml (issue 15): the multiplier and
    -sigma_nn within 1e-8 of p0 at every common sample of [0, 1.5 b] (measured 9e-12), energy per
    cylinder and load factor within 1e-10 (2e-13, 6e-14), the pressure from the stresses (on the
    mean normal) within 2e-6 of p0 inside the zone (it was 3.7e-4 on the lower body's normal).
    Not the located zone end: it is the
    root of g - lambda_h/kappa with kappa of one body's E', while between two bodies the gap
    opens under both (1.7 % inside p8's; E* in kappa brings it to 1.3e-5 but leaves
    bilateral-rp.yaml at a noise floor of 5e-7: open, issue 15). With the other body's normal alone (normal: other) the upper
    node is pushed along the lower body's normal, which at a node of the edge the zone ends in is
    tilted by the surfaces' crossing there: energy 3.3e-6, multiplier 8e-4 of p0 off (asserted,
    so that the mean normal is seen to be what closes the gap)."""
    uni = run(hpcontact, root, "p8.yaml", tmp_path / "uni")
    bil = run(hpcontact, root, "bilateral.yaml", tmp_path / "bil")
    assert bil["converged"] and bil["dofs"] == 2 * uni["dofs"]
    p0 = uni["contact"]["hertz_peak_pressure"]
    ru, rb = rows_by_x(tmp_path / "uni" / "pressure.csv"), rows_by_x(tmp_path / "bil" / "pressure.csv")
    common = sorted(set(ru) & set(rb))
    assert len(common) >= len(ru) - 1
    for column in ("pressure_multiplier", "minus_sigma_nn"):
        assert max(abs(float(ru[x][column]) - float(rb[x][column])) for x in common) < 1e-8 * p0
    # the pressure from the stresses along the mean normal, as the multiplier acts: inside the
    # zone within 2e-6 of p0 (measured 7.8e-7 near its end; the foot of a point between the
    # nodes is not quite its mirror image, the surfaces touch at the nodes only)
    (end,) = uni["contact"]["gamma_star"]
    inside = [x for x in common if x <= end[0]]
    assert len(inside) > 600
    assert max(abs(float(ru[x]["pressure_from_stress"]) - float(rb[x]["pressure_from_stress"]))
               for x in inside) < 2e-6 * p0
    assert abs(bil["strain_energy"] / (2 * uni["strain_energy"]) - 1) < 1e-10
    assert abs(bil["load_factor"] / uni["load_factor"] - 1) < 1e-10
    assert abs(bil["contact"]["resultant"][1] - 35000) < 35
    one = hpcontact("run", os.path.join(root, HERTZ, "bilateral.yaml"), "--out", tmp_path / "one",
                    "-q", "--set", "contact[0].normal=other")
    assert one.returncode == 0, one.stderr
    s1 = json.loads((tmp_path / "one" / "summary.json").read_text())
    r1 = rows_by_x(tmp_path / "one" / "pressure.csv")
    assert abs(s1["strain_energy"] / (2 * uni["strain_energy"]) - 1) > 1e-6
    assert max(abs(float(ru[x]["pressure_multiplier"]) - float(r1[x]["pressure_multiplier"]))
               for x in set(ru) & set(r1)) > 1e-4 * p0


def test_bilateral_rp_moves_a_node_of_each_body_and_equals_rp8(hpcontact, root, tmp_path):
    """rp between two bodies (bilateral-rp.yaml): the zone end on each body gets its own node
    (node 2 of the upper and of the lower cylinder), the two ends are mirror images, and the
    result equals the unilateral rp8.yaml: zone end within 1e-6 mm (measured 8e-8), energy per
    cylinder and load factor within 1e-8 (measured 1e-10), the multiplier within 1e-5 of p0
    (2.3e-7) and the pressure from stresses within 1e-4 of p0 (measured 4e-7) except at the zone
    end itself, where it jumps from one element's stress to the next and the two runs' ends
    differ by 1e-7 mm (the meshes follow their own located ends to the 1e-8 tolerance)."""
    uni = run(hpcontact, root, "rp8.yaml", tmp_path / "uni")
    bil = run(hpcontact, root, "bilateral-rp.yaml", tmp_path / "bil")
    assert bil["converged"] and bil["adapt"]["converged"]
    last = bil["adapt"]["history"][-1]["nodes"]
    assert sorted((n["body"], n["node"]) for n in last) == [(0, 2), (1, 2)]
    upper, lower = bil["contact"]["gamma_star"], bil["contact"]["gamma_star_other"]
    assert len(upper) == len(lower) == 1
    assert abs(upper[0][0] - lower[0][0]) < 1e-7 and abs(upper[0][1] + lower[0][1]) < 1e-7
    end = uni["contact"]["gamma_star"][0][0]
    assert abs(upper[0][0] - end) < 1e-6
    assert abs(bil["strain_energy"] / (2 * uni["strain_energy"]) - 1) < 1e-8
    assert abs(bil["load_factor"] / uni["load_factor"] - 1) < 1e-8
    p0 = uni["contact"]["hertz_peak_pressure"]
    with open(tmp_path / "uni" / "pressure.csv") as f:
        ru = list(csv.DictReader(f))
    with open(tmp_path / "bil" / "pressure.csv") as f:
        rb = list(csv.DictReader(f))
    assert len(ru) == len(rb)
    assert max(abs(float(a["pressure_multiplier"]) - float(b["pressure_multiplier"]))
               for a, b in zip(ru, rb)) < 1e-5 * p0
    away = [(a, b) for a, b in zip(ru, rb) if abs(float(a["x"]) - end) > 1e-5]
    assert len(away) >= len(ru) - 2
    assert max(abs(float(a["minus_sigma_nn"]) - float(b["minus_sigma_nn"]))
               for a, b in away) < 1e-4 * p0
    # Per unit length along the obstacle (the plane's normal, the lower body's deformed one: the
    # same inside the zone, where the interface is flat by symmetry).
    inside = [(a, b) for a, b in away if float(a["x"]) < end]
    assert max(abs(float(a["pressure_from_stress"]) - float(b["pressure_from_stress"]))
               for a, b in inside) < 1e-4 * p0


def test_bilateral_equals_unilateral_when_the_zone_end_is_a_node(hpcontact, root, tmp_path):
    """What separates bilateral.yaml from p8.yaml is the edge the zone ends in, not the exact
    method: with node 2 of each cylinder moved onto the zone end that rp8.yaml locates, p8 and
    its bilateral twin agree to Newton's tolerance — the multiplier to 1e-8 of p0 (measured
    9e-11), the energy per cylinder and the load factor to 1e-11 (2.8e-12 at the default
    solver.tolerance 1e-10, 2e-16 at 1e-13).
    Why the seed's mesh cannot: at an active collocation node the constraint "the node lies on
    the other boundary" has its gradient along that boundary's normal, whatever the gap's
    definition, so the upper node is pushed along the lower cylinder's normal. Where an edge is
    only partly in contact its deformed trace is curved at the nodes, the normal tilts, and the
    mirror image of the lower body's load is not the upper's; on edges wholly inside or outside
    the zone the interface is flat and the two problems coincide."""
    rp = run(hpcontact, root, "rp8.yaml", tmp_path / "rp8")
    (end,) = rp["contact"]["gamma_star"]
    with open(tmp_path / "rp8" / "mesh.yaml") as f:
        line = next(s for s in f if s.strip().startswith("2: ["))
    x, y = (float(v) for v in line.split("[")[1].split("]")[0].split(","))
    assert abs(x - end[0]) < 1e-8
    seed_node = "2.48, 0.312399677938814"
    for name in ("p8.yaml", "bilateral.yaml", "reference-pressure.csv"):
        with open(os.path.join(root, HERTZ, name)) as f:
            text = f.read()
        if name.endswith(".yaml"):
            assert text.count(seed_node) == 1
            text = text.replace(seed_node, f"{x!r}, {y!r}").replace(
                "2.48, -0.312399677938814", f"{x!r}, {-y!r}")
        (tmp_path / HERTZ).mkdir(parents=True, exist_ok=True)
        (tmp_path / HERTZ / name).write_text(text)
    uni = run(hpcontact, tmp_path, "p8.yaml", tmp_path / "uni")
    bil = run(hpcontact, tmp_path, "bilateral.yaml", tmp_path / "bil")
    p0 = uni["contact"]["hertz_peak_pressure"]
    with open(tmp_path / "uni" / "pressure.csv") as f:
        ru = list(csv.DictReader(f))
    with open(tmp_path / "bil" / "pressure.csv") as f:
        rb = list(csv.DictReader(f))
    assert len(ru) == len(rb) > 100
    assert max(abs(float(a["pressure_multiplier"]) - float(b["pressure_multiplier"]))
               for a, b in zip(ru, rb)) < 1e-8 * p0
    assert abs(bil["strain_energy"] / (2 * uni["strain_energy"]) - 1) < 1e-11
    assert abs(bil["load_factor"] / uni["load_factor"] - 1) < 1e-11


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


def test_the_mesh_helper_takes_the_cylinder_and_the_load(hpcontact, root, tmp_path):
    """scripts/hertz_mesh.py for another case than the dissertation's (R = 25, aluminium,
    F = 2000 N/mm): the file it writes carries that case (material, compare, target F/2), its
    grading point defaults to 0.982 b of that case, and the run's zone and pressure follow
    Hertz's b = √(4 F R (1 − ν²) / (π E)) computed here (measured b +0.09 %, p_max +0.04 %,
    0.32 % in L2 on the graded 96-element mesh at p = 6)."""
    import math
    import subprocess
    import sys
    R, E, nu, F = 25.0, 70000.0, 0.33, 2000.0
    text = subprocess.run(
        [sys.executable, os.path.join(root, "scripts", "hertz_mesh.py"), "graded", "--radius", "25",
         "--E", "70000", "--nu", "0.33", "--force", "2000", "--degree", "6", "--case", "alu"],
        check=True, capture_output=True, text=True).stdout
    b = math.sqrt(4 * F * R * (1 - nu ** 2) / (math.pi * E))
    assert "material: {E: 70000, nu: 0.33, plane: strain}" in text
    assert "compare: {radius: 25, force: 2000}" in text and "value: 1000," in text
    assert f"towards x = {0.982 * b!r}" in text
    case = tmp_path / "alu.yaml"
    case.write_text(text)
    r = hpcontact("run", case, "--out", tmp_path / "alu", "-q")
    assert r.returncode == 0, r.stderr
    c = json.loads((tmp_path / "alu" / "summary.json").read_text())["contact"]
    assert c["hertz_half_width"] == pytest.approx(b, rel=1e-12)
    assert abs(c["half_width"] / b - 1) < 5e-3
    assert abs(c["pressure_max"] / c["hertz_peak_pressure"] - 1) < 5e-3
    assert c["multiplier"]["e_L2_hertz_percent"] < 1.0
