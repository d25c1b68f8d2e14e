"""A 3D problem through the Python module: described like `hpcontact check` describes it, run to
the summary the command line writes, and fields at points refused with what to read instead."""
import json
import os
import subprocess

import pytest

import hpcontact
from conftest import scaled_timeout

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SPHERE = os.path.join(ROOT, "examples", "solid", "thick-sphere-octant.yaml")


def test_a_3d_problem_describes_itself():
    d = hpcontact.Problem.from_file(SPHERE, set=["discretization.degree=3"]).describe()
    assert d["dimension"] == 3 and d["method"] == "p"
    assert d["bodies"] == [{"name": "shell", "nodes": 14, "elements": 3, "faces": 15}]
    assert d["dofs"] > d["dofs_condensed"] > 0


def test_a_3d_run_gives_the_command_lines_summary(tmp_path, hpcontact_exe):
    sets = ["discretization.degree=3"]
    result = hpcontact.Problem.from_file(SPHERE, set=sets).run()
    r = subprocess.run([hpcontact_exe, "run", SPHERE, "--out", str(tmp_path), "-q",
                        "--set", sets[0]], capture_output=True, text=True,
                       timeout=scaled_timeout(120))
    assert r.returncode == 0, r.stderr
    written = json.loads((tmp_path / "summary.json").read_text())
    assert set(written) == set(result.summary)
    for key in ("dofs", "strain_energy", "volume", "von_mises_max", "error", "elements"):
        assert written[key] == result.summary[key], key
    with pytest.raises(ValueError, match="3D result.*solution.vtu"):
        result.displacement([[1.5, 0.1, 0.1]])
