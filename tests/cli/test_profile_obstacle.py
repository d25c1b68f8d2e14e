"""A rigid profile with corners (contact[].obstacle.type: profile): one segment is the plane
through it, a closed square rounded by half its side is the circle, the O-ring groove as one
profile squeezes as the four planes, a ring slid over a sharp convex corner converges at every
step, and a wrong profile is refused naming the key and the point."""
import json
import os
import re

from conftest import csv_rows, expect_refused


def run(hpcontact, case, out, *settings):
    args = ["run", case, "--out", out, "-q"]
    for s in settings:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == 0, r.stderr
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def numbers(value, path=""):
    """The numeric leaves of a summary, by their path."""
    if isinstance(value, dict):
        for k, v in value.items():
            yield from numbers(v, f"{path}.{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(value, (int, float)) and not isinstance(value, bool):
        yield path, float(value)


def hertz_with(root, tmp_path, obstacle):
    """examples/hertz/p8.yaml (a cylinder pressed on a plane to F/2 = 35000) with another obstacle."""
    folder = os.path.join(root, "examples", "hertz")
    text = open(os.path.join(folder, "p8.yaml")).read()
    plane = "obstacle: {type: plane, point: [0, 0], normal: [0, 1]}"
    assert plane in text
    path = tmp_path / "case.yaml"
    path.write_text(text.replace(plane, "obstacle: " + obstacle))
    (tmp_path / "reference-pressure.csv").write_text(open(os.path.join(folder, "reference-pressure.csv")).read())
    return path


def test_one_segment_is_the_plane_through_it(hpcontact, root, tmp_path):
    """A profile of one segment along y = 0 gives the plane's run to round-off: every number of
    summary.json and of contact.csv (the frame is the same line)."""
    plane = run(hpcontact, hertz_with(root, tmp_path, "{type: plane, point: [0, 0], normal: [0, 1]}"),
                tmp_path / "plane")
    segment = run(hpcontact, hertz_with(root, tmp_path, "{type: profile, points: [[-5, 0], [15, 0]]}"),
                  tmp_path / "segment")
    assert segment["converged"] and segment["contact"]["obstacle"].startswith("profile(")
    a, b = dict(numbers(plane)), dict(numbers(segment))
    assert a.keys() == b.keys()
    scale = {k: max(1.0, abs(v)) for k, v in a.items()}
    worst = max((abs(a[k] - b[k]) / scale[k], k) for k in a if k != ".wall_time_s")
    assert worst[0] < 1e-9, worst  # measured: identical (0)
    rows_a, rows_b = csv_rows(tmp_path / "plane" / "contact.csv"), csv_rows(tmp_path / "segment" / "contact.csv")
    assert len(rows_a) == len(rows_b) > 0
    for column in ("x", "y", "gap", "pressure", "pressure_from_stress", "s", "minus_sigma_nn"):
        values = [float(r[column]) for r in rows_a]
        size = max(1.0, max(abs(v) for v in values))
        assert max(abs(v - float(r[column])) for v, r in zip(values, rows_b)) < 1e-9 * size, column


def test_a_rounded_square_is_the_circle(hpcontact, root, tmp_path):
    """A closed square of side 100 with every corner rounded by 50, clockwise (the cylinder
    outside it), is the disc of radius 50 about (0, -50): the cylinder pressed on it deforms as
    on type: circle, to round-off."""
    circle = run(hpcontact, hertz_with(root, tmp_path, "{type: circle, center: [0, -50], radius: 50}"),
                 tmp_path / "circle")
    square = run(hpcontact, hertz_with(root, tmp_path, "{type: profile, closed: true, fillet: 50, "
                                       "points: [[-50, -100], [-50, 0], [50, 0], [50, -100]]}"),
                 tmp_path / "square")
    assert square["converged"] and square["newton_iterations"] == circle["newton_iterations"]
    for key in ("strain_energy",):
        assert abs(square[key] - circle[key]) < 1e-10 * abs(circle[key])
    r_c, r_s = circle["contact"]["resultant"], square["contact"]["resultant"]
    assert max(abs(p - q) for p, q in zip(r_c, r_s)) < 1e-9 * abs(r_c[1])
    rows_c, rows_s = csv_rows(tmp_path / "circle" / "contact.csv"), csv_rows(tmp_path / "square" / "contact.csv")
    for column in ("x", "y", "gap", "minus_sigma_nn"):
        values = [float(r[column]) for r in rows_c]
        size = max(1.0, max(abs(v) for v in values))
        assert max(abs(v - float(r[column])) for v, r in zip(values, rows_s)) < 1e-9 * size, column


def history(out, pair):
    return [r for r in csv_rows(os.path.join(out, "contact_history.csv")) if r["pair"] == str(pair)]


def test_groove_as_one_profile_squeezes_as_four_planes(hpcontact, root, tmp_path):
    """examples/o-ring/o-ring-profile-groove.yaml (bottom, walls, chamfered mouth, filleted
    bottom corners: one profile) against o-ring-groove.yaml (four planes), at squeezes of 2 and 3
    mm (the walls reached at the last step and at 2.25 mm): at every step the plate's force is the
    same to 1e-9, and the profile's resultant is the sum of the bottom's and the walls'."""
    folder = os.path.join(root, "examples", "o-ring")
    for squeeze in (2, 3):
        move = f"contact[1].obstacle.displacement=[0, -{squeeze}]"
        run(hpcontact, os.path.join(folder, "o-ring-groove.yaml"), tmp_path / f"planes{squeeze}", move)
        s = run(hpcontact, os.path.join(folder, "o-ring-profile-groove.yaml"), tmp_path / f"profile{squeeze}", move)
        assert s["converged"] and len(s["contact_pairs"]) == 2
        planes = [history(tmp_path / f"planes{squeeze}", k) for k in range(4)]
        profile = [history(tmp_path / f"profile{squeeze}", k) for k in range(2)]
        assert len(profile[1]) == len(planes[1]) == 4
        walls = 0.0
        for step in range(4):
            plate = float(planes[1][step]["normal_force"])
            assert abs(float(profile[1][step]["normal_force"]) - plate) < 1e-9 * plate
            for c in ("resultant_x", "resultant_y"):
                parts = sum(float(planes[k][step][c]) for k in (0, 2, 3))
                assert abs(float(profile[0][step][c]) - parts) < 1e-9 * plate, (squeeze, step, c)
            walls = float(planes[3][step]["normal_force"])
        assert walls > 0.5  # the walls carry load at the end: the profile's walls are used


def test_a_ring_slid_over_a_sharp_corner_converges_at_every_step(hpcontact, root, tmp_path):
    """The ring of o-ring-groove.yaml pressed 1 mm by a plate onto a ledge (profile [[-40, 0], [3,
    0], [3, -30]]: a plateau with a sharp convex corner at x = 3), then the ledge slid by -6 in 12
    steps, carrying the contact over the corner to x = -3 (the ring touching the corner alone):
    every step converges, without a cut, with exact contact (collocation and mortar) and with the
    penalty; the force falls as the support moves off the ring's axis."""
    text = open(os.path.join(root, "examples", "o-ring", "o-ring-groove.yaml")).read()
    body = text[text.index("bodies:"):text.index("contact:\n")]
    case = tmp_path / "slide.yaml"
    case.write_text("case: slide\n" + body + """contact:
  - body: ring
    edges: [bottom]
    obstacle: {type: profile, points: [[-40, 0], [3, 0], [3, -30]], displacement: [-6, 0]}
  - body: ring
    edges: [top]
    obstacle: {type: plane, point: [0, 20], normal: [0, -1], displacement: [0, -1]}
solver:
  stages:
    - {displacements_x: 0, displacements_y: 1, steps: 2}
    - {displacements_x: 1, displacements_y: 1, steps: 12}
discretization: {degree: 4}
""")
    variants = {"collocation": [], "mortar": ["contact[0].constraint=mortar"],
                "penalty": ["contact[0].enforcement=penalty", "contact[0].penalty=1e4",
                            "contact[1].enforcement=penalty", "contact[1].penalty=1e4"]}
    for name, settings in variants.items():
        s = run(hpcontact, case, tmp_path / name, *settings)
        assert s["converged"], name
        rows = history(tmp_path / name, 0)
        factors = [float(r["displacement_factor_x"]) for r in rows]
        expected = [0, 0] + [k / 12 for k in range(1, 13)]
        assert len(factors) == len(expected) and max(abs(a - b) for a, b in zip(factors, expected)) < 1e-9, name
        force = [float(r["normal_force"]) for r in rows]
        assert force[-1] > 0 and force[-1] < 0.5 * force[1], (name, force)


def test_profile_mistakes_are_named(hpcontact, root, tmp_path):
    """Fewer than 2 points, a repeated point, a fillet that does not fit, a chain that crosses
    itself, fillets of the wrong count, and profile keys on another type: refused before
    solving, naming the key, the point and the file."""
    case = os.path.join(root, "examples", "o-ring", "o-ring-profile-groove.yaml")
    groove = "[[-14, 20], [-11.3, 20], [-10.3, 19], [-10.3, 0], [10.3, 0], [10.3, 19], [11.3, 20], [14, 20]]"
    cases = [
        (["contact[0].obstacle.points=[[0, 0]]"], "contact[0].obstacle.points (from --set): must have at least 2 entries"),
        (["contact[0].obstacle.points=[[-14, 20], [-11.3, 20], [-11.3, 20], [-10.3, 0], [10.3, 0], "
          "[10.3, 19], [11.3, 20], [14, 20]]"],
         "contact[0].obstacle.points[2]: repeats the point before it, points[1]"),
        (["contact[0].obstacle.fillet=[0, 0, 20, 0.4, 0, 0]"],
         "contact[0].obstacle.fillet[2]: the fillet of radius 20 at points[3] needs 20 of the segment "
         "points[2]–points[3] (length 19)"),
        (["contact[0].obstacle.points=[[-14, 20], [-11.3, 20], [-10.3, 19], [-10.3, 0], [10.3, 0], "
          "[10.3, 19], [-12, 19.5], [14, 20]]"],
         "contact[0].obstacle.points[5]: the chain crosses itself: the segment points[5]–points[6] meets "
         "the segment points[1]–points[2]"),
        (["contact[0].obstacle.fillet=[0.4, 0.4]"], "contact[0].obstacle.fillet: has 2 radii for the 6 corners"),
        (["contact[0].obstacle.fillet=0", f"contact[0].obstacle.points={groove}", "contact[0].obstacle.closed=true"],
         "contact[0].obstacle.points[0]: the chain turns back on itself at points[0]"),
        (["contact[1].obstacle.fillet=1"], "contact[1].obstacle.fillet: does nothing for type: plane"),
        (["contact[1].obstacle.closed=true"], "contact[1].obstacle.closed: does nothing for type: plane"),
    ]
    for i, (settings, message) in enumerate(cases):
        # given by --set: the key named with "(from --set)", a usage error (exit 2)
        key, cause = message.split(": ", 1)
        key = key.replace(" (from --set)", "")
        expect_refused(hpcontact, case, tmp_path / f"out{i}", settings, f"{key} (from --set): {cause}", 2)
