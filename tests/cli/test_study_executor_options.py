"""The command line of the study executors: the Slurm options only with --executor slurm,
--collect alone, and --jobs not with the scheduler; each a usage error (exit 2) naming the option."""
import os

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STUDY = os.path.join(ROOT, "examples", "hertz", "table-5-1.yaml")


@pytest.mark.parametrize("args, named", [
    (["--partition", "debug"], "--partition: only with --executor slurm"),
    (["--time", "5"], "--time: only with --executor slurm"),
    (["--cpus-per-task", "2"], "--cpus-per-task: only with --executor slurm"),
    (["--sbatch-option=--mem=1G"], "--sbatch-option: only with --executor slurm"),
    (["--wait"], "--wait: only with --executor slurm"),
    (["--executor", "slurm", "--jobs", "2"], "--jobs: not with --executor slurm"),
])
def test_option_of_the_other_executor(hpcontact, tmp_path, args, named):
    r = hpcontact("study", STUDY, "--out", tmp_path / "out", *args)
    assert r.returncode == 2, r.stderr
    assert named in r.stderr
    assert not (tmp_path / "out").exists()


def test_collect_takes_no_study_file(hpcontact, tmp_path):
    r = hpcontact("study", STUDY, "--collect", tmp_path)
    assert r.returncode == 2
    assert "--collect DIR takes no study file" in r.stderr


def test_no_study_file_and_no_collect(hpcontact):
    r = hpcontact("study")
    assert r.returncode == 2
    assert "give a study file (or --collect DIR)" in r.stderr


def test_unknown_executor(hpcontact, tmp_path):
    r = hpcontact("study", STUDY, "--executor", "pbs", "--out", tmp_path / "out")
    assert r.returncode == 2
    assert "--executor" in r.stderr and "pbs" in r.stderr


@pytest.mark.parametrize("args, named", [
    (["--jobs", "-1"], "--jobs: must be a number of runs at a time from 1 to 4096, or 0 for the "
                       "machine's cores (got '-1')"),
    (["--jobs", "99999999999"], "(got '99999999999')"),
    (["--executor", "slurm", "--cpus-per-task", "0"], "--cpus-per-task: must be a number of CPUs "
                                                      "from 1 to 4096 (got '0')"),
])
def test_a_count_out_of_range_says_which_counts_are_taken(hpcontact, tmp_path, args, named):
    """--jobs -1 was refused with a bound of 309 digits (the largest double); a count out of its
    range now says what the option takes."""
    r = hpcontact("study", STUDY, "--out", tmp_path / "out", *args)
    assert r.returncode == 2, r.stderr
    assert named in r.stderr and len(r.stderr.splitlines()[0]) < 200, r.stderr
