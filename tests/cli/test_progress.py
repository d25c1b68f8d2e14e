"""`hpcontact run`'s progress as a person follows it (docs/output.md): plain lines when piped
(a line per load step and hp step with "k of n" and the elapsed time), a status line redrawn on
a terminal, JSON lines with --log-json, Newton iterations only with -v, nothing with -q."""
import json
import math
import os
import fcntl
import pty
import re
import select
import struct
import subprocess
import termios

import yaml

from timeouts import scaled_timeout

STAGED = "tests/cli/data/block-press-push.yaml"  # two stages of two load steps, a few ms
CUT = "tests/cli/data/crushed-block.yaml"  # step 2 of 2 converges a part of itself, then fails
HP = "examples/hertz/hp-tolerance.yaml"
HP_SETS = ["--set", "adapt.tolerance=1e-3", "--set", "output.vtu=false"]

LOAD_LINE = re.compile(r"^  load step (\d+) of (\d+)( \(a part of it, cut\))?: .* · elapsed \d+:\d\d")


def stage_steps(root, case):
    """The input's load steps of a staged case, from its file: the stages' steps summed."""
    spec = yaml.safe_load(open(os.path.join(root, case)))
    return sum(stage["steps"] for stage in spec["solver"]["stages"])


def summary(out):
    return json.loads((out / "summary.json").read_text())


def events(stdout):
    return [json.loads(line) for line in stdout.splitlines()]


def test_piped_output_has_a_line_per_load_step_counting_to_the_stages_steps(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, STAGED), "--out", tmp_path)
    assert r.returncode == 0, r.stderr
    assert "\r" not in r.stdout
    steps = [LOAD_LINE.match(line) for line in r.stdout.splitlines()]
    steps = [(int(m[1]), int(m[2])) for m in steps if m]
    n = stage_steps(root, STAGED)
    assert n == 4 and steps == [(k, n) for k in range(1, n + 1)], r.stdout
    assert summary(tmp_path)["load_steps"] == n
    # the result is the last line
    assert r.stdout.splitlines()[-1].startswith("  results in "), r.stdout


def test_a_cut_step_keeps_its_number_in_the_lines_and_the_json(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, CUT), "--out", tmp_path / "lines")
    assert r.returncode == 1
    lines = [LOAD_LINE.match(line) for line in r.stdout.splitlines()]
    assert [(m[1], m[2], bool(m[3])) for m in lines if m] == [("1", "2", False), ("2", "2", True)], r.stdout
    r = hpcontact("run", os.path.join(root, CUT), "--out", tmp_path / "json", "--log-json")
    steps = [e for e in events(r.stdout) if e["kind"] == "load_step"]
    assert [(e["step"], e["of"], e["part"]) for e in steps] == [(1, 2, False), (2, 2, True)]
    # a part of step 2 does not count as step 2 done: at the pace of step 1, one step is left
    assert steps[1]["solve_remaining_s"] == \
        steps[1]["solve_elapsed_s"] / 1 * 1
    assert events(r.stdout)[-1]["kind"] == "error"


def test_newton_iterations_only_with_verbose(hpcontact, root, tmp_path):
    case = os.path.join(root, STAGED)
    quiet = hpcontact("run", case, "--out", tmp_path)
    loud = hpcontact("run", case, "--out", tmp_path, "-v")  # the same folder: the same lines
    assert quiet.returncode == 0 and loud.returncode == 0
    is_iteration = re.compile(r"^\s+iteration \d+: \|R\| ")
    assert not any(is_iteration.match(line) for line in quiet.stdout.splitlines()), quiet.stdout
    printed = sum(bool(is_iteration.match(line)) for line in loud.stdout.splitlines())
    assert printed == summary(tmp_path)["newton_iterations"] > 0, loud.stdout
    # -v adds the iteration lines and nothing else
    others = [line for line in loud.stdout.splitlines() if not is_iteration.match(line)]
    strip = lambda lines: [re.sub(r"elapsed \d+:\d\d.*|, [0-9.e-]+ s$", "", line) for line in lines]
    assert strip(others) == strip(quiet.stdout.splitlines())


def test_log_json_carries_the_steps_and_a_monotone_time(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, STAGED), "--out", tmp_path, "--log-json")
    assert r.returncode == 0, r.stderr
    ev = events(r.stdout)
    n = stage_steps(root, STAGED)
    steps = [e for e in ev if e["kind"] == "load_step"]
    assert [(e["step"], e["of"], e["part"]) for e in steps] == [(k, n, False) for k in range(1, n + 1)]
    times = [e["time_s"] for e in ev]
    assert times == sorted(times)
    solve_times = [e["solve_elapsed_s"] for e in steps]
    assert solve_times == sorted(solve_times)
    # the last step leaves nothing of the solve; before it, the pace of the steps done
    assert steps[-1]["solve_remaining_s"] == 0
    for e in steps:
        assert math.isclose(e["solve_remaining_s"], e["solve_elapsed_s"] / e["step"] * (n - e["step"]))
    # the Newton iterations are always in the JSON (without -v), each once
    s = summary(tmp_path)
    assert sum(e["kind"] == "iteration" for e in ev) == s["newton_iterations"]
    assert sum(e["newton_iterations"] for e in steps) == s["newton_iterations"]
    written = [e["path"] for e in ev if e["kind"] == "file_written"]
    assert "summary.json" in written and all((tmp_path / p).exists() for p in written)
    assert ev[0]["kind"] == "start" and ev[-1]["kind"] == "done"


def test_log_json_hp_steps_are_summary_history(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, HP), "--out", tmp_path, "--log-json", *HP_SETS)
    assert r.returncode == 0, r.stderr
    adapt = summary(tmp_path)["adapt"]
    steps = [e for e in events(r.stdout) if e["kind"] == "adapt_step"]
    assert len(steps) == len(adapt["history"]) >= 3
    for e, h in zip(steps, adapt["history"]):
        est = h["estimated_error"]
        traction = max(est["pressure_rel_L2"], est.get("shear_rel_L2") or -math.inf)
        assert (e["method"], e["step"], e["max_steps"], e["dofs"], e["tolerance"]) == \
            ("hp", h["step"], adapt["steps"], h["dofs"], adapt["tolerance"])
        assert math.isclose(e["estimate"], traction, rel_tol=1e-12)
    assert steps[-1]["estimate"] <= adapt["tolerance"] < steps[-2]["estimate"]


def test_piped_hp_lines_say_the_step_of_at_most_n(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, HP), "--out", tmp_path, *HP_SETS)
    assert r.returncode == 0, r.stderr
    adapt = summary(tmp_path)["adapt"]
    found = re.findall(r"^  hp step (\d+) of at most (\d+): estimated error .* · elapsed \d+:\d\d$",
                       r.stdout, re.M)
    assert found == [(str(h["step"]), str(adapt["steps"])) for h in adapt["history"]], r.stdout


def run_on_a_terminal(exe, *args, columns=0):
    """Runs hpcontact with its stdout a pseudo-terminal (`columns` wide, 0: not said); returns
    (exit status, what it wrote)."""
    leader, follower = pty.openpty()
    fcntl.ioctl(follower, termios.TIOCSWINSZ, struct.pack("HHHH", 24, columns, 0, 0))
    p = subprocess.Popen([exe, *map(str, args)], stdout=follower, stderr=subprocess.PIPE)
    os.close(follower)
    written = b""
    while True:
        ready, _, _ = select.select([leader], [], [], scaled_timeout(120))
        if not ready:
            p.kill()
            break
        try:
            chunk = os.read(leader, 65536)
        except OSError:  # the follower closed: the run has ended
            break
        if not chunk:
            break
        written += chunk
    p.wait(timeout=scaled_timeout(60))
    os.close(leader)
    return p.returncode, written.decode("utf-8").replace("\r\n", "\n")  # the tty's ONLCR


def test_terminal_redraws_one_status_line_and_ends_with_the_result(exe, root, tmp_path):
    code, text = run_on_a_terminal(exe, "run", os.path.join(root, STAGED), "--out", tmp_path)
    assert code == 0, text
    assert "\r\x1b[K" in text and text.endswith("\n")
    last = text.rstrip("\n").split("\n")[-1]
    assert last.startswith("  results in ") and "\r" not in last, repr(text)
    n = stage_steps(root, STAGED)
    assert f"load step {n} of {n} [##########] · " in text and "remaining ~0:00" in text, repr(text)
    # cut to the 80 columns a terminal that says none has
    statuses = re.findall(r"\x1b\[K([^\r\n]+)(?=\r)", text)
    assert statuses and all(len(s) <= 79 for s in statuses), statuses
    # a load step is a status, not a line of its own; no iteration lines without -v
    lines = [line.split("\r")[-1] for line in text.split("\n")]
    assert not any(line.lstrip().startswith(("load step", "iteration")) for line in lines), repr(text)


def test_terminal_hp_status_says_the_step_the_estimate_and_no_made_up_time(exe, root, tmp_path):
    code, text = run_on_a_terminal(exe, "run", os.path.join(root, HP), "--out", tmp_path, *HP_SETS,
                                   columns=200)
    assert code == 0, text
    adapt = summary(tmp_path)["adapt"]
    statuses = re.findall(r"\x1b\[K([^\r\n]+)(?=\r)", text)  # drawn, then cleared: not a line
    assert any(s.startswith(f"hp step 1 of at most {adapt['steps']} · load step 1 of 1 [##########] · ")
               for s in statuses), repr(text)
    assert all("remaining unknown" in s and "remaining ~" not in s for s in statuses), statuses
    assert any("estimate " in s and "(tolerance 0.001)" in s for s in statuses), statuses
    assert text.rstrip("\n").split("\n")[-1].startswith("  results in ")


def test_quiet_prints_nothing_on_success(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, "examples/hertz/p5.yaml"), "--out", tmp_path, "-q")
    assert r.returncode == 0 and r.stdout == "" and r.stderr == "", (r.stdout, r.stderr)


ROLLER = "examples/roller-block/friction/roller-block-friction.yaml"  # exact contact, Coulomb


def iterations_by_step(ev):
    """The iteration events of each converged load step, in order."""
    steps, current = [], []
    for e in ev:
        if e["kind"] == "iteration":
            current.append(e)
        elif e["kind"] == "load_step":
            steps.append(current)
            current = []
    return steps


def test_log_json_iterations_say_the_step_taken_and_the_states_changed(hpcontact, root, tmp_path):
    # The roller under force control with friction (the line search on, the factor's change
    # capped): each iteration says the fraction of the Newton correction it took and how many
    # multiplier states changed at its tangent. Newton converges only with the active set of its
    # last two tangents equal: here each step's last correction is taken whole, its tangent (the
    # one reported) the one that convergence compared, so the last iteration of each changed none.
    r = hpcontact("run", os.path.join(root, ROLLER), "--out", tmp_path, "--log-json",
                  "--set", "adapt.method=none", "--set", "output.vtu=false")
    assert r.returncode == 0, r.stderr
    ev = events(r.stdout)
    steps = iterations_by_step(ev)
    assert len(steps) == summary(tmp_path)["load_steps"] == 2
    its = [e for s in steps for e in s]
    assert all(0 < e["step"] <= 1 and e["states_changed"] >= 0 for e in its), its
    assert all(s[-1]["states_changed"] == 0 for s in steps)
    # the text says a shortened step, and only then
    assert any(e["step"] < 1 for e in its)
    assert all(("of the correction" in e["message"]) == (e["step"] < 1) for e in its)


def test_log_json_without_line_search_takes_every_correction_whole(hpcontact, root, tmp_path):
    # The staged block (exact contact with friction, no force control) with solver.line_search
    # off: nothing shortens a correction.
    r = hpcontact("run", os.path.join(root, STAGED), "--out", tmp_path, "--log-json",
                  "--set", "solver.line_search=off")
    assert r.returncode == 0, r.stderr
    its = [e for e in events(r.stdout) if e["kind"] == "iteration"]
    assert its and all(e["step"] == 1 and "of the correction" not in e["message"] for e in its)
    assert all(e["states_changed"] >= 0 for e in its)
