"""`hpcontact study --executor slurm` on the one-node cluster of conftest.py: the job array gives
the local executor's study.csv, a cancelled task is a failed row and a resubmission completes the
study, and bad input is refused by name before anything is submitted."""
import csv
import fcntl
import json
import os
import subprocess
import time

import pytest

from conftest import scaled_timeout

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
P5 = os.path.join(ROOT, "examples", "hertz", "p5.yaml")
P15 = os.path.join(ROOT, "examples", "hertz", "p15.yaml")
STUDY_SECONDS = 120  # a study's bound on a quiet machine (scaled_timeout stretches it)
# Columns that differ between two executions of the same runs: times and paths.
VARYING = {"wall_time_s", "run_dir", "case"}


def write_study(folder, name, text):
    path = os.path.join(folder, name + ".yaml")
    with open(path, "w") as f:
        f.write(text)
    return path


def six_rows(folder):
    return write_study(folder, "six", f"""study: hertz-six
case: {P5}
sweep:
  discretization.degree: [2, 3, 4, 5, 6, 7]
columns: [contact.hertz_half_width]
""")


def hpcontact(exe, cluster, *args, timeout=STUDY_SECONDS, env=None):
    return subprocess.run([exe, *map(str, args)], env=env or cluster.env, capture_output=True,
                          text=True, timeout=scaled_timeout(timeout))


def table(folder):
    with open(os.path.join(folder, "study.csv"), newline="") as f:
        return list(csv.DictReader(f))


def submissions(folder):
    with open(os.path.join(folder, "slurm", "submission.json")) as f:
        return json.load(f)["submissions"]


def test_slurm_study_gives_the_local_table(exe, cluster, tmp_path):
    """The six Hertz rows as a job array, waited for and collected, give the study.csv of the
    local executor apart from times and paths; each row has its log and the script is kept."""
    study = six_rows(str(tmp_path))
    on_slurm, local = tmp_path / "slurm-out", tmp_path / "local-out"
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", on_slurm, "--wait",
                  "--partition", "debug", "--time", "5", "--cpus-per-task", "1")
    assert r.returncode == 0, r.stdout + r.stderr + cluster.logs()
    assert "6 of 6 runs converged" in r.stdout
    assert "warning" not in r.stdout  # the one node is this machine (127.0.0.1)
    r = hpcontact(exe, cluster, "study", study, "--out", local, "--jobs", "2")
    assert r.returncode == 0, r.stdout + r.stderr
    slurm_rows, local_rows = table(on_slurm), table(local)
    assert len(slurm_rows) == 6 and list(slurm_rows[0]) == list(local_rows[0])
    for a, b in zip(slurm_rows, local_rows):
        assert a["converged"] == "true"
        assert {k: v for k, v in a.items() if k not in VARYING} == \
               {k: v for k, v in b.items() if k not in VARYING}
    script = (on_slurm / "slurm" / "array.sh").read_text()
    assert "#SBATCH --partition=debug" in script and "#SBATCH --time=5" in script
    assert "discretization.degree=7" in script
    for row in slurm_rows:
        log = os.path.join(row["run_dir"], "log.txt")
        assert "hpcontact-task: exit 0" in open(log).read()
    # A second submission finds every row done and submits nothing.
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", on_slurm, "--wait")
    assert r.returncode == 0 and "nothing submitted" in r.stdout, r.stdout + r.stderr
    assert len(submissions(on_slurm)) == 1


def wait_running(cluster, task, seconds=60):
    seconds = scaled_timeout(seconds)
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        r = cluster.run("squeue", "-h", "-r", "-j", task, "-o", "%T", check=False)
        if r.stdout.strip() == "RUNNING":
            return
        time.sleep(0.1)
    pytest.fail(f"task {task} did not start within {seconds:.0f} s:\n{cluster.logs()}")


def wait_submitted(folder, seconds=60):
    seconds = scaled_timeout(seconds)
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        path = os.path.join(folder, "slurm", "submission.json")
        if os.path.exists(path):
            jobs = [s["job_id"] for s in submissions(folder) if s["job_id"]]
            if jobs:
                return jobs[-1]
        time.sleep(0.1)
    pytest.fail(f"no job submitted into {folder} within {seconds:.0f} s")


def lock_held(path):
    """Whether another process holds the run folder's lock file (flock) now."""
    with open(path, "a") as f:
        try:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
            fcntl.flock(f, fcntl.LOCK_UN)
            return False
        except BlockingIOError:
            return True


def wait_unlocked(run_dir, seconds=60):
    """Until no process holds the run folder's lock (.hpcontact-lock, flock): Slurm records a
    task CANCELLED when it signals it, and the run it killed may live on for a moment (up to
    KillWait) holding its folder; a run started there meanwhile is refused, as it should be."""
    path = os.path.join(run_dir, ".hpcontact-lock")
    seconds = scaled_timeout(seconds)
    deadline = time.monotonic() + seconds
    while os.path.exists(path) and lock_held(path):
        assert time.monotonic() < deadline, f"{path} still locked after {seconds:.0f} s"
        time.sleep(0.2)


def wait_locked(run_dir, seconds=60):
    """Until a process holds the run folder's lock: hpcontact has started in the task, with its
    signal handlers in place (they come before the lock). A task cancelled earlier may lose its
    run from the scheduler's view (its script killed while the run was being started), and that
    run then ends, committed, after the task was reported CANCELLED."""
    path = os.path.join(run_dir, ".hpcontact-lock")
    seconds = scaled_timeout(seconds)
    deadline = time.monotonic() + seconds
    while not (os.path.exists(path) and lock_held(path)):
        if time.monotonic() > deadline:
            pytest.fail(f"no run held {path} within {seconds:.0f} s")
        time.sleep(0.05)


def test_cancelled_task_is_a_failed_row_and_resubmission_completes(exe, cluster, tmp_path):
    """scancel of one running task: that row fails with its label and log, the others are
    collected; submitting again runs only that row, and the study is complete. The slow row
    takes ~5 s alone (degree 30, 60 Gauss points a direction): at ~2 s it sometimes finished
    before Slurm reported it running under a loaded machine, and was never cancelled."""
    study = write_study(str(tmp_path), "cancel", f"""study: cancel-one
runs:
  - {{label: fast-a, case: {P5}, set: [discretization.degree=3]}}
  - {{label: slow, case: {P15}, set: [discretization.degree=30, discretization.quadrature_extra=30]}}
  - {{label: fast-b, case: {P5}, set: [discretization.degree=4]}}
""")
    out = tmp_path / "out"
    p = subprocess.Popen([exe, "study", study, "--executor", "slurm", "--out", str(out), "--wait"],
                         env=cluster.env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        job = wait_submitted(str(out))
        wait_running(cluster, f"{job}_1")
        wait_locked(str(out / "runs" / "02-slow"))
        cluster.run("scancel", f"{job}_1")
        stdout, stderr = p.communicate(timeout=scaled_timeout(STUDY_SECONDS))
    finally:
        if p.poll() is None:
            p.kill()
            p.communicate()
    assert p.returncode == 1, stdout + stderr
    assert f"FAILED slow" in stdout and f"array task {job}_1 ended CANCELLED" in stdout, stdout
    assert f"slurm/logs/{job}_1.out" in stdout
    assert "2 of 3 runs converged" in stdout
    rows = {r["label"]: r for r in table(out)}
    assert rows["fast-a"]["converged"] == rows["fast-b"]["converged"] == "true"
    assert rows["slow"]["converged"] == "false" and "CANCELLED" in rows["slow"]["message"]
    r = hpcontact(exe, cluster, "study", "--collect", out)  # later, without following
    assert r.returncode == 1
    assert f"FAILED slow: array task {job}_1 ended CANCELLED" in r.stdout, r.stdout
    assert "2 of 3 runs converged" in r.stdout

    wait_unlocked(str(out / "runs" / "02-slow"))
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", out, "--wait")
    assert r.returncode == 0, r.stdout + r.stderr + cluster.logs()
    assert "1 tasks (rows 1," in r.stdout and "2 rows already have a successful run" in r.stdout
    assert [s["rows"] for s in submissions(out)] == [[0, 1, 2], [1]]
    assert all(row["converged"] == "true" for row in table(out))


def test_a_run_that_outlived_its_task_is_the_row(exe, cluster, tmp_path):
    """A task whose script ended without its exit line while its run went on and committed (the
    scheduler lost the process): the row is that run, written after the submission, as a
    resubmission counts it; a summary older than the submission is not the task's."""
    study = write_study(str(tmp_path), "one", f"""study: one
runs:
  - {{label: only, case: {P5}, set: [discretization.degree=3]}}
""")
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", out, "--wait")
    assert r.returncode == 0, r.stdout + r.stderr + cluster.logs()
    job = submissions(out)[-1]["job_id"]
    log = out / "slurm" / "logs" / f"{job}_0.out"
    text = log.read_text()
    assert "hpcontact-task: exit 0" in text
    log.write_text("".join(l for l in text.splitlines(True) if not l.startswith("hpcontact-task: exit")))
    r = hpcontact(exe, cluster, "study", "--collect", out)
    assert r.returncode == 0 and "1 of 1 runs converged" in r.stdout, r.stdout + r.stderr
    assert table(out)[0]["converged"] == "true"

    summary = out / "runs" / "01-only" / "summary.json"
    before = summary.stat().st_mtime - 7200
    os.utime(summary, (before, before))
    r = hpcontact(exe, cluster, "study", "--collect", out)
    assert r.returncode == 1, r.stdout + r.stderr
    assert f"FAILED only: array task {job}_0 ended COMPLETED" in r.stdout, r.stdout
    assert "without an exit status" in r.stdout


def test_no_sbatch_on_path(exe, cluster, tmp_path):
    """Without sbatch on PATH the study says so, naming --executor slurm, and writes nothing."""
    out = tmp_path / "out"
    env = dict(cluster.env, PATH=str(tmp_path))
    r = hpcontact(exe, cluster, "study", six_rows(str(tmp_path)), "--executor", "slurm", "--out", out,
                  env=env)
    assert r.returncode == 1
    assert "--executor slurm: sbatch is not on PATH" in r.stderr, r.stderr
    assert not out.exists()


def test_unknown_partition(exe, cluster, tmp_path):
    """A partition the cluster lacks is named with the ones it has; nothing is submitted."""
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", six_rows(str(tmp_path)), "--executor", "slurm", "--out", out,
                  "--partition", "gpu-none")
    assert r.returncode == 1
    assert "--partition gpu-none: the cluster has no such partition (sinfo lists: debug)" in r.stderr, r.stderr
    assert not (out / "slurm" / "submission.json").exists()


def test_sbatch_refusing_an_option(exe, cluster, tmp_path):
    """An option sbatch refuses (a bad --time) is named with sbatch's reason before submission."""
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", six_rows(str(tmp_path)), "--executor", "slurm", "--out", out,
                  "--time", "soon")
    assert r.returncode == 1
    assert "sbatch --test-only refused the job array" in r.stderr and "--time soon" in r.stderr, r.stderr
    assert "nothing was submitted" in r.stderr
    assert not (out / "slurm" / "submission.json").exists()


def test_invalid_row(exe, cluster, tmp_path):
    """A row whose input is invalid is named (number, label, key) and nothing is submitted."""
    study = write_study(str(tmp_path), "bad", f"""study: bad-row
runs:
  - {{label: good, case: {P5}}}
  - {{label: too-high, case: {P5}, set: [discretization.degree=99]}}
""")
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", out)
    assert r.returncode == 1
    assert "1 of the 2 rows cannot be run; nothing was submitted" in r.stderr, r.stderr
    assert "row 2 'too-high':" in r.stderr and "discretization.degree" in r.stderr
    assert not (out / "slurm" / "submission.json").exists()


def test_folder_the_tasks_cannot_write(exe, cluster, tmp_path):
    """Tasks that cannot write the study's folder (as on a node that does not share it): every
    row fails saying so, with the path of the log that is missing."""
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", six_rows(str(tmp_path)), "--executor", "slurm", "--out", out,
                  "--sbatch-option=--hold")
    assert r.returncode == 0, r.stdout + r.stderr
    job = wait_submitted(str(out))
    logs = out / "slurm" / "logs"
    logs.rmdir()
    logs.write_text("")  # where the tasks' logs go, a file: the node cannot open them
    cluster.run("scontrol", "release", job)
    r = hpcontact(exe, cluster, "study", "--collect", out, "--wait")
    assert r.returncode == 1
    assert "0 of 6 runs converged" in r.stdout
    assert f"left no log at {out}/slurm/logs/{job}_0.out" in r.stdout, r.stdout
    assert "file system the nodes share" in r.stdout
    logs.unlink()


def test_collect_of_a_folder_without_submission(exe, cluster, tmp_path):
    """--collect of a folder that is missing, or that no study was submitted from, says so."""
    r = hpcontact(exe, cluster, "study", "--collect", tmp_path / "none")
    assert r.returncode == 1
    assert "none: no such folder" in r.stderr, r.stderr
    assert not (tmp_path / "none").exists()
    (tmp_path / "empty").mkdir()
    r = hpcontact(exe, cluster, "study", "--collect", tmp_path / "empty")
    assert r.returncode == 1
    assert "no Slurm submission here" in r.stderr, r.stderr


def test_a_newline_cannot_put_a_command_into_the_script(exe, cluster, tmp_path):
    """A newline in the study's name would end the comment line of slurm/array.sh that names
    it, and one in --time its #SBATCH line: the rest would be a command every array task runs.
    Both are refused, naming the value, and nothing is submitted or run."""
    planted = tmp_path / "PLANTED"
    study = write_study(str(tmp_path), "named", f"""study: "x\\ntouch {planted} #"
runs:
  - {{label: only, case: {P5}, set: [discretization.degree=2]}}
""")
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", out, "--wait")
    assert r.returncode == 1, r.stdout + r.stderr
    assert "named.yaml:1:8: study: must not hold a control character" in r.stderr, r.stderr
    r = hpcontact(exe, cluster, "study", six_rows(str(tmp_path)), "--executor", "slurm", "--out", out,
                  "--wait", "--time", f"5\ntouch {planted} #")
    assert r.returncode == 1, r.stdout + r.stderr
    assert "--time '5\\x0atouch" in r.stderr and "nothing was submitted" in r.stderr, r.stderr
    assert not planted.exists()
    assert not (out / "slurm" / "submission.json").exists()


def test_a_row_whose_summary_has_gone_is_not_a_success(exe, cluster, tmp_path):
    """A row counts as done only while its run's summary.json is there: one a submission found
    complete (run before, here by the local executor) and one whose task ended with exit 0,
    whose summary.json has since gone, are failed rows that say so, and the next submission runs
    both again."""
    study = write_study(str(tmp_path), "two", f"""study: two
runs:
  - {{label: a, case: {P5}, set: [discretization.degree=2]}}
  - {{label: b, case: {P5}, set: [discretization.degree=3]}}
""")
    out = tmp_path / "out"
    r = hpcontact(exe, cluster, "study", study, "--out", out, "-q")  # the local executor
    assert r.returncode == 0, r.stdout + r.stderr
    (out / "runs" / "02-b" / "summary.json").unlink()
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", out, "--wait")
    assert r.returncode == 0, r.stdout + r.stderr + cluster.logs()
    assert "1 rows already have a successful run" in r.stdout, r.stdout
    job = submissions(out)[-1]["job_id"]
    for label in ("01-a", "02-b"):
        (out / "runs" / label / "summary.json").unlink()
    r = hpcontact(exe, cluster, "study", "--collect", out)
    assert r.returncode == 1 and "0 of 2 runs converged" in r.stdout, r.stdout + r.stderr
    assert "FAILED a: found complete when submitted, but its run's summary.json has gone since" \
        in r.stdout, r.stdout
    assert f"FAILED b: array task {job}_1 ended with exit 0, but its run's summary.json has gone " \
        "since" in r.stdout, r.stdout
    assert [row["converged"] for row in table(out)] == ["false", "false"]
    r = hpcontact(exe, cluster, "study", study, "--executor", "slurm", "--out", out, "--wait")
    assert r.returncode == 0 and "2 tasks (rows 0-1" in r.stdout, r.stdout + r.stderr
    assert [row["converged"] for row in table(out)] == ["true", "true"]
