#!/usr/bin/python3
"""Runs a study with `hpcontact study` and tabulates it like the seed's Table 5.1 (Hertz rows).

usage: study_table.py STUDY.yaml --out DIR [--hpcontact PATH] [--jobs N]

STUDY.yaml is a study file as `hpcontact study` reads it (docs/study.md: rows, sweeps, zip,
seed values); this script runs `hpcontact study STUDY.yaml --out DIR --jobs N` (its progress
lines printed as they come) and, from DIR/study.json, writes

  DIR/study.csv, DIR/study.json, DIR/runs/NN-label/   as `hpcontact study` writes them
  DIR/table.md     the rows as a Markdown table: DOF, wall time, the pressure errors of
                   summary.json contact (e_seed, e_L2 against Hertz, Shtayerman, the reference
                   curve; the penalty traction's), the half width, and a row's seed values
                   (seed: {dofs, time_s, vs_hertz, vs_shtayerman}) beside them
  DIR/pressure.png p/p0 over x/b (b, p0: Hertz) of every row's pressure_from_stress against
                   Hertz, Shtayerman and the reference curve, full range [0, 1.5] and zoomed on
                   the end of the contact zone x/b in [0.85, 1.1] (seed Fig. 5.11-5.14); rows
                   without a contact[].compare section are left out of the plot

Exit status: 0 all rows converged; 1 a row failed (it is named, left empty in the table and the
plot, and the rest is written) or the study file is wrong (hpcontact's message names the file,
line and key); 2 a wrong command line or no hpcontact program.
"""
import json
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import default_hpcontact, read_columns, script_parser, unit_text, units_of  # noqa: E402

CONTACT_KEYS = ["e_seed_hertz_percent", "e_seed_shtayerman_percent", "e_seed_reference_percent",
                "e_L2_hertz_percent", "e_L2_shtayerman_percent", "e_L2_reference_percent",
                "half_width"]
# The same measures of the pressure the method carries (summary.json contact.multiplier for exact
# contact, contact.penalty_traction with enforcement: penalty).
PENALTY_KEYS = ["e_seed_hertz_percent", "e_seed_shtayerman_percent", "e_L2_reference_percent"]
SEED_KEYS = ["dofs", "time_s", "vs_hertz", "vs_shtayerman"]


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


def write_markdown(path, study, rows, jobs):
    """table.md: one line per row of study.json, the seed's columns where any row has them."""
    seed_keys = [k for k in SEED_KEYS if any(k in r.get("seed", {}) for r in rows)]
    first = next((r["summary"] for r in rows if r.get("summary")), None)
    length = unit_text("length", units_of(first))
    head = ["discretisation", "DOF", "time [s]", "e_seed vs Hertz [%]",
            "e_seed vs Shtayerman [%]", "e_seed vs reference [%]", "e_L2 vs Hertz [%]",
            "e_L2 vs Shtayerman [%]", "e_L2 vs reference [%]", f"half width {length}",
            "method's pressure: e_seed vs Hertz [%]", "method's pressure: e_seed vs Shtayerman [%]",
            "method's pressure: e_L2 vs reference [%]"]
    head += [{"dofs": "seed DOF", "time_s": "seed time [s]", "vs_hertz": "seed vs Hertz [%]",
              "vs_shtayerman": "seed vs Shtayerman [%]"}[k] for k in seed_keys]
    lines = []
    if study.get("title"):
        lines += [f"**{study['title']}**", ""]
    lines += ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for row in rows:
        s, seed = row.get("summary"), row.get("seed", {})
        if not row.get("converged") or s is None:
            cells = [row["label"], "failed"] + ["-"] * 11
        else:
            c = s.get("contact", {})
            cells = [row["label"], fmt(s.get("dofs"), 0), fmt_time(s.get("wall_time_s"))]
            cells += [fmt(c.get(k), 4) for k in CONTACT_KEYS[:3]]
            cells += [fmt(c.get(k), 2) for k in CONTACT_KEYS[3:6]]
            cells += [fmt(c.get("half_width"), 4)]
            pen = c.get("penalty_traction") or c.get("multiplier") or {}
            cells += [fmt(pen.get(k), 4) for k in PENALTY_KEYS[:2]] + [fmt(pen.get(PENALTY_KEYS[2]), 2)]
        cells += [fmt(seed.get(k), 0 if k in ("dofs", "time_s") else 4) for k in seed_keys]
        lines.append("| " + " | ".join(cells) + " |")
    lines.append("")
    legend = ("e_seed: the squared measure that reads like the seed's Table 5.1 (the dissertation "
              "of docs/references.md), e_L2: relative L2 error of the pressure from stresses over "
              "[0, 1.5 b] (docs/theory.md §10); reference: the curve compare.reference names "
              "(for Hertz our overkill solution, examples/hertz/reference.yaml). method's pressure: "
              "the same measures of the multiplier (exact contact) or of the penalty traction "
              "(enforcement: penalty) instead of the pressure from stresses.")
    if first is not None:
        c = first.get("contact", {})
        if "hertz_half_width" in c:
            legend += (f" Hertz b = {c['hertz_half_width']:.4f} {length}, p0 = "
                       f"{c['hertz_peak_pressure']:.1f} {unit_text('pressure', units_of(first))}; "
                       f"Shtayerman b = {c.get('shtayerman_half_width', float('nan')):.4f}.")
    legend += (f" Our times: whole run (wall clock, summary.json), {jobs} run(s) at a time on "
               f"{os.cpu_count()} cores")
    legend += "; the seed's: a 2.4 GHz Core 2." if "time_s" in seed_keys else "."
    lines += [legend, ""]
    with open(path, "w") as f:
        f.write("\n".join(lines))


def write_plot(path, study, rows):
    """pressure.png; False if no row has a pressure comparison to plot."""
    fig, (ax, az) = plt.subplots(1, 2, figsize=(13, 5.2), gridspec_kw={"width_ratios": [1.6, 1]})
    closed, b, p0, ref = None, None, None, None
    colours = plt.get_cmap("tab10" if len(rows) <= 10 else "tab20")
    curves = []
    for i, row in enumerate(rows):
        s = row.get("summary")
        pressure = os.path.join(row["run_dir"], "pressure.csv")
        if s is None or "hertz_half_width" not in s.get("contact", {}) or \
                not os.path.isfile(pressure):
            continue
        c = s["contact"]
        b, p0 = c["hertz_half_width"], c["hertz_peak_pressure"]
        cols = read_columns(pressure)
        closed = closed or cols
        if ref is None and c.get("reference"):
            rpath = os.path.join(os.path.dirname(row["case"]), c["reference"])
            if os.path.isfile(rpath):
                rc = read_columns(rpath)
                ref = (rc["x"], rc.get("pressure_from_stress", rc.get("pressure")))
        xb = [x / b for x in cols["x"]]
        pb = [p / p0 for p in cols["pressure_from_stress"]]
        curves.append((row["label"], xb, pb, colours(i)))
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
    low, high = -0.15, 1.2
    lo, hi, clipped = math.inf, -math.inf, False
    for label, x, p, style in lines:
        shown = [v for u, v in zip(x, p) if 0 <= u <= 1.5]
        clipped = clipped or any(v < low or v > high for v in shown)
        ax.plot(x, p, label=label, **style)
        az.plot(x, p, **style)
        inside = [v for u, v in zip(x, p) if 0.85 <= u <= 1.1]
        if inside:
            lo, hi = min(lo, min(inside)), max(hi, max(inside))
    if clipped:  # say so where the curves are named
        ax.plot([], [], " ", label=f"curves clipped to {low} ≤ p/p0 ≤ {high}")
    ax.set_xlim(0, 1.5)
    ax.set_ylim(low, high)
    az.set_xlim(0.85, 1.1)
    if lo < hi:
        pad = 0.05 * (hi - lo)
        az.set_ylim(max(lo - pad, -0.6), min(hi + pad, high))
    ax.axvspan(0.85, 1.1, color="0.9", zorder=0)
    for a, title in ((ax, study.get("title") or study["study"]),
                     (az, "end of the contact zone")):
        a.set_xlabel("x / b (b: Hertz half width) [-]")
        a.set_ylabel("p / p0 (p0: Hertz peak pressure) [-]")
        a.axhline(0, color="0.6", lw=0.6)
        a.grid(alpha=0.3)
        a.set_title(title, fontsize=10)
    ax.legend(loc="lower left", fontsize=7.5, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return True


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("study", help="study file (YAML; docs/study.md, e.g. examples/hertz/table-5-1.yaml)")
    ap.add_argument("--out", required=True, help="output folder (created; earlier study.csv, "
                    "study.json, table.md, pressure.png replaced)")
    ap.add_argument("--hpcontact", default=default_hpcontact(),
                    help="the hpcontact program (default: build/hpcontact of this repository, "
                    "<prefix>/bin/hpcontact of an installed script, else hpcontact on PATH; now "
                    "%(default)s)")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    args = ap.parse_args(argv)
    if not os.path.isfile(args.hpcontact) or not os.access(args.hpcontact, os.X_OK):
        print(f"study_table: hpcontact program not found at {args.hpcontact} (--hpcontact)",
              file=sys.stderr)
        return 2
    out = args.out
    for name in ("table.md", "pressure.png"):
        if os.path.exists(os.path.join(out, name)):
            os.remove(os.path.join(out, name))
    code = subprocess.run([args.hpcontact, "study", args.study, "--out", out,
                           "--jobs", str(max(1, args.jobs))]).returncode
    summary = os.path.join(out, "study.json")
    if code not in (0, 1) or not os.path.isfile(summary):
        return code if code else 1
    with open(summary) as f:
        study = json.load(f)
    rows = study["runs"]
    write_markdown(os.path.join(out, "table.md"), study, rows, args.jobs)
    plotted = write_plot(os.path.join(out, "pressure.png"), study, rows)
    print(f"wrote {os.path.join(out, 'table.md')}"
          + (", pressure.png" if plotted else " (no pressure comparison to plot)"), flush=True)
    failed = [r["label"] for r in rows if not r.get("converged")]
    if failed:
        print(f"study_table: {len(failed)} run(s) failed: {', '.join(failed)}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
