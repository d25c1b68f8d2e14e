"""hp's one rule for a refinement it cannot build (issue 40, "Bad input and failures": internal
errors of the rp/hp machinery are never shown to a user as such). A user's pin in a hole with
friction, pressed and partly unloaded: the zone resolution's refinement towards one vertex of the
hole (a coarse, curved element) would invert an element, and so would the first layer around the
zone end that vertex later follows. Before, the run stopped at step 0 with "hp: refining towards
node 22 with factor 0.33 gives an invalid mesh". Now each such refinement is left out, said in
the log and in summary.json (adapt.history[].left_out), and the loop goes on to its own end."""
import json
import os

PIN = "examples/pin-in-hole/pin-in-hole.yaml"
UNLOADED = ["contact[0].friction={law: coulomb, mu: 0.2}",
            "solver.stages=[{displacements: 2, loads: 0, steps: 2}, "
            "{displacements: 1, loads: 0, steps: 1}]",
            "adapt.steps=1"]


def test_a_refinement_that_cannot_be_built_is_left_out_and_the_loop_goes_on(hpcontact, root, tmp_path):
    out = tmp_path / "pin"
    args = ["run", os.path.join(root, PIN), "--out", str(out)]
    for s in UNLOADED:
        args += ["--set", s]
    r = hpcontact(*args)
    # The loop ends as a loop with a tolerance ends when its steps run out, not by the refinement.
    assert r.returncode == 1, r.stderr
    error = [line for line in r.stderr.splitlines() if "error:" in line]
    assert len(error) == 1 and "the tolerance 0.001 was not reached: 1 steps taken" in error[0], r.stderr
    assert "invalid mesh" not in error[0] and "rp:" not in error[0]
    history = json.loads((out / "last-good" / "summary.json").read_text())["adapt"]["history"]
    assert [h["step"] for h in history] == [0, 1]
    # What was left out, in each step that left something out, and said in the log as well.
    left = {h["step"]: h.get("left_out", []) for h in history}
    assert left[0] and all("can be built" in n and "left to the later steps" in n for n in left[0])
    assert left[1] and all("cannot be refined more than" in n or "cannot move onto it" in n for n in left[1])
    for step, notes in left.items():
        for note in notes:
            assert note in r.stdout, note
            assert PIN not in note  # the cause without the file's name, which the run names once
    # Each step has its estimate: the loop measured the meshes it could build.
    assert all(h["estimated_error"]["shear_rel_L2"] > 0 for h in history)
