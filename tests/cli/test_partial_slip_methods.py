"""The exact method against the seed's penalty (eps_N = eps_T = 1000 E) on one fixed p = 8 mesh:
two equal steel cylinders (R = 10, b/R = 0.02) pressed and then sheared by about half the
friction capacity (scripts/partial_slip_mesh.py --shear-displacement), the shear and the
pressure against Cattaneo–Mindlin and Hertz by both of scripts/partial_slip_compare.py's
metrics for both methods (each at its own points; one uniform grid for both).

The mesh is the structured grid graded (one layer) towards the a and c Cattaneo–Mindlin gives
for the forces a p = 4 run of the same problem carried (--carried): the nodes where the
exact traction's square roots begin, as an engineer grades towards them or rp moves nodes to
them. Measured (2026-12-07): shear 0.88 % (uniform) and 0.83 % (own points) exact, 0.98 % and
0.97 % penalty; pressure 0.26 %, 0.29 % exact, 0.43 %, 0.43 % penalty. Neither method is
tuned here: with the grading 2 % away from the carried a and c (towards those of the nominal
force, examples/partial-slip/README.md) the penalty is ahead on this measure (1.07 % against
1.20 %), and on the coarse polar mesh by the uniform grid (1.27 % against 1.63 %)."""
import json
import os

import pytest
import yaml

from conftest import load_script, partial_slip_generator

compare = load_script("partial_slip_compare")
COMMON = ["--shear-displacement", "0.0042", "--grade-at", "a", "c", "--layers", "1"]
PENALTY = ["--set", "contact[0].enforcement=penalty", "--set", "contact[0].penalty=2.1e8",
           "--set", "contact[0].friction.penalty=2.1e8"]


def write_case(root, path, *args):
    r = partial_slip_generator(root, *COMMON, *args)
    assert r.returncode == 0, r.stderr
    path.write_text(r.stdout)
    return path


@pytest.fixture(scope="module")
def runs(hpcontact, root, tmp_path_factory):
    """The p = 4 run that places a and c, then the p = 8 mesh solved by both methods: their
    uniform_errors (with the own points' figures)."""
    tmp = tmp_path_factory.mktemp("methods")
    first = write_case(root, tmp / "p4.yaml", "--degree", "4")
    r = hpcontact("run", first, "--out", tmp / "p4", "-q")
    assert r.returncode == 0, r.stderr
    case = write_case(root, tmp / "p8.yaml", "--degree", "8", "--carried", str(tmp / "p4"))
    out = {}
    for method, extra in (("exact", []), ("penalty", PENALTY)):
        r = hpcontact("run", case, "--out", tmp / method, "-q", *extra)
        assert r.returncode == 0, r.stderr
        out[method] = compare.uniform_errors(str(tmp / method))
    return case, out


def mesh_abscissae(case):
    """The x of the upper body's nodes on its contact edges (read back from the problem file)."""
    spec = yaml.safe_load(open(case))
    body = spec["bodies"][0]
    ids = {n for edge in body["edge_sets"]["contact"] for n in edge}
    return sorted(body["nodes"][n][0] for n in ids)


def test_the_mesh_has_nodes_where_the_runs_zone_and_stick_zone_end(runs):
    """The premise: both runs' a and c (Cattaneo–Mindlin's for the forces each carried) lie
    within 1e-3 of them of a node of the contact edges, on both sides."""
    case, out = runs
    xs = mesh_abscissae(case)
    for method, m in out.items():
        for end in (m["a"], m["c"], -m["a"], -m["c"]):
            assert min(abs(x - end) for x in xs) < 1e-3 * abs(end), (method, end)


def test_the_exact_shear_is_no_worse_than_the_penaltys_on_the_same_mesh(runs):
    """Issue 40's Must-show 5: the shear's relative L2 error against Cattaneo–Mindlin, exact
    against penalty, by each metric; and the pressure's against Hertz. Both below 1.5 % (a
    method off by a node's worth at c or a is several per cent: test_partial_slip.py)."""
    _, out = runs
    exact, penalty = out["exact"], out["penalty"]
    for metric in ("shear_rel_L2_uniform", "shear_rel_L2_own_points",
                   "pressure_rel_L2_uniform", "pressure_rel_L2_own_points"):
        assert exact[metric] <= penalty[metric], (metric, exact[metric], penalty[metric])
        assert penalty[metric] < 0.015, metric


def test_both_methods_carry_the_same_forces(runs):
    """The same model: P and Q of the two runs within 0.1 % (the penalty's penetration costs
    0.04 % of P at 1000 E)."""
    _, out = runs
    for key in ("P", "Q"):
        assert out["exact"][key] == pytest.approx(out["penalty"][key], rel=1e-3), key


def test_a_run_without_forces_cannot_place_the_mesh(root, tmp_path):
    """--carried naming a folder without summary.json: the generator says which file, writes
    nothing."""
    r = partial_slip_generator(root, *COMMON, "--carried", str(tmp_path / "nowhere"))
    assert r.returncode != 0 and r.stdout == ""
    assert os.path.join(str(tmp_path / "nowhere"), "summary.json") in r.stderr
    (tmp_path / "run").mkdir()
    (tmp_path / "run" / "summary.json").write_text(json.dumps(
        {"contact_pairs": [{"normal_force": 100.0, "tangential_force": 40.0}]}))
    r = partial_slip_generator(root, *COMMON, "--carried", str(tmp_path / "run"))
    assert r.returncode != 0 and "Q < mu P" in r.stderr


def test_a_polar_mesh_with_a_ring_at_the_stick_zones_end(hpcontact, root, tmp_path):
    """--mesh polar --grade-at a c: a ring at c inside the one at a, the contact edges a chain
    from -3a to 3a through nodes at -a, -c, 0, c, a (a ring of radius r meets the arc at
    x = r sqrt(1 - r²/4R²)), and the mesh checks without warnings."""
    r = partial_slip_generator(root, "--mesh", "polar", "--grade-at", "a", "c", "--degree", "3")
    assert r.returncode == 0, r.stderr
    case = tmp_path / "polar.yaml"
    case.write_text(r.stdout)
    spec = yaml.safe_load(r.stdout)
    a = compare.closed_form(5.0, 210000 / (2 * (1 - 0.3 ** 2)), 0.3, 700.0, 0)[0]
    c = a * 0.5 ** 0.5
    body = spec["bodies"][0]
    edges = body["edge_sets"]["contact"]
    assert all(e[1] == f[0] for e, f in zip(edges, edges[1:]))
    xs = [body["nodes"][n][0] for n in [edges[0][0]] + [e[1] for e in edges]]
    on_arc = lambda r: r * (1 - r * r / (4 * 10.0 ** 2)) ** 0.5  # noqa: E731  (R = 10)
    expected = [on_arc(r) for r in (-3 * a, -a, -c, 0, c, a, 3 * a)]
    assert len(xs) == len(expected)
    assert xs == pytest.approx(expected, rel=1e-12, abs=1e-15)
    checked = hpcontact("check", case)
    assert checked.returncode == 0, checked.stderr
    assert "warning" not in checked.stdout + checked.stderr
