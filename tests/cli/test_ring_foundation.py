"""examples/ring-foundation: the composite Neo-Hooke ring pressed onto a rigid plane through a
stiff strip, under arc-length control, and scripts/ring_foundation_study.py's load path."""
import csv
import os
import subprocess

from conftest import scaled_timeout


def test_arc_length_path_reaches_the_load_in_equilibrium(exe, root, tmp_path):
    out = tmp_path / "path"
    r = subprocess.run(["/usr/bin/python3", os.path.join(root, "scripts/ring_foundation_study.py"),
                        "--hpcontact", exe, "--out", out], capture_output=True, text=True,
                       timeout=scaled_timeout(300))
    assert r.returncode == 0, r.stdout + r.stderr
    with open(out / "path.csv") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) >= 5
    load = [float(row["load_N"]) for row in rows]
    top = [float(row["top_displacement_mm"]) for row in rows]
    # The arc-length method ends on the full load.
    assert abs(load[-1] - 2070) <= 1e-9 * 2070
    # Only the foundation carries vertical load (the constraints are horizontal): the contact
    # reaction balances the applied load at every converged step, to Newton's tolerance.
    for row, f in zip(rows, load):
        assert abs(float(row["reaction_N"]) - f) <= 1e-6 * f, row
    # The load grows along this path (no limit point) and the ring flattens with it.
    assert all(b > a for a, b in zip(load, load[1:]))
    assert all(b > a for a, b in zip(top, top[1:]))
    assert (out / "path.png").stat().st_size > 10000
