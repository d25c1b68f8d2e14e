"""The Python module's reactions: result.reactions and result.reaction_history as numpy arrays,
the same figures as summary.json's `reactions` and path.csv's columns, step by step."""
import csv
import json
import os

import numpy as np
import pytest

import hpcontact


def test_reactions_are_summary_json_s(root, tmp_path):
    """Two bars (pressed, then pushed by 300 in four steps): result.reactions holds the last
    step's support forces and moments and the pair's force as summary.json does; the history has
    a row per converged step (path.csv's), the lower bar's base pushing back the shear each step."""
    problem = hpcontact.Problem.from_file(os.path.join(root, "examples", "two-bars", "stick.yaml"))
    result = problem.run(out=tmp_path / "out")
    r, h = result.reactions, result.reaction_history
    assert r["body"] == ["upper", "lower"] and r["constraint"] == [0, 0]
    assert r["force"].shape == (2, 2) and r["moment"].shape == (2,)
    with open(tmp_path / "out" / "summary.json") as f:
        summary = json.load(f)
    for i, s in enumerate(summary["reactions"]["supports"]):
        np.testing.assert_allclose(r["force"][i], s["force"], rtol=1e-14, atol=1e-9)
        assert r["moment"][i] == pytest.approx(s["moment"], rel=1e-14)
    np.testing.assert_allclose(r["pair_force"][0], summary["contact"]["resultant"], rtol=1e-12)
    assert r["equilibrium_residual"] == summary["equilibrium_residual"] < 1e-8
    with open(tmp_path / "out" / "path.csv") as f:
        rows = list(csv.DictReader(f))
    assert h["force"].shape == (len(rows), 2, 2) == (5, 2, 2)
    np.testing.assert_allclose(h["force"][-1], r["force"], rtol=0, atol=0)
    loads = np.array([float(row["load_factor"]) for row in rows])
    np.testing.assert_allclose(h["force"][:, 1, 0], -300 * loads, rtol=1e-10, atol=1e-9)
    np.testing.assert_allclose(h["force"][:, 0, 1], [float(row["reaction_upper_0_y"]) for row in rows],
                               rtol=1e-10)
    assert np.all(h["equilibrium_residual"] < 1e-8)


def test_axisymmetric_reactions_have_no_moment(root, lame):
    """An axisymmetric body's moment is nan (not reported); a linear solve's history is its one
    solve (Lamé's quarter cylinder: each support pushes back p a = 1000 of the bore's pressure)."""
    problem = hpcontact.Problem.from_file(os.path.join(root, "examples", "lame", "shrink-fit.yaml"))
    result = problem.run()
    assert result.reactions["force"].shape == (3, 2)
    assert np.all(np.isnan(result.reactions["moment"]))
    h = lame.reaction_history
    assert h["force"].shape == (1, 2, 2) and h["pair_force"].shape == (1, 0, 2)
    np.testing.assert_allclose(h["force"][0], [[0, -1000], [-1000, 0]], rtol=0, atol=1e-9)
