"""Singular points: where a contact zone is closed up to an end or a corner of a contact
boundary the exact pressure is unbounded. The run says so (summary.json `singular_points`, a
warning), fits the singularity's strength, and keeps the peak out of `pressure_max`.

Sadowsky's rigid flat punch (examples/flat-punch/flat-punch.yaml, a hand-graded mesh from
scripts/flat_punch_mesh.py) against the closed form p(x) = P / (pi sqrt(a² − x²)), whose corner
singularity is K d^(−1/2) with K = P / (pi sqrt(2 a)); smooth zones and zones that end on a
mirror report none."""
import json
import math
import os
import subprocess
import sys

import pytest

from conftest import csv_rows

CASE = os.path.join("examples", "flat-punch", "flat-punch.yaml")
P, A = 100.0, 1.0  # the script's defaults: the force on the whole punch, its half width
K_SADOWSKY = P / (math.pi * math.sqrt(2 * A))


def run(hpcontact, problem, folder, *sets):
    r = hpcontact("run", problem, "--out", folder, "-q", *sets)
    assert r.returncode == 0, r.stderr
    return json.loads((folder / "summary.json").read_text()), csv_rows(folder / "contact.csv"), r.stderr


@pytest.fixture(scope="module")
def punch(hpcontact, root, tmp_path_factory):
    return run(hpcontact, os.path.join(root, CASE), tmp_path_factory.mktemp("punch"))


def test_the_example_is_what_the_script_writes(root):
    """The example is the mesh script's output with its defaults (so the test's P and a are)."""
    made = subprocess.run([sys.executable, os.path.join(root, "scripts", "flat_punch_mesh.py")],
                          capture_output=True, text=True, check=True).stdout
    with open(os.path.join(root, CASE)) as f:
        assert f.read() == made


def test_the_punch_corner_is_singular_with_sadowskys_strength(punch):
    """One singular point, the corner (a, 0); its exponent 1/2 to 0.005 and K, free and as a
    square-root singularity, within 1 % of Sadowsky's (measured +0.04 % and −0.08 %; 2 rings about
    the corner: −0.13 % and −0.22 %, 6 at p = 10: 0.01 % and −0.03 %)."""
    summary, _, stderr = punch
    (pair,) = summary["contact_pairs"]
    (sp,) = pair["singular_points"]
    assert sp["at"] == pytest.approx([A, 0.0], abs=1e-12)
    assert sp["peak_converged"] is False
    assert "end of the contact edges of body 'block'" in sp["where"]
    fit = sp["fit"]
    assert fit["exponent"] == pytest.approx(0.5, abs=5e-3)
    assert fit["strength"] == pytest.approx(K_SADOWSKY, rel=1e-2)
    assert fit["square_root_strength"] == pytest.approx(K_SADOWSKY, rel=1e-2)
    assert fit["points"] >= 6 and fit["from"] > sp["excluded_within"]
    assert "the pressure is unbounded at (1, 0)" in stderr
    assert any("unbounded" in w for w in summary["warnings"])


def test_pressure_max_is_the_largest_away_from_the_corner(punch):
    """pressure_max is the largest pressure farther than `pressure_max_beyond` from the corner:
    beyond the element touching it and 1 % of the zone's extent (a); below the corner's peak; the
    peak is the row at the corner."""
    summary, rows, _ = punch
    pair = summary["contact_pairs"][0]
    sp = pair["singular_points"][0]
    assert sp["pressure_max_beyond"] == pytest.approx(max(sp["excluded_within"], 0.01 * A), rel=1e-9)
    away = [float(r["pressure"]) for r in rows if A - float(r["X"]) >= sp["pressure_max_beyond"] * (1 + 1e-6)]
    assert pair["pressure_max"] == pytest.approx(max(away), rel=1e-10)
    (corner,) = [float(r["pressure"]) for r in rows if float(r["X"]) == A]
    assert sp["peak"] == pytest.approx(corner, rel=1e-10) and corner > 10 * pair["pressure_max"]


def test_the_pressure_is_sadowskys_inside_0_9_a(punch):
    """For |x| < 0.9 a the pressure is Sadowsky's to 0.1 % (measured 0.035 %; the block is finite,
    100 a)."""
    _, rows, _ = punch
    inside = [r for r in rows if float(r["X"]) < 0.9 * A]
    assert len(inside) > 10
    for r in inside:
        x = float(r["X"])
        assert float(r["pressure"]) == pytest.approx(P / (math.pi * math.sqrt(A * A - x * x)), rel=1e-3), x


def test_another_punch_and_material(hpcontact, root, tmp_path):
    """A mesh and problem the example was not tuned on (a = 2, P = 300, nu = 0.45, five rings
    about the corner at p = 6): K within 1 % (measured −0.05 % and −0.16 %)."""
    problem = tmp_path / "punch.yaml"
    made = subprocess.run([sys.executable, os.path.join(root, "scripts", "flat_punch_mesh.py"),
                           "--half-width", "2", "--force", "300", "--nu", "0.45", "--layers", "5",
                           "--degree", "6"], capture_output=True, text=True, check=True).stdout
    problem.write_text(made)
    summary, _, _ = run(hpcontact, problem, tmp_path / "out")
    (sp,) = summary["contact_pairs"][0]["singular_points"]
    K = 300 / (math.pi * math.sqrt(2 * 2))
    assert sp["at"] == pytest.approx([2, 0], abs=1e-12)
    assert sp["fit"]["strength"] == pytest.approx(K, rel=1e-2)
    assert sp["fit"]["square_root_strength"] == pytest.approx(K, rel=1e-2)


def test_too_coarse_to_fit_is_said(hpcontact, root, tmp_path):
    """One ring about the corner: its neighbours hold too few pressures to fit; the point is
    reported (its peak far above the mean) with no fit, and the warning says to refine."""
    problem = tmp_path / "punch.yaml"
    problem.write_text(subprocess.run([sys.executable, os.path.join(root, "scripts", "flat_punch_mesh.py"),
                                       "--ratio", "0.3", "--layers", "1"],
                                      capture_output=True, text=True, check=True).stdout)
    summary, _, stderr = run(hpcontact, problem, tmp_path / "out")
    (sp,) = summary["contact_pairs"][0]["singular_points"]
    assert sp["fit"] is None
    assert "too few pressures" in stderr and "refine the mesh towards it" in stderr


@pytest.mark.parametrize("case", [os.path.join("examples", "hertz", "p8.yaml"),
                                  os.path.join("examples", "tutorial", "punch.yaml"),
                                  os.path.join("examples", "lame", "shrink-fit.yaml"),
                                  os.path.join("examples", "hertz", "bilateral.yaml"),
                                  os.path.join("examples", "pin-in-hole", "pin-in-hole.yaml")])
def test_smooth_zones_and_mirrors_have_none(hpcontact, root, tmp_path, case):
    """Zones that end smoothly, or close up to a mirror (Hertz's half model at x = 0, a
    shrink fit's quarter at its symmetry lines, the pin's load line, where its pressure is
    largest and the fit alone would call it rising) have no singular point, and pressure_max is
    the largest pressure of all."""
    summary, rows, _ = run(hpcontact, os.path.join(root, case), tmp_path)
    for pair in summary["contact_pairs"]:
        assert "singular_points" not in pair, (case, pair["singular_points"])
        own = [float(r["pressure"]) for r in rows if int(r["pair"]) == pair["pair"] and r["body"] == pair["body"]]
        assert pair["pressure_max"] == pytest.approx(max(own), rel=1e-10)


def test_hp_from_a_coarse_mesh_grades_towards_the_corner(hpcontact, root, tmp_path):
    """examples/flat-punch/coarse-hp.yaml: a 4 x 4 mesh of the block, p = 4, hp to 3e-4. There is
    no Γ* (the zone is closed up to the corner): hp grades towards the singular point and
    estimates the error away from it; it reaches the tolerance by itself (measured 12 steps,
    3321 DOF, about 1 s), the pressure within 0.1 % of Sadowsky's for |x| < 0.9 a (measured
    0.019 %) and K within 1 % (measured −0.03 %, K½ −0.006 %). Before, hp refused it: "no end
    of a contact zone found"."""
    summary, rows, _ = run(hpcontact, os.path.join(root, "examples", "flat-punch", "coarse-hp.yaml"),
                           tmp_path)
    assert summary["converged"] and summary["adapt"]["stopped"] == "tolerance reached"
    assert summary["adapt"]["estimated_error"]["pressure_rel_L2"] <= 3e-4
    history = summary["adapt"]["history"]
    assert len(history) > 3 and history[-1]["elements"] > history[0]["elements"]
    (sp,) = summary["contact_pairs"][0]["singular_points"]
    assert sp["at"] == pytest.approx([A, 0.0], abs=1e-12)
    assert sp["fit"]["strength"] == pytest.approx(K_SADOWSKY, rel=1e-2)
    assert sp["fit"]["square_root_strength"] == pytest.approx(K_SADOWSKY, rel=1e-2)
    inside = [r for r in rows if float(r["X"]) < 0.9 * A]
    assert len(inside) > 5
    for r in inside:
        x = float(r["X"])
        assert float(r["pressure"]) == pytest.approx(P / (math.pi * math.sqrt(A * A - x * x)), rel=1e-3), x


@pytest.mark.parametrize("carrier", ["punch", "block"])
def test_an_elastic_punchs_corner_is_one_point_whichever_body_carries(hpcontact, root, tmp_path, carrier):
    """A steel punch with sharp corners on the steel block (scripts/flat_punch_mesh.py
    --elastic-punch): the punch's corner is the end of its own contact edges and stands on the
    end of the block's; it is one singular point (not one per body), at (a, 0), whichever body
    carries the multipliers, with the pressure rising towards it (between equal elastic bodies
    more weakly than at a rigid punch's corner: measured λ 0.23)."""
    problem = tmp_path / "punch.yaml"
    problem.write_text(subprocess.run([sys.executable, os.path.join(root, "scripts", "flat_punch_mesh.py"),
                                       "--elastic-punch", "--layers", "3", "--degree", "6"],
                                      capture_output=True, text=True, check=True).stdout)
    sets = [] if carrier == "punch" else [
        "--set", "contact[0]={body: block, edges: [face], obstacle: {type: body, body: punch, edges: [bottom]}}"]
    summary, _, stderr = run(hpcontact, problem, tmp_path / "out", *sets)
    (sp,) = summary["contact_pairs"][0]["singular_points"]
    assert sp["at"] == pytest.approx([A, 0.0], abs=1e-9)
    assert 0.05 < sp["fit"]["exponent"] < 0.5
    assert stderr.count("the pressure is unbounded") == 1


@pytest.mark.parametrize("args, steps_at_most, follows_a_second_end", [
    (["--rounded", "0.5", "--layers", "1", "--ratio", "0.3", "--degree", "4"], 6, False),
    (["--rounded", "0.5", "--layers", "1", "--ratio", "0.3", "--degree", "4", "--half-width", "0.93"], 6, False),
    (["--rounded", "2", "--layers", "2", "--degree", "4"], 8, True),
])
def test_hp_reaches_1e_3_on_a_punch_with_rounded_corners(hpcontact, root, tmp_path, args, steps_at_most,
                                                         follows_a_second_end):
    """A rigid punch whose corners are rounded (a curve obstacle: the flat, then an arc, through
    points), from a coarse mesh at p = 4: hp reaches 1e-3 of the pressure by itself (measured 5,
    5 and 7 steps, about 1 s). With a rounding of 2 a the spline through the points makes the zone
    open briefly near the flat's end (two Γ* within one coarse element, one served): the estimate's
    error peaks at the second, and hp refines towards it from then on (before, the estimate
    stalled: 1.4 % to 2.6 % over the last steps of 12)."""
    problem = tmp_path / "punch.yaml"
    made = subprocess.run([sys.executable, os.path.join(root, "scripts", "flat_punch_mesh.py"), *args],
                          capture_output=True, text=True, check=True).stdout
    problem.write_text(made + "adapt: {method: hp, tolerance: 1e-3}\n")
    r = hpcontact("run", problem, "--out", tmp_path / "out")
    assert r.returncode == 0, r.stderr
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    assert summary["adapt"]["stopped"] == "tolerance reached"
    assert summary["adapt"]["estimated_error"]["pressure_rel_L2"] <= 1e-3
    assert len(summary["adapt"]["history"]) <= steps_at_most + 1
    assert "singular_points" not in summary["contact_pairs"][0]
    assert ("which no refinement follows" in r.stdout + r.stderr) == follows_a_second_end


def test_positions_are_given_undeformed_and_deformed(punch, hpcontact, root, tmp_path):
    """Where a position is reported it is reported twice: the zone's extent along the surface of
    the undeformed points (what the linear theory's closed forms compare with) and of the
    deformed ones (zone.deformed), a singular point's `at` and `at_deformed` (the corner's row of
    contact.csv, X and x). Hertz p = 8 (b/R = 0.2): the deformed zone ends at the deformed Γ*,
    2.5 % inside the undeformed one."""
    summary, rows, _ = punch
    (sp,) = summary["contact_pairs"][0]["singular_points"]
    (corner,) = [r for r in rows if float(r["X"]) == A]
    assert sp["at_deformed"] == pytest.approx([float(corner["x"]), float(corner["y"])], abs=1e-9)
    assert sp["at_deformed"][1] < -1e-4  # pushed down
    hertz, _, _ = run(hpcontact, os.path.join(root, "examples", "hertz", "p8.yaml"), tmp_path)
    pair = hertz["contact_pairs"][0]
    zone = pair["zone"]
    assert zone["to"] == pytest.approx(pair["gamma_star"][0][0], rel=1e-12)
    assert zone["deformed"]["to"] == pytest.approx(pair["gamma_star_deformed"][0][0], rel=1e-12)
    assert zone["deformed"]["to"] < 0.98 * zone["to"]
