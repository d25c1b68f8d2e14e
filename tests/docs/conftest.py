"""Fixtures of the documentation tests: the repository root, its tracked files, the program."""
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.append(os.path.join(ROOT, "tests"))
from timeouts import scaled_timeout  # noqa: E402,F401  (the test files' time limits)


def pytest_addoption(parser):
    parser.addoption("--hpcontact", default=os.path.join(ROOT, "build", "hpcontact"),
                     help="path of the hpcontact executable")


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def exe(request):
    path = request.config.getoption("--hpcontact")
    if not os.access(path, os.X_OK):
        pytest.fail(f"hpcontact executable not found at {path}")
    return path


@pytest.fixture(scope="session")
def tracked_files():
    """The repository's files as git tracks them (with changes not yet committed); without git
    (a source tarball), every file outside build folders and results/."""
    r = subprocess.run(["git", "-C", ROOT, "ls-files", "--cached", "--others", "--exclude-standard"],
                       capture_output=True, text=True)
    if r.returncode == 0 and r.stdout.strip():
        return [f for f in r.stdout.splitlines() if os.path.isfile(os.path.join(ROOT, f))]
    out = []
    for folder, dirs, files in os.walk(ROOT):
        rel = os.path.relpath(folder, ROOT)
        dirs[:] = [d for d in dirs if not (d.startswith("build") or d in (".git", "results"))]
        out += [os.path.normpath(os.path.join(rel, f)) for f in files]
    return out
