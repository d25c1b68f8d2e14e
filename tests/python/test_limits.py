"""A problem given to the module as text, and its set= values, are bounded as a problem file and
--set values are (docs/input.md, "Limits"): at most 16 MB, and at most 10^6 YAML values counted
before yaml-cpp builds the tree. Texts past the values' limit are read in a child process whose
address space their trees would not fit into, so that a refusal there came before the tree."""
import json
import re
import resource
import subprocess
import sys

import pytest

import hpcontact
from conftest import scaled_timeout

# The interpreter and module take some 40 MB; the trees refused below would take 500 MB.
REFUSED_WITHIN = 256 << 20

CHILD = """
import json, sys, hpcontact
args = json.load(sys.stdin)
try:
    hpcontact.Problem.from_yaml(args["text"], set=args["set"])
    print("accepted")
except hpcontact.InputError as e:
    print(e)
"""


def read_in_small_memory(text, set=None):
    """from_yaml(text, set=set) in a child process limited to REFUSED_WITHIN: its first line of
    output, the InputError's message or 'accepted'."""
    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (REFUSED_WITHIN, REFUSED_WITHIN))
    r = subprocess.run([sys.executable, "-c", CHILD], input=json.dumps({"text": text, "set": set}),
                       capture_output=True, text=True, timeout=scaled_timeout(60), preexec_fn=limit)
    assert r.returncode == 0, r.stderr[-2000:]
    return r.stdout.splitlines()[0]


def test_from_yaml_is_bounded_as_a_file_is(lame_file):
    """Problem.from_yaml of 20 MB parsed for minutes at ~150 bytes per byte. Now a text of more
    than 16 MB is refused at once, and one of more than 10^6 values at the value that passes the
    limit, naming the label as a file's name is named."""
    with pytest.raises(hpcontact.InputError) as info:
        hpcontact.Problem.from_yaml("case: x\n" + "# a comment line of forty characters ...\n" * 430_000)
    assert str(info.value) == "<string>: the problem file is larger than the 16 MB it may have (16.8 MB)"
    message = read_in_small_memory("case: x\ndescription:\n- " + "0\n- " * 1_000_000 + "0\n")
    assert message.startswith("<string>:999998:3: the problem file has more than the 1000000 YAML "
                              "values an input may have"), message
    message = read_in_small_memory("case: x\ndescription: [" + "0," * 1_000_000 + "0]\n")
    assert message.startswith("<string>:2:14: the problem file has a flow list or map ([...] or "
                              "{...}) starting here with more than the 1000000 YAML values"), message
    with open(lame_file) as f:
        text = f.read()
    assert read_in_small_memory(text) == "accepted"  # a problem within the bounds is read there


def test_set_values_are_bounded_as_files_are(lame_file):
    """set= values went to yaml-cpp unbounded. Now each is bounded as a --set value is: its bytes,
    and its values to what the rest of the problem leaves it."""
    with open(lame_file) as f:
        text = f.read()
    with pytest.raises(hpcontact.InputError) as info:
        hpcontact.Problem.from_yaml(text, set={"description": "x" * (17 << 20)})
    assert str(info.value) == ("<string>: --set description=xxxxxxxxxxxxxxxxxxxx...: the --set value is "
                               "larger than the 16 MB it may have (17 MB)")
    # A block list of 999 990 values: within 10^6 alone, not with the rest of the problem.
    many = "description=\n- " + "0\n- " * 999_989 + "0"
    message = read_in_small_memory(text, set=[many])
    assert re.match(r"<string>: --set description=\\n- 0\\n- 0\\n- 0\\n- 0\.\.\.: at line \d+, "
                    r"column 3: the --set value has more than the \d+ YAML values the rest of the "
                    "problem leaves it of the 1000000", message), message
    # Two values of 610 000 values each (aliases of a list of 10^4: their trees are small), each
    # within the limit alone: the second is bounded by what the first left, at its 38th alias.
    half = "[&a [" + ",".join(["0"] * 10_000) + "]" + ", *a" * 60 + "]"
    message = read_in_small_memory(text, set=[f"description={half}", f"exact.center={half}"])
    column = half.find("*a") + 4 * 37 + 1
    assert re.match(r"<string>: --set exact.center=\[&a \[0,0,0,0,0,0,0,0\.\.\.: at line 1, "
                    f"column {column}: the --set value has more than the 3\\d{{5}} YAML values the "
                    "rest of the problem leaves it", message), message
