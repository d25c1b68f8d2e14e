"""scripts/study_table.py end to end on a small study (tests/cli/data/study-small.yaml): every
row run, its summary.json values in table.csv unchanged, table.md and pressure.png written."""
import csv
import importlib.util
import json
import os
import subprocess
import sys

from conftest import load_script

STUDY = os.path.join("tests", "cli", "data", "study-small.yaml")
NUMBERS = ["e_seed_hertz_percent", "e_seed_shtayerman_percent", "e_seed_reference_percent",
           "e_L2_hertz_percent", "e_L2_shtayerman_percent", "e_L2_reference_percent",
           "half_width", "p_max"]


def study_script(root, exe, *args):
    return subprocess.run([sys.executable, os.path.join(root, "scripts", "study_table.py"),
                           *map(str, args), "--hpcontact", exe], capture_output=True, text=True,
                          timeout=120)


def test_study_table_rows_equal_the_runs(exe, root, tmp_path):
    r = study_script(root, exe, os.path.join(root, STUDY), "--out", tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(os.path.join(root, STUDY)) as f:
        study = json.loads("\n".join(l for l in f if not l.lstrip().startswith("#")))
    labels = [run["label"] for run in study["runs"]]
    # one progress line per row
    assert sum(line.startswith("[") for line in r.stdout.splitlines()) == len(labels)

    with open(tmp_path / "table.csv") as f:
        rows = list(csv.DictReader(f))
    assert [row["label"] for row in rows] == labels
    for row, run in zip(rows, study["runs"]):
        s = json.loads((tmp_path / row["run_dir"] / "summary.json").read_text())
        c = s["contact"]
        assert row["converged"] == "true" and s["converged"] is True
        assert int(row["dofs"]) == s["dofs"]
        assert float(row["wall_time_s"]) == s["wall_time_s"]
        for key in NUMBERS:
            assert float(row[key]) == c[key], key
        assert int(row["seed_dofs"]) == run["seed"]["dofs"]
        assert float(row["seed_vs_hertz"]) == run["seed"]["vs_hertz"]
        assert float(row["seed_vs_shtayerman"]) == run["seed"]["vs_shtayerman"]
    assert rows[0]["dofs"] == "220"                       # p5: the seed's DOF count

    md = (tmp_path / "table.md").read_text()
    assert all(f"| {label} |" in md for label in labels)
    png = (tmp_path / "pressure.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000


def test_failed_run_is_reported(exe, root, tmp_path):
    """A row whose run fails: named on the progress line, 'failed' in the table, exit status 1,
    the other rows still tabulated."""
    study = tmp_path / "study.yaml"
    p5 = os.path.join(root, "examples", "hertz", "p5.yaml")
    study.write_text(json.dumps({"study": "bad", "runs": [
        {"label": "good", "case": p5},
        {"label": "bad degree", "case": p5, "set": ["discretization.degree=0"]}]}))
    r = study_script(root, exe, study, "--out", tmp_path / "out")
    assert r.returncode == 1
    assert "bad degree: FAILED" in r.stdout and "bad degree" in r.stderr
    with open(tmp_path / "out" / "table.csv") as f:
        rows = {row["label"]: row for row in csv.DictReader(f)}
    assert rows["bad degree"]["converged"] == "failed" and rows["bad degree"]["dofs"] == ""
    assert rows["good"]["dofs"] == "220"


def test_study_file_errors_name_the_place(root, tmp_path):
    study = tmp_path / "study.yaml"
    study.write_text('{"study": "x", "runs": [{"label": "a", "case": "missing.yaml"}]}')
    r = study_script(root, "/nonexistent", study, "--out", tmp_path / "out")
    assert r.returncode == 2 and "runs[0]" in r.stderr and "missing.yaml" in r.stderr
    study.write_text('{"study": "x", "runs": [{"label": "a", "cas": "p5.yaml"}]}')
    r = study_script(root, "/nonexistent", study, "--out", tmp_path / "out")
    assert r.returncode == 2 and "unknown key(s) cas" in r.stderr


def test_study_file_reads_without_pyyaml(root, monkeypatch):
    """The study files are JSON-compatible flow YAML: without PyYAML the json module reads
    them, and both readers agree."""
    module = load_script("study_table")
    path = os.path.join(root, "examples", "hertz", "table-5-1.yaml")
    with_yaml = module.load_study(path) if importlib.util.find_spec("yaml") else None
    monkeypatch.setitem(sys.modules, "yaml", None)        # `import yaml` raises ImportError
    without = module.load_study(path)
    assert len(without["runs"]) == 12 and without["runs"][0]["seed"]["dofs"] == 710
    if with_yaml is not None:
        assert with_yaml == without
