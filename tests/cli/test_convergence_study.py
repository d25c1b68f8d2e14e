"""scripts/convergence_study.py on examples/hertz/convergence.yaml --quick (seed §5.2.4, docs/cases.md §1
"Energy-norm convergence"): the CSV has the summary.json columns, the reference is extrapolated,
the p- and rp-curves converge at the measured rates and reach 1 % where they did when the study
was set up (examples/hertz/CONVERGENCE.md), the adaptive hp-version (hp.yaml, one run, its
adapt.history steps as points) reaches 1 % below the seed's 750 DOF and fits the exponential law
better than a power law, and failures are reported rather than hidden. About 15 s on 2 cores."""
import csv
import json
import math
import os
import subprocess
import sys

import pytest

from conftest import scaled_timeout

STUDY = os.path.join("examples", "hertz", "convergence.yaml")
REQUIRED = ["method", "mesh", "p", "dofs", "strain_energy", "energy_rel_percent",
            "e_L2_hertz_percent", "wall_time_s"]


def study_script(root, exe, *args, timeout=120):
    return subprocess.run([sys.executable, os.path.join(root, "scripts", "convergence_study.py"),
                           *map(str, args), "--hpcontact", exe], capture_output=True, text=True,
                          timeout=scaled_timeout(timeout))


@pytest.fixture(scope="module")
def quick(exe, root, tmp_path_factory):
    """The --quick study, run once for every test of this file."""
    out = tmp_path_factory.mktemp("convergence-quick")
    r = study_script(root, exe, os.path.join(root, STUDY), "--out", out, "--quick", "--jobs", 2)
    assert r.returncode == 0, r.stdout + r.stderr
    with open(out / "convergence.csv") as f:
        rows = list(csv.DictReader(f))
    data = json.loads((out / "convergence.json").read_text())
    return dict(out=out, rows=rows, json=data, stdout=r.stdout)


def curve(quick, label):
    """DOF-sorted (p, dofs, error) of a curve's successful runs."""
    pts = [(int(r["p"]), int(r["dofs"]), float(r["energy_rel_percent"]), float(r["strain_energy"]))
           for r in quick["rows"] if r["label"] == label and r["status"] == "ok"]
    return sorted(pts, key=lambda t: t[1])


def summary(quick, label):
    return next(c for c in quick["json"]["curves"] if c["label"] == label)


def test_csv_has_the_results_md_columns(quick):
    with open(quick["out"] / "convergence.csv") as f:
        header = next(csv.reader(f))
    assert header[:len(REQUIRED)] == REQUIRED
    for r in quick["rows"]:
        if r["status"] == "ok":
            assert int(r["dofs"]) > 0 and float(r["strain_energy"]) > 0
            assert float(r["energy_rel_percent"]) >= 0 and float(r["wall_time_s"]) > 0
            assert r["e_L2_hertz_percent"] != ""
    methods = {r["method"] for r in quick["rows"]}
    assert {"reference", "h", "p", "rp", "hp"} <= methods


def test_reference_extrapolated_and_reported(quick):
    """Three reference runs (displacement control: energies fall with p), eq. 4.14 gives a value
    just below the highest p's, and every row names both it and the highest-p value."""
    ref = quick["json"]["reference"]
    runs = [r for r in ref["runs"] if r["status"] == "ok"]
    assert len(runs) == 3
    u = [r["strain_energy"] for r in runs]
    assert u[0] > u[1] > u[2]
    assert ref["extrapolated"] is not None and "eq. 4.14" in ref["note"]
    assert ref["energy"] == ref["extrapolated"] and ref["pmax"] == u[2]
    assert 0 < u[2] - ref["extrapolated"] < 1e-4                 # measured 9.4e-6
    # snapshot: 6bd4b43 — the full study's extrapolation from p = 8..10 (this program's output).
    # The energy of the finite quarter cylinder has no closed form; the independent checks are
    # eq. 4.14 itself on energies of known limit (test_energy_extrapolation.py), the energies it
    # is made from against the work of the forces (ContactSolve.StrainEnergyIsHalfTheWorkOfTheForces)
    # and the reference's pressure against Hertz and Shtayerman (test_hertz.py).
    assert abs(ref["extrapolated"] - 7695.76845) < 2e-4
    for r in quick["rows"]:
        assert float(r["reference_energy"]) == ref["energy"]
        assert float(r["reference_energy_pmax"]) == u[2]
    for r in runs:                                               # v gives F/2 on the overkill mesh
        assert abs(r["resultant_y"] - 35000) < 0.05


def test_p_curve_falls_monotonically(quick):
    """p = 2..12 on the seed's 4-element mesh under the constant displacement: the strain energy
    falls towards U_ref and the error with it, at every step (under force control it does not)."""
    pts = curve(quick, "p, 4 el.")
    assert [p for p, *_ in pts] == list(range(2, 13))
    assert [n for _, n, *_ in pts][:3] == [40, 84, 144]         # 2(6 + 10(p-1) + 4(p-1)^2)
    errors = [e for *_, e, _ in pts]
    energies = [u for *_, u in pts]
    assert all(b < a for a, b in zip(errors, errors[1:])), errors
    assert all(b < a for a, b in zip(energies, energies[1:])), energies
    assert energies[-1] > quick["json"]["reference"]["energy"]


def test_p_curve_rate(quick):
    """Measured β = 0.83 on p = 8..12 (0.99 over p = 2..12; local rates 0.2-1.5, the error
    depends on where Γ* falls for each p). Seed: β ≈ 1.0."""
    c = summary(quick, "p, 4 el.")
    assert c["fit_dofs"] == [544, 684, 840, 1012, 1200]
    assert 0.7 <= c["beta"] <= 1.1, c["beta"]


def test_rp_curve_rate(quick):
    """rp on 4 elements: measured β = 1.36 (p = 7, 8, 10, 12 of the quick sweep; 1.37 in the full
    study), the seed's β ≈ 1.4."""
    c = summary(quick, "rp, 4 el.")
    assert 1.2 <= c["beta"] <= 1.6, c["beta"]


def test_rp_below_p_at_equal_dofs(quick):
    """Same mesh, same p, same DOF: moving node A onto Γ* lowers the error at every p run."""
    p = {deg: e for deg, _, e, _ in curve(quick, "p, 4 el.")}
    rp = {deg: e for deg, _, e, _ in curve(quick, "rp, 4 el.")}
    common = sorted(set(p) & set(rp))
    assert len(common) >= 5
    for deg in common:
        assert rp[deg] < p[deg], (deg, rp[deg], p[deg])
    assert rp[12] < 0.5 * p[12]                                   # measured 0.19 vs 0.73 %


def test_one_percent_crossings(quick):
    """Measured: p at 931 DOF (seed ~900), rp at 353 DOF (seed ~550)."""
    p = summary(quick, "p, 4 el.")
    rp = summary(quick, "rp, 4 el.")
    assert p["dofs_1pct_kind"] == rp["dofs_1pct_kind"] == "interpolated"
    assert 750 <= p["dofs_1pct"] <= 1150, p["dofs_1pct"]
    assert 250 <= rp["dofs_1pct"] <= 500, rp["dofs_1pct"]
    md = (quick["out"] / "convergence.md").read_text()
    assert f"| {p['dofs_1pct']:.0f} |" in md and f"| {rp['dofs_1pct']:.0f} |" in md


def test_h_curves_converge_slower(quick):
    """h-version, p = 1 and 2 on uniform meshes: algebraic, slower than rp (full study: β = 0.65
    and 0.72; the seed's 0.5 and 0.8)."""
    for label in ("h, p=1 (Q4, uniform)", "h, p=2 (Q9, uniform)"):
        pts = curve(quick, label)
        errors = [e for *_, e, _ in pts]
        assert len(pts) == 3 and all(b < a for a, b in zip(errors, errors[1:])), errors
        assert 0.5 <= summary(quick, label)["beta"] <= 0.9
        assert summary(quick, label)["beta"] < summary(quick, "rp, 4 el.")["beta"]


HP = "hp, factor 0.17 (hp.yaml)"
HP_SEED = "hp, factor 0.5 (seed)"
HP_CONST = "hp mesh, 2 steps, constant p"
HP_GOAL = "hp to a tolerance, goal-oriented degrees (hp-tolerance.yaml)"


def rows_of(quick, label):
    return [r for r in quick["rows"] if r["label"] == label]


def line_rms(x, y):
    """(slope, rms residual) of the least-squares line through (x, y)."""
    n = len(x)
    mx, my = sum(x) / n, sum(y) / n
    a = sum((u - mx) * (v - my) for u, v in zip(x, y)) / sum((u - mx) ** 2 for u in x)
    b = my - a * mx
    return a, math.sqrt(sum((v - a * u - b) ** 2 for u, v in zip(x, y)) / n)


def test_expected_failures_and_fixed_rp_points(quick):
    """rp on 4 elements: p = 4 and 7 (formerly "two zone ends are nearest to the same node")
    now converge; p = 2 still fails, now with "did not reach the zone ends in 20 relocations",
    and is reported as expected (exit status 0)."""
    rp = {r["p"]: r for r in rows_of(quick, "rp, 4 el.")}
    assert rp["2"]["status"] == "failed (expected)"
    assert "did not reach the zone ends" in rp["2"]["message"]
    for p in ("4", "7"):
        assert rp[p]["status"] == "ok" and not rp[p]["message"], rp[p]
    assert "rp, 4 el. p=2 4 el.: FAILED (expected)" in quick["stdout"]
    md = (quick["out"] / "convergence.md").read_text()
    assert "**missing**" not in md and "Summary beside the seed" in md
    for label in ("h, p=1 (Q4, uniform)", "h, p=2 (Q9, uniform)", "p, 4 el.", "rp, 4 el.", HP,
                  HP_SEED, HP_CONST, HP_GOAL):
        assert f"## {label}" in md
    png = (quick["out"] / "convergence.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 20_000


def test_hp_history_is_one_run_under_displacement_control(quick):
    """hp.yaml run once: its 8 adaptive steps are 8 rows (steps 1..8, 4 + 4k elements, degrees
    1..k+2); under the study's fixed v the step energies fall at every step and stay above
    U_ref, and the final contact force is F/2 within 0.01 % (measured 35000.0009 N)."""
    rows = rows_of(quick, HP)
    assert [int(r["adapt_step"]) for r in rows] == list(range(1, 9))
    assert [int(r["elements"]) for r in rows] == [4 + 4 * k for k in range(1, 9)]
    assert [int(r["p"]) for r in rows] == [k + 2 for k in range(1, 9)]
    assert [int(r["dofs"]) for r in rows] == [77, 181, 351, 603, 953, 1417, 2011, 2751]
    assert len({r["run_dir"] for r in rows}) == 1 and all(r["status"] == "ok" for r in rows)
    u = [float(r["strain_energy"]) for r in rows]
    assert all(b < a for a, b in zip(u, u[1:])), u
    assert u[-1] > quick["json"]["reference"]["energy"]
    t = [float(r["wall_time_s"]) for r in rows]
    assert all(b > a for a, b in zip(t, t[1:])), t
    assert abs(float(rows[-1]["resultant_y"]) - 35000) < 3.5
    assert all(r["resultant_y"] == "" for r in rows[:-1])     # contact.csv: final mesh only


def test_hp_reaches_one_percent_below_seed_dofs(quick):
    """Full hp (hp.yaml, factor 0.17, rising degree): e < 1 % at step 3 (351 DOF, e = 0.76 %),
    interpolated 312 DOF; the seed needed ~750. At the seed's factor 0.5: 897 DOF (e = 0.86 % at
    step 5, 953 DOF) -- more than the seed's 750."""
    hp, hp5 = summary(quick, HP), summary(quick, HP_SEED)
    assert hp["dofs_1pct_kind"] == "interpolated" and hp["dofs_1pct"] <= 750, hp["dofs_1pct"]
    first = next(p for p in hp["points"] if p["energy_rel_percent"] < 1.0)
    assert first["dofs"] <= 750, first
    assert 250 <= hp["dofs_1pct"] <= 400, hp["dofs_1pct"]                     # measured 312
    assert 800 <= hp5["dofs_1pct"] <= 1000, hp5["dofs_1pct"]                  # measured 897
    assert hp["dofs_1pct"] < summary(quick, "rp, 4 el.")["dofs_1pct"]        # rp: 353


def test_hp_to_a_tolerance_reaches_one_percent_within_300_dofs(quick):
    """The loop to a tolerance with its defaults (hp-tolerance.yaml, factor 0.15, goal-oriented
    degrees in the trunk space; the study's penalty leaves the energy surplus as the indicator),
    its steps as points under the study's fixed v (issue 16: 1 % energy error with at most 300
    DOF): the first step below 1 % has 284 DOF (e = 0.57 %), 1 % interpolated at 227 DOF; the
    rising degree of hp.yaml needs 351 (312 interpolated). Its steps fall faster than a power
    law: the exponential law fits them better."""
    goal = summary(quick, HP_GOAL)
    first = next(p for p in goal["points"] if p["energy_rel_percent"] < 1.0)
    print(f"goal-oriented hp: first below 1 % at {first['dofs']} DOF ({first['energy_rel_percent']:.3g} %), "
          f"interpolated {goal['dofs_1pct']:.0f}")
    assert first["dofs"] <= 300, first
    assert goal["dofs_1pct"] <= 300 and goal["dofs_1pct"] < summary(quick, HP)["dofs_1pct"]
    rows = rows_of(quick, HP_GOAL)
    assert len({r["run_dir"] for r in rows}) == 1 and all(r["status"] == "ok" for r in rows)
    errors = [float(r["energy_rel_percent"]) for r in rows]
    assert all(b < a for a, b in zip(errors, errors[1:])), errors


def test_hp_points_above_the_floor_fit_exponential_better(quick):
    """ln e against N^(1/3) (e = C exp(-γ N^(1/3))) against ln e over ln N: on the points above
    the reference's floor the exponential law leaves the smaller rms residual. Measured on the
    quick sweep (reference p = 4..6, floor 0.0025 %, so 7 of the 8 factor-0.17 steps): rms 0.190
    (exp., γ = 0.83) against 0.197 (alg.) -- only 4 % apart; at factor 0.5 (all 8 steps): 0.129
    against 0.463. Constant p on the twice-refined mesh: 0.018 against 0.152
    (examples/hertz/CONVERGENCE.md)."""
    thr = quick["json"]["reference"]["fit_threshold_percent"]
    assert 0 < thr < 0.02
    measured = {}
    for label, n_min in ((HP, 6), (HP_SEED, 6), (HP_CONST, 3)):
        pts = [(int(r["dofs"]), float(r["energy_rel_percent"])) for r in rows_of(quick, label)
               if r["status"] == "ok" and r["below_floor"] == "false"]
        assert len(pts) >= n_min and all(e >= thr for _, e in pts), (label, pts)
        ln_e = [math.log(e) for _, e in pts]
        beta, rms_alg = line_rms([math.log(n) for n, _ in pts], ln_e)
        gamma, rms_exp = line_rms([n ** (1 / 3) for n, _ in pts], ln_e)
        measured[label] = (-beta, rms_alg, -gamma, rms_exp)
        assert rms_exp < rms_alg, (label, measured[label])
        laws = summary(quick, label)["laws_above_floor"]                  # the script agrees
        assert laws["n"] == len(pts)
        assert abs(laws["rms_exponential"] - rms_exp) < 1e-9 and abs(laws["gamma"] + gamma) < 1e-9
    assert 0.6 <= measured[HP][2] <= 1.0, measured                        # γ, measured 0.83
    assert measured[HP_SEED][3] < 0.5 * measured[HP_SEED][1], measured
    for label in (HP, HP_SEED):                                           # both γ reported
        c = summary(quick, label)
        assert c["gamma"] is not None and c["beta"] is not None
        assert 2.0 <= c["beta"] <= 3.2, (label, c["beta"])                 # last 4: 2.62, 2.63


def test_hp_constant_degree_on_refined_mesh(quick):
    """The seed's dashed curves: a constant p on the mesh refined twice (final mesh's energy
    per p). The error falls with p, faster than rp on 4 elements (measured β = 2.63 on p = 3, 5,
    7 of the quick sweep; 3.71 on p = 6..9 in the full study; seed: 5.5)."""
    pts = curve(quick, HP_CONST)
    assert [p for p, *_ in pts] == [3, 5, 7, 9]
    errors = [e for _, _, e, _ in pts]
    assert all(b < a for a, b in zip(errors, errors[1:])), errors
    assert all(r["mesh"] == "4 el. + 2 hp steps (12 el.)" for r in rows_of(quick, HP_CONST))
    assert summary(quick, HP_CONST)["beta"] > summary(quick, "rp, 4 el.")["beta"] + 0.5


def small_study(tmp_path, root, curves, control=None, sets=None):
    hertz = os.path.join(root, "examples", "hertz")
    study = {"study": "small", "reference": {"case": os.path.join(hertz, "p5.yaml"),
                                              "degrees": [10, 11, 12]}, "curves": curves}
    if control:
        study["control"] = control
    if sets:
        study["set"] = sets
    path = tmp_path / "study.yaml"
    path.write_text(json.dumps(study))
    return path


def test_force_control_total_potential_is_monotone(exe, root, tmp_path):
    """With the seed's penalty under force control the strain energy of the p-version is not
    monotone in p (measured: U rises from p = 4 to 6 and 8 to 9), while the total potential
    U + U_penalty - F v falls at every p, as it must on nested spaces: the penalty's energy is
    the same functional on every p (its 50 Gauss points per edge). Exact contact constrains the
    gap at each degree's own Gauss-Lobatto nodes, so its admissible sets are not nested and no
    such ordering holds (measured -9358.1, -9356.8, -9365.6, ... for p = 4, 5, 6)."""
    p5 = os.path.join(root, "examples", "hertz", "p5.yaml")
    path = small_study(tmp_path, root, [{"label": "p", "method": "p", "case": p5,
                                         "degrees": [4, 5, 6, 7, 8, 9]}], {"type": "force"},
                       ["contact[0].enforcement=penalty"])
    r = study_script(root, exe, path, "--out", tmp_path / "out")
    assert r.returncode == 0, r.stdout + r.stderr
    with open(tmp_path / "out" / "convergence.csv") as f:
        rows = [r for r in csv.DictReader(f) if r["method"] == "p"]
    u = [float(r["strain_energy"]) for r in rows]
    pi = [float(r["potential_energy"]) for r in rows]
    assert not all(b < a for a, b in zip(u, u[1:])) and not all(b > a for a, b in zip(u, u[1:]))
    assert all(b < a for a, b in zip(pi, pi[1:])), pi
    for row in rows:
        assert abs(float(row["resultant_y"]) - 35000) < 1e-3
    assert (tmp_path / "out" / "convergence.png").stat().st_size > 20_000


def test_failures_reported_not_hidden(exe, root, tmp_path):
    """An unexpected failure: a row 'failed' with the program's message, exit status 1, the
    rest written; the same failure listed in expect_fail: exit status 0."""
    p5 = os.path.join(root, "examples", "hertz", "p5.yaml")
    curves = [{"label": "p", "method": "p", "case": p5, "degrees": [4, 31]},
              {"label": "hp", "method": "hp", "missing": "not yet"}]
    path = small_study(tmp_path, root, curves, {"type": "displacement", "v": 0.4874668747})
    r = study_script(root, exe, path, "--out", tmp_path / "a")
    assert r.returncode == 1, r.stdout + r.stderr
    assert "p p=31 4 el.: FAILED" in r.stdout and "1 run(s) failed" in r.stderr
    with open(tmp_path / "a" / "convergence.csv") as f:
        rows = {(r["label"], r["p"]): r for r in csv.DictReader(f)}
    assert rows[("p", "31")]["status"] == "failed" and "degree" in rows[("p", "31")]["message"]
    assert rows[("p", "4")]["status"] == "ok" and float(rows[("p", "4")]["energy_rel_percent"]) > 0
    assert rows[("hp", "")]["status"] == "missing"

    curves[0]["expect_fail"] = {"31": "degree above 30"}
    path = small_study(tmp_path, root, curves, {"type": "displacement", "v": 0.4874668747})
    r = study_script(root, exe, path, "--out", tmp_path / "b")
    assert r.returncode == 0, r.stdout + r.stderr
    assert "FAILED (expected)" in r.stdout


def test_bad_study_file_is_named(exe, root, tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(json.dumps({"study": "bad", "reference": {"case": "x.yaml", "degrees": [1]},
                                "curves": [], "typo": 1}))
    r = study_script(root, exe, path, "--out", tmp_path / "out")
    assert r.returncode == 2
    assert str(path) in r.stderr and "typo" in r.stderr
    hp = os.path.join(root, "examples", "hertz", "hp.yaml")
    for bad, words in (({"history": "yes"}, "'history' is true or false"),
                       ({"history": True, "degrees": [4, 5]}, "one run")):
        curve_ = {"label": "hp", "method": "hp", "case": hp, **bad}
        r = study_script(root, exe, small_study(tmp_path, root, [curve_]), "--out", tmp_path / "o")
        assert r.returncode == 2 and words in r.stderr, r.stderr


def test_history_of_a_run_without_adaptivity_is_a_failure(exe, root, tmp_path):
    """history: true on a run without adapt.history (p5.yaml): a failed row, exit status 1."""
    p5 = os.path.join(root, "examples", "hertz", "p5.yaml")
    path = small_study(tmp_path, root, [{"label": "h", "method": "hp", "case": p5,
                                         "history": True}],
                       {"type": "displacement", "v": 0.48746687470142525})
    r = study_script(root, exe, path, "--out", tmp_path / "out")
    assert r.returncode == 1, r.stdout + r.stderr
    with open(tmp_path / "out" / "convergence.csv") as f:
        rows = [x for x in csv.DictReader(f) if x["label"] == "h"]
    assert len(rows) == 1 and rows[0]["status"] == "failed"
    assert "no adapt.history" in rows[0]["message"]
