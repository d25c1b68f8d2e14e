"""The figures the examples' READMEs quote are the program's (issue 44 item 6): each is marked
with its run and summary.json entry, and scripts/example_figures.py --check reruns the examples
and fails on a stale one — shown here on a doctored copy of a README — so that they cannot
drift as examples/roller-block's did (1889 DOF, 4 steps quoted for a run that had become 1102 DOF
and 6 steps)."""
import os
import shutil
import subprocess

from conftest import ROOT, scaled_timeout

PYTHON = "/usr/bin/python3"
SCRIPT = os.path.join(ROOT, "scripts", "example_figures.py")


def figures(exe, *args):
    return subprocess.run([PYTHON, SCRIPT, "--hpcontact", exe, *args], capture_output=True, text=True,
                          timeout=scaled_timeout(600))


def test_every_marked_figure_is_current(exe):
    r = figures(exe, "--check")
    assert r.returncode == 0, r.stdout + r.stderr


def doctored(tmp_path, old, new):
    """examples/roller-block copied, its README with `old` replaced by `new` (once)."""
    folder = tmp_path / "roller-block"
    shutil.copytree(os.path.join(ROOT, "examples", "roller-block"), folder,
                    ignore=shutil.ignore_patterns("friction"))
    readme = folder / "README.md"
    text = readme.read_text()
    assert text.count(old) == 1
    readme.write_text(text.replace(old, new))
    return readme


def test_a_stale_figure_fails_the_check_and_is_rewritten(exe, tmp_path):
    """The Gmsh run's DOF count set back to the old README's 1889 and its L2 error's last digit
    changed: --check names both (line, key, the current value, what the README shows) and exits
    1; without --check both are rewritten to the program's values with the digits they had, and
    the check passes."""
    readme = doctored(tmp_path, "roller-block-gmsh.yaml:dofs-->1102<", "roller-block-gmsh.yaml:dofs-->1889<")
    text = readme.read_text().replace("e_L2_hertz_percent-->1.01<", "e_L2_hertz_percent-->1.02<")
    readme.write_text(text)
    r = figures(exe, "--check", str(readme))
    assert r.returncode == 1, r.stdout + r.stderr
    stale = [line for line in r.stdout.splitlines() if "the README shows" in line]
    assert len(stale) == 2, r.stdout
    assert "dofs is 1102, the README shows 1889" in stale[0]
    assert "contact.e_L2_hertz_percent is 1.0098" in stale[1] and stale[1].endswith("shows 1.02")
    assert readme.read_text() == text  # --check writes nothing
    assert figures(exe, str(readme)).returncode == 0
    rewritten = readme.read_text()
    assert "dofs-->1102<" in rewritten and "e_L2_hertz_percent-->1.01<" in rewritten
    assert figures(exe, "--check", str(readme)).returncode == 0


def test_a_marker_that_names_nothing_is_an_error(exe, tmp_path):
    """A key summary.json does not have, and a file that does not exist: exit 2 naming them."""
    readme = doctored(tmp_path, "roller-block-gmsh.yaml:dofs-->", "roller-block-gmsh.yaml:dof_count-->")
    r = figures(exe, "--check", str(readme))
    assert r.returncode == 2 and "summary.json has no 'dof_count'" in r.stderr, r.stderr
    readme = doctored(tmp_path / "b", "roller-block.yaml:dofs-->", "no-such.yaml:dofs-->")
    r = figures(exe, "--check", str(readme))
    assert r.returncode == 2 and "no problem file" in r.stderr and "no-such.yaml" in r.stderr, r.stderr
