"""compare.reference against the force the closed forms are computed for: a reference pressure
curve carries a force (twice its integral over x >= 0 for a cylinder, its integral over
2 pi r dr for a sphere); one that carries another load than the run's, by more than 1 %, is
refused before anything is solved, with both forces and the file in the message. Plane
(examples/hertz/p5.yaml and its reference-pressure.csv, F = 70000 N/mm) and axisymmetric
(examples/hertz/ball-on-flat.yaml against a Hertz curve for F = 250 N written here)."""
import json
import math
import os

import pytest

from conftest import expect_refused

HERTZ = os.path.join("examples", "hertz")


def hertz_sphere_reference(path, F, R=10.0, E=210000.0, nu=0.3):
    """The 3-D Hertz pressure of a sphere of radius R on a rigid flat under F, sampled to 1.5 a
    (the ball-on-flat example's material): p0 sqrt(1 − r²/a²), a = (3 F R / (4 E*))^(1/3),
    p0 = 3 F / (2 pi a²), E* = E / (1 − nu²)."""
    a = (3 * F * R / (4 * E / (1 - nu * nu))) ** (1 / 3)
    p0 = 3 * F / (2 * math.pi * a * a)
    rows = ["x,pressure"]
    for i in range(401):
        r = 1.5 * a * i / 400
        rows.append(f"{r!r},{p0 * math.sqrt(max(0.0, 1 - (r / a) ** 2))!r}")
    path.write_text("\n".join(rows) + "\n")
    return str(path)


def cases(root, tmp_path):
    """(case, its reference, the force it carries, the settings that put the run's force at F)."""
    ball = hertz_sphere_reference(tmp_path / "ball-reference.csv", 250)
    return {
        "plane": (os.path.join(root, HERTZ, "p5.yaml"), "reference-pressure.csv", 70000,
                  # F = 2 × the half model's target (F/2 = 35000)
                  lambda F: [f"solver.target_resultant.value={F / 2!r}", f"contact[0].compare.force={F!r}"],
                  "(twice its integral over x >= 0)"),
        "axisymmetric": (os.path.join(root, HERTZ, "ball-on-flat.yaml"), ball, 250,
                         lambda F: [f"contact[0].compare.reference={ball}", "adapt.tolerance=0.05",
                                    f"solver.target_resultant.value={F!r}"],
                         "(its integral over 2 pi r dr)"),
    }


@pytest.mark.parametrize("kind", ["plane", "axisymmetric"])
@pytest.mark.parametrize("off", [1.02, 1 / 1.02], ids=["above", "below"])
def test_a_reference_of_another_load_is_refused(hpcontact, root, tmp_path, kind, off):
    """The run's force 2 % above or below the reference's: refused (exit 1) naming the key, the
    file, the force it carries, how that was measured and the force of the closed forms."""
    case, reference, carried, settings, measured = cases(root, tmp_path)[kind]
    F = carried * off
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q", *sum((["--set", s] for s in settings(F)), []))
    assert r.returncode == 1, r.stderr
    message = f"contact[0].compare.reference: '{reference}' carries F = "
    assert message in r.stderr, r.stderr
    got = float(r.stderr.split(message, 1)[1].split()[0])
    assert abs(got - carried) < 1e-3 * carried, r.stderr
    computed = f"{measured} but the closed forms are computed for F = "
    assert computed in r.stderr, r.stderr
    assert abs(float(r.stderr.split(computed, 1)[1].split(":")[0]) - F) < 1e-6 * F, r.stderr
    expect_refused(hpcontact, case, str(tmp_path / "out"), settings(F), message, 1)


@pytest.mark.parametrize("kind", ["plane", "axisymmetric"])
def test_a_reference_of_the_runs_load_is_compared(hpcontact, root, tmp_path, kind):
    """The same references at their own force (0.5 % off, within the 1 % allowed): the run goes on
    and measures its pressure against the reference, a curve of its shape (the L2 difference a
    few percent, of the size of the closed form's: measured 6.0 % against 5.3 % for the cylinder,
    13.9 % against 13.8 % for the sphere's pressure from the stresses)."""
    case, reference, carried, settings, _ = cases(root, tmp_path)[kind]
    out = tmp_path / "out"
    r = hpcontact("run", case, "--out", out, "-q", "--set", "output.vtu=false",
                  *sum((["--set", s] for s in settings(carried * 1.005)), []))
    assert r.returncode == 0, r.stderr
    c = json.loads((out / "summary.json").read_text())["contact"]
    assert c["reference"] == reference
    assert 0 < c["e_L2_reference_percent"] < 2 * c["e_L2_hertz_percent"] + 1, c
