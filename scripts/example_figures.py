#!/usr/bin/python3
"""Keeps the figures the examples' READMEs quote equal to what the program gives: each figure is
marked with the run and the summary.json entry it comes from, and this script runs the examples
and checks (or rewrites) the marked values.

usage: example_figures.py [--check] [--hpcontact PATH] [README ...]

A marked figure (an HTML comment around it: invisible when rendered):

  <!--fig:FILE:KEY-->VALUE<!--/fig-->

FILE is a problem file relative to the README's folder, run once per check with `hpcontact run
FILE --out TMP -q` (a run that fails counts with its last-good/summary.json: a README may quote
where a failing run stopped); FILE?KEY=VALUE&KEY=VALUE runs it with those `--set` overrides (a
table of degrees: thick-cylinder.yaml?discretization.degree=6); KEY is a path into its summary.json, dot-separated, with list
indices as numbers (contact_pairs.0.normal_force) and a trailing '#' for a list's length
(adapt.history#). VALUE is the number as the README shows it: it matches when it equals the
summary's value rounded to the digits shown (half a unit of the last digit; an integer
exactly). Times are not marked: they differ from run to run and machine to machine (the
READMEs say when and where they were measured).

--check writes nothing: it prints every stale figure (README:line, key, shown, current) and
exits 1 if there is one; tests/docs runs it over examples/*/README.md, so a figure cannot drift
from the program. Without --check the stale values are rewritten with the digits they had.
Without README arguments: every examples/**/README.md with a marker.
Exit status: 0 current (or rewritten), 1 stale (--check), 2 a wrong marker, a file or key that
does not exist, a run without summary.json, or a wrong command line.
"""
import argparse
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

SCRIPTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(SCRIPTS)
sys.path.insert(0, SCRIPTS)
from hpc_run import default_hpcontact  # noqa: E402

FIGURE = re.compile(r"<!--fig:(?P<file>[^:>]+):(?P<key>[\w.#-]+)-->(?P<value>.*?)<!--/fig-->")
NUMBER = re.compile(r"^[+\-−]?(\d+\.?\d*|\.\d+)([eE][+\-]?\d+)?$")


class MarkerError(Exception):
    """A marker that cannot be checked: its file, key or value is wrong (exit 2)."""


def lookup(summary, key, where):
    """summary.json's entry at KEY (dots, list indices, a trailing '#' for a length)."""
    length = key.endswith("#")
    node = summary
    for part in (key[:-1] if length else key).split("."):
        if isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        elif isinstance(node, dict) and part in node:
            node = node[part]
        else:
            raise MarkerError(f"{where}: summary.json has no '{key}' (no '{part}')")
    if length:
        if not isinstance(node, list):
            raise MarkerError(f"{where}: '{key[:-1]}' is not a list, so it has no length")
        return len(node)
    if isinstance(node, bool) or not isinstance(node, (int, float)):
        raise MarkerError(f"{where}: '{key}' is not a number ({json.dumps(node)[:60]})")
    return node


def shown_digits(text):
    """The decimals VALUE shows (after its point, less its exponent), None for an integer."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    if "." not in mantissa and not exponent:
        return None
    return decimals - (int(exponent) if exponent else 0)


def matches(shown, value):
    """Whether the README's VALUE is the summary's value to the digits it shows."""
    number = float(shown.replace("−", "-"))
    decimals = shown_digits(shown)
    if decimals is None:
        return number == round(value)
    return abs(number - value) <= 0.5 * 10.0 ** (-decimals) * (1 + 1e-9)


def formatted(shown, value):
    """value written as VALUE was (its digits, its minus sign)."""
    decimals = shown_digits(shown)
    mantissa, _, exponent = shown.lower().partition("e")
    if exponent:
        text = f"{value:.{len(mantissa.split('.')[1]) if '.' in mantissa else 0}e}"
    elif decimals is None:
        text = str(round(value))
    else:
        text = f"{value:.{decimals}f}"
    return text.replace("-", "−") if "−" in shown else text


class Runs:
    """Each problem file run once, its summary.json kept."""

    def __init__(self, hpcontact, folder):
        self.hpcontact, self.folder, self.summaries = hpcontact, folder, {}

    def summary(self, run, where):
        if run in self.summaries:
            return self.summaries[run]
        path, _, query = run.partition("?")
        if not os.path.isfile(path):
            raise MarkerError(f"{where}: no problem file {os.path.relpath(path, ROOT)}")
        sets = []
        for setting in filter(None, query.split("&")):
            if "=" not in setting:
                raise MarkerError(f"{where}: '{setting}' is not KEY=VALUE")
            sets += ["--set", setting]
        out = os.path.join(self.folder, f"run{len(self.summaries)}")
        r = subprocess.run([self.hpcontact, "run", path, "--out", out, "-q", *sets], capture_output=True, text=True)
        for candidate in (os.path.join(out, "summary.json"), os.path.join(out, "last-good", "summary.json")):
            if os.path.isfile(candidate) and (r.returncode == 0 or "last-good" in candidate):
                with open(candidate) as f:
                    self.summaries[run] = json.load(f)
                return self.summaries[run]
        raise MarkerError(f"{where}: {os.path.relpath(path, ROOT)} wrote no summary.json "
                          f"(exit {r.returncode}): {r.stderr.strip()[:300]}")


def check_readme(readme, runs):
    """The README's stale figures [(line, key, shown, current, start, end)] in file order."""
    with open(readme, encoding="utf-8") as f:
        text = f.read()
    stale = []
    for m in FIGURE.finditer(text):
        line = text.count("\n", 0, m.start()) + 1
        where = f"{os.path.relpath(readme, ROOT)}:{line}"
        shown = m.group("value").strip()
        if not NUMBER.match(shown):
            raise MarkerError(f"{where}: the marked value '{shown}' is not a number")
        summary = runs.summary(os.path.join(os.path.dirname(readme), m.group("file")), where)
        value = lookup(summary, m.group("key"), where)
        if not matches(shown, value):
            stale.append((line, m.group("key"), shown, value, m.start("value"), m.end("value")))
    return text, stale


def rewrite(readme, text, stale):
    for _, _, shown, value, start, end in reversed(stale):
        text = text[:start] + formatted(shown, value) + text[end:]
    with open(readme, "w", encoding="utf-8") as f:
        f.write(text)


def marked_readmes():
    found = []
    for path in sorted(glob.glob(os.path.join(ROOT, "examples", "**", "README.md"), recursive=True)):
        with open(path, encoding="utf-8") as f:
            if FIGURE.search(f.read()):
                found.append(path)
    return found


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("readmes", nargs="*", help="READMEs to check (default: every marked example README)")
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 if a figure is stale")
    parser.add_argument("--hpcontact", default=default_hpcontact(), help="the program (default: build/hpcontact)")
    args = parser.parse_args(argv)
    if not os.path.isfile(args.hpcontact):
        parser.error(f"no program at {args.hpcontact} (build it, or give --hpcontact)")
    readmes = [os.path.abspath(r) for r in args.readmes] or marked_readmes()
    any_stale = False
    with tempfile.TemporaryDirectory(prefix="example-figures-") as tmp:
        runs = Runs(args.hpcontact, tmp)
        for readme in readmes:
            try:
                text, stale = check_readme(readme, runs)
            except (MarkerError, OSError) as e:
                print(f"example_figures: {e}", file=sys.stderr)
                return 2
            for line, key, shown, value, _, _ in stale:
                print(f"{os.path.relpath(readme, ROOT)}:{line}: {key} is {value:.10g}, the README shows {shown}")
            any_stale |= bool(stale)
            if stale and not args.check:
                rewrite(readme, text, stale)
    if any_stale and args.check:
        print("stale figures: run scripts/example_figures.py to rewrite them (and reread the prose around them)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
