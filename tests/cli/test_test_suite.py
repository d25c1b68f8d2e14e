"""The test suite on a busy machine (tests/CMakeLists.txt, tests/timeouts.py): every pytest file
is a ctest test of its own, so that ctest -j runs them side by side each within its own time
limit, its tests marked slow apart under the label `make test` leaves out; and the tests' own
waits stretch with the machine's load and HPC_TEST_TIMEOUT_SCALE."""
import glob
import json
import os
import re
import subprocess

import pytest

import timeouts


def ctest_tests(build):
    """The build's ctest tests: name -> (command, {property: value})."""
    r = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, capture_output=True, text=True,
                       timeout=timeouts.scaled_timeout(60))
    assert r.returncode == 0, r.stderr
    return {t["name"]: (t.get("command", []), {p["name"]: p["value"] for p in t.get("properties", [])})
            for t in json.loads(r.stdout)["tests"]}


def marker_expression(command, path):
    """The -m expression given to pytest after the file's path, or None."""
    after = command[command.index(path) + 1:]
    return after[after.index("-m") + 1] if "-m" in after else None


def test_every_pytest_file_is_a_ctest_test_with_its_own_time_limit(exe, root):
    build = os.path.dirname(os.path.abspath(exe))
    if not os.path.exists(os.path.join(build, "CTestTestfile.cmake")):
        pytest.skip(f"{exe} is not in a CMake build folder")
    tests = ctest_tests(build)
    for suite in ("cli", "docs"):
        for path in glob.glob(os.path.join(root, "tests", suite, "test_*.py")):
            name = f"{suite}/{os.path.basename(path)[:-3]}"
            with open(path) as f:
                marked_slow = re.search(r"^ *@pytest\.mark\.slow", f.read(), re.M)
            assert name in tests, f"{path} is not a ctest test of its own"
            command, props = tests[name]
            assert path in command and props["LABELS"] == [suite], (name, command, props)
            assert props["TIMEOUT"] >= 600, name  # minutes, for a busy machine
            if marked_slow:  # its slow tests apart, labelled slow (ctest -LE slow leaves them out)
                assert marker_expression(command, path) == "not slow", command
                slow_command, slow_props = tests[name + ":slow"]
                assert marker_expression(slow_command, path) == "slow", slow_command
                assert slow_props["LABELS"] == [suite, "slow"]
            else:
                assert marker_expression(command, path) is None and name + ":slow" not in tests


def test_time_limits_stretch_with_the_load_and_the_environment(monkeypatch):
    cores = os.cpu_count() or 1
    monkeypatch.delenv("HPC_TEST_TIMEOUT_SCALE", raising=False)
    monkeypatch.setattr(os, "getloadavg", lambda: (0.1, 0.2, 0.3))
    assert timeouts.scaled_timeout(120) == 120  # a quiet machine: as written
    monkeypatch.setattr(os, "getloadavg", lambda: (2.0 * cores, 4.0 * cores, 0.0))
    assert timeouts.scaled_timeout(120) == pytest.approx(480)  # the larger of 1 and 5 minutes
    monkeypatch.setenv("HPC_TEST_TIMEOUT_SCALE", "2.5")
    assert timeouts.scaled_timeout(120) == pytest.approx(1200)
    for bad in ("fast", "0", "-1", "nan"):
        monkeypatch.setenv("HPC_TEST_TIMEOUT_SCALE", bad)
        with pytest.raises(ValueError, match=f"HPC_TEST_TIMEOUT_SCALE='{bad}' in the environment: "
                                             "not a positive number"):
            timeouts.scaled_timeout(120)
