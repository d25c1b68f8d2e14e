"""The general plot scripts on a real run: scripts/plot_contact.py (contact.csv of any case)
and scripts/plot_field.py (a field of solution.vtu on the deformed mesh)."""
import os
import subprocess

PYTHON = "/usr/bin/python3"


def run_script(root, name, *args):
    return subprocess.run([PYTHON, os.path.join(root, "scripts", name), *map(str, args)],
                          capture_output=True, text=True, timeout=120)


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
