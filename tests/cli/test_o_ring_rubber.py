"""The Mooney-Rivlin O-ring (examples/o-ring/o-ring-mooney-rivlin.yaml: the axisymmetric ring of
o-ring-axisymmetric.yaml with a rubber law, p = 5, 4 load steps), checked against what holds
independently of the program:

- the total force is the pressure over the surface of revolution, 2 pi ∫ p r ds along the
  deformed contact.csv points (trapezoidal rule; the sampled points miss the zone ends' jump, as
  in test_o_ring_axisymmetric.py: asserted to 5 %), and it grows faster and faster with the
  squeeze;
- at a small squeeze every law is linear elasticity of its small-strain moduli: the ring of
  mooney-rivlin (mu = 2 (C10 + C01) = 3.4, K = 35) and that of the compressible neo-hooke with the
  same mu and K (E = 9 K mu / (3 K + mu), nu = (3 K - 2 mu) / (2 (3 K + mu))) carry the same force
  up to the strains in the contact, O(a/R) ~ sqrt(squeeze) for a Hertzian contact: at 1 % and
  5 % of the 0.4 mm squeeze the forces agree to 2e-3 (measured 5.7e-4 and 1.2e-3), and the
  difference grows by about sqrt(5) (measured 2.13) between them;
- a rubber law's constants are refused naming the file and the key when they do not apply."""
import csv
import json
import math
import os

import pytest

CASE = "examples/o-ring/o-ring-mooney-rivlin.yaml"
MU, K = 3.4, 35.0


def run(hpcontact, root, out, case=CASE, *sets):
    args = ["run", os.path.join(root, case), "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


def column(rows, name):
    return [float(r[name]) for r in rows]


def test_force_is_the_pressure_over_the_ring_and_grows(hpcontact, root, tmp_path):
    summary = run(hpcontact, root, tmp_path / "mr")
    assert summary["converged"]
    with open(tmp_path / "mr" / "contact.csv") as f:
        points = list(csv.DictReader(f))
    with open(tmp_path / "mr" / "contact_history.csv") as f:
        history = list(csv.DictReader(f))
    F = summary["contact"]["normal_force"]
    p, x, y = column(points, "pressure"), column(points, "x"), column(points, "y")
    integral = sum(0.5 * (p[i] * 2 * math.pi * x[i] + p[i + 1] * 2 * math.pi * x[i + 1])
                   * math.hypot(x[i + 1] - x[i], y[i + 1] - y[i]) for i in range(len(p) - 1))
    assert abs(integral / F - 1) < 0.05, (integral, F)
    forces = [0.0] + column(history, "normal_force")
    steps = [b - a for a, b in zip(forces, forces[1:])]
    assert len(steps) == 4 and all(s > 0 for s in steps)
    assert all(b > a for a, b in zip(steps, steps[1:])), steps


def test_small_squeeze_is_the_linear_law_of_mu_and_K(hpcontact, root, tmp_path):
    E = 9 * K * MU / (3 * K + MU)
    nu = (3 * K - 2 * MU) / (2 * (3 * K + MU))
    difference = []
    for fraction in (0.01, 0.05):
        squeeze = f"contact[0].obstacle.displacement=[0, {-0.4 * fraction!r}]"
        rubber = run(hpcontact, root, tmp_path / f"mr{fraction}", CASE, squeeze)
        neo = run(hpcontact, root, tmp_path / f"nh{fraction}", "examples/o-ring/o-ring-axisymmetric.yaml",
                  squeeze, "discretization.degree=5", "solver.load_steps=4",
                  f"bodies[0].material.E={E!r}", f"bodies[0].material.nu={nu!r}")
        difference.append(abs(rubber["contact"]["normal_force"] / neo["contact"]["normal_force"] - 1))
    assert max(difference) < 2e-3, difference
    assert 1.7 < difference[1] / difference[0] < 2.8, difference


def test_constants_that_do_not_apply_are_refused(hpcontact, root, tmp_path):
    refused = [("bodies[0].material.E=10", "bodies[0].material.E",
                "is not a constant of model mooney-rivlin (it takes C10, C01, K)"),
               ("bodies[0].material.C20=0.1", "bodies[0].material.C20", "is not a constant"),
               ("bodies[0].material.K=0", "bodies[0].material.K", "must be > 0 (got 0)"),
               ("bodies[0].material.C01=-0.3", "bodies[0].material.C01", "must be >= 0"),
               ("bodies[0].material.model=yeoh", "bodies[0].material.C01",
                "is not a constant of model yeoh (it takes C10, C20, C30, K)"),
               ("bodies[0].material.model=neo-hooke", "bodies[0].material",
                "missing required key 'E' (model neo-hooke takes E, nu)"),
               ("bodies[0].material.plane=stress", "bodies[0].material.plane",
                "mooney-rivlin is implemented in plane strain and axisymmetry only")]
    for setting, key, cause in refused:
        r = hpcontact("run", os.path.join(root, CASE), "--out", tmp_path / "x", "--set", setting)
        assert r.returncode != 0, setting
        assert "o-ring-mooney-rivlin.yaml" in r.stderr and key in r.stderr and cause in r.stderr, r.stderr
        assert not (tmp_path / "x" / "summary.json").exists()
