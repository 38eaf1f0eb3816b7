"""Peer timings for the series job of the foundation issue, printed as JSON lines.

Job: f(x) = (sin x / x)^(1/2 + th), th symbolic, to N coefficients, and the reversion of
y = x f(x). Peers (routes taken from shared/peers/series_sympy.py and series_flint.py):
  sympy : sympy.polys.ring_series over QQ[th] (rs_sin, rs_log, rs_exp, rs_series_reversion)
  flint : python-flint, QQ[th] coefficients (fmpq_poly), Miller power recurrence + Lagrange inversion
  fmpq  : python-flint fmpq_series at th = 1/3 (exact QQ, FLINT's C series routines)
Each figure is the best of `repeat` runs. The x^7 reversion coefficient is printed as a stamp.
Usage: python series_peers.py PEER N [repeat]
"""
import json
import sys
import time


def best(repeat, f):
    t_best, out = float("inf"), None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = f()
        t_best = min(t_best, time.perf_counter() - t0)
    return t_best, out


def sympy_job(n, repeat):
    from sympy.polys.domains import QQ
    from sympy.polys.ring_series import rs_exp, rs_log, rs_mul, rs_series_reversion, rs_sin
    from sympy.polys.rings import ring

    R, X, TH = ring("x,th", QQ)

    def series():
        sx = rs_sin(X, X, n + 1)
        q = R({(k - 1, j): c for (k, j), c in sx.terms()})
        return rs_exp((QQ(1, 2) + TH) * rs_log(q, X, n), X, n)

    ts, f = best(repeat, series)
    g = rs_mul(X, f, X, n)
    tr, rev = best(repeat, lambda: rs_series_reversion(g, X, n, X))
    c7 = sum(c * TH ** j for (k, j), c in rev.terms() if k == 7)
    return {"series_s": ts, "reversion_s": tr, "rev_x7": str(c7)}


def flint_job(n, repeat):
    from math import factorial

    from flint import fmpq, fmpq_poly

    gc = [fmpq((-1) ** (k // 2), factorial(k + 1)) if k % 2 == 0 else fmpq(0) for k in range(n)]
    alpha = fmpq_poly([fmpq(1, 2), 1])

    def miller(gc, alpha, m):
        f = [fmpq_poly([1])]
        a1 = alpha + 1
        for k in range(1, m):
            acc = fmpq_poly(0)
            for j in range(1, k + 1):
                if gc[j] != 0:
                    acc += (a1 * j - k) * (f[k - j] * gc[j])
            f.append(acc / k)
        return f

    ts, _ = best(repeat, lambda: miller(gc, alpha, n))

    def reversion():
        rev = [fmpq_poly(0)]
        for m in range(1, n):
            fn = miller(gc[:m], alpha * (-m), m)
            rev.append(fn[m - 1] / m)
        return rev

    tr, rev = best(repeat, reversion)
    return {"series_s": ts, "reversion_s": tr, "rev_x7": str(rev[7]) if n > 7 else ""}


def fmpq_job(n, repeat):
    from math import factorial

    from flint import ctx, fmpq, fmpq_series

    ctx.cap = n
    gc = [fmpq((-1) ** (k // 2), factorial(k + 1)) if k % 2 == 0 else fmpq(0) for k in range(n)]
    th = fmpq(1, 3)
    ts, f = best(repeat, lambda: ((fmpq(1, 2) + th) * fmpq_series(gc).log()).exp())
    y = fmpq_series([0] + f.coeffs()[: n - 1])
    tr, _ = best(repeat, lambda: y.reversion())
    return {"series_s": ts, "reversion_s": tr}


if __name__ == "__main__":
    peer, n = sys.argv[1], int(sys.argv[2])
    repeat = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    job = {"sympy": sympy_job, "flint": flint_job, "fmpq": fmpq_job}[peer]
    out = job(n, repeat)
    out.update({"peer": peer, "N": n})
    print(json.dumps(out), flush=True)
