"""`hpcontact study`: a sweep and explicit rows run as separate processes into one table."""
import csv
import json
import os


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
