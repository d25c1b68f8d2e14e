"""Crashes and false successes: what makes the numerics fail (values at the edge of double
precision, memory running out, a degenerate element) ends the run with exit 1 and a message
naming the place and the cause, never with a signal, and never with a summary claiming success."""
import os
import re
import resource
import subprocess

import pytest

from conftest import scaled_timeout

BLOCK = "examples/neumann/block.yaml"  # two p-elements, condensed, no contact
HERTZ = "examples/hertz/p5.yaml"


def failed_cleanly(r, out):
    """Exit 1 (a signal would be negative), one error line, no summary.json."""
    assert r.returncode == 1, (r.returncode, r.stderr)
    assert r.stderr.startswith("hpcontact: error: ") and r.stderr.count("\n") == 1, r.stderr
    assert not (out / "summary.json").exists()


def test_error_inside_the_parallel_assembly_is_reported(hpcontact, root, tmp_path):
    """An element whose stiffness cannot be condensed (nu = 0.49999999999999994: 1 - 2 nu lost to
    round-off) was an exception inside the OpenMP loop, which aborted the process; now it is the
    error it is, naming the body, the element and the values."""
    out = tmp_path / "out"
    r = hpcontact("run", os.path.join(root, BLOCK), "--out", out, "-q",
                  "--set", "bodies[0].material.nu=0.49999999999999994")
    failed_cleanly(r, out)
    assert "bodies[0] (block): element 1: static condensation" in r.stderr, r.stderr
    assert "nu = 0.49999999999999994" in r.stderr, r.stderr


@pytest.mark.parametrize("case, value", [(BLOCK, "bodies[0].material.E=4.9e-324"),
                                         (BLOCK, "bodies[0].material.thickness=1e-320"),
                                         (BLOCK, "bodies[0].material.E=1e308"),
                                         (BLOCK, "bodies[0].loads[0].resultant=1e308"),
                                         (HERTZ, "contact[0].penalty=1e308"),
                                         (HERTZ, "bodies[0].constraints[1].uy=-1e308")])
def test_values_beyond_double_precision_are_refused_with_their_key(hpcontact, root, tmp_path, case,
                                                                   value):
    """E, thickness, a load, a penalty or a displacement at the ends of double precision (which
    aborted the process, or ran into 'the residual is not finite' without naming the key) are
    refused as input: exit 2 for --set, naming the key, the value and why."""
    out = tmp_path / "out"
    r = hpcontact("run", os.path.join(root, case), "--out", out, "-q", "--set", value)
    assert r.returncode == 2, r.stderr
    key, shown = value.split("=")
    assert f"{key} (from --set): must be 0 or of magnitude between 1e-100 and 1e+100 (got {shown})" \
        in r.stderr, r.stderr
    assert not (out / "summary.json").exists()


def limited_run(exe, args, mb, **kwargs):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (mb << 20, mb << 20))
    return subprocess.run([exe, *args], capture_output=True, text=True, preexec_fn=limit, **kwargs)


def test_memory_running_out_is_reported_not_a_crash(exe, root, tmp_path):
    """Under address-space limits from the least the program loads in (its shared libraries:
    OpenBLAS maps some 50 MB; below it the loader, not the program, ends the process) to 120 MB
    more, a run (Lamé at p = 20, ~140 MB) either succeeds or ends with exit 1 saying it ran out
    of memory, wherever the allocation failed (element assembly in parallel, the factorisation,
    post-processing)."""
    args = ["run", os.path.join(root, "examples/lame/thick-cylinder.yaml"), "-q",
            "--set", "discretization.degree=20", "--set", "output.vtu=false"]
    loads = [mb for mb in range(30, 400, 10)
             if limited_run(exe, ["--version"], mb, timeout=scaled_timeout(30)).returncode == 0]
    assert loads, "the program does not load within 400 MB of address space"
    out_of_memory = 0
    for mb in range(loads[0], loads[0] + 130, 10):
        out = tmp_path / f"out-{mb}"
        r = limited_run(exe, [*args, "--out", str(out)], mb, timeout=scaled_timeout(120))
        assert r.returncode in (0, 1), (mb, r.returncode, r.stderr)
        if r.returncode == 1:
            # libgomp ends the process itself (exit 1) when it cannot start its threads.
            assert "out of memory" in r.stderr or "Thread creation failed" in r.stderr, (mb, r.stderr)
            assert not (out / "summary.json").exists()
            out_of_memory += "out of memory" in r.stderr
    assert out_of_memory >= 3


BOX_3D = """case: box-3d
dimension: 3
bodies:
  - name: block
    material: {E: 5000, nu: 0.27}
    box: {from: [0, 0, 0], to: [1, 1, 1], elements: [6, 6, 6]}
    constraints:
      - {faces: [z0], ux: 0, uy: 0, uz: 0}
    loads:
      - {faces: [z1], traction: [0, 0, -1]}
discretization: {degree: 4}
output: {vtu: false}
"""


def test_a_3d_factor_that_will_not_fit_is_refused_with_its_size(exe, tmp_path):
    """A 3D problem (216 hexahedra at p = 4, 10224 unknowns after condensation, a factor of
    0.12 GB) under address-space limits from the least the program loads in to 260 MB more either
    succeeds or ends with exit 1 saying it ran out of memory, and at least once it is refused
    before the factorisation with the factor's size in GB and the memory left (not killed, not a
    failed allocation): CHOLMOD's analysis sized it against the limit."""
    problem = tmp_path / "box.yaml"
    problem.write_text(BOX_3D)
    loads = [mb for mb in range(30, 400, 10)
             if limited_run(exe, ["--version"], mb, timeout=scaled_timeout(30)).returncode == 0]
    assert loads, "the program does not load within 400 MB of address space"
    refused = 0
    for mb in range(loads[0], loads[0] + 270, 20):
        out = tmp_path / f"out-{mb}"
        r = limited_run(exe, ["run", str(problem), "--out", str(out), "-q"], mb,
                        timeout=scaled_timeout(120))
        assert r.returncode in (0, 1), (mb, r.returncode, r.stderr)
        if r.returncode == 1:
            assert "out of memory" in r.stderr or "Thread creation failed" in r.stderr, (mb, r.stderr)
            assert not (out / "summary.json").exists()
            if "would run out of memory: its factor has" in r.stderr:
                assert re.search(r"needs about [0-9.]+ GB with its workspace .* but [0-9.]+ GB are "
                                 r"available \(the address-space limit \(ulimit -v\)", r.stderr), r.stderr
                refused += 1
    assert refused >= 1


def test_solution_that_is_not_finite_is_an_error(hpcontact, root, tmp_path):
    """Values each within the input's bounds whose products overflow (a strain of 1e199 in an
    element 1e-99 wide) gave exit 0, converged: true and energy NaN; every result is now checked
    before it is reported. A formula whose value leaves the bounds is refused with its key."""
    out = tmp_path / "out"
    r = hpcontact("run", os.path.join(root, "tests/cli/data/overflow.yaml"), "--out", out, "-q")
    failed_cleanly(r, out)
    assert "the solution is not finite (strain energy" in r.stderr, r.stderr
    assert "too large for double precision" in r.stderr, r.stderr
    r = hpcontact("run", os.path.join(root, BLOCK), "--out", out, "-q",
                  "--set", "bodies[0].constraints[0].ux=1e100*1e100")
    failed_cleanly(r, out)
    assert "bodies[0].constraints[0].ux: '1e100*1e100' is 1e+200 at (0, 0), beyond the magnitude" \
        in r.stderr, r.stderr


DUPLICATE = """case: twice
bodies:
  - name: block
    material: {E: 1000, nu: 0.3}
    nodes: {1: [0, 0], 2: [1, 0], 3: [1, 1], 4: [0, 1]}
    elements: {1: [1, 2, 3, 4], 2: [2, 3, 4, 1]}
    edge_sets: {bottom: [[1, 2]], top: [[3, 4]]}
    constraints:
      - {edges: [bottom], ux: 0, uy: 0}
      - {edges: [top], uy: -0.1}
discretization: {method: p, degree: 2}
"""


def test_degenerate_elements_are_refused_before_solving(hpcontact, root, tmp_path):
    """Two corners at one point (node 2 of the Hertz mesh 1e-9 from node 1: the run 'succeeded'
    with p_max 4.5 times Hertz's), and the same element given twice, are refused by check and
    run with the body and the element named."""
    for move, corners in (("bodies[0].nodes.2=[1e-9, 0]", "its corners 1 and 2 are at one point"),
                          ("bodies[0].nodes.5=[1e-13, 4]", "its corners 5 and 4 are at one point")):
        for command in ("check", "run"):
            out = tmp_path / f"{command}-out"
            extra = ["--out", out, "-q"] if command == "run" else []
            r = hpcontact(command, os.path.join(root, HERTZ), *extra, "--set", move)
            assert r.returncode == 1, (command, r.stderr)
            assert f"bodies[0] (cylinder): element 1 is degenerate: {corners}" in r.stderr, r.stderr
            assert not (out / "summary.json").exists()
    case = tmp_path / "twice.yaml"
    case.write_text(DUPLICATE)
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q")
    failed_cleanly(r, tmp_path / "out")
    assert "elements 1 and 2 have the same corners: an element is given twice" in r.stderr


def test_curved_edge_that_crosses_its_element_is_refused(hpcontact, root, tmp_path):
    """An arc bulging through its element (a half circle on the bottom edge of a flat element,
    bowing up across the top edge) makes det J change sign at Gauss points: refused, naming
    the element."""
    case = tmp_path / "bulge.yaml"
    case.write_text(DUPLICATE.replace("[1, 1], 4: [0, 1]", "[1, 0.2], 4: [0, 0.2]")
                    .replace(", 2: [2, 3, 4, 1]", "")
                    .replace("    edge_sets:", "    curves:\n      - {nodes: [1, 2], arc: "
                             "{center: [0.5, 0], radius: 0.5, ccw: false}}\n    edge_sets:"))
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q")
    failed_cleanly(r, tmp_path / "out")
    assert "bodies[0] (block): element 1 has a" in r.stderr, r.stderr
    assert "Jacobian determinant" in r.stderr and "curved edges cross" in r.stderr, r.stderr
