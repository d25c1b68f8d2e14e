"""contact[].carrier: auto — the program chooses which of two bodies carries the multipliers, by a
rule symmetric in the bodies (model/contact_carrier.hpp), says which and why, and refuses it where
it means nothing."""
import os
import re

import pytest

from conftest import expect_refused

PRESS_FIT = os.path.join("examples", "lame", "press-fit-short-hub.yaml")


def chosen(hpcontact, case, pair):
    """The carrier `hpcontact check` reports for pair 0 written as `pair` with carrier: auto, and the rule."""
    r = hpcontact("check", case, "--set", pair)
    assert r.returncode == 0, r.stderr
    m = re.search(r"carrier auto: body '([^']+)' carries: (.*)", r.stdout)
    assert m, r.stdout
    return m.group(1), m.group(2)


@pytest.mark.parametrize("case, a, b, expected, rule", [
    # the hub's bore lies within the shaft's longer face: the hub, whose zone ends at its last node
    (PRESS_FIT, ("shaft", "outer"), ("hub", "bore"), "hub", "lie within body 'shaft''s (100 % "),
    # the pin's half circle is meshed finer than the plate's hole
    (os.path.join("examples", "pin-in-hole", "pin-in-hole.yaml"), ("pin", "outer_below"),
     ("plate", "inner_below"), "pin", "the finer contact mesh"),
    # a shrink-fit slice: both faces alike, both steel: the body named first
    (os.path.join("examples", "lame", "shrink-fit.yaml"), ("shaft", "outer"), ("hub", "inner"), "shaft",
     "the body named first under bodies"),
])
def test_auto_chooses_the_same_body_whichever_the_input_names_first(hpcontact, root, case, a, b, expected, rule):
    """The same body, for the same reason, with the pair written either way round."""
    for (body, edges), (other, other_edges) in ((a, b), (b, a)):
        pair = (f"contact[0]={{body: {body}, edges: [{edges}], obstacle: {{type: body, body: {other}, "
                f"edges: [{other_edges}]}}, carrier: auto}}")
        got, why = chosen(hpcontact, os.path.join(root, case), pair)
        assert got == expected and rule in why, (body, got, why)


def test_auto_is_refused_where_there_is_no_choice(hpcontact, root, tmp_path):
    """Against a rigid obstacle, with the penalty (no multipliers) and with compare (measured along
    the obstacle as written), carrier: auto is refused naming the key, before any solve."""
    hertz = os.path.join(root, "examples", "hertz", "p8.yaml")
    expect_refused(hpcontact, hertz, tmp_path / "rigid", ["contact[0].carrier=auto"],
                   "contact[0].carrier (from --set): auto chooses which of two bodies", 2)
    case = os.path.join(root, PRESS_FIT)
    expect_refused(hpcontact, case, tmp_path / "penalty",
                   ["contact[0].enforcement=penalty", "contact[0].penalty=2.1e8", "contact[0].carrier=auto"],
                   "the penalty has none", 2)
    bilateral = os.path.join(root, "examples", "hertz", "bilateral.yaml")
    expect_refused(hpcontact, bilateral, tmp_path / "compare", ["contact[0].carrier=auto"],
                   "contact[0].carrier (from --set): auto may swap body and obstacle", 2)
