"""Bad friction and load-path input ends with a message naming the file, the key and the cause,
and no summary.json. The values come from --set: a value the schema refuses is a command-line
mistake (exit 2), a combination the model refuses an input error (exit 1)."""
import csv
import os

import pytest

from conftest import expect_refused

STICK = os.path.join("examples", "two-bars", "stick.yaml")


@pytest.mark.parametrize("settings, message, code", [
    (["contact[0].friction.mu=-0.1"], "contact[0].friction.mu", 2),
    (["contact[0].friction.penalty=0"], "contact[0].friction.penalty", 2),
    (["contact[0].friction.penalty=-1e8"], "contact[0].friction.penalty", 2),
    (["contact[0].friction.law=viscous"], "contact[0].friction.law", 2),
    (["solver.target_resultant.value=2297.5", "solver.stages[1].displacements=0.5"],
     "solver.stages[1].displacements (from --set): under solver.target_resultant the last stage reaches the target force", 2),
    (["solver.stages[0].steps=0"], "solver.stages[0].steps", 2),
])
def test_bad_friction_input(hpcontact, root, tmp_path, settings, message, code):
    expect_refused(hpcontact, os.path.join(root, STICK), str(tmp_path), settings, message, code)


@pytest.mark.parametrize("friction, message", [
    ("{law: coulomb, penalty: 1.0e8}", "missing key 'mu'"),  # mu has no meaningful default
    ("{law: stick}", "missing key 'penalty'"),
])
def test_friction_missing_key(hpcontact, root, tmp_path, friction, message):
    """With the seed's penalty (enforcement: penalty) the tangential penalty is required; exact
    friction needs none (test_exact_friction_needs_no_tangential_penalty)."""
    case = tmp_path / "case.yaml"
    text = open(os.path.join(root, STICK)).read()
    case.write_text(text.replace("friction: {law: stick, penalty: 1.0e8}", "friction: " + friction))
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q",
                  "--set", "contact[0].enforcement=penalty")
    assert r.returncode == 1
    assert message in r.stderr, r.stderr


def test_exact_friction_needs_no_tangential_penalty(hpcontact, root, tmp_path):
    """Exact stick (the default enforcement) without friction.penalty: the augmentation of the
    stick rows defaults to the normal one; the run converges and reports stick at every node."""
    case = tmp_path / "case.yaml"
    text = open(os.path.join(root, STICK)).read()
    case.write_text(text.replace("friction: {law: stick, penalty: 1.0e8}", "friction: {law: stick}"))
    r = hpcontact("run", case, "--out", tmp_path / "out", "-q")
    assert r.returncode == 0, r.stderr
    with open(tmp_path / "out" / "contact.csv") as f:
        rows = list(csv.DictReader(f))
    # the body with the multiplier nodes (the other body's points follow it in contact.csv)
    states = {row["state"] for row in rows if row["body"] == rows[0]["body"]}
    assert states == {"stick"}, states
