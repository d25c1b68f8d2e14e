"""ParaView output: solution.vtu and contact.vtu parse as XML with the documented arrays, and
with output.steps a .pvd lists one file per converged load step (the rows of path.csv)."""
import csv
import os
import xml.etree.ElementTree as ET

import numpy as np


def arrays(path):
    root = ET.parse(path).getroot()
    piece = root.find("UnstructuredGrid/Piece")
    data = {a.get("Name"): np.array(a.text.split(), dtype=float)
            for a in piece.iter("DataArray") if a.get("Name")}
    return int(piece.get("NumberOfPoints")), data


def test_contact_vtu_and_load_steps(hpcontact, root, tmp_path):
    out = tmp_path / "coulomb"
    r = hpcontact("run", os.path.join(root, "examples/two-bars/coulomb.yaml"), "--out", out, "-q",
                  "--set", "output.steps=true")
    assert r.returncode == 0, r.stderr
    n, body = arrays(out / "solution.vtu")
    for name in ("displacement", "von_mises", "principal_1", "principal_2", "sigma_xx",
                 "strain_xx", "degree", "element", "body"):
        assert name in body, name
    assert n > 0 and np.all(np.isfinite(body["von_mises"]))

    with open(out / "contact.csv") as f:
        rows = list(csv.DictReader(f))
    # contact.vtu holds each pair's own body's points; contact.csv both bodies' (upper first)
    rows = [row for row in rows if row["body"] == rows[0]["body"]]
    n, contact = arrays(out / "contact.vtu")
    assert n == len(rows)
    for name in ("traction", "gap", "pressure", "pressure_from_stress", "tangential_traction",
                 "slip", "state", "displacement", "pair"):
        assert name in contact, name
    p_csv = np.array([float(row["pressure"]) for row in rows])
    assert np.allclose(contact["pressure"], p_csv, rtol=1e-10, atol=1e-9 * p_csv.max())
    states = {"open": 0, "contact": 1, "stick": 2, "slip": 3}
    assert list(contact["state"].astype(int)) == [states[row["state"]] for row in rows]
    # The traction's normal part is the pressure: |traction| >= pressure at every point.
    t = contact["traction"].reshape(-1, 3)[:, :2]
    assert np.all(np.linalg.norm(t, axis=1) >= contact["pressure"] * (1 - 1e-12))

    with open(out / "path.csv") as f:
        steps = list(csv.DictReader(f))
    for pvd in ("solution.pvd", "contact.pvd"):
        sets = ET.parse(out / pvd).getroot().findall("Collection/DataSet")
        assert len(sets) == len(steps) >= 2
        assert [float(s.get("timestep")) for s in sets] == list(range(1, len(steps) + 1))
        for s in sets:
            m, data = arrays(out / s.get("file"))
            assert m > 0 and "displacement" in data
    # The last step is the solution.
    _, last = arrays(out / "steps" / f"step-{len(steps):04d}.vtu")
    assert np.array_equal(last["displacement"], body["displacement"])


def test_stress_fields_of_lame_cylinder(hpcontact, root, tmp_path):
    """The stress fields solution.vtu holds are Lamé's at every written point of the thick
    cylinder (p = 10): σ_r = A − B/r², σ_θ = A + B/r² (A = p a²/(b² − a²), B = A b²; a = 10,
    b = 20, p = 100), σ_z = ν(σ_r + σ_θ); principal_1 = σ_θ, principal_2 = σ_r; von Mises
    √(½((σ_r − σ_θ)² + (σ_θ − σ_z)² + (σ_z − σ_r)²)). Within 1e-5 p (measured 2.3e-6 p)."""
    r = hpcontact("run", os.path.join(root, "examples/lame/thick-cylinder.yaml"), "--out", tmp_path,
                  "-q", "--set", "discretization.degree=10")
    assert r.returncode == 0, r.stderr
    piece = ET.parse(tmp_path / "solution.vtu").getroot().find("UnstructuredGrid/Piece")
    xyz = np.array(piece.find("Points/DataArray").text.split(), dtype=float).reshape(-1, 3)
    _, f = arrays(tmp_path / "solution.vtu")
    a, b, p, nu = 10.0, 20.0, 100.0, 0.3
    A = p * a * a / (b * b - a * a)
    B = A * b * b
    rad = np.hypot(xyz[:, 0], xyz[:, 1])
    c, s = xyz[:, 0] / rad, xyz[:, 1] / rad
    sr, st = A - B / rad**2, A + B / rad**2
    sz = nu * (sr + st)
    expected = {
        "sigma_xx": sr * c * c + st * s * s,
        "sigma_yy": sr * s * s + st * c * c,
        "sigma_xy": (sr - st) * s * c,
        "sigma_zz": sz,
        "principal_1": st,
        "principal_2": sr,
        "von_mises": np.sqrt(0.5 * ((sr - st)**2 + (st - sz)**2 + (sz - sr)**2)),
    }
    assert len(rad) > 100 and np.all((rad > a * (1 - 1e-8)) & (rad < b * (1 + 1e-8)))
    for name, value in expected.items():
        err = np.max(np.abs(f[name] - value))
        assert err < 1e-5 * p, (name, err)
