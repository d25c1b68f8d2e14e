"""A rigid obstacle given as a curve through points (contact[].obstacle.type: curve):
examples/curve-obstacle/crowned-rail.yaml, a cylinder on a rail whose crown is 13 points of a
circle, against the same run with the exact circle and against Hertz for the effective radius."""
import csv
import json
import os
import re


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def pressures(out):
    with open(os.path.join(out, "contact.csv")) as f:
        # −n·σ·n: independent of how positions along the obstacle are measured (arc length
        # along the curve, x for the circle)
        return [float(r["minus_sigma_nn"]) for r in csv.DictReader(f)]


def test_crowned_rail_equals_the_exact_circle_and_meets_hertz(hpcontact, root, tmp_path):
    example = os.path.join(root, "examples", "curve-obstacle", "crowned-rail.yaml")
    text = open(example).read()
    # The same problem with the exact circle the points were taken from.
    circle = re.sub(r"    obstacle:\n      type: curve\n      point: \[0, 0\]\n      points:\n"
                    r"(        - .*\n)+",
                    "    obstacle: {type: circle, center: [0, -30], radius: 30}\n", text)
    assert circle != text
    circle_file = tmp_path / "circle.yaml"
    circle_file.write_text(circle)
    runs = {}
    for name, path in (("curve", example), ("circle", circle_file)):
        out = tmp_path / name
        r = hpcontact("run", path, "--out", out)
        assert r.returncode == 0, r.stderr
        runs[name] = out
    s = summary(runs["curve"])
    assert s["converged"]
    c = s["contact"]
    assert abs(c["resultant"][1] - 35000) < 35
    # The spline through points 2.6 mm apart is within ~1e-6 mm of the circle where the
    # cylinder touches it; the pressures from stresses agree to 1e-4 of the peak (measured 2.1e-5).
    p_curve, p_circle = pressures(runs["curve"]), pressures(runs["circle"])
    assert len(p_curve) == len(p_circle) > 0
    peak = max(p_circle)
    assert max(abs(a - b) for a, b in zip(p_curve, p_circle)) < 1e-4 * peak
    # Hertz with R* = 7.5 mm: the rp-run's zone ends within 1 % of b (measured 0.8 % short) and
    # its pressure is about as far from Hertz as the rp examples' on the plane (measured 0.16 %).
    assert abs(c["half_width"] - c["hertz_half_width"]) < 0.01 * c["hertz_half_width"]
    assert c["e_seed_hertz_percent"] < 0.3


def test_curve_obstacle_mistakes_are_named(hpcontact, root, tmp_path):
    example = os.path.join(root, "examples", "curve-obstacle", "crowned-rail.yaml")
    text = open(example).read()
    # The points in the wrong order put the body on the rail's far side: refused before solving.
    lines = text.splitlines(keepends=True)
    first = next(i for i, l in enumerate(lines) if l.startswith("        - ["))
    last = max(i for i, l in enumerate(lines) if l.startswith("        - ["))
    lines[first:last + 1] = reversed(lines[first:last + 1])
    bad = tmp_path / "reversed.yaml"
    bad.write_text("".join(lines))
    r = hpcontact("run", bad, "--out", tmp_path / "out")
    assert r.returncode == 1
    assert "reversed.yaml" in r.stderr and "contact[0].obstacle" in r.stderr
    assert "inside curve(13 points" in r.stderr
    assert not (tmp_path / "out" / "summary.json").exists()
