#!/usr/bin/python3
"""Neumann load shapes and the regularity of the solution (seed §4.5 and §5.2.4.3.1): p-sweeps
of the examples in examples/neumann, relative energy-norm errors and their algebraic rates β.

Studies (--study, default all three):
  block           block 2 x 2 mm, two elements, rectangular and triangular load (seed Fig. 4.5,
                  4.6); --all-shapes adds the other three shapes
  plate-hole      plate with a hole, eight elements, the five load shapes (seed Fig. 4.8-4.10)
  quarter-circle  the Hertz quarter circle with a triangular load instead of contact, on the
                  four-element Hertz mesh and on a 36-element mesh (seed Fig. 5.29, 5.30)

Each study runs `hpcontact run CASE --set discretization.degree=p --set
bodies[0].loads[0].shape=SHAPE` (--jobs at a time, default 2) and writes into OUT/<study>/

  convergence.csv  one row per run: study, method, mesh, shape, p, dofs, strain_energy,
                   energy_rel_percent (seed eq. 4.3 against the study's reference energy),
                   e_L2_hertz_percent (empty: no contact), wall_time_s, reference,
                   reference_energy, energy_rel_percent_extrapolated and extrapolated_energy
                   (against U_ex of eq. 4.14, for a second opinion on the reference)
  beta.csv         per mesh and shape: the fitted rate β (error ∝ N^-β, least squares over the
                   fit range of p) against either reference, and the errors at p = 8
  convergence.png  relative error in energy norm against DOF, log-log, one curve per shape
                   (solid: against the study's reference; dotted: against U_ex of eq. 4.14),
                   the fitted β in the legend

References, as in the seed: the block against the same block on a uniformly refined mesh
(each element split 10 x 10: 200 elements) at p = 10, the plate with a hole against p = 20 on
the same mesh, the quarter circle against U_ex extrapolated by eq. 4.14 from its three
highest degrees (18, 19, 20); degrees 2-15 are plotted for block and plate. The eq. 4.14
column of block and plate uses p = 16, 18, 20: where a load's break point lies inside an element
edge (bspline2's joint at t = 1/3) the energy increments are uneven, large and small roughly
alternating, and steps of two even them out somewhat; for bspline2 the column is still only a
rough second opinion (examples/neumann/README.md).

The load shapes are those of docs/input.md; bspline2 is the seed's eq. 4.9. hpcontact splits a
loaded edge at the load's break points (the ends of its interval, bspline2's joint), so the
load vector is integrated exactly at every p.

    scripts/neumann_study.py --hpcontact build/hpcontact   # all three, about 15 s on 2 cores
    scripts/neumann_study.py --study plate-hole --quick    # a small sweep, a few seconds
    scripts/neumann_study.py --write-fine-mesh examples/neumann/quarter-circle-36.yaml
"""
import argparse
import concurrent.futures
import csv
import math
import pathlib
import sys
import tempfile
import time

import matplotlib
import yaml

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SCRIPTS = pathlib.Path(__file__).resolve().parent
ROOT = SCRIPTS.parent
sys.path.insert(0, str(SCRIPTS))
from energy_extrapolation import (ExtrapolationError, extrapolate_energy, fit_beta,  # noqa: E402
                                  relative_energy_error)
from hpc_run import default_hpcontact, run_case  # noqa: E402

SHAPES = ["constant", "linear", "bspline1", "bspline2", "hermite"]
SHAPE_NAMES = {"constant": "rectangular", "linear": "triangular",
               "bspline1": "B-spline one-sided", "bspline2": "B-spline two-sided",
               "hermite": "Hermite"}
CSV_COLUMNS = ["study", "method", "mesh", "shape", "p", "dofs", "strain_energy",
               "energy_rel_percent", "e_L2_hertz_percent", "wall_time_s", "reference",
               "reference_energy", "energy_rel_percent_extrapolated", "extrapolated_energy"]
BETA_COLUMNS = ["study", "mesh", "shape", "fit_p_min", "fit_p_max", "beta", "beta_extrapolated",
                "error_p8_percent", "error_p8_extrapolated_percent", "reference",
                "reference_energy", "extrapolated_energy"]


def study_config(name, quick=False, all_shapes=False):
    """The sweep of one study: meshes (label, problem file), shapes, degrees of the sweep, the
    reference ("degree", p) or ("extrapolate", (p0, p1, p2)), the degrees of the eq. 4.14
    column, and the range of p of the β fit."""
    examples = ROOT / "examples" / "neumann"
    if name in ("block", "plate-hole"):
        cfg = {"meshes": [(name, examples / f"{name}.yaml")],
               "shapes": SHAPES if name == "plate-hole" or all_shapes else ["constant", "linear"],
               "degrees": list(range(2, 16)), "reference": ("degree", 20),
               "extrapolate": (16, 18, 20), "fit": (8, 15)}
        if quick:
            cfg.update(degrees=list(range(2, 11)), reference=("degree", 14),
                       extrapolate=(10, 12, 14), fit=(6, 10))
        if name == "block":   # the seed's reference: refinement factor 10, 200 elements, p = 10
            cfg["reference"] = ("refined", 10, 10)
        return cfg
    if name == "quarter-circle":
        cfg = {"meshes": [("quarter-circle", examples / "quarter-circle.yaml"),
                          ("quarter-circle-36", examples / "quarter-circle-36.yaml")],
               "shapes": ["linear"], "degrees": list(range(2, 21)),
               "reference": ("extrapolate", (18, 19, 20)), "extrapolate": (18, 19, 20),
               "fit": (8, 17)}
        if quick:
            cfg.update(meshes=cfg["meshes"][:1], degrees=list(range(2, 15)),
                       reference=("extrapolate", (12, 13, 14)), extrapolate=(12, 13, 14),
                       fit=(6, 11))
        return cfg
    raise ValueError(f"unknown study {name!r}")


def run_one(hpcontact, case, degree, shape, out, sets=()):
    """One run (sets: further `--set` overrides); returns its summary.json. Raises RuntimeError
    naming the run if it fails."""
    summary, msg = run_case(hpcontact, case, out, [f"discretization.degree={degree}",
                                                   f"bodies[0].loads[0].shape={shape}", *sets])
    if summary is None:
        raise RuntimeError(f"{case} p = {degree} {shape}: {msg}")
    if not summary.get("converged"):
        raise RuntimeError(f"{case} p = {degree} {shape}: did not converge")
    return summary


def run_study(name, cfg, hpcontact, jobs=2, workdir=None):
    """Runs every (mesh, shape, p) of the study, jobs at a time, in workdir (default: a
    temporary folder, removed afterwards). Returns (rows, fits): rows for
    convergence.csv and fits for beta.csv, as lists of dicts keyed by the CSV columns, plus
    the raw curves under fits[i]["curve"] (p, dofs, error, error_extrapolated)."""
    kind, *ref = cfg["reference"]
    needed = set(cfg["degrees"]) | set(cfg["extrapolate"])
    if kind == "degree":
        needed.add(ref[0])
    elif kind == "extrapolate":
        needed |= set(ref[0])
    tasks = [(mesh, case, shape, p) for mesh, case in cfg["meshes"] for shape in cfg["shapes"]
             for p in sorted(needed)]
    own_tmp = None
    if workdir is None:
        own_tmp = tempfile.TemporaryDirectory()
        workdir = own_tmp.name
    workdir = pathlib.Path(workdir)
    if kind == "refined":   # the reference runs: each mesh refined uniformly, at degree ref[1]
        for mesh, case in cfg["meshes"]:
            refined_case = workdir / f"{mesh}-refined-{ref[0]}.yaml"
            refined_case.write_text(refine_uniformly(case, ref[0]))
            tasks += [(mesh + "@refined", refined_case, shape, ref[1]) for shape in cfg["shapes"]]
    results = {}
    try:
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
            futures = {pool.submit(run_one, hpcontact, case, p, shape,
                                   workdir / f"{mesh}-{shape}-p{p}"): (mesh, shape, p)
                       for mesh, case, shape, p in tasks}
            for f in concurrent.futures.as_completed(futures):
                results[futures[f]] = f.result()
    finally:
        if own_tmp is not None:
            own_tmp.cleanup()

    rows, fits = [], []
    for mesh, _ in cfg["meshes"]:
        for shape in cfg["shapes"]:
            runs = {p: results[(mesh, shape, p)] for p in sorted(needed)}
            dofs = {p: s["dofs"] for p, s in runs.items()}
            energy = {p: s["strain_energy"] for p, s in runs.items()}
            ex = cfg["extrapolate"]
            try:
                u_ext = extrapolate_energy([dofs[p] for p in ex], [energy[p] for p in ex])
            except ExtrapolationError as e:
                if kind == "extrapolate":
                    raise RuntimeError(f"{name} {mesh} {shape}: {e}") from e
                print(f"warning: {name} {mesh} {shape}: no eq. 4.14 column: {e}", file=sys.stderr)
                u_ext = None
            err_ext = lambda u: relative_energy_error(u, u_ext) if u_ext else math.nan  # noqa: E731
            if kind == "degree":
                u_ref, ref_text = energy[ref[0]], f"p={ref[0]} same mesh"
            elif kind == "refined":
                r = results[(mesh + "@refined", shape, ref[1])]
                u_ref = r["strain_energy"]
                ref_text = (f"mesh refined {ref[0]}x{ref[0]} per element ({r['dofs']} DOF) "
                            f"p={ref[1]}")
            else:
                u_ref = extrapolate_energy([dofs[p] for p in ref[0]], [energy[p] for p in ref[0]])
                ref_text = "eq. 4.14 from p=" + ",".join(str(p) for p in ref[0])
            for p, s in runs.items():
                rows.append({"study": name, "method": s["method"], "mesh": mesh, "shape": shape,
                             "p": p, "dofs": s["dofs"], "strain_energy": repr(s["strain_energy"]),
                             "energy_rel_percent": relative_energy_error(s["strain_energy"], u_ref),
                             "e_L2_hertz_percent": "", "wall_time_s": s["wall_time_s"],
                             "reference": ref_text, "reference_energy": repr(u_ref),
                             "energy_rel_percent_extrapolated": err_ext(s["strain_energy"]),
                             "extrapolated_energy": repr(u_ext) if u_ext else ""})
            curve = [(p, dofs[p], relative_energy_error(energy[p], u_ref), err_ext(energy[p]))
                     for p in cfg["degrees"]]
            lo, hi = cfg["fit"]
            sel = [c for c in curve if lo <= c[0] <= hi and c[2] > 0]
            sel_ext = [c for c in curve if lo <= c[0] <= hi and c[3] > 0]
            at8 = {c[0]: c for c in curve}.get(8)
            fits.append({"study": name, "mesh": mesh, "shape": shape, "fit_p_min": lo,
                         "fit_p_max": hi,
                         "beta": fit_beta([c[1] for c in sel], [c[2] for c in sel]),
                         "beta_extrapolated": fit_beta([c[1] for c in sel_ext],
                                                       [c[3] for c in sel_ext])
                         if len(sel_ext) >= 2 else math.nan,
                         "error_p8_percent": at8[2] if at8 else "",
                         "error_p8_extrapolated_percent": at8[3] if at8 else "",
                         "reference": ref_text, "reference_energy": repr(u_ref),
                         "extrapolated_energy": repr(u_ext) if u_ext else "", "curve": curve,
                         "reference_kind": kind})
    for mesh, _ in cfg["meshes"]:   # the refined reference runs as rows of their own
        for shape in cfg["shapes"]:
            r = results.get((mesh + "@refined", shape, ref[1])) if kind == "refined" else None
            if r is not None:
                rows.append({"study": name, "method": r["method"],
                             "mesh": f"{mesh}-refined-{ref[0]}", "shape": shape,
                             "p": ref[1], "dofs": r["dofs"],
                             "strain_energy": repr(r["strain_energy"]), "energy_rel_percent": 0.0,
                             "e_L2_hertz_percent": "", "wall_time_s": r["wall_time_s"],
                             "reference": "(the reference run)",
                             "reference_energy": repr(r["strain_energy"]),
                             "energy_rel_percent_extrapolated": "", "extrapolated_energy": ""})
    rows.sort(key=lambda r: (r["mesh"], SHAPES.index(r["shape"]), r["p"]))
    return rows, fits


def write_outputs(name, cfg, rows, fits, out):
    out.mkdir(parents=True, exist_ok=True)

    def fmt(v):
        if isinstance(v, float):
            return "" if math.isnan(v) else f"{v:.6e}"
        return v

    with open(out / "convergence.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow({k: (fmt(v) if k not in ("wall_time_s",) else v) for k, v in r.items()})
    fmt4 = lambda v: "" if math.isnan(v) else f"{v:.4f}"  # noqa: E731
    with open(out / "beta.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=BETA_COLUMNS)
        w.writeheader()
        for r in fits:
            w.writerow({k: fmt(r[k]) if k.startswith("error") else
                        (fmt4(r[k]) if k.startswith("beta") else r[k]) for k in BETA_COLUMNS})

    fig, ax = plt.subplots(figsize=(7, 5))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    markers = "osD^v<>"
    for i, fit in enumerate(fits):
        c = colors[i % len(colors)]
        shown = [(n, e) for _, n, e, _ in fit["curve"] if e > 0]
        label = SHAPE_NAMES[fit["shape"]] if len(cfg["meshes"]) == 1 else \
            f"{SHAPE_NAMES[fit['shape']]}, {fit['mesh']}"
        ax.loglog(*zip(*shown), marker=markers[i % len(markers)], color=c, ms=4,
                  label=f"{label}: β = {fit['beta']:.2f}" + (
                      f" ({fit['beta_extrapolated']:.2f} vs U_ex)"
                      if fit["reference_kind"] != "extrapolate"
                      and not math.isnan(fit["beta_extrapolated"]) else ""))
        if fit["reference_kind"] != "extrapolate" and fit["extrapolated_energy"]:
            ax.loglog([n for _, n, _, _ in fit["curve"]], [e for *_, e in fit["curve"]], ":",
                      color=c, lw=1)
    lo, hi = cfg["fit"]
    kind, *ref = cfg["reference"]
    dotted = "\n(dotted: against U_ex of eq. 4.14 from p = " + \
        ", ".join(map(str, cfg["extrapolate"])) + ")"
    if kind == "degree":
        ref_text = f"p = {ref[0]} on the same mesh" + dotted
    elif kind == "refined":
        ref_text = f"mesh refined {ref[0]} x {ref[0]} per element, p = {ref[1]}" + dotted
    else:
        ref_text = "U_ex of eq. 4.14 from p = " + ", ".join(map(str, ref[0]))
    ax.set_title(f"{name}: reference {ref_text}; β: least squares over p = {lo}-{hi}",
                 fontsize=9)
    ax.set_xlabel("degrees of freedom")
    ax.set_ylabel("relative error in energy norm [%]")
    ax.grid(which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "convergence.png", dpi=120)
    plt.close(fig)


def print_summary(name, cfg, fits, seconds):
    print(f"{name}: {len(fits)} curve(s), {seconds:.1f} s")
    print(f"  {'mesh':<18} {'shape':<10} {'beta':>6} {'beta(ex)':>8} {'e(p=8) %':>10} "
          f"{'e(p=8) ex %':>11}  reference")
    for f in fits:
        e8 = f"{f['error_p8_percent']:.4g}" if f["error_p8_percent"] != "" else "-"
        e8x = f"{f['error_p8_extrapolated_percent']:.4g}" if f["error_p8_percent"] != "" else "-"
        print(f"  {f['mesh']:<18} {f['shape']:<10} {f['beta']:>6.3f} "
              f"{f['beta_extrapolated']:>8.3f} {e8:>10} {e8x:>11}  {f['reference']} "
              f"U = {float(f['reference_energy']):.12g}")


def refine_uniformly(case, n):
    """The problem file `case` (straight-edged quadrilaterals only) as YAML text with every
    element split into n x n by its bilinear map; edge sets follow their edges, everything else
    (material, constraints, loads, discretisation) is kept. Node ids are renumbered."""
    spec = yaml.safe_load(pathlib.Path(case).read_text())
    body = spec["bodies"][0]
    if body.get("curves") or len(spec["bodies"]) != 1:
        raise ValueError(f"{case}: refine_uniformly handles one body with straight edges only")
    xy = {int(k): v for k, v in body["nodes"].items()}
    ids = {}

    def node(p):
        key = (round(p[0], 12), round(p[1], 12))
        if key not in ids:
            ids[key] = len(ids) + 1
        return ids[key]

    def point(corners, s, t):   # bilinear map of the reference square [0, 1]²
        (x1, y1), (x2, y2), (x3, y3), (x4, y4) = corners
        w = ((1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t)
        return (w[0] * x1 + w[1] * x2 + w[2] * x3 + w[3] * x4,
                w[0] * y1 + w[1] * y2 + w[2] * y3 + w[3] * y4)

    elements = {}
    for quad in body["elements"].values():
        corners = [xy[v] for v in quad]
        for j in range(n):
            for i in range(n):
                elements[len(elements) + 1] = [
                    node(point(corners, (i + di) / n, (j + dj) / n))
                    for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
    edge_sets = {}
    for name, edges in (body.get("edge_sets") or {}).items():
        edge_sets[name] = []
        for a, b in edges:
            (xa, ya), (xb, yb) = xy[a], xy[b]
            pts = [node((xa + (xb - xa) * k / n, ya + (yb - ya) * k / n)) for k in range(n + 1)]
            edge_sets[name] += [[pts[k], pts[k + 1]] for k in range(n)]
    body["nodes"] = {i: [x, y] for (x, y), i in ids.items()}
    body["elements"] = elements
    body["edge_sets"] = edge_sets
    spec["case"] = f"{spec['case']}-refined-{n}"
    return f"# {case} with every element split {n} x {n} (scripts/neumann_study.py)\n" + \
        yaml.safe_dump(spec, sort_keys=False, default_flow_style=None)


def write_fine_mesh(path, cells=(6, 6), fine=0.5):
    """The quarter circle on a cells[0] x cells[1] grid refined towards the load (hertz_mesh.py's
    'refined' preset with its zone ending at x = 2.48, where the load ends, on a node)."""
    import hertz_mesh
    zone = 2.48
    bottom, left, right_t, comment = hertz_mesh.refined(cells[0], cells[1], zone, fine)
    nodes, quads, bot, right, sym, top = hertz_mesh.build(bottom, left, len(left) - 1, right_t)
    arc = [e for e, x in zip(bot, bottom) if x < zone - 1e-9]
    es = lambda edges: ", ".join(f"[{a}, {b}]" for a, b in edges)  # noqa: E731
    lines = [
        "# Quarter circle with a triangular load instead of contact (seed §5.2.4.3.1, docs/cases.md",
        f"# §4), the {len(quads)}-element mesh: as quarter-circle.yaml (same geometry, material,",
        "# supports and load: vertical triangular traction on the arc x in [0, 2.48], resultant",
        "# 35000 N), on a finer mesh in place of the seed's 147-element one (its figure is lost).",
        *[f"# {c.replace('contact zone', 'loaded zone')}" for c in comment],
        f"# Generated by scripts/neumann_study.py --write-fine-mesh {path}",
        "case: neumann-quarter-circle-36" if len(quads) == 36 else
        f"case: neumann-quarter-circle-{len(quads)}",
        "description: >",
        f"  Quarter circle R = 10 mm, {len(quads)} p-elements, triangular vertical traction on the",
        "  arc x in [0, 2.48] with resultant 35000 N; ux = 0 on x = 0, uy = 0 on y = 10.",
        "", "bodies:", "  - name: cylinder",
        "    material: {E: 210000, nu: 0.3, plane: strain}", "    nodes:"]
    lines += hertz_mesh.mesh_lines(nodes, quads, bot + right)
    lines += ["    edge_sets:", f"      symmetry: [{es(sym)}]", f"      centre: [{es(top)}]",
              f"      arc: [{es(arc)}]",
              "    constraints:", "      - {edges: [symmetry], ux: 0}",
              "      - {edges: [centre], uy: 0}",
              "    loads:",
              "      - {edges: [arc], traction: [0, 1], resultant: 35000, shape: linear, along: x, "
              "interval: [0, 2.48]}",
              "", "discretization:", "  method: p", "  degree: 8", "  condense: true",
              "", "output:", "  vtu: false"]
    pathlib.Path(path).write_text("\n".join(lines) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--hpcontact", default=default_hpcontact(),
                    help="the hpcontact program (default %(default)s)")
    ap.add_argument("--study", action="append", choices=["block", "plate-hole", "quarter-circle"],
                    help="study to run (repeatable; default all three)")
    ap.add_argument("--quick", action="store_true",
                    help="small sweeps: p up to 10 against p = 14 (block, plate), the four-element "
                         "quarter circle up to p = 14")
    ap.add_argument("--all-shapes", action="store_true",
                    help="block: run all five shapes, not only rectangular and triangular")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (default 2)")
    ap.add_argument("--out", default=str(ROOT / "results" / "neumann"),
                    help="output folder, one subfolder per study (default %(default)s)")
    ap.add_argument("--write-fine-mesh", metavar="PATH",
                    help="write the 36-element quarter-circle problem file to PATH and exit")
    args = ap.parse_args()
    if args.write_fine_mesh:
        write_fine_mesh(args.write_fine_mesh)
        print(f"wrote {args.write_fine_mesh}")
        return
    if not pathlib.Path(args.hpcontact).exists():
        sys.exit(f"hpcontact executable not found at {args.hpcontact} (give --hpcontact)")
    for name in args.study or ["block", "plate-hole", "quarter-circle"]:
        cfg = study_config(name, args.quick, args.all_shapes)
        start = time.time()
        try:
            rows, fits = run_study(name, cfg, args.hpcontact, args.jobs)
        except RuntimeError as e:
            sys.exit(f"{name}: {e}")
        out = pathlib.Path(args.out) / name
        write_outputs(name, cfg, rows, fits, out)
        print_summary(name, cfg, fits, time.time() - start)
        print(f"  wrote {out / 'convergence.csv'}, {out / 'beta.csv'}, {out / 'convergence.png'}")


if __name__ == "__main__":
    main()
