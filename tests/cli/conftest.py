"""Fixtures of the command-line tests: the path of the built hpcontact program, and the
scripts/ modules loaded for tests of their functions."""
import csv
import importlib.util
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.append(os.path.join(ROOT, "tests"))
from timeouts import scaled_timeout  # noqa: E402  (the time limits, also the test files')


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: long, and checking what a faster test also checks: "
                            "a ctest test of its own labelled slow, which `make test` leaves out "
                            "(tests/CMakeLists.txt)")


def pytest_addoption(parser):
    parser.addoption("--hpcontact", default=os.path.join(ROOT, "build", "hpcontact"),
                     help="path of the hpcontact executable")


@pytest.fixture(scope="session")
def hpcontact(request):
    path = request.config.getoption("--hpcontact")
    if not os.path.exists(path):
        pytest.fail(f"hpcontact executable not found at {path}")

    def run(*args, timeout=300):
        """`hpcontact args...`, given `timeout` seconds (on a quiet machine) to finish."""
        return subprocess.run([path, *map(str, args)], capture_output=True, text=True,
                              timeout=scaled_timeout(timeout))

    return run


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def exe(hpcontact, request):
    """The executable's path (the hpcontact fixture fails the test if it is missing)."""
    return request.config.getoption("--hpcontact")


def expect_refused(hpcontact, case, out, settings, message, code):
    """`hpcontact run case --out out -q` with each of `settings` as --set: exit `code`, `message`
    and the case's file name on stderr, and no summary.json in `out`."""
    args = ["run", case, "--out", out, "-q"]
    for s in settings:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == code, r.stderr
    assert message in r.stderr, r.stderr
    assert os.path.basename(case) in r.stderr
    assert not os.path.exists(os.path.join(out, "summary.json"))


def csv_rows(path):
    """A CSV file's rows as dicts (contact.csv, path.csv, ...)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def partial_slip_generator(root, *args):
    """scripts/partial_slip_mesh.py with these arguments (two cylinders, R = 10): the finished
    process, the problem file on its stdout."""
    return subprocess.run([sys.executable, os.path.join(root, "scripts", "partial_slip_mesh.py"), *args],
                          capture_output=True, text=True, timeout=scaled_timeout(60))


def load_script(name):
    """scripts/<name>.py as a module (its functions, without running main)."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(ROOT, "scripts", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
