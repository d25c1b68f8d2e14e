"""Fixtures of the Python module's tests: the repository root, the command-line program (for
comparing with its files) and runs shared by several tests."""
import os
import sys

import pytest

import hpcontact

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.append(os.path.join(ROOT, "tests"))
from timeouts import scaled_timeout  # noqa: E402,F401  (the test files' time limits)


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def hpcontact_exe():
    """The hpcontact program of the same build (ctest sets HPCONTACT_EXE)."""
    path = os.environ.get("HPCONTACT_EXE", os.path.join(ROOT, "build", "hpcontact"))
    if not os.path.exists(path):
        pytest.fail(f"hpcontact executable not found at {path} (set HPCONTACT_EXE)")
    return path


@pytest.fixture(scope="session")
def lame_file():
    return os.path.join(ROOT, "examples", "lame", "thick-cylinder.yaml")


@pytest.fixture(scope="session")
def hertz_p5_file():
    return os.path.join(ROOT, "examples", "hertz", "p5.yaml")


@pytest.fixture(scope="session")
def lame(lame_file):
    """The Lamé thick cylinder at p = 8 (a few milliseconds)."""
    return hpcontact.Problem.from_file(lame_file).run()


@pytest.fixture(scope="session")
def hertz_p5(hertz_p5_file):
    """The Hertz benchmark at p = 5 under force control (a few hundredths of a second)."""
    return hpcontact.Problem.from_file(hertz_p5_file).run()
