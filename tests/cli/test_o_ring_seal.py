"""The O-ring seal example (issue 43, item 5: examples/o-ring/o-ring-seal.yaml): a cord of 3.53
mm of incompressible rubber in a groove profile, squeezed by a plate to a gap of 0.1 mm, then
pressurised from the left by two penetrating follower pressures. Checked against what holds
independently of the solve: the body's balance, the fluid's resultant from the gland's height,
where the pressures stop, the seal criterion and the way the plate zone moves towards the
extrusion gap."""
import json
import math
import os
import subprocess
import sys

import pytest

A = 3.53 / 2                     # the cord's radius, its centre undeformed at (0, A)
GLAND = 2.85                     # the plate's final height above the groove bottom y = 0
WALL_X = 1.77                    # the groove wall on the sealed side (right)


def example(root):
    return os.path.join(root, "examples", "o-ring", "o-ring-seal.yaml")


def run_at(hpcontact, root, out, pressure, steps_per_unit=4):
    """The example at system pressure `pressure`, 1/steps_per_unit of it a load step."""
    sets = [f"bodies[0].loads[0].pressure={pressure}", f"bodies[0].loads[1].pressure={pressure}",
            f"solver.stages[1].steps={max(1, round(pressure * steps_per_unit))}"]
    args = ["run", example(root), "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args, timeout=60)
    assert r.returncode == 0, r.stderr
    return json.load(open(os.path.join(out, "summary.json")))


@pytest.fixture(scope="module")
def sealed(hpcontact, root, tmp_path_factory):
    """The example as written: system pressure 4 N/mm²."""
    out = tmp_path_factory.mktemp("seal")
    r = hpcontact("run", example(root), "--out", out, "-q", timeout=60)
    assert r.returncode == 0, r.stderr
    return json.load(open(out / "summary.json"))


def test_the_fluid_acts_over_the_glands_height_and_the_contacts_carry_it(sealed):
    """A pressure p on a curve pushes it by p times the curve's chord turned: its x resultant is
    p times the height between its ends. The two pressures run from the plate's contact (y =
    2.85 deformed) down to the bottom's (y = 0) without a gap between them: p × 2.85 along x,
    which the contacts carry back (nothing else holds the ring)."""
    (balance,) = sealed["reactions"]["balance"]
    p = 4.0
    assert balance["loads"][0] == pytest.approx(p * GLAND, rel=1e-9)
    assert balance["contact"][0] == pytest.approx(-p * GLAND, rel=1e-9)
    assert balance["reactions"] == [0.0, 0.0]
    assert balance["relative"] < 1e-12
    assert sealed["equilibrium_residual"] < 1e-12


def test_the_pressures_stop_inside_the_plates_and_the_bottoms_contact(sealed):
    """Each pressure stops at a point of the outline (radius A about (0, A)) inside its pair's
    contact zone (undeformed): the upper one on the upper half at the plate's zone, the lower
    one on the lower half at the groove's bottom; neither leaks nor wets more than half the
    outline."""
    up, down = sealed["penetration"]
    plate, groove = sealed["contact_pairs"][1], sealed["contact_pairs"][0]
    for pen in (up, down):
        x, y = pen["stop"]
        assert math.hypot(x, y - A) == pytest.approx(A, abs=1e-9)
        assert pen["leaks"] is False
        assert 0 < pen["wetted_length"] < math.pi * A
    assert (up["contact"], down["contact"]) == (1, 0)
    plate_x = sorted(x for x, _ in plate["gamma_star"])
    assert up["stop"][1] > A and plate_x[0] < up["stop"][0] < plate_x[-1]
    bottom_x = sorted(end[0] for end, (_, y) in zip(groove["gamma_star"], groove["gamma_star_deformed"])
                      if y < 0.05)   # the ends of the zone on the bottom (deformed y = 0)
    assert len(bottom_x) == 2
    assert down["stop"][1] < A and bottom_x[0] < down["stop"][0] < bottom_x[-1]
    assert not sealed.get("warnings")


def test_the_seal_holds_where_the_peak_contact_pressure_exceeds_the_system_pressure(sealed):
    """Sealed (no leak): the peak contact pressure on the plate and on the groove both above
    the system pressure of 4 N/mm²."""
    for pair in sealed["contact_pairs"]:
        assert pair["pressure_max"] > 4.0


def test_the_plate_zone_moves_towards_the_gap_and_stays_inside_the_wall(hpcontact, root, tmp_path):
    """Raised from 1 to 4.5 N/mm², the pressure pushes the ring towards the sealed side: the
    plate zone's deformed right end moves right at every pressure, but stays left of the groove
    wall's x = 1.77 (no extrusion up to 4.5 N/mm²: README.md), and the seal holds at each."""
    ends = []
    for i, p in enumerate((1.0, 2.5, 4.5)):
        s = run_at(hpcontact, root, tmp_path / "runs" / f"0{i + 1}-p", p)
        assert not any(pen["leaks"] for pen in s["penetration"])
        assert all(pair["pressure_max"] > p for pair in s["contact_pairs"])
        ends.append(max(x for x, _ in s["contact_pairs"][1]["gamma_star_deformed"]))
    assert ends[0] < ends[1] < ends[2] < WALL_X
    # scripts/plot_seal.py reads the same figures from the run folders (a study's layout)
    r = subprocess.run([sys.executable, os.path.join(root, "scripts", "plot_seal.py"), tmp_path,
                        "--units", "mm,N"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    table = [line.split(",") for line in r.stdout.splitlines()[1:4]]
    assert [float(row[0]) for row in table] == [1.0, 2.5, 4.5]
    assert [float(row[3]) for row in table] == pytest.approx(ends, abs=1e-4)
    assert "extrusion onset: not reached" in r.stdout
    assert os.path.getsize(tmp_path / "seal.png") > 0


def test_the_squeeze_curve_stiffens(hpcontact, root, tmp_path):
    """Squeeze alone (no pressure): the plate force grows faster than the squeeze (each quarter of
    the squeeze adds more force than the one before, the contact widening), and the groove
    carries the plate's force back: equal and opposite along y."""
    s = run_at(hpcontact, root, tmp_path, 0, steps_per_unit=0)
    plate, groove = s["contact_pairs"][1], s["contact_pairs"][0]
    assert groove["resultant"][1] == pytest.approx(-plate["resultant"][1], rel=1e-9)
    forces = [0.0]
    with open(tmp_path / "contact_history.csv") as f:
        header = f.readline().strip().split(",")
        for line in f:
            row = dict(zip(header, line.strip().split(",")))
            if row["pair"] == "1" and float(row["load_factor"]) == 0.0:
                forces.append(float(row["normal_force"]))
    steps = [b - a for a, b in zip(forces, forces[1:])]
    assert len(steps) >= 4 and all(b > a > 0 for a, b in zip(steps, steps[1:]))


def test_the_onset_is_interpolated_between_the_runs_that_bracket_the_wall(root):
    """plot_seal.onset: the zone end 1.70 at 4 and 1.90 at 5 N/mm² reaches 1.77 at 4.35."""
    sys.path.insert(0, os.path.join(root, "scripts"))
    from plot_seal import onset
    rows = [{"p_s": 3.0, "plate_zone_end": 1.6}, {"p_s": 4.0, "plate_zone_end": 1.7},
            {"p_s": 5.0, "plate_zone_end": 1.9}]
    assert onset(rows, WALL_X) == pytest.approx(4.35, abs=1e-12)
    assert onset(rows[:2], WALL_X) is None


def test_the_fronts_are_followed_and_a_front_that_does_not_settle_is_said(hpcontact, root, tmp_path):
    """Ramped to 8 N/mm² in steps of 0.25: with the fronts moved at every Newton iterate the
    solve jumped at 4.75 N/mm² to the state wetted all round (an incompressible ring does not
    feel it: the plate back at its squeeze force 3.42 N/mm, its peak 2.33 below p_s, the step
    before at 6.88 above it) and reported a leak, or failed there. The fronts are now held through
    each Newton solve and moved between solves: the sealed state is followed to 4.92 N/mm²
    (measured; 4.94 with steps of 0.125), where the groove side's front reaches the end of its
    chain and back (its contact pressure there about the fluid's); the run stops saying so, its
    last converged state sealed."""
    out = tmp_path / "ramp"
    r = hpcontact("run", example(root), "--out", out, "-q", "--set", "bodies[0].loads[0].pressure=8",
                  "--set", "bodies[0].loads[1].pressure=8", "--set", "solver.stages[1].steps=32",
                  timeout=120)
    assert r.returncode == 1, r.stderr
    assert "the fronts of the penetrating pressures did not settle in 12 solves" in r.stderr, r.stderr
    assert "bodies[0].loads[1]: wetted length" in r.stderr and "(leaking)" in r.stderr, r.stderr
    good = json.load(open(out / "last-good" / "summary.json"))
    p_s = 8 * good["loads_factor"]
    assert 4.8 < p_s < 5.0, p_s
    assert not any(p["leaks"] for p in good["penetration"])
    assert good["contact_pairs"][1]["pressure_max"] > p_s
