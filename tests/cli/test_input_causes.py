"""Inputs that are legal value by value but not together, each refused with its cause, the file
and the key (issue 41's weak answers: before, each was refused for a wrong reason, or ran)."""
import os

from conftest import expect_refused


def example(root, *path):
    return os.path.join(root, "examples", *path)


def test_a_force_target_that_double_precision_cannot_resolve_is_refused(hpcontact, root, tmp_path):
    """E = 1e100 with the target of 35000: a displacement of 1e-96 of the body's size (refused
    before as 'constraints that repeat one another')."""
    expect_refused(hpcontact, example(root, "hertz", "p8.yaml"), tmp_path, ["bodies[0].material.E=1e100"],
                   "solver.target_resultant.value: a force of 35000 moves body 'cylinder' (E = 1e+100 at ", 1)
    r = hpcontact("run", example(root, "hertz", "p8.yaml"), "--out", tmp_path, "-q",
                  "--set", "bodies[0].material.E=1e100")
    assert "below what double precision resolves" in r.stderr and "bodies[0].material" in r.stderr


def test_a_force_target_beyond_elasticity_is_refused(hpcontact, root, tmp_path):
    """E = 1e-100 (refused before as 'does not reach the obstacle'), and a target of 5e99 with
    steel (ran for minutes, then 'held only by contact')."""
    for settings in (["bodies[0].material.E=1e-100"],
                     ["solver.target_resultant.value=5e99", "contact[0].compare={radius: 10}"]):
        expect_refused(hpcontact, example(root, "hertz", "p8.yaml"), tmp_path, settings,
                       "no elastic solution means anything there", 1)


def test_two_parallel_planes_on_one_edge_set_are_refused(hpcontact, root, tmp_path):
    """The Hertz cylinder's contact edges against a second plane below the first, both exact:
    the constraints contradict one another where both touch (the solve ended in NaN)."""
    case = tmp_path / "two-planes.yaml"
    text = open(example(root, "hertz", "p8.yaml")).read()
    text = text.replace("compare: {radius: 10, force: 70000, reference: reference-pressure.csv}", "")
    text = text.replace("\ndiscretization:", "  - body: cylinder\n    edges: [contact]\n"
                        "    obstacle: {type: plane, point: [0, -0.001], normal: [0, 1]}\n\ndiscretization:")
    case.write_text(text)
    expect_refused(hpcontact, str(case), tmp_path / "out", [],
                   "contact[1].edges: shares contact edges with contact[0]", 1)


def test_a_reference_curve_with_a_nan_row_is_refused(hpcontact, root, tmp_path):
    """A NaN in the reference's pressure column names the file, the line and the column (it was
    reported as a load mismatch)."""
    lines = open(example(root, "hertz", "reference-pressure.csv")).read().splitlines()
    cells = lines[5].split(",")
    cells[5] = "nan"
    lines[5] = ",".join(cells)
    (tmp_path / "reference-pressure.csv").write_text("\n".join(lines) + "\n")
    case = tmp_path / "p8.yaml"
    case.write_text(open(example(root, "hertz", "p8.yaml")).read())
    expect_refused(hpcontact, str(case), tmp_path / "out", [],
                   "contact[0].compare.reference: '" + str(tmp_path / "reference-pressure.csv") +
                   "' line 6, column 6: 'nan' is not a finite number", 1)


def test_elements_stacked_on_one_another_are_refused(hpcontact, root, tmp_path):
    """A second element on the first's place under other node numbers (was accepted: twice the
    stiffness there)."""
    case = tmp_path / "stacked.yaml"
    case.write_text("""case: stacked
bodies:
  - name: block
    material: {E: 1000, nu: 0.3, plane: strain}
    nodes: {1: [0, 0], 2: [1, 0], 3: [1, 1], 4: [0, 1], 5: [0, 0], 6: [1, 0], 7: [1, 1], 8: [0, 1]}
    elements: {1: [1, 2, 3, 4], 2: [5, 6, 7, 8]}
    edge_sets: {bottom: [[1, 2]], top: [[3, 4]]}
    constraints:
      - {edges: [bottom], ux: 0, uy: 0}
    loads:
      - {edges: [top], traction: [0, -1]}
discretization: {method: p, degree: 2}
""")
    expect_refused(hpcontact, str(case), tmp_path / "out", [],
                   "elements 1 and 2 lie on one another (their corners are at the same points", 1)


def test_a_failed_linear_solve_names_the_file(hpcontact, root, tmp_path):
    """The linear path (no contact): a singular stiffness (nu next to 1/2) is named by the
    problem file, as the nonlinear path's failures are."""
    expect_refused(hpcontact, example(root, "lame", "thick-cylinder.yaml"), tmp_path,
                   ["bodies[0].material.nu=0.49999999999999"],
                   "thick-cylinder.yaml: the solver stopped: the stiffness matrix is singular", 1)
