#!/usr/bin/python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The no-slip limit of free rolling at full coupling (docs/formulation.md 8(p), 8(t)), by two routes that share
nothing but the equations, and the limit beta_D -> 0 (Johnson's level).

  identity  8(t)'s images of the fundamental function, H[w T_j] + i beta_D w T_j = -R_{T_j}/cosh(pi eps) and
            int w T_j, from the Joukowski coefficients, against mpmath's quadrature (30 digits) for j = 0 .. 6;
  smooth    route A (the collocation on w T_j of problems/no_slip_coupled, written again in numpy) against 8(p)'s
            closed form, and route B against it;
  rough     route A against route B for data/aluminium-on-steel-rough.toml's layer at a = a_H ((T, A) = (1.08, 1.19)
            tangential, (3.9, 4.5) normal, roller 1); route B Richardson-extrapolated (order 2);
  johnson   full coupling against Johnson's level (route B without beta_D p1 in (D1)) as beta_D -> 0.
Route A: F = p - i p1 = w phi, phi = sum c_j T_j, the layers' integrals by tanh-sinh on each side of the kernels' jump.
Route B: p = sqrt(1 - r^2) sum a_k U_k, p1 = sqrt(1 - r^2) sum c_k U_k (H[sqrt(1 - t^2) U_k] = -T_{k+1}), no oscillation
carried (order 2), collocated at n + 3 Chebyshev points, least squares; the layers' integrals in eta = cos(theta) by
Gauss-Legendre on each side of the jump. Both at lambda = 1, scaled to int p = 1 afterwards.
Minutes (route B at n = 1024: about a minute alone): not a test. tests/test_no_slip_coupled.cpp holds the numbers.
Usage: no_slip_full.py [identity] [smooth] [rough] [johnson]
"""
import math
import sys

import numpy as np
from scipy.special import eval_chebyt, eval_chebyu

BETA = 0.143834  # aluminium on steel (8(a))
ROUGH_K1 = ((1.08, 1.19),)  # K1*: tangential (T, A)
ROUGH_K2 = ((3.9, 4.5),)  # K2*: normal


def eps_of(beta):
    return math.log((1 - beta) / (1 + beta)) / (2 * math.pi)


def gammas(eps, count):
    """((1 + u)/(1 - u))^(2 i eps) = sum gamma_m u^m: (1 - u^2) G' = 4 i eps G."""
    g = np.zeros(count + 1, complex)
    g[0] = 1
    g[1] = 4j * eps
    for m in range(1, count):
        g[m + 1] = (4j * eps * g[m] + (m - 1) * g[m - 1]) / (m + 1)
    return g


def images(eps, n):
    """R[k, j]: T_k's coefficient in R_{T_j}; L[j] = int w T_j (8(t))."""
    g = gammas(eps, 2 * n + 8)
    gam = lambda m: g[m] if m >= 0 else 0.0
    y = lambda k, j: 0.25 * (gam(k + j + 1) + gam(k - j + 1) - gam(k + j - 1) - gam(k - j - 1))
    R = np.zeros((n + 2, n + 1), complex)
    L = np.zeros(n + 1, complex)
    ch = math.cosh(math.pi * eps)
    for j in range(n + 1):
        R[0, j] = y(0, j)
        for k in range(1, j + 2):
            R[k, j] = 2 * y(-k, j)
        L[j] = -math.pi * (y(1, j) - y(-1, j)) / (2 * ch)
    return R, L


def kern(z, terms):
    return sum(T * np.exp(-A * np.abs(z)) for T, A in terms) * np.sign(z)


def tanh_sinh(a, b, h=1 / 32, tmax=4.5):
    t = np.arange(-tmax, tmax + h / 2, h)
    u = 0.5 * math.pi * np.sinh(t)
    wt = h * 0.5 * math.pi * np.cosh(t) / np.cosh(u) ** 2 * (b - a) / 2
    from_a = (b - a) / (1 + np.exp(-2 * u))
    to_b = (b - a) / (1 + np.exp(2 * u))
    return from_a, to_b, wt


def route_a(beta, n, K1=(), K2=()):
    eps = eps_of(beta)
    ch = math.cosh(math.pi * eps)
    R, L = images(eps, n)
    M = n + 2
    rm = np.cos((2 * np.arange(M) + 1) * math.pi / (2 * M))
    Rv = np.array([eval_chebyt(k, rm) for k in range(n + 2)]).T @ R
    I1 = np.zeros((M, n + 1), complex)
    I2 = np.zeros((M, n + 1), complex)
    if K1 or K2:
        for m, r in enumerate(rm):
            for left in (True, False):
                a, b = (-1.0, r) if left else (r, 1.0)
                fa, tb, wt = tanh_sinh(a, b)
                plus = fa if left else 1 + r + fa
                minus = 1 - r + tb if left else tb
                z = -tb if left else fa
                ok = (plus > 0) & (minus > 0) & (z != 0)
                plus, minus, z, wt = plus[ok], minus[ok], z[ok], wt[ok]
                w = np.sqrt(plus * minus) * np.exp(1j * eps * (np.log(plus) - np.log(minus))) * wt
                eta = -1 + plus if left else 1 - minus
                Tj = np.array([eval_chebyt(k, eta) for k in range(n + 1)]).T
                if K1:
                    I1[m] += (w * kern(z, K1)) @ Tj
                if K2:
                    I2[m] += (w * kern(z, K2)) @ Tj
    c = n + 1
    A = np.zeros((2 * M, 2 * c + 2))
    rhs = np.zeros(2 * M)
    A[:M, :c] = -Rv.real / ch + I2.real
    A[:M, c:2 * c] = Rv.imag / ch - I2.imag
    A[:M, 2 * c] = 2 / math.pi
    rhs[:M] = -2 / math.pi * rm
    A[M:, :c] = -Rv.imag / ch + I1.imag
    A[M:, c:2 * c] = -Rv.real / ch + I1.real
    A[M:, 2 * c + 1] = 1.0
    x = np.linalg.solve(A, rhs)
    coeff = x[:c] + 1j * x[c:2 * c]
    load = coeff @ L
    P = load.real
    return dict(lam=1 / P, e=x[2 * c], xi=x[2 * c + 1] / P, Q=-load.imag / P, phi=coeff / P, eps=eps)


def route_b(beta, n, K1=(), K2=(), johnson=False, extra=40):
    M = n + 3
    rm = np.cos((2 * np.arange(M) + 1) * math.pi / (2 * M))
    c = n + 1
    T = np.array([eval_chebyt(k + 1, rm) for k in range(c)]).T
    S = np.sqrt(1 - rm * rm)[:, None] * np.array([eval_chebyu(k, rm) for k in range(c)]).T
    xg, wg = np.polynomial.legendre.leggauss(n // 2 + extra)
    ks = np.arange(1, c + 1)

    def kmat(terms):
        out = np.zeros((M, c))
        if not terms:
            return out
        for m, r in enumerate(rm):
            tr = math.acos(r)
            for a, b in ((0.0, tr), (tr, math.pi)):
                th = (a + b) / 2 + (b - a) / 2 * xg
                f = kern(np.cos(th) - r, terms) * np.sin(th) * (b - a) / 2 * wg
                out[m] += f @ np.sin(np.outer(th, ks))
        return out

    K1m, K2m = kmat(K1), kmat(K2)
    A = np.zeros((2 * M, 2 * c + 2))
    rhs = np.zeros(2 * M)
    A[:M, :c] = -T + K2m
    A[:M, c:2 * c] = 0.0 if johnson else beta * S
    A[:M, 2 * c] = 2 / math.pi
    rhs[:M] = -2 / math.pi * rm
    A[M:, c:2 * c] = -T + K1m
    A[M:, :c] = -beta * S
    A[M:, 2 * c + 1] = -1.0
    x = np.linalg.lstsq(A, rhs, rcond=None)[0]
    P = math.pi / 2 * x[0]
    return dict(lam=1 / P, e=x[2 * c], xi=x[2 * c + 1] / P, Q=math.pi / 2 * x[c] / P)


def closed(beta):
    eps = eps_of(beta)
    return dict(lam=1 / (1 + 4 * eps * eps), xi=4 * eps / (math.pi * (1 + 4 * eps * eps)))


def identity():
    import mpmath as mp
    mp.mp.dps = 30
    for beta in (BETA, 0.5, -0.3):
        eps = eps_of(beta)
        R, L = images(eps, 6)
        worst = 0.0
        for j in range(7):
            f = lambda t: mp.sqrt(1 - t * t) * mp.exp(1j * eps * mp.log((1 + t) / (1 - t))) * mp.chebyt(j, t)
            worst = max(worst, abs(complex(mp.quad(f, [-1, 0, 1])) - L[j]))
            for r0 in (mp.mpf('-0.9'), mp.mpf('0.3'), mp.mpf('0.99')):
                Hq = mp.quad(lambda t: (f(t) - f(r0)) / (t - r0), [-1, r0, 1]) / mp.pi + f(r0) * mp.log((1 - r0) / (1 + r0)) / mp.pi
                lhs = complex(Hq + 1j * beta * f(r0))
                rhs = -sum(R[k, j] * float(mp.chebyt(k, r0)) for k in range(j + 2)) / math.cosh(math.pi * eps)
                worst = max(worst, abs(lhs - rhs))
        print(f"identity beta_D {beta}: largest residual over j = 0..6, three points and the loads {worst:.1e}")


def smooth():
    for beta in (BETA, 0.5):
        c = closed(beta)
        a = route_a(beta, 8)
        print(f"smooth beta_D {beta}: closed lambda {c['lam']:.15f} xi {c['xi']:.15f}; route A (n = 8) "
              f"{a['lam'] - c['lam']:+.1e} {a['xi'] - c['xi']:+.1e}")
        for n in (32, 64, 128, 256):
            b = route_b(beta, n)
            print(f"  route B n = {n}: lambda {b['lam'] - c['lam']:+.2e}, xi {b['xi'] - c['xi']:+.2e}, e {b['e']:+.1e}")


def rough():
    for n in (32, 64, 128, 256):
        a = route_a(BETA, n, ROUGH_K1, ROUGH_K2)
        print(f"rough route A n = {n}: lambda {a['lam']:.12f} xi {a['xi']:.12f} e {a['e']:+.1e} int p1 {a['Q']:+.1e}", flush=True)
    phi = a['phi']
    print(f"  phi(1) = {phi.sum():.6f}, phi(-1) = {(phi * (-1.0) ** np.arange(len(phi))).sum():.6f}")
    levels = []
    for n in (256, 512, 1024):
        b = route_b(BETA, n, ROUGH_K1, ROUGH_K2)
        levels.append(b)
        print(f"rough route B n = {n}: lambda {b['lam']:.12f} xi {b['xi']:.12f}", flush=True)
    for key in ('lam', 'xi'):
        v = [lv[key] for lv in levels]
        ratio = (v[1] - v[0]) / (v[2] - v[1])
        print(f"  route B {key}: change ratio {ratio:.2f}, Richardson {v[2] + (v[2] - v[1]) / (ratio - 1):.12f}")


def johnson():
    for beta in (0.01, 0.02, 0.04, BETA):
        f = route_b(beta, 128, ROUGH_K1, ROUGH_K2)
        j = route_b(beta, 128, ROUGH_K1, ROUGH_K2, johnson=True)
        print(f"rough beta_D {beta}: (xi_full - xi_J)/beta^3 {(f['xi'] - j['xi']) / beta ** 3:.5f}, "
              f"(lambda_full - lambda_J)/beta^2 {(f['lam'] - j['lam']) / beta ** 2:.5f}, xi_J/beta {j['xi'] / beta:.7f}")
    for beta in (0.01, 0.02, 0.04, BETA):
        c = closed(beta)
        print(f"smooth beta_D {beta}: (xi_full + 4 beta/pi^2)/beta^3 {(c['xi'] + 4 * beta / math.pi ** 2) / beta ** 3:.5f} "
              f"(8(p): {-4 / math.pi ** 2 * (1 / 3 - 4 / math.pi ** 2):.5f} as beta -> 0)")


if __name__ == '__main__':
    parts = sys.argv[1:] or ['identity', 'smooth', 'rough', 'johnson']
    for part in parts:
        globals()[part]()
