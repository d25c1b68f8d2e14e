#!/usr/bin/python3
"""Draws one field of a solution.vtu (written by `hpcontact run`) on the deformed mesh, with the
element outlines and the rigid obstacles: a quick look without ParaView.

usage: plot_field.py RESULTS_DIR/solution.vtu [--field von_mises] [--scale 0] [--out FILE.png]
       [--xlim A B] [--ylim A B] [--vmin V] [--vmax V] [--units LENGTH,FORCE]

--field: a point field of the file (von_mises, sigma_xx, sigma_yy, sigma_xy, sigma_zz,
principal_1, principal_2, strain_xx, strain_yy, gamma_xy).

--scale: magnification of the displacement (1: true scale). 0 (the default) chooses it: the
largest displacement drawn as 5 % of the size of the view (the model, or --xlim/--ylim), but
where bodies touch each other or a rigid obstacle, no more than keeps what touches touching.
Magnifying a deformation misdraws contact both ways: it pushes a body into what it presses on,
and it parts surfaces whose contact closed an overlap of the input — a press fit's shaft is
meshed larger than the hub's bore by the interference δ, the solution closes it, and at scale
s the two are drawn (s - 1) δ apart (× 180 drew a hub 3.6 mm off its shaft). So the scale is
the largest, at least 1, at which (a) no drawn body penetrates another or an obstacle deeper
than the computed solution does, plus a tolerance, and (b) no boundary point that touches
(lies within the tolerance of the other body or the obstacle at true scale) is drawn farther
from it — apart or into it — than at true scale, plus the tolerance. The tolerance is 0.2 % of
the view's size: about a pixel at the default figure size, an overlap or a gap no one sees.
Bounding the drawing, rather than a fraction of the element size, keeps the picture honest
where it matters (what a reader sees touching does touch) and lets the magnification grow
wherever contact is not at stake. The title gives the scale and why; --scale 1 draws the true
deformation.

The rigid obstacles of the run's contact pairs (input.yaml beside the .vtu: planes, circles,
curves through points) are drawn in grey at their final position (obstacle.displacement times
the last displacement factor of path.csv, magnified like the bodies).

--vmin/--vmax: the colour range; by default the field's range, except where a few points lie far
outside the rest (a stress singularity, e.g. at an element corner whose blending map
degenerates: a value more than nine times the spread of the central 98 % beyond the 1st or 99th
percentile): then the colours are clipped at the 0.5th or 99.5th percentile, the colour bar
shows an arrow, and the legend says so with the extreme value and where it is. The same holds
for a --vmin or --vmax the data exceed.

Axis and colour-bar labels carry units: those summary.json names (a "units" entry), else "input
units" (the program has no unit system: its results are in the units of the input's numbers).
Writes FILE.png (default: <field>.png next to the .vtu) and prints its name, the scale, the
obstacles drawn and any clipping.
"""
import csv
import json
import os
import sys
from collections import Counter

import matplotlib

matplotlib.use("Agg")
import matplotlib.patches as mpatches  # noqa: E402
import matplotlib.path as mpath  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import axis_label, read_vtu, script_parser, units_of  # noqa: E402
from plot_runs import parse_units  # noqa: E402

STRESS_FIELDS = {"von_mises", "sigma_xx", "sigma_yy", "sigma_xy", "sigma_zz", "principal_1",
                 "principal_2"}
OVERLAP_TOLERANCE = 0.002  # of the view's size: an overlap or a gap no one sees (about a pixel)


def results_file(vtu, name):
    """A file of the run the .vtu belongs to (beside it, or one folder up for steps/*.vtu)."""
    here = os.path.dirname(os.path.abspath(vtu))
    for folder in (here, os.path.dirname(here)):
        if os.path.isfile(os.path.join(folder, name)):
            return os.path.join(folder, name)
    return None


def read_run(vtu):
    """summary.json (or {}), input.yaml's contact pairs and body names (or []), and the final
    displacement factor of path.csv (or 1)."""
    summary, pairs, bodies, factor = {}, [], [], 1.0
    path = results_file(vtu, "summary.json")
    if path:
        with open(path) as f:
            summary = json.load(f)
    path = results_file(vtu, "input.yaml")
    if path:
        try:
            import yaml
            with open(path) as f:
                problem = yaml.safe_load(f) or {}
            pairs = problem.get("contact") or []
            bodies = [b.get("name") for b in problem.get("bodies") or []]
        except Exception as e:  # noqa: BLE001 - a plot without obstacles beats no plot
            print(f"plot_field: {path}: obstacles not drawn ({e})", file=sys.stderr)
    path = results_file(vtu, "path.csv")
    if path:
        with open(path) as f:
            rows = list(csv.DictReader(f))
        if rows and rows[-1].get("displacement_factor"):
            factor = float(rows[-1]["displacement_factor"])
    return summary, pairs, bodies, factor


def natural_spline(points, n=400):
    """Points along the natural cubic spline through `points` (chord-length parameter), as the
    program builds a curve obstacle; two points give the straight segment."""
    p = np.asarray(points, dtype=float)
    if len(p) < 3:
        return p
    t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))])
    h = np.diff(t)
    m = len(p)
    A = np.zeros((m, m))
    rhs = np.zeros((m, 2))
    A[0, 0] = A[-1, -1] = 1.0
    for i in range(1, m - 1):
        A[i, i - 1], A[i, i], A[i, i + 1] = h[i - 1], 2 * (h[i - 1] + h[i]), h[i]
        rhs[i] = 6 * ((p[i + 1] - p[i]) / h[i] - (p[i] - p[i - 1]) / h[i - 1])
    M = np.linalg.solve(A, rhs)  # second derivatives at the knots
    per = max(2, n // (m - 1))  # samples per interval, the knots among them
    s = np.append(np.concatenate([np.linspace(t[i], t[i + 1], per, endpoint=False)
                                  for i in range(m - 1)]), t[-1])
    k = np.clip(np.searchsorted(t, s, side="right") - 1, 0, m - 2)
    a, b = (t[k + 1] - s) / h[k], (s - t[k]) / h[k]
    return (a[:, None] * p[k] + b[:, None] * p[k + 1]
            + ((a**3 - a)[:, None] * M[k] + (b**3 - b)[:, None] * M[k + 1]) * (h[k] ** 2)[:, None] / 6)


def distance_to_polyline(x, line, extend_ends=False):
    """Distance of points x (n, 2) to the polyline `line` (m, 2), signed: positive to its left
    walking along it; with extend_ends, the polyline goes on straight along its end tangents."""
    a, d = line[:-1], np.diff(line, axis=0)
    length2 = np.maximum((d**2).sum(axis=1), 1e-300)
    rel = x[:, None, :] - a[None, :, :]
    lo, hi = np.zeros(len(d)), np.ones(len(d))
    if extend_ends:
        lo[0], hi[-1] = -np.inf, np.inf
    t = np.clip((rel * d[None]).sum(axis=2) / length2[None], lo, hi)
    dist = np.linalg.norm(rel - t[:, :, None] * d[None], axis=2)
    j, n = dist.argmin(axis=1), np.arange(len(x))
    cross = d[j, 0] * rel[n, j, 1] - d[j, 1] * rel[n, j, 0]
    return np.where(cross >= 0, 1.0, -1.0) * dist[n, j]


class Obstacle:
    """A rigid obstacle of input.yaml at its final position: signed distance of points (negative:
    inside the obstacle) and a drawing."""

    def __init__(self, spec, shift):
        self.kind = spec.get("type")
        self.shift = np.asarray(spec.get("displacement") or [0, 0], dtype=float) * shift
        if self.kind == "plane":
            n = np.asarray(spec.get("normal") or [0, 1], dtype=float)
            self.normal = n / np.linalg.norm(n)
            self.point = np.asarray(spec.get("point") or [0, 0], dtype=float)
        elif self.kind == "circle":
            self.center = np.asarray(spec.get("center") or [0, 0], dtype=float)
            self.radius = float(spec["radius"])
            self.inside = bool(spec.get("inside", False))
        elif self.kind == "curve":
            self.line = natural_spline(spec["points"])

    def distance(self, x, scale):
        """Signed distance of points x to the obstacle moved by scale × its displacement."""
        x = x - scale * self.shift
        if self.kind == "plane":
            return (x - self.point) @ self.normal
        if self.kind == "circle":
            r = np.linalg.norm(x - self.center, axis=1)
            return self.radius - r if self.inside else r - self.radius
        return distance_to_polyline(x, self.line, extend_ends=True)

    def draw(self, ax, scale, view, label):
        grey = dict(color="0.35", lw=1.6, zorder=4)
        shift = scale * self.shift
        (x0, x1), (y0, y1) = view
        span = max(x1 - x0, y1 - y0)
        if self.kind == "plane":
            p, n = self.point + shift, self.normal
            t = np.array([-n[1], n[0]])
            ends = np.array([p + s * t for s in (-4 * span, 4 * span)])
            ends += (np.array([(x0 + x1) / 2, (y0 + y1) / 2]) - p) @ t * t  # centred on the view
            band = np.vstack([ends, ends[::-1] - 0.03 * span * n])
            ax.add_patch(mpatches.Polygon(band, closed=True, facecolor="0.8", edgecolor="none",
                                          hatch="///", zorder=3))
            ax.plot(ends[:, 0], ends[:, 1], label=label, **grey)
        elif self.kind == "circle":
            c = self.center + shift
            ax.add_patch(mpatches.Circle(c, self.radius, facecolor="none" if self.inside else "0.85",
                                         edgecolor="none", hatch=None if self.inside else "///",
                                         zorder=3))
            a = np.linspace(0, 2 * np.pi, 721)
            ax.plot(c[0] + self.radius * np.cos(a), c[1] + self.radius * np.sin(a), label=label,
                    **grey)
        elif self.kind == "curve":
            line = self.line + shift
            d0, d1 = line[1] - line[0], line[-1] - line[-2]
            line = np.vstack([line[0] - 4 * span * d0 / np.linalg.norm(d0), line,
                              line[-1] + 4 * span * d1 / np.linalg.norm(d1)])
            ax.plot(line[:, 0], line[:, 1], label=label, **grey)


def boundary_loops(cells, body, which, X):
    """The boundary of body `which` in the VTU's sub-cells: the closed loops of point indices
    (sub-cell edges that one sub-cell of the body has; coincident points merged by position)."""
    key = {}
    ids = np.array([key.setdefault(tuple(np.round(p, 9)), i) for i, p in enumerate(X)])
    count, first = Counter(), {}
    for c in cells[body == which]:
        for k in range(4):
            a, d = ids[c[k]], ids[c[(k + 1) % 4]]
            e = (min(a, d), max(a, d))
            count[e] += 1
            first.setdefault(e, (c[k], c[(k + 1) % 4]))
    edges = [first[e] for e, n in count.items() if n == 1]
    nxt = {}
    for a, d in edges:
        nxt.setdefault(ids[a], []).append((a, d))
    loops, used = [], set()
    for start in edges:
        if start in used:
            continue
        loop, e = [], start
        while e not in used:
            used.add(e)
            loop.append(e[0])
            options = [o for o in nxt.get(ids[e[1]], []) if o not in used]
            if not options:
                break
            e = options[0]
        if len(loop) >= 3:
            loops.append(np.array(loop))
    return loops


def penetration(x, scale, obstacles, loops_of, pairs_bodies):
    """The deepest penetration in the drawn configuration x (at magnification `scale`): of a
    body's boundary points into a rigid obstacle of its pairs, or into the other body of a
    two-body pair."""
    deepest = 0.0
    for b, obstacle in obstacles:
        if loops_of[b]:
            pts = x[np.concatenate(loops_of[b])]
            deepest = max(deepest, float(-obstacle.distance(pts, scale).min()))
    for a, b in pairs_bodies:
        for inner, outer in ((a, b), (b, a)):
            if not loops_of[inner] or not loops_of[outer]:
                continue
            pts = x[np.concatenate(loops_of[inner])]
            inside = np.zeros(len(pts), dtype=bool)
            for loop in loops_of[outer]:
                inside ^= mpath.Path(x[loop]).contains_points(pts)
            if inside.any():
                to_boundary = np.min([np.abs(distance_to_polyline(pts[inside], x[np.append(loop, loop[0])]))
                                      for loop in loops_of[outer]], axis=0)
                deepest = max(deepest, float(to_boundary.max()))
    return deepest


def distance_to_loops(pts, x, loops, chunk=512):
    """Unsigned distance of points pts (n, 2) to the nearest of the closed loops (point indices
    into x), in chunks of points (the distances to every segment are held at once)."""
    out = np.full(len(pts), np.inf)
    for loop in loops:
        line = x[np.append(loop, loop[0])]
        for i in range(0, len(pts), chunk):
            d = np.abs(distance_to_polyline(pts[i:i + chunk], line))
            out[i:i + chunk] = np.minimum(out[i:i + chunk], d)
    return out


class ClosedContact:
    """The boundary points that touch a rigid obstacle or the other body of a two-body pair in
    the computed solution (drawn at true scale within `tolerance` of it), and their distance
    to it then. separation(s) is how much farther from it — apart or into it — the drawing at
    magnification s puts them: an interference fit's surfaces start overlapped by the
    interference δ and the solution closes it, so at scale s they are drawn (s - 1) δ apart."""

    def __init__(self, X, u, tolerance, obstacles, loops_of, pairs_bodies):
        self.X, self.u, self.checks = X, u, []
        x = X + u
        for b, obstacle in obstacles:
            if loops_of[b]:
                idx = np.concatenate(loops_of[b])
                d = np.abs(obstacle.distance(x[idx], 1.0))
                self.checks.append((idx[d <= tolerance], d[d <= tolerance], obstacle, None))
        for a, b in pairs_bodies:
            for own, other in ((a, b), (b, a)):
                if loops_of[own] and loops_of[other]:
                    idx = np.concatenate(loops_of[own])
                    d = distance_to_loops(x[idx], x, loops_of[other])
                    self.checks.append((idx[d <= tolerance], d[d <= tolerance], None,
                                        loops_of[other]))

    def separation(self, s):
        """The largest growth of a touching point's distance to what it touches, drawn at s."""
        x = self.X + s * self.u
        worst = 0.0
        for idx, d1, obstacle, loops in self.checks:
            if not len(idx):
                continue
            d = (np.abs(obstacle.distance(x[idx], s)) if obstacle is not None
                 else distance_to_loops(x[idx], x, loops))
            worst = max(worst, float((d - d1).max()))
        return worst


def view_size(X, xlim, ylim):
    """The diagonal of what the plot shows: the model's extent, or the ranges --xlim and --ylim
    give (a zoom on the contact magnifies less and sees a smaller gap)."""
    lo, hi = X.min(axis=0), X.max(axis=0)
    for k, lim in enumerate((xlim, ylim)):
        if lim:
            lo[k], hi[k] = min(lim), max(lim)
    return float(np.linalg.norm(hi - lo))


def choose_scale(X, u, size, obstacles, loops_of, pairs_bodies):
    """The automatic magnification and a note saying why (see --scale): `size` the extent of
    the view the tolerance is a fraction of."""
    umax = np.abs(u).max()
    wanted = 0.05 * size / umax if umax > 0 else 1.0
    if not obstacles and not pairs_bodies:
        return wanted, "5 % of the size"
    tolerance = OVERLAP_TOLERANCE * size
    closed = ClosedContact(X, u, tolerance, obstacles, loops_of, pairs_bodies)

    def depth(s):
        return penetration(X + s * u, s, obstacles, loops_of, pairs_bodies)

    allowed = depth(1.0) + tolerance

    def fits(s):
        return depth(s) <= allowed and closed.separation(s) <= tolerance

    top = max(wanted, 1.0)
    if fits(top):
        return top, "5 % of the size" if top == wanted else "true scale"
    lo, hi = 1.0, top
    for _ in range(40):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if fits(mid) else (lo, mid)
    return lo, ("the largest at which touching bodies neither overlap nor part; 5 % of the "
                f"size: × {wanted:.3g}")


def colour_range(values, points, vmin, vmax, unit):
    """vmin, vmax of the colours, the colour bar's extend and a legend note on clipping."""
    finite = values[np.isfinite(values)]
    notes, lo_clip, hi_clip = [], False, False
    if finite.size:
        p1, p99 = np.percentile(finite, [1, 99])
        spread = max(p99 - p1, 1e-300)
        if vmax is None and finite.max() > p99 + 9 * spread:
            vmax = float(np.percentile(finite, 99.5))
        if vmin is None and finite.min() < p1 - 9 * spread:
            vmin = float(np.percentile(finite, 0.5))
        where = lambda i: f"({points[i][0]:.4g}, {points[i][1]:.4g})"  # noqa: E731
        safe = np.where(np.isfinite(values), values, np.nan)
        if vmax is not None and finite.max() > vmax:
            hi_clip = True
            notes.append(f"colours clipped above {vmax:.4g} {unit}: max {finite.max():.4g} "
                         f"at {where(int(np.nanargmax(safe)))} (undeformed)")
        if vmin is not None and finite.min() < vmin:
            lo_clip = True
            notes.append(f"colours clipped below {vmin:.4g} {unit}: min {finite.min():.4g} "
                         f"at {where(int(np.nanargmin(safe)))} (undeformed)")
    extend = {(False, False): "neither", (True, False): "max", (False, True): "min",
              (True, True): "both"}[(hi_clip, lo_clip)]
    return vmin, vmax, extend, notes


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("vtu", help="a solution.vtu of `hpcontact run` (or steps/step-NNNN.vtu)")
    ap.add_argument("--field", default="von_mises", help="point field to colour by (default %(default)s)")
    ap.add_argument("--scale", type=float, default=0.0,
                    help="displacement magnification; 0: automatic (see below; default)")
    ap.add_argument("--out", help="PNG to write (default: <field>.png beside the .vtu)")
    ap.add_argument("--xlim", type=float, nargs=2, metavar=("A", "B"), help="x range of the view")
    ap.add_argument("--ylim", type=float, nargs=2, metavar=("A", "B"), help="y range of the view")
    ap.add_argument("--vmin", type=float, help="bottom of the colour scale (default: see below)")
    ap.add_argument("--vmax", type=float, help="top of the colour scale (default: see below)")
    ap.add_argument("--units", metavar="LENGTH,FORCE",
                    help="the units the input's numbers are in, e.g. mm,N: labels then say [mm], "
                         "[N/mm²] (hpcontact has no units of its own; default: see below)")
    args = ap.parse_args(argv)
    try:
        X, cell_list, point_data, cell_data = read_vtu(args.vtu)
    except (OSError, ValueError) as e:
        sys.exit(f"plot_field: {e}")
    for name, data in ((args.field, point_data), ("displacement", point_data),
                       ("element", cell_data), ("body", cell_data)):
        if name not in data:
            sys.exit(f"plot_field: {args.vtu}: no DataArray '{name}'"
                     + (f" (point fields: {', '.join(sorted(point_data))})" if data is point_data else ""))
    summary, pairs, body_names, factor = read_run(args.vtu)
    try:
        units = parse_units(args.units) if args.units else units_of(summary)
    except ValueError as e:
        ap.error(str(e))
    u = point_data["displacement"][:, :2]
    cells = np.array(cell_list, dtype=int).reshape(-1, 4)
    element = cell_data["element"].astype(int)
    body = cell_data["body"].astype(int)
    values = point_data[args.field]

    index = {name: i for i, name in enumerate(body_names)}
    loops_of = {b: boundary_loops(cells, body, b, X) for b in sorted(set(body))}
    obstacles, pairs_bodies, drawn_obstacles = [], [], []
    for k, pair in enumerate(pairs):
        spec, b = pair.get("obstacle") or {}, index.get(pair.get("body"))
        if b is None or b not in loops_of:
            continue
        if spec.get("type") == "body":
            other = index.get(spec.get("body"))
            if other in loops_of:
                pairs_bodies.append((b, other))
        elif spec.get("type") in ("plane", "circle", "curve"):
            o = Obstacle(spec, factor)
            obstacles.append((b, o))
            drawn_obstacles.append((k, o))

    size = np.linalg.norm(X.max(axis=0) - X.min(axis=0))
    if args.scale > 0:
        scale, why = args.scale, "--scale"
    else:
        scale, why = choose_scale(X, u, view_size(X, args.xlim, args.ylim), obstacles, loops_of,
                                  pairs_bodies)
    x = X + scale * u
    tri = mtri.Triangulation(x[:, 0], x[:, 1],
                             np.vstack([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]]))
    fig, ax = plt.subplots(figsize=(6.8, 5.4))
    kind = "stress" if args.field in STRESS_FIELDS else "strain" \
        if args.field.startswith(("strain", "gamma")) else None
    unit = axis_label("", kind, units).strip() if kind else ""
    vmin, vmax, extend, notes = colour_range(values, X, args.vmin, args.vmax, unit)
    pc = ax.tripcolor(tri, values, shading="gouraud", cmap="viridis", vmin=vmin, vmax=vmax)
    fig.colorbar(pc, ax=ax, shrink=0.85, extend=extend,
                 label=f"{args.field} {unit}".strip())
    # Element outlines: the sub-cell edges that only one sub-cell of their element has.
    count, ends = Counter(), {}
    for c, e, b in zip(cells, element, body):
        for k in range(4):
            a, d = c[k], c[(k + 1) % 4]
            key = (b, e) + tuple(sorted((tuple(np.round(X[a], 9)), tuple(np.round(X[d], 9)))))
            count[key] += 1
            ends[key] = (a, d)
    for key, n in count.items():
        if n == 1:
            a, d = ends[key]
            ax.plot(x[[a, d], 0], x[[a, d], 1], "-", color="0.15", lw=0.6)
    pad = 0.04 * size
    view = (tuple(args.xlim) if args.xlim else (x[:, 0].min() - pad, x[:, 0].max() + pad),
            tuple(args.ylim) if args.ylim else (x[:, 1].min() - pad, x[:, 1].max() + pad))
    for k, o in drawn_obstacles:
        o.draw(ax, scale, view, f"rigid {o.kind} (contact[{k}])")
    for note in notes:
        ax.add_patch(mpatches.Rectangle((np.nan, np.nan), 0, 0, color="none", label=note))
    ax.set_aspect("equal")
    ax.set_xlim(*view[0])
    ax.set_ylim(*view[1])
    ax.set_xlabel(axis_label("x", "length", units))
    ax.set_ylabel(axis_label("y", "length", units))
    if drawn_obstacles or notes:  # below the axes: it hides no part of the bodies
        ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.13), frameon=False)
    ax.set_title(f"{args.field} on the deformed mesh, displacement × {scale:.3g}\n({why})",
                 fontsize=9)
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(args.vtu), args.field + ".png")
    fig.savefig(out, dpi=100, bbox_inches="tight")
    plt.close(fig)
    drawn = "; ".join(f"rigid {o.kind} (contact[{k}])" for k, o in drawn_obstacles)
    print(f"wrote {out}: {args.field}, displacement × {scale:.4g} ({why})"
          + (f"; obstacles: {drawn}" if drawn else "") + "".join(f"; {n}" for n in notes))
    return 0


if __name__ == "__main__":
    sys.exit(main())
