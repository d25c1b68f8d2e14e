#!/usr/bin/python3
"""Runs a study (a table of Hertz runs, e.g. the seed's Table 5.1) and tabulates and plots it.

usage: study_table.py STUDY.yaml [--hpcontact PATH] --out DIR [--jobs N] [--vtu]

STUDY.yaml lists the rows: label, case (a problem file relative to the study file), optional
`set` overrides and the seed's values for the side-by-side columns; its format is described in
examples/hertz/table-5-1.yaml. Every row is run with `hpcontact run CASE --out DIR/runs/NN-NAME
-q` (N at a time, default 2; --vtu keeps the .vtu output, off by default), a progress line is
printed as each row finishes, and the script writes

  DIR/table.csv    one row per run: summary.json values as written there (full precision) and
                   the seed's values; columns in CSV_COLUMNS below
  DIR/table.md     the same as a Markdown table, rounded, with a legend
  DIR/pressure.png p/p0 over x/b (b, p0: Hertz) of every row's pressure_from_stress against
                   Hertz, Shtayerman and the reference curve, full range [0, 1.5] and zoomed on
                   the end of the contact zone x/b in [0.85, 1.1] (seed Fig. 5.11-5.14)

A row whose run fails is reported (its folder, the program's last message), left empty in the
table and plot, and makes the script exit with status 1 after writing what it has.
"""
import argparse
import concurrent.futures
import csv
import json
import math
import os
import re
import sys
import threading

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
from hpc_run import StudyError, check_labelled, csv_number, read_columns, run_case  # noqa: E402
RUN_KEYS = {"label", "case", "set", "seed"}
SEED_KEYS = {"dofs", "time_s", "vs_hertz", "vs_shtayerman"}
CONTACT_KEYS = ["e_seed_hertz_percent", "e_seed_shtayerman_percent", "e_seed_reference_percent",
                "e_L2_hertz_percent", "e_L2_shtayerman_percent", "e_L2_reference_percent",
                "half_width", "p_max"]
# The same measures of the penalty traction (summary.json contact.penalty_traction).
PENALTY_KEYS = ["e_seed_hertz_percent", "e_seed_shtayerman_percent", "e_L2_reference_percent"]
CSV_COLUMNS = (["label", "case", "run_dir", "converged", "dofs", "wall_time_s", "rp_iterations"]
               + CONTACT_KEYS + ["penalty_" + k for k in PENALTY_KEYS]
               + ["seed_dofs", "seed_time_s", "seed_vs_hertz", "seed_vs_shtayerman"])


def load_study(path):
    """The study as a dict, checked; case paths made absolute. PyYAML if installed, else JSON
    (the study files are JSON-compatible flow YAML with whole-line # comments)."""
    with open(path) as f:
        text = f.read()
    try:
        import yaml
    except ImportError:
        yaml = None
    try:
        if yaml is not None:
            data = yaml.safe_load(text)
        else:
            data = json.loads("\n".join("" if line.lstrip().startswith("#") else line
                                        for line in text.splitlines()))
    except Exception as e:  # noqa: BLE001 - any parse error is reported with the file name
        raise StudyError(f"{path}: cannot parse the study file: {e}")
    where = lambda s: f"{path}: {s}"  # noqa: E731
    if not isinstance(data, dict):
        raise StudyError(where("a study file is a mapping with keys study, title, runs"))
    unknown = set(data) - {"study", "title", "runs"}
    if unknown:
        raise StudyError(where(f"unknown key(s) {', '.join(sorted(unknown))}"))
    if not isinstance(data.get("study"), str):
        raise StudyError(where("'study' (the study's name, a string) is required"))
    runs = data.get("runs")
    if not isinstance(runs, list) or not runs:
        raise StudyError(where("'runs' must be a non-empty list"))
    folder = os.path.dirname(os.path.abspath(path))
    check_labelled(runs, "runs", RUN_KEYS, "each run is a mapping with label, case, set, seed", where)
    for i, run in enumerate(runs):
        at = lambda s: where(f"runs[{i}]: {s}")  # noqa: E731
        if not isinstance(run.get("case"), str) or not run["case"]:
            raise StudyError(at("'case' (a string) is required"))
        run["case_path"] = os.path.normpath(os.path.join(folder, run["case"]))
        if not os.path.isfile(run["case_path"]):
            raise StudyError(at(f"case file {run['case_path']} does not exist"))
        sets = run.setdefault("set", [])
        if not isinstance(sets, list) or not all(isinstance(s, str) and "=" in s for s in sets):
            raise StudyError(at("'set' is a list of \"key=value\" strings"))
        seed = run.setdefault("seed", {})
        if not isinstance(seed, dict) or set(seed) - SEED_KEYS:
            raise StudyError(at(f"'seed' is a mapping with keys among {sorted(SEED_KEYS)}"))
        for k, v in seed.items():
            if not isinstance(v, (int, float)) or isinstance(v, bool):
                raise StudyError(at(f"seed.{k} must be a number"))
    return data


def run_one(hpcontact, run, out_dir, vtu):
    return run_case(hpcontact, run["case_path"], out_dir, run["set"], vtu)


def csv_row(run, result):
    s = result.get("summary") or {}
    c = s.get("contact", {})
    seed = run["seed"]
    row = {"label": run["label"], "case": run["case"], "run_dir": result["run_dir"],
           "converged": csv_number(s.get("converged")) if s else "failed",
           "dofs": csv_number(s.get("dofs")), "wall_time_s": csv_number(s.get("wall_time_s"))}
    row["rp_iterations"] = csv_number(s.get("adapt", {}).get("iterations"))
    row.update({k: csv_number(c.get(k)) for k in CONTACT_KEYS})
    pen = c.get("penalty_traction", {})
    row.update({"penalty_" + k: csv_number(pen.get(k)) for k in PENALTY_KEYS})
    row.update({"seed_dofs": csv_number(seed.get("dofs")), "seed_time_s": csv_number(seed.get("time_s")),
                "seed_vs_hertz": csv_number(seed.get("vs_hertz")),
                "seed_vs_shtayerman": csv_number(seed.get("vs_shtayerman"))})
    return row


def fmt(v, digits):
    if v is None or v == "":
        return "-"
    if isinstance(v, int) and not isinstance(v, bool):
        return str(v)
    return f"{v:.{digits}f}"


def fmt_time(t):
    if t is None:
        return "-"
    return f"{t:.3f}" if t < 1 else f"{t:.2f}" if t < 100 else f"{t:.0f}"


def write_markdown(path, study, runs, results, jobs):
    head = ["discretisation", "DOF", "time [s]", "e_seed vs Hertz [%]",
            "e_seed vs Shtayerman [%]", "e_seed vs reference [%]", "e_L2 vs Hertz [%]",
            "e_L2 vs Shtayerman [%]", "e_L2 vs reference [%]", "half width [mm]",
            "penalty: e_seed vs Hertz [%]", "penalty: e_seed vs Shtayerman [%]",
            "penalty: e_L2 vs reference [%]", "seed DOF", "seed time [s]", "seed vs Hertz [%]", "seed vs Shtayerman [%]"]
    lines = []
    if study.get("title"):
        lines += [f"**{study['title']}**", ""]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    first = None
    for run, res in zip(runs, results):
        s, seed = res.get("summary"), run["seed"]
        if s is None:
            cells = [run["label"], "failed"] + ["-"] * 11
        else:
            first = first or s
            c = s.get("contact", {})
            cells = [run["label"], fmt(s.get("dofs"), 0), fmt_time(s.get("wall_time_s"))]
            cells += [fmt(c.get(k), 4) for k in CONTACT_KEYS[:3]]
            cells += [fmt(c.get(k), 2) for k in CONTACT_KEYS[3:6]]
            cells += [fmt(c.get("half_width"), 4)]
            pen = c.get("penalty_traction", {})
            cells += [fmt(pen.get(k), 4) for k in PENALTY_KEYS[:2]] + [fmt(pen.get(PENALTY_KEYS[2]), 2)]
        cells += [fmt(seed.get("dofs"), 0), fmt(seed.get("time_s"), 0),
                  fmt(seed.get("vs_hertz"), 4), fmt(seed.get("vs_shtayerman"), 4)]
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    legend = ("e_seed: the squared measure that reads like the seed's Table 5.1, e_L2: relative "
              "L2 error of the pressure from stresses over [0, 1.5 b] (CASES.md §1); reference: "
              "our overkill solution of the same model (examples/hertz/reference.yaml). "
              "penalty: the same measures of the penalty traction eps_N <-g_N> instead of the "
              "pressure from stresses.")
    if first is not None:
        c = first.get("contact", {})
        if "hertz_half_width" in c:
            legend += (f" Hertz b = {c['hertz_half_width']:.4f} mm, p0 = "
                       f"{c['hertz_peak_pressure']:.1f} N/mm²; Shtayerman b = "
                       f"{c.get('shtayerman_half_width', float('nan')):.4f} mm.")
    legend += (f" Our times: whole run (wall clock, summary.json), {jobs} run(s) at a time on "
               f"{os.cpu_count()} cores; the seed's: a 2.4 GHz Core 2.")
    lines += [legend, ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def write_plot(path, study, runs, results):
    fig, (ax, az) = plt.subplots(1, 2, figsize=(13, 5.2), gridspec_kw={"width_ratios": [1.6, 1]})
    closed, b, p0, ref = None, None, None, None
    colours = plt.get_cmap("tab10" if len(runs) <= 10 else "tab20")
    curves = []
    for i, (run, res) in enumerate(zip(runs, results)):
        s = res.get("summary")
        pressure = os.path.join(res["run_dir_abs"], "pressure.csv")
        if s is None or "hertz_half_width" not in s.get("contact", {}) or \
                not os.path.isfile(pressure):
            continue
        c = s["contact"]
        b, p0 = c["hertz_half_width"], c["hertz_peak_pressure"]
        cols = read_columns(pressure)
        closed = closed or cols
        if ref is None and c.get("reference"):
            rpath = os.path.join(os.path.dirname(run["case_path"]), c["reference"])
            if os.path.isfile(rpath):
                rc = read_columns(rpath)
                ref = (rc["x"], rc.get("pressure_from_stress", rc.get("pressure")))
        xb = [x / b for x in cols["x"]]
        pb = [p / p0 for p in cols["pressure_from_stress"]]
        curves.append((run["label"], xb, pb, colours(i)))
    if closed is None:
        plt.close(fig)
        return False
    xb = [x / b for x in closed["x"]]
    lines = [("Hertz", xb, [p / p0 for p in closed["hertz"]], dict(color="k", ls="--", lw=1.2)),
             ("Shtayerman", xb, [p / p0 for p in closed["shtayerman"]],
              dict(color="k", ls=":", lw=1.6))]
    if ref is not None and ref[1] is not None:
        lines.append(("reference (overkill)", [x / b for x in ref[0]], [p / p0 for p in ref[1]],
                      dict(color="0.45", ls="-", lw=2.4, alpha=0.6)))
    lines += [(label, x, p, dict(color=col, lw=1.1)) for label, x, p, col in curves]
    lo, hi = math.inf, -math.inf
    for label, x, p, style in lines:
        ax.plot(x, p, label=label, **style)
        az.plot(x, p, **style)
        inside = [v for u, v in zip(x, p) if 0.85 <= u <= 1.1]
        if inside:
            lo, hi = min(lo, min(inside)), max(hi, max(inside))
    ax.set_xlim(0, 1.5)
    ax.set_ylim(-0.15, 1.2)
    az.set_xlim(0.85, 1.1)
    if lo < hi:
        pad = 0.05 * (hi - lo)
        az.set_ylim(max(lo - pad, -0.6), min(hi + pad, 1.2))
    ax.axvspan(0.85, 1.1, color="0.9", zorder=0)
    for a, title in ((ax, study.get("title") or study["study"]),
                     (az, "end of the contact zone")):
        a.set_xlabel("x / b (Hertz)")
        a.set_ylabel("p / p0 (Hertz)")
        a.axhline(0, color="0.6", lw=0.6)
        a.grid(alpha=0.3)
        a.set_title(title, fontsize=10)
    ax.legend(loc="lower left", fontsize=7.5, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def slug(text):
    return re.sub(r"[^A-Za-z0-9.+-]+", "-", text).strip("-") or "run"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    ap.add_argument("study", help="study file (YAML; see examples/hertz/table-5-1.yaml)")
    ap.add_argument("--hpcontact", default=os.path.join(ROOT, "build", "hpcontact"),
                    help="the hpcontact executable (default: build/hpcontact)")
    ap.add_argument("--out", required=True, help="output folder")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    ap.add_argument("--vtu", action="store_true", help="keep each run's .vtu output")
    args = ap.parse_args(argv)
    try:
        study = load_study(args.study)
    except (OSError, StudyError) as e:
        print(f"study_table: {e}", file=sys.stderr)
        return 2
    if not os.path.isfile(args.hpcontact) or not os.access(args.hpcontact, os.X_OK):
        print(f"study_table: hpcontact executable not found at {args.hpcontact}", file=sys.stderr)
        return 2
    runs = study["runs"]
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    results = []
    for i, run in enumerate(runs):
        name = f"{i + 1:02d}-{slug(os.path.splitext(os.path.basename(run['case']))[0])}"
        results.append({"run_dir": os.path.join("runs", name),
                        "run_dir_abs": os.path.join(args.out, "runs", name)})
    n, done, lock = len(runs), [0], threading.Lock()
    print(f"study {study['study']}: {n} run(s), {args.jobs} at a time, {args.hpcontact}",
          flush=True)

    def work(i):
        summary, error = run_one(args.hpcontact, runs[i], results[i]["run_dir_abs"], args.vtu)
        results[i].update(summary=summary, error=error)
        with lock:
            done[0] += 1
            head = f"[{done[0]}/{n}] {runs[i]['label']}"
            if error:
                print(f"{head}: FAILED ({runs[i]['case']}, {results[i]['run_dir_abs']}): "
                      f"{error}", flush=True)
            else:
                c = summary.get("contact", {})
                extra = "".join(f", {name} {c[k]:.4g} %" for name, k in
                                (("e_seed vs Shtayerman", "e_seed_shtayerman_percent"),
                                 ("e_L2 vs reference", "e_L2_reference_percent")) if k in c)
                conv = "" if summary.get("converged", True) else ", NOT converged"
                print(f"{head}: {summary.get('dofs')} DOF, {summary.get('wall_time_s', 0):.2f} s"
                      f"{extra}{conv}", flush=True)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        list(pool.map(work, range(n)))

    with open(os.path.join(args.out, "table.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_COLUMNS)
        w.writeheader()
        for run, res in zip(runs, results):
            w.writerow(csv_row(run, res))
    write_markdown(os.path.join(args.out, "table.md"), study, runs, results, args.jobs)
    plotted = write_plot(os.path.join(args.out, "pressure.png"), study, runs, results)
    print(f"wrote {os.path.join(args.out, 'table.csv')}, table.md"
          + (", pressure.png" if plotted else " (no pressure curves to plot)"), flush=True)
    failed = [r["label"] for r, res in zip(runs, results) if res.get("error")]
    if failed:
        print(f"study_table: {len(failed)} run(s) failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
