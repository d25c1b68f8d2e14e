"""Writes BENCHMARKS.md from hpc_bench's JSON results (bench/run.sh calls it; standard library only);
with --only, rewrites some sections of it from a run of their benchmarks alone."""

import datetime
import json
import math
import os
import re
import subprocess
import sys
import textwrap

UNIT_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def load(path):
    """Returns (context, {run name: {aggregate or "single": entry}}); times are converted to seconds."""
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    runs = {}
    for b in data["benchmarks"]:
        name = b["run_name"].removesuffix("/real_time").removesuffix("/process_time")
        name = re.sub(r"/(iterations|repeats):\d+", "", name)  # a benchmark's own counts
        kind = b.get("aggregate_name", "single") if b.get("run_type") == "aggregate" else "single"
        if b.get("aggregate_unit", "time") == "time":
            scale = UNIT_SECONDS[b["time_unit"]]
            b = dict(b, real_time=b["real_time"] * scale, cpu_time=b["cpu_time"] * scale)
        runs.setdefault(name, {})[kind] = b
    return data["context"], runs


def central(runs, name):
    """The median over repetitions (or the single run), or None if the benchmark was not run."""
    r = runs.get(name)
    if not r:
        return None
    return r.get("median") or r.get("single") or r.get("mean")


def repetitions(runs):
    return max((e.get("repetitions", 1) for r in runs.values() for e in r.values()), default=1)


def spread(runs, name, key="real_time"):
    """Coefficient of variation over repetitions as text, '' without repetitions."""
    cv = runs.get(name, {}).get("cv")
    return f"{100 * cv[key]:.0f} %" if cv else ""


def fmt_time(seconds):
    if seconds is None:
        return "—"
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6), ("ns", 1e-9)):
        if seconds >= scale or unit == "ns":
            value = seconds / scale
            digits = 0 if value >= 100 else 1 if value >= 10 else 2
            return f"{value:.{digits}f} {unit}"


def fmt_ratio(a, b):
    return f"{a / b:.1f}×" if a and b else "—"


def cpu_model():
    try:
        with open("/proc/cpuinfo", encoding="utf-8") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU"


def blas_library():
    """The BLAS that libblas.so.3 resolves to (CHOLMOD's factorisation speed depends on it)."""
    for path in ("/usr/lib/x86_64-linux-gnu/libblas.so.3", "/usr/lib/aarch64-linux-gnu/libblas.so.3"):
        if os.path.exists(path):
            real = os.path.realpath(path)
            kind = "OpenBLAS" if "openblas" in real else "BLIS" if "blis" in real else \
                "MKL" if "mkl" in real else "reference (netlib)" if "/blas/libblas.so" in real else ""
            return (f"{kind}, " if kind else "") + f"`{real}`"
    return "unknown"


def git_revision():
    try:
        rev = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True,
                             check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True, check=True).stdout.strip()
        return rev + (" with uncommitted changes" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def element_section(runs):
    rows = []
    for p in range(1, 21):
        b = central(runs, f"BM_ElementStiffness/{p}")
        if b:
            rows.append((p, b))
    out = ["## Element stiffness against p", "",
           "One curved element (element 1 of the Hertz quarter circle 2×2: an exact arc edge, the",
           "blending map evaluated at every Gauss point), tensor-product space, (p + 2)² Gauss points.",
           "One thread. `per mode²·point` is the time divided by modes² × Gauss points, the cost",
           "of the straightforward B^T D B sum.", "",
           "| p | modes | matrix size | Gauss points | time | per mode²·point | spread |",
           "|---:|---:|---:|---:|---:|---:|---:|"]
    for p, b in rows:
        modes, points, t = int(b["modes"]), int(b["gauss_points"]), b["real_time"]
        out.append(f"| {p} | {modes} | {2 * modes} | {points} | {fmt_time(t)} | "
                   f"{fmt_time(t / (modes * modes * points))} | "
                   f"{spread(runs, f'BM_ElementStiffness/{p}')} |")
    t10, t20 = central(runs, "BM_ElementStiffness/10"), central(runs, "BM_ElementStiffness/20")
    if t10 and t20:
        slope = math.log(t20["real_time"] / t10["real_time"]) / math.log(2.0)
        out += ["", f"Between p = 10 and p = 20 the time grows like p^{slope:.1f} "
                    "(modes² × Gauss points grows like p^6)."]
    return out


def hex_element_section(runs):
    def name(p, space, hex_map, kernel):
        return f"BM_HexElementStiffness/p:{p}/space:{space}/map:{hex_map}/kernel:{kernel}"

    rows = []
    for hex_map, map_name in ((0, "trilinear"), (1, "blending")):
        for space, space_name in ((0, "tensor"), (1, "trunk")):
            for p in range(1, 9):
                blocks, factored = (central(runs, name(p, space, hex_map, k)) for k in (0, 1))
                if blocks and factored:
                    rows.append((p, space, space_name, hex_map, map_name, blocks, factored))
    if not rows:
        return []
    out = ["## 3D: hexahedron stiffness against p", "",
           "One hexahedron's 3n × 3n stiffness (bench/bench_hex_element.cpp) by the two kernels:",
           "`blocks`, the modes' values and physical gradients at the Gauss points and the six",
           "products M_kl = G_k G_lᵀ (fem/hex_elasticity.hpp, O(p⁹)), and `factored`, sum",
           "factorisation (fem/hex_factored_stiffness.hpp, O(p⁷)): the map's Jacobians at the points,",
           "three 1D contractions over the matrix of all tensor products, the element's modes gathered",
           "from it. A distorted trilinear hex, (p + 1)³ Gauss points, and a blending hex with two",
           "spherical faces (the thick sphere's octant), (p + 3)³ points. CPU time per element, one",
           "thread. `automatic` is the kernel assemble_hex_elasticity takes (fem/hex_element.hpp: the",
           "factored one where its operation count is below 0.7 of the blocks'); `spread` the larger",
           "of the two kernels'.", "",
           "| map | space | p | modes | Gauss points | blocks | factored | blocks / factored | automatic | spread |",
           "|---|---|---:|---:|---:|---:|---:|---:|---|---:|"]
    for p, space, space_name, hex_map, map_name, blocks, factored in rows:
        worst = max((spread(runs, name(p, space, hex_map, k), "cpu_time") for k in (0, 1)),
                    key=lambda text: float(text.split()[0]) if text else 0.0)
        automatic = "factored" if factored.get("automatic_factored") else "blocks"
        out.append(f"| {map_name} | {space_name} | {p} | {int(blocks['modes'])} | "
                   f"{int(blocks['gauss_points'])} | {fmt_time(blocks['cpu_time'])} | "
                   f"{fmt_time(factored['cpu_time'])} | "
                   f"{fmt_ratio(blocks['cpu_time'], factored['cpu_time'])} | {automatic} | {worst} |")
    slopes = []
    for kernel, label in ((0, "blocks"), (1, "factored")):
        t4, t8 = (central(runs, name(p, 0, 0, kernel)) for p in (4, 8))
        if t4 and t8:
            slopes.append(f"{label} p^{math.log(t8['cpu_time'] / t4['cpu_time']) / math.log(2.0):.1f}")
    if slopes:
        out += ["", "Tensor space, trilinear hex, p = 4 to 8: the time grows like " + ", ".join(slopes) +
                " (modes² × Gauss points like p⁹, the factored contractions like p⁷; at these degrees"
                " its set-up and the gather, O(p⁶), still count). On the blending hex the map's"
                " evaluation at the points (about 30 µs each) is most of the time up to p ≈ 5."]
    return out


def hex_solve_section(runs):
    sizes = [(4, 4, 4), (8, 7, 7), (10, 9, 9)]
    rows = [(size, central(runs, "BM_HexBoxSolve/nx:{}/ny:{}/nz:{}".format(*size))) for size in sizes]
    rows = [(size, b) for size, b in rows if b]
    if not rows:
        return []
    out = ["## 3D: one condensed linear solve against its size", "",
           "A box of nx × ny × nz trilinear hexahedra (unit cubes with their nodes moved by up to",
           "0.15, so that none is affine), p = 4, tensor space, clamped on z = 0 under its weight",
           "(bench/bench_hex_solve.cpp): the (p − 1)³ = 27 internal modes of each element condensed,",
           "the system over the vertex, edge and face modes solved by CHOLMOD's supernodal Cholesky,",
           "the 2D code's solver (solve/fixed_dofs.hpp). The boxes are those whose condensed systems",
           "come nearest 10⁴, 5·10⁴ and 10⁵ unknowns at p = 4, the degree a 3D p-version mesh starts",
           "at and where the factored element kernel already wins. CPU times (all threads; the",
           "machine is shared, wall clock in the raw results): `assembly`, element stiffness (sum",
           "factorisation), condensation, the sparse matrix, one thread; `factorise + solve`, the",
           "free block, CHOLMOD's analysis, factorisation and solve (BLAS as above); `total` both.",
           "Memory: CHOLMOD's estimate after its analysis (what the refusal of a",
           "factor that will not fit compares, solve/linear_solver.hpp), its peak, and the process's",
           "peak resident memory during the solve (VmHWM reset before it). One iteration each, the",
           "median of 3 repetitions.", "",
           "| box | elements | dofs | system | assembly | factorise + solve | total | "
           "factor entries | GFLOP | estimate | CHOLMOD peak | peak RSS | spread |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for (nx, ny, nz), b in rows:
        name = f"BM_HexBoxSolve/nx:{nx}/ny:{ny}/nz:{nz}"
        rss = f"{b['peak_rss_gb']:.2f} GB" + ("" if b.get("peak_rss_of_iteration") else " (process)")
        out.append(f"| {nx}×{ny}×{nz} | {int(b['elements'])} | {int(b['dofs'])} | {int(b['n_system'])} | "
                   f"{fmt_time(b['assembly_cpu_s'])} | {fmt_time(b['solve_cpu_s'])} | "
                   f"{fmt_time(b['cpu_time'])} | "
                   f"{b['factor_entries'] / 1e6:.1f} M | {b['factor_gflop']:.0f} | "
                   f"{b['estimate_gb']:.2f} GB | {b['cholmod_peak_gb']:.2f} GB | {rss} | "
                   f"{spread(runs, name, 'cpu_time')} |")
    ratios = []
    if len(rows) >= 2:
        (s0, a), (s1, b) = rows[0], rows[-1]
        grow = math.log(b["n_system"] / a["n_system"])
        ratios.append(f"| largest / smallest: system size | {fmt_ratio(b['n_system'], a['n_system'])} |")
        for key, label in (("assembly_cpu_s", "assembly"), ("solve_cpu_s", "factorise + solve"),
                           ("factor_entries", "factor entries"), ("factor_gflop", "factorisation flops"),
                           ("peak_rss_gb", "peak resident memory")):
            ratios.append(f"| largest / smallest: {label} | {fmt_ratio(b[key], a[key])} "
                          f"(∝ n^{math.log(b[key] / a[key]) / grow:.2f}) |")
    for size, b in rows:
        ratios.append(f"| {size[0]}×{size[1]}×{size[2]}: share of factorise + solve in the CPU time | "
                      f"{100 * b['solve_cpu_s'] / (b['solve_cpu_s'] + b['assembly_cpu_s']):.0f} % |")
    return out + ratios_table(ratios)


def solve_section(runs):
    out = ["## Whole problems", "",
           "The Hertz quarter circle 2×2 (4 elements, 2 of them curved, prescribed displacement, no",
           "contact) at uniform p. `solve` times discretize + assembly + factorisation + solve;",
           "`condensed` eliminates each element's internal modes before assembly (the condensation",
           "counts as assembly) and recovers them after. `time` is wall clock, with OpenMP threads on",
           "all cores; `CPU` is the CPU time of all threads together, which other load on the machine",
           "disturbs less. `assembly` and `factorise + solve` are solve_linear()'s own wall-clock",
           "split of the same runs.", "",
           "| run | p | dofs | system size | time | CPU | assembly | factorise + solve | spread |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for p in (8, 15):
        name = f"BM_Discretize/{p}"
        b = central(runs, name)
        if b:
            out.append(f"| discretize only | {p} | {int(b['dofs'])} | | {fmt_time(b['real_time'])} "
                       f"| {fmt_time(b['cpu_time'])} | | | {spread(runs, name)} |")
    for condense in (0, 1):
        for p in (8, 15):
            name = f"BM_LinearSolve/p:{p}/condense:{condense}"
            b = central(runs, name)
            if b:
                label = "solve, condensed" if condense else "solve, full"
                out.append(f"| {label} | {p} | {int(b['dofs'])} | {int(b['n_system'])} | "
                           f"{fmt_time(b['real_time'])} | {fmt_time(b['cpu_time'])} | "
                           f"{fmt_time(b['assembly_ms'] * 1e-3)} | "
                           f"{fmt_time(b['solve_ms'] * 1e-3)} | {spread(runs, name)} |")
    b = central(runs, "BM_LameEndToEnd")
    if b:
        out.append(f"| Lamé example end to end | {int(b['p'])} | {int(b['dofs'])} | | "
                   f"{fmt_time(b['real_time'])} | {fmt_time(b['cpu_time'])} | | | "
                   f"{spread(runs, 'BM_LameEndToEnd')} |")
    out += ["", "`Lamé example end to end` is examples/lame/thick-cylinder.yaml (2 elements) read,",
            "discretised, solved and post-processed (stresses, energy, error against the closed form)",
            "as `hpcontact run` does, without writing files."]

    ratios = []
    for p in (8, 15):
        full = central(runs, f"BM_LinearSolve/p:{p}/condense:0")
        cond = central(runs, f"BM_LinearSolve/p:{p}/condense:1")
        if full and cond:
            ratios.append(f"| full / condensed, p = {p}: total time | "
                          f"{fmt_ratio(full['real_time'], cond['real_time'])} |")
            ratios.append(f"| full / condensed, p = {p}: total CPU time | "
                          f"{fmt_ratio(full['cpu_time'], cond['cpu_time'])} |")
            ratios.append(f"| full / condensed, p = {p}: factorise + solve | "
                          f"{fmt_ratio(full['solve_ms'], cond['solve_ms'])} |")
    for condense, label in ((0, "full"), (1, "condensed")):
        a = central(runs, f"BM_LinearSolve/p:15/condense:{condense}")
        b = central(runs, f"BM_LinearSolve/p:8/condense:{condense}")
        if a and b:
            ratios.append(f"| p = 15 / p = 8, {label} solve | {fmt_ratio(a['real_time'], b['real_time'])} "
                          f"(dofs {fmt_ratio(a['dofs'], b['dofs'])}) |")
    e15, full15 = central(runs, "BM_ElementStiffness/15"), central(runs, "BM_LinearSolve/p:15/condense:0")
    if full15:
        ratios.append(f"| p = 15, full solve: share of factorise + solve | "
                      f"{100 * full15['solve_ms'] * 1e-3 / full15['real_time']:.0f} % |")
    cond15 = central(runs, "BM_LinearSolve/p:15/condense:1")
    if cond15:
        ratios.append(f"| p = 15, condensed solve: share of assembly (stiffness + condensation) | "
                      f"{100 * cond15['assembly_ms'] * 1e-3 / cond15['real_time']:.0f} % |")
    if e15 and full15:
        ratios.append(f"| p = 15, full solve: share of 4 element stiffnesses (one thread) | "
                      f"{100 * 4 * e15['real_time'] / full15['real_time']:.0f} % |")
    return out + ratios_table(ratios)


def ratios_table(ratios):
    """The rows "| ratio | value |" under their heading, or nothing."""
    if not ratios:
        return []
    return ["", "Ratios within this run:", "", "| ratio | value |", "|---|---:|"] + ratios


def contact_section(runs):
    out = ["## Contact: analytic against the dissertation's finite-difference tangent", "",
           "The Hertz examples p5 and p8 (examples/hertz) with the seed's penalty (`enforcement: penalty`),",
           "the whole contact solve (force control: six load steps, about 45 Newton iterations),",
           "discretisation outside the timed region.",
           "`analytic` is the consistent tangent solved by CHOLMOD; `FD` is the dissertation's tangent",
           "(D. Franke's, docs/references.md; eq. 3.36: central differences of the whole residual, one column per unknown, normals of",
           "the undisturbed state) solved by UMFPACK LU; `full` runs Newton on all free unknowns, as",
           "the dissertation did, `condensed` on vertex and edge modes only (our default).", "",
           "| run | p | dofs | Newton iterations | time | spread |", "|---|---:|---:|---:|---:|---:|"]
    labels = {(0, 1): "analytic, condensed", (0, 0): "analytic, full", (1, 0): "FD, full"}
    for p in (5, 8):
        for (fd, cond), label in labels.items():
            name = f"BM_HertzSolve/p:{p}/fd:{fd}/condense:{cond}"
            b = central(runs, name)
            if b:
                out.append(f"| {label} | {p} | {int(b['dofs'])} | {int(b['newton_iterations'])} | "
                           f"{fmt_time(b['real_time'])} | {spread(runs, name)} |")
    for p in (5, 8):
        for fd, label in ((0, "analytic"), (1, "FD")):
            name = f"BM_HertzTangent/p:{p}/fd:{fd}"
            b = central(runs, name)
            if b:
                out.append(f"| one {label} tangent (full) | {p} | {int(b['dofs'])} | | "
                           f"{fmt_time(b['real_time'])} | {spread(runs, name)} |")
    ratios = []
    for p in (5, 8):
        fd = central(runs, f"BM_HertzSolve/p:{p}/fd:1/condense:0")
        full = central(runs, f"BM_HertzSolve/p:{p}/fd:0/condense:0")
        cond = central(runs, f"BM_HertzSolve/p:{p}/fd:0/condense:1")
        if fd and full:
            ratios.append(f"| p = {p}: FD solve / analytic solve, both full | "
                          f"{fmt_ratio(fd['real_time'], full['real_time'])} |")
        if fd and cond:
            ratios.append(f"| p = {p}: FD solve (full, the dissertation's setting) / our default | "
                          f"{fmt_ratio(fd['real_time'], cond['real_time'])} |")
        tf = central(runs, f"BM_HertzTangent/p:{p}/fd:1")
        ta = central(runs, f"BM_HertzTangent/p:{p}/fd:0")
        if tf and ta:
            ratios.append(f"| p = {p}: one FD tangent / one analytic tangent | "
                          f"{fmt_ratio(tf['real_time'], ta['real_time'])} |")
    out += ratios_table(ratios)
    out += ["", "### Examples end to end", "",
            "As `hpcontact run` does them: read the YAML, discretise, solve (force control), post-process",
            "and write every file (summary.json, contact.csv, pressure.csv, solution.vtu, input.yaml) into a",
            "temporary folder. The time a user waits, less process start-up.", "",
            "| example | dofs | Newton iterations (all solves) | time | CPU | spread |", "|---|---:|---:|---:|---:|---:|"]
    examples = ["examples/hertz/p15.yaml", "examples/hertz/bilateral.yaml",
                "examples/curve-obstacle/crowned-rail.yaml (rp loop)",
                "examples/hertz/hp-tolerance.yaml (hp loop to 1e-4, its comparisons at every step)",
                "examples/hertz/hp-tolerance.yaml without `compare` (hp loop to 1e-4)"]
    for k, label in enumerate(examples):
        name = f"BM_ExampleEndToEnd/example:{k}"
        b = central(runs, name)
        if b:
            out.append(f"| {label} | {int(b['dofs'])} | {int(b['newton_iterations'])} | "
                       f"{fmt_time(b['real_time'])} | {fmt_time(b['cpu_time'])} | {spread(runs, name)} |")
    return out


def adapt_section(runs):
    out = ["## Adaptive loops (issue 4)", "",
           "Whole loops on the Hertz examples, from reading the input to the last solve, without",
           "post-processing or files: the rp relocation loop of examples/hertz/rp5.yaml and rp8.yaml",
           "(secant steps, to 1e-10 of the body size) and the 8-step hp loop of examples/hertz/hp.yaml",
           "with the refinement factor 0.17 (the example's) and the dissertation's 0.5, with exact contact",
           "(the default). Each solve is a force-controlled Newton solve started from the previous mesh's",
           "solution carried onto the new mesh.", "",
           "| loop | final dofs | solves | Newton iterations | time | spread |",
           "|---|---:|---:|---:|---:|---:|"]
    rows = [(f"BM_RpLoop/p:{p}", f"rp, p = {p}") for p in (5, 8)]
    rows += [(f"BM_HpLoop/factor_percent:{f}", f"hp, 8 steps, factor {f / 100:g}") for f in (17, 50)]
    for name, label in rows:
        b = central(runs, name)
        if b:
            out.append(f"| {label} | {int(b['dofs'])} | {int(b['solves'])} | "
                       f"{int(b['newton_iterations'])} | {fmt_time(b['real_time'])} | "
                       f"{spread(runs, name)} |")
    out += ["", "The hp loop to a requested accuracy (examples/hertz/hp-tolerance.yaml, issue 16): every step",
            "solved twice (the step and, for its error estimate, one degree higher on its mesh), stopped at",
            "the first step estimated below the tolerance; its defaults (goal-oriented degrees in the trunk",
            "space) and the rising degree in the tensor space (the defaults before); beside the defaults' loop",
            "one linear elastic solve of its final mesh (no contact), and the ratio of the two, measured in",
            "this run. The same loop end to end, files written, is in \"Examples end to end\" above (with",
            "and without the example's comparisons, which probe the pressure ~10⁴ times at every step).", "",
            "| tolerance | degrees | steps | final dofs | solves | Newton iterations | estimate | time | spread | "
            "one linear solve of the final mesh | loop / linear solve |",
            "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for k in (3, 4):
        lin = central(runs, f"BM_HpToToleranceFinalLinearSolve/tol_exp:{k}")
        for rising, label in ((0, "goal-oriented, trunk"), (1, "rising, tensor")):
            name = f"BM_HpToTolerance/tol_exp:{k}/rising:{rising}"
            b = central(runs, name)
            if not b:
                continue
            ratio = [f"{fmt_time(lin['real_time'])}", f"{b['real_time'] / lin['real_time']:.0f}"] \
                if lin and not rising else ["", ""]
            out.append(f"| 1e-{k} | {label} | {int(b['steps'])} | {int(b['dofs'])} | {int(b['solves'])} | "
                       f"{int(b['newton_iterations'])} | {b['estimate']:.2g} | "
                       f"{fmt_time(b['real_time'])} | {spread(runs, name)} | {ratio[0]} | {ratio[1]} |")
    return out


def nonlinear_section(runs):
    out = ["## Finite strain, friction, arc-length (issue 5)", "",
           "Whole solves of the examples, from the discretised problem to the converged last step",
           "(no files), with exact contact (the default): load steps, Newton iterations, and the time per",
           "load step. The axle in the",
           "ring (Neo-Hooke, 20 nominal steps), the two bars (press, then push in 4 steps; stick and",
           "Coulomb), the snap-through of the shallow arch (tests/cli/data) under load control and",
           "with the arc-length method, the composite ring on the foundation (arc-length).", "",
           "| case | dofs | load steps | Newton iterations | time | per step | spread |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    cases = ["examples/axle-ring/ring2-p4.yaml", "examples/axle-ring/ring12-p4.yaml",
             "examples/axle-ring/ring16-p5.yaml", "examples/two-bars/stick.yaml",
             "examples/two-bars/coulomb.yaml", "tests/cli/data/shallow-arch.yaml",
             "examples/ring-foundation/ring.yaml"]
    rows = [(f"BM_Nonlinear/{c}", c) for c in cases]
    rows.append(("BM_ArcLength/tests/cli/data/shallow-arch.yaml", "shallow arch, arc-length"))
    for name, label in rows:
        b = central(runs, name)
        if b:
            steps = max(1, int(b["load_steps"]))
            out.append(f"| {label} | {int(b['dofs'])} | {steps} | {int(b['newton_iterations'])} | "
                       f"{fmt_time(b['real_time'])} | {fmt_time(b['real_time'] / steps)} | "
                       f"{spread(runs, name)} |")
    out += ["", "One Newton step's linear solve on the two bars (p = [15, 5], penalty tangent at the converged",
            "state): the unsymmetric Coulomb tangent by LU (UMFPACK) against the symmetric stick tangent",
            "by LU and by Cholesky (CHOLMOD), same mesh and unknowns.", "",
            "| tangent | solver | dofs | nonzeros | factorise + solve | spread |",
            "|---|---|---:|---:|---:|---:|"]
    for law, solver in (("coulomb", "lu"), ("stick", "lu"), ("stick", "cholmod")):
        name = f"BM_TwoBarsLinearStep/{law}/{solver}"
        b = central(runs, name)
        if b:
            out.append(f"| {law} | {solver} | {int(b['dofs'])} | {int(b['nonzeros'])} | "
                       f"{fmt_time(b['real_time'])} | {spread(runs, name)} |")
    a, c = central(runs, "BM_TwoBarsLinearStep/coulomb/lu"), central(runs, "BM_TwoBarsLinearStep/stick/cholmod")
    if a and c:
        out += ["", f"Unsymmetric (LU) / symmetric (CHOLMOD): {fmt_ratio(a['real_time'], c['real_time'])}."]
    return out


ENFORCEMENT_CASES = ["examples/hertz/p8.yaml", "examples/hertz/rp8.yaml", "examples/hertz/hp.yaml",
                     "examples/hertz/bilateral.yaml", "examples/curve-obstacle/crowned-rail.yaml",
                     "examples/two-bars/stick.yaml", "examples/two-bars/coulomb.yaml",
                     "examples/axle-ring/ring12-p4.yaml", "examples/ring-foundation/ring.yaml"]


def enforcement_section(runs):
    out = ["## Exact contact against the penalty (issue 15)", "",
           "Each case solved twice in this run, from reading the input to the last solve (no files):",
           "with exact contact (the default: multipliers at the Gauss–Lobatto nodes, semi-smooth Newton,",
           "bordered force control, warm starts in the rp and hp loops) and with every pair turned to",
           "`enforcement: penalty` (the seed's method; the bilateral example, which gives no penalty,",
           "with its former 1.05e8). `solves` counts the meshes solved (rp relocations, hp steps).",
           "The CPU column sums all threads.", "",
           "| case | dofs | penalty: solves | Newton | time | CPU | exact: solves | Newton | time | CPU |"
           " penalty / exact time | spread |",
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    ratios = []
    for case in ENFORCEMENT_CASES:
        pen, ex = (central(runs, f"BM_Enforcement/{k}/{case}") for k in ("penalty", "exact"))
        if not (pen and ex):
            continue
        worst = max((spread(runs, f"BM_Enforcement/{k}/{case}") for k in ("penalty", "exact")),
                    key=lambda text: float(text.split()[0]) if text else 0.0)
        out.append(f"| {case} | {int(ex['dofs'])} | {int(pen['solves'])} | {int(pen['newton_iterations'])} | "
                   f"{fmt_time(pen['real_time'])} | {fmt_time(pen['cpu_time'])} | {int(ex['solves'])} | "
                   f"{int(ex['newton_iterations'])} | {fmt_time(ex['real_time'])} | {fmt_time(ex['cpu_time'])} | "
                   f"{fmt_ratio(pen['real_time'], ex['real_time'])} | {worst} |")
        if ex.get("most_per_relocation"):
            ratios.append(f"| {case}: most Newton iterations of one relocation after the first, exact "
                          f"(penalty) | {int(ex['most_per_relocation'])} ({int(pen['most_per_relocation'])}) |")
    p8, linear = central(runs, "BM_Enforcement/exact/examples/hertz/p8.yaml"), central(runs, "BM_HertzP8LinearSolve")
    if p8 and linear:
        ratios.insert(0, f"| Hertz p8, force controlled, exact: Newton iterations | {int(p8['newton_iterations'])} |")
        ratios.insert(1, "| Hertz p8, force controlled, exact / one linear elastic solve of the same mesh "
                         f"({fmt_time(linear['real_time'])}): time | {fmt_ratio(p8['real_time'], linear['real_time'])} |")
        ratios.insert(2, f"| the same, CPU time | {fmt_ratio(p8['cpu_time'], linear['cpu_time'])} |")
    hp = central(runs, "BM_Enforcement/exact/examples/hertz/hp.yaml")
    if hp:
        ratios.append(f"| hp loop of hp.yaml, exact: Newton iterations over all its solves | {int(hp['newton_iterations'])} |")
    out += ratios_table(ratios)
    out += ["", "The linear elastic solve is examples/hertz/p8.yaml without its contact pair (its prescribed",
            "displacement only): discretise, assemble (condensed, as the contact solve), factorise, solve."]
    return out


def blas_section(runs, reference_path):
    """The BLAS-sensitive benchmarks run again on the reference (netlib) BLAS in the same
    `make bench` (LD_LIBRARY_PATH to it): before and after OpenBLAS."""
    if not reference_path or not os.path.exists(reference_path):
        return []
    _, ref = load(reference_path)
    out = ["## The BLAS: reference (netlib) against the one above", "",
           textwrap.fill("The benchmarks whose time is the factorisation's, run again in the same"
                         " `make bench` with libblas.so.3 and liblapack.so.3 taken from Debian's"
                         " reference BLAS and LAPACK (LD_LIBRARY_PATH): what installing a fast BLAS"
                         " (scripts/install-deps.sh) bought. Medians of the same repetitions; the"
                         " ratio is reference / installed.", width=95), "",
           "| benchmark | reference BLAS | installed BLAS | ratio | factorise + solve: reference | installed |",
           "|---|---:|---:|---:|---:|---:|"]
    for name in sorted(ref):
        a, b = central(ref, name), central(runs, name)
        if not a or not b:
            continue
        fs = ("", "")
        if "solve_ms" in a and "solve_ms" in b:
            fs = (fmt_time(a["solve_ms"] * 1e-3), fmt_time(b["solve_ms"] * 1e-3))
        out.append(f"| {name.removeprefix('BM_')} | {fmt_time(a['real_time'])} | {fmt_time(b['real_time'])} "
                   f"| {fmt_ratio(a['real_time'], b['real_time'])} | {fs[0]} | {fs[1]} |")
    return out + [""]


def main(results_path, output_path, reference_blas_path=None):
    context, runs = load(results_path)
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    cores = len(os.sched_getaffinity(0))
    load_avg = context.get("load_avg") or []
    reps = repetitions(runs)
    lines = [
        f"Generated by `make bench` (bench/run.sh) on {now}, {cpu_model()}, {cores} cores — "
        "do not edit by hand; run `make bench` to regenerate.",
        "",
        "# Benchmarks",
        "",
        f"Commit {git_revision()}; Release build; BLAS {blas_library()}; "
        f"OMP_NUM_THREADS={os.environ.get('OMP_NUM_THREADS', 'unset (all cores)')}; "
        f"load average at start {', '.join(f'{x:.1f}' for x in load_avg) or 'unknown'}. "
        f"Raw results: `{results_path}` (Google Benchmark JSON).",
        "",
        textwrap.fill(
            "How to read it: each time is "
            + (f"the median of {reps} repetitions (run in random order), each repetition running"
               " the operation" if reps > 1 else "from one run of the operation, repeated")
            + " as often as fits in 0.2 s (at least once). `spread` is the coefficient"
            " of variation across the repetitions: above ~10 % the machine was busy and that row is"
            " unreliable; compare rows of the same run (the ratios) rather than figures across"
            " machines or days. Set-up (building the problem, and for the element kernel the whole"
            " discretisation) is outside the timed region unless the row says otherwise. The"
            " factorisation is CHOLMOD's supernodal Cholesky on the BLAS named above, so the"
            " factorise + solve column depends on that library as much as on this code.",
            width=95),
        "",
    ]
    lines += element_section(runs) + [""] + hex_element_section(runs) + [""] + hex_solve_section(runs)
    lines += [""] + solve_section(runs) + [""] + blas_section(runs, reference_blas_path)
    lines += enforcement_section(runs) + [""] + contact_section(runs) + [""] + adapt_section(runs) + [""] + nonlinear_section(runs) + [""]
    lines += kept_sections(output_path)
    with open(output_path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


# The sections a run of their benchmarks alone can rewrite (bench/run.sh with SECTIONS=...): name
# -> (the function that writes it, the benchmarks it reads, the heading it goes before when the
# file has none of it yet).
PARTIAL_SECTIONS = {
    "hex-element": (hex_element_section, "BM_HexElementStiffness", "## Whole problems"),
    "hex-solve": (hex_solve_section, "BM_HexBoxSolve", "## Whole problems"),
}


def replace_sections(results_path, output_path, names):
    """Rewrites only the named sections of an existing BENCHMARKS.md from a run of their
    benchmarks, each stamped with its own commit, date and load (the file's header keeps those
    of the last whole run); the rest of the file stays as it is."""
    context, runs = load(results_path)
    text = open(output_path, encoding="utf-8").read()
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    load_avg = ", ".join(f"{x:.1f}" for x in context.get("load_avg") or []) or "unknown"
    for name in names:
        write, benchmarks, before = PARTIAL_SECTIONS[name]
        lines = write(runs)
        if not lines:
            sys.exit(f"report.py: {results_path} has no {benchmarks} results for the section {name}")
        stamp = (f"*This section regenerated alone (`SECTIONS={','.join(names)} bash bench/run.sh`) on {now}, "
                 f"commit {git_revision()}, load average at start {load_avg}.*")
        block = "\n".join(lines[:2] + [stamp, ""] + lines[2:]) + "\n\n"
        start = text.find(lines[0] + "\n")
        if start < 0:
            start = end = text.index(before + "\n")
        else:
            end = text.find("\n## ", start + 1)
            end = len(text) if end < 0 else end + 1
        text = text[:start] + block + text[end:]
    with open(output_path, "w", encoding="utf-8") as f:
        f.write(text)


def kept_sections(path):
    """The sections of the old file that other scripts write (between "<!-- kept: NAME -->" and
    "<!-- /kept: NAME -->", e.g. bench/study_executors.py's), as lines to keep at the end."""
    if not os.path.exists(path):
        return []
    text = open(path, encoding="utf-8").read()
    kept = re.findall(r"(<!-- kept: ([\w-]+) -->.*?<!-- /kept: \2 -->)", text, flags=re.S)
    return [line for block, _ in kept for line in block.split("\n") + [""]]


if __name__ == "__main__":
    if len(sys.argv) == 5 and sys.argv[1] == "--only":
        unknown = [n for n in sys.argv[2].split(",") if n not in PARTIAL_SECTIONS]
        if unknown:
            sys.exit(f"report.py: no section {', '.join(unknown)} (sections: {', '.join(PARTIAL_SECTIONS)})")
        replace_sections(sys.argv[3], sys.argv[4], sys.argv[2].split(","))
        sys.exit(0)
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: report.py RESULTS.json BENCHMARKS.md [REFERENCE-BLAS-RESULTS.json]\n"
                 "       report.py --only SECTION[,SECTION...] RESULTS.json BENCHMARKS.md")
    main(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) == 4 else None)
