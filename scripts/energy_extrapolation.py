#!/usr/bin/python3
"""Error estimates from strain energies: the seed's extrapolation of the exact energy from three
discretisations (eq. 4.14), the relative energy-norm error (eq. 4.3) and the algebraic rate β
of a convergence curve. Importable (scripts/neumann_study.py,
tests/cli/test_energy_extrapolation.py) and runnable:

    scripts/energy_extrapolation.py N0 U0 N1 U1 N2 U2     # prints U_ex and the implied β

The model behind eq. 4.14 is the algebraic rate of the error in energy norm (eq. 4.12-4.13):

    U_ex - U_i = k² N_i^(-2β),   i = 0, 1, 2   (N_0 < N_1 < N_2 degrees of freedom)

Eliminating k and β from three such equations leaves one equation for U_ex (eq. 4.14):

    (U_ex - U_2) / (U_ex - U_1) = ((U_ex - U_1) / (U_ex - U_0))^Q,   Q = ln(N_2/N_1) / ln(N_1/N_0)

(the seed writes Q = log(N_{p-1}/N_p) / log(N_{p-2}/N_{p-1}), the same number). It has a root
beyond U_2 if and only if the energies are strictly monotone and their increments shrink fast
enough for a positive β: (U_2 - U_1)/(U_1 - U_0) < Q. The energies may rise (a displacement
method under loads: U_FE < U_ex, eq. 4.11) or fall (prescribed displacements: U_FE > U_ex);
the root lies on the far side of U_2 either way.
"""
import math
import sys

__all__ = ["ExtrapolationError", "extrapolate_energy", "implied_beta", "relative_energy_error",
           "fit_beta", "fit_power_law"]


class ExtrapolationError(ValueError):
    """The three energies admit no extrapolation (not monotone, or no root of eq. 4.14)."""


def _residual(y, r, q):
    """Eq. 4.14 in y = ln z, z = |U_ex - U_2| / |U_2 - U_1| > 0, r = |U_2 - U_0| / |U_2 - U_1|:
    f = ln z - (1 + Q) ln(z + 1) + Q ln(z + r) = Q ln(1 + r/z) - (1 + Q) ln(1 + 1/z), written
    with log1p so that it keeps its digits for large z, and df/dy. f -> -inf as z -> 0 and
    f -> (Q (r - 1) - 1)/z as z -> inf, positive when a root exists."""
    z = math.exp(y)
    f = q * math.log1p(r / z) - (1 + q) * math.log1p(1 / z)
    df = (1 + q) / (z + 1) - q * r / (z + r)
    return f, df


def extrapolate_energy(dofs, energies, tol=1e-15, max_iterations=200):
    """U_ex from three (N, U) pairs by eq. 4.14 (seed §4.9), Newton's method on ln|U_ex - U_2|
    safeguarded by bisection inside a bracket of the root.

    dofs: three strictly increasing degree-of-freedom counts N_0 < N_1 < N_2.
    energies: the three strain energies, strictly monotone (rising or falling).
    Returns U_ex. Raises ExtrapolationError, naming the values, when the energies are not
    strictly monotone or decrease too slowly for eq. 4.14 to have a root (no positive β)."""
    if len(dofs) != 3 or len(energies) != 3:
        raise ExtrapolationError(f"need three (dofs, energy) pairs, got {len(dofs)} dofs and "
                                 f"{len(energies)} energies")
    n0, n1, n2 = (float(n) for n in dofs)
    u0, u1, u2 = (float(u) for u in energies)
    if not 0 < n0 < n1 < n2:
        raise ExtrapolationError(f"dofs must be positive and strictly increasing, got {list(dofs)}")
    sign = 1.0 if u1 > u0 else -1.0
    d1, d0 = sign * (u2 - u1), sign * (u2 - u0)   # distances of U_1, U_0 from U_2, > 0 if monotone
    if not (sign * (u1 - u0) > 0 and d1 > 0):
        raise ExtrapolationError(f"energies must be strictly monotone, got {list(energies)}")
    q = math.log(n2 / n1) / math.log(n1 / n0)
    r = d0 / d1
    if not q * (r - 1) > 1:
        raise ExtrapolationError(
            f"eq. 4.14 has no solution for dofs {list(dofs)}, energies {list(energies)}: the "
            f"increment ratio (U2-U1)/(U1-U0) = {1 / (r - 1):.6g} is not below "
            f"Q = ln(N2/N1)/ln(N1/N0) = {q:.6g}, so no positive rate beta fits")
    # Bracket the root in y = ln z: f < 0 for small z, f > 0 for large z.
    lo, hi = -1.0, 1.0
    while _residual(lo, r, q)[0] >= 0:
        lo -= 2.0
        if lo < -700:
            raise ExtrapolationError(
                f"eq. 4.14: no bracket below the root for energies {list(energies)}")
    while _residual(hi, r, q)[0] <= 0:
        hi += 2.0
        if hi > 700:
            raise ExtrapolationError(
                f"eq. 4.14: the root lies beyond |U_ex - U_2| = e^700 |U_2 - U_1| for energies "
                f"{list(energies)} (beta nearly zero)")
    y = 0.5 * (lo + hi)
    for _ in range(max_iterations):
        f, df = _residual(y, r, q)
        if f == 0:
            break
        if f < 0:
            lo = y
        else:
            hi = y
        y_new = y - f / df if df != 0 else math.nan
        if not lo < y_new < hi:          # Newton left the bracket (or df = 0): bisect instead
            y_new = 0.5 * (lo + hi)
        done = abs(y_new - y) <= tol * max(1.0, abs(y)) or hi - lo <= tol * max(1.0, abs(y))
        y = y_new
        if done:
            break
    else:
        raise ExtrapolationError(f"eq. 4.14: Newton did not converge for energies {list(energies)}")
    return u2 + sign * d1 * math.exp(y)


def implied_beta(dofs, energies, u_ex):
    """The rate β of eq. 4.13 that the last two of three energies imply with U_ex."""
    n1, n2 = dofs[1], dofs[2]
    e1, e2 = abs(u_ex - energies[1]), abs(u_ex - energies[2])
    return -0.5 * math.log(e2 / e1) / math.log(n2 / n1)


def relative_energy_error(u, u_ref):
    """Relative error in energy norm in percent, 100·sqrt(|U_ref - U| / U_ref) (seed eq. 4.3).
    u_ref must be positive."""
    if not u_ref > 0:
        raise ValueError(f"the reference energy must be positive, got {u_ref}")
    return 100.0 * math.sqrt(abs(u_ref - u) / u_ref)


def fit_power_law(dofs, errors):
    """Least-squares fit of ln e = ln k - β ln N; returns (β, k). Needs at least two points
    with distinct N and every error positive."""
    if len(dofs) != len(errors) or len(dofs) < 2:
        raise ValueError(
            f"need at least two (dofs, error) pairs, got {len(dofs)} and {len(errors)}")
    if any(not e > 0 for e in errors):
        raise ValueError(f"errors must be positive for a log-log fit, got {list(errors)}")
    xs = [math.log(n) for n in dofs]
    ys = [math.log(e) for e in errors]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    if sxx == 0:
        raise ValueError(f"dofs must not all be equal, got {list(dofs)}")
    slope = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx
    return -slope, math.exp(my - slope * mx)


def fit_beta(dofs, errors):
    """Algebraic rate β of error ∝ N^-β: minus the least-squares slope of ln(error) against
    ln(dofs)."""
    return fit_power_law(dofs, errors)[0]


def main(argv=None):
    import argparse
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog=__doc__.split("\n\n", 1)[1])
    for i in range(3):
        ap.add_argument(f"N{i}", type=float, help=f"degrees of freedom of discretisation {i}"
                        + (" (N0 < N1 < N2)" if i == 0 else ""))
        ap.add_argument(f"U{i}", type=float, help="its strain energy")
    args = ap.parse_args(argv)
    dofs = [args.N0, args.N1, args.N2]
    energies = [args.U0, args.U1, args.U2]
    u_ex = extrapolate_energy(dofs, energies)
    print(f"U_ex = {u_ex!r}  (beta = {implied_beta(dofs, energies, u_ex):.4f}; "
          f"e_2 = {relative_energy_error(energies[2], u_ex):.6g} %)")


if __name__ == "__main__":
    sys.exit(main())
