#!/usr/bin/python3
"""Draws one field of a solution.vtu (written by `hpcontact run`) on the deformed mesh, with the
element outlines: a quick look without ParaView.

usage: plot_field.py RESULTS_DIR/solution.vtu [--field von_mises] [--scale 0] [--out FILE.png]
       [--xlim A B] [--ylim A B] [--vmax V]

--field: a point field of the file (von_mises, sigma_xx, sigma_yy, sigma_xy, sigma_zz,
principal_1, principal_2, strain_xx, strain_yy, gamma_xy). --scale: magnification of the
displacement (0: automatic, the largest displacement drawn as 5 % of the model size; 1: true
scale). --vmax: top of the colour scale; by default the largest value, unless it exceeds ten
times the 99th percentile (a stress singularity, e.g. at an element corner whose blending map
degenerates): then the 99.5th percentile, and the title gives the maximum and where it is.
Writes FILE.png (default: von_mises.png next to the .vtu, named after the field).
"""
import argparse
import os
import sys
from collections import Counter

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_vtu  # noqa: E402


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("vtu")
    ap.add_argument("--field", default="von_mises")
    ap.add_argument("--scale", type=float, default=0.0)
    ap.add_argument("--out")
    ap.add_argument("--xlim", type=float, nargs=2)
    ap.add_argument("--ylim", type=float, nargs=2)
    ap.add_argument("--vmax", type=float)
    args = ap.parse_args(argv)
    try:
        X, cell_list, point_data, cell_data = read_vtu(args.vtu)
    except (OSError, ValueError) as e:
        sys.exit(str(e))
    for name, data in ((args.field, point_data), ("displacement", point_data),
                       ("element", cell_data), ("body", cell_data)):
        if name not in data:
            sys.exit(f"{args.vtu}: no DataArray '{name}'")
    u = point_data["displacement"][:, :2]
    cells = np.array(cell_list, dtype=int).reshape(-1, 4)
    element = cell_data["element"].astype(int)
    body = cell_data["body"].astype(int)
    values = point_data[args.field]

    size = np.linalg.norm(X.max(axis=0) - X.min(axis=0))
    umax = np.abs(u).max()
    scale = args.scale if args.scale > 0 else (0.05 * size / umax if umax > 0 else 1.0)
    x = X + scale * u
    tri = mtri.Triangulation(x[:, 0], x[:, 1],
                             np.vstack([cells[:, [0, 1, 2]], cells[:, [0, 2, 3]]]))
    fig, ax = plt.subplots(figsize=(6.4, 5.2))
    finite = values[np.isfinite(values)]
    vmax, clipped = args.vmax, ""
    if vmax is None and finite.size and finite.max() > 10 * max(np.percentile(finite, 99), 1e-300):
        vmax = np.percentile(finite, 99.5)
        at = X[np.nanargmax(np.where(np.isfinite(values), values, -np.inf))]
        clipped = f"\ncolours clipped at {vmax:.4g}; max {finite.max():.4g} at ({at[0]:.4g}, {at[1]:.4g})"
    pc = ax.tripcolor(tri, values, shading="gouraud", cmap="viridis", vmax=vmax)
    fig.colorbar(pc, ax=ax, shrink=0.85, label=args.field)
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
    ax.set_aspect("equal")
    if args.xlim:
        ax.set_xlim(*args.xlim)
    if args.ylim:
        ax.set_ylim(*args.ylim)
    ax.set_title(f"{args.field}, displacement x {scale:.3g}{clipped}", fontsize=10)
    fig.tight_layout()
    out = args.out or os.path.join(os.path.dirname(args.vtu), args.field + ".png")
    fig.savefig(out, dpi=100, bbox_inches="tight")
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
