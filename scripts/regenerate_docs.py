#!/usr/bin/python3
"""Regenerates what the tutorial shows of the program: it runs the tutorial's commands and
rewrites the marked blocks and values of docs/tutorial.md, examples/tutorial/README.md and
the tutorial section of docs/examples.md.

usage: regenerate_docs.py [--check] [--hpcontact PATH] [--python-path DIR] [--update-reference]

The commands run in a temporary folder that looks like the repository root (examples/ and
scripts/ linked, build/hpcontact the program), so the logs read as they would from the root.
Marked in the documents (HTML comments: invisible when rendered):

  <!-- generated: NAME -->          a block (a fenced log, file excerpt or table), replaced
  ...                               whole by what the runs give for NAME
  <!-- end: NAME -->
  <!--v:NAME-->value<!--/v-->       one value in the text (a count, a factor, an error)

NAME is one of BLOCKS or VALUES below. --check writes nothing: it compares the documents with
what the runs give, times masked (wall-clock seconds differ from run to run), prints a diff
of what is stale and exits 1 if anything is; tests/docs runs it, so the tutorial cannot drift
from the program. Without --check the documents are rewritten (then review the prose around
the numbers: it says what they mean, and a changed count may change what it should say).

A command the tutorial shows failing (or succeeding) that does not any more is an error
naming the block: the text around it needs rewriting, not only the log. The reference curve
examples/tutorial/reference-pressure.csv is the hp run's pressure.csv; it is rewritten only
with --update-reference (the p-study's errors are measured against it).
Exit status: 0 current (or rewritten), 1 stale (--check) or a command did not behave as the
tutorial says, 2 a wrong command line or no program.
"""
import csv
import difflib
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

SCRIPTS = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(SCRIPTS)
sys.path.insert(0, SCRIPTS)
from hpc_run import default_hpcontact, read_columns, read_vtu, script_parser  # noqa: E402

DOCUMENTS = ["docs/tutorial.md", "examples/tutorial/README.md", "docs/examples.md"]
CASE = "examples/tutorial/punch.yaml"
BLOCK = re.compile(r"(<!-- generated: (?P<name>[\w-]+) -->\n)(?P<body>.*?)(<!-- end: (?P=name) -->)", re.S)
VALUE = re.compile(r"(<!--v:(?P<name>[\w.-]+)-->)(?P<value>.*?)(<!--/v-->)")
# Wall-clock times: a number of seconds, or summary.json's wall_time_s.
TIME = [re.compile(r"\b\d+(\.\d+)?(e[-+]?\d+)? s\b"), re.compile(r'("wall_time_s": )[0-9.e+-]+'),
        re.compile(r"((?:elapsed |remaining ~|solve ~))\d+:\d\d(?::\d\d)?")]  # progress lines


class TutorialError(Exception):
    """A command did not do what the tutorial says it does; the message names the block."""


class Workspace:
    """A temporary folder that looks like the repository root to the tutorial's commands."""

    def __init__(self, hpcontact, python_path):
        self.dir = tempfile.mkdtemp(prefix="hpcontact-docs-")
        for name in ("examples", "scripts"):
            os.symlink(os.path.join(ROOT, name), os.path.join(self.dir, name))
        os.makedirs(os.path.join(self.dir, "build"))
        os.symlink(os.path.abspath(hpcontact), os.path.join(self.dir, "build", "hpcontact"))
        self.env = dict(os.environ, PYTHONDONTWRITEBYTECODE="1")
        if python_path:
            self.env["PYTHONPATH"] = os.path.abspath(python_path)

    def run(self, block, command, expect=0, stdin=None):
        """Runs a command line as the tutorial writes it; its output (stdout, then stderr).
        TutorialError if its exit status is not `expect`."""
        args = command.split()
        if args[0].endswith(".py"):
            args = ["/usr/bin/python3"] + args
        r = subprocess.run(args, cwd=self.dir, env=self.env, capture_output=True, text=True,
                           input=stdin, timeout=1200)
        if r.returncode != expect:
            raise TutorialError(f"{block}: `{command}` exited {r.returncode}, the tutorial says "
                                f"{expect}; its output:\n{r.stdout}{r.stderr}")
        return (r.stdout + r.stderr).rstrip("\n")

    def path(self, *parts):
        return os.path.join(self.dir, *parts)

    def json(self, *parts):
        with open(self.path(*parts)) as f:
            return json.load(f)

    def close(self):
        shutil.rmtree(self.dir, ignore_errors=True)


def fenced(text, lang=""):
    return f"```{lang}\n{text}\n```\n"


def excerpt(lines, keep):
    """The lines of `lines` that `keep` selects, "  ..." where lines are left out."""
    out, skipped = [], False
    for i, line in enumerate(lines):
        if keep(i, line):
            if skipped:
                out.append("  ...")
            out.append(line)
            skipped = False
        else:
            skipped = True
    if skipped:
        out.append("  ...")
    return out


def first_step_iterations(lines):
    """A run's log with the Newton iteration lines of its first load step only; those of the
    later steps are one "    ..." each."""
    out, steps_done = [], 0
    for line in lines:
        if line.lstrip().startswith("iteration "):
            if steps_done == 0:
                out.append(line)
            elif out[-1] != "    ...":
                out.append("    ...")
        else:
            steps_done += line.lstrip().startswith("load step ")
            out.append(line)
    return out


def key_lines(lines, prefix, first, last, also=()):
    """The lines that start with `prefix`: the first `first` and the last `last` of them, with
    "  ..." for those left out, "..." for the lines before; lines starting with an `also` prefix
    are kept where they are."""
    marked = [i for i, line in enumerate(lines) if line.lstrip().startswith(prefix)]
    keep = set(marked[:first] + marked[-last:])
    out = ["..."] if marked and marked[0] > 0 else []
    gap = False
    for i, line in enumerate(lines):
        if i in keep or line.lstrip().startswith(tuple(also)):
            if gap:
                out.append("  ...")
            out.append(line)
            gap = False
        elif i in marked:
            gap = True
    return out


def compact_json(value, indent=0, column=0):
    """summary.json as the tutorial prints it: keys sorted, two-space indent, a list of numbers
    on one line, a list of lists one inner list a line (aligned); `column` is where the value
    starts on its line."""
    pad = " " * indent
    if isinstance(value, dict):
        items = []
        for k in sorted(value):
            head = f'{pad}  "{k}": '
            items.append(head + compact_json(value[k], indent + 2, len(head)))
        return "{\n" + ",\n".join(items) + f"\n{pad}}}"
    if isinstance(value, list) and value and all(isinstance(v, list) for v in value):
        return "[" + (",\n" + " " * (column + 1)).join(json.dumps(v) for v in value) + "]"
    return json.dumps(value)


def punch_with_pressure_load(text):
    """punch.yaml with the push on the top replaced by a pressure and no force control."""
    import yaml
    spec = yaml.safe_load(text)
    body = spec["bodies"][0]
    body["constraints"] = [c for c in body["constraints"] if "top" not in c.get("edges", [])]
    body["loads"] = [{"edges": ["top"], "pressure": 3000}]
    spec.get("solver", {}).pop("target_resultant", None)
    if not spec.get("solver"):
        spec.pop("solver", None)
    return yaml.safe_dump(spec, sort_keys=False)


PYTHON_SESSION_RUNNER = r'''
import contextlib, io, sys, traceback
source = sys.stdin.read().split("\n")
statements, current = [], None
for line in source:
    if line.startswith(">>> "):
        current = [line[4:]]
        statements.append(current)
    elif line.startswith("... ") or line == "...":
        current.append(line[4:])
env = {}
for lines in statements:
    code = "\n".join(lines) + ("\n" if len(lines) > 1 else "")
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        try:
            exec(compile(code, "<tutorial>", "single"), env)
        except Exception as e:
            name = type(e).__module__ + "." + type(e).__qualname__
            print("Traceback (most recent call last):\n  ...\n" + name + ": " + str(e))
    print("\x00" + out.getvalue(), end="")
'''


def python_session(ws, block_text):
    """The tutorial's Python session, each statement's output replaced by what it prints now."""
    body = block_text.split("\n", 1)[1].rsplit("```", 1)[0]   # inside the fence
    lines = body.rstrip("\n").split("\n")
    r = subprocess.run(["/usr/bin/python3", "-c", PYTHON_SESSION_RUNNER], cwd=ws.dir, env=ws.env,
                       input=body, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise TutorialError(f"python: the session did not run:\n{r.stderr}")
    outputs = r.stdout.split("\x00")[1:]
    result, k = [], -1
    for line in lines:
        if line.startswith(">>> "):
            if k >= 0 and outputs[k]:
                result += outputs[k].rstrip("\n").split("\n")
            k += 1
            result.append(line)
        elif line.startswith("... ") or line == "...":
            result.append(line)
    if k >= 0 and outputs[k]:
        result += outputs[k].rstrip("\n").split("\n")
    return fenced("\n".join(result), "python")


def generate(ws, documents, update_reference):
    """Runs everything; returns {block name: text}, {value name: text}."""
    blocks, values = {}, {}
    run_cmd = f"build/hpcontact run {CASE} --out results/punch"

    # §4, §7: check, a pressure load that cannot work, the run.
    blocks["check"] = fenced(f"$ build/hpcontact check {CASE}\n" +
                             ws.run("check", f"build/hpcontact check {CASE}"))
    with open(os.path.join(ROOT, CASE)) as f:
        variant = punch_with_pressure_load(f.read())
    with open(ws.path("punch-pressure.yaml"), "w") as f:
        f.write(variant)
    log = ws.run("pressure-load-error", "build/hpcontact run punch-pressure.yaml --out results/err "
                 "--set contact[0].enforcement=penalty", expect=1)
    blocks["pressure-load-error"] = fenced(log.splitlines()[-1])
    log = ws.run("run", run_cmd + " -v")  # -v: the Newton iterations too
    blocks["run"] = fenced(f"$ {run_cmd} -v\n" + "\n".join(first_step_iterations(log.split("\n"))))
    summary = ws.json("results", "punch", "summary.json")
    c = summary["contact"]
    path = read_columns(ws.path("results", "punch", "path.csv"))
    push = abs(summary["load_factor"] * 0.01)
    values.update({
        "load_steps": str(summary["load_steps"]),
        "newton_iterations": str(summary["newton_iterations"]),
        "path_rows": str(len(path["step"])),
        "contact_counts": ", ".join(re.findall(r"iteration \d+: .*?, (\d+) points in contact", log)),
        "load_factor": f"{summary['load_factor']:.5g}",
        "push": f"{push:.3g}",
        "dofs": str(summary["dofs"]),
        "strain_energy": f"{summary['strain_energy']:.6g}",
        "half_width": f"{c['half_width']:.4g}",
        "gamma_star_count": str(len(c.get("gamma_star", []))),
        "p_max": f"{c['p_max']:.0f}",
        "hertz_p0": f"{c['hertz_peak_pressure']:.0f}",
        "multiplier_e_L2_hertz": f"{c['multiplier']['e_L2_hertz_percent']:.0f}",
        "wall_time": f"{summary['wall_time_s']:.2g} s",
    })
    # §7: the same with the seed's penalty: force control by a first solve, a proportional
    # guess and secant steps.
    ws.run("penalty-run", f"{run_cmd}-penalty -q --set contact[0].enforcement=penalty")
    penalty = ws.json("results", "punch-penalty", "summary.json")
    path = read_columns(ws.path("results", "punch-penalty", "path.csv"))
    if len(path["step"]) < 3:
        raise TutorialError("penalty-run: force control with the penalty took fewer than three "
                            "solves; the text about its first solve, guess and secant steps is wrong")
    values.update({
        "penalty_first_force": f"{path['resultant_y'][0]:.0f}",
        "penalty_second_force": f"{path['resultant_y'][1]:.0f}",
        "penalty_secant_steps": str(len(path["step"]) - 2),
        "penalty_load_steps": str(penalty["load_steps"]),
        "penalty_newton_iterations": str(penalty["newton_iterations"]),
        "penalty_load_factor": f"{penalty['load_factor']:.5g}",
        "penalty_p_max": f"{penalty['contact']['p_max']:.0f}",
        "penalty_penetration": f"{penalty['contact']['max_penetration']:.2g}",
    })
    if summary["load_steps"] != 1:
        raise TutorialError(f"run: force control took {summary['load_steps']} load steps; the text "
                            "says exact contact solves it in one (section 7)")
    if len(c.get("gamma_star", [])) != 1:
        raise TutorialError("summary: the p = 8 run has more than one contact zone end; the text "
                            "about its single contact zone (section 8) needs rewriting")
    better = ws.run("better-guess", f"{run_cmd}-guess -q --set bodies[0].constraints[1].uy=-0.15")
    del better
    guess = ws.json("results", "punch-guess", "summary.json")
    values["guess_load_steps"] = str(guess["load_steps"])
    values["guess_newton_iterations"] = str(guess["newton_iterations"])
    # §7: --set examples: a ten times larger penalty is only an augmentation with exact contact.
    ws.run("stiffer", f"{run_cmd}-stiffer -q --set contact[0].penalty=2.1e9")
    stiffer = ws.json("results", "punch-stiffer", "summary.json")
    change = abs(stiffer["strain_energy"] / summary["strain_energy"] - 1)
    if change >= 1e-10:
        raise TutorialError(f"stiffer: a larger penalty changed the strain energy by {change:.1e} "
                            "relatively; the tutorial says it does not change the answer")
    values["stiffer_energy_change"] = "less than 1e-10"  # round-off; the text's claim is the bound
    ws.run("mortar", f"{run_cmd}-mortar -q --set contact[0].constraint=mortar")
    mortar = ws.json("results", "punch-mortar", "summary.json")
    values["mortar_strain_energy"] = f"{mortar['strain_energy']:.6g}"
    values["mortar_half_width"] = f"{mortar['contact']['half_width']:.4g}"

    # §8: summary.json, contact.csv, path.csv, plots, the .pvd.
    blocks["summary"] = fenced(compact_json(summary), "json")
    with open(ws.path("results", "punch", "contact.csv")) as f:
        rows = f.read().rstrip("\n").split("\n")
    blocks["contact-csv"] = fenced("\n".join(rows[:3] + ["..."] + rows[-1:]))
    values["contact_rows"] = str(len(rows) - 1)
    with open(ws.path("results", "punch", "path.csv")) as f:
        blocks["path-csv"] = fenced(f.read().rstrip("\n"))
    cmd = "scripts/plot_pressure.py results/punch"
    blocks["plot-pressure"] = fenced(f"$ {cmd}\n" + ws.run("plot-pressure", cmd))
    pressure = read_columns(ws.path("results", "punch", "pressure.csv"))
    b, p0 = c["hertz_half_width"], c["hertz_peak_pressure"]
    multiplier = [p / p0 for x, p in zip(pressure["x"], pressure["pressure_multiplier"]) if x <= 1.5 * b]
    values["multiplier_peak_p0"] = f"{max(multiplier):.3g}"
    values["multiplier_min_p0"] = f"{min(multiplier):.2g}"
    pressure = read_columns(ws.path("results", "punch-penalty", "pressure.csv"))
    penalty = [p / p0 for x, p in zip(pressure["x"], pressure["pressure_penalty"]) if x <= 1.5 * b]
    values["penalty_peak_p0"] = f"{max(penalty):.3g}"
    cmd = "scripts/plot_field.py results/punch/solution.vtu --scale 1"
    blocks["plot-field"] = fenced(f"$ {cmd}\n" + ws.run("plot-field", cmd))
    X, _, points, _ = read_vtu(ws.path("results", "punch", "solution.vtu"))
    vm = points["von_mises"]
    top = int(vm.argmax())
    values["von_mises_max"] = f"{vm[top]:.0f}"
    values["von_mises_max_y"] = f"{X[top][1]:.3g}"
    ws.run("pvd", f"{run_cmd}-steps -q --set output.steps=true")
    with open(ws.path("results", "punch-steps", "solution.pvd")) as f:
        pvd = f.read().rstrip("\n").split("\n")
    sets = [i for i, line in enumerate(pvd) if "<DataSet" in line]
    keep = set(range(sets[0] + 2)) | set(range(sets[-1], len(pvd))) if len(sets) > 4 else set(range(len(pvd)))
    blocks["pvd"] = fenced("\n".join(excerpt(pvd, lambda i, _: i in keep)).replace("  ...", "..."), "xml")
    values["pvd_steps"] = str(len(sets))

    # §10: the hp reference, the p-study, the rp run, the closed forms.
    cmd = (f"build/hpcontact run {CASE} --out results/punch-hp --set adapt.method=hp "
           "--set adapt.factor=0.17 --set discretization.condense=true")
    shown = key_lines(ws.run("hp-run", cmd).split("\n"), "hp step", 4, 3)
    blocks["hp-run"] = fenced(f"$ build/hpcontact run {CASE} --out results/punch-hp \\\n"
                              "      --set adapt.method=hp --set adapt.factor=0.17 --set "
                              "discretization.condense=true\n" + "\n".join(shown) +
                              "\n$ cp results/punch-hp/pressure.csv examples/tutorial/reference-pressure.csv")
    hp = ws.json("results", "punch-hp", "summary.json")
    history = hp["adapt"]["history"]
    values["hp_steps"] = str(len(history) - 1)
    values["hp_dofs"] = str(hp["dofs"])
    values["hp_zone_end"] = f"{hp['contact']['half_width']:.6g}"
    values["hp_zone_end_short"] = f"{hp['contact']['half_width']:.4g}"
    values["hp_e_L2_shtayerman"] = f"{hp['contact']['e_L2_shtayerman_percent']:.3g}"
    if update_reference:
        shutil.copyfile(ws.path("results", "punch-hp", "pressure.csv"),
                        os.path.join(ROOT, "examples", "tutorial", "reference-pressure.csv"))

    cmd = "examples/tutorial/p_study.py --hpcontact build/hpcontact --out results/tutorial-study"
    log = ws.run("p-study-log", cmd).split("\n")
    blocks["p-study-log"] = fenced(f"$ {cmd}\n" + "\n".join(
        excerpt(log, lambda i, _: i == 0 or i >= len(log) - 2)).replace("  ...", "..."))
    with open(ws.path("results", "tutorial-study", "study.md")) as f:
        blocks["p-study-table"] = f.read().rstrip("\n") + "\n"
    with open(ws.path("results", "tutorial-study", "study.csv")) as f:
        study = list(csv.DictReader(f))
    p_rows = {int(r["p"]): r for r in study if r["method"] == "p"}
    rp_rows = {int(r["p"]): r for r in study if r["method"] == "rp"}
    err = lambda r: float(r["e_L2_reference_percent"])  # noqa: E731
    values.update({
        "p_first_error": f"{err(p_rows[min(p_rows)]):.2g}",
        "p_last_error": f"{err(p_rows[max(p_rows)]):.2g}",
        "p6_error": f"{err(p_rows[6]):.2g}" if 6 in p_rows else "",
        "p10_error": f"{err(p_rows[10]):.2g}" if 10 in p_rows else "",
        "p8_half_width": f"{float(p_rows[8]['half_width']):.4g}",
        "p12_half_width": f"{float(p_rows[12]['half_width']):.4g}",
        "rp_relocations": f"{min(int(r['rp_iterations']) for r in rp_rows.values())}–"
                          f"{max(int(r['rp_iterations']) for r in rp_rows.values())}",
        "rp8_error": f"{err(rp_rows[8]):.2g}",
        "p8_error": f"{err(p_rows[8]):.2g}",
        "rp12_error": f"{err(rp_rows[12]):.2g}",
        "rp12_multiplier_error": f"{float(rp_rows[12]['e_L2_reference_multiplier_percent']):.2g}",
        "p8_multiplier_error": f"{float(p_rows[8]['e_L2_reference_multiplier_percent']):.2g}",
        "rp_p_max": f"{round(float(rp_rows[12]['p_max']), -2):.0f}",
        "p_study_time": f"{sum(float(r['wall_time_s']) for r in study):.3g} s",
        "rp_shtayerman_errors": ", ".join(f"{float(rp_rows[p]['e_L2_shtayerman_percent']):.3g}"
                                          for p in (8, 10, 12)),
    })
    ends = [hp["contact"]["half_width"]] + [float(r["half_width"]) for p, r in rp_rows.items() if p >= 8]
    values["converged_zone_ends"] = f"{min(ends):.4g}–{max(ends):.4g}"
    ws.run("rp14", f"build/hpcontact run {CASE} --out results/punch-rp14 -q --set adapt.method=rp "
           "--set discretization.degree=14 --set discretization.condense=true")
    rp14 = ws.json("results", "punch-rp14", "summary.json")
    values["rp14_shtayerman_error"] = f"{rp14['contact']['e_L2_shtayerman_percent']:.3g}"
    values["rp14_dofs"] = str(rp14["dofs"])

    cmd = f"build/hpcontact run {CASE} --out results/punch-rp --set adapt.method=rp"
    shown = key_lines(ws.run("rp-run", cmd).split("\n"), "rp iteration", 2, 1, also=["dofs "])
    plot = "scripts/plot_contact.py results/punch results/punch-rp --xlim 0 2.6"
    blocks["rp-run"] = fenced(f"$ {cmd}\n" + "\n".join(shown) + f"\n$ {plot}\n" +
                              ws.run("rp-run", plot))
    rp = ws.json("results", "punch-rp", "summary.json")
    values["rp_iterations"] = str(rp["adapt"]["iterations"])
    values["hertz_b"] = f"{c['hertz_half_width']:.4g}"
    values["shtayerman_b"] = f"{c['shtayerman_half_width']:.4g}"

    # The Python session (needs the module: --python-path).
    for doc in documents.values():
        for m in BLOCK.finditer(doc):
            if m.group("name") == "python":
                blocks["python"] = python_session(ws, m.group("body"))
    return blocks, values


def render(text, blocks, values, where):
    """The document with its marked blocks and values replaced; KeyError names a mark that has
    no generator."""
    def block(m):
        name = m.group("name")
        if name not in blocks:
            raise KeyError(f"{where}: block '{name}' has no generator in scripts/regenerate_docs.py")
        return m.group(1) + blocks[name] + m.group(4)

    def value(m):
        name = m.group("name")
        if name not in values:
            raise KeyError(f"{where}: value '{name}' has no generator in scripts/regenerate_docs.py")
        return m.group(1) + values[name] + m.group(4)

    return VALUE.sub(value, BLOCK.sub(block, text))


def masked(text):
    """The text with wall-clock times replaced by <time>."""
    return TIME[2].sub(r"\1<time>", TIME[1].sub(r"\1<time>", TIME[0].sub("<time> s", text)))


NUMBER = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")
ROUND_OFF = 1e-8  # below it a printed number is a residual or a gap of round-off
RELATIVE = 1e-8   # other numbers: the same to this, whatever the BLAS's order of operations


def same(a, b):
    """Whether two documents show the same, times aside: the same text between their numbers,
    and numbers equal to RELATIVE, or both below ROUND_OFF in magnitude (a final Newton
    residual, a gap of 1e-19: what another BLAS or CPU changes)."""
    a, b = masked(a), masked(b)
    if NUMBER.sub("#", a) != NUMBER.sub("#", b):
        return False
    for x, y in zip(NUMBER.findall(a), NUMBER.findall(b)):
        if x == y:
            continue
        u, v = float(x), float(y)
        if abs(u) < ROUND_OFF and abs(v) < ROUND_OFF:
            continue
        if abs(u - v) > RELATIVE * max(abs(u), abs(v)):
            return False
    return True


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("--check", action="store_true",
                    help="compare only: print what is stale and exit 1 if anything is")
    ap.add_argument("--hpcontact", default=default_hpcontact(),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--python-path", default=os.path.join(ROOT, "build", "python"),
                    help="folder of the built Python module, for the Python session "
                         "(default %(default)s)")
    ap.add_argument("--update-reference", action="store_true",
                    help="also copy the hp run's pressure.csv to "
                         "examples/tutorial/reference-pressure.csv")
    args = ap.parse_args(argv)
    if not os.access(args.hpcontact, os.X_OK):
        print(f"regenerate_docs: no hpcontact program at {args.hpcontact} (--hpcontact)",
              file=sys.stderr)
        return 2
    if args.check and args.update_reference:
        print("regenerate_docs: --check writes nothing; leave out --update-reference", file=sys.stderr)
        return 2
    documents = {}
    for name in DOCUMENTS:
        with open(os.path.join(ROOT, name)) as f:
            documents[name] = f.read()
    ws = Workspace(args.hpcontact, args.python_path)
    try:
        blocks, values = generate(ws, documents, args.update_reference)
        fresh = {name: render(text, blocks, values, name) for name, text in documents.items()}
    except (TutorialError, KeyError) as e:
        print(f"regenerate_docs: {e}", file=sys.stderr)
        return 1
    finally:
        ws.close()
    stale = 0
    for name, text in documents.items():
        if args.check:
            if not same(text, fresh[name]):
                stale += 1
                diff = difflib.unified_diff(masked(text).splitlines(), masked(fresh[name]).splitlines(),
                                            f"{name} (now)", f"{name} (the program's)", lineterm="")
                print("\n".join(diff))
        elif not same(text, fresh[name]):  # a new time or round-off alone is no change
            with open(os.path.join(ROOT, name), "w") as f:
                f.write(fresh[name])
            print(f"rewrote {name}")
    if args.check and stale:
        print(f"regenerate_docs: {stale} document(s) stale: run scripts/regenerate_docs.py",
              file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
