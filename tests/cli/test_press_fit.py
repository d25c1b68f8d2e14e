"""A shaft press-fitted into a shorter hub (examples/lame/press-fit-short-hub.yaml, axisymmetric):
the gap only where the partner is (no shaft row beyond the hub's end in contact, whichever body
carries the multipliers), Lamé's shrink-fit pressure for free ends at mid-length, and the two
carriers' answers against each other."""
import json
import math
import os

import pytest

from conftest import csv_rows, expect_refused

CASE = os.path.join("examples", "lame", "press-fit-short-hub.yaml")
HUB_CARRIES = "contact[0]={body: hub, edges: [bore], obstacle: {type: body, body: shaft, edges: [outer]}}"
HUB_END = 50.0


@pytest.fixture(scope="module")
def runs(hpcontact, root, tmp_path_factory):
    out = {}
    for name, sets in (("shaft", []), ("hub", ["--set", HUB_CARRIES])):
        folder = tmp_path_factory.mktemp(name)
        r = hpcontact("run", os.path.join(root, CASE), "--out", folder, "-q", *sets)
        assert r.returncode == 0, r.stderr
        out[name] = (json.loads((folder / "summary.json").read_text()), csv_rows(folder / "contact.csv"))
    return out


def test_no_row_beyond_the_hub_is_in_contact(runs):
    """The shaft runs 20 mm past the hub's end: its rows there are open (no pressure, no finite
    gap against the bore's extension), whichever body carries the multipliers; before, they
    were 'contact' at 126 N/mm² with a negative gap measured against the extended bore."""
    for carrier, (_, rows) in runs.items():
        beyond = [r for r in rows if r["body"] == "shaft" and float(r["Y"]) > HUB_END + 1e-6]
        assert len(beyond) >= 5, carrier
        for r in beyond:
            assert r["state"] == "open" and float(r["pressure"]) == 0, (carrier, r)
        inside = [r for r in rows if r["body"] == carrier and float(r["Y"]) < 45]
        assert inside and all(r["state"] == "contact" for r in inside), carrier


def test_mid_length_pressure_is_lames_for_free_ends(runs):
    """Ten times as long as its wall is thick, the hub holds Lamé's shrink-fit pressure for
    cylinders free to extend (sigma_z = 0) at mid-length: p = E d (c² − b²) / (2 b c²) = 78.75
    with E 210000, d 0.01, b 10, c 20, to 0.5 % (measured 0.06 % and 0.15 %: each carrier's
    pressure is per unit of its own surface, 0.1 % apart in radius and 3e-4 in axial stretch)."""
    lame = 210000 * 0.01 * (20 ** 2 - 10 ** 2) / (2 * 10 * 20 ** 2)
    for carrier, (_, rows) in runs.items():
        (mid,) = [float(r["pressure"]) for r in rows if r["body"] == carrier and float(r["Y"]) == 0]
        assert mid == pytest.approx(lame, rel=5e-3), carrier


def _at_mid_length(rows, body):
    """A body's row nearest z = 0: its radius X and pressure, and its surface's axial stretch
    dz/dZ there (z odd in Z about the mirror: z/Z of the next row, to O(Z²))."""
    own = sorted((r for r in rows if r["body"] == body), key=lambda r: float(r["Y"]))
    first, nxt = own[0], own[1]
    assert abs(float(first["Y"])) < 1e-2
    return float(first["X"]), float(first["pressure"]), float(nxt["y"]) / float(nxt["Y"])


def test_the_carriers_agree(runs):
    """Either body may carry the multipliers; each body's rows report the pressure per unit area
    of its own undeformed surface (its stresses' reference): the shaft's, and the hub's, at
    mid-length the same whichever carries, to 2e-6 (measured 9.3e-7 and 9.3e-7 at p = 8; before,
    the other body's rows held the carrier's multiplier per unit of the carrier's surface, 7e-4
    off). The two surfaces differ in radius (10 and 9.99) and stretch differently along the axis
    (Poisson: +2.25e-4 and -0.75e-4), so the ring forces 2 pi R p per unit of each body's own
    undeformed length differ by 3.0e-4 (what this test compared before); per unit deformed length,
    2 pi R p / (dz/dZ), the two bodies' agree to 2e-6 in each run (measured 1e-6: the action and
    reaction). The normal force, the resultant of the whole fit, agrees to 1e-5 (measured 6.8e-6
    at p = 8, 2.3e-4 at p = 4, 2.1e-5 at p = 10: the shaft's multipliers resolve the hub's end
    inside its elements, the hub's at its own last node)."""
    for body in ("shaft", "hub"):
        (_, p_shaft, _), (_, p_hub, _) = (_at_mid_length(runs[c][1], body) for c in ("shaft", "hub"))
        assert p_shaft == pytest.approx(p_hub, rel=2e-6), body
    for carrier, (_, rows) in runs.items():
        (R_s, p_s, st_s), (R_h, p_h, st_h) = (_at_mid_length(rows, b) for b in ("shaft", "hub"))
        assert abs(R_s * p_s / (R_h * p_h) - 1) == pytest.approx(3.0e-4, abs=2e-5), carrier
        assert R_s * p_s / st_s == pytest.approx(R_h * p_h / st_h, rel=2e-6), carrier
    radial = {c: abs(s["contact_pairs"][0]["resultant"][0]) for c, (s, _) in runs.items()}
    assert radial["shaft"] == pytest.approx(radial["hub"], rel=1e-5)
    for s, _ in runs.values():
        pair = s["contact_pairs"][0]
        # a ring pressure's resultant is radial: the normal force is its magnitude, positive
        assert pair["normal_force"] == pytest.approx(abs(pair["resultant"][0]), rel=1e-9)
        assert pair["normal_force"] > 0


def test_the_hub_end_is_singular_whichever_body_carries(runs):
    """The hub's end closes on the shaft: its peak is reported as a singular point (the hub's
    corner at (9.99, 50), the peak no converged value, a strength fitted from the pressures beyond
    the elements touching it, rising towards it), whichever body carries the multipliers; the
    mirror z = 0 and the shaft's open end are none; pressure_max is the largest away from it."""
    for carrier, (summary, rows) in runs.items():
        pair = summary["contact_pairs"][0]
        (sp,) = pair["singular_points"]
        assert sp["at"] == pytest.approx([9.99, HUB_END], abs=1e-9), carrier
        assert "body 'hub' (node 28)" in sp["where"] and sp["peak_converged"] is False
        if carrier == "shaft":  # the shaft's point that the hub's deformed corner touches
            shaft = sorted((float(r["Y"]), float(r["y"])) for r in rows if r["body"] == "shaft")
            below = max(p for p in shaft if p[0] <= sp["s"])
            above = min(p for p in shaft if p[0] > sp["s"])
            w = (sp["s"] - below[0]) / (above[0] - below[0])
            touched = below[1] + w * (above[1] - below[1])  # that point's deformed z
            assert touched == pytest.approx(sp["at_deformed"][1], abs=2e-4)
            assert sp["s"] < HUB_END - 5e-3
        else:  # the hub's own end
            assert sp["s"] == pytest.approx(HUB_END, abs=1e-12)
        assert sp["fit"]["exponent"] > 0.05 and sp["fit"]["points"] >= 6, carrier
        assert pair["pressure_max"] < sp["peak"], carrier
        own = [float(r["pressure"]) for r in rows if r["body"] == carrier
               and abs(float(r["Y"]) - sp["s"]) >= sp["pressure_max_beyond"] * (1 + 1e-6)]
        assert pair["pressure_max"] == pytest.approx(max(own), rel=1e-10), carrier
        assert any("unbounded" in w for w in summary["warnings"]), carrier


def test_cuts_that_repeat_the_residuals_stop_at_once(hpcontact, root, tmp_path):
    """The interference is in the geometry, not the load: with too few Newton iterations every
    cut of the first step fails with the same residuals. The run stops at the first repeat (one
    cut, not five) and says why; a load that a cut does change (Hertz) goes through its cuts."""
    r = hpcontact("run", os.path.join(root, CASE), "--out", tmp_path / "fit", "-q",
                  "--set", "solver.max_iterations=2")
    assert r.returncode != 0
    assert "failed after 1 cuts" in r.stderr and "repeated the same residuals" in r.stderr, r.stderr
    assert "an interference" in r.stderr
    r = hpcontact("run", os.path.join(root, "examples", "hertz", "p8.yaml"), "--out", tmp_path / "hertz",
                  "-q", "--set", "solver.max_iterations=1")
    assert r.returncode != 0
    assert "failed after 5 cuts" in r.stderr and "repeated the same residuals" not in r.stderr, r.stderr


def test_a_ramped_interference_presses_step_by_step_to_the_same_fit(runs, hpcontact, root, tmp_path):
    """contact[].interference: ramp relieves the input's overlap with the displacement factor:
    the hub carrying, in four load steps, none cut, at most 8 Newton iterations each (4–6
    measured); the ring force grows with the factor (each step's resultant f times the last's
    to 1e-3: 1.6e-4 measured, the contact's geometry changes a little on the way) and ends at the
    fit the unramped run finds at once: normal force, peak pressure and strain energy to 1e-8."""
    out = tmp_path / "ramp"
    ramped = HUB_CARRIES[:-1] + ", interference: ramp}"
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q", "--set", ramped,
                  "--set", "solver.load_steps=4")
    assert r.returncode == 0, r.stderr
    steps = csv_rows(out / "path.csv")
    assert [float(s["displacement_factor"]) for s in steps] == [0.25, 0.5, 0.75, 1.0]
    assert all(int(s["iterations"]) <= 8 for s in steps)
    last = float(steps[-1]["resultant_x"])
    for s in steps:
        assert float(s["resultant_x"]) == pytest.approx(float(s["displacement_factor"]) * last, rel=1e-3)
    summary = json.loads((out / "summary.json").read_text())
    at_once, _ = runs["hub"]
    for key in ("normal_force", "pressure_max"):
        assert summary["contact_pairs"][0][key] == pytest.approx(at_once["contact_pairs"][0][key], rel=1e-8), key
    assert summary["strain_energy"] == pytest.approx(at_once["strain_energy"], rel=1e-8)


def test_a_ramp_is_refused_where_it_means_nothing(hpcontact, root, tmp_path):
    """The penalty takes an overlap as a penetration from the start: interference: ramp with
    enforcement: penalty is refused naming the key, before any solve."""
    expect_refused(hpcontact, os.path.join(root, CASE), tmp_path / "out",
                   ["contact[0].enforcement=penalty", "contact[0].penalty=2.1e8", "contact[0].interference=ramp"],
                   "contact[0].interference", 2)


def test_auto_lets_the_hub_carry_and_says_why(runs, hpcontact, root, tmp_path):
    """contact[].carrier: auto on the input as written (the shaft named as the pair's body): the
    hub, whose bore lies within the shaft's face, carries; summary.json's `carrier` says so and
    why; contact.csv is the hub-carried run's, byte for byte. normal_direction, written for the
    force on the shaft (-x), turns with the swap to the hub's (+x): the same positive normal
    force as the hub-carried run's radial resultant."""
    out = tmp_path / "auto"
    r = hpcontact("run", os.path.join(root, CASE), "--out", out, "-q", "--set", "contact[0].carrier=auto",
                  "--set", "contact[0].normal_direction=[-1, 0]")
    assert r.returncode == 0, r.stderr
    pair = json.loads((out / "summary.json").read_text())["contact_pairs"][0]
    assert pair["body"] == "hub" and pair["obstacle"] == "body 'shaft'"
    assert pair["carrier"].startswith("auto: body 'hub' carries: its contact edges lie within body 'shaft''s")
    (hub_summary, hub_rows) = runs["hub"]
    assert hub_summary["contact_pairs"][0]["carrier"] == "as written: body 'hub'"
    assert csv_rows(out / "contact.csv") == hub_rows
    assert pair["normal_force"] == pytest.approx(hub_summary["contact_pairs"][0]["resultant"][0], rel=1e-12)
    assert pair["normal_force"] > 0
