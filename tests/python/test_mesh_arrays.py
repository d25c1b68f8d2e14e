"""The Python module's mesh with fields (issue 44 item 5): result.mesh() against Lamé's closed
form at every sampled point, and against solution.vtu as meshio reads it (the same arrays), for
one body and for two."""
import os

import meshio
import numpy as np
import pytest

import hpcontact


def lame_closed_form(X, E=200000.0, nu=0.3, a=10.0, b=20.0, p=100.0):
    """Plane strain thick cylinder under inner pressure p: u_r = (1+nu)/E ((1-2nu) A r + B/r),
    sigma_r = A - B/r², sigma_t = A + B/r², sigma_z = 2 nu A, A = p a²/(b²-a²), B = A b²."""
    r = np.hypot(X[:, 0], X[:, 1])
    A = p * a * a / (b * b - a * a)
    B = A * b * b
    u_r = (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r)
    c, s = X[:, 0] / r, X[:, 1] / r
    sr, st = A - B / r**2, A + B / r**2
    stress = np.column_stack([sr * c * c + st * s * s, sr * s * s + st * c * c, (sr - st) * c * s,
                              np.full_like(r, 2 * nu * A)])
    return np.column_stack([u_r * c, u_r * s]), stress


def test_lame_fields_at_every_sampled_point(lame):
    """p = 8 on two exact-arc elements: displacement to 1e-6 of its largest value and stresses to
    2e-4 of the pressure at each of the 2 × 9 × 9 points (the discretisation's error: 2.6e-7 and
    5.7e-5 measured); the von Mises column is the stress's."""
    m = lame.mesh()
    assert m["points"].shape == (2 * 81, 2) and m["cells"].shape == (2 * 64, 4)
    assert list(m["cell_degree"]) == [8] * 128 and m["body_names"] == ["cylinder"]
    u, stress = lame_closed_form(m["points"])
    np.testing.assert_allclose(m["displacement"], u, atol=1e-6 * np.abs(u).max())
    np.testing.assert_allclose(m["stress"], stress, atol=2e-4 * 100)
    sxx, syy, sxy, szz = m["stress"].T
    vm = np.sqrt(0.5 * ((sxx - syy) ** 2 + (syy - szz) ** 2 + (szz - sxx) ** 2) + 3 * sxy**2)
    np.testing.assert_allclose(m["von_mises"], vm, rtol=1e-12, atol=1e-9)
    # every cell counter-clockwise on the undeformed points (positive signed area)
    P = m["points"][m["cells"]]
    area = 0.5 * np.sum(P[:, :, 0] * np.roll(P[:, :, 1], -1, axis=1) - np.roll(P[:, :, 0], -1, axis=1) * P[:, :, 1], axis=1)
    assert np.all(area > 0)
    # the same points as result.displacement() locates
    np.testing.assert_allclose(lame.displacement(m["points"][::7]), m["displacement"][::7], rtol=0, atol=1e-12)


@pytest.mark.parametrize("case", [os.path.join("lame", "thick-cylinder.yaml"), os.path.join("two-bars", "stick.yaml"),
                                  os.path.join("o-ring", "o-ring-incompressible.yaml")])
def test_mesh_is_solution_vtu_as_meshio_reads_it(root, tmp_path, case):
    """Every array equal to the file's (its 10 significant digits), the cells the same."""
    result = hpcontact.Problem.from_file(os.path.join(root, "examples", case)).run(out=tmp_path / "out")
    m = result.mesh()
    vtu = meshio.read(tmp_path / "out" / "solution.vtu")
    np.testing.assert_array_equal(vtu.cells_dict["quad"], m["cells"])
    np.testing.assert_allclose(vtu.points[:, :2], m["points"], rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(vtu.point_data["displacement"][:, :2], m["displacement"], rtol=1e-9, atol=1e-15)
    for k, name in enumerate(["sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz"]):
        np.testing.assert_allclose(vtu.point_data[name], m["stress"][:, k], rtol=1e-9, atol=1e-9, err_msg=name)
    for k, name in enumerate(["strain_xx", "strain_yy", "gamma_xy"]):
        np.testing.assert_allclose(vtu.point_data[name], m["strain"][:, k], rtol=1e-9, atol=1e-15, err_msg=name)
    np.testing.assert_allclose(vtu.point_data["von_mises"], m["von_mises"], rtol=1e-9, atol=1e-9)
    np.testing.assert_array_equal(vtu.cell_data["body"][0], m["cell_body"])
    np.testing.assert_array_equal(vtu.cell_data["element"][0], m["cell_element"])
    assert len(m["body_names"]) == 1 + ("two-bars" in case)
    # the mixed element's pressure where a body has one, as the file's pressure_mixed
    assert ("pressure_mixed" in m) == ("incompressible" in case) == ("pressure_mixed" in vtu.point_data)
    if "pressure_mixed" in m:
        p = m["pressure_mixed"]
        np.testing.assert_allclose(vtu.point_data["pressure_mixed"], p, rtol=1e-9, atol=1e-9 * np.abs(p).max())
        assert np.abs(p).max() > 0


def test_subdivisions(lame):
    """subdivisions = 3: 4 × 4 points and 9 cells per element; out of range refused."""
    m = lame.mesh(subdivisions=3)
    assert m["points"].shape == (2 * 16, 2) and m["cells"].shape == (2 * 9, 4)
    with pytest.raises(ValueError, match="subdivisions"):
        lame.mesh(subdivisions=-1)
