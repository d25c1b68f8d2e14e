"""Bounded work (docs/input.md, "Limits"): a key or a product of keys that would make a run never
end or exhaust memory is refused at once, naming the key, the limit and why; input files are
read only if they are regular files of a bounded size. Runs are given an address-space limit and a
timeout, so that a regression fails the test instead of the machine."""
import os
import re
import resource
import subprocess

import pytest

from conftest import scaled_timeout

BLOCK = "examples/neumann/block.yaml"
HERTZ = "examples/hertz/p5.yaml"


# Address space in which an input must be refused: the program takes some 100 MB of it; the
# trees the refused inputs would build take 500 MB to GBs, so a refusal within it came before.
REFUSED_WITHIN = 256 << 20


def limited(exe, *args, timeout=60, address_space=2 << 30):
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (address_space, address_space))
    return subprocess.run([exe, *map(str, args)], capture_output=True, text=True,
                          timeout=scaled_timeout(timeout), preexec_fn=limit)


def strip(n):
    """A strip of n x 1 elements given inline: 14 YAML values per element."""
    nodes = "\n".join(f"      {i + 1}: [{i}, 0]\n      {n + 2 + i}: [{i}, 1]" for i in range(n + 1))
    elements = "\n".join(f"      {i + 1}: [{i + 1}, {i + 2}, {n + 3 + i}, {n + 2 + i}]"
                         for i in range(n))
    return (f"case: strip\nbodies:\n  - name: strip\n    material: {{E: 1, nu: 0.3}}\n"
            f"    nodes:\n{nodes}\n    elements:\n{elements}\n")


def grid_msh(nx, ny):
    """An nx x ny grid of first-order quads on [0, nx] x [0, ny] in MSH 4.1, surface 'plate'."""
    nn = (nx + 1) * (ny + 1)
    quads = "".join(f"{j * nx + i + 1} {j * (nx + 1) + i + 1} {j * (nx + 1) + i + 2} "
                    f"{(j + 1) * (nx + 1) + i + 2} {(j + 1) * (nx + 1) + i + 1}\n"
                    for j in range(ny) for i in range(nx))
    return ("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n2 1 \"plate\"\n"
            f"$EndPhysicalNames\n$Entities\n0 0 1 0\n1 0 0 0 {nx} {ny} 0 1 1 0\n$EndEntities\n"
            f"$Nodes\n1 {nn} 1 {nn}\n2 1 0 {nn}\n" + "".join(f"{k + 1}\n" for k in range(nn))
            + "".join(f"{k % (nx + 1)} {k // (nx + 1)} 0\n" for k in range(nn))
            + f"$EndNodes\n$Elements\n1 {nx * ny} 1 {nx * ny}\n2 1 3 {nx * ny}\n{quads}"
            "$EndElements\n")


MESH_PROBLEM = ("case: grid\nbodies:\n  - name: plate\n    material: {E: 1, nu: 0.3}\n"
                "    gmsh: {file: mesh.msh, surface: plate}\n")


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


def alias_bomb():
    """One strip of 1000 elements and 1000 bodies that repeat its nodes and elements by alias:
    14 million values from 140 kB (it took 0.9 GB before it was refused for want of supports)."""
    text = strip(1000).replace("    nodes:\n", "    nodes: &n\n").replace("    elements:\n",
                                                                            "    elements: &e\n")
    return text + "".join(f"  - {{name: s{k}, material: {{E: 1, nu: 0.3}}, nodes: *n, elements: *e}}\n"
                          for k in range(1000))


# Texts past the limit, made when their test runs, where the refusal names and whether it names a
# flow collection's bracket (counted from the text: yaml-cpp's scanner holds a flow list whole,
# 280 bytes a value, before its parser reports any of it) or the value that passes the limit.
FLOW = "has a flow list or map ([...] or {...}) starting here with more than the 1000000 YAML values"
VALUES = "has more than the 1000000 YAML values"
PAST_THE_LIMIT = {
    # The densest YAML: a flow list, one value per 2 bytes (2 MB took 1 GB and 9 s before it was
    # refused as not a string).
    "flow-list": (lambda: "case: x\ndescription: [" + "0," * 1_000_000 + "0]\n", "2:14", FLOW),
    # A flow map of keys alone, two values per 2 bytes (4 MB took 2.1 GB): as a key's value,
    # yaml-cpp reports it as it reads, and it is refused at the value that passes the limit.
    "flow-map": (lambda: "case: x\ndescription: {" + "a," * 600_000 + "a}\n", "2:1000010", VALUES),
    # A flow list where a key could stand, which yaml-cpp holds whole before counting starts.
    "flow-list-as-item": (lambda: "case: x\ndescription:\n  - [" + "0," * 1_500_000 + "0]\n", "3:5",
                          FLOW),
    # A mesh given inline, just past the limit: its value 1000001 is element 71330's id.
    "inline-mesh": (lambda: strip(71_500), "214338:7", VALUES),
    # The 71st body of aliases passes the limit with its elements.
    "aliases": (lambda: alias_bomb(), "3079:51", VALUES),
}


@pytest.mark.parametrize("name", PAST_THE_LIMIT)
def test_yaml_values_are_counted_before_the_tree_is_built(exe, tmp_path, name):
    """yaml-cpp's tree takes some 500 bytes per value, up to 500 per byte of the file, and an
    alias repeats a subtree for a few bytes: a 15.9 MB file took 2.4 GB. The values are counted
    first (the parser's events, no tree) and a problem of more than 10^6 is refused at the value
    that passes the limit, in an address space its tree would not fit into."""
    text, where, what = PAST_THE_LIMIT[name]
    case = tmp_path / f"{name}.yaml"
    case.write_text(text())
    r = limited(exe, "check", case, timeout=60, address_space=REFUSED_WITHIN)
    assert r.returncode == 1, r.stderr[:300]
    line = r.stderr.splitlines()[0]
    assert f"{case}:{where}: the problem file {what}" in line, line
    assert "give fewer elements" in line, line


def test_an_alias_cycle_is_refused(exe, tmp_path):
    """An alias inside what its anchor names is a cycle: a tree without end, refused as such."""
    case = tmp_path / "cycle.yaml"
    case.write_text("case: x\nbodies:\n  - &b {name: b, material: {E: 1, nu: 0.3}, curves: [*b]}\n")
    r = limited(exe, "check", case, timeout=30, address_space=REFUSED_WITHIN)
    assert r.returncode == 1, r.stderr
    assert f"{case}:3:54: an alias inside the list or map its anchor names: a cycle" in r.stderr, r.stderr


def test_set_values_are_bounded_as_files_are(exe, root, tmp_path):
    """A --set value is YAML read as a file is: 100 aliases of a list of 10^4 values (60 kB, the
    command line's limit for one argument is 128 kB) are refused as 10^6 values, before any tree."""
    value = "[&a [" + ",".join(["0"] * 10_000) + "]" + ", *a" * 100 + "]"
    r = limited(exe, "check", os.path.join(root, BLOCK), "--set", f"description={value}",
                timeout=30, address_space=REFUSED_WITHIN)
    assert r.returncode == 2, r.stderr  # from the command line
    line = r.stderr.splitlines()[0]
    # The 99th alias passes what the block's 124 other values leave.
    column = value.find("*a") + 4 * 98 + 1
    assert f"block.yaml: --set description=[&a [0,0,0,0,0,0,0,0...: at line 1, column {column}: " in line, line
    assert re.search(r"the --set value has more than the \d+ YAML values the rest of the problem "
                     "leaves it of the 1000000 an input may have", line), line


def test_gmsh_meshes_are_bounded_before_they_are_read(exe, tmp_path):
    """A Gmsh mesh becomes part of the problem's YAML tree: `check` of 10^6 elements took 5.4 GB.
    The node and element counts of a .msh file are refused at their header line, before the
    section is read, and a mesh that would pass the problem's 10^6 values before it is written
    into the tree."""
    (tmp_path / "case.yaml").write_text(MESH_PROBLEM)
    head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    for section, count, most in (("Nodes", 800_001, 800_000), ("Elements", 200_001, 200_000)):
        (tmp_path / "mesh.msh").write_text(head + f"${section}\n1 {count} 1 {count}\n")
        r = limited(exe, "check", tmp_path / "case.yaml", timeout=30, address_space=REFUSED_WITHIN)
        assert r.returncode == 1, r.stderr
        assert (f"mesh.msh:5: the header says {count} {section.lower()}, more than the {most} a "
                "mesh file may have") in r.stderr, r.stderr
        assert "give a coarser mesh" in r.stderr, r.stderr
    # A file of 100 MB is held once while it is read (its buffer grew to twice that to find its
    # end), and refused at the header without reading the nodes.
    (tmp_path / "mesh.msh").write_text(head + "$Nodes\n1 50000000 1 50000000\n" + "1\n" * 50_000_000)
    r = limited(exe, "check", tmp_path / "case.yaml", timeout=30, address_space=REFUSED_WITHIN)
    assert r.returncode == 1, r.stderr
    assert "mesh.msh:5: the header says 50000000 nodes, more than the 800000" in r.stderr, r.stderr
    # 316 x 316 quads: 4 values per node (100489) and 6 per element (99856), with the keys 1001100.
    (tmp_path / "mesh.msh").write_text(grid_msh(316, 316))
    r = limited(exe, "check", tmp_path / "case.yaml", timeout=60, address_space=REFUSED_WITHIN)
    assert r.returncode == 1, r.stderr
    assert ("case.yaml:5:11: bodies[0].gmsh: the mesh of " in r.stderr and
            "mesh.msh (100489 corner nodes, 99856 elements) makes 1001100 YAML values, which with "
            "the problem's " in r.stderr and "more than the 1000000 an input may have" in r.stderr), r.stderr


def test_the_effective_input_is_bounded_as_a_file_is(exe, tmp_path):
    """input.yaml, the problem with its defaults filled in, is read back to reproduce a run: a
    problem file of exactly 16 MB (a long description) whose defaults would take its effective
    input past 16 MB is refused when read, not when its input.yaml is. (Its values:
    test_yaml_limits.cpp.)"""
    head = 'case: square\ndescription: "'
    tail = ('"\nbodies:\n  - name: block\n    material: {E: 1000, nu: 0.25}\n'
            "    nodes: {1: [0, 0], 2: [1, 0], 3: [1, 1], 4: [0, 1]}\n    elements: {1: [1, 2, 3, 4]}\n"
            "    edge_sets: {bottom: [[1, 2]]}\n    constraints: [{edges: [bottom], ux: 0, uy: 0}]\n")
    case = tmp_path / "long.yaml"
    case.write_text(head + "x" * ((16 << 20) - len(head) - len(tail)) + tail)
    assert case.stat().st_size == 16 << 20
    r = limited(exe, "check", case, timeout=60)
    assert r.returncode == 1, r.stderr[:300]
    assert (f"{case}: the effective input (input.yaml, the problem with its defaults filled in) is "
            "larger than the 16 MB a problem file may have (16 MB), so it could not be read back"
            in r.stderr), r.stderr[:300]
