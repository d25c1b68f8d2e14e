"""The stiff axle in an elastic ring (seed §5.4): finite strain (Neo-Hooke) with contact against
a moving rigid circle; and what a finite-strain run says when an element inverts."""
import json
import os

import pytest

RING = os.path.join("examples", "axle-ring")

# The seed's strain energies (§5.4) of its 2- and 12-element meshes with p = 4.
SEED = {"ring2-p4.yaml": 77.01673366, "ring12-p4.yaml": 76.52192848}


def summary(path):
    with open(os.path.join(path, "summary.json")) as f:
        return json.load(f)


@pytest.mark.parametrize("name", sorted(SEED))
def test_energy_within_half_a_percent_above_the_seed(hpcontact, root, tmp_path, name):
    """With the seed's method (the penalty, eps_N as in the file), our reading of the setup
    (outer boundary fixed, axle touching at the start; README.md) gives energies 0.4-0.5 % above
    the seed's, as README.md says (measured 77.394 and 76.849: +0.49 % and +0.43 %): asserted
    between +0.4 % and +0.5 %."""
    r = hpcontact("run", os.path.join(root, RING, name), "--out", tmp_path, "-q",
                  "--set", "contact[0].enforcement=penalty")
    assert r.returncode == 0, r.stderr
    s = summary(tmp_path)
    assert s["converged"]
    assert 0.004 < s["strain_energy"] / SEED[name] - 1 < 0.005, s["strain_energy"]
    c = s["contact"]
    # Half model: the vertical resultant pushes the ring down; the zone ends once on the inner arc.
    assert c["resultant"][1] < 0
    assert len(c["gamma_star"]) == 1


def test_refined_meshes_agree(hpcontact, root, tmp_path):
    """With exact contact (the default) the 12-element p = 4 and the locally refined 16-element
    p = 5 meshes agree to 1e-4 (measured 77.2247 and 77.2264, 2e-5 apart; with the penalty
    76.8485 and 76.8411: the penalty eps_N = 1000 E of the ring lowers the energy by 0.5 %)."""
    energies = []
    for name in ("ring12-p4.yaml", "ring16-p5.yaml"):
        r = hpcontact("run", os.path.join(root, RING, name), "--out", tmp_path / name, "-q")
        assert r.returncode == 0, r.stderr
        energies.append(summary(tmp_path / name)["strain_energy"])
    assert abs(energies[0] / energies[1] - 1) < 1e-4, energies


def test_inverting_element_is_reported_and_last_step_kept(hpcontact, root, tmp_path):
    """A block pressed beyond its own height (tests/cli/data/crushed-block.yaml): the load step
    that moves the top below the bottom inverts the element. The run fails (exit 1) naming the
    load step (the input's numbering), the element, its body and det F; no summary.json in the output folder, the last
    converged step in last-good/ marked converged: false with its load factor (0.75: the steps
    0.5 and 1 with one halving allowed reach 0.75, then the step of 0.25 to 1 inverts, and no
    shorter step is allowed: the load cannot be carried beyond 0.75)."""
    r = hpcontact("run", os.path.join(root, "tests", "cli", "data", "crushed-block.yaml"),
                  "--out", tmp_path, "-q")
    assert r.returncode == 1
    assert "load step 2 (factor 1)" in r.stderr, r.stderr  # the input's step 2, after its part to 0.75
    assert "the load cannot be carried beyond the last converged step (factor 0.75)" in r.stderr
    assert "element 7 of body 'block' inverts: det F = -" in r.stderr, r.stderr
    assert not os.path.exists(tmp_path / "summary.json")
    kept = summary(tmp_path / "last-good")
    assert kept["converged"] is False
    assert kept["load_factor"] == 0.75
    assert "inverts" in kept["message"]
    assert os.path.exists(tmp_path / "last-good" / "solution.vtu")


def test_a_failed_run_says_its_files_went_to_last_good(hpcontact, root, tmp_path):
    """The same run with progress lines: the files written for the last converged state are
    named with last-good/ in front, never as if they were the run's results."""
    r = hpcontact("run", os.path.join(root, "tests", "cli", "data", "crushed-block.yaml"),
                  "--out", tmp_path)
    assert r.returncode == 1
    wrote = [line.strip() for line in r.stdout.splitlines() if line.strip().startswith("wrote ")]
    assert "wrote last-good/summary.json (the last converged state)" in wrote, r.stdout
    assert "wrote last-good/solution.vtu (the last converged state)" in wrote, r.stdout
    assert not any(line.startswith(("wrote summary.json", "wrote solution.vtu")) for line in wrote)


def test_a_cut_step_keeps_its_number(hpcontact, root, tmp_path):
    """Load steps are the input's: the second of two, cut once, converges a part of itself
    (to 0.75) and fails beyond it — both reported as load step 2, no load step 3 of 2."""
    r = hpcontact("run", os.path.join(root, "tests", "cli", "data", "crushed-block.yaml"),
                  "--out", tmp_path)
    assert r.returncode == 1
    lines = [line.strip() for line in r.stdout.splitlines()]
    assert any(line.startswith("load step 1 of 2: factor 0.5") for line in lines), r.stdout
    assert any(line.startswith("load step 2 of 2 (a part of it, cut): factor 0.75") for line in lines), r.stdout
    assert "load step 3" not in r.stdout + r.stderr
    assert "load step 2 (factor 1) failed after 1 cuts" in r.stderr


@pytest.mark.parametrize("setting, message", [
    ("bodies[0].material.plane=stress", "neo-hooke is implemented in plane strain and axisymmetry only"),
    ("bodies[0].material.model=mooney", "mooney"),
])
def test_bad_material_input(hpcontact, root, tmp_path, setting, message):
    r = hpcontact("run", os.path.join(root, RING, "ring2-p4.yaml"), "--out", tmp_path, "-q",
                  "--set", setting)
    assert r.returncode != 0
    assert message in r.stderr, r.stderr
    assert "material" in r.stderr
