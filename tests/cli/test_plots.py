"""The general plot scripts on a real run: scripts/plot_contact.py (contact.csv of any case),
scripts/plot_field.py (a field of solution.vtu on the deformed mesh, with the rigid obstacles,
at a scale that keeps touching bodies apart) and scripts/plot_pressure.py (what its view clips);
the units of their labels."""
import csv
import json
import os
import subprocess

import numpy as np
import pytest

from conftest import load_script, scaled_timeout

PYTHON = "/usr/bin/python3"


def run_script(root, name, *args):
    return subprocess.run([PYTHON, os.path.join(root, "scripts", name), *map(str, args)],
                          capture_output=True, text=True, timeout=scaled_timeout(120))


def test_contact_and_field_plots_of_the_tutorial_punch(hpcontact, root, tmp_path):
    out = tmp_path / "punch"
    r = hpcontact("run", os.path.join(root, "examples/tutorial/punch.yaml"), "--out", out, "-q",
                  "--set", "discretization.degree=4")
    assert r.returncode == 0, r.stderr
    r = run_script(root, "plot_contact.py", out, "--out", tmp_path / "contact.png")
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "contact.png").stat().st_size > 10000
    r = run_script(root, "plot_field.py", out / "solution.vtu", "--out", tmp_path / "vm.png")
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "vm.png").stat().st_size > 10000
    # A field the file does not have is refused with its name.
    r = run_script(root, "plot_field.py", out / "solution.vtu", "--field", "colour")
    assert r.returncode != 0 and "colour" in r.stderr


def test_plot_field_keeps_touching_bodies_apart_at_its_automatic_scale(hpcontact, root, tmp_path):
    """Two cylinders pressed together (examples/hertz/bilateral.yaml): magnifying the
    displacements 5 % of the size would push one into the other; the automatic scale is the
    largest (at least 1) at which the drawn bodies overlap no deeper than the solution itself
    does plus 0.2 % of the size, and the plot says so."""
    out = tmp_path / "bilateral"
    r = hpcontact("run", os.path.join(root, "examples/hertz/bilateral.yaml"), "--out", out, "-q",
                  "--set", "discretization.degree=5")
    assert r.returncode == 0, r.stderr
    r = run_script(root, "plot_field.py", out / "solution.vtu", "--out", tmp_path / "vm.png")
    assert r.returncode == 0, r.stderr
    assert "the largest at which touching bodies neither overlap nor part" in r.stdout, r.stdout

    pf = load_script("plot_field")
    X, cells, points, cell_data = pf.read_vtu(str(out / "solution.vtu"))
    u = points["displacement"][:, :2]
    cells = np.array(cells).reshape(-1, 4)
    body = cell_data["body"].astype(int)
    loops = {b: pf.boundary_loops(cells, body, b, X) for b in (0, 1)}
    assert all(len(loops[b]) == 1 for b in (0, 1))            # each body one closed boundary
    size = np.linalg.norm(X.max(axis=0) - X.min(axis=0))
    scale, _ = pf.choose_scale(X, u, size, [], loops, [(0, 1)])
    depth = lambda s: pf.penetration(X + s * u, s, [], loops, [(0, 1)])  # noqa: E731
    allowed = depth(1.0) + pf.OVERLAP_TOLERANCE * size
    wanted = 0.05 * size / np.abs(u).max()
    assert 1.0 <= scale < wanted
    assert depth(scale) <= allowed < depth(wanted)
    assert f"× {scale:.4g}" in r.stdout


def test_plot_field_draws_the_rigid_obstacles_where_they_are(hpcontact, root, tmp_path):
    """The obstacles of input.yaml are drawn (and named) at their place: the signed distance of
    each kind is that of its geometry, a curve through points is the spline through them."""
    out = tmp_path / "punch"
    r = hpcontact("run", os.path.join(root, "examples/tutorial/punch.yaml"), "--out", out, "-q",
                  "--set", "discretization.degree=4")
    assert r.returncode == 0, r.stderr
    r = run_script(root, "plot_field.py", out / "solution.vtu", "--out", tmp_path / "vm.png")
    assert r.returncode == 0 and "obstacles: rigid plane (contact[0])" in r.stdout, r.stdout

    pf = load_script("plot_field")
    pts = np.array([[0.0, 2.0], [3.0, -0.5]])
    plane = pf.Obstacle({"type": "plane", "point": [0, 0], "normal": [0, 2],
                         "displacement": [0, 1]}, shift=0.5)
    assert np.allclose(plane.distance(pts, 1.0), [1.5, -1.0])   # moved up by 0.5
    circle = pf.Obstacle({"type": "circle", "center": [0, 0], "radius": 1.0}, shift=1.0)
    assert np.allclose(circle.distance(np.array([[2.0, 0.0], [0.5, 0.0]]), 1.0), [1.0, -0.5])
    hole = pf.Obstacle({"type": "circle", "center": [0, 0], "radius": 1.0, "inside": True}, 1.0)
    assert np.allclose(hole.distance(np.array([[0.5, 0.0]]), 1.0), [0.5])
    knots = [[0, 0], [1, 0.5], [2, 0], [3, -1]]
    curve = pf.Obstacle({"type": "curve", "points": knots}, 1.0)
    assert np.abs(curve.distance(np.array(knots, dtype=float), 1.0)).max() < 1e-9
    assert curve.distance(np.array([[1.0, 2.0]]), 1.0)[0] > 0       # the body's side: the left
    line = pf.Obstacle({"type": "curve", "points": [[0, 0], [1, 0]]}, 1.0)
    assert line.distance(np.array([[-5.0, 1.0], [7.0, -2.0]]), 1.0) == pytest.approx([1.0, -2.0])


def test_plot_pressure_says_which_curves_its_view_clips(hpcontact, root, tmp_path):
    """plot_pressure.py shows p/p0 up to 1.3; a curve above it is named with its maximum."""
    out = tmp_path / "punch"
    r = hpcontact("run", os.path.join(root, "examples/tutorial/punch.yaml"), "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    r = run_script(root, "plot_pressure.py", out, tmp_path / "p.png")
    assert r.returncode == 0, r.stderr
    with open(out / "summary.json") as f:
        c = json.load(f)["contact"]
    with open(out / "pressure.csv") as f:
        rows = list(csv.DictReader(f))
    column, label = (("pressure_multiplier", "FE, multiplier") if "pressure_multiplier" in rows[0]
                     else ("pressure_penalty", "FE, penalty traction"))
    top = max(float(row[column]) / c["hertz_peak_pressure"] for row in rows
              if float(row["x"]) <= 1.5 * c["hertz_half_width"])
    if top > 1.3:
        assert f"{label} (clipped: max {top:.3g} p0)" in r.stdout, r.stdout
    else:
        assert "clipped" not in r.stdout, r.stdout
    r = run_script(root, "plot_pressure.py", tmp_path / "nowhere")
    assert r.returncode == 1 and "nowhere" in r.stderr


def test_units_in_labels_are_the_runs_or_input_units():
    """Without a units note the labels say "input units"; a note names them."""
    h = load_script("hpc_run")
    assert h.axis_label("x", "length") == "x (length, input units)"
    assert h.unit_text("stress", {"force": "N", "length": "mm"}) == "[N/mm²]"
    assert h.unit_text("penalty", {"force": "N", "length": "mm"}) == "[N/mm³]"
    assert h.unit_text("force per thickness", {"force": "kN", "length": "m"}) == "[kN/m]"
    assert h.unit_text("energy per thickness", {"force": "N", "length": "mm"}) == "[N·mm/mm]"
    assert h.unit_text("stress", "N, mm") == "(stress, units: N, mm)"
    assert h.unit_text("strain") == "[-]"
    assert h.units_of({"units": {"length": "mm"}}) == {"length": "mm"}
    assert h.units_of({}) is None


def test_contact_history_plot_of_the_o_ring(hpcontact, root, tmp_path):
    """plot_contact_history.py draws both pairs of the O-ring over its load steps (from
    contact_history.csv: one row per step and pair, equal forces on the two plates), and names
    the missing file of a folder without a history."""
    out = tmp_path / "ring"
    r = hpcontact("run", os.path.join(root, "examples/o-ring/o-ring.yaml"), "--out", out, "-q",
                  "--set", "solver.load_steps=3", "--set", "discretization.degree=4")
    assert r.returncode == 0, r.stderr
    with open(out / "contact_history.csv") as f:
        rows = list(csv.DictReader(f))
    assert [(int(r["step"]), int(r["pair"])) for r in rows] == [(s, p) for s in (1, 2, 3) for p in (0, 1)]
    for s in (0, 2, 4):
        a, b = float(rows[s]["normal_force"]), float(rows[s + 1]["normal_force"])
        assert a > 0 and abs(a - b) < 1e-9 * a
    assert float(rows[0]["normal_force"]) < float(rows[2]["normal_force"]) < float(rows[4]["normal_force"])
    r = run_script(root, "plot_contact_history.py", out, "--out", tmp_path / "history.png")
    assert r.returncode == 0, r.stderr
    assert (tmp_path / "history.png").stat().st_size > 10000
    (tmp_path / "empty").mkdir()
    r = run_script(root, "plot_contact_history.py", tmp_path / "empty")
    assert r.returncode != 0 and "contact_history.csv: no such file" in r.stderr, r.stderr
