"""The Python module's load history: result.load_history (path.csv) and result.contact_history
(contact_history.csv) as numpy arrays, equal to the files' columns row by row."""
import csv
import os

import numpy as np

import hpcontact


def columns(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {key: [row[key] for row in rows] for key in rows[0]}


def test_load_and_contact_history_are_the_files(root, tmp_path):
    """Two bars pressed, then pushed by 300 in four steps (5 converged steps, one pair): every
    column the module gives equals the file's to the 12 digits the files carry; the pushing
    force grows with the load factor as the pair's tangential force does."""
    problem = hpcontact.Problem.from_file(os.path.join(root, "examples", "two-bars", "stick.yaml"))
    result = problem.run(out=tmp_path / "out")
    path = columns(tmp_path / "out" / "path.csv")
    h = result.load_history
    assert list(h["step"]) == [int(s) for s in path["step"]] == [1, 2, 3, 4, 5]
    for key in ("displacement_factor", "load_factor", "arc_length", "resultant_x", "resultant_y"):
        np.testing.assert_allclose(h[key], [float(v) for v in path[key]], rtol=1e-11, atol=1e-12, err_msg=key)
    assert list(h["iterations"]) == [int(v) for v in path["iterations"]]
    history = columns(tmp_path / "out" / "contact_history.csv")
    c = result.contact_history
    assert list(c["step"]) == [int(s) for s in history["step"]]
    assert c["body"] == history["body"]
    for key in ("normal_force", "tangential_force", "contact_length", "pressure_max", "load_factor"):
        np.testing.assert_allclose(c[key], [float(v) for v in history[key]], rtol=1e-11, atol=1e-12, err_msg=key)
    assert list(c["stick_points"]) == [int(v) for v in history["stick_points"]]
    # the shear the pair carries follows the push, 300 × the load factor (the bars stick)
    np.testing.assert_allclose(np.abs(c["tangential_force"]), 300 * c["load_factor"], rtol=1e-8, atol=1e-8)


def test_a_linear_run_without_contact_has_no_history(root):
    """A linear solve without contact has no load steps (no path.csv): both are empty."""
    problem = hpcontact.Problem.from_file(os.path.join(root, "examples", "lame", "thick-cylinder.yaml"))
    result = problem.run()
    assert result.contact_history == {}
    assert len(result.load_history["step"]) == 0


def test_progress_lines_from_python(root, capsys):
    """run(quiet=False) prints a line per load step (5 for the two bars) and no Newton iteration;
    verbose=True adds one line per iteration, as many as summary's newton_iterations; quiet (the
    default) prints nothing."""
    problem = hpcontact.Problem.from_file(os.path.join(root, "examples", "two-bars", "stick.yaml"))
    problem.run()
    assert capsys.readouterr().out == ""
    problem.run(quiet=False)
    lines = capsys.readouterr().out.splitlines()
    assert sum("load step" in line for line in lines) == 5
    assert not any(line.strip().startswith("iteration ") for line in lines)
    result = problem.run(quiet=False, verbose=True)
    lines = capsys.readouterr().out.splitlines()
    iterations = [line for line in lines if line.strip().startswith("iteration ")]
    assert len(iterations) == result.summary["newton_iterations"] > 0
    assert sum("load step" in line for line in lines) == 5
