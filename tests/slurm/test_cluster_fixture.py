"""The test cluster itself: a daemon that cannot start fails the test with its log (it is not
skipped), and its process is gone afterwards."""
import pytest

from conftest import boot, require_slurm, start


def test_a_daemon_that_does_not_start_fails_with_its_log(tmp_path):
    """slurmctld with a plugin that does not exist ends at once: the failure shows its log."""
    require_slurm()
    c = boot(str(tmp_path), "SchedulerType=sched/none-such\n")
    try:
        with pytest.raises(pytest.fail.Exception) as failure:
            start(c)
    finally:
        c.stop()
    message = str(failure.value)
    assert "slurmctld ended at start" in message, message
    assert "--- slurmctld.log ---" in message and "sched/none-such" in message, message
    assert all(p.poll() is not None for p in c.daemons.values())
