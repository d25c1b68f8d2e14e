"""The plot scripts of the adaptive runs and of stress differences: scripts/plot_adapt.py (pressure
of every rp/hp iteration) and scripts/von_mises_difference.py (VTU + PNG of |Δσ_vM|)."""
import os
import re
import subprocess
import sys

from conftest import scaled_timeout

PY = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


def script(root, name, *args):
    return subprocess.run([PY, os.path.join(root, "scripts", name), *map(str, args)],
                          capture_output=True, text=True, timeout=scaled_timeout(120))


def test_plot_adapt_draws_every_rp_iteration(hpcontact, root, tmp_path):
    out = tmp_path / "rp5"
    r = hpcontact("run", os.path.join(root, "examples/hertz/rp5.yaml"), "--out", out, "-q",
                  "--set", "adapt.tolerance=1e-6", "--set", "output.vtu=false")
    assert r.returncode == 0, r.stderr
    r = script(root, "plot_adapt.py", out)
    assert r.returncode == 0, r.stderr
    assert (out / "adapt-pressure.png").stat().st_size > 20000
    # A plain p run has no iterations to draw: a clear message, exit 1.
    p = tmp_path / "p5"
    hpcontact("run", os.path.join(root, "examples/hertz/p5.yaml"), "--out", p, "-q")
    r = script(root, "plot_adapt.py", p)
    assert r.returncode == 1 and "not an rp/hp run" in r.stderr


def test_von_mises_difference_of_two_degrees(hpcontact, root, tmp_path):
    for p in (4, 8):
        r = hpcontact("run", os.path.join(root, "examples/hertz/p5.yaml"), "--out", tmp_path / f"p{p}",
                      "-q", "--set", f"discretization.degree={p}", "--set", "output.vtu_subdivisions=8")
        assert r.returncode == 0, r.stderr
    r = script(root, "von_mises_difference.py", tmp_path / "p4/solution.vtu",
               tmp_path / "p8/solution.vtu", "--out", tmp_path / "diff")
    assert r.returncode == 0, r.stderr
    vtu = (tmp_path / "diff/von-mises-difference.vtu").read_text()
    m = re.search(r'Name="von_mises_difference_percent"[^>]*>(.*?)</DataArray>', vtu, re.S)
    values = [float(v) for v in m.group(1).split()]
    assert all(v >= 0 for v in values) and max(values) > 0.1  # p = 4 is visibly off
    assert "nan" not in vtu
    assert (tmp_path / "diff/von-mises-difference.png").stat().st_size > 20000
    # The same run against itself: zero everywhere.
    r = script(root, "von_mises_difference.py", tmp_path / "p8/solution.vtu",
               tmp_path / "p8/solution.vtu", "--out", tmp_path / "same")
    assert r.returncode == 0 and "max difference 0 %" in r.stdout, r.stdout
    # Different sampling: refused.
    hpcontact("run", os.path.join(root, "examples/hertz/p5.yaml"), "--out", tmp_path / "p4b", "-q",
              "--set", "discretization.degree=4", "--set", "output.vtu_subdivisions=6")
    r = script(root, "von_mises_difference.py", tmp_path / "p4b/solution.vtu",
               tmp_path / "p8/solution.vtu", "--out", tmp_path / "bad")
    assert r.returncode == 1 and "different point counts" in r.stderr
