"""The Python module: problems read or composed, runs, the summary, fields at points against
Lamé's closed form, the interface curves against the command line's files, and its errors."""
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest
import yaml

import hpcontact
from conftest import scaled_timeout

# Lamé: a = 10, b = 20 mm, internal pressure 100 N/mm², E = 200000, nu = 0.3, plane strain.
A_IN, B_OUT, P, E, NU = 10.0, 20.0, 100.0, 200000.0, 0.3


def lame_exact(points):
    """Displacement (n, 2) and stress (n, 4: sxx, syy, sxy, szz) of the closed form."""
    x, y = points[:, 0], points[:, 1]
    r, c, s = np.hypot(x, y), x / np.hypot(x, y), y / np.hypot(x, y)
    a_ = P * A_IN**2 / (B_OUT**2 - A_IN**2)
    b_ = P * A_IN**2 * B_OUT**2 / (B_OUT**2 - A_IN**2)
    u_r = (1 + NU) / E * ((1 - 2 * NU) * a_ * r + b_ / r)
    s_r, s_t = a_ - b_ / r**2, a_ + b_ / r**2
    u = np.c_[u_r * c, u_r * s]
    stress = np.c_[s_r * c * c + s_t * s * s, s_r * s * s + s_t * c * c, (s_r - s_t) * s * c,
                   NU * (s_r + s_t)]
    return u, stress


def quarter_annulus(n_r=21, n_t=31):
    """Points of the quarter annulus, its boundary included (r = a, b; theta = 0, 90°)."""
    r, t = np.meshgrid(np.linspace(A_IN, B_OUT, n_r), np.linspace(0, math.pi / 2, n_t))
    return np.c_[(r * np.cos(t)).ravel(), (r * np.sin(t)).ravel()]


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def test_problem_describes_itself(lame_file):
    """A problem read from a file names its case and file and counts its unknowns like
    `hpcontact check` (p = 8 on two elements: 288 free dofs, 92 after condensation)."""
    problem = hpcontact.Problem.from_file(lame_file)
    assert problem.case == "lame-thick-cylinder"
    assert problem.file == lame_file
    d = problem.describe()
    assert (d["method"], d["dofs"], d["dofs_condensed"]) == ("p", 288, 92)
    assert d["bodies"] == [{"name": "cylinder", "nodes": 6, "elements": 2, "edges": 7}]
    assert problem.dofs == 288
    assert "degree: 8" in problem.input


def test_summary_is_that_of_summary_json(lame, lame_file, tmp_path):
    """result.summary holds what summary.json holds: a run with out= writes the same keys and
    values (but the wall time), and the files of the command line."""
    result = hpcontact.Problem.from_file(lame_file).run(out=tmp_path)  # a str or a Path
    assert result.out == str(tmp_path)
    written = json.loads((tmp_path / "summary.json").read_text())
    assert set(written) == set(result.summary) == set(lame.summary)
    for key in written:
        if key not in ("wall_time_s", "solve_time_s", "assembly_time_s"):
            assert written[key] == result.summary[key] == lame.summary[key], key
    assert written["converged"] is True and isinstance(written["dofs"], int)
    assert (tmp_path / "input.yaml").exists() and (tmp_path / "solution.vtu").exists()
    assert lame.out is None


def test_lame_displacement_at_points(lame):
    """Displacements at 651 points of the quarter annulus (boundaries included) match Lamé's
    u_r to 1e-6 of the largest displacement at p = 8, where the energy-norm error is 7e-4 %."""
    points = quarter_annulus()
    exact_u, _ = lame_exact(points)
    u = lame.displacement(points)
    assert u.shape == points.shape
    error = np.abs(u - exact_u).max() / np.abs(exact_u).max()
    print(f"Lame p = 8, {len(points)} points: max |u - u_exact| / max |u_exact| = {error:.3g}")
    assert error < 1e-6, error
    assert lame.summary["error"]["energy_norm_rel_percent"] < 1e-3


def test_lame_stress_at_points(lame):
    """Stresses (sxx, syy, sxy, szz) at the same points match Lamé's to 2e-4 of the pressure."""
    points = quarter_annulus()
    _, exact_s = lame_exact(points)
    s = lame.stress(points)
    assert s.shape == (len(points), 4)
    error = np.abs(s - exact_s).max() / P
    print(f"Lame p = 8: max |s - s_exact| / pressure = {error:.3g}")
    assert error < 2e-4, error


def test_lame_displacement_converges_exponentially(lame_file):
    """The displacement error at points falls by more than 20 for every two degrees
    (p = 4, 6, 8: the p-version's exponential rate on a smooth solution)."""
    points = quarter_annulus(11, 11)
    exact_u, _ = lame_exact(points)
    errors = []
    for p in (4, 6, 8):
        r = hpcontact.Problem.from_file(lame_file, set={"discretization.degree": p}).run()
        errors.append(np.abs(r.displacement(points) - exact_u).max() / np.abs(exact_u).max())
    print("Lame displacement error at points, p = 4, 6, 8: " + ", ".join(f"{e:.3g}" for e in errors))
    assert errors[0] > 20 * errors[1] > 400 * errors[2], errors


def test_single_point_and_body_name(lame):
    """One point of shape (2,) gives one row of shape (2,); body= restricts the search, and an
    unknown body name is a ValueError naming the bodies."""
    u = lame.displacement([15.0, 0.0])
    assert u.shape == (2,)
    assert np.allclose(u, lame.displacement([[15.0, 0.0]], body="cylinder")[0], rtol=0, atol=0)
    with pytest.raises(ValueError, match="'cylinder'"):
        lame.stress([15.0, 0.0], body="ring")


def test_point_outside_raises_value_error(lame):
    """A point outside every body raises ValueError naming the first such point."""
    with pytest.raises(ValueError, match=r"point 1 \(25, 0\) lies outside every body"):
        lame.displacement([[15.0, 0.0], [25.0, 0.0], [5.0, 0.0]])
    with pytest.raises(ValueError, match=r"point 0 \(5, 5\)"):  # inside the hole
        lame.stress([[5.0, 5.0]])
    with pytest.raises(ValueError, match="shape"):
        lame.displacement(np.zeros((3, 3)))


def test_hertz_p5_resultant(hertz_p5):
    """Force control finds the push for F/2 = 35000 N: the summary's resultant within 0.1 %."""
    c = hertz_p5.summary["contact"]
    assert abs(c["resultant"][1] - 35000) < 35
    assert hertz_p5.summary["converged"] is True


def test_contact_arrays_equal_contact_csv(hertz_p5, hertz_p5_file, hpcontact_exe, tmp_path):
    """result.contact() has a row per multiplier node of the contact set (exact enforcement
    against a rigid plane: the p + 1 Gauss-Lobatto points of each of its edges, a shared vertex
    once), and its columns equal contact.csv of a command-line run of the same case: numbers to
    1e-12 relative beyond the 12 digits the file keeps, states exactly."""
    with open(hertz_p5_file) as f:
        spec = yaml.safe_load(f)
    pair = spec["contact"][0]
    body = next(b for b in spec["bodies"] if b["name"] == pair["body"])
    n_edges = sum(len(body["edge_sets"][s]) for s in pair["edges"])
    p = spec["discretization"]["degree"]
    n_points = n_edges * p + 1  # one chain of edges

    table = hertz_p5.contact()
    assert all(len(v) == n_points for v in table.values())
    assert set(table["state"]) <= {"open", "contact"}
    closed = (table["gap"] <= 0) | (table["pressure"] > 0)
    assert (table["state"] == "contact").sum() == closed.sum() > 0

    r = subprocess.run([hpcontact_exe, "run", hertz_p5_file, "--out", str(tmp_path), "-q"],
                       capture_output=True, text=True, timeout=scaled_timeout(300))
    assert r.returncode == 0, r.stderr
    rows = read_csv(tmp_path / "contact.csv")
    assert list(rows[0]) == list(table)  # same columns, same order
    assert len(rows) == n_points
    for key in table:
        if key in ("state", "body"):
            assert list(table[key]) == [row[key] for row in rows]
            continue
        file_values = np.array([float(row[key]) for row in rows])
        digits = 0.5e-11 * np.abs(file_values)  # what 12 significant digits round away
        assert np.all(np.abs(table[key] - file_values) <= 1e-12 * np.abs(file_values) + digits), key


def test_displacement_at_contact_points(hertz_p5):
    """At the contact points (the multiplier nodes on the curved boundary, located by inverting
    the blending map) displacement() equals contact()'s x − X, evaluated by the contact code, to
    round-off: 1e-10 of the largest displacement, since the nodes at element corners invert to
    reference coordinates ±1 only to ~1e-12 (measured 9.6e-12 relative)."""
    table = hertz_p5.contact()
    u = hertz_p5.displacement(np.c_[table["X"], table["Y"]])
    moved = np.c_[table["x"] - table["X"], table["y"] - table["Y"]]
    assert np.abs(u - moved).max() < 1e-10 * np.abs(moved).max()


def test_pressure_curve_equals_pressure_csv(hertz_p5_file, tmp_path):
    """result.pressure_curve() holds pressure.csv's columns plus the reference curve the input
    names; integrated by the trapezoidal rule, its pressure from stresses gives the summary's
    e_L2 against Hertz (to 2 % of that error)."""
    result = hpcontact.Problem.from_file(hertz_p5_file).run(out=str(tmp_path))
    curve = result.pressure_curve()
    rows = read_csv(tmp_path / "pressure.csv")
    assert set(rows[0]) | {"reference"} == set(curve)
    for key in rows[0]:
        file_values = np.array([float(row[key]) for row in rows])
        assert np.allclose(curve[key], file_values, rtol=1e-11, atol=1e-9 * file_values.max())
    c = result.summary["contact"]
    b, p0 = c["hertz_half_width"], c["hertz_peak_pressure"]
    x = curve["x"]
    assert x[0] == 0 and abs(x[-1] - 1.5 * b) < 1e-12 * b and np.all(np.diff(x) >= 0)
    assert abs(curve["hertz"][0] / p0 - 1) < 1e-12
    assert abs(curve["reference"].max() / p0 - 1) < 0.02  # the overkill solution's peak
    e_l2 = 100 * math.sqrt(np.trapz((curve["pressure_from_stress"] - curve["hertz"])**2, x)
                           / np.trapz(curve["hertz"]**2, x))
    assert abs(e_l2 / c["e_L2_hertz_percent"] - 1) < 0.02, (e_l2, c["e_L2_hertz_percent"])


def test_no_contact_no_curves(lame):
    """Without contact: contact() has empty columns, pressure_curve() is None."""
    table = lame.contact()
    assert "pressure" in table and all(len(v) == 0 for v in table.values())
    assert lame.pressure_curve() is None


def test_from_yaml_gives_the_same_run(lame_file, lame):
    """A problem composed as text (here the file's text, degree changed by set=) runs like the
    file; its label names it in messages."""
    with open(lame_file) as f:
        text = f.read()
    problem = hpcontact.Problem.from_yaml(text, label="composed.yaml", set=["discretization.degree=8"])
    assert problem.file == "composed.yaml"
    assert problem.run().summary["strain_energy"] == lame.summary["strain_energy"]
    with pytest.raises(hpcontact.InputError, match="composed.yaml"):
        hpcontact.Problem.from_yaml(text.replace("nu: 0.3", "nu: 0.7"), label="composed.yaml")


def test_bad_input_raises_input_error(lame_file):
    """E < 0 (by set=) raises InputError, a ValueError too, naming the file and the key."""
    with pytest.raises(hpcontact.InputError) as info:
        hpcontact.Problem.from_file(lame_file, set=["bodies[0].material.E=-1"])
    message = str(info.value)
    assert "thick-cylinder.yaml" in message and "E" in message
    assert isinstance(info.value, ValueError) and isinstance(info.value, hpcontact.Error)
    assert "\n" not in message
    with pytest.raises(hpcontact.InputError, match="no_such_key"):
        hpcontact.Problem.from_file(lame_file, set={"solver.no_such_key": 1})
    with pytest.raises(hpcontact.Error, match="no-such-file.yaml"):
        hpcontact.Problem.from_file("no-such-file.yaml")
    with pytest.raises(TypeError):
        hpcontact.Problem.from_file(lame_file, set=[1])


def test_non_converging_run_raises_solver_error(hertz_p5_file, tmp_path):
    """One Newton iteration without cut-backs cannot solve Hertz: SolverError (a RuntimeError),
    and no summary.json in the output folder."""
    problem = hpcontact.Problem.from_file(
        hertz_p5_file, set=["solver.max_iterations=1", "solver.max_cuts=0"])
    with pytest.raises(hpcontact.SolverError) as info:
        problem.run()
    assert isinstance(info.value, RuntimeError) and isinstance(info.value, hpcontact.Error)
    assert "p5.yaml" in str(info.value)
    with pytest.raises(hpcontact.SolverError):
        problem.run(out=str(tmp_path))
    assert not (tmp_path / "summary.json").exists()


def test_example_hertz_script(root, tmp_path):
    """examples/python/hertz.py runs p8 through the module and writes its plot (PNG > 10 kB)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(p for p in (os.path.dirname(hpcontact.__file__),
                                                    env.get("PYTHONPATH")) if p)
    r = subprocess.run([sys.executable, os.path.join(root, "examples", "python", "hertz.py"),
                        "--out", str(tmp_path)], capture_output=True, text=True, env=env,
                       timeout=scaled_timeout(300))
    assert r.returncode == 0, r.stderr
    png = tmp_path / "hertz-pressure.png"
    assert png.exists() and png.stat().st_size > 10_000
    assert "hertz-p8: 544 DOF, resultant 35000.0 N" in r.stdout


def test_run_out_never_overwrites_a_users_file(lame_file, tmp_path):
    """run(out=d) with a user's own d/input.yaml (not the problem file) raises Error naming it
    and leaves it as it was; so does a folder that holds the problem file itself."""
    (tmp_path / "input.yaml").write_text("my notes, not hpcontact's\n")
    problem = hpcontact.Problem.from_file(lame_file)
    with pytest.raises(hpcontact.Error, match="input.yaml: hpcontact did not write this file"):
        problem.run(out=tmp_path)
    assert (tmp_path / "input.yaml").read_text() == "my notes, not hpcontact's\n"
    assert not (tmp_path / "summary.json").exists()
    case = tmp_path / "case" / "lame.yaml"
    case.parent.mkdir()
    case.write_text(open(lame_file).read())
    with pytest.raises(hpcontact.Error, match="holds the problem file"):
        hpcontact.Problem.from_file(case).run(out=case.parent)
    assert case.read_text() == open(lame_file).read()


def test_interrupted_run_leaves_the_earlier_results(root, lame_file, tmp_path):
    """A run stopped by KeyboardInterrupt (here raised by a timer's signal handler) leaves the
    folder's earlier results byte-identical and no staging folder behind."""
    import signal

    out = tmp_path / "out"
    hpcontact.Problem.from_file(lame_file).run(out=out)
    before = {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()}
    long = hpcontact.Problem.from_file(os.path.join(root, "examples", "hertz", "p15.yaml"),
                                       set=["solver.load_steps=400",
                                            "contact[0].enforcement=penalty"])

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGALRM, interrupt)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.5)
        with pytest.raises(KeyboardInterrupt):
            long.run(out=out)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert {p.name: p.read_bytes() for p in out.iterdir() if p.is_file()} == before
    assert not [p for p in out.iterdir() if p.name.startswith(".hpcontact-staging")]


def test_numerical_breakdowns_raise_solver_error(root):
    """An exception inside the parallel assembly (nu lost to round-off) killed the interpreter,
    and values whose products overflow (a strain of 1e199 in an element 1e-99 wide) returned
    converged: true with energy NaN; both raise SolverError naming the cause. Run in a child
    interpreter, so that a crash fails this test, not the suite."""
    script = f"""
import hpcontact
block = hpcontact.Problem.from_file({os.path.join(root, "examples", "neumann", "block.yaml")!r},
                                    set=["bodies[0].material.nu=0.49999999999999994"])
overflow = hpcontact.Problem.from_file({os.path.join(root, "tests", "cli", "data", "overflow.yaml")!r})
for problem, cause in ((block, "static condensation"), (overflow, "the solution is not finite")):
    try:
        problem.run()
        print("no error for", problem)
    except hpcontact.SolverError as e:
        print("SolverError:", cause in str(e), str(e))
"""
    r = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                       timeout=scaled_timeout(120),
                       env=dict(os.environ, PYTHONPATH=os.path.dirname(hpcontact.__file__)))
    assert r.returncode == 0, r.stderr
    lines = r.stdout.splitlines()
    assert len(lines) == 2 and all(line.startswith("SolverError: True") for line in lines), r.stdout
