#!/usr/bin/python3
"""Checks of the derivation behind src/hpcontact/analytic/pin_in_hole.cpp (Persson's pin in a hole).

1. Michell's compliances (C1): the radial rim displacement of a disc and of a hole in an infinite
   plate under the pressure cos(n theta), from the Airy functions r^m cos(n theta) (sympy).
2. The body-force load: a uniform body force on the disc, balanced by the pressure
   (P/(pi R)) cos(theta), moves the rim radially by a multiple of cos(theta) only (sympy).
3. The kernel in closed form (K1) against its Fourier series.
4. The collocation's answer against a second, crude method: piecewise-linear pressure,
   collocation at its nodes, kernel integrals by adaptive quadrature, Richardson-extrapolated.
Each prints what it compares; the script exits 1 if a comparison fails.
"""
import argparse
import sys

import numpy as np
import sympy as sp
from scipy.integrate import quad

failures = []


def expect(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


r, G, kap = sp.symbols("r G kappa", positive=True)
n = sp.symbols("n", integer=True, positive=True)


def michell(m):
    """sigma_rr, sigma_rtheta, U, V of phi = r^m cos(n theta) (u_r = U cos, u_theta = V sin)."""
    srr = (m - n**2) * r**(m - 2)
    srt = n * (m - 1) * r**(m - 2)
    U = ((kap + 1) * (m - n**2) - (3 - kap) * m * (m - 1)) / (8 * G * (m - 1)) * r**(m - 1)
    V = (((kap + 1) * m * (m - 1) - (3 - kap) * (m - n**2)) * r**(m - 1) / (8 * G) - U) / n
    # U from eps_rr, V from eps_thth; the shear strain must then agree with sigma_rtheta / G
    assert sp.simplify(-n * U / r + sp.diff(V, r) - V / r - srt / G) == 0
    return srr, srt, U, V


def check_compliances():
    """1. Michell's compliances (C1) of the disc and of the hole."""
    R = sp.symbols("R", positive=True)
    A, B = sp.symbols("A B")
    for name, ms, sign, expected in [
            ("disc", (n, n + 2), -1, 1 / (n - 1) + kap / (n + 1)),
            ("hole", (-n, 2 - n), 1, kap / (n - 1) + 1 / (n + 1))]:
        t0, t1 = michell(ms[0]), michell(ms[1])
        sol = sp.solve([(A * t0[0] + B * t1[0]).subs(r, R) + 1, (A * t0[1] + B * t1[1]).subs(r, R)],
                       [A, B])
        u = (A * t0[2] + B * t1[2]).subs(sol).subs(r, R)
        expect(sp.simplify(sign * u * 4 * G / R - expected) == 0,
               f"{name}: u_r = {'+' if sign > 0 else '-'}(R p/4G)({expected})")



def check_body_force():
    """2. A uniform body force moves the disc's rim radially by a multiple of cos(theta) only."""
    R = sp.symbols("R", positive=True)
    x, y, th, b = sp.symbols("x y theta b", real=True)
    lam = G * (3 - kap) / (kap - 1)  # plane strain
    c = sp.symbols("c")
    c1 = sp.solve(2 * G * c + (lam + G) * 2 * c + b, c)[0]  # u = (c x^2, 0) solves Navier with b
    coeffs = sp.symbols("a0:18")
    monomials = [x**i * y**j for i in range(4) for j in range(4) if 1 <= i + j <= 3]
    hx = sum(coeffs[k] * monomials[k] for k in range(9))
    hy = sum(coeffs[9 + k] * monomials[k] for k in range(9))
    ux, uy = c1 * x**2 + hx, hy
    exx, eyy = sp.diff(ux, x), sp.diff(uy, y)
    exy = (sp.diff(ux, y) + sp.diff(uy, x)) / 2
    sxx = lam * (exx + eyy) + 2 * G * exx
    syy = lam * (exx + eyy) + 2 * G * eyy
    sxy = 2 * G * exy
    eqs = []
    for e in [sp.diff(sxx, x) + sp.diff(sxy, y) + b, sp.diff(sxy, x) + sp.diff(syy, y)]:
        eqs += sp.Poly(sp.expand(e), x, y).coeffs()
    X, Y = R * sp.cos(th), R * sp.sin(th)
    p1 = b * R  # P/(pi R) with P = b pi R^2
    tx = (sxx * sp.cos(th) + sxy * sp.sin(th)).subs({x: X, y: Y}) + p1 * sp.cos(th)**2
    ty = (sxy * sp.cos(th) + syy * sp.sin(th)).subs({x: X, y: Y}) + p1 * sp.cos(th) * sp.sin(th)
    for f in (tx, ty):
        f = sp.expand(sp.expand_trig(f))
        for k in range(5):
            eqs += [sp.integrate(f * sp.cos(k * th), (th, 0, 2 * sp.pi)),
                    sp.integrate(f * sp.sin(k * th), (th, 0, 2 * sp.pi))]
    sol = sp.solve(eqs, coeffs, dict=True)[0]
    ur = sp.expand(((ux * sp.cos(th) + uy * sp.sin(th)).subs({x: X, y: Y})).subs(sol))
    modes = [sp.simplify(sp.integrate(ur * sp.cos(k * th), (th, 0, 2 * sp.pi)) / sp.pi)
             for k in range(5)]
    expect(all(modes[k] == 0 for k in (0, 2, 3, 4)),
           f"body force: the rim's u_r modes 0..4 are {modes} (only cos theta)")



def check_kernel():
    """3. The kernel in closed form (K1) against its Fourier series."""
    beta = 0.3
    nn = np.arange(2, 4000000)
    for xv in [0.1, 0.7, 2.0, 3.5, 5.9, -1.3, -4.0]:
        series = np.sum((nn + beta) / (nn**2 - 1.0) * np.cos(nn * xv))
        closed = (-np.cos(xv) * np.log(abs(2 * np.sin(xv / 2)))
                  + beta / 2 * (xv * np.sin(xv) - np.pi * np.sin(abs(xv)))
                  - (1 - beta) / 2 * (1 + np.cos(xv) / 2))
        expect(abs(series - closed) < 1e-6, f"kernel at x = {xv}: series {series:.8f}, closed {closed:.8f}")




def crude_force(eps, R, dR, E_star, beta, L0, m):
    """P for the half-angle eps: hat functions on m intervals of [0, eps], collocation at nodes."""
    def kernel(xv):
        if xv == 0:
            return 0.0
        S = (-np.cos(xv) * np.log(abs(2 * np.sin(xv / 2)))
             + beta / 2 * (xv * np.sin(xv) - np.pi * np.sin(abs(xv)))
             - (1 - beta) / 2 * (1 + np.cos(xv) / 2))
        return (2 * R / E_star * S + L0 / 2) / np.pi
    nodes = np.linspace(0, eps, m + 1)
    h = eps / m
    M = np.zeros((m + 1, m + 1))
    for i in range(m + 1):
        for j in range(m):
            for sgn in ([1] if j == 0 else [1, -1]):
                lo, hi = max(-eps, sgn * nodes[j] - h), min(eps, sgn * nodes[j] + h)
                f = lambda ph: max(0, 1 - abs(sgn * ph - nodes[j]) / h) * kernel(nodes[i] - ph)
                pts = [nodes[i]] if lo < nodes[i] < hi else None
                M[i, j] += quad(f, lo, hi, points=pts, limit=200)[0]
        M[i, m] = -np.cos(nodes[i])
    p = np.r_[np.linalg.solve(M, -dR * np.ones(m + 1))[:m], 0]
    return R * 2 * np.sum((p[1:] * np.cos(nodes[1:]) + p[:-1] * np.cos(nodes[:-1])) / 2 * h)



def check_against_crude_method():
    """4. The collocation's P at eps = 1 (steel on steel) against the crude method."""
    # steel on steel, R1 = 10, dR = 0.01: E* = E/(2(1 - nu^2)), beta = 0, Lambda_0 = R/E*
    E_star = 210000 / (2 * (1 - 0.09))
    P40, P80 = (crude_force(1.0, 10.0, 0.01, E_star, 0.0, 10.0 / E_star, m) for m in (40, 80))
    extrapolated = (2 * P80 - P40) / (E_star * 0.01)
    expect(abs(extrapolated / 1.56010321717741 - 1) < 2e-4,
           f"P/(E* dR) at eps = 1: crude method extrapolated {extrapolated:.6f}, collocation "
           "1.56010321717741 (PinInHoleContact)")



def main(argv=None):
    argparse.ArgumentParser(description=__doc__,
                            formatter_class=argparse.RawDescriptionHelpFormatter).parse_args(argv)
    check_compliances()
    check_body_force()
    check_kernel()
    check_against_crude_method()
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
