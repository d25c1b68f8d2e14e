"""Fixtures of the command-line tests: the path of the built hpcontact program, and the
scripts/ modules loaded for tests of their functions; helpers shared by them (a refused run,
a CSV's rows, hp's rules of degrees on a run's output)."""
import csv
import importlib.util
import json
import math
import os
import subprocess
import sys

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.append(os.path.join(ROOT, "tests"))
from timeouts import scaled_timeout  # noqa: E402  (the time limits, also the test files')


def pytest_configure(config):
    config.addinivalue_line("markers", "slow: long, and checking what a faster test also checks: "
                            "a ctest test of its own labelled slow, which `make test` leaves out "
                            "(tests/CMakeLists.txt)")


def pytest_addoption(parser):
    parser.addoption("--hpcontact", default=os.path.join(ROOT, "build", "hpcontact"),
                     help="path of the hpcontact executable")


@pytest.fixture(scope="session")
def hpcontact(request):
    path = request.config.getoption("--hpcontact")
    if not os.path.exists(path):
        pytest.fail(f"hpcontact executable not found at {path}")

    def run(*args, timeout=300):
        """`hpcontact args...`, given `timeout` seconds (on a quiet machine) to finish."""
        return subprocess.run([path, *map(str, args)], capture_output=True, text=True,
                              timeout=scaled_timeout(timeout))

    return run


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def exe(hpcontact, request):
    """The executable's path (the hpcontact fixture fails the test if it is missing)."""
    return request.config.getoption("--hpcontact")


def expect_refused(hpcontact, case, out, settings, message, code):
    """`hpcontact run case --out out -q` with each of `settings` as --set: exit `code`, `message`
    and the case's file name on stderr, and no summary.json in `out`."""
    args = ["run", case, "--out", out, "-q"]
    for s in settings:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == code, r.stderr
    assert message in r.stderr, r.stderr
    assert os.path.basename(case) in r.stderr
    assert not os.path.exists(os.path.join(out, "summary.json"))


def csv_rows(path):
    """A CSV file's rows as dicts (contact.csv, path.csv, ...)."""
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def partial_slip_generator(root, *args):
    """scripts/partial_slip_mesh.py with these arguments (two cylinders, R = 10): the finished
    process, the problem file on its stdout."""
    return subprocess.run([sys.executable, os.path.join(root, "scripts", "partial_slip_mesh.py"), *args],
                          capture_output=True, text=True, timeout=scaled_timeout(60))


def load_script(name):
    """scripts/<name>.py as a module (its functions, without running main)."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(ROOT, "scripts", name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _element_degrees(inp, mesh, body):
    """Every element's degree (the larger of p_xi, p_eta) of one body of mesh.yaml, those without
    an entry of degrees at the body's or discretization's degree of input.yaml."""
    def larger(p):
        return max(p) if isinstance(p, list) else p
    spec = next(b for b in inp["bodies"] if b["name"] == body)
    default = larger(spec.get("degree", inp["discretization"]["degree"]))
    given = mesh[body].get("degrees", {})
    return {e: larger(given[e]) if e in given else default for e in mesh[body]["elements"]}


def _facing(e, f):
    """Whether the contact edge f faces e (each ((x0, y0), (x1, y1))): the part of f whose
    projection falls on e covers more than half of the shorter edge, and f's midpoint lies within
    half the shorter length of e's line (adapt/facing_degrees.hpp)."""
    (ax, ay), (bx, by) = e
    (cx, cy), (dx, dy) = f
    le, lf = math.hypot(bx - ax, by - ay), math.hypot(dx - cx, dy - cy)
    tx, ty = (bx - ax) / le, (by - ay) / le
    s0, s1 = tx * (cx - ax) + ty * (cy - ay), tx * (dx - ax) + ty * (dy - ay)
    overlap = min(le, max(s0, s1)) - max(0.0, min(s0, s1))
    shorter = min(le, lf)
    mx, my = 0.5 * (cx + dx) - ax, 0.5 * (cy + dy) - ay
    return overlap > 0.5 * shorter and abs(tx * my - ty * mx) < 0.5 * shorter


def _contact_edges(mesh, body, sets, degrees):
    """The edges of the named edge sets of one body of mesh.yaml: (its end points, its element's
    degree)."""
    b = mesh[body]
    out = []
    for name in sets:
        for n0, n1 in b["edge_sets"][name]:
            element = next(e for e, nodes in b["elements"].items() if n0 in nodes and n1 in nodes)
            out.append(((tuple(b["nodes"][n0]), tuple(b["nodes"][n1])), degrees[element]))
    return out


def assert_hp_degree_rules(out):
    """hp's rules of degrees on the run in the folder `out` (summary.json, input.yaml, mesh.yaml):
    with degrees set by hp (rising or goal), no element below adapt.min_degree at any recorded
    step after the input's (each step's degree_range) nor on the result's mesh, and on that mesh
    the facing contact edges of two bodies under an exactly enforced pair with friction of equal
    degree (the larger of the two, adapt/facing_degrees.hpp; every step's mesh:
    HpMesh.EveryStepKeepsTheMinimumDegreeAndEqualFacingDegrees). Returns how many facing
    couples there were."""
    import yaml  # Debian's python3-yaml, as the tests that read mesh.yaml
    with open(os.path.join(out, "summary.json")) as f:
        a = json.load(f)["adapt"]
    assert a["method"] == "hp", a["method"]
    if a["degree"] == "constant":
        return 0
    low = a["min_degree"]
    for h in a["history"][1:]:  # step 0 is the input's mesh, with the input's degrees
        assert h["degree_range"][0] >= low, (h["step"], h["degree_range"], low)
    with open(os.path.join(out, "input.yaml")) as f:
        inp = yaml.safe_load(f)
    with open(os.path.join(out, "mesh.yaml")) as f:
        mesh = yaml.safe_load(f)
    degrees = {b: _element_degrees(inp, mesh, b) for b in mesh}
    for b, d in degrees.items():
        if a["result_step"] > 0:
            assert min(d.values()) >= low, (b, sorted(d.items(), key=lambda kv: kv[1])[:3], low)
    couples = 0
    for pair in inp.get("contact", []):
        obstacle = pair["obstacle"]
        if (obstacle["type"] != "body" or pair.get("friction", {}).get("law", "none") == "none"
                or pair["enforcement"] != "augmented-lagrangian"):
            continue
        ours = _contact_edges(mesh, pair["body"], pair["edges"], degrees[pair["body"]])
        theirs = _contact_edges(mesh, obstacle["body"], obstacle["edges"], degrees[obstacle["body"]])
        for e, p in ours:
            for f, q in theirs:
                if _facing(e, f) or _facing(f, e):
                    couples += 1
                    assert p == q, (pair["body"], e, p, obstacle["body"], f, q)
    return couples
