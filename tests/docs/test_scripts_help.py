"""Every script's --help is complete: it exits 0, prints the usage and the description, and
names and explains every argument the script takes (scripts/*.py and the examples' scripts)."""
import argparse
import glob
import importlib.util
import inspect
import os
import subprocess

import pytest

from conftest import scaled_timeout

PYTHON = "/usr/bin/python3"
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPTS = sorted(p for p in glob.glob(os.path.join(ROOT, "scripts", "*.py"))
                 + glob.glob(os.path.join(ROOT, "examples", "*", "*.py"))
                 if os.path.basename(p) not in ("hpc_run.py", "plot_runs.py"))  # modules, not scripts


class Captured(Exception):
    def __init__(self, parser):
        self.parser = parser


def parser_of(path, monkeypatch):
    """The ArgumentParser the script's main() builds (stopped at parse_args)."""
    spec = importlib.util.spec_from_file_location(os.path.basename(path)[:-3], path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)

    def capture(self, *args, **kwargs):
        raise Captured(self)

    monkeypatch.setattr(argparse.ArgumentParser, "parse_args", capture)
    takes_argv = bool(inspect.signature(module.main).parameters)
    with pytest.raises(Captured) as got:
        module.main([]) if takes_argv else module.main()
    return got.value.parser


@pytest.mark.parametrize("path", SCRIPTS, ids=lambda p: os.path.relpath(p, ROOT))
def test_help_names_and_explains_every_argument(path, monkeypatch):
    if path.endswith(os.path.join("python", "hertz.py")) and importlib.util.find_spec("hpcontact") is None:
        pytest.skip("the Python module is not built (PYTHONPATH=build/python)")
    r = subprocess.run([PYTHON, path, "--help"], capture_output=True, text=True,
                       timeout=scaled_timeout(60), cwd=ROOT)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("usage: "), r.stdout[:200]
    parser = parser_of(path, monkeypatch)
    assert parser.description and len(parser.description) > 20, "no description"
    for action in parser._actions:
        if isinstance(action, argparse._HelpAction):
            continue
        if action.option_strings:
            name = action.option_strings[-1]
        elif action.metavar:
            name = action.metavar
        else:
            name = "{" + ",".join(action.choices) + "}" if action.choices else action.dest
        assert action.help, f"{name}: no help text"
        assert name in r.stdout, f"{name} is not in --help"
    with open(path) as f:
        first = f.readline()
    assert first == "#!/usr/bin/python3\n", "the interpreter with numpy and matplotlib"
    assert os.access(path, os.X_OK), "not executable"
