"""End-to-end runs of the hpcontact program: results written, bad input refused clearly."""
import csv
import json
import os
import subprocess
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from conftest import scaled_timeout

LAME = "examples/lame/thick-cylinder.yaml"


def test_lame_run_writes_summary_vtu_and_input(hpcontact, root, tmp_path):
    """A run of the Lamé example leaves summary.json (the keys of docs/tutorial.md §8), a VTU and input.yaml."""
    out = tmp_path / "lame"
    r = hpcontact("run", os.path.join(root, LAME), "--out", out)
    assert r.returncode == 0, r.stderr
    s = json.loads((out / "summary.json").read_text())
    for key in ("case", "method", "dofs", "strain_energy", "newton_iterations", "load_steps",
                "converged", "wall_time_s"):
        assert key in s
    assert s["converged"] is True and s["method"] == "p"
    assert s["error"]["energy_rel_percent"] <= 0.01
    tree = ET.parse(out / "solution.vtu")
    names = {a.get("Name") for a in tree.iter("DataArray")}
    assert {"displacement", "von_mises", "sigma_xx", "sigma_zz", "principal_1"} <= names
    # the effective input reproduces the run
    r2 = hpcontact("run", out / "input.yaml", "--out", tmp_path / "again", "-q")
    assert r2.returncode == 0, r2.stderr
    s2 = json.loads((tmp_path / "again" / "summary.json").read_text())
    assert s2["strain_energy"] == s["strain_energy"]


def test_set_override_changes_degree(hpcontact, root, tmp_path):
    """--set discretization.degree=3 runs the example at p = 3 (fewer dofs, larger error)."""
    r = hpcontact("run", os.path.join(root, LAME), "--out", tmp_path, "-q",
                  "--set", "discretization.degree=3")
    assert r.returncode == 0, r.stderr
    s = json.loads((tmp_path / "summary.json").read_text())
    # 6 nodes, 7 edges (2 modes each at p = 3), 2 × 4 internal modes; 4 modes fixed per component
    assert s["dofs"] == 2 * (6 + 7 * 2 + 2 * 4) - 2 * 4
    assert s["error"]["energy_rel_percent"] > 0.01


def test_check_describes_without_solving(hpcontact, root, tmp_path):
    """check prints bodies, elements, degrees and free dofs, and writes nothing."""
    r = hpcontact("check", os.path.join(root, LAME))
    assert r.returncode == 0, r.stderr
    assert "2 elements" in r.stdout and "free dofs 288" in r.stdout


BAD_INPUTS = {
    "empty.yaml": ("", "empty"),
    "truncated.yaml": ("case: x\nbodies:\n  - name: a\n    material: {E: 1", "truncated"),
    "garbage.yaml": ("\x00\x01\x02\xff\xfe binary", None),
    "wrong-type.yaml": (None, "material.E"),
    "negative-E.yaml": (None, "material.E"),
    "nu-half.yaml": (None, "material.nu"),
    "inverted.yaml": (None, "element 1"),
    "unknown-key.yaml": (None, "colour"),
    "missing-edge.yaml": (None, "edge_sets"),
    "unconstrained.yaml": (None, "not held against rigid-body motion"),
}


def lame_text(root):
    with open(os.path.join(root, LAME)) as f:
        return f.read()


def damaged(root, name):
    text, _ = BAD_INPUTS[name]
    if text is not None:
        return text
    t = lame_text(root)
    if name == "wrong-type.yaml":
        return t.replace("E: 200000", "E: stiff")
    if name == "negative-E.yaml":
        return t.replace("E: 200000", "E: -200000")
    if name == "nu-half.yaml":
        return t.replace("nu: 0.3", "nu: 0.5")
    if name == "inverted.yaml":
        return t.replace("1: [1, 2, 4, 3]", "1: [1, 3, 4, 2]")
    if name == "unknown-key.yaml":
        return t.replace("method: p", "method: p\n  colour: red")
    if name == "unconstrained.yaml":  # the x symmetry constraint dropped: free in x
        return "\n".join(line for line in t.splitlines() if "edges: [left]" not in line)
    if name == "missing-edge.yaml":
        return t.replace("bottom: [[1, 2]]", "bottom: [[1, 4]]")
    raise KeyError(name)


@pytest.mark.parametrize("name", sorted(BAD_INPUTS))
def test_bad_input_fails_cleanly(hpcontact, root, tmp_path, name):
    """Damaged input ends with exit code 1, one message naming the file, no crash, no summary."""
    path = tmp_path / name
    path.write_bytes(damaged(root, name).encode("utf-8", "surrogateescape")
                     if isinstance(damaged(root, name), str) else damaged(root, name))
    out = tmp_path / "out"
    r = hpcontact("run", path, "--out", out, "-q")
    assert r.returncode == 1, (r.returncode, r.stdout, r.stderr)  # a signal would be negative
    assert name in r.stderr, r.stderr
    _, fragment = BAD_INPUTS[name]
    if fragment and fragment not in ("empty", "truncated"):
        assert fragment in r.stderr, r.stderr
    assert not (out / "summary.json").exists()


def test_cli_mistakes_exit_2(hpcontact, root, tmp_path):
    """Unknown sub-command or missing file: one-line message and the usage, exit code 2."""
    for args in (["frobnicate"], ["run", tmp_path / "nope.yaml"], ["run"]):
        r = hpcontact(*args)
        assert r.returncode == 2, (args, r.stderr)
        assert "hpcontact" in r.stderr and "Usage" in r.stderr


@pytest.mark.parametrize("override,fragment", [
    ("discretization.colour=3", "discretization.colour"),     # no such key
    ("bodies[3].material.E=1", "bodies[3]"),                  # no such list element
    ("bodies[0].material.E=stiff", "bodies[0].material.E"),   # wrong type
    ("bodies[0].material.nu=0.7", "bodies[0].material.nu"),   # out of range
    ("discretization.degree", "key.path=value"),              # malformed
])
def test_bad_set_override_is_a_command_line_error(hpcontact, root, tmp_path, override, fragment):
    """A --set with a key that does not exist or a bad value is a mistake on the command line:
    one line naming it, the usage, exit code 2, and no summary."""
    r = hpcontact("run", os.path.join(root, LAME), "--out", tmp_path, "--set", override)
    assert r.returncode == 2, r.stderr
    assert fragment in r.stderr.splitlines()[0] and "Usage" in r.stderr
    assert not (tmp_path / "summary.json").exists()


def test_docs_input_md_is_current(hpcontact, root):
    """docs/input.md is exactly what `hpcontact --help-input` prints (regenerate it if not)."""
    r = hpcontact("--help-input")
    assert r.returncode == 0
    with open(os.path.join(root, "docs", "input.md")) as f:
        assert f.read() == r.stdout, "docs/input.md is stale: run build/hpcontact --help-input > docs/input.md"


def test_hertz_run_writes_contact_curve(hpcontact, root, tmp_path):
    """The Hertz p8 example converges to F/2 and writes the interface curve contact.csv."""
    r = hpcontact("run", os.path.join(root, "examples/hertz/p8.yaml"), "--out", tmp_path, "-q")
    assert r.returncode == 0, r.stderr
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["converged"] and s["dofs"] == 544
    assert abs(s["contact"]["resultant"][1] - 35000) < 35
    lines = (tmp_path / "contact.csv").read_text().splitlines()
    assert lines[0] == ("pair,X,Y,x,y,gap,pressure,pressure_from_stress,tangential_gap,"
                        "tangential_traction,slip,state,body,s,traction,minus_sigma_nn,"
                        "tangent_x,tangent_y,shear_from_stress")
    assert {line.split(",")[11] for line in lines[1:]} <= {"open", "contact"}  # frictionless
    # a row per multiplier node: 8 + 1 Gauss-Lobatto points on each of the 2 contact edges,
    # their shared vertex once (exact enforcement against a rigid plane: collocation)
    assert len(lines) == 1 + 2 * 8 + 1
    # the comparison with the closed forms: its keys, and its curves on [0, 1.5 b_Hertz]
    for key in ("e_L2_hertz_percent", "e_L2_shtayerman_percent", "e_seed_hertz_percent",
                "e_seed_shtayerman_percent", "hertz_half_width", "shtayerman_half_width"):
        assert key in s["contact"], key
    assert abs(s["contact"]["hertz_half_width"] - 1.96524) < 1e-5
    curve = (tmp_path / "pressure.csv").read_text().splitlines()
    assert curve[0] == ("x,pressure_from_stress,pressure_multiplier,hertz,shtayerman,pressure,"
                        "minus_sigma_nn")
    # 1001 uniform samples, plus each end of the contact zone (the kink a reference must keep)
    ends = [g for g in s["contact"]["gamma_star"] if 0 < g[0] < 1.5 * 1.96524]
    assert len(curve) == 1002 + len(ends)
    assert all(f"{g[0]:.12g}" in "\n".join(curve) for g in ends)


def test_newton_failure_is_reported_not_summarised(hpcontact, root, tmp_path):
    """A Newton run that cannot converge cuts the step, then stops: exit 1, a message naming
    the load step and the residual history, and no summary.json."""
    r = hpcontact("run", os.path.join(root, "examples/hertz/p5.yaml"), "--out", tmp_path, "-q",
                  "--set", "solver.max_iterations=1", "--set", "solver.max_cuts=2")
    assert r.returncode == 1, r.stderr
    assert "load step" in r.stderr and "residual history" in r.stderr and "2 cuts" in r.stderr
    assert not (tmp_path / "summary.json").exists()


def test_body_held_only_by_frictionless_contact_is_named(hpcontact, root, tmp_path):
    """The Hertz cylinder without its symmetry constraint slides freely along the frictionless
    plane: the tangent is singular (a round-off pivot, not an exact zero), and the message names
    the body and the motion only contact would have to stop."""
    with open(os.path.join(root, "examples/hertz/p5.yaml")) as f:
        text = f.read()
    text = text.replace("      - {edges: [symmetry], ux: 0}\n", "")
    text = text.replace(", reference: reference-pressure.csv", "")
    case = tmp_path / "sliding.yaml"
    case.write_text(text)
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q", "--set", "solver.max_cuts=1")
    assert r.returncode == 1, r.stderr
    assert "sliding.yaml" in r.stderr and "singular" in r.stderr, r.stderr
    assert "body 'cylinder' is held only by contact against translation in x" in r.stderr, r.stderr
    assert not (tmp_path / "out" / "summary.json").exists()


def test_pressure_plot(hpcontact, root, tmp_path):
    """scripts/plot_pressure.py turns a Hertz run into a non-trivial PNG."""
    import subprocess
    r = hpcontact("run", os.path.join(root, "examples/hertz/p5.yaml"), "--out", tmp_path, "-q")
    assert r.returncode == 0, r.stderr
    p = subprocess.run(["/usr/bin/python3", os.path.join(root, "scripts", "plot_pressure.py"),
                        str(tmp_path)], capture_output=True, text=True, timeout=scaled_timeout(120))
    assert p.returncode == 0, p.stderr
    png = (tmp_path / "pressure.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 20000


def test_log_json_is_one_event_per_line(hpcontact, root, tmp_path):
    """--log-json: every stdout line is a JSON object; a contact run reports its Newton
    iterations and load steps, and ends with done (or error, for a failed run)."""
    import json
    case = os.path.join(root, "examples/hertz/p5.yaml")
    r = hpcontact("run", case, "--out", tmp_path, "--log-json")
    assert r.returncode == 0, r.stderr
    events = [json.loads(line) for line in r.stdout.splitlines()]
    kinds = [e["kind"] for e in events]
    assert kinds[0] == "start" and kinds[-1] == "done"
    assert "iteration" in kinds and "load_step" in kinds
    assert events[-1]["converged"] is True and events[-1]["dofs"] == 220
    times = [e["time_s"] for e in events]
    assert times == sorted(times)
    r = hpcontact("run", case, "--out", tmp_path / "bad", "--log-json",
                  "--set", "solver.max_iterations=1", "--set", "solver.max_cuts=0")
    assert r.returncode == 1
    last = json.loads(r.stdout.splitlines()[-1])
    assert last["kind"] == "error" and "p5.yaml" in last["message"]


def test_log_json_stays_json_with_a_path_that_is_not_utf8(exe, root, tmp_path):
    """A problem file or output folder whose name is bytes that are not UTF-8 (Latin-1) ended
    --log-json in 'internal error: [json.exception...]'; such a byte is U+FFFD in the events,
    every line is JSON (UTF-8), and the run succeeds."""
    import shutil
    case = os.fsencode(tmp_path) + b"/caf\xe9.yaml"
    shutil.copy(os.path.join(root, "examples/lame/thick-cylinder.yaml"), case)
    out = os.fsencode(tmp_path) + b"/r\xe9sultats"
    r = subprocess.run([exe, "run", case, "--out", out, "--log-json"], capture_output=True,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    events = [json.loads(line) for line in r.stdout.decode("utf-8").splitlines()]
    assert events[0]["kind"] == "start" and events[0]["file"].endswith("caf\ufffd.yaml")
    assert events[-1]["kind"] == "done" and os.path.exists(out + b"/summary.json")


@pytest.mark.parametrize("case", ["examples/hertz/p5.yaml", "examples/axle-ring/ring2-p4.yaml",
                                  "examples/two-bars/coulomb.yaml"])
def test_same_input_gives_bit_identical_results(hpcontact, root, tmp_path, case):
    """Deterministic: two runs of one input write the same summary numbers (all but the wall
    time) and the same contact.csv, byte for byte (assembly runs on several threads)."""
    import json
    outs = [tmp_path / "a", tmp_path / "b"]
    for out in outs:
        r = hpcontact("run", os.path.join(root, case), "--out", out, "-q")
        assert r.returncode == 0, r.stderr
    summaries = []
    for out in outs:
        with open(out / "summary.json") as f:
            s = json.load(f)
        s.pop("wall_time_s")
        summaries.append(json.dumps(s, sort_keys=True))
    assert summaries[0] == summaries[1]
    assert (outs[0] / "contact.csv").read_bytes() == (outs[1] / "contact.csv").read_bytes()


def test_check_builds_the_contact_pairs(hpcontact, root, tmp_path):
    """check describes each contact pair, and refuses one a run would refuse (here a plane whose
    normal points away from the body), without solving."""
    case = os.path.join(root, "examples/hertz/p5.yaml")
    r = hpcontact("check", case)
    assert r.returncode == 0, r.stderr
    assert ("contact[0]: body 'cylinder', 2 edges, 100 Gauss points, against plane(point=(0,0), "
            "normal=(0,1)), exact: 11 multiplier nodes, collocation") in r.stdout, r.stdout
    assert "contact[0].compare: E* 230769, R* 10 (R1 10, R2 inf), F 70000" in r.stdout
    r = hpcontact("check", case, "--set", "contact[0].enforcement=penalty")
    assert "normal=(0,1)), penalty 2.1e+08" in r.stdout, r.stdout
    with open(case) as f:
        text = f.read().replace("normal: [0, 1]", "normal: [0, -1]")
    bad = tmp_path / "wrong-normal.yaml"
    bad.write_text(text)
    r = hpcontact("check", bad)
    assert r.returncode == 1
    assert "wrong-normal.yaml" in r.stderr and "contact[0].obstacle" in r.stderr


def test_help_on_every_sub_command_and_version(hpcontact):
    """--help of the program and of each sub-command names its options; --version the version."""
    r = hpcontact("--help")
    assert r.returncode == 0 and all(c in r.stdout for c in ("run", "check", "study"))
    for sub, options in (("run", ["--out", "--set", "--quiet", "--log-json"]),
                         ("check", ["--set"]), ("study", ["--out", "--jobs", "--quiet"])):
        r = hpcontact(sub, "--help")
        assert r.returncode == 0, (sub, r.stderr)
        assert all(o in r.stdout for o in options), (sub, r.stdout)
    r = hpcontact("--version")
    assert r.returncode == 0 and r.stdout.startswith("hpcontact ")


def test_pressure_is_force_per_unit_length_along_the_obstacle(hpcontact, root, tmp_path):
    """contact.csv's pressure is the contact force per unit length along the obstacle: on the
    Hertz cylinder (p = 8, exact contact, force control to F/2 = 35000) it is the multiplier
    times dS/dx = 1/cos θ, and its integral over x, ∫ λ_h (dS/dx) dx = ∫ λ_h R dθ with λ_h the
    degree-8 polynomial through each edge's nodes (Gauss–Legendre in θ, exact), is the applied
    force within 1e-6; summary.json says what its pressure figures are measured as."""
    r = hpcontact("run", os.path.join(root, "examples/hertz/p8.yaml"), "--out", tmp_path, "-q")
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "contact.csv") as f:
        rows = list(csv.DictReader(f))
    # the nodes of each edge: 9 Gauss–Lobatto nodes, x ascending, the shared vertex once
    x = np.array([float(row["s"]) for row in rows])
    p = np.array([float(row["pressure"]) for row in rows])
    lam = np.array([float(row["traction"]) for row in rows])
    order = np.argsort(x)
    x, p, lam = x[order], p[order], lam[order]
    # p = λ dS/dx with dS/dx = 1/cos θ = R / sqrt(R² − x²) on the undeformed circle R = 10
    R = 10.0
    assert np.allclose(p, lam * R / np.sqrt(R**2 - x**2), rtol=1e-9)
    assert np.all(p >= lam - 1e-9)
    # ∫ p dx = ∫ λ dS: on each edge λ is the degree-8 polynomial through its nodes in the
    # edge parameter, θ linear in it (an exact arc), so integrate in θ exactly.
    theta = np.arcsin(x / R)
    force = 0.0
    for edge in (slice(0, 9), slice(8, 17)):
        t_nodes = theta[edge]
        coef = np.polyfit(t_nodes, lam[edge], 8)
        g, w = np.polynomial.legendre.leggauss(12)
        a, b = t_nodes[0], t_nodes[-1]
        tq = 0.5 * (a + b) + 0.5 * (b - a) * g
        force += 0.5 * (b - a) * np.sum(w * np.polyval(coef, tq)) * R
    assert abs(force / 35000 - 1) < 1e-6, force
    s = json.loads((tmp_path / "summary.json").read_text())
    assert s["contact"]["pressure_measured_as"] == "force per unit length along the obstacle"
    assert s["contact"]["pressure_max"] == pytest.approx(float(p.max()), rel=1e-9)
