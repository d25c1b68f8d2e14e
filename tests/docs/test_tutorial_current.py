"""docs/tutorial.md, examples/tutorial/README.md and docs/examples.md (its tutorial section) show
what the program does now: rerunning the tutorial's commands (scripts/regenerate_docs.py
--check) gives their marked logs, excerpts, tables and numbers, wall-clock times aside. When the program changes, rerun
scripts/regenerate_docs.py (then read the prose around what changed)."""
import importlib.util
import os
import subprocess

import pytest

from conftest import ROOT, scaled_timeout

PYTHON = "/usr/bin/python3"
SCRIPT = os.path.join(ROOT, "scripts", "regenerate_docs.py")


def load():
    spec = importlib.util.spec_from_file_location("regenerate_docs", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_tutorial_matches_a_rerun_of_its_commands(exe):
    module_dir = os.environ.get("PYTHONPATH") or os.path.join(ROOT, "build", "python")
    if importlib.util.find_spec("hpcontact") is None and not os.path.isdir(module_dir):
        pytest.skip("the Python module is not built: the tutorial's Python session cannot run")
    r = subprocess.run([PYTHON, SCRIPT, "--check", "--hpcontact", exe, "--python-path", module_dir],
                       capture_output=True, text=True, timeout=scaled_timeout(900))
    assert r.returncode == 0, (
        "the tutorial no longer shows what the program does; run scripts/regenerate_docs.py:\n"
        + r.stdout[-6000:] + r.stderr[-3000:])


def test_a_changed_value_or_block_is_stale_and_a_changed_time_is_not():
    """What --check compares: the document rendered from the runs against the document; only
    wall-clock times are masked."""
    m = load()
    doc = ("steps <!--v:load_steps-->6<!--/v-->, took <!--v:wall_time-->0.24 s<!--/v-->\n"
           "<!-- generated: path-csv -->\n```\nstep\n1\n```\n<!-- end: path-csv -->\n")
    same = m.render(doc, {"path-csv": "```\nstep\n1\n```\n"}, {"load_steps": "6", "wall_time": "0.31 s"}, "t")
    assert same != doc and m.masked(same) == m.masked(doc)           # only the time differs
    for blocks, values in (({"path-csv": "```\nstep\n1\n```\n"}, {"load_steps": "7", "wall_time": "0.24 s"}),
                           ({"path-csv": "```\nstep\n1\n2\n```\n"}, {"load_steps": "6", "wall_time": "0.24 s"})):
        assert m.masked(m.render(doc, blocks, values, "t")) != m.masked(doc)
    with pytest.raises(KeyError, match="value 'nothing' has no generator"):
        m.render("<!--v:nothing-->1<!--/v-->", {}, {}, "t")
    assert m.masked('"wall_time_s": 0.237765604,') == '"wall_time_s": <time>,'
    assert m.masked("results in results/punch/, 0.237766 s") == "results in results/punch/, <time> s"


def test_round_off_is_no_change_and_a_digit_is():
    """Another BLAS or CPU changes what round-off prints: a final residual or a gap below 1e-8,
    the last of 16 digits; those are the same document, a changed figure is not."""
    m = load()
    assert m.same("|R| 15512.2 -> 4.152e-11, gap -2.2e-19", "|R| 15512.2 -> 3.9e-11, gap 1.6e-19")
    assert m.same('"strain_energy": 988.6802002412228', '"strain_energy": 988.6802002412236')
    assert not m.same('"strain_energy": 988.6802002412228', '"strain_energy": 988.6803002412228')
    assert not m.same("|R| 15512.2 -> 4.152e-11", "|R| 15512.2 -> 4.152e-7")
    assert not m.same("6 Newton iterations", "7 Newton iterations")
    assert not m.same("load step 1", "load steps 1")
