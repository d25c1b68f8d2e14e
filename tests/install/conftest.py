"""Options of the install tests: the build folder to install from."""
import os
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.append(os.path.join(ROOT, "tests"))
from timeouts import scaled_timeout  # noqa: E402,F401  (the test files' time limits)


def pytest_addoption(parser):
    parser.addoption("--build-dir", default=os.path.join(ROOT, "build"),
                     help="the configured and built folder that `cmake --install` installs from")
    parser.addoption("--cmake", default="cmake", help="the cmake program")


@pytest.fixture(scope="session")
def build_dir(request):
    path = request.config.getoption("--build-dir")
    if not os.path.isfile(os.path.join(path, "CMakeCache.txt")):
        pytest.fail(f"{path}: not a configured build folder (no CMakeCache.txt)")
    return path


@pytest.fixture(scope="session")
def cmake(request):
    return request.config.getoption("--cmake")


@pytest.fixture(scope="session")
def root():
    return ROOT
