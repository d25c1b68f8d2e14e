"""3D problems through the command line (`dimension: 3`, one body of hexahedra): a uniform
stress state reproduced to round-off through face sets, constraints, traction and pressure
loads, the energy, summary.json and solution.vtu; the thick sphere's octant against Lamé; check;
and every refusal of a 3D input naming the file, the key and the cause."""
import json
import math
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from conftest import expect_refused

E, NU, T = 5000.0, 0.27, 3.0
BOX = f"""case: uniform-3d
dimension: 3
bodies:
  - name: block
    material: {{E: {E}, nu: {NU}}}
    box: {{from: [1, -1, 0], to: [4, 1, 0.5], elements: [3, 2, 1]}}
    constraints:
      - {{faces: [x0], ux: 0}}
      - {{faces: [y0], uy: 0}}
      - {{faces: [z0], uz: 0}}
    loads:
      - {{faces: [x1], traction: [{T}, 0, 0]}}
discretization: {{degree: 3}}
output: {{vtu_subdivisions: 2}}
"""


@pytest.fixture
def box(tmp_path):
    path = tmp_path / "box.yaml"
    path.write_text(BOX)
    return str(path)


def run_ok(hpcontact, case, out, *sets):
    args = ["run", case, "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def vtu_arrays(path):
    """Points, cells and every point array of a .vtu file written in ASCII."""
    piece = ET.parse(path).getroot().find("UnstructuredGrid/Piece")
    def array(node):
        n = int(node.get("NumberOfComponents", "1"))
        values = np.array(node.text.split(), dtype=float)
        return values.reshape(-1, n) if n > 1 else values
    points = array(piece.find("Points/DataArray"))
    cells = {a.get("Name"): array(a) for a in piece.find("Cells")}
    data = {a.get("Name"): array(a) for a in piece.find("PointData")}
    return int(piece.get("NumberOfCells")), points, cells, data


@pytest.mark.parametrize("load", ["traction", "pressure", "displacement"])
def test_a_uniform_stress_is_reproduced_to_round_off(hpcontact, box, tmp_path, load):
    """σ_xx = T on a 3 × 2 × 0.5 box held by three symmetry planes: u = (T x'/E, −ν T y'/E,
    −ν T z/E) with x' = x − 1, y' = y + 1, the energy T² V / (2E), at every point of
    solution.vtu; the pressure −T on x1 is the same load, and so is u_x = 3T/E prescribed on x1
    (its vertex modes moved, its edge and face modes not)."""
    sets = {"traction": [],
            "pressure": [f"bodies[0].loads=[{{faces: [x1], pressure: {-T}}}]"],
            "displacement": ["bodies[0].loads=[]",
                             "bodies[0].constraints=[{faces: [x0], ux: 0}, {faces: [y0], uy: 0}, "
                             f"{{faces: [z0], uz: 0}}, {{faces: [x1], ux: {3 * T / E!r}}}]"]}[load]
    s = run_ok(hpcontact, box, str(tmp_path / "out"), *sets)
    volume = 3 * 2 * 0.5
    assert s["dimension"] == 3 and s["elements"] == 6 and s["converged"]
    assert s["volume"] == pytest.approx(volume, rel=1e-13)
    assert s["strain_energy"] == pytest.approx(T * T * volume / (2 * E), rel=1e-11)
    corner = math.hypot(T * 3 / E, NU * T * 2 / E, NU * T * 0.5 / E)
    assert s["displacement_max"] == pytest.approx(corner, rel=1e-11)
    assert s["von_mises_max"]["value"] == pytest.approx(T, rel=1e-11)
    n_cells, x, cells, data = vtu_arrays(str(tmp_path / "out" / "solution.vtu"))
    assert n_cells == 6 * 2 ** 3 and len(x) == 6 * 3 ** 3
    expected = np.column_stack([T * (x[:, 0] - 1) / E, -NU * T * (x[:, 1] + 1) / E,
                                -NU * T * x[:, 2] / E])
    assert np.abs(data["displacement"] - expected).max() < 1e-12 * T / E * 10
    assert np.abs(data["sigma_xx"] - T).max() < 1e-10 * T
    for name in ["sigma_yy", "sigma_zz", "sigma_yz", "sigma_xz", "sigma_xy"]:
        assert np.abs(data[name]).max() < 1e-10 * T, name
    assert np.abs(data["principal_stress"][:, 0] - T).max() < 1e-10 * T
    assert np.abs(data["von_mises"] - T).max() < 1e-10 * T


def test_the_thick_sphere_octant_against_lame(hpcontact, root, tmp_path):
    """examples/solid/thick-sphere-octant.yaml: 3 blending hexahedra, p = 6 — the energy from
    below within 1e-6 of Lamé's (measured 6.9e-7, as the library's test at p = 6), the reported
    energy-norm error its square root; at p = 4 the error larger (2.3e-4 measured)."""
    case = os.path.join(root, "examples", "solid", "thick-sphere-octant.yaml")
    a, b, p, E_, nu = 1.0, 2.0, 1.0, 1000.0, 0.3
    u_a = p * a ** 3 / (E_ * (b ** 3 - a ** 3)) * ((1 - 2 * nu) * a + (1 + nu) * b ** 3 / (2 * a * a))
    exact = 0.5 * p * u_a * 4 * math.pi * a * a / 8
    errors = {}
    for degree in (4, 6):
        s = run_ok(hpcontact, case, str(tmp_path / f"p{degree}"), f"discretization.degree={degree}")
        errors[degree] = (exact - s["strain_energy"]) / exact
        assert s["error"]["energy_rel_percent"] == pytest.approx(
            100 * math.sqrt(abs(errors[degree])), rel=1e-6)
    assert 0 < errors[6] < 1e-6
    assert errors[4] > 50 * errors[6]


def test_check_describes_a_3d_problem(hpcontact, box):
    r = hpcontact("check", box)
    assert r.returncode == 0, r.stderr
    assert "3D, p-version (hexahedra, trunk space)" in r.stdout
    assert "6 hexahedra, degree 3,3,3" in r.stdout
    assert "x0 (2) x1 (2) y0 (3) y1 (3) z0 (6) z1 (6)" in r.stdout


@pytest.mark.parametrize("old,new,message", [
    ("dimension: 3", "dimension: 2", "box.yaml:2:12: dimension: must be >= 3 (got 2)"),
    ("faces: [x0], ux: 0", "faces: [left], ux: 0",
     "box.yaml:8:18: bodies[0].constraints[0].faces[0]: no face set of that name in the body's "
     "mesh (it has: x0, x1, y0, y1, z0, z1; got 'left')"),
    ("    constraints:", "    shell_octant: {inner_radius: 1, outer_radius: 2}\n    constraints:",
     "bodies[0]: has more than one mesh: give one of box, shell_octant and gmsh"),
    ("to: [4, 1, 0.5]", "to: [4, 1, -1]",
     "bodies[0].box.to: must be larger than from in every coordinate (coordinate 2: -1 <= 0)"),
    ("discretization:", "  - {name: b, material: {E: 1, nu: 0}, box: {from: [0,0,0], to: [1,1,1]}}"
     "\ndiscretization:", "bodies[1]: a 3D problem has one body"),
    ("nu: 0.27}", "nu: 0.27, plane: strain}", "bodies[0].material.plane: unknown key"),
    ("traction: [3.0, 0, 0]", "traction: [3.0, 0, 0], pressure: 1",
     "bodies[0].loads[0]: give one of traction and pressure"),
    ("faces: [y0], uy: 0", "faces: [y0]",
     "bodies[0].constraints[1]: prescribes nothing: give ux, uy or uz"),
    ("faces: [y0], uy: 0", "faces: [y0, x0], uy: 0, ux: 1",
     "bodies[0].constraints[1]: gives ux = 1 on faces where "
     "bodies[0].constraints[0] (line 8) gives 0: a node cannot move by both"),
    ("      - {faces: [y0], uy: 0}\n", "",
     "body 'block': the stiffness cannot be factorised — is the body held against every rigid "
     "motion"),
    ("degree: 3", "degree: [3, 3]",
     "discretization.degree: must be an integer or [p_xi, p_eta, p_zeta] (got [3, 3])"),
    ("degree: 3", "degree: 13", "discretization.degree: must be <= 12 (got 13)"),
    ("elements: [3, 2, 1]", "elements: 200", "more than the 5e+07 a run may have"),
    ("traction: [3.0, 0, 0]", "traction: [3.0, 0]",
     "bodies[0].loads[0].traction: must be [x, y, z] (got [3.0, 0])"),
])
def test_a_wrong_3d_input_is_refused_naming_the_cause(hpcontact, tmp_path, old, new, message):
    assert old in BOX
    path = tmp_path / "box.yaml"
    path.write_text(BOX.replace(old, new))
    expect_refused(hpcontact, str(path), str(tmp_path / "out"), [], message, 1)


def test_a_wrong_3d_value_from_the_command_line_is_a_usage_error(hpcontact, box, tmp_path):
    """As for a 2D problem: a value given by --set that is wrong is the command line's error."""
    r = hpcontact("run", box, "--out", str(tmp_path / "out"), "-q", "--set", "dimension=2")
    assert r.returncode == 2
    assert "dimension (from --set): must be >= 3 (got 2)" in r.stderr


def test_a_gmsh_body_and_its_wrong_inputs(hpcontact, root, tmp_path):
    """A 3D body from a gmsh file (examples/plate-hole-3d): its face sets are the physical
    surfaces, the effective input names the file by its absolute path (input.yaml runs from its
    own folder), and an unknown volume, an unknown face set and a missing file are refused by
    their keys."""
    mesh = os.path.join(root, "examples", "plate-hole-3d", "plate-thin.msh")
    text = f"""case: plate
dimension: 3
bodies:
  - name: plate
    material: {{E: 1000, nu: 0.25}}
    gmsh: {{file: {mesh}, volumes: [plate]}}
    constraints:
      - {{faces: [x0], ux: 0}}
      - {{faces: [y0], uy: 0}}
      - {{faces: [z0], uz: 0}}
    loads:
      - {{faces: [end], pressure: -1}}
discretization: {{degree: 2}}
"""
    path = tmp_path / "plate.yaml"
    path.write_text(text)
    first = run_ok(hpcontact, str(path), str(tmp_path / "a"))
    again = run_ok(hpcontact, str(tmp_path / "a" / "input.yaml"), str(tmp_path / "b"))
    assert again["strain_energy"] == first["strain_energy"] and first["elements"] == 33
    for old, new, message in [
            ("volumes: [plate]", "volumes: [steel]",
             "bodies[0].gmsh.volumes[0]: no 3D physical group of that name"),
            ("faces: [end]", "faces: [top]", "no face set of that name in the body's mesh (it "
             "has: end, hole, side, x0, y0, z0, z1; got 'top')"),
            ("plate-thin.msh", "missing.msh", "bodies[0].gmsh.file: ")]:
        bad = tmp_path / "bad.yaml"
        bad.write_text(text.replace(old, new))
        expect_refused(hpcontact, str(bad), str(tmp_path / "bad"), [], message, 1)


def test_a_surface_that_the_faces_are_not_on_is_refused(hpcontact, root, tmp_path):
    """bodies[].surfaces with a radius the hole's nodes are not at: refused naming the surface's
    key and the element (the vertices must lie on it)."""
    case = os.path.join(root, "examples", "plate-hole-3d", "plate-hole-3d.yaml")
    text = open(case).read().replace("radius: 2}", "radius: 2.1}")
    assert "radius: 2.1}" in text
    bad = tmp_path / "plate.yaml"
    bad.write_text(text.replace("plate-thin.msh", os.path.join(os.path.dirname(case), "plate-thin.msh")))
    r = hpcontact("run", str(bad), "--out", str(tmp_path / "out"), "-q")
    assert r.returncode == 1, r.stderr
    assert "bodies[0].surfaces[0]: element 0 of the mesh: vertex V0 is not on cylinder(" in r.stderr


def test_a_resultant_scales_the_load_to_that_force(hpcontact, box, tmp_path):
    """traction [1, 0, 0] on x1 (area 2 × 0.5) with resultant 3: the traction 3 / 1 = 3 = T, the
    uniform state again; a pressure on all six faces of the box (a closed surface) with a
    resultant is refused: its integral vanishes."""
    s = run_ok(hpcontact, box, str(tmp_path / "a"),
               "bodies[0].loads=[{faces: [x1], traction: [1, 0, 0], resultant: 3}]")
    assert s["strain_energy"] == pytest.approx(T * T * 3 / (2 * E), rel=1e-11)
    path = tmp_path / "closed.yaml"
    path.write_text(BOX.replace("- {faces: [x1], traction: [3.0, 0, 0]}",
                                "- {faces: [x0, x1, y0, y1, z0, z1], pressure: 1, resultant: 5}"))
    expect_refused(hpcontact, str(path), str(tmp_path / "b"), [],
                   "bodies[0].loads[0]: the load's integral over its faces vanishes", 1)


def test_a_face_on_two_surfaces_is_refused(hpcontact, root, tmp_path):
    """The hole's face set named on two cylinders: refused naming the second surface's key."""
    case = os.path.join(root, "examples", "plate-hole-3d", "plate-hole-3d.yaml")
    line = "      - {faces: [hole], cylinder: {point: [0, 0, 0], axis: [0, 0, 1], radius: 2}}\n"
    text = open(case).read()
    assert line in text
    text = text.replace(line, line + line.replace("radius: 2}", "radius: 3}"))
    bad = tmp_path / "plate.yaml"
    bad.write_text(text.replace("plate-thin.msh", os.path.join(os.path.dirname(case), "plate-thin.msh")))
    r = hpcontact("run", str(bad), "--out", str(tmp_path / "out"), "-q")
    assert r.returncode == 1, r.stderr
    assert "bodies[0].surfaces[1]: face " in r.stderr
    assert "is also in the sets of bodies[0].surfaces[0]: a face lies on one surface" in r.stderr
