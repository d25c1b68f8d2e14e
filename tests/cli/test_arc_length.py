"""The cylindrical arc-length method (solver.control: arc-length) on a snap-through: a clamped
shallow arch under a dead load (tests/cli/data/shallow-arch.yaml, Neo-Hooke)."""
import csv
import json
import os

import pytest

ARCH = os.path.join("tests", "cli", "data", "shallow-arch.yaml")


def path_of(out):
    with open(os.path.join(out, "path.csv")) as f:
        rows = list(csv.DictReader(f))
    return [float(r["load_factor"]) for r in rows], [float(r["monitor_uy"]) for r in rows]


@pytest.fixture(scope="module")
def runs(hpcontact, root, tmp_path_factory):
    out = {}
    for control in ("load", "arc-length"):
        d = tmp_path_factory.mktemp(control)
        r = hpcontact("run", os.path.join(root, ARCH), "--out", d, "-q", "--set", f"solver.control={control}")
        assert r.returncode == 0, r.stderr
        out[control] = d
    return out


def test_arc_length_passes_the_limit_point(runs):
    """Along the arc-length path the load factor rises to a maximum (the limit point, measured
    0.570), falls (to 0.494) while the apex keeps moving down, and rises again to 1; the apex
    displacement never jumps (each step below 0.06, a tenth of the total)."""
    lam, uy = path_of(runs["arc-length"])
    peak = next(i for i in range(len(lam) - 1) if lam[i + 1] < lam[i])  # first local maximum
    assert 0.3 < lam[peak] < 0.9
    assert min(lam[peak:]) < lam[peak] - 0.03  # the load falls after the limit point
    assert lam[-1] == 1.0
    assert all(b < a for a, b in zip(uy, uy[1:]))  # the apex goes down monotonically
    assert max(a - b for a, b in zip(uy, uy[1:])) < 0.06


def test_load_control_jumps_where_arc_length_follows(runs):
    """Load control reaches the same final state by a jump: one step moves the apex by more
    than half of the whole displacement (measured 0.34 of 0.58); both end at the same apex
    displacement and strain energy (1e-8)."""
    lam, uy = path_of(runs["load"])
    jumps = [a - b for a, b in zip(uy, uy[1:])]
    assert max(jumps) > 0.5 * abs(uy[-1])
    _, uy_arc = path_of(runs["arc-length"])
    assert abs(uy[-1] - uy_arc[-1]) < 1e-8 * abs(uy[-1])
    energies = [json.load(open(os.path.join(runs[c], "summary.json")))["strain_energy"] for c in runs]
    assert abs(energies[0] / energies[1] - 1) < 1e-8


def test_arc_length_that_cannot_continue(hpcontact, root, tmp_path):
    """With one corrector iteration allowed no step converges: the step length is halved down
    to its minimum and the run stops with a message naming the load factor it stopped at
    (nothing converged, so nothing is kept and no summary.json is written)."""
    r = hpcontact("run", os.path.join(root, ARCH), "--out", tmp_path, "-q",
                  "--set", "solver.control=arc-length", "--set", "solver.max_iterations=1")
    assert r.returncode == 1
    assert "the arc-length method cannot continue from load factor 0" in r.stderr, r.stderr
    assert "shallow-arch.yaml" in r.stderr
    assert not os.path.exists(tmp_path / "summary.json")
    assert not os.path.exists(tmp_path / "last-good")


def test_arc_length_that_stalls_keeps_its_last_step(hpcontact, root, tmp_path):
    """With two corrector iterations the steps shrink at the limit point until the step budget
    (500) is spent below load factor 1: exit 1, the message says so, and the last converged step
    is in last-good/ with converged: false and its load factor (measured 0.5595, below the
    limit point 0.570)."""
    r = hpcontact("run", os.path.join(root, ARCH), "--out", tmp_path, "-q",
                  "--set", "solver.control=arc-length", "--set", "solver.max_iterations=2")
    assert r.returncode == 1
    assert "did not reach 1.000000 in 500 arc-length steps" in r.stderr, r.stderr
    assert not os.path.exists(tmp_path / "summary.json")
    kept = json.load(open(tmp_path / "last-good" / "summary.json"))
    assert kept["converged"] is False
    assert 0.3 < kept["loads_factor"] < 1
    lam, _ = path_of(tmp_path / "last-good")
    assert not os.path.exists(tmp_path / "path.csv")
    assert abs(lam[-1] - kept["loads_factor"]) < 1e-9


def test_arc_length_without_loads_is_refused(hpcontact, root, tmp_path):
    r = hpcontact("run", os.path.join(root, ARCH), "--out", tmp_path, "-q",
                  "--set", "solver.control=arc-length", "--set", "bodies[0].loads[0].traction=[0, 0]")
    assert r.returncode == 1
    assert "arc-length scales the loads, and there are none" in r.stderr, r.stderr
