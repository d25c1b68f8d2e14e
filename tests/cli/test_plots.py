"""The general plot scripts on a real run: scripts/plot_contact.py (contact.csv of any case),
scripts/plot_field.py (a field of solution.vtu on the deformed mesh, with the rigid obstacles,
at a scale that keeps touching bodies apart) and scripts/plot_pressure.py (what its view clips);
the units of their labels."""
import csv
import json
import os
import shutil
import subprocess

import matplotlib.figure
import numpy as np
import pytest

from conftest import csv_rows, load_script, scaled_timeout

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


def test_plot_pressure_says_which_curves_its_view_clips(hpcontact, root, tmp_path, monkeypatch):
    """plot_pressure.py shows p/p0 up to 1.3; a curve above it is named with its maximum.
    Several runs: one colour and one legend entry each (--label), the closed forms once."""
    out = tmp_path / "punch"
    r = hpcontact("run", os.path.join(root, "examples/tutorial/punch.yaml"), "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    r = run_script(root, "plot_pressure.py", out, tmp_path / "p.png")
    assert r.returncode == 0, r.stderr
    with open(out / "summary.json") as f:
        c = json.load(f)["contact"]
    with open(out / "pressure.csv") as f:
        rows = list(csv.DictReader(f))
    column, label = (("pressure_multiplier", "punch: multiplier") if "pressure_multiplier" in rows[0]
                     else ("pressure_penalty", "punch: penalty traction"))
    top = max(float(row[column]) / c["hertz_peak_pressure"] for row in rows
              if float(row["x"]) <= 1.5 * c["hertz_half_width"])
    if top > 1.3:
        assert f"{label} (clipped: max {top:.3g} p0)" in r.stdout, r.stdout
    else:
        assert "clipped" not in r.stdout, r.stdout
    r = run_script(root, "plot_pressure.py", tmp_path / "nowhere")
    assert r.returncode == 1 and "nowhere" in r.stderr

    shutil.copytree(out, tmp_path / "again")
    fig = figure_of("plot_pressure", [out, tmp_path / "again", "--label", "first", "--label",
                                      "second", "--out", tmp_path / "two.png"], monkeypatch)
    texts = legend_texts(fig)
    assert texts.count("first") == 1 and texts.count("second") == 1 and texts.count("Hertz") == 1
    ax = fig.axes[0]
    b, p0 = c["hertz_half_width"], c["hertz_peak_pressure"]
    stress = [line for line in ax.lines if line.get_linewidth() == 1.8]
    assert len(stress) == 2
    assert np.allclose(stress[1].get_xdata(), [float(row["x"]) / b for row in rows])
    assert np.allclose(stress[1].get_ydata(), [float(row["pressure_from_stress"]) / p0 for row in rows])


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


# Several pairs and several runs: the O-ring in a groove (four rigid planes, four pairs), squeezed
# 2 mm and 3 mm. The figures are read back from matplotlib (Agg): panels, titles, legend texts,
# axis labels and the data of the lines.

GROOVE = "examples/o-ring/o-ring-groove.yaml"
GROOVE_PAIRS = ["contact[0]: ring [bottom]", "contact[1]: ring [top]", "contact[2]: ring [left]",
                "contact[3]: ring [right]"]


@pytest.fixture(scope="module")
def groove_runs(tmp_path_factory, request):
    """The groove O-ring squeezed 2 mm (as the file has it) and 3 mm: their folders."""
    hpcontact = request.getfixturevalue("hpcontact")
    root = request.getfixturevalue("root")
    base = tmp_path_factory.mktemp("groove")
    folders = []
    for squeeze in (2, 3):
        out = base / f"squeeze-{squeeze}"
        r = hpcontact("run", os.path.join(root, GROOVE), "--out", out, "-q",
                      "--set", f"contact[1].obstacle.displacement=[0, -{squeeze}]")
        assert r.returncode == 0, r.stderr
        folders.append(out)
    return folders


def figure_of(script, argv, monkeypatch):
    """The matplotlib Figure a plot script's main(argv) draws (kept from plt.close)."""
    module = load_script(script)
    kept = []
    monkeypatch.setattr(module.plt, "close", lambda fig: kept.append(fig))
    assert module.main([str(a) for a in argv]) in (0, None)
    figures = [f for f in kept if isinstance(f, matplotlib.figure.Figure)]
    assert len(figures) == 1
    return figures[0]


def titled_axes(fig):
    """The axes of a figure that carry a title (the top axes of each pair's panel)."""
    return [a for a in fig.axes if a.get_title()]


def legend_texts(fig):
    return [t.get_text() for legend in fig.legends for t in legend.get_texts()]


def test_the_groove_o_ring_has_four_pairs_the_walls_reached_later(groove_runs):
    """The test case itself: four pairs per step; the plates carry equal forces and so do the
    two walls (the section is symmetric); the walls are reached only as the ring bulges, earlier
    under the larger squeeze."""
    for out in groove_runs:
        rows = csv_rows(out / "contact_history.csv")
        assert sorted({int(r["pair"]) for r in rows}) == [0, 1, 2, 3]
        for step in {r["step"] for r in rows}:
            f = {int(r["pair"]): float(r["normal_force"]) for r in rows if r["step"] == step}
            assert f[0] > 0 and abs(f[0] - f[1]) < 1e-9 * f[0]
            assert abs(f[2] - f[3]) <= 1e-9 * f[0]
    first_touch = []
    for out in groove_runs:
        rows = csv_rows(out / "contact_history.csv")
        first_touch.append(min(float(r["displacement_factor"]) for r in rows
                               if r["pair"] == "2" and float(r["normal_force"]) > 0))
    assert first_touch[1] < first_touch[0] <= 1.0


def test_contact_history_one_panel_per_pair_one_label_per_run(groove_runs, monkeypatch, tmp_path):
    """plot_contact_history.py draws a panel per pair titled with its edges and obstacle, one
    legend entry per run (--label), the force against the squeeze (the top plate's displacement
    times the factor, not the factor) with the units of --units."""
    fig = figure_of("plot_contact_history",
                    [*groove_runs, "--label", "2 mm", "--label", "3 mm", "--units", "mm,N",
                     "--out", tmp_path / "h.png"], monkeypatch)
    panels = titled_axes(fig)
    assert [a.get_title().split("\n")[0] for a in panels] == GROOVE_PAIRS
    assert "vs plane x = -10.3" in panels[2].get_title()
    assert legend_texts(fig) == ["2 mm", "3 mm"]
    for ax in panels:
        assert ax.get_xlabel() == "squeeze [mm]"
        assert ax.get_ylabel() == "normal force per unit length [N/mm]"
        assert len(ax.lines) == 2 + 1                    # a curve per run, the zero line
    for k, ax in enumerate(panels):
        for run, (out, squeeze) in enumerate(zip(groove_runs, (2, 3))):
            rows = [r for r in csv_rows(out / "contact_history.csv") if int(r["pair"]) == k]
            x, y = ax.lines[run].get_data()
            assert np.allclose(x, [squeeze * float(r["displacement_factor"]) for r in rows])
            assert np.allclose(y, [float(r["normal_force"]) for r in rows])
    assert (tmp_path / "h.png").stat().st_size > 20000


def test_contact_history_axes_a_user_chooses(groove_runs, root, monkeypatch, tmp_path):
    """--x load_factor or a pair's force (normal_force:1) and several --y of two kinds (a row of
    axes per kind); folder names label the runs by default; a squeeze the run does not have,
    and a --label count that is not one per folder, are refused with their reasons."""
    fig = figure_of("plot_contact_history",
                    [*groove_runs, "--x", "normal_force:1", "--y", "normal_force,contact_length",
                     "--out", tmp_path / "h.png"], monkeypatch)
    assert legend_texts(fig) == ["squeeze-2", "squeeze-3"]
    assert len(fig.axes) == 4 * 2 and len(titled_axes(fig)) == 4
    wall = titled_axes(fig)[3]
    rows = csv_rows(groove_runs[1] / "contact_history.csv")
    x, y = wall.lines[1].get_data()
    assert np.allclose(x, [float(r["normal_force"]) for r in rows if r["pair"] == "1"])
    assert np.allclose(y, [float(r["normal_force"]) for r in rows if r["pair"] == "3"])
    below = fig.axes[fig.axes.index(wall) + 1]          # the pair's contact length, same x
    assert below.get_xlabel() == "normal force of pair 1 per unit length (input units)"
    assert below.get_ylabel() == "contact length (input units)"
    fig = figure_of("plot_contact_history", [groove_runs[0], "--x", "load_factor",
                                             "--out", tmp_path / "h.png"], monkeypatch)
    assert fig.axes[0].get_xlabel() == "load factor [-]"
    assert np.allclose(fig.axes[0].lines[0].get_xdata(), [0.25, 0.5, 0.75, 1.0])
    r = run_script(root, "plot_contact_history.py", *groove_runs, "--x", "squeeze:walls")
    assert r.returncode == 2 and "no prescribed displacement 'walls'" in r.stderr
    assert "contact[1]" in r.stderr and "input.yaml" in r.stderr
    r = run_script(root, "plot_contact_history.py", *groove_runs, "--label", "only one")
    assert r.returncode == 2 and "--label: given 1 time(s) for 2 RESULTS_DIR" in r.stderr


def test_contact_plot_one_panel_per_pair_one_label_per_run(groove_runs, monkeypatch, tmp_path):
    """plot_contact.py: a panel (pressure over gap) per pair; a wall's points along Y, a plate's
    along X; the curves are contact.csv's columns of that pair; one legend entry per run."""
    fig = figure_of("plot_contact", [*groove_runs, "--units", "mm,N", "--out", tmp_path / "c.png"],
                    monkeypatch)
    panels = titled_axes(fig)
    assert [a.get_title().split("\n")[0] for a in panels] == GROOVE_PAIRS
    assert len(fig.axes) == 2 * 4
    texts = legend_texts(fig)
    assert texts.count("squeeze-2") == 1 and texts.count("squeeze-3") == 1
    assert panels[0].get_ylabel() == "contact pressure [N/mm²]"
    rows = [r for r in csv_rows(groove_runs[1] / "contact.csv") if r["pair"] == "3"]
    stress = panels[3].lines[2]                       # run 2: from stresses, then `pressure`
    assert np.allclose(stress.get_xdata(), [float(r["Y"]) for r in rows])
    assert np.allclose(stress.get_ydata(), [float(r["pressure_from_stress"]) for r in rows])
    gap_axes = fig.axes[fig.axes.index(panels[3]) + 1]
    assert gap_axes.get_xlabel() == "undeformed Y [mm]"
    rows = [r for r in csv_rows(groove_runs[0] / "contact.csv") if r["pair"] == "0"]
    assert np.allclose(panels[0].lines[0].get_xdata(), [float(r["X"]) for r in rows])


def test_plot_field_keeps_a_press_fit_closed(hpcontact, root, tmp_path):
    """examples/lame/press-fit-short-hub.yaml: the shaft is meshed 0.01 mm larger than the bore
    and the solution closes the overlap; magnified s times the surfaces would be drawn (s - 1)
    0.01 apart (5 % of the size: × 300, 3 mm). At the automatic scale the drawn gap between the
    shaft's contact points and the hub's, read from contact.csv, stays within 0.2 % of the model
    size of what it is at true scale."""
    out = tmp_path / "press-fit"
    r = hpcontact("run", os.path.join(root, "examples/lame/press-fit-short-hub.yaml"), "--out", out,
                  "-q", "--set", "discretization.degree=4")
    assert r.returncode == 0, r.stderr
    r = run_script(root, "plot_field.py", out / "solution.vtu", "--out", tmp_path / "vm.png")
    assert r.returncode == 0, r.stderr
    scale = float(r.stdout.split("displacement × ")[1].split()[0])
    rows = csv_rows(out / "contact.csv")
    shaft = [r for r in rows if r["body"] == "shaft" and r["state"] == "contact"
             and float(r["Y"]) < 49]
    hub = sorted((r for r in rows if r["body"] == "hub"), key=lambda r: float(r["Y"]))
    hub_Y = [float(r["Y"]) for r in hub]

    def gaps(s):
        """Radial gap drawn at scale s between each shaft point and the hub's bore at its Y."""
        bore = [float(r["X"]) + s * (float(r["x"]) - float(r["X"])) for r in hub]
        return np.array([np.interp(float(r["Y"]), hub_Y, bore)
                         - (float(r["X"]) + s * (float(r["x"]) - float(r["X"]))) for r in shaft])

    X, _, points, _ = load_script("hpc_run").read_vtu(str(out / "solution.vtu"))
    size = np.linalg.norm(X.max(axis=0) - X.min(axis=0))
    bound = np.abs(gaps(1.0)).max() + 0.002 * size
    wanted = 0.05 * size / np.abs(points["displacement"][:, :2]).max()
    assert len(shaft) > 10
    assert 1.0 < scale < wanted
    assert np.abs(gaps(scale)).max() <= bound
    assert np.abs(gaps(wanted)).max() > 10 * bound      # what the old scale drew


def test_labels_and_units_of_several_runs():
    """--units LENGTH,FORCE; a run's label is its folder's name (with the parent's where two
    folders share a name); squeeze: the factors times the prescribed displacement along it."""
    pr = load_script("plot_runs")
    assert pr.parse_units("mm, N") == {"length": "mm", "force": "N"}
    with pytest.raises(ValueError, match="LENGTH,FORCE"):
        pr.parse_units("mm")
    assert pr.unit_of("force per thickness", {"length": "m", "force": "kN"}) == "[kN/m]"
    assert pr.unit_of("pressure", None) == "(input units)"
    assert pr.run_labels(["a/run", "b/other/"], None) == ["run", "other"]
    assert pr.run_labels(["a/run", "b/run"], None) == ["a/run", "b/run"]
    assert pr.run_labels(["a", "b"], ["one", "two"]) == ["one", "two"]
    problem = {"contact": [{"obstacle": {"type": "plane", "displacement": [0, -2]}}],
               "bodies": [{"name": "punch", "constraints": [{"edges": ["top"], "uy": -0.5},
                                                            {"edges": ["side"], "ux": 0}]}]}
    found = pr.prescribed_displacements(problem, "in.yaml")
    assert [p.name for p in found] == ["contact[0]", "punch/top"]
    assert pr.find_prescribed(problem, "top", "in.yaml").squeeze(0.5, 0.5) == pytest.approx(0.25)
    assert pr.find_prescribed(problem, "contact[0]", "in.yaml").squeeze(1, 0.5) == pytest.approx(1.0)
    with pytest.raises(ValueError, match="several prescribed displacements"):
        pr.find_prescribed(problem, None, "in.yaml")
    diagonal = pr.Prescribed("d", [], [3.0, 4.0], "")
    assert diagonal.squeeze(1.0, 1.0) == pytest.approx(5.0)
    assert diagonal.squeeze(0.0, 1.0) == pytest.approx(16 / 5)   # (0, 4) along (3, 4)/5
