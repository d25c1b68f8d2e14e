"""Meshes from gmsh end to end: the Hertz quarter cylinder of examples/gmsh/hertz.geo meshed by
gmsh (second order: arcs recovered from midside nodes; first order: arcs named in the problem
file), solved with force control to F/2 = 35000 N, against Shtayerman and the p-examples."""
import json
import math
import os
import shutil
import subprocess

import pytest
import yaml

from conftest import scaled_timeout

GMSH = "/usr/bin/gmsh"
EXAMPLE = "examples/gmsh"
needs_gmsh = pytest.mark.skipif(not os.path.exists(GMSH), reason=f"{GMSH} not installed")


def make_mesh(root, folder, order, name):
    """Meshes examples/gmsh/hertz.geo with gmsh into folder/name (MSH 4.1 ASCII)."""
    geo = folder / "hertz.geo"
    shutil.copy(os.path.join(root, EXAMPLE, "hertz.geo"), geo)
    r = subprocess.run([GMSH, "-2", "-order", str(order), "-format", "msh41", str(geo), "-o",
                        str(folder / name)], capture_output=True, text=True,
                       timeout=scaled_timeout(120))
    assert r.returncode == 0, r.stdout + r.stderr
    return folder / name


def problem(root, folder, example):
    """The example's problem file in `folder`, with the reference curve found where it lies."""
    with open(os.path.join(root, EXAMPLE, example)) as f:
        text = f.read()
    reference = os.path.join(root, "examples", "hertz", "reference-pressure.csv")
    path = folder / example
    path.write_text(text.replace("../hertz/reference-pressure.csv", reference))
    return path


def run(hpcontact, case, out, *sets):
    args = ["run", case, "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    return json.loads((out / "summary.json").read_text())


def arcs(out):
    """(nodes, centre, radius) of every curve of the effective input, with the nodes' positions."""
    with open(out / "input.yaml") as f:
        body = yaml.safe_load(f)["bodies"][0]
    assert "gmsh" not in body
    nodes = {int(k): v for k, v in body["nodes"].items()}
    return [([nodes[n] for n in c["nodes"]], c["arc"]["center"], c["arc"]["radius"])
            for c in body["curves"]], body


@needs_gmsh
def test_second_order_gmsh_mesh_solves_hertz(hpcontact, root, tmp_path):
    """hertz.geo meshed by gmsh with 9-node quads, p = 4, 5, 6: every arc recovered from the
    midside nodes is the circle R = 10 about (0, 10) to 1e-9 (measured 2e-15), the contact force
    is F/2 within 0.1 %, and e_seed against Shtayerman is at the level of the p-examples on the
    seed's 4-element mesh (examples/hertz: p = 5 0.346 %, p = 8 0.158 %; measured here 0.164,
    0.136, 0.072 % with 1020, 1585, 2274 DOF)."""
    make_mesh(root, tmp_path, 2, "hertz.msh")
    case = problem(root, tmp_path, "hertz.yaml")
    dofs = {4: 1020, 5: 1585, 6: 2274}
    errors = {}
    for p in (4, 5, 6):
        out = tmp_path / f"p{p}"
        s = run(hpcontact, case, out, f"discretization.degree={p}")
        c = s["contact"]
        assert s["converged"] and s["dofs"] == dofs[p]
        assert abs(c["resultant"][1] - 35000) <= 35
        errors[p] = c["e_seed_shtayerman_percent"]
        assert errors[p] < 0.346, errors
        curves, body = arcs(out)
        assert len(curves) == 7  # 5 contact edges, 2 beyond
        for ends, centre, radius in curves:
            assert abs(radius - 10) < 1e-9
            assert math.dist(centre, [0, 10]) < 1e-9
            for x in ends:
                assert abs(math.dist(x, [0, 10]) - 10) < 1e-9
        assert len(body["edge_sets"]["contact"]) == 5
        assert len(body["elements"]) == 31
    assert errors[6] < 0.158 and errors[6] < errors[4], errors


@needs_gmsh
def test_first_order_mesh_with_named_arcs_equals_second_order(hpcontact, root, tmp_path):
    """The first-order mesh of the same .geo, its arcs named in the problem file (gmsh.arcs),
    has the same corner nodes and exact geometry, so it gives the second-order mesh's solution
    (strain energy to 1e-10, e_seed to 1e-9)."""
    make_mesh(root, tmp_path, 2, "hertz.msh")
    make_mesh(root, tmp_path, 1, "hertz-linear.msh")
    s2 = run(hpcontact, problem(root, tmp_path, "hertz.yaml"), tmp_path / "order2")
    s1 = run(hpcontact, problem(root, tmp_path, "hertz-linear.yaml"), tmp_path / "order1")
    assert s1["dofs"] == s2["dofs"]
    assert abs(s1["strain_energy"] / s2["strain_energy"] - 1) < 1e-10
    c1, c2 = s1["contact"], s2["contact"]
    assert abs(c1["e_seed_shtayerman_percent"] - c2["e_seed_shtayerman_percent"]) < 1e-9
    curves, _ = arcs(tmp_path / "order1")
    assert len(curves) == 7 and all(r == 10 for _, _, r in curves)


@needs_gmsh
def test_committed_meshes_are_those_of_the_geo(hpcontact, root, tmp_path):
    """examples/gmsh runs without gmsh from its committed .msh files; they are what gmsh makes
    of hertz.geo (the same solution, to round-off)."""
    make_mesh(root, tmp_path, 2, "hertz.msh")
    fresh = run(hpcontact, problem(root, tmp_path, "hertz.yaml"), tmp_path / "fresh")
    for example in ("hertz.yaml", "hertz-linear.yaml"):
        s = run(hpcontact, os.path.join(root, EXAMPLE, example), tmp_path / ("out-" + example))
        assert s["dofs"] == fresh["dofs"] == 1585
        assert abs(s["strain_energy"] / fresh["strain_energy"] - 1) < 1e-10
        assert s["contact"]["reference"] == "../hertz/reference-pressure.csv"


def test_examples_run(hpcontact, root, tmp_path):
    """The committed examples (no gmsh needed): F/2 within 0.1 %, e_seed vs Shtayerman below
    the p = 5 example's 0.346 % (measured 0.136 %)."""
    for example in ("hertz.yaml", "hertz-linear.yaml"):
        s = run(hpcontact, os.path.join(root, EXAMPLE, example), tmp_path / example)
        c = s["contact"]
        assert s["converged"] and abs(c["resultant"][1] - 35000) <= 35
        assert c["e_seed_shtayerman_percent"] < 0.346


@needs_gmsh
def test_triangles_are_refused_with_the_fix(hpcontact, root, tmp_path):
    """A triangle mesh (no recombination) is an error naming the .msh file, the line of the
    first triangle and the gmsh option that makes quadrilaterals."""
    geo = tmp_path / "disc.geo"
    geo.write_text('SetFactory("OpenCASCADE");\nDisk(1) = {0, 0, 0, 1};\n'
                   'Physical Surface("disc") = {1};\nPhysical Curve("rim") = {1};\n')
    r = subprocess.run([GMSH, "-2", "-format", "msh41", str(geo), "-o", str(tmp_path / "disc.msh")],
                       capture_output=True, text=True, timeout=scaled_timeout(120))
    assert r.returncode == 0, r.stdout + r.stderr
    case = tmp_path / "disc.yaml"
    case.write_text("case: disc\nbodies:\n  - name: disc\n    material: {E: 1, nu: 0.3}\n"
                    "    gmsh: {file: disc.msh}\n")
    r = hpcontact("check", case)
    assert r.returncode == 1
    message = r.stderr.strip()
    assert message.count("\n") == 0, message
    assert str(tmp_path / "disc.msh") + ":" in message
    assert "is a 3-node triangle (gmsh type 2): hpcontact needs quadrilaterals; recombine the " \
           "mesh (Mesh.RecombineAll = 1)" in message
