#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Local exponents of the traction at full coupling (docs/formulation.md 8(l)).

Three parts, each printing its numbers:
  identity  the Cauchy identity of Jacobi weights that a shifted-exponent collocation would rest
            on, (1/pi) PV int w P_n^(a,b)/(tau - t) = cot(pi a) w P_n^(a,b) - (2/sin(pi a)) P_{n+1}^(-a,-b),
            a + b = 1, checked by QUADPACK's Cauchy-weight rule (scipy) against Jacobi polynomials;
  fits      log-log slopes of the program's tractions next to the contact edges and the zone
            ends, at full coupling and (as the control) at Johnson's level, against the exponents
            derived in 8(l): 1/2 -+ eps at the edges, 1/2 - eps at an exit, 3/2 + eps at an entry,
            eps = arctan(sigma beta_D f)/pi, and the one-sided kink B (r - c)_+^(1/2 - eps) of p
            at an exit, B = beta_D A / ((1 + k^2) sin(pi (1/2 - eps))) with q ~ A (c - r)^(1/2 - eps);
  ends      the convergence of the zone ends in n at full coupling.
The variants of 8(l) that take q out of (D1) or G were a local patch of the alternation, not this script.
Needs the Python module (PYTHONPATH=build/python) and scipy. Slow (minutes): not a test.
Usage: coupled_exponents.py [identity] [fits] [ends] [--n N] [--strong]
"""
import json
import math
import sys

import warnings

import numpy as np

warnings.simplefilter("ignore")  # QUADPACK's round-off notes at 1e-14: the identity's residual is printed


def identity():
    from scipy.integrate import quad
    from scipy.special import eval_jacobi
    worst = 0.0
    for eps in (0.0, -0.0022891, -0.047394, 0.2):
        a, b = 0.5 - eps, 0.5 + eps           # exit exponent a at t = 1, entry b at t = -1
        for n in (0, 1, 2, 5, 9):
            for t in (-0.83, -0.2, 0.37, 0.91):
                g = lambda x: (1 - x) ** a * (1 + x) ** b * eval_jacobi(n, a, b, x)
                pv = quad(g, -1, 1, weight="cauchy", wvar=t, epsabs=1e-14, epsrel=1e-13, limit=400)[0] / math.pi
                lhs = pv - math.cos(math.pi * a) / math.sin(math.pi * a) * g(t)
                rhs = -2.0 / math.sin(math.pi * a) * eval_jacobi(n + 1, -a, -b, t)
                worst = max(worst, abs(lhs - rhs))
    print(f"identity: largest |lhs - rhs| over eps, n = 0..9, four t: {worst:.2e}")
    # Index +1 (weight 1/w), the identity behind the inversion p = (k h - w H[h/w]) / (1 + k^2) of
    # H[p] + k p = h, cot(pi a) = -k: H[P_m^(-a,-b) / w] = -cot(pi a) P_m^(-a,-b) / w + P_{m-1}^(a,b) / (2 sin(pi a)),
    # in theta = arccos(tau) (the end singularities theta^(-2 eps) are integrable there).
    worst = 0.0
    for eps in (-0.0022891, -0.047394, 0.2):
        a, b = 0.5 - eps, 0.5 + eps
        for m in (1, 2, 6):
            for t in (-0.6, 0.15, 0.8):
                th0 = math.acos(t)
                h = lambda x: (1 - x) ** -a * (1 + x) ** -b * eval_jacobi(m, -a, -b, x)

                def g(th):  # h(cos th) sin th (th - th0) / (cos th - t), half angles for 1 -+ cos th
                    sn, cs = math.sin(th / 2), math.cos(th / 2)
                    w = (2 * sn * sn) ** -a * (2 * cs * cs) ** -b * eval_jacobi(m, -a, -b, math.cos(th))
                    if abs(th - th0) < 1e-9:
                        return -w * math.sin(th) / math.sin(th0)
                    return w * math.sin(th) * (th - th0) / (math.cos(th) - t)
                # the end pieces left out, below 1e-14 wide, weigh below 1e-13 (integrand ~ th^(-2|eps|))
                pv = quad(g, 1e-14, math.pi - 1e-14, weight="cauchy", wvar=th0, epsabs=1e-13, epsrel=1e-12,
                          limit=800)[0] / math.pi
                rhs = -math.cos(math.pi * a) / math.sin(math.pi * a) * h(t) + eval_jacobi(m - 1, a, b, t) / (2 * math.sin(math.pi * a))
                worst = max(worst, abs(pv - rhs))
    print(f"identity, index +1: largest |lhs - rhs|: {worst:.2e}")
    # The discrete form: Gauss-Jacobi nodes t_k (weights W_k) of P_n^(a,b), collocation points x_m the
    # n + 1 zeros of P_{n+1}^(-a,-b): (1/pi) sum W_k psi(t_k) / (t_k - x_m) equals the left side above
    # at x_m for every psi of degree <= n - 1 (as (4.6)-(4.7) do for a = b = 1/2).
    from scipy.special import roots_jacobi
    worst = 0.0
    for eps in (0.0, -0.0022891, -0.047394, 0.2):
        a, b = 0.5 - eps, 0.5 + eps
        n = 12
        tk, Wk = roots_jacobi(n, a, b)
        xm, _ = roots_jacobi(n + 1, -a, -b)
        for j in range(n):
            disc = np.array([np.sum(Wk * eval_jacobi(j, a, b, tk) / (tk - x)) / math.pi for x in xm])
            exact = -2.0 / math.sin(math.pi * a) * eval_jacobi(j + 1, -a, -b, xm)
            worst = max(worst, float(np.max(np.abs(disc - exact))))
    print(f"identity, discrete (n = 12, degrees 0..11 at the 13 collocation points): largest error {worst:.2e}")


def scene(beta, f, Q, coupling):
    import roughroll
    return roughroll.Scene(friction=f, Q=Q, beta_d=beta, coupling=coupling)


def fit_exponent(d, y, base):
    """Least squares of log(y / d^base) = c0 + g log d + c1 d + c2 d^2: returns g (the shift)."""
    A = np.column_stack([np.ones_like(d), np.log(d), d, d * d])
    coef, *_ = np.linalg.lstsq(A, np.log(y / d ** base), rcond=None)
    return coef[1], coef[0]


def fits(beta, f, Qf, n):
    import roughroll  # noqa: F401
    sigma = -1.0  # the cases below are braked, slip- at both edges and both sides of the stick zone
    k = sigma * beta * f
    eps = math.atan(k) / math.pi
    print(f"\nfits: beta_D = {beta}, f = {f}, Q/f = {Qf}, n = {n}: k = sigma beta_D f = {k:.6g}, "
          f"eps = arctan(k)/pi = {eps:.6g}")
    print("  predicted shifts (exponent minus the basis's): left edge -eps = %.5f, right edge +eps = %.5f, "
          "exit -eps = %.5f, entry +eps = %.5f" % (-eps, eps, -eps, eps))
    d = np.logspace(-3.5, -1.3, 30)
    for coupling in ("johnson", "full"):
        s = scene(beta, f, Qf * f, coupling)
        pt = s.point(n=n, method="product")
        c, st = pt.c0, pt.stick_start
        r = np.concatenate([-1 + d, 1 - d, c - d, st + d, c + d, [c]])
        t = s.traction(Qf * f, r=r, n=n, method="product")
        p, p1 = np.asarray(t["p"]), np.asarray(t["p1"])
        m = len(d)
        q = p1 - sigma * f * p
        pl, pr = p[:m], p[m:2 * m]
        qc, qs = q[2 * m:3 * m], q[3 * m:4 * m]
        gl, _ = fit_exponent(d, pl / np.sqrt(2 - d), 0.5)
        gr, _ = fit_exponent(d, pr / np.sqrt(2 - d), 0.5)
        gc, lnA = fit_exponent(d, np.abs(qc), 0.5)
        gs, _ = fit_exponent(d, np.abs(qs), 1.5)
        far = d >= 5e-3  # the zone ends again, at distances well above the ends' own error (1e-5 .. 1e-4)
        gc2, _ = fit_exponent(d[far], np.abs(qc[far]), 0.5)
        gs2, _ = fit_exponent(d[far], np.abs(qs[far]), 1.5)
        print(f"  {coupling:8s} ends s = {st:.9f}, c = {c:.9f}; fitted shifts (d from 3e-4 to 5e-2): left edge "
              f"{gl:+.5f}, right edge {gr:+.5f}, exit {gc:+.5f}, entry {gs:+.5f}; ends from d = 5e-3: exit "
              f"{gc2:+.5f}, entry {gs2:+.5f}")
        # The one-sided kink of p at the exit: second difference across c.
        pc = p[-1]
        D2 = p[4 * m:5 * m] + p[2 * m:3 * m] - 2 * pc
        A = math.exp(lnA) * np.sign(qc[0])
        alpha = 0.5 - eps
        B = beta * A / ((1 + k * k) * math.sin(math.pi * alpha))
        for dd in (0.01, 0.02, 0.05):
            i = int(np.argmin(np.abs(d - dd)))
            print(f"    d = {d[i]:.3g}: p(c+d) + p(c-d) - 2 p(c) = {D2[i]:+.4e}; predicted kink B d^alpha = "
                  f"{B * d[i] ** alpha:+.4e} (A = {A:.5g})")


def ends(beta, f, Qf, ns):
    print(f"\nends: beta_D = {beta}, f = {f}, Q/f = {Qf}, full coupling")
    prev = None
    for n in ns:
        pt = scene(beta, f, Qf * f, "full").point(n=n, method="product")
        row = (pt.stick_start, pt.c0, pt.xi, pt.hertz_load_ratio)
        if prev is None:
            print(f"  n = {n:4d}: s = {row[0]:.10f}  c = {row[1]:.10f}  xi = {row[2]:.12f}  P_H/P2 = {row[3]:.12f}")
        else:
            dv = [a - b for a, b in zip(row, prev)]
            print(f"  n = {n:4d}: s = {row[0]:.10f}  c = {row[1]:.10f}  xi = {row[2]:.12f}  P_H/P2 = {row[3]:.12f}"
                  f"   changes {dv[0]:+.2e} {dv[1]:+.2e} {dv[2]:+.2e} {dv[3]:+.2e}")
        prev = row


if __name__ == "__main__":
    args = sys.argv[1:]
    n = int(args[args.index("--n") + 1]) if "--n" in args else 256
    case = (0.3, 0.2, -0.75) if "--strong" in args else (0.1438337, 0.05, -0.75)
    if "identity" in args:
        identity()
    if "fits" in args:
        fits(*case, n)
    if "ends" in args:
        ends(*case, [32, 64, 128, 256])
