#!/usr/bin/python3
"""The relative difference of the von Mises stress between two runs on the same mesh (e.g.
p = 10 against p = 20, seed Fig. 5.28 and 5.35), as VTU for ParaView and as PNG.

usage: von_mises_difference.py A.vtu B.vtu --out DIR [--cap PERCENT]

A and B are solution.vtu files of `hpcontact run` written with the same mesh and the same
`output.vtu_subdivisions` (e.g. `--set output.vtu_subdivisions=16`), so that their points
coincide. The difference 100·|σ_vM(A) − σ_vM(B)| / S (B is the better run; S = --scale, by
default the 99.9th percentile of σ_vM(B): a corner of 180° between two edges on one circle, as
at node 3 of the Hertz 2×2 mesh, makes the map singular there and the sampled stress of a
high degree unbounded at that one point, which must not set the scale) is
written as the point field von_mises_difference_percent into DIR/von-mises-difference.vtu
(a copy of B) and plotted into DIR/von-mises-difference.png with the colour scale capped at
--cap percent (default 0.1, the seed's). Exits 1 with a message if the points do not coincide
(within 1e-6 of the model size; rp meshes of two degrees differ by their relocated nodes, and
the largest distance is printed). The PNG is drawn on the undeformed mesh; its axes are in the
input's length units (summary.json's "units" beside B.vtu where it names them), and where
differences exceed --cap the colour bar shows an arrow and the legend the share of points
clipped and the maximum.
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.tri as mtri  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import axis_label, read_vtu, script_parser, units_of  # noqa: E402


def read_solution(path):
    """Points, cells and von Mises stress of a solution.vtu; SystemExit naming what is missing."""
    try:
        points, cells, point_data, _ = read_vtu(path)
    except (OSError, ValueError) as e:
        raise SystemExit(str(e))
    if "von_mises" not in point_data:
        raise SystemExit(f"{path}: no DataArray 'von_mises' (not a solution.vtu of hpcontact?)")
    return points, cells, point_data["von_mises"]


def main(argv=None):
    ap = script_parser(__doc__)
    ap.add_argument("a", metavar="A.vtu", help="solution.vtu of the run to measure")
    ap.add_argument("b", metavar="B.vtu", help="solution.vtu of the better run (the reference)")
    ap.add_argument("--out", required=True, metavar="DIR", help="folder for the VTU and the PNG")
    ap.add_argument("--cap", type=float, default=0.1,
                    help="top of the colour scale in percent (default %(default)s)")
    ap.add_argument("--scale", type=float,
                    help="the stress the difference is relative to (default: 99.9th percentile "
                         "of B's von Mises stress)")
    args = ap.parse_args(argv)
    (xa, _, va), (xb, cells, vb) = read_solution(args.a), read_solution(args.b)
    if xa.shape != xb.shape:
        print(f"{args.a}, {args.b}: different point counts ({len(xa)} and {len(xb)}): write both "
              "with the same mesh and output.vtu_subdivisions", file=sys.stderr)
        return 1
    size = np.ptp(xb, axis=0).max()
    mismatch = np.abs(xa - xb).max()
    if mismatch > 1e-6 * size:
        print(f"{args.a}, {args.b}: the points differ by up to {mismatch:.3g} (model size "
              f"{size:.3g}): not the same mesh", file=sys.stderr)
        return 1
    scale = args.scale or float(np.percentile(vb, 99.9))
    diff = 100 * np.abs(va - vb) / scale
    os.makedirs(args.out, exist_ok=True)
    # The VTU: B with the difference added to its point data.
    field = ('<DataArray type="Float64" Name="von_mises_difference_percent" format="ascii">\n'
             + "\n".join(f"{v:.10g}" for v in diff) + "\n</DataArray>\n")
    with open(args.b) as f:
        vtu = f.read().replace("</PointData>", field + "</PointData>", 1)
    vtu_path = os.path.join(args.out, "von-mises-difference.vtu")
    with open(vtu_path, "w") as f:
        f.write(vtu)
    # The PNG: the cells (quads) as two triangles each.
    tris = []
    for c in cells:
        if len(c) == 4:
            tris += [[c[0], c[1], c[2]], [c[0], c[2], c[3]]]
        elif len(c) == 3:
            tris.append(list(c))
    tri = mtri.Triangulation(xb[:, 0], xb[:, 1], tris)
    units = None
    summary_path = os.path.join(os.path.dirname(os.path.abspath(args.b)), "summary.json")
    if os.path.isfile(summary_path):
        with open(summary_path) as f:
            units = units_of(json.load(f))
    fig, ax = plt.subplots(figsize=(6.5, 6.4))
    share = 100 * np.mean(diff > args.cap)
    im = ax.tripcolor(tri, np.minimum(diff, args.cap), shading="gouraud", cmap="jet",
                      vmin=0, vmax=args.cap)
    fig.colorbar(im, ax=ax, extend="max" if share > 0 else "neither",
                 label=f"|Δσ_vM| / {scale:.5g} [%]")
    if share > 0:
        ax.plot([], [], " ", label=f"colours clipped above {args.cap:g} %: {share:.1f} % of the "
                                   f"points, max {diff.max():.3g} %")
        ax.legend(fontsize=7.5, loc="upper center", bbox_to_anchor=(0.5, -0.1), frameon=False)
    ax.set_xlabel(axis_label("x", "length", units))
    ax.set_ylabel(axis_label("y", "length", units))
    ax.set_aspect("equal")
    ax.set_title(f"{os.path.basename(os.path.dirname(os.path.abspath(args.a)))} vs "
                 f"{os.path.basename(os.path.dirname(os.path.abspath(args.b)))}: max "
                 f"{diff.max():.3g} %", fontsize=10)
    fig.tight_layout()
    png_path = os.path.join(args.out, "von-mises-difference.png")
    fig.savefig(png_path, dpi=110)
    plt.close(fig)
    print(f"wrote {vtu_path}, {png_path}; scale {scale:.6g}; max difference {diff.max():.4g} % "
          f"at ({xb[diff.argmax(), 0]:.4g}, {xb[diff.argmax(), 1]:.4g}); {share:.1f} % of the "
          f"points above {args.cap:g} %")
    return 0


if __name__ == "__main__":
    sys.exit(main())
