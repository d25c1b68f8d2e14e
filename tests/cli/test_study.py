"""scripts/study_table.py end to end on a small study (tests/cli/data/study-small.yaml): it runs
the study file with `hpcontact study` (one reader, one format), and its table.md and
pressure.png show every row's summary.json and seed values."""
import csv
import json
import os
import subprocess
import sys

import yaml

from conftest import scaled_timeout

STUDY = os.path.join("tests", "cli", "data", "study-small.yaml")


def study_script(root, exe, *args):
    return subprocess.run([sys.executable, os.path.join(root, "scripts", "study_table.py"),
                           *map(str, args), "--hpcontact", exe], capture_output=True, text=True,
                          timeout=scaled_timeout(120))


def table_cells(md):
    """The rows of table.md's table: {label: [cells]}."""
    rows = [line.strip("|").split("|") for line in md.splitlines() if line.startswith("| ")]
    return {cells[0].strip(): [c.strip() for c in cells[1:]] for cells in rows[1:]}


def test_study_table_rows_are_the_study_commands_rows(exe, root, tmp_path):
    r = study_script(root, exe, os.path.join(root, STUDY), "--out", tmp_path)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(os.path.join(root, STUDY)) as f:
        study = yaml.safe_load(f)
    labels = [run["label"] for run in study["runs"]]
    # hpcontact study's progress: one line per row
    assert sum("ok " in line for line in r.stdout.splitlines()) == len(labels), r.stdout
    with open(tmp_path / "study.csv") as f:
        rows = list(csv.DictReader(f))
    assert [row["label"] for row in rows] == labels
    cells = table_cells((tmp_path / "table.md").read_text())
    assert list(cells) == labels
    for row, run in zip(rows, study["runs"]):
        s = json.loads(open(os.path.join(row["run_dir"], "summary.json")).read())
        assert row["converged"] == "true" and s["converged"] is True
        line = cells[run["label"]]
        assert line[0] == str(s["dofs"])                                  # DOF
        assert line[3] == f"{s['contact']['e_seed_shtayerman_percent']:.4f}"
        assert line[-4:] == [f"{run['seed']['dofs']}", f"{run['seed']['time_s']}",
                             f"{run['seed']['vs_hertz']:.4f}", f"{run['seed']['vs_shtayerman']:.4f}"]
        assert row["seed_dofs"] == str(run["seed"]["dofs"])
    assert rows[0]["dofs"] == "220"                       # p5: the dissertation's DOF count
    png = (tmp_path / "pressure.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000


def test_a_sweep_and_a_zip_study_file_is_read_as_hpcontact_study_reads_it(exe, root, tmp_path):
    """What `hpcontact study` takes, study_table.py takes: case + sweep + zip, no runs list."""
    study = tmp_path / "study.yaml"
    study.write_text(f"study: zipped\ncase: {os.path.join(root, 'examples/hertz/p5.yaml')}\n"
                     "sweep: {discretization.degree: [4, 5]}\n"
                     "zip:\n  contact[0].penalty: [1e6, 1e7]\n  contact[0].quadrature: [40, 50]\n")
    r = study_script(root, exe, study, "--out", tmp_path / "out", "--jobs", 2)
    assert r.returncode == 0, r.stdout + r.stderr
    cells = table_cells((tmp_path / "out" / "table.md").read_text())
    assert list(cells) == ["degree=4, penalty=1e6, quadrature=40", "degree=4, penalty=1e7, quadrature=50",
                           "degree=5, penalty=1e6, quadrature=40", "degree=5, penalty=1e7, quadrature=50"]


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
    assert "FAILED bad degree" in r.stdout and "bad degree" in r.stderr
    cells = table_cells((tmp_path / "out" / "table.md").read_text())
    assert cells["bad degree"][0] == "failed" and cells["good"][0] == "220"


def test_study_file_errors_name_the_place(exe, root, tmp_path):
    """A wrong study file is hpcontact's error (file, line, key): exit 1, no table."""
    study = tmp_path / "study.yaml"
    study.write_text('{"study": "x", "runs": [{"label": "a", "case": "missing.yaml"}]}')
    r = study_script(root, exe, study, "--out", tmp_path / "out")
    assert r.returncode == 1 and "runs[0].case" in r.stderr and "missing.yaml" in r.stderr
    study.write_text('{"study": "x", "runs": [{"label": "a", "cas": "p5.yaml"}]}')
    r = study_script(root, exe, study, "--out", tmp_path / "out")
    assert r.returncode == 1 and "runs[0].cas: unknown key" in r.stderr
    assert not (tmp_path / "out" / "table.md").exists()
    r = study_script(root, "/nonexistent", study, "--out", tmp_path / "out")
    assert r.returncode == 2 and "/nonexistent" in r.stderr
