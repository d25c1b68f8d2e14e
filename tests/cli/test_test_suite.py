"""The test suite on a busy machine (tests/timeouts.py): the tests' own waits stretch with the
machine's load and HPC_TEST_TIMEOUT_SCALE."""
import os

import pytest

import timeouts


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
