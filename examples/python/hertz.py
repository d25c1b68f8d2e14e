#!/usr/bin/python3
"""The Hertz benchmark through the Python module: run examples/hertz/p8.yaml, plot the contact
pressure p/p0 over x/b against Hertz and Shtayerman (as scripts/plot_pressure.py does from a
run's files), and save the plot as a PNG.

usage: PYTHONPATH=build/python /usr/bin/python3 examples/python/hertz.py [--out results/python]
           [--problem examples/hertz/p8.yaml] [--set key.path=value ...]
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import hpcontact  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--problem", default=os.path.join(ROOT, "examples", "hertz", "p8.yaml"),
                        help="problem file with a contact[].compare section (default %(default)s)")
    parser.add_argument("--out", default="results/python", help="folder of the PNG")
    parser.add_argument("--set", action="append", default=[], metavar="KEY=VALUE",
                        help="override an input value (repeatable)")
    args = parser.parse_args(argv)

    try:
        problem = hpcontact.Problem.from_file(args.problem, set=args.set)
        result = problem.run()
    except hpcontact.Error as e:
        print(f"hertz.py: {e}", file=sys.stderr)
        return 1
    summary = result.summary
    contact = summary["contact"]
    curve = result.pressure_curve()
    if curve is None:
        print(f"hertz.py: {args.problem} has no contact compare section", file=sys.stderr)
        return 1
    b, p0 = contact["hertz_half_width"], contact["hertz_peak_pressure"]
    points = result.contact()  # contact.csv: the multiplier nodes (penalty: the Gauss points)
    print(f"{problem.case}: {summary['dofs']} DOF, resultant {contact['resultant'][1]:.1f} N, "
          f"p_max {contact['p_max']:.0f}, half width {contact['half_width']:.4f} "
          f"(Hertz b = {b:.4f}), e_L2 vs Shtayerman {contact['e_L2_shtayerman_percent']:.2f} %")

    fig, ax = plt.subplots(figsize=(7, 4.5))
    xb = curve["x"] / b
    ax.plot(xb, curve["hertz"] / p0, "k--", lw=1.2, label="Hertz")
    ax.plot(xb, curve["shtayerman"] / p0, "k:", lw=1.5, label="Shtayerman")
    if "reference" in curve:
        ax.plot(xb, curve["reference"] / p0, color="C2", lw=1.0, label="reference (overkill)")
    ax.plot(points["X"] / b, points["pressure"] / p0, ".", color="0.6", ms=3,
            label="FE, contact.csv pressure (multiplier at its nodes)")
    ax.plot(xb, curve["pressure_from_stress"] / p0, "C0", lw=1.8, label="FE, from stresses")
    ax.axvline(contact["half_width"] / b, color="C3", lw=0.8, alpha=0.7,
               label="FE end of the contact zone")
    ax.set_xlabel("x / b (Hertz)")
    ax.set_ylabel("p / p0 (Hertz)")
    ax.set_xlim(0, 1.5)
    ax.set_ylim(-0.1, 1.3)
    ax.grid(alpha=0.3)
    ax.set_title(f"{summary['case']}: {summary['method']}-version, {summary['dofs']} DOF, "
                 f"e_L2 vs Shtayerman {contact['e_L2_shtayerman_percent']:.2f} %", fontsize=10)
    ax.legend(loc="upper right", fontsize=9)
    fig.tight_layout()
    os.makedirs(args.out, exist_ok=True)
    png = os.path.join(args.out, "hertz-pressure.png")
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
