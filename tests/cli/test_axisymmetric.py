"""Axisymmetric bodies from the command line (issue 18): the thick sphere example against Lamé,
and what does not apply to a solid of revolution refused with its key."""
import json
import math
import os


def test_thick_sphere_energy_is_lames(hpcontact, root, tmp_path):
    """examples/lame/thick-sphere.yaml: the hemisphere's strain energy ½ p u(a) 2π a² = 40π
    N·mm (u(a) = 0.004 mm) to 1e-8 (measured 1.5e-9: energy-norm error 3.9e-5), and the summary
    says its integrals are over the whole solid."""
    r = hpcontact("run", os.path.join(root, "examples/lame/thick-sphere.yaml"), "--out",
                  tmp_path / "s", "-q")
    assert r.returncode == 0, r.stderr
    s = json.loads((tmp_path / "s" / "summary.json").read_text())
    assert abs(s["strain_energy"] / (40 * math.pi) - 1) < 1e-8
    assert "2 pi r" in s["units"]["axisymmetric"]
    # exact: lame_sphere: the energy-norm error from the exact strains (hoop strain included)
    # equals the one from the energies, √((U − U_h)/U), and is below 0.01 %
    e = s["error"]
    assert e["reference"] == "analytic:lame_sphere"
    assert abs(e["reference_energy"] / (40 * math.pi) - 1) < 1e-10
    from_energies = 100 * math.sqrt(1 - s["strain_energy"] / (40 * math.pi))
    assert abs(e["energy_norm_rel_percent"] / from_energies - 1) < 1e-3
    assert e["energy_norm_rel_percent"] < 0.01


def test_what_does_not_apply_is_refused(hpcontact, root, tmp_path):
    case = os.path.join(root, "examples/lame/thick-sphere.yaml")
    r = hpcontact("run", case, "--out", tmp_path / "t", "--set", "bodies[0].material.thickness=2")
    assert r.returncode != 0 and "bodies[0].material.thickness" in r.stderr
    assert "axisymmetric" in r.stderr and not (tmp_path / "t" / "summary.json").exists()
    # the Hertz cylinder read as a ball: its section is the whole solid, so the target is the
    # total force, and a compare.force of the cylinder's (twice the target) is refused as such
    r = hpcontact("run", os.path.join(root, "examples/hertz/p8.yaml"), "--out", tmp_path / "c",
                  "--set", "bodies[0].material.plane=axisymmetric")
    assert r.returncode != 0 and "contact[0].compare.force" in r.stderr
    assert "(a whole model)" in r.stderr


def test_hoop_strain_and_stress_in_the_vtu_are_lames(hpcontact, root, tmp_path):
    """solution.vtu of the thick sphere: strain_hoop = u_r / r = A + B / r³ and sigma_zz (the hoop
    stress) = A' + B' / r³ (Lamé: A = p a³ (1 − 2ν) / (E (b³ − a³)), B = p a³ b³ (1 + ν) / (2 E
    (b³ − a³)), σθ = p a³ / (b³ − a³) (1 + b³ / 2r³)) at every sampled point: the strain to 1e-5
    of its largest value, the stress to 3e-4 (1.2e-4 measured, at the inner surface; p = 8, the
    energy-norm error 3.9e-5)."""
    import meshio
    import numpy as np
    r = hpcontact("run", os.path.join(root, "examples/lame/thick-sphere.yaml"), "--out", tmp_path / "s", "-q")
    assert r.returncode == 0, r.stderr
    vtu = meshio.read(tmp_path / "s" / "solution.vtu")
    X = vtu.points[:, :2]
    rr = np.hypot(X[:, 0], X[:, 1])
    a, b, p, E, nu = 10.0, 20.0, 100.0, 200000.0, 0.3
    A = p * a**3 * (1 - 2 * nu) / (E * (b**3 - a**3))
    B = p * a**3 * b**3 * (1 + nu) / (2 * E * (b**3 - a**3))
    hoop = A + B / rr**3
    off_axis = X[:, 0] > 1e-9
    assert off_axis.sum() > 100
    strain = vtu.point_data["strain_hoop"]
    assert np.max(np.abs(strain - hoop)) < 1e-5 * np.max(hoop)
    # and the displacement's own u_r / r off the axis, to the file's 10 digits
    u = vtu.point_data["displacement"]
    assert np.max(np.abs(strain[off_axis] - u[off_axis, 0] / X[off_axis, 0])) < 1e-9 * np.max(hoop)
    sigma_hoop = p * a**3 / (b**3 - a**3) * (1 + b**3 / (2 * rr**3))
    assert np.max(np.abs(vtu.point_data["sigma_zz"] - sigma_hoop)) < 3e-4 * np.max(sigma_hoop)
