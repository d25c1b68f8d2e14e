#!/usr/bin/python3
"""Plots the contact pressure of a run (its pressure.csv) against Hertz and Shtayerman.

usage: plot_pressure.py RESULTS_DIR [OUT.png]
Reads RESULTS_DIR/pressure.csv and RESULTS_DIR/summary.json; writes RESULTS_DIR/pressure.png
(p/p0 over x/b, like the seed's Fig. 5.11-5.14).
"""
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hpc_run import read_columns  # noqa: E402


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    folder = argv[1]
    out = argv[2] if len(argv) > 2 else os.path.join(folder, "pressure.png")
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    contact = summary.get("contact", {})
    if "hertz_half_width" not in contact:
        print(f"{folder}: summary.json has no pressure comparison (contact[].compare)",
              file=sys.stderr)
        return 1
    b, p0 = contact["hertz_half_width"], contact["hertz_peak_pressure"]
    cols = read_columns(os.path.join(folder, "pressure.csv"))
    xb = [x / b for x in cols["x"]]
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(xb, [p / p0 for p in cols["hertz"]], "k--", lw=1.2, label="Hertz")
    ax.plot(xb, [p / p0 for p in cols["shtayerman"]], "k:", lw=1.5, label="Shtayerman")
    # the pressure the method carries: the multiplier (exact enforcement) or the penalty traction
    method = "pressure_multiplier" if "pressure_multiplier" in cols else "pressure_penalty"
    ax.plot(xb, [p / p0 for p in cols[method]], color="0.55", lw=0.9,
            label="FE, multiplier" if method == "pressure_multiplier" else "FE, penalty traction")
    ax.plot(xb, [p / p0 for p in cols["pressure_from_stress"]], "C0", lw=1.8,
            label="FE, from stresses")
    ax.set_xlabel("x / b (Hertz)")
    ax.set_ylabel("p / p0 (Hertz)")
    ax.set_xlim(0, 1.5)
    ax.set_ylim(-0.1, 1.3)
    ax.grid(alpha=0.3)
    ax.set_title(f"{summary['case']}: {summary['method']}-version, {summary['dofs']} DOF, "
                 f"e_L2 vs Shtayerman {contact['e_L2_shtayerman_percent']:.2f} %", fontsize=10)
    ax.legend(loc="lower left", fontsize=9)
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
