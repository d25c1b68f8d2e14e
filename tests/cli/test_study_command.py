"""`hpcontact study`: a sweep and explicit rows run as separate processes into one table."""
import csv
import json
import math
import os
import subprocess
import sys

import pytest

from conftest import scaled_timeout


def write_study(tmp_path, root, body):
    path = tmp_path / "study.yaml"
    path.write_text(f"study: lame-p\ncase: {os.path.join(root, 'examples/lame/thick-cylinder.yaml')}\n"
                    + body)
    return path


def read_rows(out):
    with open(out / "study.csv") as f:
        return list(csv.DictReader(f))


def test_sweep_over_degrees_converges_and_a_bad_row_is_reported(hpcontact, root, tmp_path):
    study = write_study(tmp_path, root, "sweep:\n  discretization.degree: [2, 3, 4, 5]\n"
                        "runs:\n  - {label: incompressible, set: ['bodies[0].material.nu=0.5']}\n")
    out = tmp_path / "out"
    r = hpcontact("study", study, "--out", out, "--jobs", "2")
    assert r.returncode == 1, r.stdout + r.stderr  # one row failed
    rows = read_rows(out)
    assert [row["label"] for row in rows] == ["degree=2", "degree=3", "degree=4", "degree=5",
                                              "incompressible"]
    good = rows[:4]
    assert all(row["converged"] == "true" for row in good)
    dofs = [int(row["dofs"]) for row in good]
    errors = [float(row["error.energy_rel_percent"]) for row in good]
    assert dofs == sorted(dofs) and len(set(dofs)) == 4
    # p-convergence on the exact geometry: each degree at least halves the energy error (Lamé).
    assert all(b < 0.5 * a for a, b in zip(errors, errors[1:])), errors
    bad = rows[4]
    assert bad["converged"] == "false" and "material.nu" in bad["message"], bad
    assert "FAILED incompressible" in r.stdout
    with open(out / "study.json") as f:
        doc = json.load(f)
    assert doc["study"] == "lame-p" and len(doc["runs"]) == 5
    assert doc["runs"][0]["summary"]["dofs"] == dofs[0]
    assert os.path.exists(os.path.join(good[0]["run_dir"], "summary.json"))


def test_explicit_rows_with_seed_values(hpcontact, root, tmp_path):
    study = write_study(tmp_path, root, "set: ['discretization.degree=3']\nruns:\n"
                        "  - {label: plain, seed: {energy: 7.48}}\n"
                        "  - {label: condensed, set: ['discretization.condense=true']}\n")
    out = tmp_path / "out"
    r = hpcontact("study", study, "--out", out, "-q", "-j", "1")
    assert r.returncode == 0, r.stdout + r.stderr
    assert r.stdout == ""
    rows = read_rows(out)
    assert rows[0]["seed_energy"] == "7.48" and rows[1]["seed_energy"] == ""
    # Condensing internal modes changes how the system is solved, not the solution.
    e0, e1 = (float(row["strain_energy"]) for row in rows)
    assert abs(e0 - e1) <= 1e-10 * e0


def test_bad_study_files_are_refused_with_their_place(hpcontact, root, tmp_path):
    cases = {
        "colour: red\nruns: [{label: a}]\n": "colour: unknown key",
        "runs: [{label: a}, {label: a}]\n": "used twice",
        "sweep: {discretization.degree: 3}\n": "sweep.discretization.degree",
        "runs: [{label: a, case: nowhere.yaml}]\n": "no such problem file",
    }
    for body, fragment in cases.items():
        study = write_study(tmp_path, root, body)
        r = hpcontact("study", study, "--out", tmp_path / "out")
        assert r.returncode == 1, (body, r.stderr)
        assert "study.yaml" in r.stderr and fragment in r.stderr, (body, r.stderr)
    r = hpcontact("study", tmp_path / "missing.yaml")
    assert r.returncode == 2 and "Usage" in r.stderr


def test_zip_links_the_load_and_the_closed_forms_force(hpcontact, root, tmp_path):
    """examples/hertz/load-study.yaml: the zip's two keys vary together (3 rows, not 9), crossed
    with the sweep's two degrees; each run carries the force it was given (the resultant on the
    half model is its target) and compares with Hertz for its own load: b = sqrt(4 F R (1 - nu²)
    / (pi E)) for F = compare.force, R = 10, E = 210000, nu = 0.3."""
    out = tmp_path / "out"
    r = hpcontact("study", os.path.join(root, "examples", "hertz", "load-study.yaml"), "--out", out,
                  "-q", "-j", "2")
    assert r.returncode == 0, r.stdout + r.stderr
    rows = read_rows(out)
    targets, forces = [17500, 35000, 52500], [35000, 70000, 105000]
    assert [row["label"] for row in rows] == [
        f"degree={p}, value={t}, force={f}" for p in (5, 8) for t, f in zip(targets, forces)]
    for row, (target, force) in zip(rows, [(t, f) for _ in (5, 8) for t, f in zip(targets, forces)]):
        assert row["converged"] == "true", row
        assert abs(json.loads(row["contact.resultant"])[1] - target) <= 1e-6 * target, row
        b = (4 * force * 10 * (1 - 0.3**2) / (math.pi * 210000)) ** 0.5
        assert abs(float(row["contact.hertz_half_width"]) - b) <= 1e-9 * b, row

    # scripts/plot_study.py: any two columns of that table, one curve per group; a column that
    # is not there is named with the file and the columns that are.
    plot = [sys.executable, os.path.join(root, "scripts", "plot_study.py"), str(out)]
    png = tmp_path / "b.png"
    r = subprocess.run(plot + ["--x", "contact.hertz_half_width", "--y", "contact.half_width",
                               "--y", "contact.p_max", "--log", "--out", str(png)],
                       capture_output=True, text=True, timeout=scaled_timeout(120))
    assert r.returncode == 0 and r.stdout.strip() == f"wrote {png}", r.stdout + r.stderr
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    r = subprocess.run(plot + ["--x", "dofs", "--y", "contact.nothing"], capture_output=True,
                       text=True, timeout=scaled_timeout(120))
    assert r.returncode == 1 and "study.csv: no column 'contact.nothing'" in r.stderr, r.stderr
    assert "contact.half_width" in r.stderr


def test_a_name_with_a_control_character_is_refused_with_its_place(hpcontact, root, tmp_path):
    """The study's name, a row's label and a sweep value (which names its row) go into folders,
    tables, the terminal and a Slurm job's script, where a newline would end a line and make the
    rest a command of every task: one with a control character is refused, naming the file, line,
    key and the value escaped, and nothing is run."""
    case = os.path.join(root, "examples/lame/thick-cylinder.yaml")
    cases = {
        f'study: "x\\ntouch PWNED #"\ncase: {case}\nruns: [{{label: a}}]\n': "1:8: study:",
        f'study: s\ncase: {case}\nruns: [{{label: "a\\x1b[2J"}}]\n': "3:16: runs[0].label:",
        f'study: s\ncase: {case}\nsweep: {{title: [plain, "c\\rd"]}}\n': "3:24: sweep.title[1]:",
    }
    for body, place in cases.items():
        study = tmp_path / "study.yaml"
        study.write_text(body)
        out = tmp_path / "out"
        r = hpcontact("study", study, "--out", out, "-q")
        assert r.returncode == 1, (body, r.stdout + r.stderr)
        assert f"study.yaml:{place} must not hold a control character" in r.stderr, r.stderr
        assert not any(c in r.stderr for c in "\x1b\r") and r.stderr.count("\n") == 1, r.stderr
        assert not (out / "runs").exists() and not (tmp_path / "PWNED").exists()


def test_a_study_file_whose_name_is_not_utf8_gives_a_json_table(exe, root, tmp_path):
    """A study file or output folder named in bytes that are not UTF-8 (Latin-1) ended the study
    in 'internal error: [json.exception...]' when study.json was written; such a byte is U+FFFD
    there, and study.json is JSON."""
    folder = os.fsencode(tmp_path)
    study = folder + b"/\xe9tude.yaml"
    with open(study, "w") as f:
        f.write(f"study: s\ncase: {os.path.join(root, 'examples/lame/thick-cylinder.yaml')}\n"
                "runs: [{label: a}]\n")
    out = folder + b"/r\xe9sultats"
    r = subprocess.run([exe, "study", study, "--out", out, "-q"], capture_output=True, timeout=300)
    assert r.returncode == 0, r.stderr
    with open(out + b"/study.json", encoding="utf-8") as f:
        doc = json.load(f)
    assert doc["file"].endswith("\ufffdtude.yaml") and doc["runs"][0]["converged"] is True


def test_collect_of_a_forged_submission_record_names_the_key(hpcontact, tmp_path):
    """--collect of a folder whose slurm/submission.json was edited (a row that is not a number,
    a job id that names a path) ended in 'internal error: [json.exception...]' or read beyond the
    study; it is refused, naming the file and the key, and nothing is written."""
    out = tmp_path / "out"
    (out / "slurm").mkdir(parents=True)
    (out / ".hpcontact-manifest").write_text("slurm/submission.json\n")  # a study wrote it
    record = {"study": {"file": "s.yaml", "name": "s", "title": "", "columns": [],
                        "runs": [{"label": "a", "case": "a.yaml", "set": [], "seed": []}]},
              "submissions": [{"job_id": "12", "rows": [0], "complete": []}]}
    for key, value, said in (("rows", ["0"], "submissions[0].rows must be a list of row numbers"),
                             ("rows", [5], "submissions[0].rows must be a list of row numbers"),
                             ("job_id", "../../x", "submissions[0].job_id must be Slurm's job id")):
        forged = json.loads(json.dumps(record))
        forged["submissions"][0][key] = value
        (out / "slurm" / "submission.json").write_text(json.dumps(forged))
        r = hpcontact("study", "--collect", out)
        assert r.returncode == 1, r.stdout + r.stderr
        assert "internal error" not in r.stderr and said in r.stderr, r.stderr
        assert "submission.json: not a submission record" in r.stderr
        assert not (out / "study.csv").exists()


def test_columns_reach_into_lists_and_a_column_no_run_has_is_named(hpcontact, root, tmp_path):
    """A study's `columns` key into a list by its entry's index (contact_pairs.2.normal_force, a
    groove wall's force: before, an empty column and no word); a key no run's summary.json has is named in a warning."""
    study = tmp_path / "s.yaml"
    case = os.path.join(root, "examples", "o-ring", "o-ring-groove.yaml")
    study.write_text(f"study: columns\ncase: '{case}'\nsweep:\n  discretization.degree: [3, 4]\n"
                     "columns: [contact_pairs.2.normal_force, contact_pairs.5.normal_force, contact.no_such_key]\n")
    out = tmp_path / "out"
    r = hpcontact("study", study, "--out", out, "-q", "-j", "2")
    assert r.returncode == 0, r.stdout + r.stderr
    rows = read_rows(out)
    assert len(rows) == 2
    for row in rows:
        summary = json.load(open(os.path.join(out, row["run_dir"], "summary.json")))
        assert float(row["contact_pairs.2.normal_force"]) == pytest.approx(
            summary["contact_pairs"][2]["normal_force"], rel=1e-11)
        assert summary["contact_pairs"][2]["normal_force"] != pytest.approx(summary["contact_pairs"][1]["normal_force"], rel=0.1)
        assert row["contact_pairs.5.normal_force"] == "" and row["contact.no_such_key"] == ""
    for column in ("contact_pairs.5.normal_force", "contact.no_such_key"):
        assert f"s.yaml: columns: '{column}' is in no run's summary.json, so its study.csv column is empty" \
            in r.stderr, r.stderr
    assert "contact_pairs.2.normal_force' is in no" not in r.stderr
