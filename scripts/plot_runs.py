"""What the plot scripts share when they draw several runs and several contact pairs: the runs'
labels, the units the user names, what identifies a pair, a grid of one panel per pair, one
legend entry per run beside the panels, and the prescribed displacements (the squeeze) a run's
effective input gives. Standard library and matplotlib only (PyYAML where it is installed)."""
import math
import os
import sys

from hpc_run import unit_text, units_of


def add_run_arguments(ap, what):
    """The arguments every multi-run plot takes: the folders, --label once per folder, --units."""
    ap.add_argument("folders", nargs="+", metavar="RESULTS_DIR",
                    help=f"--out folders of `hpcontact run` ({what})")
    ap.add_argument("--label", action="append", metavar="TEXT",
                    help="the legend label of a run, given once per RESULTS_DIR in their order "
                         "(default: the folder's name)")
    ap.add_argument("--units", metavar="LENGTH,FORCE",
                    help="the units the input's numbers are in, e.g. mm,N: axis labels then say "
                         "[mm], [N/mm] (hpcontact has no units of its own; default: those "
                         "summary.json names, else 'input units')")


def parse_units(text):
    """--units LENGTH,FORCE as the mapping unit_text takes, e.g. "mm,N" -> {"length": "mm",
    "force": "N"}; ValueError saying what is wrong."""
    parts = [p.strip() for p in text.split(",")]
    if len(parts) != 2 or not all(parts):
        raise ValueError(f"--units: give LENGTH,FORCE, e.g. mm,N (got '{text}')")
    return {"length": parts[0], "force": parts[1]}


def chosen_units(args, summary):
    """The units of the labels: --units, else those summary.json names, else None."""
    return parse_units(args.units) if args.units else units_of(summary)


def unit_of(quantity, units):
    """The unit of a quantity of QUANTITIES in a label: "[N/mm]" where the units name length and
    force, else "(input units)" (the quantity's words say what it is)."""
    if isinstance(units, dict) and "length" in units and "force" in units:
        return unit_text(quantity, units)
    return "[-]" if unit_text(quantity) == "[-]" else "(input units)"


def run_labels(folders, labels):
    """One label per run: --label as given, else the folder's name (with its parent's where two
    folders have one name). ValueError when the number of --label differs from the folders'."""
    if labels:
        if len(labels) != len(folders):
            raise ValueError(f"--label: given {len(labels)} time(s) for {len(folders)} "
                             "RESULTS_DIR (once per folder, in their order)")
        return list(labels)
    paths = [os.path.normpath(os.path.abspath(f)) for f in folders]
    names = [os.path.basename(p) for p in paths]
    if len(set(names)) < len(names):
        names = [os.path.join(os.path.basename(os.path.dirname(p)), os.path.basename(p))
                 for p in paths]
    return names if len(set(names)) == len(names) else paths


def read_problem(folder):
    """The run's effective input (input.yaml) as a mapping, or {} without it (or without
    PyYAML): titles and squeezes then come from what the CSV files and summary.json say."""
    path = os.path.join(folder, "input.yaml")
    if not os.path.isfile(path):
        return {}
    try:
        import yaml
        with open(path) as f:
            return yaml.safe_load(f) or {}
    except Exception as e:  # noqa: BLE001 - a plot with plainer titles beats no plot
        print(f"{os.path.basename(sys.argv[0])}: {path}: not read ({e})", file=sys.stderr)
        return {}


def _point(v):
    return "(" + ", ".join(f"{float(c):g}" for c in v) + ")"


def obstacle_text(spec, moved=True):
    """A short description of contact[].obstacle: "plane y = 20", "circle (0, 0) r = 5", ...,
    with its displacement if `moved` ("plane y = 20, moved (0, -2)")."""
    kind = spec.get("type")
    if kind == "plane":
        p, n = spec.get("point") or [0, 0], spec.get("normal") or [0, 1]
        if n[0] == 0:
            text = f"plane y = {float(p[1]):g}"
        elif n[1] == 0:
            text = f"plane x = {float(p[0]):g}"
        else:
            text = f"plane through {_point(p)}, normal {_point(n)}"
    elif kind == "circle":
        text = (f"{'hole' if spec.get('inside') else 'circle'} {_point(spec.get('center') or [0, 0])}"
                f" r = {float(spec.get('radius', 0)):g}")
    elif kind == "curve":
        text = f"curve through {len(spec.get('points') or [])} points"
    elif kind == "body":
        edges = spec.get("edges") or []
        text = f"body {spec.get('body')}" + (f" [{', '.join(edges)}]" if edges else "")
    else:
        return str(kind)
    d = spec.get("displacement") or [0, 0]
    return text + (f", moved {_point(d)}" if moved and any(float(c) != 0 for c in d) else "")


def pair_title(k, problem, summary, moved=True):
    """What identifies contact pair k (the `pair` column of contact.csv and contact_history.csv):
    from input.yaml its body, edge sets and obstacle ("contact[1]: ring [top]\\nvs plane y = 20,
    moved (0, -2)"; without the displacement unless `moved`); without input.yaml summary.json's
    body and obstacle; else "pair k"."""
    pairs = problem.get("contact") or []
    if k < len(pairs) and isinstance(pairs[k], dict):
        p = pairs[k]
        return (f"contact[{k}]: {p.get('body')} [{', '.join(p.get('edges') or [])}]\n"
                f"vs {obstacle_text(p.get('obstacle') or {}, moved)}")
    for p in summary.get("contact_pairs") or []:
        if p.get("pair") == k:
            return f"contact[{k}]: {p.get('body')}\nvs {p.get('obstacle')}"
    return f"pair {k}"


def panel_grid(n):
    """Rows and columns of n panels: side by side up to 3, else in rows of 2 (4 pairs: 2 x 2)
    or 3."""
    cols = n if n <= 3 else (2 if n == 4 else 3)
    return math.ceil(n / cols), cols


def legend_below(fig, handles, labels, ncol=None):
    """One legend for the figure, below its panels, where it covers no curve; returns the
    height it takes as a fraction of the figure (for tight_layout's rect)."""
    if not handles:
        return 0.0
    ncol = ncol or min(len(labels), 3)
    rows = math.ceil(len(labels) / ncol)
    height = (0.12 + 0.2 * rows) / fig.get_figheight()
    fig.legend(handles, labels, loc="lower center", ncol=ncol, fontsize=8, frameon=False,
               bbox_to_anchor=(0.5, 0.0))
    return height


# The prescribed displacements of a run (obstacle.displacement, constraints' ux/uy), and the
# squeeze: the distance one of them has moved at a load step.

class Prescribed:
    """One prescribed displacement of input.yaml: `name` (contact[K] for a pair's obstacle,
    BODY/EDGE_SET+... or BODY/nodes for a constraint), the names a user may call it by,
    its vector d at factor 1 and what it is."""

    def __init__(self, name, aliases, d, what):
        self.name, self.aliases, self.d, self.what = name, set(aliases) | {name}, d, what

    def squeeze(self, factor_x, factor_y):
        """How far it has moved along its own direction at these factors: (f_x d_x, f_y d_y)
        projected on d/|d| (f |d| when f_x = f_y = f)."""
        norm = math.hypot(*self.d)
        return (factor_x * self.d[0] ** 2 + factor_y * self.d[1] ** 2) / norm


def prescribed_displacements(problem, where):
    """The non-zero prescribed displacements of an effective input. A formula (a string) is
    not one vector: ValueError naming the key, `where` the file."""
    found = []
    for k, pair in enumerate(problem.get("contact") or []):
        spec = (pair or {}).get("obstacle") or {}
        d = [float(c) for c in spec.get("displacement") or [0, 0]]
        if any(d):
            found.append(Prescribed(f"contact[{k}]", {str(k)}, d,
                                    f"contact[{k}]'s obstacle ({obstacle_text(spec)})"))
    for b, body in enumerate(problem.get("bodies") or []):
        for j, c in enumerate((body or {}).get("constraints") or []):
            values = [c.get("ux", 0), c.get("uy", 0)]
            key = f"bodies[{b}].constraints[{j}]"
            if any(isinstance(v, str) for v in values):
                raise ValueError(f"{where}: {key}: a formula is no single displacement, so no "
                                 "squeeze is computed from it")
            d = [float(v) for v in values]
            if not any(d):
                continue
            edges = c.get("edges") or []
            name = f"{body.get('name')}/" + ("+".join(edges) if edges else "nodes")
            found.append(Prescribed(name, set(edges) | {body.get("name")}, d,
                                    f"the prescribed displacement {_point(d)} of {name}"))
    return found


def find_prescribed(problem, name, where):
    """The prescribed displacement `name` names (None: the only one of the run). ValueError
    listing the run's candidates when there is none or more than one."""
    found = prescribed_displacements(problem, where)
    matching = [p for p in found if name is None or name in p.aliases]
    if len(matching) == 1:
        return matching[0]
    listed = ", ".join(p.name for p in found) or "none"
    if not matching:
        what = f"no prescribed displacement '{name}'" if name else "no prescribed displacement"
    else:
        what = (f"'{name}' names several prescribed displacements" if name else
                "several prescribed displacements")
    raise ValueError(f"{where}: {what} (the run's: {listed}); name one as squeeze:NAME")


def pair_cells(fig, n_pairs, n_rows, height_ratios=None):
    """The axes of one panel per pair, laid out by panel_grid: a list (per pair) of n_rows axes
    stacked in the pair's cell and sharing its abscissa (the top one carries the title)."""
    from matplotlib.gridspec import GridSpec, GridSpecFromSubplotSpec
    rows, cols = panel_grid(n_pairs)
    outer = GridSpec(rows, cols, figure=fig)
    cells = []
    for k in range(n_pairs):
        inner = GridSpecFromSubplotSpec(n_rows, 1, subplot_spec=outer[k // cols, k % cols],
                                        height_ratios=height_ratios, hspace=0.08)
        axes = [fig.add_subplot(inner[0])]
        axes += [fig.add_subplot(inner[i], sharex=axes[0]) for i in range(1, n_rows)]
        for a in axes[:-1]:
            a.tick_params(labelbottom=False)
        cells.append(axes)
    return cells


def common_pair_title(k, runs):
    """The title of pair k's panel for several runs (objects with .problem, .summary, .pairs):
    the first run's; without the obstacle's displacement where the runs' titles differ by it
    (two squeezes of one model)."""
    having = [r for r in runs if k in r.pairs]
    titles = {pair_title(k, r.problem, r.summary) for r in having}
    return pair_title(k, having[0].problem, having[0].summary, moved=len(titles) == 1)
