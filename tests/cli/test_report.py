"""report.html (issue 44): the page a run writes beside summary.json, and a study beside
study.csv, opened in headless Chromium. The rendered page shall hold every number it marks with a
data-key equal to summary.json's at that key (a study's table: study.csv's cells), draw a pressure
curve per pair with a point per contact row, von Mises on every element and the hp history with
a point per step, load nothing from outside the page, say that a failed run's page is its last
converged state and why, and show a user's string (a body name) as written, never as markup."""
import json
import math
import os
import re
import shutil
import subprocess
from html.parser import HTMLParser

import pytest

from conftest import csv_rows, scaled_timeout

CHROMIUM = shutil.which("chromium")
needs_chromium = pytest.mark.skipif(CHROMIUM is None, reason="chromium not installed "
                                    "(scripts/install-deps.sh installs it)")
HP = "examples/hertz/hp.yaml"        # 9 hp steps, 2751 DOF: about 1 s
P5 = "examples/hertz/p5.yaml"        # one p = 5 solve: 0.1 s
BLOCK = "tests/cli/data/crushed-block.yaml"  # fails at its third load step, the second kept
ODD_NAME = '<b>&"x\'s'


class Page(HTMLParser):
    """The elements of a page a test reads: every element's tag and attributes in order, the
    text of each element marked data-key (or data-row/data-column, data-status, data-body), and
    the polylines and polygons of each <svg data-figure>."""

    def __init__(self, text):
        super().__init__(convert_charrefs=True)
        self.tags, self.marked, self.figures = [], [], {}
        self._open = []      # [tag, attrs, text] of marked elements being read
        self._figure = None  # the data-figure of the <svg> being read
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append((tag, a))
        if tag == "svg" and "data-figure" in a:
            self._figure = a["data-figure"]
            self.figures[self._figure] = {"svg": a, "polyline": [], "polygon": []}
        elif self._figure and tag in ("polyline", "polygon"):
            self.figures[self._figure][tag].append(a)
        if any(k in a for k in ("data-key", "data-row", "data-status", "data-body")):
            self._open.append([tag, a, ""])

    def handle_endtag(self, tag):
        if tag == "svg":
            self._figure = None
        if self._open and self._open[-1][0] == tag:
            self.marked.append(tuple(self._open.pop()))

    def handle_data(self, data):
        for element in self._open:
            element[2] += data

    def with_attribute(self, name):
        return [(a, text) for _, a, text in self.marked if name in a]


def rendered(path, tmp_path):
    """The DOM of `path` as headless Chromium renders it (--dump-dom), in a HOME and profile of
    its own; its stderr (a missing D-Bus, ...) is not an error."""
    home = tmp_path / "chromium-home"
    home.mkdir(exist_ok=True)
    r = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                        f"--user-data-dir={home / 'profile'}", "--dump-dom",
                        "file://" + os.path.abspath(path)],
                       capture_output=True, text=True, timeout=scaled_timeout(120),
                       env=dict(os.environ, HOME=str(home)))
    assert r.returncode == 0, r.stderr
    assert "</html>" in r.stdout, r.stdout[-500:]
    return Page(r.stdout)


def at_key(summary, key):
    node = summary
    for part in key.split("."):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def assert_matches_summary(page, summary):
    """Every data-key element's text is summary.json's value at that key (numbers to 1e-9
    relative); returns the keys."""
    keys = []
    for a, text in page.with_attribute("data-key"):
        key, value = a["data-key"], at_key(summary, a["data-key"])
        if isinstance(value, bool):
            assert text == ("true" if value else "false"), key
        elif isinstance(value, (int, float)):
            assert math.isclose(float(text), value, rel_tol=1e-9, abs_tol=0), (key, text, value)
        elif value is None:
            assert text == "none", key
        else:
            assert text == value, (key, text, value)
        keys.append(key)
    return keys


def points(polyline):
    return [tuple(map(float, p.split(","))) for p in polyline["points"].split()]


def series_points(figure, role):
    return [p for line in figure["polyline"] if line.get("data-series") == role for p in points(line)]


def assert_self_contained(path):
    """No script, style sheet, image, font or frame from anywhere: no URL but the page's own
    fragments (url(#...))."""
    text = open(path, encoding="utf-8").read()
    for forbidden in ("<script", "<link", "<img", "<iframe", "@import", "http://", "https://",
                      "file://", " src=", " href="):
        assert forbidden not in text, forbidden
    assert all(u.startswith("url(#") for u in re.findall(r"url\([^)]*\)", text))


def run(hpcontact, root, case, out, *sets, code=0):
    args = ["run", os.path.join(root, case), "--out", out, "-q"]
    for s in sets:
        args += ["--set", s]
    r = hpcontact(*args)
    assert r.returncode == code, r.stderr
    return r


@needs_chromium
def test_hp_run_report_shows_summary_numbers_and_figures(hpcontact, root, tmp_path):
    """An hp run's rendered report.html: every marked number is summary.json's, the pressure
    plot has a point per contact row on a line affine in the pressure, von Mises covers every
    element of the result's mesh, the history plot a point per hp step in order of DOF."""
    out = tmp_path / "hp"
    run(hpcontact, root, HP, out)
    summary = json.loads((out / "summary.json").read_text())
    assert_self_contained(out / "report.html")
    page = rendered(out / "report.html", tmp_path)

    keys = assert_matches_summary(page, summary)
    n = len(summary["adapt"]["history"])
    for key in ("dofs", "strain_energy", "newton_iterations", "contact_pairs.0.pressure_max",
                "contact_pairs.0.normal_force", "contact_pairs.0.half_width",
                "contact_pairs.0.e_L2_hertz_percent", "contact_pairs.0.body",
                f"adapt.history.{n - 1}.dofs", f"adapt.history.{n - 1}.e_L2_hertz_percent"):
        assert key in keys, key
    assert [a["data-status"] for a, _ in page.with_attribute("data-status")] == ["converged"]

    # the pressure: a point per row of contact.csv, in its order, x affine in s and y in the
    # pressure
    rows = [r for r in csv_rows(out / "contact.csv") if r["pair"] == "0"]
    drawn = series_points(page.figures["pressure-0"], "pressure")
    assert len(drawn) == len(rows) > 50
    for axis, column, sign in ((0, "s", 1), (1, "pressure", -1)):  # larger pressures higher up
        v = [float(r[column]) for r in rows]
        hi, lo = max(range(len(v)), key=v.__getitem__), min(range(len(v)), key=v.__getitem__)
        slope = (drawn[hi][axis] - drawn[lo][axis]) / (v[hi] - v[lo])
        assert slope * sign > 0
        for point, value in zip(drawn, v):
            assert point[axis] == pytest.approx(drawn[lo][axis] + slope * (value - v[lo]), abs=0.02)
    assert len(series_points(page.figures["pressure-0"], "pressure_from_stress")) == len(rows)

    # von Mises: n x n cells on each of the result's elements
    elements = summary["adapt"]["history"][summary["adapt"]["result_step"]]["elements"]
    field = page.figures["von-mises"]
    cells = [c for c in field["polygon"] if c.get("class") == "cell"]
    assert int(field["svg"]["data-cells"]) == len(cells)
    assert len(cells) % elements == 0 and math.isqrt(len(cells) // elements) ** 2 == len(cells) // elements
    assert len([c for c in field["polygon"] if c.get("class") == "outline"]) == elements

    # the hp history: a point per step, x increasing with DOF, y falling with the error
    history = summary["adapt"]["history"]
    drawn = series_points(page.figures["history"], "e_L2_hertz_percent")
    assert len(drawn) == len(history)
    for (a, b) in zip(range(n), range(1, n)):
        da, db = history[a]["dofs"], history[b]["dofs"]
        ea, eb = history[a]["e_L2_hertz_percent"], history[b]["e_L2_hertz_percent"]
        assert (drawn[b][0] - drawn[a][0]) * (db - da) > 0
        assert (drawn[b][1] - drawn[a][1]) * (eb - ea) < 0


@needs_chromium
def test_study_report_table_equals_study_csv(hpcontact, root, tmp_path):
    """A study's rendered report.html: its table's cells are study.csv's, row by row and column
    by column, and its convergence plot has a point per run for each error column."""
    study = tmp_path / "sweep.yaml"
    study.write_text(f"study: p-sweep\ntitle: 'Hertz, p = 2 to 5 <p>'\n"
                     f"case: {os.path.join(root, P5)}\n"
                     "set: ['contact[0].compare.reference=\"\"']\n"
                     "sweep: {discretization.degree: [2, 3, 4, 5]}\n")
    out = tmp_path / "study"
    r = hpcontact("study", study, "--out", out, "--jobs", "2")
    assert r.returncode == 0, r.stderr
    assert_self_contained(out / "report.html")
    rows = csv_rows(out / "study.csv")
    page = rendered(out / "report.html", tmp_path)
    cells = {(int(a["data-row"]), a["data-column"]): text for a, text in page.with_attribute("data-row")}
    assert len(cells) == len(rows) * len(rows[0]) and len(rows) == 4
    for i, row in enumerate(rows):
        for column, value in row.items():
            assert cells[(i, column)] == value, (i, column)
    plotted = [c for c in rows[0] if c.endswith("_percent")]
    assert "contact.e_L2_hertz_percent" in plotted
    for column in plotted:
        assert len(series_points(page.figures["convergence"], column)) == len(rows), column
    # each run's own page is there too
    for i in range(4):
        assert (out / "runs" / os.path.basename(rows[i]["run_dir"]) / "report.html").exists()


@needs_chromium
def test_failed_run_report_says_so(hpcontact, root, tmp_path):
    """A run that fails after a converged step: its report is in last-good/ only, under a banner
    that says the run failed, why (summary.json's message), and that this is the last converged
    state; nothing on it says converged."""
    out = tmp_path / "block"
    run(hpcontact, root, BLOCK, out, code=1)
    assert not (out / "report.html").exists()
    summary = json.loads((out / "last-good" / "summary.json").read_text())
    assert summary["converged"] is False
    page = rendered(out / "last-good" / "report.html", tmp_path)
    status = page.with_attribute("data-status")
    assert [a["data-status"] for a, _ in status] == ["failed"]
    text = " ".join(status[0][1].split())
    assert text.startswith("The run failed: ") and "this is the last converged state" in text
    assert " ".join(summary["message"].split()) in text
    assert_matches_summary(page, summary)


@needs_chromium
def test_user_strings_are_escaped(hpcontact, root, tmp_path):
    """A body named <b>&"x's: the rendered page shows the name as written (its table cell, the
    pair's body) and holds no <b> element."""
    case = tmp_path / "odd.yaml"
    text = open(os.path.join(root, P5)).read().replace("reference-pressure.csv", "")
    case.write_text(text.replace("name: cylinder", "name: " + json.dumps(ODD_NAME))
                        .replace("body: cylinder", "body: " + json.dumps(ODD_NAME)))
    out = tmp_path / "odd"
    r = hpcontact("run", case, "--out", out, "-q", "--set", 'contact[0].compare.reference=""')
    assert r.returncode == 0, r.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["contact_pairs"][0]["body"] == ODD_NAME
    page = rendered(out / "report.html", tmp_path)
    assert [text for _, text in page.with_attribute("data-body")] == [ODD_NAME]
    assert "contact_pairs.0.body" in assert_matches_summary(page, summary)
    assert not any(tag == "b" for tag, _ in page.tags)
    assert ODD_NAME not in (out / "report.html").read_text()  # only escaped in the file
