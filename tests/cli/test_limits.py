"""Bounded work (docs/input.md, "Limits"): a key or a product of keys that would make a run never
end or exhaust memory is refused at once, naming the key, the limit and why; input files are
read only if they are regular files of a bounded size. Runs are given an address-space limit and a
timeout, so that a regression fails the test instead of the machine."""
import os
import resource
import subprocess

import pytest

from conftest import scaled_timeout

BLOCK = "examples/neumann/block.yaml"
HERTZ = "examples/hertz/p5.yaml"


def limited(exe, *args, timeout=60):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (2 << 30, 2 << 30))
    return subprocess.run([exe, *map(str, args)], capture_output=True, text=True,
                          timeout=scaled_timeout(timeout), preexec_fn=limit)


@pytest.mark.parametrize("key, value, limit", [
    ("discretization.quadrature_extra", "10000000", "50"),
    ("output.vtu_subdivisions", "10000", "100"),
    ("solver.load_steps", "100000000", "10000"),
    ("solver.max_iterations", "1000000", "1000"),
    ("solver.max_cuts", "2000", "50"),
    ("adapt.max_iterations", "100000", "200"),
])
def test_key_beyond_its_bound_is_refused_at_once(exe, root, key, value, limit):
    """quadrature_extra = 1e7 never finished, even in check; vtu_subdivisions = 1e4 took 3.6 GB
    and ended in std::bad_alloc naming nothing. Now check and run refuse such values at once
    (exit 2 from --set) with the key, the limit and why."""
    for command in ("check", "run"):
        extra = ["--out", "/nonexistent/never-written"] if command == "run" else []
        case = "examples/hertz/rp8.yaml" if key.startswith("adapt.") else BLOCK
        r = limited(exe, command, os.path.join(root, case), *extra, "--set", f"{key}={value}",
                    timeout=30)
        assert r.returncode == 2, (command, r.returncode, r.stderr)
        line = r.stderr.splitlines()[0]
        assert f"{key} (from --set): must be <= {limit} (got {value}): " in line, line
        assert len(line.split(f"(got {value}): ")[1]) > 20, line  # the reason


def test_keys_that_multiply_are_bounded_together(exe, root, tmp_path):
    """995 elements with 100 sub-cells per edge would write 1e7 points into solution.vtu
    (~3 GB); 30 000 elements at p = 30 would have 5.8e7 modes. Refused when read, naming the keys
    and the products."""
    r = limited(exe, "check", os.path.join(root, "examples/hertz/h1-995.yaml"),
                "--set", "output.vtu_subdivisions=100")
    assert r.returncode == 2, r.stderr  # the key came from --set
    assert "output.vtu_subdivisions (from --set): the points of solution.vtu" in r.stderr, r.stderr
    assert "more than the 1e+07 a run may have" in r.stderr, r.stderr
    r = limited(exe, "check", os.path.join(root, "examples/hertz/h1-995.yaml"),
                "--set", "output.vtu_subdivisions=100", "--set", "output.vtu=false")
    assert r.returncode == 0, r.stderr
    # A strip of n x 1 elements, generated.
    n = 30000
    nodes = "\n".join(f"      {i + 1}: [{i}, 0]\n      {n + 2 + i}: [{i}, 1]" for i in range(n + 1))
    elements = "\n".join(f"      {i + 1}: [{i + 1}, {i + 2}, {n + 3 + i}, {n + 2 + i}]"
                         for i in range(n))
    case = tmp_path / "strip.yaml"
    case.write_text(f"case: strip\nbodies:\n  - name: strip\n    material: {{E: 1, nu: 0.3}}\n"
                    f"    nodes:\n{nodes}\n    elements:\n{elements}\n"
                    "discretization: {degree: 30, quadrature_extra: 0}\noutput: {vtu: false}\n")
    r = limited(exe, "check", case)
    assert r.returncode == 1, r.stderr
    assert "discretization: the elements' modes" in r.stderr and "5e+07" in r.stderr, r.stderr


def test_input_files_must_be_regular_and_bounded(exe, root, tmp_path):
    """`run /dev/zero` read 4 GB and ended in std::bad_alloc; a 20 MB file was parsed into a
    tree of GBs. Devices, pipes and oversized files are refused before they are read, as problem
    file, study file and reference file alike, by check as well."""
    r = limited(exe, "run", "/dev/zero", "--out", tmp_path / "out", "-q", timeout=30)
    assert r.returncode == 1, r.stderr
    assert "/dev/zero: cannot read problem file: not a regular file" in r.stderr, r.stderr
    r = limited(exe, "study", "/dev/zero", "--out", tmp_path / "study", "-q", timeout=30)
    assert r.returncode == 1 and "not a regular file" in r.stderr, r.stderr
    big = tmp_path / "big.yaml"
    big.write_text("# a comment line of forty characters ...\n" * 500_000)  # 20 MB
    r = limited(exe, "check", big, timeout=30)
    assert r.returncode == 1, r.stderr
    assert "the problem file is larger than the 16 MB it may have (19.6 MB)" in r.stderr, r.stderr
    for reference, why in (("/dev/zero", "not a regular file"),
                           ("no-such.csv", "No such file or directory")):
        r = limited(exe, "check", os.path.join(root, HERTZ),
                    "--set", f"contact[0].compare.reference={reference}", timeout=30)
        assert r.returncode == 1, r.stderr
        assert "contact[0].compare.reference: " in r.stderr and why in r.stderr, r.stderr
