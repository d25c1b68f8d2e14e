"""A run asked to stop (SIGTERM from a scheduler's time limit, SIGINT from Ctrl-C) keeps what had
converged instead of being killed with nothing: the solve stops before its next Newton
iteration, or within a moment inside one (its assembly or factorisation given up), the run ends
as a failed run (the converged state in last-good/, converged: false, no summary.json of its own
in the folder, the earlier results left as they were), and the process ends by the signal it was
sent."""
import json
import os
import re
import signal
import subprocess
import time

import pytest

from conftest import scaled_timeout

PARTIAL_SLIP = os.path.join("examples", "partial-slip")


def run_until(exe, case, out, marker, sig, *sets, again=None):
    """Runs `case` into `out`, sends `sig` when a progress line starts with `marker` (and once
    more `again` seconds later, if given); returns (exit status, stderr, the progress lines up to
    the marker)."""
    args = [exe, "run", case, "--out", str(out)]
    for s in sets:
        args += ["--set", s]
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    seen = []
    for line in p.stdout:
        seen.append(line)
        if line.strip().startswith(marker):
            p.send_signal(sig)
            if again is not None:
                time.sleep(again)
                p.send_signal(sig)
            break
    _, err = p.communicate(timeout=scaled_timeout(120))
    assert seen and seen[-1].strip().startswith(marker), "the marker line never came: " + err
    return p.returncode, err, seen


def last_good(out):
    return json.loads((out / "last-good" / "summary.json").read_text())


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_a_stopped_load_path_keeps_its_converged_steps(exe, root, tmp_path, sig):
    """small-load.yaml (three load steps) stopped after its first: the process ends by the
    signal, last-good/ holds the first step (load_steps 1, converged false), and the message
    names the signal and the load step it stopped in."""
    out = tmp_path / "r"
    code, err, _ = run_until(exe, os.path.join(root, PARTIAL_SLIP, "small-load.yaml"), out,
                             "load step 1 of", sig)
    assert code == -sig
    name = signal.Signals(sig).name
    assert re.search(f"stopped by {name} (before|in) Newton iteration", err) and "load step 2" in err
    assert not (out / "summary.json").exists()
    s = last_good(out)
    assert s["converged"] is False and s["load_steps"] == 1


def test_the_same_signal_twice_at_once_is_one_stop(exe, root, tmp_path):
    """`timeout` sends its SIGTERM to the run and then to the run's process group, so the run
    gets it twice within milliseconds: one request to stop, not a second that kills at once
    (which left nothing). Sent twice 20 ms apart, the run still keeps its first load step."""
    out = tmp_path / "r"
    code, err, _ = run_until(exe, os.path.join(root, PARTIAL_SLIP, "small-load.yaml"), out,
                             "load step 1 of", signal.SIGTERM, again=0.02)
    assert code == -signal.SIGTERM
    assert re.search("stopped by SIGTERM (before|in) Newton iteration", err), err
    assert last_good(out)["load_steps"] == 1


def test_a_stopped_hp_loop_keeps_its_best_step(exe, root, tmp_path):
    """hp to 1e-4 on the partial-slip example, stopped once its first steps are estimated: the
    best estimated step so far is kept in last-good/ with the loop's history up to it, and the
    earlier results in the folder (a finished run of the same problem to 1e-2) stay."""
    case = os.path.join(root, PARTIAL_SLIP, "hp-tolerance.yaml")
    out = tmp_path / "r"
    done = subprocess.run([exe, "run", case, "--out", str(out), "-q", "--set", "adapt.tolerance=2e-2"],
                          capture_output=True, text=True, timeout=scaled_timeout(300))
    assert done.returncode == 0, done.stderr
    before = (out / "summary.json").read_text()
    code, err, seen = run_until(exe, case, out, "hp step 1 of at most", signal.SIGTERM,
                                "adapt.tolerance=1e-4")
    assert code == -signal.SIGTERM
    assert "stopped by SIGTERM" in err and "last-good" in err
    assert (out / "summary.json").read_text() == before
    s = last_good(out)
    a = s["adapt"]
    assert s["converged"] is False and not a["converged"]
    assert "stopped by SIGTERM" in a["message"]
    # kept: the step whose estimate was the smallest among those estimated
    estimated = [h for h in a["history"] if "estimated_error" in h]
    assert len(estimated) >= 2
    best = min(estimated, key=lambda h: max(h["estimated_error"]["pressure_rel_L2"],
                                            h["estimated_error"]["shear_rel_L2"]))
    assert a["result_step"] == best["step"] and s["dofs"] == best["dofs"]


def test_a_run_whose_study_died_before_it_started_stops(exe, root, tmp_path):
    """A study's run is started with --parent-pid (the study): if that process is no longer its
    parent when the run starts (the study was killed between starting it and the run's asking to
    be told of its death), the run stops at once as on SIGTERM, writing nothing."""
    out = tmp_path / "r"
    p = subprocess.run([exe, "run", os.path.join(root, PARTIAL_SLIP, "small-load.yaml"), "--out",
                        str(out), "--parent-pid", str(os.getpid() + 1_000_000)],
                       capture_output=True, text=True, timeout=120)
    assert p.returncode == -signal.SIGTERM, p.stderr
    assert "the solver stopped: stopped by SIGTERM" in p.stderr, p.stderr
    assert not (out / "summary.json").exists() and not (out / "last-good").exists()


def test_a_stop_inside_a_long_newton_iteration_takes_effect_at_once(exe, root, tmp_path):
    """A finite-strain block at p = 30 with 44 extra Gauss points a direction: each Newton
    iteration assembles one element's tangent for seconds (2.5 s on a busy machine; at p = 20
    the first elasticity tensor's products take 0.45 s, below the test's floor of 1 s). SIGTERM a third of the way into the
    first iteration of load step 2 ends the run well within that iteration's time (it waited for
    the whole iteration), as stopped: load step 1 in last-good/, the message naming the
    iteration given up."""
    out = tmp_path / "r"
    args = [exe, "run", os.path.join(root, "tests", "cli", "data", "crushed-block.yaml"), "--out",
            str(out), "--log-json", "--set", "bodies[0].constraints[1].uy=-1e-3", "--set",
            "discretization.degree=30", "--set", "discretization.quadrature_extra=44", "--set",
            "solver.load_steps=3", "--set", "output.vtu=false"]
    p = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    events = []
    for line in p.stdout:
        events.append(json.loads(line))
        if events[-1]["kind"] == "load_step":
            break
    assert events[-1]["kind"] == "load_step", p.communicate(timeout=120)[1]
    # the last iteration of step 1 evaluated the converged state: an assembly, no factorisation
    assembly = events[-1]["time_s"] - [e for e in events if e["kind"] == "iteration"][-1]["time_s"]
    assert assembly > 1.0, f"an assembly of {assembly} s is too short to be caught inside"
    time.sleep(0.3 * assembly)
    sent = time.monotonic()
    p.send_signal(signal.SIGTERM)
    _, err = p.communicate(timeout=300)
    took = time.monotonic() - sent
    assert p.returncode == -signal.SIGTERM, err
    assert took < 0.5 * assembly, f"ended {took:.2f} s after SIGTERM (an assembly: {assembly:.2f} s)"
    assert "load step 2" in err and "stopped by SIGTERM in Newton iteration 0 (while assembling)" in err, err
    kept = last_good(out)
    assert kept["converged"] is False and kept["load_steps"] == 1
