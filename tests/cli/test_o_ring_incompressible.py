"""The incompressible Mooney-Rivlin O-ring (examples/o-ring/o-ring-incompressible.yaml: the
axisymmetric ring of o-ring-mooney-rivlin.yaml with 1/K = 0, the mixed u-p element, p = 5, 4 load
steps, Coulomb friction), checked against what holds independently of the program:

- the total force is the pressure over the surface of revolution, 2 pi ∫ p r ds along the
  deformed contact.csv points (trapezoidal rule over 31 points that miss the zone ends' jump:
  measured 6.2 % at p = 5, falling with p to 5.5 % at p = 8; 4.1 % for the compressible ring of
  test_o_ring_rubber.py, whose pressure falls less steeply at the ends; asserted to 8 %), and
  Newton converges in few iterations (measured 19 over 4 steps);
- the reported Cauchy stress takes the element's pressure: its mean (sigma_xx + sigma_yy +
  sigma_zz) / 3 is the VTU field pressure_mixed at every point to the file's 10 digits
  (measured 7e-10 of the largest stress; the isochoric stress is deviatoric, S_iso : C = 0,
  whatever J);
- a finite K with the mixed element approaches the incompressible ring at rate 1/K: the plate
  force's difference falls tenfold from K/mu = 1e3 to 1e4 (measured 9.97) and is below 1e-3
  at 1e4 (measured 1.4e-4);
- incompressible and formulation are refused naming the file and key where they do not apply."""
import csv
import json
import math
import os
import xml.etree.ElementTree as ET

import numpy as np

CASE = "examples/o-ring/o-ring-incompressible.yaml"
MU = 3.4


def run(hpcontact, root, out, *sets):
    args = ["run", os.path.join(root, CASE), "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


def point_arrays(path):
    piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    return {a.get("Name"): np.array(a.text.split(), dtype=float)
            for a in piece.find("PointData").iter("DataArray")}


def test_force_pressure_and_stress_mean(hpcontact, root, tmp_path):
    summary = run(hpcontact, root, tmp_path / "inc")
    assert summary["converged"] and summary["newton_iterations"] <= 30, summary["newton_iterations"]
    with open(tmp_path / "inc" / "contact.csv") as f:
        points = list(csv.DictReader(f))
    p = [float(r["pressure"]) for r in points]
    x = [float(r["x"]) for r in points]
    y = [float(r["y"]) for r in points]
    integral = sum(0.5 * (p[i] * 2 * math.pi * x[i] + p[i + 1] * 2 * math.pi * x[i + 1])
                   * math.hypot(x[i + 1] - x[i], y[i + 1] - y[i]) for i in range(len(p) - 1))
    F = summary["contact"]["normal_force"]
    assert abs(integral / F - 1) < 0.08, (integral, F)
    a = point_arrays(tmp_path / "inc" / "solution.vtu")
    mean = (a["sigma_xx"] + a["sigma_yy"] + a["sigma_zz"]) / 3
    scale = np.max(np.abs(a["sigma_yy"]))
    assert np.max(np.abs(a["pressure_mixed"])) > 0.1 * scale
    assert np.max(np.abs(mean - a["pressure_mixed"])) < 1e-9 * scale  # the VTU's 10 digits


def test_finite_K_approaches_the_incompressible_ring_at_rate_one_over_K(hpcontact, root, tmp_path):
    F = run(hpcontact, root, tmp_path / "inc")["contact"]["normal_force"]
    difference = []
    for ratio in (1e3, 1e4):
        s = run(hpcontact, root, tmp_path / f"k{ratio:g}", "bodies[0].material.incompressible=false",
                "bodies[0].material.formulation=mixed", f"bodies[0].material.K={ratio * MU!r}")
        difference.append(abs(s["contact"]["normal_force"] / F - 1))
    assert difference[1] < 1e-3, difference
    assert 8 < difference[0] / difference[1] < 12, difference


def test_keys_that_do_not_apply_are_refused(hpcontact, root, tmp_path):
    refused = [("bodies[0].material.K=35", "bodies[0].material.K",
                "is not taken with incompressible: true"),
               ("bodies[0].material.formulation=displacement", "bodies[0].material.formulation",
                "displacement cannot hold J = 1"),
               ("bodies[0].material.formulation=hybrid", "bodies[0].material.formulation",
                "must be one of displacement, mixed"),
               ("bodies[0].material.incompressible=false", "bodies[0].material",
                "missing required key 'K'"),
               ("discretization.degree=1", "bodies[0].material.formulation",
                "mixed needs degree 2 or more")]
    refused.append(("adapt.method=hp", "adapt.min_degree", "needs p >= 2: give adapt.min_degree: 2"))
    for setting, key, cause in refused:
        r = hpcontact("run", os.path.join(root, CASE), "--out", tmp_path / "x", "--set", setting)
        assert r.returncode != 0, setting
        assert "o-ring-incompressible.yaml" in r.stderr and key in r.stderr and cause in r.stderr, r.stderr
        assert not (tmp_path / "x" / "summary.json").exists()
    linear = os.path.join(root, "examples/o-ring/o-ring-axisymmetric.yaml")
    for setting, key in (("bodies[0].material.incompressible=true", "bodies[0].material.incompressible"),
                         ("bodies[0].material.formulation=mixed", "bodies[0].material.formulation")):
        r = hpcontact("run", linear, "--out", tmp_path / "y", "--set", setting)
        assert r.returncode != 0, setting
        assert key in r.stderr and "is for the rubber laws" in r.stderr and "not model neo-hooke" in r.stderr, r.stderr


CLOSED = """case: closed
bodies:
  - name: block
    material: {model: neo-hooke-split, C10: 0.5, incompressible: true}
    nodes: {1: [0, 0], 2: [1, 0], 3: [1, 1], 4: [0, 1]}
    elements: {1: [1, 2, 3, 4]}
    edge_sets: {all: [[1, 2], [2, 3], [3, 4], [4, 1]]}
    constraints:
      - {edges: [all], ux: "0.1*y", uy: "0"}
"""


def test_incompressible_body_held_all_round_is_refused(hpcontact, tmp_path):
    """Its mean pressure would be undetermined (a singular tangent): refused before solving."""
    path = tmp_path / "closed.yaml"
    path.write_text(CLOSED)
    r = hpcontact("run", path, "--out", tmp_path / "x")
    assert r.returncode != 0
    assert "closed.yaml" in r.stderr and "bodies[0].material.incompressible" in r.stderr, r.stderr
    assert "mean pressure undetermined" in r.stderr, r.stderr
    opened = CLOSED.replace("[[1, 2], [2, 3], [3, 4], [4, 1]]", "[[1, 2], [2, 3], [4, 1]]")
    path.write_text(opened)
    r = hpcontact("run", path, "--out", tmp_path / "y", "-q")
    assert r.returncode == 0, r.stderr
