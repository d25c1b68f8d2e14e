"""Time limits of the tests' waits that stretch with the machine: a user's machine is often busy
(a fixed 120 s for a study that needs 52 s failed 14 tests at a load of 4-11 on 2 cores). The
conftest.py of each suite under tests/ puts this folder on the path."""
import os


def scale():
    """How much longer than on a quiet machine a wait may take now: HPC_TEST_TIMEOUT_SCALE (default
    1; e.g. 3 under valgrind or on a slow emulator) times the load per core when the machine has
    more to run than it has cores (the larger of the last 1 and 5 minutes' averages)."""
    text = os.environ.get("HPC_TEST_TIMEOUT_SCALE", "1")
    try:
        factor = float(text)
    except ValueError:
        factor = 0.0
    if not factor > 0:
        raise ValueError(f"HPC_TEST_TIMEOUT_SCALE={text!r} in the environment: not a positive number "
                         "(the factor on the tests' time limits; unset it for 1)")
    load = max(os.getloadavg()[:2]) / (os.cpu_count() or 1)
    return factor * max(1.0, load)


def scaled_timeout(seconds):
    """A time limit of `seconds` on a quiet machine, for this machine now (see scale)."""
    return seconds * scale()
