"""The plate with a hole pressed onto a rigid plate (examples/plate-hole, seed §5.1): exponential
convergence of the energy error for p = 2..6 on four elements, the top load carried by the
contact, and the contact model equal to the roller model up to the penalty."""
import json
import math
import os

import pytest

CONTACT = "examples/plate-hole/contact.yaml"
ROLLER = "examples/plate-hole/roller.yaml"
DEGREES = (2, 3, 4, 5, 6)
REFERENCE_DEGREE = 14  # 1680 DOF, about 0.4 s
TOP_LOAD = 1000.0 * 2.0  # pressure × half width, per unit thickness


def run(hpcontact, root, case, degree, out):
    r = hpcontact("run", os.path.join(root, case), "--out", out, "-q",
                  "--set", f"discretization.degree={degree}")
    assert r.returncode == 0, r.stderr
    s = json.loads((out / "summary.json").read_text())
    assert s["converged"], s
    return s


@pytest.fixture(scope="module")
def contact_runs(hpcontact, root, tmp_path_factory):
    """contact.yaml at p = 2..6, 12 and the reference degree, by degree."""
    out = tmp_path_factory.mktemp("plate-hole")
    return {p: run(hpcontact, root, CONTACT, p, out / f"p{p}")
            for p in (*DEGREES, 12, REFERENCE_DEGREE)}


def errors(runs):
    """Relative energy-norm errors sqrt(|U_ref - U_p| / U_ref) (seed eq. 4.3) for p = 2..6."""
    u_ref = runs[REFERENCE_DEGREE]["strain_energy"]
    return [math.sqrt(abs(u_ref - runs[p]["strain_energy"]) / u_ref) for p in DEGREES]


def test_contact_carries_the_top_load(contact_runs):
    """At every degree the solve converges and the vertical contact resultant equals the top
    load, 1000 N/mm² × 2.0 mm, within 0.1 % (the plate has no other vertical support)."""
    for p, s in contact_runs.items():
        fx, fy = s["contact"]["resultant"]
        assert abs(fy - TOP_LOAD) <= 1e-3 * TOP_LOAD, (p, fy)
        assert abs(fx) <= 1e-6 * TOP_LOAD, (p, fx)


def test_dofs_are_the_tensor_space_of_the_four_element_mesh(contact_runs):
    """Free DOF = 2·(10 vertices + 13 edges·(p−1) + 4 elements·(p−1)²) minus ux on the symmetry
    edges (4 vertices, 2 edges)."""
    for p, s in contact_runs.items():
        assert s["dofs"] == 2 * (10 + 13 * (p - 1) + 4 * (p - 1) ** 2) - (4 + 2 * (p - 1))


def test_reference_is_converged(contact_runs):
    """The reference energy (p = 14) is converged far beyond the errors measured: p = 12 and 14
    agree to 1e-6 relative (measured 8.1e-8), 0.3 % of U_ref − U_6 (3.5e-4 relative)."""
    u12 = contact_runs[12]["strain_energy"]
    u_ref = contact_runs[REFERENCE_DEGREE]["strain_energy"]
    assert u_ref >= u12 and (u_ref - u12) / u_ref < 1e-6


def test_energy_error_converges_exponentially(contact_runs):
    """The energy error falls with p = 2..6 exponentially: ln e against p has a least-squares
    slope below −0.45 (measured −0.528, e falls by 1.7 per degree), and against ln DOF the
    curve steepens at every step (measured −0.63, −1.04, −1.36, −1.73), the step 5→6 at least
    twice as steep as 2→3 (measured 2.8 times); algebraic convergence would keep it constant."""
    e = errors(contact_runs)
    assert all(a > b for a, b in zip(e, e[1:])), e
    assert e[-1] < 0.025  # measured 1.86 % at p = 6
    ps = list(DEGREES)
    mean_p, mean_log = sum(ps) / len(ps), sum(math.log(v) for v in e) / len(e)
    slope = (sum((p - mean_p) * (math.log(v) - mean_log) for p, v in zip(ps, e))
             / sum((p - mean_p) ** 2 for p in ps))
    assert slope < -0.45, slope
    dofs = [contact_runs[p]["dofs"] for p in DEGREES]
    loglog = [math.log(e[i + 1] / e[i]) / math.log(dofs[i + 1] / dofs[i])
              for i in range(len(e) - 1)]
    assert all(a > b for a, b in zip(loglog, loglog[1:])), loglog
    assert loglog[-1] < 2.0 * loglog[0], loglog


def test_contact_equals_roller_up_to_the_penalty(hpcontact, root, tmp_path, contact_runs):
    """The whole bottom edge stays in contact, so the contact model is the roller model
    (uy = 0 on the bottom) with a penalty spring: the energies at p = 6 agree to 1e-6 relative
    (measured 4.4e-9; the uniform part of the penetration, 5e-6 mm, is a rigid shift)."""
    u_roller = run(hpcontact, root, ROLLER, 6, tmp_path / "roller")["strain_energy"]
    u_contact = contact_runs[6]["strain_energy"]
    assert abs(u_contact - u_roller) / u_roller < 1e-6
