#!/usr/bin/env python3
"""Generate Gauss-Kronrod nodes and weights on [-1, 1] to full double precision.

The Kronrod nodes are the zeros of the Stieltjes polynomial E_{n+1}, defined by
  integral_{-1}^{1} E_{n+1}(x) P_n(x) x^k dx = 0,  k = 0..n   (E monic);
the 2n+1 weights follow from exactness for polynomials of degree <= 3n+1.
Requires mpmath (pip install mpmath). Output: C++ arrays for quadrature_rules.hpp.
"""
import sys
import mpmath as mp

mp.mp.dps = 60


def legendre_coeffs(n):
    # monomial coefficients of P_n, low to high
    p0, p1 = [mp.mpf(1)], [mp.mpf(0), mp.mpf(1)]
    if n == 0:
        return p0
    for k in range(1, n):
        nxt = [mp.mpf(0)] * (k + 2)
        for i, c in enumerate(p1):
            nxt[i + 1] += mp.mpf(2 * k + 1) / (k + 1) * c
        for i, c in enumerate(p0):
            nxt[i] -= mp.mpf(k) / (k + 1) * c
        p0, p1 = p1, nxt
    return p1


def moment(k):
    return mp.mpf(2) / (k + 1) if k % 2 == 0 else mp.mpf(0)


def poly_int(c):
    return sum(ci * moment(i) for i, ci in enumerate(c))


def mul(a, b):
    out = [mp.mpf(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def kronrod(n):
    pn = legendre_coeffs(n)
    m = n + 1
    # unknown lower coefficients e_0..e_n of E = x^m + sum e_j x^j
    A = mp.matrix(n + 1, n + 1)
    b = mp.matrix(n + 1, 1)
    for k in range(n + 1):
        base = mul(pn, [mp.mpf(0)] * k + [mp.mpf(1)])
        for j in range(m):
            A[k, j] = poly_int(mul(base, [mp.mpf(0)] * j + [mp.mpf(1)]))
        b[k] = -poly_int(mul(base, [mp.mpf(0)] * m + [mp.mpf(1)]))
    e = mp.lu_solve(A, b)
    stieltjes = [e[j] for j in range(m)] + [mp.mpf(1)]
    kr = mp.polyroots(list(reversed(stieltjes)), maxsteps=500, extraprec=400)
    gauss = mp.polyroots(list(reversed(pn)), maxsteps=500, extraprec=400)
    nodes = sorted([mp.re(x) for x in list(kr) + list(gauss)])
    N = len(nodes)
    V = mp.matrix(N, N)
    rhs = mp.matrix(N, 1)
    for k in range(N):
        for i, x in enumerate(nodes):
            V[k, i] = x ** k
        rhs[k] = moment(k)
    wk = mp.lu_solve(V, rhs)
    gw = []
    for x in sorted([mp.re(g) for g in gauss]):
        # Gauss weight 2 / ((1 - x^2) P_n'(x)^2)
        d = sum(i * c * x ** (i - 1) for i, c in enumerate(pn) if i > 0)
        gw.append(2 / ((1 - x * x) * d * d))
    return nodes, [wk[i] for i in range(N)], sorted([mp.re(g) for g in gauss]), gw


def emit(n):
    nodes, wk, gnodes, gw = kronrod(n)
    half = [(x, w) for x, w in zip(nodes, wk) if x >= -mp.mpf(10) ** -40]
    gauss_set = {mp.nstr(g, 30) for g in gnodes}
    print(f"// Gauss-Kronrod G{n}K{2*n+1}: nodes x >= 0 (descending), Kronrod weights, and the")
    print(f"// Gauss weight of the node (0 where the node is Kronrod-only). From scripts/gen_kronrod.py.")
    print(f"inline constexpr KronrodNode kGK{2*n+1}[{len(half)}] = {{")
    for x, w in sorted(half, key=lambda t: -t[0]):
        x = abs(x) if abs(x) < mp.mpf(10) ** -40 else x
        g = mp.mpf(0)
        for gx, gwv in zip(gnodes, gw):
            if abs(gx - x) < mp.mpf(10) ** -40:
                g = gwv
        print(f"    {{{mp.nstr(x, 20, min_fixed=-1, max_fixed=1)}, {mp.nstr(w, 20)}, {mp.nstr(g, 20)}}},")
    print("};")


if __name__ == "__main__":
    for n in [int(a) for a in sys.argv[1:]] or [7, 10]:
        emit(n)
