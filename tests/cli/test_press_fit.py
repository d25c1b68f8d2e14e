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
    with E 210000, d 0.01, b 10, c 20, to 0.5 % (measured 0.06 % and 0.15 %: the two carriers'
    pressures are on surfaces 0.1 % apart in radius)."""
    lame = 210000 * 0.01 * (20 ** 2 - 10 ** 2) / (2 * 10 * 20 ** 2)
    for carrier, (_, rows) in runs.items():
        (mid,) = [float(r["pressure"]) for r in rows if r["body"] == carrier and float(r["Y"]) == 0]
        assert mid == pytest.approx(lame, rel=5e-3), carrier


def test_the_carriers_agree(runs):
    """Either body may carry the multipliers: the ring force per unit meridian length at
    mid-length, 2 pi r p, and the resultants' radial components are the same to 5e-4 (measured
    3.0e-4 and 3.0e-4: the one-sided constraint is posed on the carrier's surface, which the
    linear theory cannot tell from the other's at d / b = 1e-3, and the resultant takes in the
    singular peak at the hub's end, which each carrier resolves on its own edges)."""
    ring = {}
    for carrier, (_, rows) in runs.items():
        (row,) = [r for r in rows if r["body"] == carrier and float(r["Y"]) == 0]
        ring[carrier] = 2 * math.pi * float(row["X"]) * float(row["pressure"])
    assert ring["shaft"] == pytest.approx(ring["hub"], rel=5e-4)
    radial = {c: abs(s["contact_pairs"][0]["resultant"][0]) for c, (s, _) in runs.items()}
    assert radial["shaft"] == pytest.approx(radial["hub"], rel=5e-4)
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
