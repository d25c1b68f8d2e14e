"""The output folder (docs/input.md, "The output folder"): a run never deletes or overwrites a
file it did not write, never follows a link in the folder, keeps the earlier results until it
has succeeded, checks every write to the disk and holds a lock; a study passes SIGTERM/SIGINT on
to its runs."""
import csv
import json
import os
import re
import resource
import signal
import subprocess
import time

import pytest

from conftest import scaled_timeout

LAME = "examples/lame/thick-cylinder.yaml"
HERTZ = "examples/hertz/p5.yaml"
# Hertz at p = 15 by penalty in 400 load steps: long enough (seconds) to be caught while it
# solves (exact force control needs no load steps and ends in a fraction of a second).
LONG = ("examples/hertz/p15.yaml", "--set", "solver.load_steps=400",
        "--set", "contact[0].enforcement=penalty")
# A block pressed beyond its height: the third load step inverts its element, the second is
# kept in last-good/; pressed by half its height it succeeds.
BLOCK = "tests/cli/data/crushed-block.yaml"
PRESS = "bodies[0].constraints[1].uy"
NO_CONVERGED_STEP = ["--set", "solver.max_iterations=1", "--set", "solver.max_cuts=0"]


def snapshot(folder):
    """Every file below `folder` (links as their target's path) -> its bytes."""
    files = {}
    for dirpath, dirnames, filenames in os.walk(folder):
        for name in filenames + [d for d in dirnames if os.path.islink(os.path.join(dirpath, d))]:
            path = os.path.join(dirpath, name)
            rel = os.path.relpath(path, folder)
            files[rel] = ("link:" + os.readlink(path)) if os.path.islink(path) else open(path, "rb").read()
    return files


def results(folder):
    """The snapshot without our bookkeeping files (lock, manifest)."""
    return {k: v for k, v in snapshot(folder).items() if not k.startswith(".hpcontact-")}


def assert_untouched(folder, before):
    """Every file of `before` as it was, and nothing new but the lock file."""
    after = snapshot(folder)
    assert set(after) - set(before) <= {".hpcontact-lock"}, sorted(after)
    assert {k: after.get(k) for k in before} == before


def user_folder(tmp_path):
    """A folder of a user's own files: another case, a reference curve, notes, a subfolder."""
    d = tmp_path / "mine"
    (d / "data").mkdir(parents=True)
    (d / "other-case.yaml").write_text("case: not this one\n")
    (d / "hertz-reference.csv").write_text("x,pressure\n0,1\n1,0\n")
    (d / "notes.txt").write_text("keep me\n")
    (d / "data" / "pressure.csv").write_text("x,pressure\n0,7\n")  # an output name, one level down
    (d / "summary.json.tmp").write_text("a stranger's file\n")
    return d


def start(exe, *args):
    """Starts hpcontact and returns the process once it is solving (its first Newton line: -v)."""
    p = subprocess.Popen([exe, *map(str, args), "-v"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    for line in p.stdout:
        if line.lstrip().startswith("iteration "):
            return p
    p.wait()
    pytest.fail(f"the run ended before it solved: {p.returncode} {p.stderr.read()}")


def test_folder_holding_the_problem_file_is_refused(exe, root, tmp_path):
    """`cd dir && hpcontact run input.yaml --out .` is refused before the file is read, with a
    message that says why; the problem file and every other file stay as they were."""
    (tmp_path / "input.yaml").write_text(open(os.path.join(root, LAME)).read())
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "case.yaml").write_text(open(os.path.join(root, LAME)).read())
    before = snapshot(tmp_path)
    for case, out in (("input.yaml", "."), ("sub/case.yaml", ".")):
        r = subprocess.run([exe, "run", case, "--out", out, "-q"], cwd=tmp_path,
                           capture_output=True, text=True, timeout=scaled_timeout(60))
        assert r.returncode == 1, r.stderr
        assert "holds the problem file" in r.stderr and case in r.stderr, r.stderr
        assert_untouched(tmp_path, before)


def test_folder_holding_the_reference_file_is_refused(hpcontact, root, tmp_path):
    """A compare section's reference (named pressure.csv, as docs/input.md suggests) inside the
    output folder refuses the folder; the reference is not touched."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "pressure.csv").write_bytes(open(os.path.join(root, "examples/hertz/reference-pressure.csv"), "rb").read())
    case = tmp_path / "p5.yaml"
    case.write_text(open(os.path.join(root, HERTZ)).read().replace(
        "reference: reference-pressure.csv", "reference: out/pressure.csv"))
    before = snapshot(out)
    r = hpcontact("run", case, "--out", out, "-q")
    assert r.returncode == 1, r.stderr
    assert "holds the reference file of" in r.stderr and "pressure.csv" in r.stderr, r.stderr
    assert_untouched(out, before)


@pytest.mark.parametrize("name", ["pressure.csv", "input.yaml", "summary.json", "rp/pressure-1.csv"])
def test_user_file_with_an_output_name_refuses_the_folder(hpcontact, root, tmp_path, name):
    """A file with one of the program's output names that the folder's manifest does not list
    is a user's: the run is refused with its name, before solving, and the file stays."""
    out = tmp_path / "out"
    (out / name).parent.mkdir(parents=True, exist_ok=True)
    (out / name).write_text("the user's own\n")
    before = snapshot(out)
    r = hpcontact("run", os.path.join(root, HERTZ), "--out", out, "-q")
    assert r.returncode == 1, r.stderr
    assert f"{name}: hpcontact did not write this file" in r.stderr, r.stderr
    assert_untouched(out, before)


def test_user_files_and_earlier_results_survive_every_run(hpcontact, exe, root, tmp_path):
    """A user's folder used as --out: after a successful, a failing (a --set typo, a solver
    failure with and without a converged step), a stopped and a killed run, every user file is
    byte-identical and the previous results are intact until a new run succeeds."""
    out = user_folder(tmp_path)
    mine = snapshot(out)
    case = os.path.join(root, BLOCK)
    r = hpcontact("run", case, "--out", out, "-q", "--set", f"{PRESS}=-0.5")
    assert r.returncode == 0, r.stderr
    first = results(out)
    assert {"summary.json", "path.csv", "solution.vtu", "input.yaml"} <= set(first)
    assert all(first[k] == v for k, v in mine.items())

    for bad, code in ((["--set", "solver.max_iteratons=3"], 2),  # a typo
                      (["--set", "bodies[0].material.nu=0.5"], 2),
                      (["--set", f"{PRESS}=-0.5", *NO_CONVERGED_STEP], 1)):
        r = hpcontact("run", case, "--out", out, "-q", *bad)
        assert r.returncode == code, (bad, r.stderr)
        assert results(out) == first, bad

    # Stopped while solving (SIGTERM): the solve stops at its next Newton iteration or stop
    # point, the run ends by the signal, nothing is left staged and the earlier results stay
    # (what had converged, if a load step had, would be in last-good/: test_stop_signal.py).
    p = start(exe, "run", os.path.join(root, LONG[0]), "--out", out, *LONG[1:])
    p.send_signal(signal.SIGTERM)
    assert p.wait(timeout=scaled_timeout(60)) == -signal.SIGTERM
    assert {k: v for k, v in results(out).items() if not k.startswith("last-good/")} == first
    assert not any(name.startswith(".hpcontact-staging-") for name in os.listdir(out))

    # Killed outright (SIGKILL): nothing changes; its staging folder is left for the next run.
    p = start(exe, "run", os.path.join(root, LONG[0]), "--out", out, *LONG[1:])
    p.send_signal(signal.SIGKILL)
    assert p.wait(timeout=scaled_timeout(60)) == -signal.SIGKILL
    assert {k: v for k, v in results(out).items() if not k.startswith("last-good/")} == first
    assert any(name.startswith(".hpcontact-staging-") for name in os.listdir(out))

    # A failure after a converged step adds last-good/ (converged: false) and changes nothing else.
    r = hpcontact("run", case, "--out", out, "-q")
    assert r.returncode == 1 and f"is in {out}/last-good" in r.stderr, r.stderr
    now = results(out)
    assert {k: v for k, v in now.items() if not k.startswith("last-good/")} == first
    kept = json.loads(now["last-good/summary.json"])
    assert kept["converged"] is False and kept["load_factor"] == 0.75
    assert not any(k.startswith(".hpcontact-staging") for k in os.listdir(out))

    # The next success replaces the results and removes last-good/; the user's files stay.
    r = hpcontact("run", case, "--out", out, "-q", "--set", f"{PRESS}=-0.25")
    assert r.returncode == 0, r.stderr
    last = results(out)
    assert not any(k.startswith("last-good") for k in last)
    assert last["summary.json"] != first["summary.json"]
    assert all(last[k] == v for k, v in mine.items())
    manifest = (out / ".hpcontact-manifest").read_text().split()
    assert sorted(manifest) == sorted(k for k in last if k not in mine)


def test_a_later_run_replaces_only_its_own_files(hpcontact, root, tmp_path):
    """Files an earlier run wrote that the next run does not write are removed (the manifest
    lists them); a user's file put into one of our folders stays, and so does that folder."""
    out = tmp_path / "out"
    r = hpcontact("run", os.path.join(root, BLOCK), "--out", out, "-q")
    assert r.returncode == 1
    assert (out / "last-good" / "path.csv").exists()
    (out / "last-good" / "notes.txt").write_text("mine too")
    r = hpcontact("run", os.path.join(root, LAME), "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    assert sorted(results(out)) == ["input.yaml", "last-good/notes.txt", "report.html",
                                    "solution.vtu", "summary.json"]


def test_planted_links_are_never_followed(hpcontact, root, tmp_path):
    """A summary.json.tmp link is not written through; a last-good link refuses the folder and
    nothing in its target is deleted."""
    victim = tmp_path / "victim"
    victim.mkdir()
    for name in ("precious.txt", "summary.json", "contact.csv", "input.yaml"):
        (victim / name).write_text(f"the victim's {name}\n")
    out = tmp_path / "out"
    out.mkdir()
    os.symlink(victim / "precious.txt", out / "summary.json.tmp")
    r = hpcontact("run", os.path.join(root, LAME), "--out", out, "-q")
    assert r.returncode == 0, r.stderr
    assert os.readlink(out / "summary.json.tmp") == str(victim / "precious.txt")
    assert json.loads((out / "summary.json").read_text())["converged"] is True
    before = snapshot(victim)
    os.symlink(victim, out / "last-good")
    r = hpcontact("run", os.path.join(root, LAME), "--out", out, "-q")
    assert r.returncode == 1
    assert "last-good: a symbolic link" in r.stderr, r.stderr
    assert snapshot(victim) == before
    os.unlink(out / "last-good")
    os.symlink(victim / "summary.json", out / "pressure.csv")
    r = hpcontact("run", os.path.join(root, HERTZ), "--out", out, "-q")
    assert r.returncode == 1 and "pressure.csv: a symbolic link" in r.stderr, r.stderr
    assert snapshot(victim) == before


def limit_file_size(limit):
    def apply():
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # writes fail with EFBIG instead
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return apply


def test_a_write_that_fails_fails_the_run(exe, root, tmp_path):
    """Files that cannot be written whole (here: a file size limit, as a full disk does; the
    limits cut path.csv (115 bytes), the first file written, and solution.vtu (2955 bytes), each
    within one buffer written at close) end the run with exit 1 and a message naming the file and the system's
    reason; the folder's earlier results stay and nothing claims success."""
    out = tmp_path / "out"
    run = [exe, "run", os.path.join(root, BLOCK), "--out", out, "-q", "--set", f"{PRESS}=-0.5"]
    r = subprocess.run(run, capture_output=True, text=True, timeout=scaled_timeout(60))
    assert r.returncode == 0, r.stderr
    first = results(out)
    for limit, name in ((100, "path.csv"), (1000, "solution.vtu")):
        r = subprocess.run(run, capture_output=True, text=True, timeout=scaled_timeout(60),
                           preexec_fn=limit_file_size(limit))
        assert r.returncode == 1, (limit, r.stderr)
        assert f"{name}: cannot write the file: File too large" in r.stderr, r.stderr
        assert results(out) == first


def test_second_run_into_a_locked_folder_fails_at_once(hpcontact, exe, root, tmp_path):
    """While a run writes into a folder, a second run into it stops at once with exit 1 and
    says why; the first one is not disturbed."""
    out = tmp_path / "out"
    p = start(exe, "run", os.path.join(root, LONG[0]), "--out", out, *LONG[1:])
    try:
        t0 = time.monotonic()
        r = hpcontact("run", os.path.join(root, LAME), "--out", out, "-q")
        assert time.monotonic() - t0 < 10
        assert r.returncode == 1
        assert "another hpcontact run is writing into this output folder" in r.stderr, r.stderr
        assert not (out / "summary.json").exists()
        assert p.poll() is None
    finally:
        p.kill()
        p.wait()
    # The killed run's lock went with it.
    r = hpcontact("run", os.path.join(root, LAME), "--out", out, "-q")
    assert r.returncode == 0, r.stderr


def children_of(pid):
    """The pids of a process's children (Linux /proc)."""
    kids = []
    for task in os.listdir(f"/proc/{pid}/task"):
        with open(f"/proc/{pid}/task/{task}/children") as f:
            kids += [int(k) for k in f.read().split()]
    return kids


def alive(pid):
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(") ")[1][0] != "Z"
    except FileNotFoundError:
        return False


def start_long_study(exe, root, tmp_path, labels, **popen):
    """Starts a study of long runs (`labels`, two at a time) and waits until two are running;
    returns the study's process, its output folder and the runs' pids."""
    study = tmp_path / "study.yaml"
    study.write_text(f"study: long\ncase: {os.path.join(root, LONG[0])}\n"
                     "set: ['solver.load_steps=400', 'contact[0].enforcement=penalty']\n"
                     "runs:\n" + "".join(f"  - {{label: {x}}}\n" for x in labels))
    out = tmp_path / "out"
    p = subprocess.Popen([exe, "study", study, "--out", out, "-j", "2", "-q"],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **popen)
    deadline = time.monotonic() + scaled_timeout(30)
    while len(children_of(p.pid)) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    runs = children_of(p.pid)
    assert len(runs) == 2, runs
    return p, out, runs


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT, signal.SIGHUP])
def test_study_passes_signals_to_its_runs(exe, root, tmp_path, sig):
    """A study stopped by SIGTERM, SIGINT or SIGHUP (its terminal closed) stops its running runs,
    waits for them, writes no table, leaves no staging folder and ends by that signal."""
    p, out, runs = start_long_study(exe, root, tmp_path, "abc")
    time.sleep(0.3)  # the runs are solving
    p.send_signal(sig)
    _, err = p.communicate(timeout=scaled_timeout(60))
    assert p.returncode == -sig, err
    assert "study stopped by" in err, err
    assert not any(alive(pid) for pid in runs)
    assert not (out / "study.csv").exists() and not (out / "study.json").exists()
    # the logs of the two runs it started, apart from a finished study's; none of the third
    assert f"the runs' logs are in {out}/stopped/runs/" in err, err
    assert sorted(f.parent.name for f in (out / "stopped" / "runs").glob("*/log.txt")) == \
        ["01-a", "02-b"]
    assert not (out / "stopped" / "study.csv").exists()
    assert not list(out.glob(".hpcontact-staging-*"))


def test_runs_of_a_killed_study_stop_and_keep_what_had_converged(exe, root, tmp_path):
    """A study killed outright (SIGKILL: it can pass nothing on) leaves no run computing on its
    own: each run stops as on SIGTERM within seconds, its converged load steps in last-good/,
    and releases its folder."""
    p, out, runs = start_long_study(exe, root, tmp_path, "ab")
    time.sleep(1.5)  # the runs have converged load steps
    p.kill()
    p.communicate(timeout=60)
    deadline = time.monotonic() + 10  # a run alone takes ~15 s; one load step a fraction of one
    while any(alive(pid) for pid in runs) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert not any(alive(pid) for pid in runs), "the runs went on after their study was killed"
    for label in ("01-a", "02-b"):
        assert not (out / "runs" / label / "summary.json").exists()
        kept = json.loads((out / "runs" / label / "last-good" / "summary.json").read_text())
        assert kept["converged"] is False and kept["load_steps"] >= 1
        assert "stopped by SIGTERM" in kept["message"], kept["message"]


def test_ctrl_c_on_a_study_keeps_what_its_runs_had_converged(exe, root, tmp_path):
    """Ctrl-C in a terminal signals the study and its runs (one process group), and the study
    passes the signal on: each run gets SIGINT twice within milliseconds. That is one request —
    each run stops at its next Newton iteration or stop point and keeps its converged load steps in
    last-good/ — not a second one that kills at once (which lost them). Each run's log, which
    says so, is in the study's stopped/runs/."""
    # its own process group, as a terminal's job
    p, out, _ = start_long_study(exe, root, tmp_path, "ab", start_new_session=True)
    time.sleep(1.5)  # the runs have converged load steps
    os.killpg(p.pid, signal.SIGINT)
    _, err = p.communicate(timeout=scaled_timeout(60))
    assert p.returncode == -signal.SIGINT, err
    for label in ("01-a", "02-b"):
        kept = json.loads((out / "runs" / label / "last-good" / "summary.json").read_text())
        assert kept["converged"] is False and kept["load_steps"] >= 1
        assert re.search("stopped by SIGINT (before|in) Newton iteration", kept["message"]), \
            kept["message"]
        assert "stopped by SIGINT" in (out / "stopped" / "runs" / label / "log.txt").read_text()


def test_study_into_a_folder_with_a_users_table_is_refused(hpcontact, root, tmp_path):
    """A study.csv the study did not write refuses the folder and stays."""
    study = tmp_path / "study.yaml"
    study.write_text(f"study: s\ncase: {os.path.join(root, LAME)}\nruns:\n  - {{label: a}}\n")
    out = tmp_path / "out"
    out.mkdir()
    (out / "study.csv").write_text("mine\n")
    r = hpcontact("study", study, "--out", out, "-q")
    assert r.returncode == 1 and "study.csv: hpcontact did not write this file" in r.stderr, r.stderr
    assert (out / "study.csv").read_text() == "mine\n"
    r = hpcontact("study", study, "--out", tmp_path, "-q")
    assert r.returncode == 1 and "holds the study file" in r.stderr, r.stderr


def test_a_run_and_a_study_do_not_share_a_folder(hpcontact, root, tmp_path):
    """A study into a run's output folder, and a run into a study's, was refused as if the
    manifest had been edited, with the advice to remove it and the results it lists; the folder
    holds another command's results, and that is what is said, with nothing removed."""
    study = tmp_path / "study.yaml"
    study.write_text(f"study: s\ncase: {os.path.join(root, LAME)}\nruns:\n  - {{label: a}}\n")
    for first, then, kind in ((["run", os.path.join(root, LAME)], ["study", study], "a study"),
                              (["study", study], ["run", os.path.join(root, LAME)], "a run")):
        out = tmp_path / f"{first[0]}-out"
        r = hpcontact(*first, "--out", out, "-q")
        assert r.returncode == 0, r.stderr
        before = snapshot(out)
        r = hpcontact(*then, "--out", out, "-q")
        assert r.returncode == 1, r.stderr
        assert f"holds results that are not {kind}'s" in r.stderr, r.stderr
        assert "a run and a study cannot share an output folder" in r.stderr
        assert "remove" not in r.stderr
        assert_untouched(out, before)


def test_a_run_killed_by_a_signal_is_a_failed_row_that_says_so(exe, root, tmp_path):
    """A run that dies by a signal (SIGKILL here, as the kernel's out-of-memory killer sends it)
    is a failed row 'killed by signal 9'; the next row runs, the table is written and the study
    exits 1."""
    study = tmp_path / "study.yaml"
    study.write_text("study: killed\nruns:\n"
                     f"  - {{label: killed, case: {os.path.join(root, LONG[0])}, "
                     "set: ['solver.load_steps=400', 'contact[0].enforcement=penalty']}\n"
                     f"  - {{label: next, case: {os.path.join(root, LAME)}}}\n")
    out = tmp_path / "out"
    p = subprocess.Popen([exe, "study", study, "--out", out, "-j", "1"], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while not children_of(p.pid) and time.monotonic() < deadline:
        time.sleep(0.05)
    run = children_of(p.pid)
    assert len(run) == 1, run
    os.kill(run[0], signal.SIGKILL)
    stdout, stderr = p.communicate(timeout=120)
    assert p.returncode == 1, stdout + stderr
    assert "FAILED killed" in stdout and "killed by signal 9" in stdout, stdout
    rows = {r["label"]: r for r in csv.DictReader(open(out / "study.csv"))}
    assert rows["killed"]["converged"] == "false" and rows["killed"]["message"].startswith("killed by signal 9")
    assert rows["next"]["converged"] == "true"
